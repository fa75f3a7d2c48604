//! essl's checker as a Node.js addon, the native half of the npm package `essl`
//! (`crates/essl-node`: `index.js`, `index.d.ts`, the Vite/Rollup plugin and the webpack
//! loader are its JavaScript half).
//!
//! Every call goes through the one checking pipeline the CLI, the build-script checker and
//! the editor server use ([`essl_check::check_text`], [`essl_check::link`]); the translator is
//! [`essl_translate`]; `runCli` is the `essl` command itself ([`essl_cli::cli::main_from`]). No
//! GPU stack is built into it. Options and results cross as JSON text: the JS side checks
//! argument types (throwing `TypeError`s), parses the result, and keeps this surface small; a
//! diagnostic's rustc-style text is written when JS first reads it ([`render`]). A panic
//! inside a call is caught and becomes a thrown `Error`, never an abort of the Node process.

use std::collections::HashSet;
use std::ffi::OsString;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use essl_check::{CheckOptions, CheckedShader, Configs, Files};
use napi::bindgen_prelude::{AsyncTask, Either, External};
use napi::{Env, Error, Status, Task};
use napi_derive::napi;
use serde_json::json;

pub mod minify;
mod options;
mod report;

/// mimalloc for the addon's own allocations, as for the `essl` binary (Node's and V8's are
/// their own): checking a shader allocates many small objects.
#[global_allocator]
static ALLOCATOR: essl_alloc::Allocator = essl_alloc::Allocator;

/// The largest text a call takes, as the CLI's largest file ([`essl_check::MAX_FILE_SIZE`]).
const MAX_TEXT: usize = essl_check::MAX_FILE_SIZE as usize;

fn type_error(message: impl Into<String>) -> Error {
    Error::new(Status::InvalidArg, message.into())
}

/// Runs `f`, turning a panic into a thrown `Error`.
fn guarded<T>(what: &str, f: impl FnOnce() -> napi::Result<T>) -> napi::Result<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => {
            let why = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(Error::new(
                Status::GenericFailure,
                format!("essl: internal error in {what}: {why}"),
            ))
        }
    }
}

fn too_big(text: &str) -> napi::Result<()> {
    if text.len() > MAX_TEXT {
        return Err(Error::new(
            Status::InvalidArg,
            format!(
                "the source is {} bytes, over essl's limit of {MAX_TEXT} bytes",
                text.len()
            ),
        ));
    }
    Ok(())
}

/// How long the settings read for one set of options are kept: a bundler checks hundreds of
/// modules in a second, each of which would otherwise look for `essl.toml` in every folder
/// above it again; an edited `essl.toml` is read within this time.
const SETTINGS_KEPT: Duration = Duration::from_secs(1);

/// The settings for `opts`, shared by the calls of the last [`SETTINGS_KEPT`] with the same
/// overrides: kept by the overrides as read ([`options::Options::settings_key`]) and the stage
/// asked for, of which the overrides are a function.
fn configs(opts: &options::Options) -> Arc<Configs> {
    type Kept = Vec<(Arc<str>, Option<essl::Stage>, Instant, Arc<Configs>)>;
    static KEPT: Mutex<Kept> = Mutex::new(Vec::new());
    let stage = opts.overrides.stage;
    let now = Instant::now();
    let mut kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
    kept.retain(|(_, _, at, _)| now.duration_since(*at) < SETTINGS_KEPT);
    if let Some((_, _, _, c)) = kept
        .iter()
        .find(|(key, s, _, _)| *s == stage && **key == *opts.settings_key)
    {
        return c.clone();
    }
    let c = Arc::new(Configs::new(opts.overrides.clone()));
    kept.push((opts.settings_key.clone(), stage, now, c.clone()));
    c
}

/// Checks `text` as the file `options.filename` (its extension says what it is: a shader file,
/// or an HTML or JS/TS file holding shaders). Returns the checked unit as JSON.
fn check_one(text: String, opts: &options::Options) -> napi::Result<essl_check::CheckedUnit> {
    too_big(&text)?;
    let configs = configs(opts);
    let check = CheckOptions {
        link: opts.link,
        lints: opts.lints,
        ..CheckOptions::default()
    };
    let (unit, _) = essl_check::check_text(&opts.filename, text, &configs, &Files::disk(), check)
        .map_err(|e| match e {
        // An `essl.toml` that cannot be read is an error, as it is for `essl lint`; the
        // others are about the arguments.
        essl_check::UsageError::Config(_) => Error::new(Status::GenericFailure, e.to_string()),
        _ => type_error(e.to_string()),
    })?;
    Ok(unit)
}

/// What `checkJson` and `linkJson` answer: the result's JSON, and the diagnostics whose
/// rustc-style text its `rendered` indices stand for ([`report::Rendering`]).
#[napi(object, object_from_js = false)]
pub struct Answer {
    /// The result as JSON.
    pub json: String,
    /// The diagnostics for [`render`].
    pub rendering: External<report::Rendering>,
}

/// An answer as it crosses to JavaScript: the JSON text alone when no diagnostic has a text to
/// render (most results), which spares an object and an external per call.
pub type Answered = Either<String, Answer>;

impl Answer {
    fn new((json, rendering): (String, report::Rendering)) -> Answered {
        if rendering.is_empty() {
            return Either::A(json);
        }
        Either::B(Answer {
            json,
            rendering: External::new(rendering),
        })
    }
}

/// `render(rendering, index)`: the rustc-style text of a diagnostic of an answer (a
/// diagnostic's `rendered`, written when it is first read).
#[napi]
pub fn render(rendering: &External<report::Rendering>, index: u32) -> napi::Result<String> {
    guarded("render", || Ok(rendering.render(index as usize)))
}

/// `check(source, options)`: diagnostics of a shader, or of every shader of a JS/TS or HTML
/// file, and the programs linked where the pairs are known; JSON of `{shaders, programs,
/// errors, warnings}`.
#[napi(js_name = "checkJson")]
pub fn check_json(source: String, options: String) -> napi::Result<Answered> {
    check_text_json(source, options).map(Answer::new)
}

/// `checkJsonBatchAsync(sources, options)`: [`check_json`] of each source with the options at
/// its index, one after another on one thread of Node's pool; a promise of their answers, a
/// [`Failed`] where one throws. A bundler's modules arrive a few at a time: checked in batches
/// (`checkAsync` queues them in `index.js`), they cost one trip through the pool each rather than
/// one per module, and leave the pool's other threads to the bundler's own reads and writes.
#[napi(js_name = "checkJsonBatchAsync")]
pub fn check_json_batch_async(sources: Vec<String>, options: Vec<String>) -> AsyncTask<BatchTask> {
    AsyncTask::new(BatchTask {
        items: sources.into_iter().zip(options).collect(),
    })
}

/// What a check of a batch that failed answers: the message and whether it is about the
/// arguments (a `TypeError` in JS).
#[napi(object, object_from_js = false)]
pub struct Failed {
    /// The error's message.
    pub message: String,
    /// Whether the arguments were at fault.
    pub invalid_arg: bool,
}

/// The work of [`check_json_batch_async`].
pub struct BatchTask {
    items: Vec<(String, String)>,
}

impl Task for BatchTask {
    type Output = Vec<napi::Result<(String, report::Rendering)>>;
    type JsValue = Vec<Either<Answered, Failed>>;

    fn compute(&mut self) -> napi::Result<Self::Output> {
        Ok(std::mem::take(&mut self.items)
            .into_iter()
            .map(|(source, options)| check_text_json(source, options))
            .collect())
    }

    fn resolve(&mut self, _env: Env, output: Self::Output) -> napi::Result<Self::JsValue> {
        Ok(output
            .into_iter()
            .map(|r| match r {
                Ok(answer) => Either::A(Answer::new(answer)),
                Err(e) => Either::B(Failed {
                    invalid_arg: e.status == Status::InvalidArg,
                    message: e.reason,
                }),
            })
            .collect())
    }
}

fn check_text_json(source: String, options: String) -> napi::Result<(String, report::Rendering)> {
    guarded("check", || {
        let opts = options::read(&options, "shader.glsl").map_err(|e| type_error(e.0))?;
        let given = source.clone();
        let mut unit = check_one(source, &opts)?;
        let partner = with_partner(&mut unit, &opts)?;
        let mut rendering = report::Rendering::default();
        let mut out = report::unit(&unit, Some(&given), &mut rendering);
        if opts.overrides.deny_warnings {
            // `--deny warnings`: a warning fails the check as an error does.
            out.errors += out.warnings;
        }
        if let Some(s) = partner.and_then(|i| out.shaders.get_mut(i)) {
            // The partner's own diagnostics are its module's to report.
            s.as_partner();
        }
        Ok((to_json(&out)?, rendering))
    })
}

/// The JSON text of a result.
fn to_json(value: &impl serde::Serialize) -> napi::Result<String> {
    serde_json::to_string(value).map_err(|e| Error::new(Status::GenericFailure, e.to_string()))
}

/// Links a lone shader file with its partner on disk (`light.frag` with `light.vert`), as
/// `essl lint` pairs them: the partner is checked and added after it, and the program after
/// the unit's. Returns the partner's index, if there is one.
fn with_partner(
    unit: &mut essl_check::CheckedUnit,
    opts: &options::Options,
) -> napi::Result<Option<usize>> {
    if !opts.link || unit.shaders.len() != 1 || unit.shaders[0].embedded_at.is_some() {
        return Ok(None);
    }
    // A name that is not on disk (a text checked as `shader.frag`) has no partner.
    if !opts.filename.is_file() {
        return Ok(None);
    }
    let folder = opts.filename.parent().unwrap_or(Path::new("."));
    let files = files_in(folder);
    let exists =
        |p: &Path| p.parent() == Some(folder) && p.file_name().is_some_and(|n| files.contains(n));
    let Some(path) = essl_check::partner(&opts.filename, exists) else {
        return Ok(None);
    };
    let Ok(text) = essl_check::read_source(&path) else {
        return Ok(None);
    };
    let mut other = opts.clone();
    other.filename = path;
    other.overrides.stage = None;
    let mut theirs = check_one(text, &other)?;
    let Some(partner) = theirs.shaders.pop() else {
        return Ok(None);
    };
    let mine = &unit.shaders[0];
    let (vs, fs) = match mine.stage {
        essl::Stage::Vertex => (mine, &partner),
        essl::Stage::Fragment => (&partner, mine),
    };
    let mut program = essl_check::link(vs, fs);
    (program.vertex, program.fragment) = match mine.stage {
        essl::Stage::Vertex => (0, 1),
        essl::Stage::Fragment => (1, 0),
    };
    unit.shaders.push(partner);
    unit.programs.push(program);
    Ok(Some(1))
}

/// The names of the files in `folder` (following links), read once in [`SETTINGS_KEPT`]: a
/// bundler checks the shaders of a folder one after the other, and looking for each one's
/// partner file took a dozen `stat`s. A partner file created since is seen within that time.
fn files_in(folder: &Path) -> Arc<HashSet<OsString>> {
    type Kept = Vec<(PathBuf, Instant, Arc<HashSet<OsString>>)>;
    static KEPT: Mutex<Kept> = Mutex::new(Vec::new());
    let now = Instant::now();
    {
        let mut kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
        kept.retain(|(_, at, _)| now.duration_since(*at) < SETTINGS_KEPT);
        if let Some((_, _, names)) = kept.iter().find(|(f, _, _)| f == folder) {
            return names.clone();
        }
    }
    let names: HashSet<OsString> = std::fs::read_dir(folder)
        .into_iter()
        .flatten()
        .flatten()
        .filter(|e| {
            e.file_type()
                .is_ok_and(|t| t.is_file() || (t.is_symlink() && e.path().is_file()))
        })
        .map(|e| e.file_name())
        .collect();
    let names = Arc::new(names);
    let mut kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
    kept.push((folder.to_path_buf(), now, names.clone()));
    names
}

/// The one shader of a stage-named check (a lone text: no pair to look for).
fn lone_shader(source: String, options: &str, stage: essl::Stage) -> napi::Result<CheckedShader> {
    let default = match stage {
        essl::Stage::Vertex => "shader.vert",
        essl::Stage::Fragment => "shader.frag",
    };
    let mut opts = options::read(options, default).map_err(|e| type_error(e.0))?;
    opts.overrides.stage = Some(stage);
    let ext = opts.filename.extension().and_then(|e| e.to_str());
    if !matches!(
        ext,
        Some("vert" | "frag" | "vs" | "fs" | "glsl" | "vsh" | "fsh")
    ) {
        opts.filename = opts.filename.with_file_name(Path::new(default));
    }
    let unit = check_one(source, &opts)?;
    unit.shaders
        .into_iter()
        .find(|s| s.stage == stage)
        .ok_or_else(|| type_error(format!("the {default} text holds no {stage:?} shader")))
}

/// What `linkJson` answers.
#[derive(serde::Serialize)]
struct Linked<'a> {
    fragment: report::Shader<'a>,
    program: report::Program<'a>,
    vertex: report::Shader<'a>,
}

/// `link(vertex, fragment, options)`: both shaders checked, then linked as WebGL's
/// `linkProgram`; JSON of `{vertex, fragment, program}` (each shader's result, the program's).
#[napi(js_name = "linkJson")]
pub fn link_json(
    vertex: String,
    fragment: String,
    vertex_options: String,
    fragment_options: String,
) -> napi::Result<Answered> {
    guarded("link", || {
        let given = (vertex.clone(), fragment.clone());
        let vs = lone_shader(vertex, &vertex_options, essl::Stage::Vertex)?;
        let fs = lone_shader(fragment, &fragment_options, essl::Stage::Fragment)?;
        let program = essl_check::link(&vs, &fs);
        let mut rendering = report::Rendering::default();
        let vertex = report::shader(&vs, Some(&given.0), &mut rendering);
        let fragment = report::shader(&fs, Some(&given.1), &mut rendering);
        let mut program = report::program(&program, &mut rendering);
        (program.vertex, program.fragment) = (0, 1);
        let json = to_json(&Linked {
            fragment,
            program,
            vertex,
        })?;
        Ok(Answer::new((json, rendering)))
    })
}

/// `translate(vertex, fragment, {to})`: the program in WGSL, SPIR-V, MSL, HLSL or GLSL and its
/// binding map; JSON of `{vertex, fragment, bindings}` (SPIR-V as an array of words).
#[napi(js_name = "translateJson")]
pub fn translate_json(
    vertex: String,
    fragment: String,
    to: String,
    options: String,
) -> napi::Result<String> {
    guarded("translate", || {
        let target = essl_translate::Target::from_name(&to).ok_or_else(|| {
            type_error(format!(
                "options.to must be one of 'wgsl', 'spirv', 'msl', 'hlsl', 'glsl', not '{to}'"
            ))
        })?;
        let vs = lone_shader(vertex, &options, essl::Stage::Vertex)?;
        let fs = lone_shader(fragment, &options, essl::Stage::Fragment)?;
        let (Some(v), Some(f)) = (&vs.shader, &fs.shader) else {
            return Err(Error::new(
                Status::GenericFailure,
                "a shader's #include could not be followed".to_string(),
            ));
        };
        let t = essl_translate::translate_program(v, f, &essl_translate::Options::new(target))
            .map_err(|e| {
                let shown: Vec<String> = [&vs, &fs]
                    .iter()
                    .flat_map(|s| s.all())
                    .filter(|(_, d)| d.is_error())
                    .map(|(file, d)| essl::render::human_string(file, std::slice::from_ref(d)))
                    .collect();
                Error::new(
                    Status::GenericFailure,
                    format!("essl: {e}\n{}", shown.join("")),
                )
            })?;
        let code = |c: &essl_translate::Code| match c {
            essl_translate::Code::Text(t) => json!(t),
            essl_translate::Code::SpirV(words) => json!(words),
        };
        Ok(json!({
            "vertex": code(&t.vertex),
            "fragment": code(&t.fragment),
            "bindings": t.bindings,
        })
        .to_string())
    })
}

/// `runCli(args)`: the `essl` command with `args` (after the program's name), printing to this
/// process's standard output and error; its exit status.
#[napi(js_name = "runCli")]
pub fn run_cli(args: Vec<String>) -> napi::Result<u32> {
    guarded("the essl command", || {
        let argv = std::iter::once("essl".into()).chain(args.into_iter().map(Into::into));
        Ok(u32::from(essl_cli::cli::main_from(argv)))
    })
}
