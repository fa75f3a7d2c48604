//! Lints shader files and prints the findings as people read them:
//! `cargo run -p essl-lint --example lint-files -- shaders-glsl/*.frag`.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

fn main() {
    for path in std::env::args().skip(1) {
        let p = std::path::Path::new(&path);
        let Some(stage) = Stage::from_path(p) else {
            continue;
        };
        let text = std::fs::read_to_string(p).expect("readable file");
        let shader = compile(
            SourceFile::new(path.clone(), text),
            stage,
            &CompileOptions::default(),
        );
        if !shader.ok() {
            println!("{path}: does not compile");
            continue;
        }
        for d in essl_lint::lint(&shader, &essl_lint::LintOptions::default().notes(true)) {
            let lc = shader.file.line_col(d.span.start);
            println!(
                "{path}:{lc}: {}: {} [{}] {}",
                d.severity.as_str(),
                d.message,
                d.code,
                d.label
            );
            for s in &d.secondary {
                println!("    {}: {}", shader.file.line_col(s.span.start), s.message);
            }
            if let Some(h) = d.help_text(&shader.file) {
                println!("    help: {h}");
            }
        }
    }
}
