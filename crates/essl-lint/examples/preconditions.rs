//! Prints the uniform preconditions of shaders, one line each (`file:line:col rule: condition
//! — message`): `cargo run -p essl-lint --example preconditions -- FILE…`.
fn main() {
    for path in std::env::args().skip(1) {
        let Some(stage) = essl::Stage::from_path(std::path::Path::new(&path)) else {
            eprintln!("{path}: not a .vert or .frag file");
            continue;
        };
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("{path}: {e}");
                continue;
            }
        };
        let shader = essl::compile(
            essl::source::SourceFile::new(path.clone(), text),
            stage,
            &essl::CompileOptions::default(),
        );
        for p in essl_lint::preconditions(&shader) {
            let reported = if p.reported { " [static finding]" } else { "" };
            println!("{}{reported}", p.describe(&shader.file));
        }
    }
}
