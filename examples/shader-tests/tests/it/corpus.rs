//! The bindings of every webgl2fundamentals program that Chromium links were generated, and so
//! compiled with this crate (`build.rs`): one module per linked pair of the oracle's record.

#[cfg(essl_corpus)]
#[test]
fn every_linked_pair_has_bindings() {
    let generated = include_str!(concat!(env!("OUT_DIR"), "/corpus.rs"));
    let oracle: serde_json::Value = serde_json::from_str(include_str!(
        "../../../../tests/oracle/webgl2fundamentals.json"
    ))
    .unwrap();
    let linked: Vec<String> = oracle["programs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["ok"] == true)
        .map(|p| format!("pub mod p{}_{} {{", p["vertex"], p["fragment"]))
        .collect();
    assert!(linked.len() >= 50, "{} linked programs", linked.len());
    for module in &linked {
        assert!(generated.contains(module.as_str()), "no `{module}`");
    }
    assert_eq!(generated.matches("\npub mod ").count(), linked.len());
    println!("{} programs with bindings", linked.len());
}

/// Without the corpus the bindings were not generated: skip, or fail under
/// `ESSL_REQUIRE_CORPORA=1`.
#[cfg(not(essl_corpus))]
#[test]
fn corpus_is_absent() {
    assert!(
        essl_testdata::corpus_file("webgl2fundamentals_shaders.jsonl").is_none(),
        "the corpus appeared after the build: rebuild"
    );
}
