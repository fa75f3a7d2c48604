//! The stiff-case matrix: the library's formulations are finite and within 1/255 of the f64
//! model everywhere (or the API refuses the parameters); the seeds' formulas fail where
//! `docs/numerical-stability.md` says, and its table is this run's.

use essl_lights::stiff::{self, Case, Model, Outcome};

fn rows() -> Vec<stiff::Row> {
    stiff::run()
}

#[test]
fn library_is_finite_and_within_one_level_everywhere() {
    let rows = rows();
    assert!(rows.len() >= 100);
    for r in &rows {
        assert!(
            r.library_highp.ok(),
            "{} / {}: library highp {:?}",
            r.model.name(),
            r.case.name(),
            r.library_highp
        );
        // Refusals only where the parameters are impossible.
        if let Outcome::Rejected(msg) = &r.library_highp {
            let expected = matches!(
                r.case,
                Case::Swapped | Case::UpParallel | Case::ZeroViewport
            ) || (r.case == Case::Cone0 && r.model == Model::SpotProjected);
            assert!(
                expected,
                "{} / {}: rejected: {msg}",
                r.model.name(),
                r.case.name()
            );
        }
    }
    // The control row passes for the seeds too (the transplant measures formulations, not
    // different models).
    for r in rows.iter().filter(|r| r.case == Case::Baseline) {
        assert!(r.seed_highp.ok(), "{}: {:?}", r.model.name(), r.seed_highp);
        assert!(r.seed_f64.ok(), "{}: {:?}", r.model.name(), r.seed_f64);
    }
}

fn find(rows: &[stiff::Row], m: Model, c: Case) -> &stiff::Row {
    rows.iter()
        .find(|r| r.model == m && r.case == c)
        .unwrap_or_else(|| panic!("no row {m:?} {c:?}"))
}

#[test]
fn seeds_fail_where_documented() {
    let rows = rows();
    let nan = |o: &Outcome| !o.finite();
    let off = |o: &Outcome| !o.ok();
    // 0/0 of the zero-width ramp (articles 000, 001, 003, 004).
    for m in [
        Model::SpotLinear,
        Model::SpotSmooth,
        Model::SpotProjected,
        Model::Flashlight,
    ] {
        assert!(
            nan(&find(&rows, m, Case::InnerEqualsOuter).seed_highp),
            "{m:?}"
        );
        assert!(nan(&find(&rows, m, Case::Cone0).seed_highp), "{m:?}");
        assert!(off(&find(&rows, m, Case::Swapped).seed_highp), "{m:?}");
    }
    // normalize(0).
    for m in [
        Model::Point,
        Model::SpotSmooth,
        Model::SpotStep,
        Model::Flashlight,
    ] {
        let r = find(&rows, m, Case::LightOnSurface);
        assert!(m == Model::Point || nan(&r.seed_highp), "{m:?}");
    }
    assert!(nan(
        &find(&rows, Model::SpotSmooth, Case::ZeroNormal).seed_highp
    ));
    // Article 003: acos past ±1, cross of parallel vectors.
    assert!(nan(
        &find(&rows, Model::SpotProjected, Case::AcosPastOne).seed_highp
    ));
    assert!(nan(
        &find(&rows, Model::SpotProjected, Case::UpParallel).seed_highp
    ));
    // Article 001: pow of a negative base; article 002: pow(0, 0); unclamped Lambert.
    assert!(nan(
        &find(&rows, Model::SpotStep, Case::LightBehind).seed_mediump
    ));
    assert!(nan(&find(&rows, Model::Point, Case::Shininess0).seed_highp));
    assert!(off(&find(
        &rows,
        Model::DirectionalLambert,
        Case::LightBehind
    )
    .seed_mediump));
    // Blinn's half vector of L = -V.
    assert!(nan(
        &find(&rows, Model::SpotSmooth, Case::BackFace).seed_highp
    ));
    // mediump: overflow past 65504 and underflow at 1e-6.
    assert!(off(
        &find(&rows, Model::Point, Case::MediumpRange).seed_mediump
    ));
    assert!(nan(
        &find(&rows, Model::SpotStep, Case::ScaleMicro).seed_mediump
    ));
    assert!(nan(
        &find(&rows, Model::SpotStep, Case::ScaleMega).seed_mediump
    ));
    // Article 004: division by a zero viewport.
    assert!(nan(
        &find(&rows, Model::Flashlight, Case::ZeroViewport).seed_highp
    ));
}

/// A cell's class: `O` within 1/255, `F` off, `N` not finite, `R` rejected, `U` no reference.
fn class(cell: &str) -> char {
    if cell.contains("rejected") {
        'R'
    } else if cell.contains("NaN") {
        'N'
    } else if cell.contains("no ref") {
        'U'
    } else if cell.contains("**") {
        'F'
    } else {
        'O'
    }
}

#[test]
fn the_documented_table_is_this_runs() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/numerical-stability.md");
    let doc = std::fs::read_to_string(&path).expect("docs/numerical-stability.md");
    let a = doc.find(stiff::BEGIN_MARKER).expect("begin marker");
    let b = doc.find(stiff::END_MARKER).expect("end marker");
    let classes = |text: &str| -> Vec<String> {
        text.lines()
            .filter(|l| {
                l.starts_with("| ") && !l.starts_with("| ---") && !l.contains("light model")
            })
            .map(|l| {
                let cells: Vec<&str> = l.split(" | ").collect();
                let mut k = format!("{} / {}:", cells[0].trim_start_matches("| "), cells[1]);
                for c in &cells[2..] {
                    k.push(class(c));
                }
                k
            })
            .collect()
    };
    let documented = classes(&doc[a..b]);
    let run = classes(&stiff::markdown(&rows()));
    assert_eq!(
        documented, run,
        "docs/numerical-stability.md is stale: run `cargo run -p essl-lights --bin stiff-table`"
    );
}
