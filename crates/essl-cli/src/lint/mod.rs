//! `essl lint`: the one checking pipeline ([`essl_check`]) with the command line's output.
//!
//! 1. [`essl_check::find`] finds the inputs (files, folders, standard input, shaders inside
//!    HTML and JS files);
//! 2. [`essl_check::run`] checks them on a thread pool, and [`check`] renders each unit's
//!    result on the thread that checked it (writing a fixed file back there);
//! 3. [`results`] holds what that gives, and the totals and exit status;
//! 4. [`output`] renders a result in the chosen format ([`lines`] for the one-line formats and
//!    `--statistics`) and writes everything in a stable order.
//!
//! The options are read once: what checking needs goes to the pipeline as
//! [`essl_check::Overrides`] and [`essl_check::CheckOptions`], what rendering needs is
//! resolved into a [`options::Look`] (colour decided against the terminal).

mod check;
mod json;
mod lines;
mod options;
mod output;
mod results;

use std::io::{IsTerminal, Write};

pub use options::{ColorMode, Format, LintOptions, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};

use essl_check::{CheckOptions, Configs, Files, FixMode};
use options::Look;
use results::LintResults;

/// A progress bar on stderr when it is a terminal and there are enough files to wait for.
fn progress_bar(files: usize) -> Option<indicatif::ProgressBar> {
    (std::io::stderr().is_terminal() && files > 20).then(|| {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(files as u64),
            indicatif::ProgressDrawTarget::stderr(),
        );
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} checking {pos}/{len} shaders {wide_bar} {elapsed}",
        ) {
            bar.set_style(style);
        }
        bar
    })
}

/// The WebGL version the run checks for, as the JSON summary names it: the flag's, or that of
/// the first path's essl.toml.
fn run_target(options: &LintOptions, configs: &Configs) -> essl::Target {
    if let Some(t) = options.overrides.target {
        return t;
    }
    let settings = options.paths.first().and_then(|p| {
        if p.as_os_str() == "-" {
            let name = options.find.stdin_name.clone().unwrap_or_default();
            configs.for_file(&name).ok()
        } else if p.is_dir() {
            configs.for_folder(p).ok()
        } else {
            configs.for_file(p).ok()
        }
    });
    settings.map_or(essl::Target::WebGl2, |s| s.compile.target)
}

/// Runs `essl lint` and returns the exit status.
pub fn run(options: &LintOptions) -> i32 {
    let configs = Configs::new(options.overrides.clone());
    if options.overrides.config.is_some() {
        if let Err(e) = configs.for_folder(std::path::Path::new(".")) {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    }
    let found = match essl_check::find(&options.paths, &options.find, &configs) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    if found.shader_count() == 0 && found.hosts.is_empty() && found.errors.is_empty() {
        let names: Vec<String> = options
            .paths
            .iter()
            .map(|p| format!("`{}`", p.display()))
            .collect();
        eprintln!(
            "error: no shaders found in {}{} (looked for .vert, .frag, .vs, .fs, .vsh, .fsh, \
             .glsl files, and shaders inside .html, .js and .ts files)",
            names.join(", "),
            if found.skipped.is_empty() {
                String::new()
            } else {
                format!("; {} skipped", found.skipped.len())
            }
        );
        for s in &found.skipped {
            eprintln!("skipped {}: {}", s.at, s.reason());
        }
        return EXIT_USAGE;
    }
    let bar = progress_bar(found.shader_count());
    let look = Look::of(options, run_target(options, &configs));
    let check_options = CheckOptions {
        link: options.link,
        lints: true,
        fix: match (options.fix, options.unsafe_fixes) {
            (false, _) => FixMode::Off,
            (true, false) => FixMode::Certain,
            (true, true) => FixMode::Suggested,
        },
        phase: essl_check::Phase::Full,
    };
    let sink = |_, unit: essl_check::CheckedUnit| {
        if let Some(bar) = &bar {
            bar.inc((unit.shaders.len() + unit.unread.len()) as u64);
        }
        check::unit_result(unit, options, look)
    };
    let mut files = Files::disk();
    let run = essl_check::run(&found, &configs, &mut files, check_options, &sink);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let mut results = LintResults {
        collect_errors: found.errors,
        skipped: found.skipped,
        ..LintResults::default()
    };
    for (f, p) in run.results {
        results.files.extend(f);
        results.programs.extend(p);
    }
    results.files.sort_by_key(|f| f.order);
    results.programs.sort_by_key(|p| p.order);
    let base = results.files.len();
    results.fixed_includes = run
        .fixed_includes
        .iter()
        .enumerate()
        .map(|(k, f)| check::fixed_include(f, base + k, options, look))
        .collect();

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let from_stdin = results.files.iter().any(|f| f.named.stdin);
    let written = if options.diff {
        output::write_fixed(&mut out, &results, true)
    } else if options.statistics {
        out.write_all(lines::statistics(&results).as_bytes())
    } else if options.fix && from_stdin {
        // The fixed text goes to stdout; the report to stderr.
        output::write_fixed(&mut out, &results, false).and_then(|()| {
            let mut err = std::io::stderr().lock();
            output::write(&mut err, &results, look)
        })
    } else {
        output::write(&mut out, &results, look)
    };
    if let Err(e) = written.and_then(|()| out.flush()) {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!(
                "error: cannot write the output: {}",
                essl_check::io_message(&e)
            );
            return EXIT_USAGE;
        }
    }
    results.exit_status(options.exit_zero, options.diff)
}
