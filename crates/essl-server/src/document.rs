//! An open document and the shaders in it: a shader file is one shader; an HTML page or a JS/TS
//! file holds any number, found as `essl lint` finds them ([`essl_build::extract`]), each
//! checked on its own text and placed back on the document's lines, and paired into programs
//! where the file makes that plain.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::source::{SourceFile, Span};
use essl_build::extract::{self, HostKind, Skip};
use essl_build::Config;
use lsp_types::{DiagnosticSeverity, Position, Uri};

use crate::analysis::{self, Analysis};
use crate::convert::{self, Place};

/// One shader of a document.
#[derive(Debug)]
pub struct Part {
    /// Where its text starts in the document.
    pub base: u32,
    /// Its check.
    pub analysis: Arc<Analysis>,
}

/// An open document.
#[derive(Debug)]
pub struct Doc {
    /// Its path (or its URI, for one that is not a file).
    pub path: PathBuf,
    /// Its text.
    pub text: SourceFile,
    /// Whether it is an HTML or JS/TS file, whose shaders are parts of it.
    pub host: bool,
    /// Its shaders.
    pub parts: Vec<Part>,
    /// The programs it makes plain: (vertex, fragment) indices into `parts`.
    pub pairs: Vec<(usize, usize)>,
    /// The shaders it holds that are not checked, and why.
    pub skipped: Vec<(Range<usize>, Skip)>,
}

impl Doc {
    /// Runs the front end on every shader of `text`, the document at `path`; `old`, the
    /// previous check of the same document, lends its lint findings until the new ones run.
    pub fn check(path: PathBuf, text: String, config: &Config, old: Option<&Doc>) -> Doc {
        let mut doc = match HostKind::of(&path) {
            None => {
                let analysis = Analysis::check(&path, &text, config);
                let file = analysis.shader.file.clone();
                Doc {
                    path,
                    text: file,
                    host: false,
                    parts: vec![Part {
                        base: 0,
                        analysis: Arc::new(analysis),
                    }],
                    pairs: Vec::new(),
                    skipped: Vec::new(),
                }
            }
            Some(kind) => host(path, text, kind, config),
        };
        if let Some(old) = old.filter(|o| o.parts.len() == doc.parts.len()) {
            for (new, old) in doc.parts.iter_mut().zip(&old.parts) {
                if let Some(a) = Arc::get_mut(&mut new.analysis) {
                    a.carry_lints(&old.analysis);
                }
            }
        }
        doc
    }

    /// Whether some shader still waits for lowering and the lints.
    pub fn unlinted(&self) -> bool {
        self.parts.iter().any(|p| !p.analysis.linted)
    }

    /// Lowers and lints every shader that waits for it; whether any did.
    pub fn lint(&mut self, rules: &essl_lint::LintOptions) -> bool {
        let mut any = false;
        for part in &mut self.parts {
            // Requests hold no analysis between messages, so this one is not shared.
            if let Some(a) = Arc::get_mut(&mut part.analysis).filter(|a| !a.linted) {
                a.lint(rules);
                any = true;
            }
        }
        any
    }

    /// Where part `i` lies in the document.
    pub fn place(&self, i: usize) -> Place<'_> {
        let part = &self.parts[i];
        Place {
            doc: &self.text,
            base: part.base,
            len: part.analysis.shader.file.text().len() as u32,
        }
    }

    /// The shader at a position, and where it lies.
    pub fn at(&self, pos: Position) -> Option<(&Analysis, Place<'_>)> {
        (0..self.parts.len())
            .map(|i| (&*self.parts[i].analysis, self.place(i)))
            .find(|(_, place)| place.offset(pos).is_some())
    }

    /// Every shader and where it lies.
    pub fn all(&self) -> impl Iterator<Item = (&Analysis, Place<'_>)> {
        (0..self.parts.len()).map(|i| (&*self.parts[i].analysis, self.place(i)))
    }

    /// The document's own diagnostics: each shader's, a note for each shader not checked, and
    /// the link diagnostics of the programs it makes plain.
    pub fn diagnostics(&self, uri: &Uri) -> Vec<lsp_types::Diagnostic> {
        let mut out = Vec::new();
        for (a, place) in self.all() {
            for d in a.diagnostics() {
                out.push(convert::diagnostic(place, &a.shader.file, uri, d));
            }
        }
        for (range, why) in &self.skipped {
            let line_end = self.text.text()[range.clone()]
                .find('\n')
                .map_or(range.end, |n| range.start + n);
            let span = Span::new(range.start as u32, line_end as u32);
            out.push(lsp_types::Diagnostic {
                range: convert::range(&self.text, span),
                severity: Some(DiagnosticSeverity::INFORMATION),
                code: Some(lsp_types::NumberOrString::String("not-checked".into())),
                source: Some("essl".into()),
                message: format!("shader not checked: {}", why.reason()),
                ..lsp_types::Diagnostic::default()
            });
        }
        for &(v, f) in &self.pairs {
            let (vs, fs) = (&self.parts[v].analysis, &self.parts[f].analysis);
            let Some(program) = analysis::link(&vs.shader, &fs.shader) else {
                continue;
            };
            for d in &program.diagnostics {
                let i = if d.stage == Some(essl::Stage::Fragment) {
                    f
                } else {
                    v
                };
                let file = &self.parts[i].analysis.shader.file;
                out.push(convert::link_diagnostic(
                    self.place(i),
                    file,
                    uri,
                    &d.diagnostic,
                ));
            }
        }
        out
    }
}

/// The shaders of an HTML or JS/TS file.
fn host(path: PathBuf, text: String, kind: HostKind, config: &Config) -> Doc {
    let found = extract::extract(kind, &text);
    let mut parts = Vec::new();
    let mut skipped = Vec::new();
    // Where each shader found went among the parts.
    let mut part_of = vec![None; found.len()];
    for (k, e) in found.iter().enumerate() {
        match (e.skip, e.stage) {
            (None, Some(stage)) => {
                part_of[k] = Some(parts.len());
                let analysis = Analysis::check_as(&path, &text[e.range.clone()], stage, config);
                parts.push(Part {
                    base: e.range.start as u32,
                    analysis: Arc::new(analysis),
                });
            }
            (skip, _) => skipped.push((e.range.clone(), skip.unwrap_or(Skip::NoStage))),
        }
    }
    let pairs = extract::pairs(&found)
        .into_iter()
        .filter_map(|(v, f)| Some((part_of[v]?, part_of[f]?)))
        .collect();
    let file = SourceFile::new(path.display().to_string(), text);
    Doc {
        path,
        text: file,
        host: true,
        parts,
        pairs,
        skipped,
    }
}

/// The path of a document's URI (the URI itself when it names no file).
pub fn path_of(uri: &Uri) -> PathBuf {
    convert::uri_to_path(uri).unwrap_or_else(|| Path::new(uri.as_str()).to_path_buf())
}
