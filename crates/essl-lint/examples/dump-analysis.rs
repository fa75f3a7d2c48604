//! Prints what the analysis knows about every expression of a shader's functions (span text and
//! value), for debugging a finding: `cargo run -p essl-lint --example dump-analysis -- FILE`.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

fn main() {
    for path in std::env::args().skip(1) {
        let p = std::path::Path::new(&path);
        let stage = Stage::from_path(p).unwrap_or(Stage::Fragment);
        let text = std::fs::read_to_string(p).expect("a readable file");
        let shader = compile(
            SourceFile::new(path.clone(), text),
            stage,
            &CompileOptions::default(),
        );
        print!("{}", essl_lint::dump(&shader));
    }
}
