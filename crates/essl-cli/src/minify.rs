//! `essl minify FILE`: one shader file checked as `essl lint` checks it (its folder's
//! essl.toml, its `#include`s), then minified ([`essl_check::minify`]): comments, white space
//! and local names go, every name WebGL sees stays, and the output is compiled again and its
//! interface compared with the original's before it is written. A shader with errors is not
//! minified: its diagnostics are printed as `essl lint` prints them.

use std::path::PathBuf;

use essl::{Stage, Target};

/// What `essl minify` was asked.
#[derive(Clone, Debug)]
pub struct MinifyArgs {
    /// The shader file.
    pub path: PathBuf,
    /// Its stage, where the extension does not tell it.
    pub stage: Option<Stage>,
    /// The WebGL version, over essl.toml's.
    pub target: Option<Target>,
    /// Macros, as `NAME` or `NAME=VALUE`.
    pub defines: Vec<String>,
    /// Keep local names (comments and white space only).
    pub no_rename: bool,
    /// Where to write (default: standard output).
    pub out: Option<PathBuf>,
}

/// Runs `essl minify`; the exit status (0 minified, 1 the shader has errors or the output
/// failed its check, 2 usage or I/O errors).
pub fn run(args: &MinifyArgs) -> i32 {
    let text = match essl_check::read_source(&args.path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: {}: {e}", args.path.display());
            return 2;
        }
    };
    let configs = essl_check::Configs::new(essl_check::Overrides {
        stage: args.stage,
        target: args.target,
        defines: args
            .defines
            .iter()
            .map(|d| match d.split_once('=') {
                Some((n, v)) => (n.to_string(), v.to_string()),
                None => (d.clone(), "1".to_string()),
            })
            .collect(),
        ..essl_check::Overrides::default()
    });
    let options = essl_check::CheckOptions {
        lints: false,
        link: false,
        ..essl_check::CheckOptions::default()
    };
    let files = essl_check::Files::disk();
    let unit = match essl_check::check_text(&args.path, text, &configs, &files, options) {
        Ok((unit, _)) => unit,
        Err(e) => {
            eprintln!("error: {e}");
            return 2;
        }
    };
    let [shader] = unit.shaders.as_slice() else {
        eprintln!(
            "error: {} is not one shader (essl minify takes a .vert/.frag file)",
            args.path.display()
        );
        return 2;
    };
    if !shader.ok() {
        for g in &shader.diagnostics {
            eprint!("{}", essl::render::human_string(&g.file, &g.diagnostics));
        }
        return 1;
    }
    let minified = match essl_check::minify(shader, !args.no_rename) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {}: {e}", args.path.display());
            return 1;
        }
    };
    match &args.out {
        None => {
            println!("{}", minified.text);
            0
        }
        Some(path) => match std::fs::write(path, &minified.text) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: {}: {e}", path.display());
                2
            }
        },
    }
}
