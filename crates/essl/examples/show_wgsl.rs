//! Prints the naga module essl lowers a shader to, as WGSL (development aid).
fn main() {
    let path = std::env::args().nth(1).expect("path");
    let src = std::fs::read_to_string(&path).unwrap();
    let stage = essl::Stage::from_path(std::path::Path::new(&path)).unwrap();
    let sh = essl::compile(
        essl::source::SourceFile::new(&path, src),
        stage,
        &Default::default(),
    );
    for d in &sh.diagnostics {
        eprintln!("{}: {}", d.code, d.message);
    }
    let lowered = sh.naga.expect("lowered");
    let (m, info) = (&lowered.module, lowered.info().expect("validated"));
    let out = naga::back::wgsl::write_string(m, info, naga::back::wgsl::WriterFlags::empty());
    match out {
        Ok(s) => println!("{s}"),
        Err(e) => println!("wgsl-out error: {e:?}"),
    }
    let spv = naga::back::spv::write_vec(m, info, &Default::default(), None);
    println!("// spv: {:?}", spv.map(|v| v.len()));
}
