//! A script's constants of literals, as its shaders interpolate them: the top-level
//! `const NAME = …` (also `let`, `var`, `export const`, `export default`), and the names it
//! imports (`import NAME from './file'`, `import {a, b as c} from './file'`), so that
//! `${NAME}` in a shader can be followed to the text it stands for.

use std::collections::HashMap;

use super::literal::{self, Expr};
use super::scan;

/// Where a name comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Binding {
    /// A constant of this file: where its value's expression starts.
    Local(usize),
    /// An import: the module specifier and the name exported there (`default` for a default
    /// import).
    Import {
        /// `'./file'` as written, without quotes.
        from: String,
        /// The exported name.
        name: String,
    },
}

/// A script's top-level names.
#[derive(Clone, Debug, Default)]
pub struct Consts {
    /// Each name's binding.
    pub names: HashMap<String, Binding>,
    /// Each exported name and the local name it exports (`default` included).
    pub exports: HashMap<String, Export>,
}

/// What an export names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Export {
    /// A local name.
    Name(String),
    /// An expression (`export default `…``): where it starts.
    Expr(usize),
}

/// The top-level names of `src`.
pub fn scan(src: &str) -> Consts {
    let b = src.as_bytes();
    let mut out = Consts::default();
    let mut depth = 0usize;
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = scan::line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = scan::comment_end(b, i),
            b'\'' | b'"' => i = scan::string_end(b, i),
            b'`' => i = scan::template(b, i, 0).end,
            b'{' | b'(' | b'[' => {
                depth += 1;
                i += 1;
            }
            b'}' | b')' | b']' => {
                depth = depth.saturating_sub(1);
                i += 1;
            }
            c if depth == 0 && scan::is_ident(c) && (i == 0 || !scan::is_ident(b[i - 1])) => {
                let word = scan::ident_at(b, i).map_or(i + 1..i + 1, |r| r);
                i = statement(src, word, &mut out);
            }
            _ => i += 1,
        }
    }
    out
}

/// Reads the statement that starts with the word at `word` (at the top level) into `out`;
/// where to go on scanning.
fn statement(src: &str, word: std::ops::Range<usize>, out: &mut Consts) -> usize {
    let b = src.as_bytes();
    let next = |at: usize| scan::skip_trivia(b, at);
    let ident = |at: usize| scan::ident_at(b, at).map(|r| (src[r.clone()].to_string(), r.end));
    match &src[word.clone()] {
        "const" | "let" | "var" => {
            if let Some((name, end)) = ident(next(word.end)) {
                let eq = next(end);
                if b.get(eq) == Some(&b'=') && b.get(eq + 1) != Some(&b'=') {
                    out.names.insert(name, Binding::Local(next(eq + 1)));
                }
                return end;
            }
            word.end
        }
        "export" => {
            let at = next(word.end);
            match ident(at) {
                Some((kw, end)) if kw == "default" => {
                    let value = next(end);
                    match ident(value) {
                        Some((name, _)) if literal::parse(b, value).is_none() => {
                            out.exports.insert("default".into(), Export::Name(name));
                        }
                        _ => {
                            out.exports.insert("default".into(), Export::Expr(value));
                        }
                    }
                    value
                }
                Some((kw, end)) if matches!(kw.as_str(), "const" | "let" | "var") => {
                    if let Some((name, _)) = ident(next(end)) {
                        out.exports.insert(name.clone(), Export::Name(name));
                    }
                    at
                }
                None if b.get(at) == Some(&b'{') => export_list(src, at, out),
                _ => at,
            }
        }
        "import" => import(src, word.end, out),
        _ => word.end,
    }
}

/// `export {a, b as c}` at `at` (its `{`), and `export {a} from '…'`: a name re-exported from
/// another script is bound as if imported. Where to go on scanning.
fn export_list(src: &str, at: usize, out: &mut Consts) -> usize {
    let b = src.as_bytes();
    let (listed, end) = name_list(src, at);
    let (from, end) = from_clause(src, end);
    for (local, exported) in listed {
        if let Some(from) = &from {
            out.names.entry(local.clone()).or_insert(Binding::Import {
                from: from.clone(),
                name: local.clone(),
            });
        }
        out.exports.insert(exported, Export::Name(local));
    }
    end.min(b.len())
}

/// The names of `{a, b as c}` at `at` (its `{`), each as (first, second) — `(b, c)` — and
/// where the list ends.
fn name_list(src: &str, at: usize) -> (Vec<(String, String)>, usize) {
    let b = src.as_bytes();
    let mut names = Vec::new();
    let mut i = at + 1;
    loop {
        i = scan::skip_trivia(b, i);
        let Some(r) = scan::ident_at(b, i) else { break };
        let first = src[r.clone()].to_string();
        i = scan::skip_trivia(b, r.end);
        let mut second = first.clone();
        if src[i..].starts_with("as") {
            if let Some(l) = scan::ident_at(b, scan::skip_trivia(b, i + 2)) {
                second = src[l.clone()].to_string();
                i = scan::skip_trivia(b, l.end);
            }
        }
        names.push((first, second));
        if b.get(i) == Some(&b',') {
            i += 1;
        }
    }
    (names, scan::skip_trivia(b, i + 1))
}

/// `from '…'` at `i`: the specifier, and where the clause ends (`i` where there is none).
fn from_clause(src: &str, i: usize) -> (Option<String>, usize) {
    let b = src.as_bytes();
    let Some(from_kw) = scan::ident_at(b, i).filter(|r| &src[r.clone()] == "from") else {
        return (None, i);
    };
    let q = scan::skip_trivia(b, from_kw.end);
    if !matches!(b.get(q), Some(b'\'' | b'"')) {
        return (None, q);
    }
    let end = scan::string_end(b, q);
    (
        Some(src[q + 1..end.saturating_sub(1).max(q + 1)].to_string()),
        end,
    )
}

/// `import NAME from '…'`, `import {a, b as c} from '…'`, `import NAME, {…} from '…'`.
fn import(src: &str, at: usize, out: &mut Consts) -> usize {
    let b = src.as_bytes();
    let mut i = scan::skip_trivia(b, at);
    let mut names: Vec<(String, String)> = Vec::new();
    if let Some(r) = scan::ident_at(b, i) {
        names.push((src[r.clone()].to_string(), "default".to_string()));
        i = scan::skip_trivia(b, r.end);
        if b.get(i) == Some(&b',') {
            i = scan::skip_trivia(b, i + 1);
        }
    }
    if b.get(i) == Some(&b'{') {
        let (listed, end) = name_list(src, i);
        names.extend(
            listed
                .into_iter()
                .map(|(exported, local)| (local, exported)),
        );
        i = end;
    }
    let (Some(from), end) = from_clause(src, i) else {
        return from_clause(src, i).1;
    };
    for (local, name) in names {
        out.names.insert(
            local,
            Binding::Import {
                from: from.clone(),
                name,
            },
        );
    }
    end
}

/// The expression a local constant is bound to, parsed.
pub fn local_expr(src: &str, at: usize) -> Option<Expr> {
    literal::parse(src.as_bytes(), at).map(|(e, _)| e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn top_level_names_exports_and_imports() {
        let src = "import main, {a as b, c} from './x.glsl';\nimport d from \"d\";\n\
                   const X = `x`;\nfunction f() { const Y = 1; }\nexport const Z = 'z';\n\
                   export default `#version 300 es`;\nexport { X as W, X };\n\
                   export { V } from './v.js';\n";
        let c = scan(src);
        assert_eq!(
            c.names["main"],
            Binding::Import {
                from: "./x.glsl".into(),
                name: "default".into()
            }
        );
        assert_eq!(
            c.names["b"],
            Binding::Import {
                from: "./x.glsl".into(),
                name: "a".into()
            }
        );
        assert!(matches!(c.names["c"], Binding::Import { .. }));
        assert!(matches!(c.names["d"], Binding::Import { .. }));
        assert!(matches!(c.names["X"], Binding::Local(_)));
        assert!(!c.names.contains_key("Y"));
        assert_eq!(c.exports["Z"], Export::Name("Z".into()));
        let Export::Expr(at) = c.exports["default"] else {
            panic!()
        };
        assert!(src[at..].starts_with("`#version"));
        assert_eq!(c.exports["W"], Export::Name("X".into()));
        assert_eq!(c.exports["X"], Export::Name("X".into()));
        assert_eq!(c.exports["V"], Export::Name("V".into()));
        assert!(matches!(&c.names["V"], Binding::Import { from, .. } if from == "./v.js"));
    }
}
