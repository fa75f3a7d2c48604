//! Bindings kept in the source tree stay those the generator writes today: essl-gl's
//! `spot_light` example keeps the bindings of the seeds' corrected spot light in
//! `crates/essl-gl/examples/spot_light/bindings.rs` (generated with the shaders' text inline,
//! so the example needs no build script). Run with `ESSL_BLESS=1` to rewrite it after a change
//! of the generator or of the shaders.

use std::path::Path;

use essl_build::bindings::{generate_with, Sources};
use essl_build::Check;

#[test]
fn spot_light_example_bindings_are_current() {
    let report = Check::new("../../shaders-glsl")
        .filter(|p| p.is_dir() || p.file_stem().is_some_and(|s| s == "spot-smooth-nbsp.fixed"))
        .run_with(&mut std::io::sink(), &mut std::io::sink())
        .unwrap();
    assert_eq!(report.programs.len(), 1);
    let text = generate_with(&report.programs, Sources::Inline);
    let path = Path::new("../essl-gl/examples/spot_light/bindings.rs");
    if std::env::var_os("ESSL_BLESS").is_some_and(|v| v == "1") {
        std::fs::write(path, &text).unwrap();
    }
    let kept = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        kept == text,
        "{} is not what the generator writes today: run `ESSL_BLESS=1 cargo test -p essl-build \
         --test it checked_in` and review the diff",
        path.display()
    );
}
