//! Runs the stiff-case matrix and writes its table into `docs/numerical-stability.md`, between the
//! `<!-- stiff-table:begin -->` and `<!-- stiff-table:end -->` markers.
//!
//! `cargo run -p essl-lights --bin stiff-table` rewrites the table; with `--check` it only
//! prints it and exits with status 1 if the document's table differs; with `--print` it only
//! prints it.

use std::path::PathBuf;
use std::process::ExitCode;

use essl_lights::stiff;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = args.iter().any(|a| a == "--check");
    let print = args.iter().any(|a| a == "--print");
    let rows = stiff::run();
    let table = stiff::markdown(&rows);
    let (total, seed_fail, lib_fail) = stiff::summary(&rows);
    let section = stiff::document_section(&rows);
    eprintln!(
        "{total} rows; the seed formula fails (at its own precision) in {seed_fail}; the \
         library's highp formula in {lib_fail}"
    );
    if print {
        println!("{table}");
        return ExitCode::SUCCESS;
    }
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/numerical-stability.md");
    let doc = match std::fs::read_to_string(&path) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("cannot read {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
    };
    let Some(updated) = stiff::replace_section(&doc, &section) else {
        eprintln!("{} has no stiff-table markers", path.display());
        return ExitCode::FAILURE;
    };
    if check {
        if updated == doc {
            eprintln!("{} is up to date", path.display());
            return ExitCode::SUCCESS;
        }
        eprintln!("{} differs from this run's table", path.display());
        return ExitCode::FAILURE;
    }
    if let Err(e) = std::fs::write(&path, updated) {
        eprintln!("cannot write {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    eprintln!("wrote {}", path.display());
    if lib_fail > 0 {
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
