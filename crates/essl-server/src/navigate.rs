//! Go to definition, find references, and the document's outline (functions, globals,
//! uniform blocks, structs).

use essl::hir::GlobalKind;
use lsp_types::{DocumentSymbol, Location, Position, SymbolKind, Uri};

use crate::analysis::Analysis;
use crate::convert::Place;
use crate::index::{self, Sym};

/// Where the name at `pos` is declared (nothing for built-ins).
pub fn definition(a: &Analysis, place: Place<'_>, uri: &Uri, pos: Position) -> Option<Location> {
    let module = &a.shader()?.module;
    let (_, sym) = a.index().symbol_at(module, place.offset(pos)?)?;
    let span = index::definition(module, sym)?;
    Some(Location::new(uri.clone(), place.range(span)?))
}

/// Every use of the name at `pos` (and its declaration, when asked).
pub fn references(
    a: &Analysis,
    place: Place<'_>,
    uri: &Uri,
    pos: Position,
    declaration: bool,
) -> Vec<Location> {
    let Some(shader) = a.shader() else {
        return Vec::new();
    };
    let module = &shader.module;
    let Some(offset) = place.offset(pos) else {
        return Vec::new();
    };
    let Some((_, sym)) = a.index().symbol_at(module, offset) else {
        return Vec::new();
    };
    let mut spans: Vec<essl::source::Span> = Vec::new();
    if declaration {
        spans.extend(index::definition(module, sym));
    }
    spans.extend(
        a.index()
            .uses
            .iter()
            .filter(|(_, s)| *s == sym)
            .map(|(span, _)| *span),
    );
    spans.sort_by_key(|s| (s.start, s.end));
    spans.dedup();
    spans
        .into_iter()
        .filter_map(|s| Some(Location::new(uri.clone(), place.range(s)?)))
        .collect()
}

#[allow(deprecated)] // `DocumentSymbol::deprecated` must be given; it is `None`.
fn symbol(
    name: String,
    detail: Option<String>,
    kind: SymbolKind,
    range: lsp_types::Range,
) -> DocumentSymbol {
    DocumentSymbol {
        name,
        detail,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range: range,
        children: None,
    }
}

/// The outline: functions (with their parameters and locals), global variables, uniform
/// blocks, in source order; what lies in an included file is left out.
pub fn symbols(a: &Analysis, place: Place<'_>) -> Vec<DocumentSymbol> {
    let Some(shader) = a.shader() else {
        return Vec::new();
    };
    let module = &shader.module;
    let at = |name: &str, detail: Option<String>, kind: SymbolKind, span: essl::source::Span| {
        Some(symbol(name.to_string(), detail, kind, place.range(span)?))
    };
    let mut out: Vec<(u32, DocumentSymbol)> = Vec::new();
    for (i, g) in module.globals.iter().enumerate() {
        if matches!(g.kind, GlobalKind::BlockMember(..)) {
            continue;
        }
        let kind = match g.kind {
            GlobalKind::Const => SymbolKind::CONSTANT,
            _ => SymbolKind::VARIABLE,
        };
        let detail = crate::hover::declaration(module, Sym::Global(i));
        out.extend(at(&g.name, detail, kind, g.span).map(|s| (g.span.start, s)));
    }
    for b in &module.blocks {
        let members: Vec<DocumentSymbol> = b
            .members
            .iter()
            .filter_map(|(name, ty, _, _)| {
                let detail = Some(ty.display(&module.structs).to_string());
                at(name, detail, SymbolKind::FIELD, b.span)
            })
            .collect();
        let block = at(
            &b.name,
            Some("uniform block".into()),
            SymbolKind::STRUCT,
            b.span,
        );
        if let Some(mut s) = block {
            s.children = Some(members);
            out.push((b.span.start, s));
        }
    }
    for (f, function) in module.functions.iter().enumerate() {
        let detail = crate::hover::declaration(module, Sym::Func(f));
        let Some(mut s) = at(&function.name, detail, SymbolKind::FUNCTION, function.span) else {
            continue;
        };
        let mut children: Vec<DocumentSymbol> = Vec::new();
        for (p, param) in function.params.iter().enumerate() {
            let detail = crate::hover::declaration(module, Sym::Param(f, p));
            children.extend(at(&param.name, detail, SymbolKind::VARIABLE, param.span));
        }
        for (l, local) in function.locals.iter().enumerate() {
            let detail = crate::hover::declaration(module, Sym::Local(f, l));
            children.extend(at(&local.name, detail, SymbolKind::VARIABLE, local.span));
        }
        s.children = Some(children);
        out.push((function.span.start, s));
    }
    out.sort_by_key(|(start, _)| *start);
    out.into_iter().map(|(_, s)| s).collect()
}
