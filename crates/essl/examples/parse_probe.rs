//! Scores the front end on a corpus quickly (development aid): `cargo run --example parse_probe -- FILE.jsonl`.
use essl::*;
fn main() {
    let path = std::env::args().nth(1).unwrap();
    let verbose = std::env::args().nth(2);
    let (mut pass_bad, mut pass_total, mut fail_total, mut fail_rej) = (0, 0, 0, 0);
    for line in std::fs::read_to_string(&path).unwrap().lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let expect = v["expect"]
            .as_str()
            .or(v["outcome"].as_str())
            .unwrap_or("pass");
        if v["version"].as_str().is_some_and(|s| s != "300 es") {
            continue;
        }
        let name = v["name"]
            .as_str()
            .or(v["file"].as_str())
            .unwrap_or("")
            .to_string();
        let mut errs = Vec::new();
        let single = match v["stage"].as_str() {
            Some("vertex") => Some(Stage::Vertex),
            Some("fragment") => Some(Stage::Fragment),
            _ => None,
        };
        if v["templated"].as_bool() == Some(true) || (v["source"].is_string() && single.is_none()) {
            continue;
        }
        for (key, stage) in [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
            ("source", single.unwrap_or(Stage::Vertex)),
        ] {
            let Some(src) = v[key].as_str() else { continue };
            let sh = compile(
                source::SourceFile::new(key, src),
                stage,
                &Default::default(),
            );
            for d in sh.diagnostics.iter().filter(|d| d.is_error()) {
                let lc = sh.file.line_col(d.span.start);
                errs.push(format!(
                    "{key}:{}:{} [{}] {}",
                    lc.line, lc.column, d.code, d.message
                ));
            }
        }
        let must_pass = matches!(expect, "pass" | "must_pass" | "build_successful");
        if must_pass {
            pass_total += 1;
            if !errs.is_empty() {
                pass_bad += 1;
                if verbose.as_deref() == Some("pass") {
                    println!("PASS-REJECTED {name}: {}", errs[0]);
                }
            }
        } else if expect == "compile_fail"
            || expect == "must_fail"
            || expect == "compile_link_fail"
            || expect == "link_fail"
        {
            fail_total += 1;
            if !errs.is_empty() {
                fail_rej += 1;
            } else if verbose.as_deref() == Some("fail") {
                println!("FAIL-ACCEPTED {name} ({expect})");
            }
        }
    }
    println!(
        "must-pass rejected: {pass_bad}/{pass_total}; must-fail rejected: {fail_rej}/{fail_total}"
    );
}
