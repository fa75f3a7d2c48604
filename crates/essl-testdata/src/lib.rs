//! Where essl's tests find the data that does not live in the repository — the conformance
//! corpora, the seed scenes with Chromium's reference pictures, the seed articles, the WebGL
//! specifications and IDL — and what a test does when it is missing.
//!
//! Each folder is looked up in this order:
//! 1. an environment variable (`ESSL_CORPORA`, `ESSL_SCENES`, `ESSL_SEEDS`, `ESSL_SPECS`), for
//!    data fetched elsewhere (`scripts/fetch-test-data.sh` writes `test-data/corpora`);
//! 2. `../shared/<name>` beside the repository, where the project's own machines keep it.
//!
//! When neither exists the test **skips** with a message on stderr — a user's clone or a fork's
//! CI has no `../shared` — unless `ESSL_REQUIRE_CORPORA=1` is set (`.ci/run` sets it), which
//! turns the skip into a failure. `CI` is deliberately not consulted: every fork's CI sets it.
//!
//! The same holds for a Vulkan adapter: tests that render skip without one unless
//! `ESSL_REQUIRE_ADAPTER=1` is set ([`adapter_missing`]).

#![deny(missing_docs)]

use std::path::{Path, PathBuf};

/// The environment variable that turns a missing data folder into a test failure.
pub const REQUIRE_CORPORA: &str = "ESSL_REQUIRE_CORPORA";
/// The environment variable that turns a missing Vulkan adapter into a test failure.
pub const REQUIRE_ADAPTER: &str = "ESSL_REQUIRE_ADAPTER";

/// The repository's root (the workspace folder).
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn flag(name: &str) -> bool {
    std::env::var_os(name).is_some_and(|v| v == "1" || v == "true")
}

/// Whether a missing data folder fails instead of skipping (`ESSL_REQUIRE_CORPORA=1`).
pub fn data_required() -> bool {
    flag(REQUIRE_CORPORA)
}

/// Where `name` (`corpora`, `scenes`, `seeds`) is looked for: the variable's value, or
/// `../shared/NAME` beside the repository.
pub fn location(var: &str, name: &str) -> PathBuf {
    match std::env::var_os(var) {
        Some(dir) if !dir.is_empty() => PathBuf::from(dir),
        _ => repo_root().join("../shared").join(name),
    }
}

fn find(var: &str, name: &str, what: &str) -> Option<PathBuf> {
    let dir = location(var, name);
    if dir.is_dir() {
        return Some(dir);
    }
    if data_required() {
        panic!(
            "{REQUIRE_CORPORA}=1 but {} is missing: {what} are required (set {var}, or put \
             shared/ beside the repository)",
            dir.display()
        );
    }
    eprintln!(
        "SKIPPED: {} is absent ({what}; set {var} or run scripts/fetch-test-data.sh)",
        dir.display()
    );
    None
}

/// The JavaScript libraries `scripts/fetch-js-libs.sh` installs (`tests/js/node_modules`:
/// deck.gl, luma.gl, three.js at pinned versions), or `None` after a skip message.
///
/// # Panics
/// When they are not installed and `ESSL_REQUIRE_CORPORA=1`.
pub fn js_libraries() -> Option<PathBuf> {
    let dir = repo_root().join("tests/js");
    if dir.join("node_modules/.essl-lock").is_file() {
        return Some(dir);
    }
    if data_required() {
        panic!(
            "{REQUIRE_CORPORA}=1 but {} has no node_modules: run scripts/fetch-js-libs.sh",
            dir.display()
        );
    }
    eprintln!(
        "SKIPPED: {}/node_modules is absent (the pinned JavaScript libraries; run \
         scripts/fetch-js-libs.sh)",
        dir.display()
    );
    None
}

/// The conformance corpora (`ESSL_CORPORA`, or `../shared/corpora`), or `None` after a skip
/// message.
///
/// # Panics
/// When the folder is missing and `ESSL_REQUIRE_CORPORA=1`.
pub fn corpora() -> Option<PathBuf> {
    find("ESSL_CORPORA", "corpora", "the conformance corpora")
}

/// The seed scenes with Chromium's reference PNGs (`ESSL_SCENES`, or `../shared/scenes`), or
/// `None` after a skip message.
///
/// # Panics
/// When the folder is missing and `ESSL_REQUIRE_CORPORA=1`.
pub fn scenes() -> Option<PathBuf> {
    find("ESSL_SCENES", "scenes", "the seed scenes")
}

/// The seed articles (`ESSL_SEEDS`, or `../shared/seeds`), or `None` after a skip message.
///
/// # Panics
/// When the folder is missing and `ESSL_REQUIRE_CORPORA=1`.
pub fn seeds() -> Option<PathBuf> {
    find("ESSL_SEEDS", "seeds", "the seed articles")
}

/// The WebGL 1 and 2 specifications and IDL (`ESSL_SPECS`, or `../shared/specs`), or `None`
/// after a skip message.
///
/// # Panics
/// When the folder is missing and `ESSL_REQUIRE_CORPORA=1`.
pub fn specs() -> Option<PathBuf> {
    find("ESSL_SPECS", "specs", "the WebGL specifications")
}

/// One corpus file (`corpora()/NAME`), or `None` after a skip message.
///
/// # Panics
/// When the file is missing and `ESSL_REQUIRE_CORPORA=1`.
pub fn corpus_file(name: &str) -> Option<PathBuf> {
    let path = corpora()?.join(name);
    if path.is_file() {
        return Some(path);
    }
    if data_required() {
        panic!("{REQUIRE_CORPORA}=1 but {} is missing", path.display());
    }
    eprintln!("SKIPPED: {} is absent", path.display());
    None
}

/// Makes a GPU object with `make` (a context, an adapter, a runner); when `make` fails, `None`
/// after [`adapter_missing`]'s skip message. (essl-gl's `Context` gives the Vulkan loader an
/// `XDG_RUNTIME_DIR` of its own where the environment has none.)
///
/// # Panics
/// When `make` fails and `ESSL_REQUIRE_ADAPTER=1`.
pub fn with_adapter<T, E: std::fmt::Display>(make: impl FnOnce() -> Result<T, E>) -> Option<T> {
    match make() {
        Ok(made) => Some(made),
        Err(e) => {
            adapter_missing(&e);
            None
        }
    }
}

/// Call when no Vulkan adapter could be had: prints a skip message and returns, or panics when
/// `ESSL_REQUIRE_ADAPTER=1`.
///
/// # Panics
/// When `ESSL_REQUIRE_ADAPTER=1`.
pub fn adapter_missing(error: &dyn std::fmt::Display) {
    if flag(REQUIRE_ADAPTER) {
        panic!("{REQUIRE_ADAPTER}=1 but no Vulkan adapter could be had: {error}");
    }
    eprintln!("SKIPPED: no Vulkan adapter ({error}); install mesa-vulkan-drivers for lavapipe");
}
