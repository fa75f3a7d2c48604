//! Snapshot tests of shaders, as a project would write them for its own `shaders/` folder:
//! `essl::snapshot` gives stable text (no colour, no absolute path) that `insta` keeps in
//! `tests/snapshots/`. A change in what essl reports about a shader shows up as a snapshot
//! diff to review (`cargo insta review`).

use std::path::{Path, PathBuf};

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The `NAME.vert` + `NAME.frag` pairs under `dir` that `keep` accepts.
fn programs(dir: &Path, keep: impl Fn(&Path) -> bool) -> Vec<(String, PathBuf, PathBuf)> {
    let (files, errors) = essl_build_files(dir);
    assert!(errors == 0, "{} cannot be listed", dir.display());
    let pairs = essl_build::files::pairs(&files);
    pairs
        .into_iter()
        .filter(|&(v, _)| keep(&files[v].path))
        .map(|(v, f)| {
            let name = essl_build::module_name(dir, &files[v].path);
            (name, files[v].path.clone(), files[f].path.clone())
        })
        .collect()
}

fn essl_build_files(dir: &Path) -> (Vec<essl_build::files::ShaderFile>, usize) {
    let (files, errors) = essl_build::files::walk(dir, &mut |_| true);
    (files, errors.len())
}

#[test]
fn this_crates_shaders() {
    let dir = crate_dir().join("shaders");
    for (name, v, f) in programs(&dir, |_| true) {
        insta::assert_snapshot!(name, essl::snapshot::program(&v, &f));
    }
}

/// Every seed program: the corrected twins link, and the verbatim shaders that have a twin
/// show the errors the articles printed.
#[test]
fn the_seeds() {
    let dir = crate_dir().join("../../shaders-glsl");
    let found = programs(&dir, |_| true);
    assert!(found.len() >= 20, "{} seed programs", found.len());
    for (name, v, f) in found {
        insta::assert_snapshot!(format!("seed_{name}"), essl::snapshot::program(&v, &f));
    }
}

/// What a browser's info logs say about the article's verbatim spot light.
#[test]
fn a_browsers_info_logs() {
    let dir = crate_dir().join("../../shaders-glsl");
    insta::assert_snapshot!(essl::snapshot::program_info_log(
        dir.join("spot-smooth-nbsp.vert"),
        dir.join("spot-smooth-nbsp.frag")
    ));
}
