//! The conformance bars (docs/conformance.md): scores the front end on `../shared/corpora/`.
//! Skips, with a message, when `../shared` is absent, unless `CI` is set (then it fails).

use std::path::Path;

use essl_cli::conformance::{bars, score};

#[test]
fn conformance_bars_are_met() {
    let corpora = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/corpora");
    if !corpora.is_dir() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but the corpora are missing at {}",
            corpora.display()
        );
        println!(
            "skipped: no corpora at {} (../shared is absent)",
            corpora.display()
        );
        return;
    }
    let report = score(&corpora).expect("the corpora parse");
    println!("{}", report.tables());
    assert_eq!(report.webgl.pass.total, 159);
    assert_eq!(report.webgl.fail.total, 67);
    assert!(report.deqp.pass.total > 4000 && report.deqp.fail.total > 1000);
    assert!(
        report.webgl.pass.ok >= bars::WEBGL_PASS,
        "WebGL must_pass {}",
        report.webgl.pass.cell()
    );
    assert!(
        report.webgl.fail.ok >= bars::WEBGL_FAIL,
        "WebGL must_fail {}",
        report.webgl.fail.cell()
    );
    assert!(
        report.deqp.pass.percent() >= bars::DEQP_PASS_PERCENT,
        "dEQP pass {}",
        report.deqp.pass.cell()
    );
    assert!(
        report.deqp.fail.percent() >= bars::DEQP_FAIL_PERCENT,
        "dEQP fail {}",
        report.deqp.fail.cell()
    );
    assert_eq!(
        report.fundamentals.ok,
        report.fundamentals.total,
        "webgl2fundamentals {}",
        report.fundamentals.cell()
    );
    assert!(report.unmet_bars().is_empty(), "{:?}", report.unmet_bars());
}
