//! Literals in JavaScript or TypeScript that hold shaders: template literals whose value
//! starts with `#version` (after white space, which is left out of the shader as twgl leaves
//! it out) or that are tagged `glsl` (`` glsl`…` ``) or marked `/* glsl */`; strings, `+`
//! chains and `[…].join('\n')` arrays whose value is a whole program (`#version` first, a
//! `main` in it). Each shader's text is the value JavaScript computes — escapes cooked
//! ([`cook`]), `${NAME}` followed to a constant of literals in the file or in a file it
//! imports ([`consts`], [`Imports`]) — kept as pieces of the file.
//!
//! A small scanner, not a parser ([`scan`]): a JavaScript parser (oxc, swc) reads all of
//! JS and TS into a syntax tree, tens of thousands of lines and minutes of build on two cores,
//! to find what this finds: literals, their escapes, and the top-level constants and imports
//! they interpolate. Regular-expression literals are not recognised: one holding a backtick
//! or a quote could hide the literals after it.

mod consts;
mod cook;
pub(crate) mod literal;
pub mod objects;
pub(crate) mod scan;

use super::{text_of, Embedded, Piece, Skip};
use literal::Expr;

pub use consts::{Binding, Consts, Export};
pub use literal::Unknown;

/// The top-level names of a script.
pub fn consts_of(src: &str) -> Consts {
    consts::scan(src)
}

/// How deep names may refer to names (`${A}` where `A` is `` `${B}` ``…) before essl stops
/// following them.
const MAX_DEPTH: usize = 16;

/// Where the constants a script imports are read from.
pub trait Imports {
    /// The value of `name` as exported by the module `from` imports (`'./chunk.glsl'`),
    /// relative to the importing script; `member` is what follows the name (`x.y` for
    /// `NAME.x.y`); `depth`, how many names deep the lookup already is.
    fn import(
        &self,
        from: &str,
        name: &str,
        member: &str,
        depth: usize,
    ) -> Result<Vec<Piece>, Unknown>;
}

/// No imports are followed.
pub struct NoImports;

impl Imports for NoImports {
    fn import(&self, from: &str, name: &str, _: &str, _: usize) -> Result<Vec<Piece>, Unknown> {
        Err(Unknown::Name(format!("{name} (from `{from}`)")))
    }
}

/// The value of `name` (possibly `NAME.member…`) in the script `src` with names `consts`.
pub fn lookup(
    src: &str,
    consts: &Consts,
    imports: &dyn Imports,
    name: &str,
    depth: usize,
) -> Result<Vec<Piece>, Unknown> {
    if depth > MAX_DEPTH {
        return Err(Unknown::TooDeep);
    }
    let (head, member) = name.split_once('.').unwrap_or((name, ""));
    match consts.names.get(head) {
        Some(Binding::Local(at)) => {
            let expr = consts::local_expr(src, *at).ok_or_else(|| Unknown::Name(name.into()))?;
            let expr = member_of(expr, member).ok_or_else(|| Unknown::Name(name.into()))?;
            let inner = |n: &str, d: usize| lookup(src, consts, imports, n, d);
            expr.pieces(src, &inner, depth)
        }
        Some(Binding::Import {
            from,
            name: exported,
        }) => imports.import(from, exported, member, depth),
        None => Err(Unknown::Name(name.into())),
    }
}

/// The value of an export `name` (possibly `default`) of the script `src`, with `member`.
pub fn exported(
    src: &str,
    consts: &Consts,
    imports: &dyn Imports,
    name: &str,
    member: &str,
    depth: usize,
) -> Result<Vec<Piece>, Unknown> {
    match consts.exports.get(name) {
        Some(Export::Name(local)) => {
            let full = if member.is_empty() {
                local.clone()
            } else {
                format!("{local}.{member}")
            };
            lookup(src, consts, imports, &full, depth)
        }
        Some(Export::Expr(at)) => {
            let expr = consts::local_expr(src, *at).ok_or_else(|| Unknown::Name(name.into()))?;
            let expr = member_of(expr, member).ok_or_else(|| Unknown::Name(name.into()))?;
            let inner = |n: &str, d: usize| lookup(src, consts, imports, n, d);
            expr.pieces(src, &inner, depth)
        }
        None => Err(Unknown::Name(name.into())),
    }
}

/// `expr.member.member…` for an object of literals.
fn member_of(expr: Expr, member: &str) -> Option<Expr> {
    let mut e = expr;
    for key in member.split('.').filter(|k| !k.is_empty()) {
        let Expr::Object(fields) = e else {
            return None;
        };
        e = fields.into_iter().find(|(k, _)| k == key)?.1;
    }
    Some(e)
}

/// The shaders in `text`, a script; `base` is added to every range (the script's offset in
/// its page).
pub fn extract(text: &str, base: usize, imports: &dyn Imports) -> Vec<Embedded> {
    let b = text.as_bytes();
    let consts = consts::scan(text);
    let mut found = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = scan::line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = scan::comment_end(b, i),
            c @ (b'`' | b'\'' | b'"' | b'[') => match literal::parse(b, i) {
                Some((expr, end)) => {
                    if let Some(mut e) = shader(text, i, &expr, &consts, imports) {
                        if e.skip.is_none() && literal::rewritten(b, end) {
                            e.skip = Some(Skip::Rewritten);
                            e.pieces.clear();
                            e.range = e.range.start..e.range.start;
                        }
                        found.push(e);
                    }
                    i = end;
                }
                None => {
                    i = match c {
                        b'`' => scan::template(b, i, 0).end,
                        b'[' => i + 1,
                        _ => scan::string_end(b, i),
                    }
                }
            },
            _ => i += 1,
        }
    }
    let parts = parts(text, &consts, &found);
    found.retain(|e| !parts.contains(&e.literal));
    modules(text, &consts, imports, &mut found);
    for e in &mut found {
        e.range.start += base;
        e.range.end += base;
        e.literal += base;
        shift(&mut e.pieces, base);
    }
    found
}

/// Where the literals start that the shaders found interpolate (`${FS_GLES}` in
/// `` `#version 300 es\n${FS_GLES}` ``): parts of those shaders, checked there rather than on
/// their own.
fn parts(text: &str, consts: &Consts, found: &[Embedded]) -> Vec<usize> {
    let mut out = Vec::new();
    for e in found.iter().filter(|e| e.skip.is_none()) {
        let Some((expr, _)) = literal::parse(text.as_bytes(), e.literal) else {
            continue;
        };
        for name in expr.substitutions(text) {
            if let Some(Binding::Local(at)) = consts.names.get(name.split('.').next().unwrap_or(""))
            {
                out.push(*at);
            }
        }
    }
    out
}

/// The luma.gl-style module objects of the file (`{name: 'skin', vs, fs, defines: {…}}`):
/// the stage their `vs` and `fs` literals are for, and the macros they define for them.
fn modules(text: &str, consts: &Consts, imports: &dyn Imports, found: &mut [Embedded]) {
    let b = text.as_bytes();
    for o in objects::objects_with(text, &["vs", "fs"]) {
        if o.get("name").is_none() {
            continue;
        }
        let defines = o
            .get("defines")
            .filter(|r| b.get(r.start) == Some(&b'{'))
            .and_then(|r| objects::object(text, r.start))
            .map(|d| {
                d.entries
                    .iter()
                    .filter_map(|(key, value)| {
                        let code = text[value.clone()].trim();
                        let pieces = match literal::parse(b, value.start) {
                            Some((e, _)) => {
                                let inner =
                                    |n: &str, depth: usize| lookup(text, consts, imports, n, depth);
                                e.pieces(text, &inner, 0).ok()?
                            }
                            None => lookup(text, consts, imports, code, 0).ok()?,
                        };
                        Some((key.clone(), text_of(text, &pieces)))
                    })
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default();
        for (key, stage) in [("vs", essl::Stage::Vertex), ("fs", essl::Stage::Fragment)] {
            let Some(value) = o.get(key) else { continue };
            let at = match consts.names.get(text[value.clone()].trim()) {
                Some(Binding::Local(at)) => *at,
                _ => value.start,
            };
            if let Some(e) = found.iter_mut().find(|e| e.literal == at) {
                e.stage = Some(stage);
                e.defines = defines.clone();
            }
        }
    }
}

fn shift(pieces: &mut [Piece], by: usize) {
    for p in pieces {
        match p {
            Piece::Raw(r) => *r = r.start + by..r.end + by,
            Piece::Cooked { raw, .. } => *raw = raw.start + by..raw.end + by,
            Piece::Added { at, .. } => *at += by,
            Piece::From { .. } => {}
        }
    }
}

/// The expression at `at` as a shader, if it is one.
fn shader(
    text: &str,
    at: usize,
    expr: &Expr,
    consts: &Consts,
    imports: &dyn Imports,
) -> Option<Embedded> {
    let (tagged, name) = context(&text[..at]);
    let inner = |n: &str, d: usize| lookup(text, consts, imports, n, d);
    let value = expr.pieces(text, &inner, 0);
    let start = expr.start();
    let version = |t: &str| t.trim_start().starts_with("#version");
    // A string, a chain or an array is a shader only when it is a whole program.
    let program = |t: &str| expr.is_template() || tagged || t.contains("main");
    match value {
        Ok(mut pieces) => {
            let body = text_of(text, &pieces);
            let has_version = version(&body);
            if !(tagged && expr.is_template() || has_version && program(&body)) {
                return None;
            }
            if has_version {
                // White space before `#version` is left out, as twgl's `createProgramInfo`
                // does before compiling: `` `\n  #version 300 es …` `` compiles in the page.
                trim_start(text, &mut pieces);
            }
            let range = extent(&pieces).unwrap_or(start..start);
            Some(Embedded {
                range,
                chunk: !has_version && !has_main(&body),
                literal: at,
                defines: Vec::new(),
                pieces,
                stage: None,
                name,
                skip: None,
            })
        }
        Err(why) => {
            let first = expr.first_text(text);
            let looks =
                (tagged && expr.is_template()) || version(first) || version(&cooked_prefix(first));
            looks.then(|| Embedded {
                range: start..start,
                pieces: Vec::new(),
                chunk: false,
                literal: at,
                defines: Vec::new(),
                stage: None,
                name,
                skip: Some(match why {
                    Unknown::Escape => Skip::Escapes,
                    _ => Skip::Interpolated,
                }),
            })
        }
    }
}

/// `first` with a leading line continuation taken out (`` `\ `` + newline + `#version`).
fn cooked_prefix(first: &str) -> String {
    first
        .trim_start_matches("\\\r\n")
        .trim_start_matches("\\\n")
        .to_string()
}

/// Whether the text defines `main` (`void main(`, with any spacing).
fn has_main(text: &str) -> bool {
    text.match_indices("main").any(|(i, _)| {
        let before = text[..i].trim_end();
        let after = text[i + 4..].trim_start();
        before.ends_with("void")
            && after.starts_with('(')
            && !text[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_')
    })
}

/// Drops the white space the pieces start with.
fn trim_start(host: &str, pieces: &mut Vec<Piece>) {
    while let Some(p) = pieces.first_mut() {
        match p {
            Piece::Raw(r) => {
                let t = &host[r.clone()];
                let kept = t.trim_start();
                r.start += t.len() - kept.len();
                if !kept.is_empty() {
                    return;
                }
            }
            Piece::Cooked { value, .. } | Piece::Added { text: value, .. } => {
                if !value.trim_start().is_empty() {
                    return;
                }
            }
            Piece::From { .. } => return,
        }
        pieces.remove(0);
    }
}

/// The host bytes from the first piece to the last.
fn extent(pieces: &[Piece]) -> Option<std::ops::Range<usize>> {
    let ends = |p: &Piece| match p {
        Piece::Raw(r) | Piece::Cooked { raw: r, .. } => Some((r.start, r.end)),
        Piece::Added { at, .. } => Some((*at, *at)),
        Piece::From { .. } => None,
    };
    let first = pieces.iter().find_map(ends)?;
    let last = pieces.iter().rev().find_map(ends)?;
    Some(first.0..last.1)
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '$'
}

/// The identifier that ends `before`, and the text before it.
fn last_ident(before: &str) -> Option<(&str, &str)> {
    let start = before
        .char_indices()
        .rev()
        .take_while(|&(_, c)| is_ident(c))
        .last()?
        .0;
    Some((&before[start..], &before[..start]))
}

/// What precedes a literal: whether it is tagged `glsl` (or marked `/* glsl */`), and the name
/// it is given (`const vs = `…``, `fs: `…``, `gl.VERTEX_SHADER, `…``).
fn context(before: &str) -> (bool, Option<String>) {
    let mut rest = before.trim_end();
    let mut tagged = false;
    if let Some(inner) = rest.strip_suffix("*/") {
        if let Some(at) = inner.rfind("/*") {
            tagged = inner[at + 2..].trim().eq_ignore_ascii_case("glsl");
            rest = inner[..at].trim_end();
        }
    } else if let Some((tag, earlier)) = last_ident(rest) {
        if tag == "glsl" {
            tagged = true;
            rest = earlier.trim_end();
        } else if tag == "return" {
            return (false, None);
        }
    }
    let name = match rest.chars().last() {
        Some('=') if !rest.ends_with("==") && !rest.ends_with("=>") => {
            last_ident(rest[..rest.len() - 1].trim_end())
        }
        Some(':') | Some(',') => last_ident(rest[..rest.len() - 1].trim_end()),
        _ => None,
    };
    let name = name.map(|(n, _)| n.to_string()).filter(|n| !n.is_empty());
    (tagged, name)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shaders(text: &str) -> Vec<(String, Option<String>, Option<Skip>, bool)> {
        extract(text, 0, &NoImports)
            .into_iter()
            .map(|e| (text_of(text, &e.pieces), e.name, e.skip, e.chunk))
            .collect()
    }

    #[test]
    fn literals_that_hold_shaders() {
        let text = "const vs = `#version 300 es\nvoid main() {}`;\n\
                    // `#version in a comment`\n\
                    const s = 'a ` quote'; const t = `not a shader`;\n\
                    const fs = glsl`precision mediump float;`;\n\
                    const x = /* glsl */ `void main() {}`;\n\
                    const y = `#version 300 es\n${defs}\nvoid main() {}`;\n\
                    gl.shaderSource(s, `#version 300 es\\nvoid main() {}`);\n";
        let found = shaders(text);
        assert_eq!(found.len(), 5, "{found:?}");
        assert_eq!(found[0].0, "#version 300 es\nvoid main() {}");
        assert_eq!(found[0].1.as_deref(), Some("vs"));
        assert_eq!(found[1].1.as_deref(), Some("fs"));
        assert!(found[1].3, "a tagged literal with no main is a chunk");
        assert_eq!(found[2].1.as_deref(), Some("x"));
        assert!(!found[2].3);
        assert_eq!(found[3].2, Some(Skip::Interpolated));
        assert_eq!(found[4].0, "#version 300 es\nvoid main() {}");
        assert_eq!(found[4].2, None);
    }

    #[test]
    fn continuations_constants_strings_and_arrays() {
        let text = "const N = 4;\nconst HEAD = `precision highp float;`;\n\
                    export default `\\\n#version 300 es\n${HEAD}\n#define K ${N}\nvoid main() {}`;\n\
                    const a = '#version 300 es\\nvoid main() {}';\n\
                    const b = ['#version 300 es', 'void main() {', '}'].join('\\n');\n\
                    const c = '#version 300 es\\n' +\n  'void main() {}';\n\
                    const header = '#version 300 es\\n';\n";
        let found = shaders(text);
        assert_eq!(found.len(), 4, "{found:?}");
        assert_eq!(
            found[0].0,
            "#version 300 es\nprecision highp float;\n#define K 4\nvoid main() {}"
        );
        assert_eq!(found[1].0, "#version 300 es\nvoid main() {}");
        assert_eq!(found[2].0, "#version 300 es\nvoid main() {\n}");
        assert_eq!(found[3].0, "#version 300 es\nvoid main() {}");
    }

    #[test]
    fn deep_nesting_is_bounded() {
        let deep = format!("a = `#version 300 es\n{}", "${`".repeat(100_000));
        let found = shaders(&deep);
        assert!(found.len() <= 1);
        let chain = (0..40)
            .map(|i| format!("const A{i} = `${{A{}}}`;\n", i + 1))
            .collect::<String>()
            + "const s = `#version 300 es\n${A0}`;\n";
        let found = shaders(&chain);
        assert_eq!(found[0].2, Some(Skip::Interpolated));
    }

    #[test]
    fn unclosed_literals_end_the_file() {
        let found = shaders("a = `#version 300 es\n${f(`x${'}'}`)}`; b = `#version");
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].2, Some(Skip::Interpolated));
    }
}
