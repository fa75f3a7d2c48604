//! `essl translate`: WebGL shaders to WGSL (or SPIR-V, MSL, HLSL, desktop GLSL), with the
//! binding map beside them.
//!
//! Files and folders are found as `essl lint` finds them; every `NAME.vert` + `NAME.frag` pair
//! is linked and translated as a program (matching varying locations, one uniform buffer for
//! both stages), any other shader on its own. Each output goes next to its input, or into the
//! folder `-o` names, as the input's file name plus the target's extension
//! (`light.frag` → `light.frag.wgsl`); the binding map, with `--bindings json`, as
//! `NAME.bindings.json` (`light.frag.bindings.json` for a lone shader). A shader with errors is
//! not translated: its diagnostics are printed as `essl lint` prints them.

use std::path::{Path, PathBuf};

use crate::files;
use essl::source::SourceFile;
use essl::{CompileOptions, Shader, Stage};
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
}

/// Runs `essl translate`; the exit status (0 all translated, 1 some could not be, 2 usage or
/// I/O errors).
pub fn run(args: &TranslateArgs) -> i32 {
    let shader_files = match crate::files::collect(&args.paths, args.stage) {
        Ok(c) if c.errors.is_empty() => c.inputs,
        Ok(c) => {
            for e in &c.errors {
                eprintln!("error: {e}");
            }
            return 2;
        }
        Err(e) => {
            eprintln!("error: {e}");
            return 2;
        }
    };
    if shader_files.is_empty() {
        eprintln!("error: no shader files (.vert, .frag, .vs, .fs, .vsh, .fsh) found");
        return 2;
    }
    if let Some(out) = args.folder() {
        if let Err(e) = std::fs::create_dir_all(out) {
            eprintln!("error: {}: {}", out.display(), files::io_message(&e));
            return 2;
        }
    }
    let mut shaders = Vec::with_capacity(shader_files.len());
    for f in &shader_files {
        match files::read_source(&f.path) {
            Ok(text) => shaders.push(essl::compile(
                SourceFile::new(f.path.display().to_string(), text),
                f.stage,
                &CompileOptions::default(),
            )),
            Err(e) => {
                eprintln!("error: {}: {e}", f.path.display());
                return 2;
            }
        }
    }
    let pairs = if args.no_link {
        Vec::new()
    } else {
        files::pairs(&shader_files)
    };
    let mut paired = vec![false; shader_files.len()];
    let mut status = 0;
    let mut written = 0usize;
    for &(v, f) in &pairs {
        paired[v] = true;
        paired[f] = true;
        let (vs, fs) = (&shaders[v], &shaders[f]);
        if report_errors(vs) | report_errors(fs) {
            status = 1;
            continue;
        }
        match essl_translate::translate_program(vs, fs, &args.options) {
            Ok(t) => {
                // `dir/light.vert` → the program's map is `light.bindings.json`.
                let base = shader_files[v].path.with_extension("");
                let outputs = [
                    (output_path(&shader_files[v].path, args), t.vertex),
                    (output_path(&shader_files[f].path, args), t.fragment),
                ];
                match write_all(&outputs, &t.bindings, &base, args) {
                    Ok(n) => written += n,
                    Err(()) => return 2,
                }
            }
            Err(e) => {
                status = 1;
                eprintln!(
                    "error: {} + {}: {}",
                    shader_files[v].path.display(),
                    shader_files[f].path.display(),
                    message(&e)
                );
            }
        }
    }
    for (i, shader) in shaders.iter().enumerate() {
        if paired[i] {
            continue;
        }
        if report_errors(shader) {
            status = 1;
            continue;
        }
        match essl_translate::translate_shader(shader, &args.options) {
            Ok(t) => {
                let path = &shader_files[i].path;
                let outputs = [(output_path(path, args), t.code)];
                // A lone `light.frag` has `light.frag.bindings.json`.
                match write_all(&outputs, &t.bindings, path, args) {
                    Ok(n) => written += n,
                    Err(()) => return 2,
                }
            }
            Err(e) => {
                status = 1;
                eprintln!("error: {}: {}", shader_files[i].path.display(), message(&e));
            }
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

/// Prints a shader's diagnostics if it has errors; whether it has.
fn report_errors(shader: &Shader) -> bool {
    if shader.ok() {
        return false;
    }
    eprint!(
        "{}",
        essl::render::human_string(&shader.file, &shader.diagnostics)
    );
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
    /// The folder `-o` names (none for `-`, standard output).
    fn folder(&self) -> Option<&Path> {
        self.out.as_deref().filter(|o| o.as_os_str() != "-")
    }

    /// Whether `-o -` asks for standard output.
    fn to_stdout(&self) -> bool {
        self.out.as_deref().is_some_and(|o| o.as_os_str() == "-")
    }

    /// Where a file named `name` goes: into `-o`'s folder, else beside `beside`.
    fn place(&self, beside: &Path, name: String) -> PathBuf {
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
            eprintln!("error: {}: {}", path.display(), files::io_message(&e));
            return Err(());
        }
    }
    Ok(files.len())
}
