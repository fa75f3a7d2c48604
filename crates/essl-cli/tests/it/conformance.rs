//! The conformance bars (docs/conformance.md): scores the front end on `../shared/corpora/`.
//! Skips, with a message, when the corpora are absent, unless `ESSL_REQUIRE_CORPORA=1`.

use essl_cli::conformance::{bars, score};

#[test]
fn conformance_bars_are_met() {
    let Some(corpora) = essl_testdata::corpora() else {
        return;
    };
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
    let es100 = report
        .es100
        .as_ref()
        .expect("the GLSL ES 1.00 corpus is scored");
    for target in [essl::Target::WebGl1, essl::Target::WebGl2] {
        let c = es100.context(target);
        assert_eq!(c.accepted.total + c.rejected.total, 2021);
        for (what, t) in [("accepted", &c.accepted), ("rejected", &c.rejected)] {
            assert!(
                t.percent() >= bars::ES100_PERCENT,
                "GLSL ES 1.00, {}: Chromium-{what} cases agreed {}",
                target.as_str(),
                t.cell()
            );
        }
    }
    assert!(report.unmet_bars().is_empty(), "{:?}", report.unmet_bars());
}
