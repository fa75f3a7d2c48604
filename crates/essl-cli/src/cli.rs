//! The `essl` command line: its arguments (clap) and the subcommand each runs. The binary
//! (`main.rs`) and the npm package's `npx essl` both call [`main_from`].

use std::ffi::OsString;
use std::path::PathBuf;

use crate::lint::{ColorMode, Format, LintOptions, EXIT_USAGE};
use clap::{Args, Parser, Subcommand, ValueEnum};
use essl::Stage;

/// WebGL shader toolkit: GLSL ES 3.00 and 1.00, for WebGL 2 and WebGL 1.
#[derive(Parser, Debug)]
#[command(name = "essl", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Check shaders as WebGL2 would, and link each NAME.vert + NAME.frag pair.
    ///
    /// Exit status: 0 clean (warnings allowed), 1 errors, 2 usage or I/O errors.
    Lint(Box<LintArgs>),
    /// Show the documentation of a diagnostic code or lint rule (all codes without one).
    Explain {
        /// A code (`missing-semicolon`, `pow-negative-base`…).
        code: Option<String>,
    },
    /// Run the Language Server over standard input and output, for editors (docs/editors.md).
    Server,
    /// Show the settings that apply to a folder: its nearest essl.toml, every key filled in.
    Config {
        /// The folder (or file) whose settings to show (default: the current folder).
        path: Option<PathBuf>,
        /// Read this essl.toml instead of looking upward for one.
        #[arg(long, value_name = "FILE")]
        config: Option<PathBuf>,
    },
    /// Score the front end on the conformance corpora (WebGL, dEQP, glslang, webgl2fundamentals).
    Conformance(ConformanceArgs),
    /// Translate shaders to WGSL, SPIR-V, MSL, HLSL or desktop GLSL (NAME.vert + NAME.frag
    /// pairs linked first), next to each input, into the folder -o names, or into the one
    /// file -o names.
    ///
    /// Exit status: 0 all translated, 1 some have errors or could not be translated, 2 usage
    /// or I/O errors.
    Translate(TranslateArgs),
    /// Minify a shader file: comments, white space and local names go; uniform, attribute,
    /// varying and output names stay; the output is compiled again and compared with the
    /// original before it is written.
    ///
    /// Exit status: 0 minified, 1 the shader has errors (not minified), 2 usage or I/O errors.
    Minify(MinifyArgs),
    /// Execute the dEQP value cases through essl's WebGL2 API as
    /// ../shared/tools/deqp-exec-oracle.py does in Chromium, with the same JSON Lines output.
    ///
    /// Exit status: 0 all pass, 1 some fail, 2 the corpus cannot be read or no context.
    #[cfg(feature = "render")]
    DeqpExec {
        /// The dEQP corpus.
        #[arg(
            default_value = "../shared/corpora/deqp_gles3.jsonl",
            value_name = "CORPUS"
        )]
        corpus: PathBuf,
        /// Only the cases whose name contains this.
        #[arg(long, value_name = "SUBSTRING")]
        only: Option<String>,
        /// Write the JSON lines to this file instead of standard output.
        #[arg(short = 'o', long = "output", value_name = "FILE")]
        output: Option<PathBuf>,
        /// Run each program from its WGSL translation (written, read back by naga's WGSL front
        /// end) instead of from essl's IR.
        #[arg(long)]
        via_wgsl: bool,
    },
    /// Render a scene (docs/scene-format.md) through essl's WebGL2 API to a PNG, and print
    /// one JSON line as webgl2-render.py does.
    #[cfg(feature = "render")]
    Render {
        /// The scene file.
        scene: PathBuf,
        /// The PNG to write.
        #[arg(short = 'o', long = "output", value_name = "PNG")]
        output: PathBuf,
        /// Time this many frames (clear + draw + read one pixel) and report the median.
        #[arg(long, default_value_t = 0, value_name = "N")]
        times: usize,
    },
    /// Measure the light shaders (essl-lights) through essl's WebGL2 API: error against the
    /// float64 reference and time per frame for each variant; write report.md, report.svg, the
    /// pictures and (full run) the GPU stiff section of numerical-stability.md.
    #[cfg(feature = "report")]
    Report {
        /// The folder to write into.
        #[arg(long, default_value = "docs", value_name = "DIR")]
        out: std::path::PathBuf,
        /// A short run (small images, few frames, fewer variants, no stiff matrix).
        #[arg(long)]
        quick: bool,
        /// The shared seed scenes (for the specialised-vs-uber part).
        #[arg(long, default_value = "../shared/scenes", value_name = "DIR")]
        scenes: std::path::PathBuf,
    },
    /// List the lint rules, or show one rule's documentation.
    Rules {
        /// A rule id (`pow-negative-base`…).
        rule: Option<String>,
    },
}

#[derive(Args, Debug)]
struct MinifyArgs {
    /// The shader file (.vert, .frag, .vs, .fs, .vsh, .fsh, or --stage).
    #[arg(value_name = "FILE")]
    path: PathBuf,
    /// The stage, where the file's extension does not tell it.
    #[arg(long, value_enum, value_name = "STAGE")]
    stage: Option<StageArg>,
    /// The WebGL version the shader is for (overrides essl.toml's `target`).
    #[arg(long, value_enum, value_name = "WEBGL")]
    target: Option<WebglArg>,
    /// A macro the shader is compiled with, `NAME` or `NAME=VALUE` (repeatable).
    #[arg(short = 'D', value_name = "NAME[=VALUE]")]
    define: Vec<String>,
    /// Keep local names: remove comments and white space only.
    #[arg(long)]
    no_rename: bool,
    /// Write to this file instead of standard output.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    output: Option<PathBuf>,
}

#[derive(Args, Debug)]
struct TranslateArgs {
    /// Shader files and folders (searched recursively for .vert/.frag/.vs/.fs/.vsh/.fsh).
    #[arg(required = true, value_name = "PATH")]
    paths: Vec<PathBuf>,

    /// The language to write.
    #[arg(long, value_enum, default_value_t = TargetArg::Wgsl)]
    to: TargetArg,

    /// Write into this folder instead of next to each input; into this file when there is
    /// one output and the name ends in the target's extension (`out.wgsl`); `-`: standard
    /// output.
    #[arg(short = 'o', long = "output", value_name = "DIR|FILE")]
    output: Option<PathBuf>,

    /// `single`: one WGSL module per program, both entry points (`vs_main`, `fs_main`) in
    /// NAME.wgsl; `per-stage`: a file per shader.
    #[arg(long, value_enum, default_value_t = ModuleArg::PerStage)]
    module: ModuleArg,

    /// How WGSL reads the loose uniforms: `buffer` (`uniforms.u_color`) or `module-scope`
    /// (`u_color`, a `let` of each at the top of the functions that read it).
    #[arg(long, value_enum, default_value_t = UniformsArg::Buffer)]
    uniforms: UniformsArg,

    /// Also write the binding map (uniform offsets, sampler and attribute bindings) as
    /// NAME.bindings.json.
    #[arg(long, value_enum, value_name = "FORMAT")]
    bindings: Option<BindingsArg>,

    /// Leave clip-space z as WebGL's -w..w (on by default except for glsl).
    #[arg(long)]
    no_depth_remap: bool,

    /// Leave gl_FragCoord.y counting from the top (on by default except for glsl).
    #[arg(long)]
    no_flip_y: bool,

    /// Write no comments.
    #[arg(long)]
    no_comments: bool,

    /// The stage of named files whose extension does not tell it.
    #[arg(long, value_enum, value_name = "STAGE")]
    stage: Option<StageArg>,

    /// Do not link NAME.vert + NAME.frag pairs: translate each shader on its own.
    #[arg(long)]
    no_link: bool,
}

impl From<StageArg> for Stage {
    fn from(s: StageArg) -> Stage {
        match s {
            StageArg::Vertex => Stage::Vertex,
            StageArg::Fragment => Stage::Fragment,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum ModuleArg {
    /// A file per shader.
    PerStage,
    /// One WGSL module per program.
    Single,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum UniformsArg {
    /// Through the uniform buffer: `uniforms.u_color`.
    Buffer,
    /// By their GLSL names: `let u_color = uniforms.u_color;` where a function reads it.
    ModuleScope,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum TargetArg {
    /// WGSL (WebGPU, wgpu).
    Wgsl,
    /// SPIR-V 1.0 for Vulkan.
    Spirv,
    /// Metal Shading Language 2.1 (for `invariant`).
    Msl,
    /// HLSL shader model 5.1.
    Hlsl,
    /// Desktop GLSL 4.50 core.
    Glsl,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum BindingsArg {
    /// JSON.
    Json,
}

#[derive(Args, Debug)]
struct LintArgs {
    /// Shader files and folders (searched for .vert/.frag/.vs/.fs/.vsh/.fsh, .glsl, and
    /// shaders inside .html/.js/.ts files), `-` for standard input.
    #[arg(required = true, value_name = "PATH")]
    paths: Vec<PathBuf>,

    /// The stage of named files (and standard input) that nothing else places.
    #[arg(long, value_enum, value_name = "STAGE")]
    stage: Option<StageArg>,

    /// The name standard input (`-`) is checked under: its extension gives the stage or says
    /// it is HTML or JS, and diagnostics name it.
    #[arg(long, value_name = "PATH")]
    stdin_filename: Option<PathBuf>,

    /// Output format.
    #[arg(long, value_enum, default_value_t = FormatArg::Human)]
    format: FormatArg,

    /// When to colour the output (auto: when stdout is a terminal).
    #[arg(long, value_enum, default_value_t = ColorArg::Auto, value_name = "WHEN")]
    color: ColorArg,

    /// Apply the fixes that are certain, in place, then report what remains.
    #[arg(long)]
    fix: bool,

    /// With `--fix`: apply the suggested fixes too (they may change what the shader does).
    #[arg(long)]
    unsafe_fixes: bool,

    /// With `--fix`: print what would change as a unified diff, and write nothing (exit 1 when
    /// something would change).
    #[arg(long, requires = "fix")]
    diff: bool,

    /// Print the diagnostics and nothing else (no summary, no linked programs).
    #[arg(short, long)]
    quiet: bool,

    /// Print how often each code occurs instead of the diagnostics.
    #[arg(long, conflicts_with = "diff")]
    statistics: bool,

    /// Exit 0 even when errors are found (2 still reports usage or I/O errors).
    #[arg(long)]
    exit_zero: bool,

    /// Leave out files and folders matching these globs, instead of essl.toml's `exclude`.
    #[arg(long, value_name = "GLOB", value_delimiter = ',')]
    exclude: Option<Vec<String>>,

    /// Leave out files and folders matching these globs, besides essl.toml's `exclude`.
    #[arg(long, value_name = "GLOB", value_delimiter = ',')]
    extend_exclude: Vec<String>,

    /// Read this essl.toml instead of looking for one upward from the first path.
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,

    /// Report a lint rule as an error (`warnings`: make every warning fail the run; `all`:
    /// every rule). See `essl rules`.
    #[arg(long, value_name = "RULE")]
    deny: Vec<String>,

    /// Report a lint rule's findings as warnings (the default of most rules; a note-level
    /// rule's findings become warnings).
    #[arg(long, value_name = "RULE")]
    warn: Vec<String>,

    /// Report every finding of a lint rule as a note (shown with `--show-notes`).
    #[arg(long, value_name = "RULE")]
    note: Vec<String>,

    /// Show notes: hazards only a uniform out of its plausible range reaches, and the findings
    /// of note-level rules (`smoothstep-reversed-constant`). Hidden by default; the summary
    /// counts them.
    #[arg(long)]
    show_notes: bool,

    /// Do not run a lint rule (`all`: none). A `// essl-allow: RULE` comment on a line (or the
    /// line before) silences one finding.
    #[arg(long, value_name = "RULE")]
    allow: Vec<String>,

    /// Define a macro before the first line, as `#define NAME VALUE` (VALUE defaults to 1).
    #[arg(short = 'D', value_name = "NAME[=VALUE]", value_parser = parse_define)]
    define: Vec<(String, String)>,

    /// Allow `#include "FILE"`, searched in the including file's folder, then in DIR (repeat
    /// for more; essl.toml's `include` adds its folders after these). GLSL ES has no
    /// `#include`: without an include folder it stays an error.
    #[arg(short = 'I', value_name = "DIR")]
    include: Vec<PathBuf>,

    /// Do not link NAME.vert + NAME.frag pairs.
    #[arg(long)]
    no_link: bool,

    /// The WebGL version of the context the shaders are for: webgl2 (the default) compiles
    /// GLSL ES 3.00 and 1.00, webgl1 GLSL ES 1.00 only (with the WebGL 1 extensions a shader
    /// enables). Overrides essl.toml's `target`.
    #[arg(long, value_enum, value_name = "WEBGL")]
    target: Option<WebglArg>,

    /// Check shaders as a library assembles them, from the copy the project has installed:
    /// `luma` (luma.gl and deck.gl: modules, hooks, prologue) or `three` (three.js materials:
    /// the prelude, `#include <chunk>`). Overrides essl.toml's `preset`.
    #[arg(long, value_enum, value_name = "LIBRARY")]
    preset: Option<PresetArg>,

    /// How many `#ifdef` configurations besides the one the defines select the lints also
    /// check — the code of each flag such as `USE_FOG`, then every flag together — reporting
    /// what they find there with the macros named (64 by default; 0: none). Overrides
    /// essl.toml's `variants`.
    #[arg(long, value_name = "N")]
    variants: Option<usize>,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum PresetArg {
    Luma,
    Three,
}

/// A WebGL version.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum WebglArg {
    /// WebGL 1: GLSL ES 1.00.
    Webgl1,
    /// WebGL 2: GLSL ES 3.00 and 1.00.
    Webgl2,
}

impl From<WebglArg> for essl::Target {
    fn from(t: WebglArg) -> essl::Target {
        match t {
            WebglArg::Webgl1 => essl::Target::WebGl1,
            WebglArg::Webgl2 => essl::Target::WebGl2,
        }
    }
}

#[derive(Args, Debug)]
struct ConformanceArgs {
    /// The folder holding the corpora's .jsonl files.
    #[arg(long, default_value = "../shared/corpora", value_name = "DIR")]
    corpora: PathBuf,

    /// Also write the tables, with an introduction, as Markdown to this file.
    #[arg(long, value_name = "FILE")]
    markdown: Option<PathBuf>,

    /// List every case where essl disagrees with the expectation.
    #[arg(long)]
    failures: bool,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum StageArg {
    Vertex,
    Fragment,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum FormatArg {
    /// rustc-style diagnostics and a summary line.
    Human,
    /// JSON Lines: one object per shader and per program.
    Json,
    /// A SARIF 2.1.0 log, for code-scanning services.
    Sarif,
    /// GitHub Actions annotations (`::error file=…,line=…::…`).
    Github,
    /// One line per diagnostic: `FILE:LINE:COL: severity[code]: message`.
    Concise,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum ColorArg {
    Auto,
    Always,
    Never,
}

fn parse_define(s: &str) -> Result<(String, String), String> {
    let (name, value) = match s.split_once('=') {
        Some((n, v)) => (n, v),
        None => (s, "1"),
    };
    let valid = name
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(format!(
            "`{name}` is not a macro name (letters, digits and `_`, not starting with a digit)"
        ));
    }
    Ok((name.to_string(), value.to_string()))
}

/// The lint levels given on the command line, in the order given (a later one wins), on top
/// of `base` (essl.toml's).
/// The `--allow/--note/--warn/--deny RULE` flags, in the order given (a later one wins), on
/// top of each folder's essl.toml; `--deny warnings` makes every warning an error.
fn rule_levels(
    matches: &clap::ArgMatches,
    overrides: &mut essl_check::Overrides,
) -> Result<(), essl_lint::UnknownRule> {
    let Some(("lint", m)) = matches.subcommand() else {
        return Ok(());
    };
    let mut given: Vec<(usize, &str, essl_lint::Level)> = Vec::new();
    for (flag, level) in [
        ("allow", essl_lint::Level::Allow),
        ("note", essl_lint::Level::Note),
        ("warn", essl_lint::Level::Warn),
        ("deny", essl_lint::Level::Deny),
    ] {
        if let (Some(values), Some(indices)) = (m.get_many::<String>(flag), m.indices_of(flag)) {
            for (v, i) in values.zip(indices) {
                given.push((i, v.as_str(), level));
            }
        }
    }
    given.sort_by_key(|(i, _, _)| *i);
    for (_, rule, level) in given {
        if rule == "warnings" && level == essl_lint::Level::Deny {
            overrides.deny_warnings = true;
            continue;
        }
        overrides.rule(rule, level)?;
    }
    Ok(())
}

/// A glob set of `patterns`, or the pattern that is not a glob.
fn glob_set(patterns: &[String]) -> Result<Option<globset::GlobSet>, String> {
    if patterns.is_empty() {
        return Ok(None);
    }
    let mut set = globset::GlobSetBuilder::new();
    for p in patterns {
        set.add(globset::Glob::new(p).map_err(|e| format!("--exclude `{p}`: {}", e.kind()))?);
    }
    set.build().map(Some).map_err(|e| e.to_string())
}

/// `essl lint`: essl.toml's settings with the flags on top, then the run.
fn lint(args: LintArgs, matches: &clap::ArgMatches) -> i32 {
    let mut overrides = essl_check::Overrides {
        config: args.config.clone(),
        target: args.target.map(essl::Target::from),
        defines: args.define.clone(),
        include_dirs: args.include.clone(),
        stage: args.stage.map(Stage::from),
        preset: args.preset.map(|p| match p {
            PresetArg::Luma => essl_check::Preset::Luma,
            PresetArg::Three => essl_check::Preset::Three,
        }),
        variants: args.variants,
        ..essl_check::Overrides::default()
    };
    if let Err(e) = rule_levels(matches, &mut overrides) {
        eprintln!("error: {e}");
        return EXIT_USAGE;
    }
    let mut exclude = args.exclude.clone().unwrap_or_default();
    exclude.extend(args.extend_exclude.iter().cloned());
    let exclude = match glob_set(&exclude) {
        Ok(set) => set,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    crate::lint::run(&LintOptions {
        paths: args.paths,
        find: essl_check::FindOptions {
            exclude,
            config_exclude: args.exclude.is_none(),
            stdin_name: args.stdin_filename,
            hosts: true,
        },
        overrides,
        format: match args.format {
            FormatArg::Human => Format::Human,
            FormatArg::Json => Format::Json,
            FormatArg::Sarif => Format::Sarif,
            FormatArg::Github => Format::Github,
            FormatArg::Concise => Format::Concise,
        },
        color: match args.color {
            ColorArg::Auto => ColorMode::Auto,
            ColorArg::Always => ColorMode::Always,
            ColorArg::Never => ColorMode::Never,
        },
        fix: args.fix,
        unsafe_fixes: args.unsafe_fixes,
        diff: args.diff,
        quiet: args.quiet,
        statistics: args.statistics,
        exit_zero: args.exit_zero,
        show_notes: args.show_notes,
        link: !args.no_link,
    })
}

/// Runs the command line `args` (the program's name first, as `std::env::args_os` gives it)
/// and returns the exit status: what `essl` prints goes to this process's standard output and
/// error. A usage error prints clap's message and returns 2 (`--help` and `--version` print and
/// return 0); nothing here ends the process.
pub fn main_from(args: impl IntoIterator<Item = OsString>) -> u8 {
    use clap::{CommandFactory, FromArgMatches};
    // Worker threads with room for a whole compile, so that `essl::compile` runs on them
    // directly instead of switching to a fresh stack segment per shader. The stack is reserved,
    // not touched: only the pages a compile uses are ever mapped.
    let _ = rayon::ThreadPoolBuilder::new()
        .stack_size(2 * essl::COMPILE_STACK)
        .thread_name(|i| format!("essl-{i}"))
        .build_global();
    let parsed = Cli::command()
        .try_get_matches_from(args)
        .and_then(|m| Cli::from_arg_matches(&m).map(|c| (m, c)));
    let (matches, cli) = match parsed {
        Ok(parsed) => parsed,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { EXIT_USAGE as u8 } else { 0 };
        }
    };
    let status = match cli.command {
        Command::Rules { rule } => crate::rules::run(rule.as_deref()),
        Command::Explain { code } => crate::explain::run(code.as_deref()),
        Command::Server => match essl_server::run_stdio() {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: {e}");
                1
            }
        },
        Command::Config { path, config } => {
            crate::settings::run(config.as_deref(), path.as_deref())
        }
        #[cfg(feature = "render")]
        Command::Render {
            scene,
            output,
            times,
        } => crate::render::run(&scene, &output, times),
        Command::Lint(args) => lint(*args, &matches),
        #[cfg(feature = "report")]
        Command::Report { out, quick, scenes } => crate::report::run(&out, quick, &scenes),
        #[cfg(feature = "render")]
        Command::DeqpExec {
            corpus,
            only,
            output,
            via_wgsl,
        } => crate::deqp_exec::run(&corpus, only.as_deref(), output.as_deref(), via_wgsl),
        Command::Translate(args) => {
            let target = match args.to {
                TargetArg::Wgsl => essl_translate::Target::Wgsl,
                TargetArg::Spirv => essl_translate::Target::SpirV,
                TargetArg::Msl => essl_translate::Target::Msl,
                TargetArg::Hlsl => essl_translate::Target::Hlsl,
                TargetArg::Glsl => essl_translate::Target::Glsl,
            };
            let mut options = essl_translate::Options::new(target);
            options.depth_remap &= !args.no_depth_remap;
            options.flip_y &= !args.no_flip_y;
            options.comments = !args.no_comments;
            if args.uniforms == UniformsArg::ModuleScope {
                options.uniforms = essl_translate::Uniforms::ModuleScope;
            }
            crate::translate::run(&crate::translate::TranslateArgs {
                paths: args.paths,
                stage: args.stage.map(Stage::from),
                options,
                bindings: args.bindings.is_some(),
                out: args.output,
                no_link: args.no_link,
                single_module: args.module == ModuleArg::Single,
            })
        }
        Command::Minify(args) => crate::minify::run(&crate::minify::MinifyArgs {
            path: args.path,
            stage: args.stage.map(Stage::from),
            target: args.target.map(essl::Target::from),
            defines: args.define,
            no_rename: args.no_rename,
            out: args.output,
        }),
        Command::Conformance(args) => {
            crate::conformance::run(&args.corpora, args.markdown.as_deref(), args.failures)
        }
    };
    status as u8
}
