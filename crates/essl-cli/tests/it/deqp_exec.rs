//! The dEQP value cases executed through essl-gl, as `essl deqp-exec` runs them (every 20th
//! case here, to keep the debug build's run short; `essl deqp-exec` runs all 4,113, and
//! Chromium passes all of them): each passes from essl's IR, and again from its WGSL
//! translation read back by naga's WGSL front end. Skips, with a message, without the corpus
//! or a Vulkan adapter, unless `ESSL_REQUIRE_CORPORA=1` / `ESSL_REQUIRE_ADAPTER=1`.

#![cfg(feature = "render")]

use essl_cli::deqp_exec::{read_cases, Runner};

/// Every 20th value case through a runner that executes essl's IR, or its WGSL translation.
fn sample_passes(via_wgsl: bool) {
    let Some(corpus) = essl_testdata::corpus_file("deqp_gles3.jsonl") else {
        return;
    };
    let cases = read_cases(&corpus, None).expect("the corpus reads");
    assert_eq!(cases.len(), 4113, "executed cases");
    let sample: Vec<_> = cases.iter().step_by(20).collect();
    let Some(mut runner) = essl_testdata::with_adapter(|| Runner::with(via_wgsl)) else {
        return;
    };
    let failed: Vec<_> = sample
        .iter()
        .map(|c| runner.run(c))
        .filter(|o| !o.ok)
        .map(|o| format!("{}: {}", o.name, o.why.unwrap_or_default()))
        .collect();
    assert!(
        failed.is_empty(),
        "via WGSL: {via_wgsl}; {} of {} fail:\n{}",
        failed.len(),
        sample.len(),
        failed.join("\n")
    );
    println!("via WGSL: {via_wgsl}: {} cases pass", sample.len());
}

// Two tests, so that the test threads run the two ways side by side.
#[test]
fn value_cases_pass_from_ir() {
    sample_passes(false);
}

#[test]
fn value_cases_pass_from_wgsl() {
    sample_passes(true);
}
