//! Every call script of `tests/gl-scripts/` (eight multi-pass programs and the probes) replayed
//! through essl-gl and compared with what Chromium answered and drew
//! (`tests/gl-scripts/chromium/`, `tests/gl-scripts/probes/chromium/`): every error a call
//! names, every status, every record (floats the GPU computed within 1e-5 relative; the
//! answers `docs/gl-scripts.md` lists as the GPU's or browser's own are printed, not
//! required), and the picture — at least 99.9 % of the pixels within 3/255, or the bar
//! `essl_gl_script::compare::picture_bar` gives the three programs whose pictures turn on the
//! rasterizer's rounding. Calls where essl-gl answers as the specification says and Chromium
//! does not are printed, not required.
//!
//! The scripts and Chromium's answers are committed, so only a Vulkan adapter is needed:
//! without one the test prints why and passes, unless `ESSL_REQUIRE_ADAPTER=1`. essl-gl's
//! pictures and difference images go to Cargo's per-target temporary folder (printed).

use std::path::{Path, PathBuf};

use crate::common;

use common::{adapter, scripts};
use essl_gl_script::{compare, read_script, replay, ReplayOptions, Results};
use essl_scene::{diff_image, RgbaImage};

/// Replays each script of `dir` against `dir/chromium/`; the problems found.
fn run(dir: &Path, out: &Path) -> (usize, Vec<String>) {
    std::fs::create_dir_all(out).unwrap();
    let mut problems = Vec::new();
    let paths = scripts(dir);
    for path in &paths {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let script = read_script(path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let ours =
            replay(&script, &ReplayOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let chromium = dir.join("chromium");
        let text = std::fs::read_to_string(chromium.join(format!("{name}.json"))).unwrap();
        let theirs = Results::from_json(&text).unwrap();
        let picture = RgbaImage::read_png(&chromium.join(format!("{name}.png"))).unwrap();
        let c = compare(
            &name,
            &script,
            (&ours.results, &ours.picture),
            (&theirs, &picture),
        )
        .unwrap();
        ours.picture
            .write_png(&out.join(format!("{name}.png")))
            .unwrap();
        let mut mine: Vec<String> = Vec::new();
        for f in &ours.results.failures {
            if essl_gl_script::compare::spec_over_chromium(&name, f) {
                println!("{name}: as the specification says, not as Chromium: {f}");
            } else {
                mine.push(format!("{name}: {f}"));
            }
        }
        mine.extend(c.mismatches.iter().map(|m| format!("{name}: record {m}")));
        if !c.picture_matches() {
            diff_image(&ours.picture, &picture, c.bar.within)
                .unwrap()
                .write_png(&out.join(format!("{name}.diff.png")))
                .unwrap();
            mine.push(format!(
                "{name}: picture {:.3}% within {}/255 (need {}%), worst {:?}",
                c.picture.fraction_within() * 100.0,
                c.bar.within,
                c.bar.fraction * 100.0,
                c.picture.worst
            ));
        }
        for m in &c.allowed {
            println!("{name}: differs where the GPU may: {m}");
        }
        println!(
            "{name:<36} {:>8.3}% within  {}",
            c.picture.fraction_within() * 100.0,
            if mine.is_empty() { "ok" } else { "FAILED" }
        );
        problems.extend(mine);
    }
    (paths.len(), problems)
}

fn gl_scripts() -> PathBuf {
    essl_testdata::repo_root().join("tests/gl-scripts")
}

#[test]
fn multi_pass_programs_match_chromium() {
    if !adapter() {
        return;
    }
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gl-scripts");
    println!("pictures in {}", out.display());
    let (n, problems) = run(&gl_scripts(), &out);
    assert_eq!(n, 8, "the eight multi-pass programs");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn probes_match_chromium() {
    if !adapter() {
        return;
    }
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gl-probes");
    println!("pictures in {}", out.display());
    let (n, problems) = run(&gl_scripts().join("probes"), &out);
    assert!(n >= 69, "{n} probes");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}
