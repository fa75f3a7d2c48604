//! Checked shaders and programs as the JavaScript API's plain objects (JSON the JS side
//! parses): each diagnostic with its code, severity, message, primary and secondary ranges
//! (1-based lines and columns in the file the author wrote, and byte offsets), notes, help, fix
//! as text edits, and its rustc-style text.

use essl::diagnostic::{Applicability, Diagnostic};
use essl::render::human_string;
use essl::source::SourceFile;
use essl::Stage;
use essl_check::{CheckedProgram, CheckedShader, CheckedUnit};
use serde_json::{json, Value};

/// `{line, column, offset}` of a byte offset of `file`.
fn position(file: &SourceFile, offset: u32) -> Value {
    let lc = file.line_col(offset);
    json!({"line": lc.line, "column": lc.column, "offset": offset})
}

/// `{start, end}` of a span of `file`.
fn range(file: &SourceFile, span: essl::source::Span) -> Value {
    let span = essl::render::clamp_span(file, span);
    json!({
        "start": position(file, span.start as u32),
        "end": position(file, span.end as u32),
    })
}

/// A diagnostic of `file` as the API's object.
pub fn diagnostic(file: &SourceFile, d: &Diagnostic) -> Value {
    let secondary: Vec<Value> = d
        .secondary
        .iter()
        .map(|l| json!({"range": range(file, l.span), "message": l.message}))
        .collect();
    let fix = d.fix.as_ref().map(|f| {
        json!({
            "message": f.message,
            "applicability": match f.applicability {
                Applicability::Certain => "certain",
                Applicability::Suggested => "suggested",
            },
            "edits": f.edits.iter().map(|e| json!({
                "range": range(file, e.span),
                "text": e.replacement,
            })).collect::<Vec<_>>(),
        })
    });
    json!({
        "code": d.code,
        "severity": d.severity.as_str(),
        "message": d.message,
        "file": file.name(),
        "range": range(file, d.span),
        "label": d.label,
        "secondary": secondary,
        "notes": d.notes,
        "help": d.help_text(file),
        "fix": fix,
        "rendered": human_string(file, std::slice::from_ref(d)),
    })
}

/// A diagnostic with no place (a link error that points into neither shader).
fn unlocated(d: &Diagnostic) -> Value {
    json!({
        "code": d.code,
        "severity": d.severity.as_str(),
        "message": d.message,
        "file": null,
        "range": null,
        "label": d.label,
        "secondary": [],
        "notes": d.notes,
        "help": d.help,
        "fix": null,
        "rendered": format!("{}[{}]: {}\n", d.severity.as_str(), d.code, d.message),
    })
}

fn stage_name(stage: Stage) -> &'static str {
    match stage {
        Stage::Vertex => "vertex",
        Stage::Fragment => "fragment",
    }
}

/// A checked shader: its file, stage, name, where it starts in its host, whether it compiled,
/// the text WebGL is given (includes in place), the files that text was read from, and its
/// diagnostics.
pub fn shader(s: &CheckedShader) -> Value {
    let embedded = s.embedded_at.and_then(|at| {
        let file = s.diagnostics.first().map(|f| f.file.clone())?;
        Some(position(&file, at))
    });
    let diagnostics: Vec<Value> = s.all().map(|(f, d)| diagnostic(f, d)).collect();
    json!({
        "file": s.path.display().to_string(),
        "stage": stage_name(s.stage),
        "name": s.name,
        "embeddedAt": embedded,
        "ok": s.ok(),
        "text": s.shader.as_ref().map(|_| s.assembly.text()),
        "files": s.assembly.files().iter().map(|f| f.name()).collect::<Vec<_>>(),
        "diagnostics": diagnostics,
    })
}

/// A linked program: whether it links, WebGL's log, the active uniforms and attributes as
/// `getActiveUniform`/`getActiveAttrib` list them, and its diagnostics.
pub fn program(p: &CheckedProgram) -> Value {
    let program = p.program.as_ref();
    let uniforms: Vec<Value> = program
        .iter()
        .flat_map(|p| &p.uniforms)
        .map(|u| json!({"name": u.name, "type": u.ty.name(), "size": u.size}))
        .collect();
    let attributes: Vec<Value> = program
        .iter()
        .flat_map(|p| &p.attributes)
        .map(|a| {
            json!({"name": a.name, "type": a.ty.name(), "size": a.size, "location": a.location})
        })
        .collect();
    let diagnostics: Vec<Value> = p
        .diagnostics
        .iter()
        .map(|d| match &d.file {
            Some(f) => diagnostic(f, &d.diagnostic),
            None => unlocated(&d.diagnostic),
        })
        .collect();
    json!({
        "vertex": p.vertex,
        "fragment": p.fragment,
        "linked": p.linked,
        "ok": program.is_some_and(|p| p.ok) && p.linked,
        "log": program.map_or("", |p| p.log.as_str()),
        "uniforms": uniforms,
        "attributes": attributes,
        "diagnostics": diagnostics,
    })
}

/// A whole checked text: its shaders, programs, and the counts of errors and warnings.
pub fn unit(u: &CheckedUnit) -> Value {
    let shaders: Vec<Value> = u.shaders.iter().map(shader).collect();
    let programs: Vec<Value> = u.programs.iter().map(program).collect();
    let count = |sev: essl::diagnostic::Severity| {
        u.shaders.iter().map(|s| s.count(sev)).sum::<usize>()
            + u.programs
                .iter()
                .flat_map(|p| &p.diagnostics)
                .filter(|d| d.diagnostic.severity == sev)
                .count()
    };
    json!({
        "shaders": shaders,
        "programs": programs,
        "errors": count(essl::diagnostic::Severity::Error),
        "warnings": count(essl::diagnostic::Severity::Warning),
    })
}
