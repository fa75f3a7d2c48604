//! Code actions for the diagnostics in a range: each fix (the certain ones preferred, as
//! `essl lint --fix` applies them; the suggested ones as they are), and, for a lint rule's
//! finding, "allow this rule here": a `// essl-allow: RULE` comment on the line before.

use std::collections::HashMap;

use essl::diagnostic::{Applicability, Diagnostic};
use essl::source::{SourceFile, Span};
use lsp_types::{
    CodeAction, CodeActionKind, CodeActionOrCommand, Range, TextEdit, Uri, WorkspaceEdit,
};

use crate::analysis::Analysis;
use crate::convert::{self, Place};

fn overlaps(a: Range, b: Range) -> bool {
    let key = |p: lsp_types::Position| (p.line, p.character);
    key(a.start) <= key(b.end) && key(b.start) <= key(a.end)
}

fn edit(uri: &Uri, edits: Vec<TextEdit>) -> WorkspaceEdit {
    WorkspaceEdit {
        changes: Some(HashMap::from([(uri.clone(), edits)])),
        ..WorkspaceEdit::default()
    }
}

/// The code actions for the diagnostics that overlap `range`.
pub fn actions(
    a: &Analysis,
    place: Place<'_>,
    uri: &Uri,
    range: Range,
) -> Vec<CodeActionOrCommand> {
    let doc = place.doc;
    let mut out = Vec::new();
    for d in a.diagnostics() {
        let at = convert::range(doc, d.span);
        if !overlaps(at, range) {
            continue;
        }
        let diagnostic = convert::diagnostic(doc, uri, d);
        if let Some(fix) = &d.fix {
            let edits = fix
                .edits
                .iter()
                .map(|e| TextEdit::new(convert::range(doc, e.span), e.replacement.clone()))
                .collect();
            out.push(CodeActionOrCommand::CodeAction(CodeAction {
                title: fix.message.clone(),
                kind: Some(CodeActionKind::QUICKFIX),
                diagnostics: Some(vec![diagnostic.clone()]),
                edit: Some(edit(uri, edits)),
                is_preferred: Some(fix.applicability == Applicability::Certain),
                ..CodeAction::default()
            }));
        }
        if let Some(action) = allow_here(doc, uri, d, diagnostic) {
            out.push(CodeActionOrCommand::CodeAction(action));
        }
    }
    out
}

/// `// essl-allow: RULE` on a new line before the finding's, indented as it is.
fn allow_here(
    file: &SourceFile,
    uri: &Uri,
    d: &Diagnostic,
    diagnostic: lsp_types::Diagnostic,
) -> Option<CodeAction> {
    essl_lint::rule(d.code)?;
    let line = file.line_index(d.span.start);
    let start = file.line_start(line);
    let text = file.line_text(line);
    let indent: String = text
        .chars()
        .take_while(|c| *c == ' ' || *c == '\t')
        .collect();
    let at = convert::range(file, Span::empty(start));
    let comment = format!("{indent}// essl-allow: {}\n", d.code);
    Some(CodeAction {
        title: format!("allow `{}` here (// essl-allow: {})", d.code, d.code),
        kind: Some(CodeActionKind::QUICKFIX),
        diagnostics: Some(vec![diagnostic]),
        edit: Some(edit(uri, vec![TextEdit::new(at, comment)])),
        is_preferred: Some(false),
        ..CodeAction::default()
    })
}
