//! `essl translate`: WebGL shaders to WGSL (or SPIR-V, MSL, HLSL, desktop GLSL), with the
//! binding map beside them.
//!
//! Files and folders are found, and shaders compiled with their folder's essl.toml, by the same
//! pipeline as `essl lint` ([`essl_check`]); every `NAME.vert` + `NAME.frag` pair
//! is linked and translated as a program (matching varying locations, one uniform buffer for
//! both stages), any other shader on its own. Each output goes next to its input, or into the
//! folder `-o` names, as the input's file name plus the target's extension
//! (`light.frag` → `light.frag.wgsl`; with `--module single`, a program's one module as
//! `light.wgsl`); the binding map, with `--bindings json`, as `NAME.bindings.json`
//! (`light.frag.bindings.json` for a lone shader). When there is one output and `-o` names a
//! file with the target's extension (`-o out.wgsl`, as glslangValidator, naga and tint take
//! it), the output is that file and its map `out.bindings.json`; a file name given for more
//! than one output is an error rather than a folder of that name. A shader with errors is
//! not translated: its diagnostics are printed as `essl lint` prints them.

use std::path::{Path, PathBuf};

use essl::Stage;
use essl_check::CheckedShader;
use essl_translate::{BindingMap, Code, Options, Target, TranslateError};

/// What `essl translate` was asked.
#[derive(Clone, Debug)]
pub struct TranslateArgs {
    /// Files and folders.
    pub paths: Vec<PathBuf>,
    /// The stage of named files whose extension does not tell it.
    pub stage: Option<Stage>,
    /// What to write, and how.
    pub options: Options,
    /// Write each binding map as JSON beside its code.
    pub bindings: bool,
    /// The folder to write into instead of next to each input; `-` prints to standard output.
    pub out: Option<PathBuf>,
    /// Do not link pairs: translate every shader on its own.
    pub no_link: bool,
    /// Write each program as one module (WGSL): both entry points in `NAME.wgsl`.
    pub single_module: bool,
}

/// Runs `essl translate`; the exit status (0 all translated, 1 some could not be, 2 usage or
/// I/O errors).
pub fn run(args: &TranslateArgs) -> i32 {
    let configs = essl_check::Configs::new(essl_check::Overrides {
        stage: args.stage,
        ..essl_check::Overrides::default()
    });
    let find = essl_check::FindOptions {
        hosts: false,
        ..essl_check::FindOptions::new()
    };
    let found = match essl_check::find(&args.paths, &find, &configs) {
        Ok(f) if f.errors.is_empty() => f,
        Ok(f) => {
            for e in &f.errors {
                eprintln!("error: {e}");
            }
            return 2;
        }
        Err(e) => {
            eprintln!("error: {e}");
            return 2;
        }
    };
    if found.inputs.is_empty() {
        eprintln!("error: no shader files (.vert, .frag, .vs, .fs, .vsh, .fsh) found");
        return 2;
    }
    let wgsl_only = [
        (args.single_module, "--module single"),
        (
            args.options.uniforms == essl_translate::Uniforms::ModuleScope,
            "--uniforms module-scope",
        ),
    ];
    for (asked, option) in wgsl_only {
        if asked && args.options.target != Target::Wgsl {
            eprintln!(
                "error: {option} writes WGSL only (not --to {})",
                args.options.target.name()
            );
            return 2;
        }
    }
    let options = essl_check::CheckOptions {
        link: !args.no_link,
        lints: false,
        ..essl_check::CheckOptions::default()
    };
    let keep = |_, unit: essl_check::CheckedUnit| unit;
    let run = essl_check::run(
        &found,
        &configs,
        &mut essl_check::Files::disk(),
        options,
        &keep,
    );
    let outputs: usize = run
        .results
        .iter()
        .map(|u| match (u.programs.first(), args.single_module) {
            (Some(_), true) => 1,
            (Some(_), false) => 2,
            (None, _) => u.shaders.len(),
        })
        .sum();
    if let Some(file) = args.file() {
        if outputs != 1 {
            eprintln!(
                "error: -o {}: a file takes one output, and {outputs} would be written: name a \
                 folder",
                file.display()
            );
            return 2;
        }
    } else if let Some(out) = args.folder() {
        if let Err(e) = std::fs::create_dir_all(out) {
            eprintln!("error: {}: {}", out.display(), essl_check::io_message(&e));
            return 2;
        }
    }
    let mut status = 0;
    let mut written = 0usize;
    for unit in &run.results {
        if let Some(u) = unit.unread.first() {
            eprintln!("error: {}: {}", u.path.display(), u.message);
            return 2;
        }
        let outcome = match unit.programs.first() {
            Some(p) => translate_pair(&unit.shaders[p.vertex], &unit.shaders[p.fragment], args),
            None => unit.shaders.iter().try_fold(Outcome::default(), |a, s| {
                Ok(a.and(translate_one(s, args)?))
            }),
        };
        match outcome {
            Ok(o) => {
                written += o.written;
                status = status.max(o.status);
            }
            Err(()) => return 2,
        }
    }
    if !args.to_stdout() {
        eprintln!(
            "essl translate: {written} file(s) written ({})",
            args.options.target.name()
        );
    }
    status
}

/// What translating a unit gave: files written and the exit status so far.
#[derive(Clone, Copy, Debug, Default)]
struct Outcome {
    written: usize,
    status: i32,
}

impl Outcome {
    fn and(self, other: Outcome) -> Outcome {
        Outcome {
            written: self.written + other.written,
            status: self.status.max(other.status),
        }
    }
}

/// A linked pair, translated as one program; `Err` when a file cannot be written.
fn translate_pair(
    v: &CheckedShader,
    f: &CheckedShader,
    args: &TranslateArgs,
) -> Result<Outcome, ()> {
    if report_errors(v) | report_errors(f) {
        return Ok(Outcome {
            written: 0,
            status: 1,
        });
    }
    let (Some(vs), Some(fs)) = (&v.shader, &f.shader) else {
        return Ok(Outcome::default());
    };
    // `dir/light.vert` → the program's map is `light.bindings.json`, its one module
    // `light.wgsl`.
    let base = v.path.with_extension("");
    if args.single_module {
        return match essl_translate::translate_program_module(vs, fs, &args.options) {
            Ok(t) => {
                let name = base.file_name().unwrap_or_default().to_string_lossy();
                let path = args.place(&base, format!("{name}.{}", args.options.target.extension()));
                Ok(Outcome {
                    written: write_all(&[(path, t.code)], &t.bindings, &base, args)?,
                    status: 0,
                })
            }
            Err(e) => {
                eprintln!(
                    "error: {} + {}: {}",
                    v.path.display(),
                    f.path.display(),
                    message(&e)
                );
                Ok(Outcome {
                    written: 0,
                    status: 1,
                })
            }
        };
    }
    match essl_translate::translate_program(vs, fs, &args.options) {
        Ok(t) => {
            let outputs = [
                (output_path(&v.path, args), t.vertex),
                (output_path(&f.path, args), t.fragment),
            ];
            Ok(Outcome {
                written: write_all(&outputs, &t.bindings, &base, args)?,
                status: 0,
            })
        }
        Err(e) => {
            eprintln!(
                "error: {} + {}: {}",
                v.path.display(),
                f.path.display(),
                message(&e)
            );
            Ok(Outcome {
                written: 0,
                status: 1,
            })
        }
    }
}

/// A shader on its own.
fn translate_one(s: &CheckedShader, args: &TranslateArgs) -> Result<Outcome, ()> {
    if report_errors(s) {
        return Ok(Outcome {
            written: 0,
            status: 1,
        });
    }
    let Some(shader) = &s.shader else {
        return Ok(Outcome::default());
    };
    match essl_translate::translate_shader(shader, &args.options) {
        Ok(t) => {
            let outputs = [(output_path(&s.path, args), t.code)];
            // A lone `light.frag` has `light.frag.bindings.json`.
            Ok(Outcome {
                written: write_all(&outputs, &t.bindings, &s.path, args)?,
                status: 0,
            })
        }
        Err(e) => {
            eprintln!("error: {}: {}", s.path.display(), message(&e));
            Ok(Outcome {
                written: 0,
                status: 1,
            })
        }
    }
}

/// Prints a shader's diagnostics if it has errors; whether it has.
fn report_errors(s: &CheckedShader) -> bool {
    if s.ok() {
        return false;
    }
    for g in &s.diagnostics {
        eprint!("{}", essl::render::human_string(&g.file, &g.diagnostics));
    }
    true
}

/// The error's words, with a hint where the cause is essl's rather than the shader's.
fn message(e: &TranslateError) -> String {
    match e {
        TranslateError::Lower(_)
        | TranslateError::Write { .. }
        | TranslateError::Reparse { .. } => {
            format!("{e} (a limitation of essl: the shader is valid WebGL)")
        }
        _ => e.to_string(),
    }
}

/// `dir/light.frag` → `OUT/light.frag.wgsl` (or next to the input).
fn output_path(input: &Path, args: &TranslateArgs) -> PathBuf {
    let name = input.file_name().unwrap_or_default().to_string_lossy();
    args.place(input, format!("{name}.{}", args.options.target.extension()))
}

impl TranslateArgs {
    /// The folder `-o` names (none for `-`, standard output, or a file).
    fn folder(&self) -> Option<&Path> {
        self.out
            .as_deref()
            .filter(|o| o.as_os_str() != "-" && self.file().is_none())
    }

    /// The file `-o` names: not a folder that exists, and ending in the target's extension.
    fn file(&self) -> Option<&Path> {
        self.out.as_deref().filter(|o| {
            !o.is_dir()
                && o.extension()
                    .is_some_and(|e| e == self.options.target.extension())
        })
    }

    /// Whether `-o -` asks for standard output.
    fn to_stdout(&self) -> bool {
        self.out.as_deref().is_some_and(|o| o.as_os_str() == "-")
    }

    /// Where a file named `name` goes: into `-o`'s folder, the file `-o` names (the one
    /// output), beside it (a map), else beside `beside`.
    fn place(&self, beside: &Path, name: String) -> PathBuf {
        if let Some(file) = self.file() {
            if name.ends_with(".bindings.json") {
                return file.with_extension("bindings.json");
            }
            return file.to_path_buf();
        }
        match self.folder() {
            Some(dir) => dir.join(name),
            None => beside.with_file_name(name),
        }
    }
}

/// Writes the code and, if asked, the binding map; the number of files written.
fn write_all(
    outputs: &[(PathBuf, Code)],
    bindings: &BindingMap,
    base: &Path,
    args: &TranslateArgs,
) -> Result<usize, ()> {
    let name = base.file_name().unwrap_or_default().to_string_lossy();
    let json_path = args.place(base, format!("{name}.bindings.json"));
    let mut files: Vec<(PathBuf, Vec<u8>)> = outputs
        .iter()
        .map(|(p, code)| (p.clone(), code.to_bytes()))
        .collect();
    if args.bindings {
        files.push((json_path, (bindings.to_json() + "\n").into_bytes()));
    }
    if args.to_stdout() {
        if args.options.target == Target::SpirV {
            eprintln!("error: SPIR-V is binary; write it to a folder with -o");
            return Err(());
        }
        for (path, bytes) in &files {
            println!("// ---- {}", path.display());
            print!("{}", String::from_utf8_lossy(bytes));
        }
        return Ok(0);
    }
    for (path, bytes) in &files {
        if let Err(e) = std::fs::write(path, bytes) {
            eprintln!("error: {}: {}", path.display(), essl_check::io_message(&e));
            return Err(());
        }
    }
    Ok(files.len())
}
