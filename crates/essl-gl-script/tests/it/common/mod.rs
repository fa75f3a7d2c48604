//! What the call-script tests share: the scripts of a folder, and whether a Vulkan adapter is
//! there.

use std::path::{Path, PathBuf};

/// Whether essl-gl can make a context; without one, prints why (or panics when
/// `ESSL_REQUIRE_ADAPTER=1`).
pub fn adapter() -> bool {
    essl_testdata::with_adapter(|| essl_gl::Context::new(1, 1)).is_some()
}

/// The `*.json` scripts of `dir`, sorted.
pub fn scripts(dir: &Path) -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    paths
}
