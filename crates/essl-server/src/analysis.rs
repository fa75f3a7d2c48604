//! One shader checked by the pipeline ([`essl_check`]): the front end first, then lowering and
//! the lints with the settings of its nearest `essl.toml`, and indexed when a request needs
//! it.

use std::sync::{Arc, OnceLock};

use essl::diagnostic::{Diagnostic, Severity};
use essl::source::{SourceFile, Span};
use essl::Shader;
use essl_check::CheckedShader;

use crate::index::Index;

/// A shader checked, with its lint findings once they have run, and indexed on first use.
#[derive(Debug)]
pub struct Analysis {
    /// The check: the shader compiled on its assembled text, its diagnostics on their files
    /// (the document's first).
    pub checked: CheckedShader,
    /// Until the lints run on this text, the previous text's lint findings that lie outside
    /// the edit ([`Analysis::carry_lints`]), on the document's text.
    carried: Vec<Diagnostic>,
    /// What its names refer to, built when a request first asks.
    index: OnceLock<Index>,
}

impl Analysis {
    /// Wraps a shader the pipeline checked.
    pub fn new(checked: CheckedShader) -> Analysis {
        Analysis {
            checked,
            carried: Vec::new(),
            index: OnceLock::new(),
        }
    }

    /// The compiled shader (none where an `#include` could not be followed).
    pub fn shader(&self) -> Option<&Shader> {
        self.checked.shader.as_ref()
    }

    /// Whether the lints have run (a shader with errors needs none).
    pub fn linted(&self) -> bool {
        self.checked.linted || !self.checked.ok()
    }

    /// Lowers the shader to naga IR and runs the lints with its folder's levels.
    pub fn lint(&mut self) {
        essl_check::finish(&mut self.checked, true);
        self.carried.clear();
    }

    /// Until the lints run on the new text, keeps the findings of `old` (the previous check
    /// of the same document) whose spans all lie in the text the edit left alone, moved by the
    /// edit's change in length, so that an editor's warnings do not blink off and on at each
    /// keystroke.
    pub fn carry_lints(&mut self, old: &Analysis) {
        if self.linted() {
            return;
        }
        let (a, b) = (old.document().text(), self.document().text());
        let prefix = a.bytes().zip(b.bytes()).take_while(|(x, y)| x == y).count();
        let most = a.len().min(b.len()) - prefix;
        let suffix = a
            .bytes()
            .rev()
            .zip(b.bytes().rev())
            .take(most)
            .take_while(|(x, y)| x == y)
            .count();
        let moved = |s: Span| -> Option<Span> {
            if s.end as usize <= prefix {
                Some(s)
            } else if s.start as usize >= a.len() - suffix {
                let shift = |x: u32| (x as usize + b.len() - a.len()) as u32;
                Some(Span::new(shift(s.start), shift(s.end)))
            } else {
                None
            }
        };
        self.carried = old
            .lint_findings()
            .filter_map(|d| move_diagnostic(d, &moved))
            .collect();
    }

    /// The document the shader lies in (its own file, or its host).
    pub fn document(&self) -> &Arc<SourceFile> {
        self.checked.file()
    }

    /// The lint findings on the document: the carried ones until the lints run.
    fn lint_findings(&self) -> impl Iterator<Item = &Diagnostic> {
        let own = self.checked.diagnostics[0]
            .diagnostics
            .iter()
            .filter(|d| essl_lint::rule(d.code).is_some());
        own.chain(&self.carried)
    }

    /// The diagnostics on the document, in source order (the lints' notes too: an editor
    /// shows them as hints).
    pub fn diagnostics(&self) -> Vec<&Diagnostic> {
        let mut all: Vec<&Diagnostic> = self.checked.diagnostics[0]
            .diagnostics
            .iter()
            .chain(&self.carried)
            .collect();
        all.sort_by(|a, b| essl::diagnostic::order(a, b));
        all
    }

    /// Diagnostics in files the shader includes, with each file.
    pub fn elsewhere(&self) -> impl Iterator<Item = (&Arc<SourceFile>, &Diagnostic)> {
        self.checked.diagnostics[1..]
            .iter()
            .flat_map(|g| g.diagnostics.iter().map(move |d| (&g.file, d)))
            .filter(|(_, d)| d.severity != Severity::Note)
    }

    /// What the shader's names refer to (empty where nothing compiled).
    pub fn index(&self) -> &Index {
        self.index.get_or_init(|| match self.shader() {
            Some(s) => Index::build(&s.module, &s.file),
            None => Index::default(),
        })
    }
}

/// `d` with every span moved by `moved`, or `None` when one of them cannot be.
fn move_diagnostic(d: &Diagnostic, moved: &impl Fn(Span) -> Option<Span>) -> Option<Diagnostic> {
    let mut d = d.clone();
    for s in d.spans_mut() {
        *s = moved(*s)?;
    }
    Some(d)
}
