//! Completion: the names in scope at the cursor (the enclosing function's parameters and
//! locals, the globals and functions), the built-in functions and variables of the shader's
//! language, and GLSL ES's keywords and types.

use essl::Version;
use lsp_types::{CompletionItem, CompletionItemKind, Documentation, Position};

use crate::analysis::Analysis;
use crate::convert::Place;
use crate::index::Sym;
use crate::{builtin_docs, hover};

const KEYWORDS: &[&str] = &[
    "attribute",
    "break",
    "centroid",
    "const",
    "continue",
    "discard",
    "do",
    "else",
    "false",
    "flat",
    "for",
    "highp",
    "if",
    "in",
    "inout",
    "invariant",
    "layout",
    "lowp",
    "mediump",
    "out",
    "precision",
    "return",
    "smooth",
    "struct",
    "switch",
    "case",
    "default",
    "true",
    "uniform",
    "varying",
    "void",
    "while",
];

fn item(label: &str, kind: CompletionItemKind, detail: Option<String>) -> CompletionItem {
    CompletionItem {
        label: label.to_string(),
        kind: Some(kind),
        detail,
        ..CompletionItem::default()
    }
}

/// The completion items at `pos`.
pub fn complete(a: &Analysis, place: Place<'_>, pos: Position) -> Vec<CompletionItem> {
    let Some(shader) = a.shader() else {
        return Vec::new();
    };
    let module = &shader.module;
    let Some(offset) = place.offset(pos) else {
        return Vec::new();
    };
    let es100 = module.version == Version::Es100;
    let mut items = Vec::new();
    // The function the cursor is in: the last one whose name comes before it.
    let current = module
        .functions
        .iter()
        .enumerate()
        .filter(|(_, f)| f.span.start <= offset)
        .max_by_key(|(_, f)| f.span.start)
        .map(|(i, _)| i);
    if let Some(f) = current {
        let function = &module.functions[f];
        for p in 0..function.params.len() {
            let detail = hover::declaration(module, Sym::Param(f, p));
            items.push(item(
                &function.params[p].name,
                CompletionItemKind::VARIABLE,
                detail,
            ));
        }
        for (l, local) in function.locals.iter().enumerate() {
            if local.span.start < offset {
                let detail = hover::declaration(module, Sym::Local(f, l));
                items.push(item(&local.name, CompletionItemKind::VARIABLE, detail));
            }
        }
    }
    for (g, global) in module.globals.iter().enumerate() {
        let detail = hover::declaration(module, Sym::Global(g));
        items.push(item(&global.name, CompletionItemKind::VARIABLE, detail));
    }
    for (f, function) in module.functions.iter().enumerate() {
        if &*function.name != "main" {
            let detail = hover::declaration(module, Sym::Func(f));
            items.push(item(&function.name, CompletionItemKind::FUNCTION, detail));
        }
    }
    for (name, doc) in builtin_docs::FUNCTIONS {
        if essl::passes::overloads_in(name, es100).is_some() {
            let mut i = item(
                name,
                CompletionItemKind::FUNCTION,
                Some(hover::builtin_overloads(name, es100)),
            );
            i.documentation = Some(Documentation::String(doc.to_string()));
            items.push(i);
        }
    }
    for (name, doc) in builtin_docs::VARIABLES {
        let mut i = item(name, CompletionItemKind::VARIABLE, None);
        i.documentation = Some(Documentation::String(doc.to_string()));
        items.push(i);
    }
    items.extend(
        KEYWORDS
            .iter()
            .map(|k| item(k, CompletionItemKind::KEYWORD, None)),
    );
    items.extend(
        // `void` is offered with the keywords.
        essl::suggest::TYPE_NAMES
            .iter()
            .filter(|t| **t != "void")
            .map(|t| item(t, CompletionItemKind::CLASS, None)),
    );
    items
}
