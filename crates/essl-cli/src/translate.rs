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

use essl::source::SourceFile;
use essl::{CompileOptions, Shader, Stage};
use essl_build::files::{self, ShaderFile};
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
    let mut shader_files = Vec::new();
    for path in &args.paths {
        if path.is_dir() {
            let (found, errors) = files::walk(path, &mut |_| true);
            if let Some((p, e)) = errors.first() {
                eprintln!("error: {}: {}", p.display(), files::io_message(e));
                return 2;
            }
            shader_files.extend(found);
        } else {
            let Some(stage) = args.stage.or_else(|| Stage::from_path(path)) else {
                eprintln!(
                    "error: {}: the extension does not say the stage (.vert or .frag); use \
                     --stage",
                    path.display()
                );
                return 2;
            };
            shader_files.push(ShaderFile {
                path: path.clone(),
                stage,
            });
        }
    }
    if shader_files.is_empty() {
        eprintln!("error: no shader files (.vert, .frag, .vs, .fs, .vsh, .fsh) found");
        return 2;
    }
    if let Some(out) = args.out.as_ref().filter(|o| o.as_os_str() != "-") {
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
                let base = program_base(&shader_files[v].path);
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
                match write_all(&outputs, &t.bindings, &lone_base(path), args) {
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
    if args.out.as_ref().is_none_or(|o| o.as_os_str() != "-") {
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
    let name = format!(
        "{}.{}",
        input.file_name().unwrap_or_default().to_string_lossy(),
        args.options.target.extension()
    );
    match args.out.as_ref().filter(|o| o.as_os_str() != "-") {
        Some(dir) => dir.join(name),
        None => input.with_file_name(name),
    }
}

/// `dir/light.vert` → `dir/light` (the program's binding map is `light.bindings.json`).
fn program_base(vertex: &Path) -> PathBuf {
    vertex.with_extension("")
}

/// `dir/light.frag` stays itself (its binding map is `light.frag.bindings.json`).
fn lone_base(path: &Path) -> PathBuf {
    path.to_path_buf()
}

/// Writes the code and, if asked, the binding map; the number of files written.
fn write_all(
    outputs: &[(PathBuf, Code)],
    bindings: &BindingMap,
    base: &Path,
    args: &TranslateArgs,
) -> Result<usize, ()> {
    let to_stdout = args.out.as_ref().is_some_and(|o| o.as_os_str() == "-");
    let json_path = {
        let name = format!(
            "{}.bindings.json",
            base.file_name().unwrap_or_default().to_string_lossy()
        );
        match args.out.as_ref().filter(|o| o.as_os_str() != "-") {
            Some(dir) => dir.join(name),
            None => base.with_file_name(name),
        }
    };
    let mut files: Vec<(PathBuf, Vec<u8>)> = outputs
        .iter()
        .map(|(p, code)| (p.clone(), code.to_bytes()))
        .collect();
    if args.bindings {
        files.push((json_path, (bindings.to_json() + "\n").into_bytes()));
    }
    if to_stdout {
        for (path, bytes) in &files {
            if args.options.target == Target::SpirV && path.extension().is_some_and(|e| e == "spv")
            {
                eprintln!(
                    "error: {}: SPIR-V is binary; write it to a folder with -o",
                    path.display()
                );
                return Err(());
            }
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
