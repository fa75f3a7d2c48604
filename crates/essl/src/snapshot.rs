//! Stable plain text of what essl says about a shader or a program, for snapshot tests
//! (`insta::assert_snapshot!`) in a project that keeps its shaders beside its Rust code.
//!
//! [`shader`] compiles one file and [`program`] compiles and links `NAME.vert` + `NAME.frag`;
//! both return the rustc-style diagnostics without colour, with the file named by its path
//! relative to the crate under test (`CARGO_MANIFEST_DIR`, which `cargo test` sets) so that the
//! text is the same on every machine. A program's text goes on with the link result and the
//! active attributes and uniforms in WebGL's enumeration order (`getActiveAttrib`,
//! `getActiveUniform`) with their WebGL types. [`shader_info_log`] and [`program_info_log`]
//! give instead the info logs in a browser's format (`ERROR: 0:LINE: 'token' : message`, as
//! `essl-gl`'s `getShaderInfoLog` returns them), for those who compare with one. The lints of
//! `essl-lint` are not part of either: add `essl_lint::lint`'s findings to a shader's
//! diagnostics before [`shader_text`] to snapshot them too.
//!
//! ```
//! # let dir = std::env::temp_dir().join("essl-snapshot-doc");
//! # std::fs::create_dir_all(&dir).unwrap();
//! # let path = dir.join("flat.frag");
//! # std::fs::write(&path, "#version 300 es\nprecision mediump float;\nout vec4 color;\nvoid main() { color = vec4(1); }\n").unwrap();
//! let text = essl::snapshot::shader(&path);
//! assert!(text.ends_with("(fragment): compiled\n"));
//! // In a test: insta::assert_snapshot!(essl::snapshot::shader("shaders/flat.frag"));
//! ```
//!
//! The text depends only on the shader and on essl's version: no absolute path, no colour, no
//! timing. Files that cannot be read give one line saying why, so that a snapshot shows it.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::link::{self, Program};
use crate::reflect::UniformSource;
use crate::render;
use crate::source::SourceFile;
use crate::{compile, CompileOptions, Shader, Stage};

/// The shader at `path` (stage from its extension: `.vert`/`.vs`/`.vsh` or
/// `.frag`/`.fs`/`.fsh`), compiled: a header line, then its diagnostics rendered rustc-style.
pub fn shader(path: impl AsRef<Path>) -> String {
    match load(path.as_ref()) {
        Ok(shader) => shader_text(&shader),
        Err(line) => line,
    }
}

/// The program `vertex` + `fragment`: both shaders as [`shader`] gives them, then the link
/// result with its diagnostics, the active attributes and the active uniforms.
pub fn program(vertex: impl AsRef<Path>, fragment: impl AsRef<Path>) -> String {
    match (load(vertex.as_ref()), load(fragment.as_ref())) {
        (Ok(vs), Ok(fs)) => program_text(&vs, &fs),
        (vs, fs) => {
            let mut out = String::new();
            for s in [vs, fs] {
                out.push_str(&s.map_or_else(|line| line, |s| shader_text(&s)));
            }
            out.push_str("== link: not attempted (a shader could not be read)\n");
            out
        }
    }
}

/// The shader's info log in a browser's format (`ERROR: 0:LINE: 'token' : message` lines;
/// empty when it compiles without warnings), as `essl-gl`'s `getShaderInfoLog` gives it.
pub fn shader_info_log(path: impl AsRef<Path>) -> String {
    match load(path.as_ref()) {
        Ok(s) => render::webgl_info_log(&s.file, &s.diagnostics),
        Err(line) => line,
    }
}

/// The three info logs of the program `vertex` + `fragment`, each under a header line:
/// both shaders' `getShaderInfoLog` and the program's `getProgramInfoLog` (the link is
/// attempted only when both compile, as a browser's link fails at once otherwise).
pub fn program_info_log(vertex: impl AsRef<Path>, fragment: impl AsRef<Path>) -> String {
    let (vs, fs) = match (load(vertex.as_ref()), load(fragment.as_ref())) {
        (Ok(vs), Ok(fs)) => (vs, fs),
        (vs, fs) => return [vs.err(), fs.err()].into_iter().flatten().collect(),
    };
    let mut out = String::new();
    for s in [&vs, &fs] {
        let _ = writeln!(out, "== {} shader info log", s.stage.as_str());
        out.push_str(&render::webgl_info_log(&s.file, &s.diagnostics));
    }
    out.push_str("== program info log\n");
    if vs.ok() && fs.ok() {
        out.push_str(&link::link(&vs, &fs).log);
    } else {
        out.push_str("(not linked: a shader did not compile)\n");
    }
    out
}

/// The text of [`shader`] for a shader compiled elsewhere (its file name is used as it is).
pub fn shader_text(shader: &Shader) -> String {
    let mut out = String::new();
    let (errors, warnings) = (shader.error_count(), shader.warning_count());
    let status = if errors == 0 { "compiled" } else { "failed" };
    let _ = write!(
        out,
        "== {} ({}): {status}",
        shader.file.name(),
        shader.stage.as_str()
    );
    if errors + warnings > 0 {
        let _ = write!(
            out,
            ", {} and {}",
            plural(errors, "error"),
            plural(warnings, "warning")
        );
    }
    out.push('\n');
    out.push_str(&render::human_string(&shader.file, &shader.diagnostics));
    out
}

/// The text of [`program`] for shaders compiled elsewhere.
pub fn program_text(vs: &Shader, fs: &Shader) -> String {
    let mut out = shader_text(vs);
    out.push_str(&shader_text(fs));
    if !(vs.ok() && fs.ok()) {
        out.push_str("== link: not attempted (a shader did not compile)\n");
        return out;
    }
    let program = link::link(vs, fs);
    out.push_str(&link_text(vs, fs, &program));
    out
}

/// The link result, its diagnostics (each rendered against the file it points into) and the
/// active attributes and uniforms of a linked program.
pub fn link_text(vs: &Shader, fs: &Shader, program: &Program) -> String {
    let mut out = String::new();
    let status = if program.ok { "linked" } else { "failed" };
    let _ = writeln!(out, "== link: {status}");
    for d in &program.diagnostics {
        let file = match d.stage {
            Some(Stage::Vertex) => Some(&vs.file),
            Some(Stage::Fragment) => Some(&fs.file),
            None => None,
        };
        match file {
            Some(file) => out.push_str(&render::human_string(
                file,
                std::slice::from_ref(&d.diagnostic),
            )),
            None => {
                let mut buf = codespan_reporting::term::termcolor::NoColor::new(Vec::new());
                render::emit_human_unlocated(
                    &mut buf,
                    std::slice::from_ref(&d.diagnostic),
                    &render::default_config(),
                )
                .expect("writing to memory cannot fail");
                out.push_str(&String::from_utf8_lossy(&buf.into_inner()));
            }
        }
    }
    if !program.ok {
        return out;
    }
    out.push_str("attributes (getActiveAttrib order):\n");
    let attributes: Vec<_> = program
        .attributes
        .iter()
        .map(|a| {
            let size = if a.size > 1 {
                format!(" [{}]", a.size)
            } else {
                String::new()
            };
            (
                format!("{}{size}", a.name),
                format!("{} @{}", a.ty.name(), a.location),
            )
        })
        .collect();
    table(&mut out, &attributes);
    out.push_str("uniforms (getActiveUniform order):\n");
    let uniforms: Vec<_> = program
        .uniforms
        .iter()
        .map(|u| {
            let size = if u.size > 1 {
                format!(" [{}]", u.size)
            } else {
                String::new()
            };
            let block = [(&u.vertex, vs), (&u.fragment, fs)]
                .into_iter()
                .find_map(|(source, shader)| match source {
                    Some(UniformSource::Block { block, .. }) => {
                        Some(format!(" (block {})", shader.module.blocks[*block].name))
                    }
                    _ => None,
                })
                .unwrap_or_default();
            (
                format!("{}{size}", u.name),
                format!("{}{block}", u.ty.name()),
            )
        })
        .collect();
    table(&mut out, &uniforms);
    out
}

/// Two aligned columns, indented by two spaces; `(none)` for an empty list.
fn table(out: &mut String, rows: &[(String, String)]) {
    if rows.is_empty() {
        out.push_str("  (none)\n");
    }
    let width = rows.iter().map(|r| r.0.chars().count()).max().unwrap_or(0);
    for (a, b) in rows {
        let _ = writeln!(out, "  {a:width$}  {b}");
    }
}

fn plural(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// The name a snapshot shows for `path`: relative to `CARGO_MANIFEST_DIR` (with `..` where
/// it lies outside), with `/` between components on every platform; the path as given when
/// the variable is unset or the file does not exist.
pub fn display_path(path: &Path) -> String {
    let relative = std::env::var_os("CARGO_MANIFEST_DIR")
        .and_then(|base| relative_to(path, Path::new(&base)))
        .unwrap_or_else(|| path.to_path_buf());
    let parts: Vec<String> = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    parts.join("/")
}

/// `path` relative to the folder `base`, both resolved (links, `..`) first.
fn relative_to(path: &Path, base: &Path) -> Option<PathBuf> {
    let path = std::fs::canonicalize(path).ok()?;
    let base = std::fs::canonicalize(base).ok()?;
    let common = path
        .components()
        .zip(base.components())
        .take_while(|(a, b)| a == b)
        .count();
    if common == 0 {
        return None;
    }
    let mut out = PathBuf::new();
    for _ in base.components().skip(common) {
        out.push("..");
    }
    for c in path.components().skip(common) {
        out.push(c);
    }
    Some(out)
}

/// Reads and compiles a file, or gives the one line that says why it could not be.
fn load(path: &Path) -> Result<Shader, String> {
    let name = display_path(path);
    let Some(stage) = Stage::from_path(path) else {
        return Err(format!(
            "== {name}: no stage (name it .vert/.vs/.vsh or .frag/.fs/.fsh)\n"
        ));
    };
    let text = std::fs::read_to_string(path).map_err(|e| format!("== {name}: {e}\n"))?;
    Ok(compile(
        SourceFile::new(name, text),
        stage,
        &CompileOptions::default(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn compiled(name: &str, stage: Stage, text: &str) -> Shader {
        compile(
            SourceFile::new(name, text),
            stage,
            &CompileOptions::default(),
        )
    }

    #[test]
    fn a_program_lists_its_interface_in_webgl_order() {
        let vs = compiled(
            "p.vert",
            Stage::Vertex,
            "#version 300 es\nin vec4 a_position;\nin vec3 a_normal;\nuniform mat4 u_m;\n\
             uniform vec3 u_l[4];\nout vec3 v_n;\n\
             void main() { v_n = a_normal + u_l[1]; gl_Position = u_m * a_position; }\n",
        );
        let fs = compiled(
            "p.frag",
            Stage::Fragment,
            "#version 300 es\nprecision mediump float;\nin vec3 v_n;\nuniform vec4 u_color;\n\
             out vec4 o;\nvoid main() { o = u_color * v_n.x; }\n",
        );
        let text = program_text(&vs, &fs);
        assert_eq!(
            text,
            "== p.vert (vertex): compiled\n== p.frag (fragment): compiled\n== link: linked\n\
             attributes (getActiveAttrib order):\n  a_position  FLOAT_VEC4 @0\n  a_normal    FLOAT_VEC3 @1\n\
             uniforms (getActiveUniform order):\n  u_m         FLOAT_MAT4\n  u_l[0] [4]  FLOAT_VEC3\n  u_color     FLOAT_VEC4\n"
        );
    }

    #[test]
    fn errors_are_counted_and_rendered_without_colour() {
        let fs = compiled(
            "bad.frag",
            Stage::Fragment,
            "#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(x); }\n",
        );
        let text = shader_text(&fs);
        assert!(text.starts_with("== bad.frag (fragment): failed, 1 error and 0 warnings\n"));
        assert!(text.contains("--> bad.frag:4:24"), "{text}");
        assert!(!text.contains('\u{1b}'), "no colour codes: {text}");
    }

    #[test]
    fn an_unreadable_file_is_one_line() {
        let text = shader("does/not/exist.frag");
        assert!(text.starts_with("== does/not/exist.frag: "), "{text}");
        assert_eq!(text.lines().count(), 1);
        assert!(shader("x.txt").contains("no stage"));
    }
}
