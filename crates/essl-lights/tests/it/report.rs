//! `essl report --quick` end to end (the library's `report::run` + `report::write` with the
//! quick settings: small images, one round of few frames): the report's structure, every
//! variant's numbers finite, the files written. And the programs the report compares are
//! minimal (no inactive uniform, no unused function).
//!
//! The GPU parts skip with a message when no Vulkan adapter exists, unless `ESSL_REQUIRE_ADAPTER=1`.

use std::path::{Path, PathBuf};

use essl_lights::report::{self, Group, ProgramKind, Settings, SEED_SCENES};
use essl_lights::*;

fn adapter() -> bool {
    essl_testdata::with_adapter(gpu::adapter).is_some()
}

fn shared_scenes() -> Option<PathBuf> {
    essl_testdata::scenes()
}

#[test]
fn quick_report_end_to_end() {
    if !adapter() {
        return;
    }
    let scenes = shared_scenes();
    let settings = Settings::quick(scenes.clone());
    let r = report::run(&settings, &mut |l| eprintln!("{l}")).unwrap();
    eprintln!("{}", report::text_table(&r));

    // Every group is there (the seed scenes' only with shared/), every number finite.
    for g in Group::ALL {
        let present = r.results.iter().any(|x| x.variant.group == g);
        assert!(
            present || (g == Group::Program && scenes.is_none()),
            "{g:?} missing"
        );
    }
    for x in &r.results {
        assert!(x.is_finite(), "{}: {x:?}", x.variant.name);
        assert_eq!(
            x.times.len(),
            settings.time_sizes.len(),
            "{}",
            x.variant.name
        );
        assert!(x.error.compared > 0, "{}", x.variant.name);
    }
    assert!(r.results.iter().any(|x| x.pareto), "an empty Pareto front");
    assert!(r.machine.renderer.len() > 2);

    // What the report is for: a coarse Gouraud grid misses the small spot (the whole spot
    // is missing: far more than 1/255), Phong shading on the same grid does not.
    let find = |name: &str| r.results.iter().find(|x| x.variant.name == name).unwrap();
    let gouraud = find("small spot, Gouraud, grid 4×4");
    let phong = find("small spot, Phong, grid 4×4");
    assert!(gouraud.error.max > 100.0, "{:?}", gouraud.error);
    assert!(phong.error.max <= 1.0, "{:?}", phong.error);
    // The library's highp programs are within 1/255 on the plane scenes, and draw no NaN.
    for x in &r.results {
        if x.variant.program == ProgramKind::Specialised
            && matches!(x.variant.group, Group::Edge | Group::Precision)
        {
            assert!(x.error.max <= 1.0, "{}: {:?}", x.variant.name, x.error);
        }
        if x.variant.program != ProgramKind::Seed(formulas::Seed::A003Projected) {
            assert_eq!(x.non_finite, 0, "{}", x.variant.name);
        }
    }
    // The specialised programs are minimal; the uber-shader's time is measured too.
    for x in r
        .results
        .iter()
        .filter(|x| x.variant.program == ProgramKind::Specialised)
    {
        assert_eq!(x.unused, 0, "{}", x.variant.name);
    }

    // The files, and the document's structure.
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-quick");
    let _ = std::fs::remove_dir_all(&out);
    let written = report::write(&r, &out).unwrap();
    assert!(written.iter().all(|p| p.is_file()));
    let svg = std::fs::read_to_string(out.join("report.svg")).unwrap();
    assert!(
        svg.contains("<svg") && svg.contains("Pareto front"),
        "{svg}"
    );
    for x in &r.results {
        assert!(
            svg.contains(&format!("\n{}\n", x.variant.label)),
            "label {} not in the chart",
            x.variant.label
        );
    }
    assert!(out.join("report-small-spot.png").is_file());
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    for heading in [
        "# Error against run time",
        "![RMS error against time per frame](report.svg)",
        "## All variants",
        "## A coarse grid with Gouraud shading misses a small spot",
        "## highp against mediump",
        "## Projected-texture coordinates",
        "## Specialised program against the uber-shader",
        "## Stiff cases on the GPU",
        "llvmpipe",
    ] {
        assert!(md.contains(heading), "{heading:?} missing from report.md");
    }
    // The main table: one row per variant, every numeric cell finite.
    let table: Vec<&str> = md
        .split("## All variants")
        .nth(1)
        .unwrap()
        .lines()
        .take_while(|l| !l.starts_with("## "))
        .filter(|l| l.starts_with('|'))
        .skip(2)
        .collect();
    assert_eq!(table.len(), r.results.len(), "{table:#?}");
    for (line, x) in table.iter().zip(&r.results) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        assert_eq!(cells[1], x.variant.name);
        // max, RMS, %, NaN px, then one time per size.
        for c in &cells[3..7 + settings.time_sizes.len()] {
            let v: f64 = c.parse().unwrap_or_else(|_| panic!("{c:?} in {line}"));
            assert!(v.is_finite(), "{line}");
        }
    }
    // --quick leaves numerical-stability.md alone.
    assert!(!out.join("numerical-stability.md").exists());
}

#[test]
fn the_compared_programs_are_minimal() {
    // The report's own variants (no shared scenes needed, no GPU).
    for v in report::variants(report::Extent::Full, None).unwrap() {
        if v.program == ProgramKind::Specialised {
            let p = v.shaders().unwrap();
            let ver = verify(&p);
            assert!(ver.is_minimal(), "{}: {ver:#?}", v.name);
        }
    }
    // The shared seed scenes' library programs.
    let Some(dir) = shared_scenes() else {
        return;
    };
    for name in SEED_SCENES {
        let scene = essl_scene::Scene::load(dir.join(format!("{name}.json"))).unwrap();
        let lit = presets::seed_equivalent(&scene).unwrap().unwrap();
        let p = generate(&lit).unwrap();
        let v = verify(&p);
        assert!(v.inactive_uniforms.is_empty(), "{name}: {v:#?}");
        assert!(v.unused_functions.is_empty(), "{name}: {v:#?}");
        assert!(v.is_minimal(), "{name}: {v:#?}");
        // The uber-shader declares more than it uses for every one of them.
        let u = verify(&generate_uber());
        assert!(u.active_uniforms.len() > v.active_uniforms.len(), "{name}");
    }
}
