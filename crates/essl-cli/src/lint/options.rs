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
    pub find: essl_check::FindOptions,
    /// What the flags set on top of each folder's essl.toml: target, macros, include folders,
    /// rule levels, denied warnings, the stage of named files.
    pub overrides: essl_check::Overrides,
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
    /// `--show-notes`: print the lints' notes (counted in the summary either way).
    pub show_notes: bool,
    /// Link `NAME.vert` + `NAME.frag` pairs (on unless `--no-link`).
    pub link: bool,
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
    /// The WebGL version the run checks for, where the flags or the first path's essl.toml
    /// name it (named in the JSON summary).
    pub target: essl::Target,
}

impl Look {
    /// The look `options` ask for, with `ColorMode::Auto` resolved against stdout; `target` is
    /// the run's WebGL version.
    pub fn of(options: &LintOptions, target: essl::Target) -> Look {
        Look {
            format: options.format,
            color: options.format == Format::Human && options.color.enabled(),
            fix: options.fix,
            quiet: options.quiet,
            target,
        }
    }
}
