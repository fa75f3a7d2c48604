//! `essl lint`: check shaders (in parallel), link the pairs, print the results in a stable order
//! and decide the exit status.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;

use essl::link::link;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use rayon::prelude::*;

use crate::files::{self, CollectError, Input, ReadError};
use crate::fix;
use crate::output::{self, Format, Totals};

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

/// What `essl lint` was asked to do.
#[derive(Clone, Debug, Default)]
pub struct LintOptions {
    /// Files and folders to check.
    pub paths: Vec<PathBuf>,
    /// `--stage`: the stage of named files whose extension does not tell.
    pub stage: Option<Stage>,
    /// Output format.
    pub format: Format,
    /// Colours of the human output.
    pub color: ColorMode,
    /// `--fix`: apply the certain fixes in place.
    pub fix: bool,
    /// `--deny warnings`: warnings fail the run.
    pub deny_warnings: bool,
    /// `-D NAME[=VALUE]` macros.
    pub defines: Vec<(String, String)>,
    /// Link `NAME.vert` + `NAME.frag` pairs (on unless `--no-link`).
    pub link: bool,
    /// Which numerical-hazard lints run and how loud (`--allow/--warn/--deny RULE`).
    pub rules: essl_lint::LintOptions,
}

/// A shader that was read and compiled.
#[derive(Debug)]
pub struct Checked {
    /// The compiled shader (after `--fix`, of the fixed text).
    pub shader: Shader,
    /// How many fixes `--fix` applied.
    pub fixes_applied: usize,
    /// Why the fixed text could not be written back, if it could not.
    pub write_error: Option<String>,
}

/// Adds the numerical-hazard lints to a compiled shader's diagnostics.
fn add_lints(shader: &mut Shader, options: &LintOptions) {
    let found = essl_lint::lint(shader, &options.rules);
    if !found.is_empty() {
        shader.diagnostics.extend(found);
        essl::diagnostic::sort(&mut shader.diagnostics);
    }
}

/// Reads, (fixes,) compiles and lints one file.
pub fn check_file(input: &Input, options: &LintOptions) -> Result<Checked, ReadError> {
    check_file_unlinted(input, options).map(|mut c| {
        add_lints(&mut c.shader, options);
        c
    })
}

fn check_file_unlinted(input: &Input, options: &LintOptions) -> Result<Checked, ReadError> {
    let compile_options = CompileOptions {
        defines: options.defines.clone(),
    };
    let name = input.path.display().to_string();
    files::read_source(&input.path).map(|text| {
        if options.fix {
            let fixed = fix::fix_text(&name, text, input.stage, &compile_options);
            let write_error = if fixed.applied > 0 {
                fix::write_atomically(&input.path, &fixed.text)
                    .err()
                    .map(|e| files::io_message(&e))
            } else {
                None
            };
            Checked {
                shader: fixed.shader,
                fixes_applied: fixed.applied,
                write_error,
            }
        } else {
            let shader = compile(SourceFile::new(name, text), input.stage, &compile_options);
            Checked {
                shader,
                fixes_applied: 0,
                write_error: None,
            }
        }
    })
}

/// One file's result, rendered in the requested format (shaders stay on the thread that
/// compiled them; what crosses threads is this).
#[derive(Debug)]
pub struct FileResult {
    /// The file.
    pub input: Input,
    /// Why it could not be read, if it could not.
    pub read_error: Option<String>,
    /// Why the fixed text could not be written back, if it could not.
    pub write_error: Option<String>,
    /// Whether it compiles.
    pub ok: bool,
    /// Its errors.
    pub errors: usize,
    /// Its warnings.
    pub warnings: usize,
    /// Fixes applied by `--fix`.
    pub fixes_applied: usize,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its text and diagnostics, kept for formats that need every file at once (SARIF).
    pub diagnostics: Option<(SourceFile, Vec<essl::diagnostic::Diagnostic>)>,
}

/// One linked pair's result, rendered.
#[derive(Debug)]
pub struct ProgramResult {
    /// The vertex shader.
    pub vertex: Input,
    /// The fragment shader.
    pub fragment: Input,
    /// Whether it was linked (both shaders compiled).
    pub linked: bool,
    /// Whether it links.
    pub ok: bool,
    /// Errors it adds to the totals (see [`output::program_counts`]).
    pub errors: usize,
    /// Warnings it adds to the totals.
    pub warnings: usize,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its link diagnostics with the file each points into, for formats that need every file
    /// at once (SARIF).
    pub diagnostics: Vec<(Option<PathBuf>, essl::diagnostic::Diagnostic)>,
}

/// Everything `essl lint` found, rendered, before printing.
#[derive(Debug, Default)]
pub struct LintResults {
    /// Paths that could not be listed.
    pub collect_errors: Vec<CollectError>,
    /// One result per file, sorted by path.
    pub files: Vec<FileResult>,
    /// One result per linked pair, sorted by the vertex shader's path.
    pub programs: Vec<ProgramResult>,
}

impl LintResults {
    /// Error and warning counts, and how many programs were linked.
    pub fn totals(&self) -> Totals {
        let mut t = Totals {
            files: self.files.len(),
            ..Totals::default()
        };
        for f in &self.files {
            t.errors += f.errors;
            t.warnings += f.warnings;
            t.fixes += f.fixes_applied;
        }
        for p in &self.programs {
            if p.linked {
                t.programs += 1;
            } else {
                t.unlinked += 1;
            }
            t.errors += p.errors;
            t.warnings += p.warnings;
        }
        t
    }

    /// Whether a file could not be listed, read or written back.
    pub fn has_io_errors(&self) -> bool {
        !self.collect_errors.is_empty()
            || self
                .files
                .iter()
                .any(|f| f.read_error.is_some() || f.write_error.is_some())
    }

    /// The exit status: 2 for I/O errors, 1 for errors (or warnings under `--deny warnings`),
    /// 0 otherwise.
    pub fn exit_status(&self, deny_warnings: bool) -> i32 {
        let t = self.totals();
        if self.has_io_errors() {
            EXIT_USAGE
        } else if t.errors > 0 || (deny_warnings && t.warnings > 0) {
            EXIT_ERRORS
        } else {
            EXIT_OK
        }
    }
}

/// What a unit of work gives: its files' results and, for a pair, the program's (each with
/// the index that sorts it).
type UnitResult = (Vec<(usize, FileResult)>, Option<(usize, ProgramResult)>);

/// A unit of work: one file, or a pair to compile and link on one thread.
enum Unit {
    Single(usize),
    Pair(usize, usize),
}

fn file_result(
    input: &Input,
    checked: &Result<Checked, ReadError>,
    options: &LintOptions,
    color: bool,
) -> FileResult {
    let rendered = output::render_file(input, checked, options, color);
    match checked {
        Err(e) => FileResult {
            input: input.clone(),
            read_error: Some(e.to_string()),
            write_error: None,
            ok: false,
            errors: 0,
            warnings: 0,
            fixes_applied: 0,
            rendered,
            diagnostics: None,
        },
        Ok(c) => FileResult {
            input: input.clone(),
            read_error: None,
            write_error: c.write_error.clone(),
            ok: c.shader.ok(),
            errors: c.shader.error_count(),
            warnings: c.shader.warning_count(),
            fixes_applied: c.fixes_applied,
            rendered,
            diagnostics: (options.format == Format::Sarif)
                .then(|| (c.shader.file.clone(), c.shader.diagnostics.clone())),
        },
    }
}

/// Checks the shaders in parallel, links the pairs (unless `options.link` is off) and renders
/// every result in `options.format`; `progress` is called once per file checked (from any
/// thread). Results come back sorted by path.
pub fn lint(
    inputs: &[Input],
    options: &LintOptions,
    color: bool,
    progress: &(dyn Fn() + Sync),
) -> LintResults {
    let pairs = if options.link {
        files::pairs(inputs)
    } else {
        Vec::new()
    };
    let mut paired = vec![false; inputs.len()];
    let mut units: Vec<Unit> = Vec::with_capacity(inputs.len());
    for &(v, f) in &pairs {
        paired[v] = true;
        paired[f] = true;
        units.push(Unit::Pair(v, f));
    }
    units.extend((0..inputs.len()).filter(|&i| !paired[i]).map(Unit::Single));
    let done: Vec<UnitResult> = units
        .par_iter()
        .map(|unit| match *unit {
            Unit::Single(i) => {
                let checked = check_file(&inputs[i], options);
                progress();
                (
                    vec![(i, file_result(&inputs[i], &checked, options, color))],
                    None,
                )
            }
            Unit::Pair(v, f) => {
                let vs = check_file(&inputs[v], options);
                progress();
                let fs = check_file(&inputs[f], options);
                progress();
                let program = match (&vs, &fs) {
                    (Ok(a), Ok(b)) => {
                        let program = link(&a.shader, &b.shader);
                        Some((
                            v,
                            output::program_result(
                                &inputs[v], &inputs[f], &a.shader, &b.shader, &program, options,
                                color,
                            ),
                        ))
                    }
                    _ => None,
                };
                (
                    vec![
                        (v, file_result(&inputs[v], &vs, options, color)),
                        (f, file_result(&inputs[f], &fs, options, color)),
                    ],
                    program,
                )
            }
        })
        .collect();
    let mut files: Vec<(usize, FileResult)> = Vec::with_capacity(inputs.len());
    let mut programs: Vec<(usize, ProgramResult)> = Vec::with_capacity(pairs.len());
    for (f, p) in done {
        files.extend(f);
        programs.extend(p);
    }
    files.sort_by_key(|(i, _)| *i);
    programs.sort_by_key(|(i, _)| *i);
    LintResults {
        collect_errors: Vec::new(),
        files: files.into_iter().map(|(_, f)| f).collect(),
        programs: programs.into_iter().map(|(_, p)| p).collect(),
    }
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
    let bar = (std::io::stderr().is_terminal() && collected.inputs.len() > 20).then(|| {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(collected.inputs.len() as u64),
            indicatif::ProgressDrawTarget::stderr(),
        );
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} checking {pos}/{len} shaders {wide_bar} {elapsed}",
        ) {
            bar.set_style(style);
        }
        bar
    });
    let tick = || {
        if let Some(bar) = &bar {
            bar.inc(1);
        }
    };
    let color = options.format == Format::Human && options.color.enabled();
    let mut results = lint(&collected.inputs, options, color, &tick);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    results.collect_errors = collected.errors;

    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let written = output::write(&mut out, &results, options, color).and_then(|()| out.flush());
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("error: cannot write the output: {}", files::io_message(&e));
            return EXIT_USAGE;
        }
    }
    results.exit_status(options.deny_warnings)
}
