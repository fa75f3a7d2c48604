fn main() {
    for path in std::env::args().skip(1) {
        let src = std::fs::read_to_string(&path).unwrap();
        let t = std::time::Instant::now();
        let sh = essl::compile(
            essl::source::SourceFile::new(&path, src),
            essl::Stage::Fragment,
            &Default::default(),
        );
        println!(
            "{path}: {:?} ok={} errors={} first={:?}",
            t.elapsed(),
            sh.ok(),
            sh.error_count(),
            sh.diagnostics.first().map(|d| &d.message)
        );
    }
}
