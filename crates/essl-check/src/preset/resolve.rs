//! Where a name or a member path in a script leads, as far as reading the script (and the
//! scripts it imports) can tell: `vs` to its constant, `CopyShader.vertexShader` to the entry of
//! the exported object, `LensflareElement.Shader` to the object a top-level
//! `LensflareElement.Shader = {…}` assigns, and a name declared in a function (`const shader =
//! …`) to its nearest declaration before the use. A value the script computes when it runs
//! leads nowhere.

use std::rc::Rc;

use crate::extract::js::{objects, scan};
use crate::imports::{DiskImports, Script};

use super::programs::bound;

/// How many names and members a path is followed through.
const MAX_DEPTH: usize = 16;

/// The names of a dotted path (`a.b.c`, white space allowed around the dots), if `code` is
/// one.
fn segments(code: &str) -> Option<Vec<&str>> {
    let parts: Vec<&str> = code.split('.').map(str::trim).collect();
    let ident = |p: &str| {
        let b = p.as_bytes();
        scan::ident_at(b, 0).is_some_and(|r| r.end == b.len())
    };
    parts.iter().all(|p| ident(p)).then_some(parts)
}

/// Whether `code` is a name or a dotted path of names.
pub(super) fn is_path(code: &str) -> bool {
    segments(code).is_some()
}

/// Where the expression the path `code` (used at byte `at` of `script`) names starts, and in
/// which script; `None` when the path leads to nothing the scripts write.
pub(super) fn path(
    script: &Rc<Script>,
    at: usize,
    code: &str,
    imports: &DiskImports,
    depth: usize,
) -> Option<(Rc<Script>, usize)> {
    if depth > MAX_DEPTH {
        return None;
    }
    let names = segments(code)?;
    let text = script.file.text();
    // `A.B = {…}` at the top level names `A.B` whatever `A` is (a class, a function).
    for k in (2..=names.len()).rev() {
        if let Some(p) = assignment(text, &names[..k].join(".")) {
            return follow(script, p, &names[k..], imports, depth + 1);
        }
    }
    let root = bound(script, names[0], imports, 0)
        .or_else(|| declared_before(text, names[0], at).map(|p| (script.clone(), p)))?;
    follow(&root.0, root.1, &names[1..], imports, depth + 1)
}

/// The expression at `at` of `script`, followed through `members`.
fn follow(
    script: &Rc<Script>,
    at: usize,
    members: &[&str],
    imports: &DiskImports,
    depth: usize,
) -> Option<(Rc<Script>, usize)> {
    if depth > MAX_DEPTH {
        return None;
    }
    let text = script.file.text();
    let b = text.as_bytes();
    // An expression that is itself a path (`const shader = LensflareElement.Shader;`).
    if let Some(end) = path_end(b, at) {
        let mut code = text[at..end].to_string();
        for m in members {
            code.push('.');
            code.push_str(m);
        }
        return path(script, at, &code, imports, depth + 1);
    }
    let Some((first, rest)) = members.split_first() else {
        return Some((script.clone(), at));
    };
    if b.get(at) != Some(&b'{') {
        return None;
    }
    let value = objects::object(text, at)?.get(first)?;
    let start = scan::skip_trivia(b, value.start);
    follow(script, start, rest, imports, depth + 1)
}

/// Where the dotted path that starts at `at` ends, if one does and nothing but `;`, `,`, `}`
/// or a line's end follows it (the whole expression is the path).
fn path_end(b: &[u8], at: usize) -> Option<usize> {
    let mut end = scan::ident_at(b, at)?.end;
    loop {
        let dot = scan::skip_trivia(b, end);
        if b.get(dot) != Some(&b'.') {
            break;
        }
        end = scan::ident_at(b, scan::skip_trivia(b, dot + 1))?.end;
    }
    let after = scan::skip_trivia(b, end);
    matches!(b.get(after), None | Some(b';' | b',' | b'}' | b')')).then_some(end)
}

/// Where the value of the last `const NAME = …` before byte `before` starts (a `let` or `var`
/// can change after it is declared: a loop's `let i = 0` is no value).
fn declared_before(text: &str, name: &str, before: usize) -> Option<usize> {
    let b = text.as_bytes();
    text[..before.min(text.len())]
        .match_indices(name)
        .filter_map(|(i, _)| {
            let keyword = text[..i].trim_end();
            let declares = ["const"].iter().any(|k| {
                keyword.ends_with(k)
                    && !keyword[..keyword.len() - k.len()]
                        .ends_with(|c: char| scan::is_ident(c as u8))
            });
            let whole =
                !b.get(i + name.len()).is_some_and(|&c| scan::is_ident(c)) && keyword.len() < i;
            let eq = scan::skip_trivia(b, i + name.len());
            let assigns = b.get(eq) == Some(&b'=') && !matches!(b.get(eq + 1), Some(b'=' | b'>'));
            (declares && whole && assigns).then(|| scan::skip_trivia(b, eq + 1))
        })
        .last()
}

/// Where the value of the first `PATH = …` statement starts (`PATH` a dotted path, not a
/// member of a longer one).
fn assignment(text: &str, path: &str) -> Option<usize> {
    let b = text.as_bytes();
    text.match_indices(path).find_map(|(i, _)| {
        let before = text[..i].trim_end();
        let starts = !before.ends_with(|c: char| scan::is_ident(c as u8) || c == '.');
        let eq = scan::skip_trivia(b, i + path.len());
        let assigns = b.get(eq) == Some(&b'=') && !matches!(b.get(eq + 1), Some(b'=' | b'>'));
        (starts && assigns).then(|| scan::skip_trivia(b, eq + 1))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn declarations_and_assignments() {
        let text = "function f() {\n  const shader = A.Shader;\n  use(shader);\n}\nA.Shader = {vertexShader: `x`};\n";
        let use_at = text.find("use(").unwrap();
        let p = declared_before(text, "shader", use_at).unwrap();
        assert!(text[p..].starts_with("A.Shader;"));
        assert_eq!(declared_before(text, "shade", use_at), None);
        let a = assignment(text, "A.Shader").unwrap();
        assert!(text[a..].starts_with("{vertexShader"));
        assert_eq!(path_end(text.as_bytes(), p), Some(p + "A.Shader".len()));
        assert_eq!(segments("a . b.c"), Some(vec!["a", "b", "c"]));
        assert_eq!(segments("a.b()"), None);
    }
}
