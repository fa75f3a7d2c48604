//! `essl lint`: a straight pipeline.
//!
//! 1. [`crate::discover`] finds the inputs (files, folders, standard input, shaders inside
//!    HTML and JS files);
//! 2. [`check`] reads, fixes, compiles, lints and links them on a thread pool, rendering each
//!    result where its shader was compiled (a host file's shaders moved onto its lines by
//!    [`relocate`]);
//! 3. [`results`] holds what that gives, and the totals and exit status;
//! 4. [`output`] renders a result in the chosen format ([`lines`] for the one-line formats and
//!    `--statistics`) and writes everything in a stable order.
//!
//! The options are read once: what checking needs stays in [`LintOptions`], what rendering
//! needs is resolved into a [`options::Look`] (colour decided against the terminal).

mod check;
mod fix;
mod include;
mod json;
mod lines;
mod options;
mod output;
mod relocate;
mod results;

use std::io::{IsTerminal, Write};

pub use options::{ColorMode, Format, LintOptions, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};

use crate::discover::{Input, Source};
use crate::files;
use options::Look;

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

/// The shaders to check, in order: shader files and standard input, then each host file's
/// shaders that are not skipped.
fn inputs(found: &crate::discover::Found) -> Vec<Input> {
    let mut inputs = found.inputs.clone();
    for host in &found.hosts {
        for (k, e) in host.embedded.iter().enumerate() {
            if let (None, Some(stage)) = (e.skip, e.stage) {
                inputs.push(Input {
                    path: host.path.clone(),
                    stage,
                    source: Source::Embedded(host.clone(), k),
                });
            }
        }
    }
    inputs
}

/// Runs `essl lint` and returns the exit status.
pub fn run(options: &LintOptions) -> i32 {
    let found = match options.finder.find(&options.paths) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    let inputs = inputs(&found);
    if inputs.is_empty() && found.errors.is_empty() {
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
            eprintln!("skipped {}: {}", s.at, s.reason);
        }
        return EXIT_USAGE;
    }
    let bar = progress_bar(inputs.len());
    let tick = || {
        if let Some(bar) = &bar {
            bar.inc(1);
        }
    };
    let look = Look::of(options);
    let mut results = check::check(&inputs, options, look, &tick);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    results.collect_errors = found.errors;
    results.skipped = found.skipped;

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let written = if options.diff {
        output::write_fixed(&mut out, &results, true)
    } else if options.statistics {
        out.write_all(lines::statistics(&results).as_bytes())
    } else if options.fix && inputs.iter().any(is_stdin) {
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
            eprintln!("error: cannot write the output: {}", files::io_message(&e));
            return EXIT_USAGE;
        }
    }
    results.exit_status(options.deny_warnings, options.exit_zero, options.diff)
}

/// Whether an input is (inside) standard input.
fn is_stdin(input: &Input) -> bool {
    match &input.source {
        Source::Text(_) => true,
        Source::Embedded(host, _) => host.stdin,
        Source::File => false,
    }
}
