//! `spv-to-wgsl FILE.spv`: the WGSL naga writes for a SPIR-V module (its SPIR-V front end,
//! its validator, its WGSL writer), on standard output. Exit status 1 with naga's message
//! when a step fails.
//!
//! `spv-to-wgsl --check FILE.wgsl…`: reads each WGSL file with naga's WGSL front end and
//! validates it; prints `ok FILE` or `error FILE: message` for each, one a line.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--check") {
        for path in &args[1..] {
            match check(path) {
                Ok(()) => println!("ok {path}"),
                Err(e) => println!("error {path}: {}", e.replace('\n', " ")),
            }
        }
        return ExitCode::SUCCESS;
    }
    let Some(path) = args.first() else {
        eprintln!("usage: spv-to-wgsl FILE.spv | spv-to-wgsl --check FILE.wgsl…");
        return ExitCode::from(2);
    };
    match convert(path) {
        Ok(text) => {
            print!("{text}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{path}: {e}");
            ExitCode::from(1)
        }
    }
}

fn validator() -> naga::valid::Validator {
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
}

fn convert(path: &str) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    let options = naga::front::spv::Options::default();
    let module = naga::front::spv::parse_u8_slice(&bytes, &options).map_err(|e| e.to_string())?;
    let info = validator()
        .validate(&module)
        .map_err(|e| e.into_inner().to_string())?;
    naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| e.to_string())
}

fn check(path: &str) -> Result<(), String> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let module = naga::front::wgsl::parse_str(&text).map_err(|e| e.emit_to_string(&text))?;
    validator()
        .validate(&module)
        .map(|_| ())
        .map_err(|e| e.into_inner().to_string())
}
