//! `essl lint --format json`: one JSON object per line for each shader, each program, and the
//! summary.
//!
//! The objects are structs that borrow the results and are written by `serde_json` straight
//! into the line, keys in alphabetical order (the order the output has always had). Building a
//! `serde_json::Value` tree first cost as much as compiling a small shader's lints did.

use essl::render::JsonDiagnostic;
use serde::Serialize;

use essl_check::{CheckedProgram, CheckedShader};

use super::options::Look;
use super::results::FileResult;

/// A shader's object:
/// `{"kind":"shader","file","stage","target","version","ok","diagnostics":[…]}` (`target`:
/// `webgl1` or `webgl2`; `version`: `100` or `300 es`, absent when the file could not be
/// read), with `"embedded_at"` (`FILE:LINE`) for a shader inside an HTML or JS file,
/// `"fixes_applied"` under `--fix`, and `"error"` when the file could not be read
/// (or the fix written back).
#[derive(Serialize)]
struct ShaderObject<'a> {
    diagnostics: Vec<JsonDiagnostic<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    embedded_at: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
    file: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    fixes_applied: Option<usize>,
    kind: &'static str,
    ok: bool,
    stage: &'static str,
    target: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    version: Option<&'static str>,
}

/// A program's object: `{"kind":"program","vertex","fragment","target","ok","log",
/// "uniforms":[{"name","type","size"}],"attributes":[{"name","type","size","location"}],
/// "diagnostics":[…]}`; each diagnostic also carries `"file"` (null, with null positions, when
/// it points into neither shader).
#[derive(Serialize)]
struct ProgramObject<'a> {
    attributes: Vec<AttributeObject<'a>>,
    diagnostics: Vec<JsonDiagnostic<'a>>,
    fragment: String,
    kind: &'static str,
    log: &'a str,
    ok: bool,
    target: &'static str,
    uniforms: Vec<UniformObject<'a>>,
    vertex: String,
}

#[derive(Serialize)]
struct AttributeObject<'a> {
    location: i32,
    name: &'a str,
    size: u32,
    #[serde(rename = "type")]
    ty: &'static str,
}

#[derive(Serialize)]
struct UniformObject<'a> {
    name: &'a str,
    size: u32,
    #[serde(rename = "type")]
    ty: &'static str,
}

/// The object of a shader that could not be read: its file and the error.
fn unread_object<'a>(r: &'a FileResult, look: Look) -> ShaderObject<'a> {
    ShaderObject {
        diagnostics: Vec::new(),
        embedded_at: None,
        error: r.read_error.as_deref(),
        file: r.named.path.display().to_string(),
        fixes_applied: None,
        kind: "shader",
        ok: false,
        stage: r.named.stage.as_str(),
        target: look.target.as_str(),
        version: None,
    }
}

/// The line of a shader that could not be read.
pub(crate) fn unread_line(r: &FileResult, look: Look) -> Vec<u8> {
    line(&unread_object(r, look))
}

/// A shader's line (its object and `\n`).
pub(crate) fn shader_line(r: &FileResult, s: &CheckedShader, look: Look) -> Vec<u8> {
    let mut diagnostics: Vec<JsonDiagnostic> = Vec::new();
    for (k, g) in s.diagnostics.iter().enumerate() {
        diagnostics.extend(g.diagnostics.iter().map(|d| {
            let j = JsonDiagnostic::new(&g.file, d);
            if k == 0 {
                j
            } else {
                j.in_file(g.file.name())
            }
        }));
    }
    let version = s.shader.as_ref().map(|sh| {
        if sh.module.version == essl::Version::Es100 {
            "100"
        } else {
            "300 es"
        }
    });
    let target = s.shader.as_ref().map_or(look.target, |sh| sh.target);
    let object = ShaderObject {
        diagnostics,
        embedded_at: r.named.embedded.then(|| r.named.label.clone()),
        error: r.write_error.as_deref().filter(|_| look.fix),
        fixes_applied: look.fix.then_some(r.fixes_applied),
        ok: s.ok(),
        target: target.as_str(),
        version,
        ..unread_object(r, look)
    };
    line(&object)
}

/// An included file `--fix` changed: `{"kind":"fixed","file","fixes_applied"}`.
pub(crate) fn fixed_line(r: &FileResult) -> Vec<u8> {
    #[derive(Serialize)]
    struct Fixed<'a> {
        #[serde(skip_serializing_if = "Option::is_none")]
        error: Option<&'a str>,
        file: String,
        fixes_applied: usize,
        kind: &'static str,
    }
    line(&Fixed {
        error: r.write_error.as_deref(),
        file: r.named.path.display().to_string(),
        fixes_applied: r.fixes_applied,
        kind: "fixed",
    })
}

/// A program's line (its object and `\n`).
pub(crate) fn program_line(
    p: &CheckedProgram,
    vs: &CheckedShader,
    fs: &CheckedShader,
    look: Look,
) -> Vec<u8> {
    let program = p.program.as_ref();
    let object = ProgramObject {
        attributes: program
            .iter()
            .flat_map(|p| &p.attributes)
            .map(|a| AttributeObject {
                location: a.location,
                name: &a.name,
                size: a.size,
                ty: a.ty.name(),
            })
            .collect(),
        diagnostics: p
            .diagnostics
            .iter()
            .map(|d| match &d.file {
                Some(file) => JsonDiagnostic::new(file, &d.diagnostic).in_file(file.name()),
                None => JsonDiagnostic::unlocated(&d.diagnostic),
            })
            .collect(),
        fragment: fs.label(),
        kind: "program",
        log: program.map_or("", |p| p.log.as_str()),
        ok: program.is_some_and(|p| p.ok),
        target: look.target.as_str(),
        uniforms: program
            .iter()
            .flat_map(|p| &p.uniforms)
            .map(|u| UniformObject {
                name: &u.name,
                size: u.size,
                ty: u.ty.name(),
            })
            .collect(),
        vertex: vs.label(),
    };
    line(&object)
}

fn line(object: &impl Serialize) -> Vec<u8> {
    let mut line = serde_json::to_vec(object).expect("these objects always serialise");
    line.push(b'\n');
    line
}
