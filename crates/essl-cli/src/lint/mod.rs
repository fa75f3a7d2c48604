//! `essl lint`: a straight pipeline.
//!
//! 1. [`crate::files`] collects the inputs (files and folders, stages from extensions);
//! 2. [`check`] reads, fixes, compiles, lints and links them on a thread pool, rendering each
//!    result where its shader was compiled;
//! 3. [`results`] holds what that gives, and the totals and exit status;
//! 4. [`output`] renders a result in the chosen format and writes everything in a stable order.
//!
//! The options are read once: what checking needs stays in [`LintOptions`], what rendering
//! needs is resolved into a [`options::Look`] (colour decided against the terminal).

mod check;
mod fix;
mod options;
mod output;
mod results;

use std::io::{IsTerminal, Write};

pub use options::{ColorMode, Format, LintOptions, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};

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

/// Runs `essl lint` and returns the exit status.
pub fn run(options: &LintOptions) -> i32 {
    let collected = match files::collect(&options.paths, options.stage) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    let bar = progress_bar(collected.inputs.len());
    let tick = || {
        if let Some(bar) = &bar {
            bar.inc(1);
        }
    };
    let look = Look::of(options);
    let mut results = check::check(&collected.inputs, options, look, &tick);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    results.collect_errors = collected.errors;

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let written = output::write(&mut out, &results, look).and_then(|()| out.flush());
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("error: cannot write the output: {}", files::io_message(&e));
            return EXIT_USAGE;
        }
    }
    results.exit_status(options.deny_warnings)
}
