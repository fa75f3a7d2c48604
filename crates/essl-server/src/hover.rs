//! Hover: a name's declaration as GLSL (qualifiers, precision, type), a function's signature,
//! a built-in's overloads and one line about it, or an expression's type.

use essl::hir::{GlobalKind, Interpolation, Module, ParamMode};
use essl::types::Precision;
use lsp_types::{Hover, HoverContents, MarkupContent, MarkupKind, Position};

use crate::analysis::Analysis;
use crate::builtin_docs;
use crate::convert::Place;
use crate::index::Sym;

fn precision(p: Option<Precision>) -> String {
    p.map(|p| format!("{} ", p.name())).unwrap_or_default()
}

/// A symbol's declaration, as GLSL.
pub fn declaration(module: &Module, sym: Sym) -> Option<String> {
    let ty = |t: &essl::types::Type| t.display(&module.structs).to_string();
    Some(match sym {
        Sym::Global(g) => {
            let g = module.globals.get(g)?;
            let mut q = String::new();
            if let Some(l) = g.location {
                q.push_str(&format!("layout(location = {l}) "));
            }
            if g.invariant {
                q.push_str("invariant ");
            }
            match g.interpolation {
                Some(Interpolation::Flat) => q.push_str("flat "),
                Some(Interpolation::Smooth) => q.push_str("smooth "),
                Some(Interpolation::NoPerspective) => q.push_str("noperspective "),
                None => {}
            }
            if g.centroid {
                q.push_str("centroid ");
            }
            let kind = match g.kind {
                GlobalKind::Private => "",
                GlobalKind::Const => "const ",
                GlobalKind::Uniform | GlobalKind::BlockMember(..) => "uniform ",
                GlobalKind::Input => "in ",
                GlobalKind::Output => "out ",
            };
            let block = match g.kind {
                GlobalKind::BlockMember(b, _) => module
                    .blocks
                    .get(b)
                    .map(|b| format!(" // in uniform block {}", b.name))
                    .unwrap_or_default(),
                _ => String::new(),
            };
            format!(
                "{q}{kind}{}{} {}{block}",
                precision(g.precision),
                ty(&g.ty),
                g.name
            )
        }
        Sym::Local(f, l) => {
            let l = module.functions.get(f)?.locals.get(l)?;
            let c = if l.constant.is_some() { "const " } else { "" };
            format!("{c}{}{} {}", precision(l.precision), ty(&l.ty), l.name)
        }
        Sym::Param(f, p) => {
            let p = module.functions.get(f)?.params.get(p)?;
            let mode = match p.mode {
                ParamMode::In => "in ",
                ParamMode::Out => "out ",
                ParamMode::InOut => "inout ",
            };
            let c = if p.is_const { "const " } else { "" };
            format!(
                "{c}{mode}{}{} {}",
                precision(p.precision),
                ty(&p.ty),
                p.name
            )
        }
        Sym::Func(f) => {
            let f = module.functions.get(f)?;
            let params: Vec<String> = f
                .params
                .iter()
                .map(|p| format!("{}{} {}", precision(p.precision), ty(&p.ty), p.name))
                .collect();
            format!(
                "{}{} {}({})",
                precision(f.ret_precision),
                ty(&f.ret),
                f.name,
                params.join(", ")
            )
        }
        Sym::BuiltinVar(v) => format!("{}{} {}", precision(v.precision()), ty(&v.ty()), v.name()),
        Sym::BuiltinFn(op) => builtin_overloads(op.name(), module.version == essl::Version::Es100),
    })
}

/// A built-in function's overloads, one a line.
pub fn builtin_overloads(name: &str, es100: bool) -> String {
    let Some(overloads) = essl::passes::overloads_in(name, es100) else {
        return name.to_string();
    };
    let mut lines: Vec<String> = overloads
        .iter()
        .map(|s| {
            let params: Vec<String> = s
                .params
                .iter()
                .map(|(t, mode)| {
                    let m = match mode {
                        ParamMode::In => "",
                        ParamMode::Out => "out ",
                        ParamMode::InOut => "inout ",
                    };
                    format!("{m}{}", t.display(&[]))
                })
                .collect();
            format!("{} {name}({})", s.ret.display(&[]), params.join(", "))
        })
        .collect();
    lines.dedup();
    lines.join("\n")
}

fn markdown(code: &str, doc: Option<&str>) -> Hover {
    let mut value = format!("```glsl\n{code}\n```");
    if let Some(doc) = doc {
        value.push_str(&format!("\n\n{doc}"));
    }
    Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value,
        }),
        range: None,
    }
}

/// The hover at `pos`.
pub fn hover(a: &Analysis, place: Place<'_>, pos: Position) -> Option<Hover> {
    let module = &a.shader()?.module;
    let offset = place.offset(pos)?;
    if let Some((span, sym)) = a.index().symbol_at(module, offset) {
        let doc = match sym {
            Sym::BuiltinFn(op) => builtin_docs::doc(op.name()),
            Sym::BuiltinVar(v) => builtin_docs::doc(v.name()),
            _ => None,
        };
        let mut h = markdown(&declaration(module, sym)?, doc);
        h.range = place.range(span);
        return Some(h);
    }
    let (span, ty) = a.index().type_at(offset)?;
    let mut h = markdown(&ty.display(&module.structs).to_string(), None);
    h.range = place.range(span);
    Some(h)
}
