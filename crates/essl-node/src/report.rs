//! Checked shaders and programs as the JavaScript API's plain objects (JSON the JS side
//! parses): each diagnostic with its code, severity, message, primary and secondary ranges
//! (1-based lines and columns in the file the author wrote, and byte offsets), notes, help, fix
//! as text edits, and its rustc-style text.
//!
//! The rustc-style text is written only when it is read: each diagnostic's `rendered` is its
//! index in a [`Rendering`] the JS side keeps beside the result, and its getter asks the addon
//! for the text ([`Rendering::render`]). Rendering one took about as long as checking a small
//! shader, and most callers read only the code, message and range.
//!
//! Each object is a struct that borrows from the checked unit and is serialised straight to
//! the JSON text (no `serde_json::Value` tree in between). Fields are declared in the
//! alphabetical order of their JSON names, the order the keys have always come in.

use std::borrow::Cow;
use std::sync::Arc;

use essl::diagnostic::{Applicability, Diagnostic};
use essl::render::human_string;
use essl::source::SourceFile;
use essl_check::{CheckedProgram, CheckedShader, CheckedUnit};
use serde::Serialize;

/// `{line, column, offset}`: a byte offset of a file, with its 1-based line and column.
#[derive(Serialize)]
pub struct Position {
    column: u32,
    line: u32,
    offset: u32,
}

/// `{start, end}` of a span.
#[derive(Serialize)]
pub struct Range {
    end: Position,
    start: Position,
}

/// The position of a byte offset of `file`.
fn position(file: &SourceFile, offset: u32) -> Position {
    let lc = file.line_col(offset);
    Position {
        column: lc.column,
        line: lc.line,
        offset,
    }
}

/// The range of a span of `file`.
fn range(file: &SourceFile, span: essl::source::Span) -> Range {
    let span = essl::render::clamp_span(file, span);
    Range {
        end: position(file, span.end as u32),
        start: position(file, span.start as u32),
    }
}

/// A secondary label: `{range, message}`.
#[derive(Serialize)]
pub struct Secondary<'a> {
    message: &'a str,
    range: Range,
}

/// A fix's edit: `{range, text}`.
#[derive(Serialize)]
pub struct Edit<'a> {
    range: Range,
    text: &'a str,
}

/// A fix: `{message, applicability, edits}`.
#[derive(Serialize)]
pub struct Fix<'a> {
    applicability: &'static str,
    edits: Vec<Edit<'a>>,
    message: &'a str,
}

/// The diagnostics of a result, in the order of their `rendered` indices, each with its file
/// (none for a diagnostic with no place).
#[derive(Default)]
pub struct Rendering(Vec<(Option<Arc<SourceFile>>, Diagnostic)>);

impl Rendering {
    /// Whether no diagnostic was added.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Adds a diagnostic; its index.
    fn push(&mut self, file: Option<&Arc<SourceFile>>, d: &Diagnostic) -> usize {
        self.0.push((file.cloned(), d.clone()));
        self.0.len() - 1
    }

    /// The rustc-style text of the diagnostic at `index` (empty past the end).
    pub fn render(&self, index: usize) -> String {
        match self.0.get(index) {
            Some((Some(file), d)) => human_string(file, std::slice::from_ref(d)),
            Some((None, d)) => format!("{}[{}]: {}\n", d.severity.as_str(), d.code, d.message),
            None => String::new(),
        }
    }
}

/// A diagnostic as the API's object.
#[derive(Serialize)]
pub struct Diag<'a> {
    code: &'static str,
    file: Option<&'a str>,
    fix: Option<Fix<'a>>,
    help: Option<Cow<'a, str>>,
    label: &'a str,
    message: &'a str,
    notes: &'a [String],
    range: Option<Range>,
    /// The index of its text in the result's [`Rendering`].
    rendered: usize,
    secondary: Vec<Secondary<'a>>,
    severity: &'static str,
}

/// A diagnostic of `file` as the API's object, its text left to `rendering`.
pub fn diagnostic<'a>(
    file: &'a Arc<SourceFile>,
    d: &'a Diagnostic,
    rendering: &mut Rendering,
) -> Diag<'a> {
    let secondary = d
        .secondary
        .iter()
        .map(|l| Secondary {
            message: &l.message,
            range: range(file, l.span),
        })
        .collect();
    let fix = d.fix.as_ref().map(|f| Fix {
        applicability: match f.applicability {
            Applicability::Certain => "certain",
            Applicability::Suggested => "suggested",
        },
        edits: f
            .edits
            .iter()
            .map(|e| Edit {
                range: range(file, e.span),
                text: &e.replacement,
            })
            .collect(),
        message: &f.message,
    });
    Diag {
        code: d.code,
        file: Some(file.name()),
        fix,
        help: d.help_text(file).map(Cow::Owned),
        label: &d.label,
        message: &d.message,
        notes: &d.notes,
        range: Some(range(file, d.span)),
        rendered: rendering.push(Some(file), d),
        secondary,
        severity: d.severity.as_str(),
    }
}

/// A diagnostic with no place (a link error that points into neither shader).
fn unlocated<'a>(d: &'a Diagnostic, rendering: &mut Rendering) -> Diag<'a> {
    Diag {
        code: d.code,
        file: None,
        fix: None,
        help: d.help.as_deref().map(Cow::Borrowed),
        label: &d.label,
        message: &d.message,
        notes: &d.notes,
        range: None,
        rendered: rendering.push(None, d),
        secondary: Vec::new(),
        severity: d.severity.as_str(),
    }
}

/// The text WebGL is given: `null` where an `#include` could not be followed, `1` where it is
/// the source the caller passed (the JS side puts that string back: the text does not cross
/// twice), else the text.
#[derive(Serialize)]
#[serde(untagged)]
pub enum Text<'a> {
    /// The text, or `None`.
    Text(Option<&'a str>),
    /// The source as given.
    Source(u8),
}

/// A checked shader as the API's object.
#[derive(Serialize)]
pub struct Shader<'a> {
    diagnostics: Vec<Diag<'a>>,
    #[serde(rename = "embeddedAt")]
    embedded_at: Option<Position>,
    file: String,
    files: Vec<&'a str>,
    name: Option<&'a str>,
    ok: bool,
    /// Whether it is the partner file a lone shader file was linked with: its diagnostics are
    /// its own module's to report, and are left out.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    partner: bool,
    stage: &'static str,
    text: Text<'a>,
}

impl Shader<'_> {
    /// Marks it as the partner file: its diagnostics are dropped.
    pub fn as_partner(&mut self) {
        self.partner = true;
        self.diagnostics.clear();
    }
}

/// A checked shader: its file, stage, name, where it starts in its host, whether it compiled,
/// the text WebGL is given (includes in place; `1` where that is `source`, the text the
/// caller passed), the files that text was read from, and its diagnostics.
pub fn shader<'a>(
    s: &'a CheckedShader,
    source: Option<&str>,
    rendering: &mut Rendering,
) -> Shader<'a> {
    let embedded_at = s.embedded_at.and_then(|at| {
        let file = s.diagnostics.first().map(|f| &f.file)?;
        Some(position(file, at))
    });
    let text = match &s.shader {
        None => Text::Text(None),
        Some(_) if source == Some(s.assembly.text()) => Text::Source(1),
        Some(_) => Text::Text(Some(s.assembly.text())),
    };
    Shader {
        diagnostics: s.all().map(|(f, d)| diagnostic(f, d, rendering)).collect(),
        embedded_at,
        file: s.path.display().to_string(),
        files: s.assembly.files().iter().map(|f| f.name()).collect(),
        name: s.name.as_deref(),
        ok: s.ok(),
        partner: false,
        stage: s.stage.as_str(),
        text,
    }
}

/// An active uniform: `{name, type, size}`.
#[derive(Serialize)]
pub struct Uniform<'a> {
    name: &'a str,
    size: u32,
    #[serde(rename = "type")]
    ty: &'static str,
}

/// An active attribute: `{name, type, size, location}`.
#[derive(Serialize)]
pub struct Attribute<'a> {
    location: i32,
    name: &'a str,
    size: u32,
    #[serde(rename = "type")]
    ty: &'static str,
}

/// A linked program as the API's object.
#[derive(Serialize)]
pub struct Program<'a> {
    attributes: Vec<Attribute<'a>>,
    diagnostics: Vec<Diag<'a>>,
    /// The fragment shader's index among the shaders.
    pub fragment: usize,
    linked: bool,
    log: &'a str,
    ok: bool,
    uniforms: Vec<Uniform<'a>>,
    /// The vertex shader's index among the shaders.
    pub vertex: usize,
}

/// A linked program: whether it links, WebGL's log, the active uniforms and attributes as
/// `getActiveUniform`/`getActiveAttrib` list them, and its diagnostics.
pub fn program<'a>(p: &'a CheckedProgram, rendering: &mut Rendering) -> Program<'a> {
    let program = p.program.as_ref();
    let uniforms = program
        .iter()
        .flat_map(|p| &p.uniforms)
        .map(|u| Uniform {
            name: &u.name,
            size: u.size,
            ty: u.ty.name(),
        })
        .collect();
    let attributes = program
        .iter()
        .flat_map(|p| &p.attributes)
        .map(|a| Attribute {
            location: a.location,
            name: &a.name,
            size: a.size,
            ty: a.ty.name(),
        })
        .collect();
    let diagnostics = p
        .diagnostics
        .iter()
        .map(|d| match &d.file {
            Some(f) => diagnostic(f, &d.diagnostic, rendering),
            None => unlocated(&d.diagnostic, rendering),
        })
        .collect();
    Program {
        attributes,
        diagnostics,
        fragment: p.fragment,
        linked: p.linked,
        log: program.map_or("", |p| p.log.as_str()),
        ok: program.is_some_and(|p| p.ok) && p.linked,
        uniforms,
        vertex: p.vertex,
    }
}

/// A whole checked text as the API's object.
#[derive(Serialize)]
pub struct Unit<'a> {
    /// How many errors (with `denyWarnings`, errors and warnings).
    pub errors: usize,
    programs: Vec<Program<'a>>,
    /// Its shaders.
    pub shaders: Vec<Shader<'a>>,
    /// How many warnings.
    pub warnings: usize,
}

/// A whole checked text: its shaders, programs, and the counts of errors and warnings. The
/// first shader's text is `1` where it is `source`.
pub fn unit<'a>(u: &'a CheckedUnit, source: Option<&str>, rendering: &mut Rendering) -> Unit<'a> {
    let shaders = u
        .shaders
        .iter()
        .enumerate()
        .map(|(i, s)| shader(s, source.filter(|_| i == 0), rendering))
        .collect();
    let programs = u.programs.iter().map(|p| program(p, rendering)).collect();
    let count = |sev: essl::diagnostic::Severity| {
        u.shaders.iter().map(|s| s.count(sev)).sum::<usize>()
            + u.programs
                .iter()
                .flat_map(|p| &p.diagnostics)
                .filter(|d| d.diagnostic.severity == sev)
                .count()
    };
    Unit {
        errors: count(essl::diagnostic::Severity::Error),
        programs,
        shaders,
        warnings: count(essl::diagnostic::Severity::Warning),
    }
}
