//! An open document and the shaders in it, as the one checking pipeline finds them
//! ([`essl_check::check_text`]): a shader file is one shader; an HTML page or a JS/TS file
//! holds any number, each placed on the document's lines by its [`essl_check::Assembly`], and
//! paired into programs where the file makes that plain.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::source::{SourceFile, Span};
use essl_check::extract::{HostKind, Skip};
use essl_check::{CheckOptions, Configs, Files, Phase};
use lsp_types::{DiagnosticSeverity, Position, Uri};

use crate::analysis::Analysis;
use crate::convert::{self, Place};

/// An open document.
#[derive(Debug)]
pub struct Doc {
    /// Its path (or its URI, for one that is not a file).
    pub path: PathBuf,
    /// Its text.
    pub text: Arc<SourceFile>,
    /// Whether it is an HTML or JS/TS file, whose shaders are parts of it.
    pub host: bool,
    /// Its shaders.
    pub parts: Vec<Arc<Analysis>>,
    /// The programs it makes plain: (vertex, fragment) indices into `parts`.
    pub pairs: Vec<(usize, usize)>,
    /// The shaders it holds that are not checked, and why.
    pub skipped: Vec<(Range<usize>, Skip)>,
    /// Why it could not be checked at all (a shader file whose stage nothing tells).
    pub unchecked: Option<String>,
}

/// The check options of an editor: the front end first, the lints later.
fn front_end() -> CheckOptions {
    CheckOptions {
        phase: Phase::FrontEnd,
        ..CheckOptions::default()
    }
}

impl Doc {
    /// Runs the front end on every shader of `text`, the document at `path`; `old`, the
    /// previous check of the same document, lends its lint findings until the new ones run.
    pub fn check(
        path: PathBuf,
        text: String,
        configs: &Configs,
        files: &Files,
        old: Option<&Doc>,
    ) -> Doc {
        let host = HostKind::of(&path).is_some();
        let ((unit, skipped), unchecked) =
            match essl_check::check_text(&path, text.clone(), configs, files, front_end()) {
                Ok(u) => (u, None),
                Err(e) => (Default::default(), Some(e.to_string())),
            };
        let skipped = skipped.into_iter().map(|s| (s.range, s.skip)).collect();
        // The document's text as its shaders hold it (a preset's program may bring shaders
        // of other files along: they are there for linking, not shown here).
        let doc_text = unit
            .shaders
            .iter()
            .find(|s| s.path == path)
            .map(|s| s.file().clone())
            .unwrap_or_else(|| Arc::new(SourceFile::new(path.display().to_string(), text)));
        let mut doc = Doc {
            path,
            text: doc_text,
            host,
            pairs: unit
                .programs
                .iter()
                .map(|p| (p.vertex, p.fragment))
                .collect(),
            parts: unit
                .shaders
                .into_iter()
                .map(|s| Arc::new(Analysis::new(s)))
                .collect(),
            skipped,
            unchecked,
        };
        if let Some(old) = old.filter(|o| o.parts.len() == doc.parts.len()) {
            for (new, old) in doc.parts.iter_mut().zip(&old.parts) {
                if let Some(a) = Arc::get_mut(new) {
                    a.carry_lints(old);
                }
            }
        }
        doc
    }

    /// Whether some shader still waits for lowering and the lints.
    pub fn unlinted(&self) -> bool {
        self.parts.iter().any(|p| !p.linted())
    }

    /// Lowers and lints every shader that waits for it; whether any did.
    pub fn lint(&mut self) -> bool {
        let mut any = false;
        for part in &mut self.parts {
            // Requests hold no analysis between messages, so this one is not shared.
            if let Some(a) = Arc::get_mut(part).filter(|a| !a.linted()) {
                a.lint();
                any = true;
            }
        }
        any
    }

    /// Where part `i` lies in the document.
    pub fn place(&self, i: usize) -> Place<'_> {
        Place {
            doc: &self.text,
            assembly: &self.parts[i].checked.assembly,
        }
    }

    /// Whether part `i` lies in this document (not a partner a preset's program brought).
    fn shown(&self, i: usize) -> bool {
        Arc::ptr_eq(self.parts[i].document(), &self.text)
    }

    /// The shader at a position, and where it lies.
    pub fn at(&self, pos: Position) -> Option<(&Analysis, Place<'_>)> {
        self.all().find(|(_, place)| place.offset(pos).is_some())
    }

    /// Every shader of the document and where it lies.
    pub fn all(&self) -> impl Iterator<Item = (&Analysis, Place<'_>)> {
        (0..self.parts.len())
            .filter(|&i| self.shown(i))
            .map(|i| (&*self.parts[i], self.place(i)))
    }

    /// The document's own diagnostics: each shader's (those in files it includes shown at
    /// the shader's start, pointing at their file), a note for each shader not checked, and
    /// the link diagnostics of the programs it makes plain.
    pub fn diagnostics(&self, uri: &Uri) -> Vec<lsp_types::Diagnostic> {
        let mut out = Vec::new();
        if let Some(why) = &self.unchecked {
            out.push(note(&self.text, 0..0, "not-checked", why.clone()));
        }
        for (a, _) in self.all() {
            for d in a.diagnostics() {
                out.push(convert::diagnostic(&self.text, uri, d));
            }
            let start = a.checked.embedded_at.unwrap_or(0);
            for (file, d) in a.elsewhere() {
                out.push(convert::elsewhere(&self.text, start, file, d));
            }
        }
        for (range, why) in &self.skipped {
            out.push(note(
                &self.text,
                range.clone(),
                "not-checked",
                format!("shader not checked: {}", why.reason()),
            ));
        }
        for &(v, f) in &self.pairs {
            let program = essl_check::link(&self.parts[v].checked, &self.parts[f].checked);
            for d in &program.diagnostics {
                match &d.file {
                    Some(file) if Arc::ptr_eq(file, &self.text) => {
                        out.push(convert::link_diagnostic(&self.text, uri, &d.diagnostic));
                    }
                    _ => {}
                }
            }
        }
        out
    }
}

/// An information-level diagnostic on the first line of `range`.
fn note(
    text: &SourceFile,
    range: Range<usize>,
    code: &str,
    message: String,
) -> lsp_types::Diagnostic {
    let line_end = text.text()[range.clone()]
        .find('\n')
        .map_or(range.end, |n| range.start + n);
    let span = Span::new(range.start as u32, line_end as u32);
    lsp_types::Diagnostic {
        range: convert::range(text, span),
        severity: Some(DiagnosticSeverity::INFORMATION),
        code: Some(lsp_types::NumberOrString::String(code.into())),
        source: Some("essl".into()),
        message,
        ..lsp_types::Diagnostic::default()
    }
}

/// The path of a document's URI (the URI itself when it names no file).
pub fn path_of(uri: &Uri) -> PathBuf {
    convert::uri_to_path(uri).unwrap_or_else(|| Path::new(uri.as_str()).to_path_buf())
}
