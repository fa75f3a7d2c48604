//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};

mod docs;
mod examples;
mod idioms;
mod preconditions;
mod recall;
mod rules;
mod seeds;
mod variants;

/// `text` compiled as the fragment shader `name`, asserting that it compiles and is lowered
/// to naga IR (what the lints read).
fn compiled(name: &str, text: &str) -> Shader {
    let s = compile(
        SourceFile::new(name, text.to_string()),
        Stage::Fragment,
        &CompileOptions::default(),
    );
    assert!(s.ok(), "does not compile:\n{text}\n{:#?}", s.diagnostics);
    assert!(
        s.naga.is_some(),
        "not lowered:\n{text}\n{:#?}",
        s.diagnostics
    );
    s
}
