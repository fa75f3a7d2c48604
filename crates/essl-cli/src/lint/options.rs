//! What `essl lint` was asked to do, and the part of it that decides how results look.

use std::io::IsTerminal;
use std::path::PathBuf;

/// Exit status: nothing to report, or only warnings.
pub const EXIT_OK: i32 = 0;
/// Exit status: some shader or program has an error (or a denied warning).
pub const EXIT_ERRORS: i32 = 1;
/// Exit status: a usage error, or a file that could not be read or written.
pub const EXIT_USAGE: i32 = 2;

/// When to colour the human output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ColorMode {
    /// Colour when stdout is a terminal (and `NO_COLOR` is not set).
    #[default]
    Auto,
    /// Always colour (ANSI escapes).
    Always,
    /// Never colour.
    Never,
}

impl ColorMode {
    /// Whether to colour stdout.
    pub fn enabled(self) -> bool {
        match self {
            ColorMode::Always => true,
            ColorMode::Never => false,
            ColorMode::Auto => {
                std::io::stdout().is_terminal()
                    && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
                    && std::env::var("TERM").map_or(true, |t| t != "dumb")
            }
        }
    }
}

/// An output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// rustc-style diagnostics and a summary line.
    #[default]
    Human,
    /// JSON Lines: one object per shader, then one per program, then a summary.
    Json,
    /// One SARIF 2.1.0 log of every file's diagnostics, for code-scanning services.
    Sarif,
    /// GitHub Actions workflow commands: `::error file=…,line=…,col=…::message`, which a run
    /// shows as annotations on the pull request's lines.
    Github,
    /// One line per diagnostic: `FILE:LINE:COL: severity[code]: message`.
    Concise,
}

/// What `essl lint` was asked to do.
#[derive(Clone, Debug, Default)]
pub struct LintOptions {
    /// Files and folders to check (`-`: standard input).
    pub paths: Vec<PathBuf>,
    /// How to find the shaders in them.
    pub finder: crate::discover::Finder,
    /// Output format.
    pub format: Format,
    /// Colours of the human output.
    pub color: ColorMode,
    /// `--fix`: apply the certain fixes in place.
    pub fix: bool,
    /// `--unsafe-fixes`: under `--fix`, apply the suggested fixes too.
    pub unsafe_fixes: bool,
    /// `--diff`: under `--fix`, print what the fixes would change instead of writing it.
    pub diff: bool,
    /// `--quiet`: print the diagnostics and nothing else (no summary, no linked programs).
    pub quiet: bool,
    /// `--statistics`: print how often each code occurs instead of the diagnostics.
    pub statistics: bool,
    /// `--exit-zero`: exit 0 even where errors were found (still 2 for usage or I/O errors).
    pub exit_zero: bool,
    /// `--deny warnings`: warnings fail the run.
    pub deny_warnings: bool,
    /// `--show-notes`: print the lints' notes (counted in the summary either way).
    pub show_notes: bool,
    /// `-D NAME[=VALUE]` macros.
    pub defines: Vec<(String, String)>,
    /// `-I DIR` (and essl.toml's `include`): folders `#include "FILE"` searches after the
    /// including file's own; empty, `#include` stays an error as GLSL ES has it.
    pub include_dirs: Vec<PathBuf>,
    /// Link `NAME.vert` + `NAME.frag` pairs (on unless `--no-link`).
    pub link: bool,
    /// `--target`: the WebGL version of the context (WebGL 2 unless asked).
    pub target: essl::Target,
    /// Which numerical-hazard lints run and how loud (`--allow/--warn/--deny RULE`).
    pub rules: essl_lint::LintOptions,
}

/// How results are rendered: decided once from the options (colour resolved against the
/// terminal), then handed to the checking threads and the final write.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Look {
    /// The output format.
    pub format: Format,
    /// Whether the human output is coloured.
    pub color: bool,
    /// Whether `--fix` ran (the output then says how many fixes were applied).
    pub fix: bool,
    /// `--quiet`: only the diagnostics.
    pub quiet: bool,
    /// Whether warnings fail the run (the summary then says so).
    pub deny_warnings: bool,
    /// The WebGL version checked for (named in the JSON output).
    pub target: essl::Target,
}

impl Look {
    /// The look `options` ask for, with `ColorMode::Auto` resolved against stdout.
    pub fn of(options: &LintOptions) -> Look {
        Look {
            format: options.format,
            color: options.format == Format::Human && options.color.enabled(),
            fix: options.fix,
            quiet: options.quiet,
            deny_warnings: options.deny_warnings,
            target: options.target,
        }
    }
}
