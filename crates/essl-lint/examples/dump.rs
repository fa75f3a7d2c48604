//! Prints the analysis of a shader's expressions: `cargo run -p essl-lint --example dump -- FILE`.
fn main() {
    let path = std::env::args().nth(1).expect("a file");
    let stage = essl::Stage::from_path(std::path::Path::new(&path)).expect("a .vert or .frag file");
    let text = std::fs::read_to_string(&path).expect("readable");
    let shader = essl::compile(
        essl::source::SourceFile::new(path, text),
        stage,
        &essl::CompileOptions::default(),
    );
    print!("{}", essl_lint::dump(&shader));
}
