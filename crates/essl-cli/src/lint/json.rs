//! `essl lint --format json`: one JSON object per line for each shader, each program, and the
//! summary.
//!
//! The objects are structs that borrow the results and are written by `serde_json` straight
//! into the line, keys in alphabetical order (the order the output has always had). Building a
//! `serde_json::Value` tree first cost as much as compiling a small shader's lints did.

use essl::render::JsonDiagnostic;
use serde::Serialize;

use super::options::Look;
use super::output::file_of;
use super::results::{Checked, Linked};
use crate::discover::{Input, Source};

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

/// A shader's line (its object and `\n`).
pub(crate) fn shader_line(input: &Input, checked: &Result<Checked, String>, look: Look) -> Vec<u8> {
    // What every shader's object says; a file that could not be read adds only its error.
    let unread = ShaderObject {
        diagnostics: Vec::new(),
        embedded_at: None,
        error: None,
        file: input.path.display().to_string(),
        fixes_applied: None,
        kind: "shader",
        ok: false,
        stage: input.stage.as_str(),
        target: look.target.as_str(),
        version: None,
    };
    let object = match checked {
        Err(e) => ShaderObject {
            error: Some(e),
            ..unread
        },
        Ok(c) => {
            let mut diagnostics: Vec<JsonDiagnostic> = c
                .shader
                .diagnostics
                .iter()
                .map(|d| JsonDiagnostic::new(&c.shader.file, d))
                .collect();
            for (file, ds) in &c.included {
                diagnostics.extend(
                    ds.iter()
                        .map(|d| JsonDiagnostic::new(file, d).in_file(file.name())),
                );
            }
            let version = if c.shader.module.version == essl::Version::Es100 {
                "100"
            } else {
                "300 es"
            };
            ShaderObject {
                diagnostics,
                embedded_at: matches!(input.source, Source::Embedded(..)).then(|| input.label()),
                error: c.write_error.as_deref().filter(|_| look.fix),
                fixes_applied: look.fix.then_some(c.fixes_applied),
                ok: c.shader.ok(),
                version: Some(version),
                ..unread
            }
        }
    };
    line(&object)
}

/// A program's line (its object and `\n`).
pub(crate) fn program_line(linked: &Linked, look: Look) -> Vec<u8> {
    let Linked {
        vertex,
        fragment,
        vs,
        fs,
        program,
    } = *linked;
    let object = ProgramObject {
        attributes: program
            .attributes
            .iter()
            .map(|a| AttributeObject {
                location: a.location,
                name: &a.name,
                size: a.size,
                ty: a.ty.name(),
            })
            .collect(),
        diagnostics: program
            .diagnostics
            .iter()
            .map(|d| match file_of(vs, fs, d) {
                Some(file) => JsonDiagnostic::new(file, &d.diagnostic).in_file(file.name()),
                None => JsonDiagnostic::unlocated(&d.diagnostic),
            })
            .collect(),
        fragment: fragment.label(),
        kind: "program",
        log: &program.log,
        ok: program.ok,
        target: look.target.as_str(),
        uniforms: program
            .uniforms
            .iter()
            .map(|u| UniformObject {
                name: &u.name,
                size: u.size,
                ty: u.ty.name(),
            })
            .collect(),
        vertex: vertex.label(),
    };
    line(&object)
}

fn line(object: &impl Serialize) -> Vec<u8> {
    let mut line = serde_json::to_vec(object).expect("these objects always serialise");
    line.push(b'\n');
    line
}
