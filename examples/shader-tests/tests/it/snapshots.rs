//! Snapshot tests of shaders, as a project would write them for its own `shaders/` folder:
//! `essl::snapshot` gives stable text (no colour, no absolute path) that `insta` keeps in
//! `tests/snapshots/`. A change in what essl reports about a shader shows up as a snapshot
//! diff to review (`cargo insta review`).

use std::path::{Path, PathBuf};

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The `NAME.vert` + `NAME.frag` pairs under `dir` that `keep` accepts, found as `essl lint`
/// and the build script find them.
fn programs(dir: &Path, keep: impl Fn(&Path) -> bool) -> Vec<(String, PathBuf, PathBuf)> {
    let configs = essl_check::Configs::new(essl_check::Overrides::default());
    let found = essl_check::find(
        &[dir.to_path_buf()],
        &essl_check::FindOptions::new(),
        &configs,
    )
    .expect("a folder");
    assert!(found.errors.is_empty(), "{:?}", found.errors);
    let files: Vec<essl_check::ShaderFile> = found
        .inputs
        .iter()
        .map(|i| essl_check::ShaderFile {
            path: i.path.clone(),
            stage: i.stage,
        })
        .collect();
    essl_check::pairs(&files)
        .into_iter()
        .filter(|&(v, _)| keep(&files[v].path))
        .map(|(v, f)| {
            let name = essl_build::module_name(dir, &files[v].path);
            (name, files[v].path.clone(), files[f].path.clone())
        })
        .collect()
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
