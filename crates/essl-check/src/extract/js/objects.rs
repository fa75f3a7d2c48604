//! Object literals a preset reads: `{vs, fs, modules: [project32, picking]}` passed to deck.gl's
//! `super.getShaders(…)` or luma.gl's `new Model(device, {…})`, `{vertexShader, fragmentShader,
//! defines}` given to three.js's `new ShaderMaterial(…)`: each key's value as the range of its
//! expression, and what the object is passed to.

use std::ops::Range;

use super::scan;

/// An object literal and its entries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Object {
    /// Its `{`.
    pub open: usize,
    /// Its entries: the key and the range of the value's expression (for a shorthand entry,
    /// `{vs}`, the key itself).
    pub entries: Vec<(String, Range<usize>)>,
    /// The callee it is the first or last argument of, as written before `(`: `super.getShaders`,
    /// `new THREE.ShaderMaterial`, `new Model`; empty for an object in no call.
    pub callee: String,
}

impl Object {
    /// The value range of `key`, if the object has it.
    pub fn get(&self, key: &str) -> Option<Range<usize>> {
        self.entries
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, r)| r.clone())
    }
}

/// Every object literal of `src` that has at least one of `keys`, outermost first.
pub fn objects_with(src: &str, keys: &[&str]) -> Vec<Object> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = scan::line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = scan::comment_end(b, i),
            b'\'' | b'"' => i = scan::string_end(b, i),
            b'`' => i = scan::template(b, i, 0).end,
            b'{' => {
                if let Some(o) = object(src, i) {
                    if o.entries.iter().any(|(k, _)| keys.contains(&k.as_str())) {
                        out.push(o);
                    }
                }
                i += 1;
            }
            _ => i += 1,
        }
    }
    out
}

/// The object literal at `open` (a `{`), if it reads as one: `key: value` and `key` entries
/// separated by commas (spreads and methods are passed over).
pub fn object(src: &str, open: usize) -> Option<Object> {
    let b = src.as_bytes();
    let mut entries = Vec::new();
    let mut i = scan::skip_trivia(b, open + 1);
    while i < b.len() && b[i] != b'}' {
        let key = match b[i] {
            b'\'' | b'"' => {
                let end = scan::string_end(b, i);
                let k = src.get(i + 1..end.saturating_sub(1))?.to_string();
                let r = i..end;
                i = end;
                (k, r)
            }
            b'.' if src[i..].starts_with("...") => {
                i = value_end(b, i + 3);
                i = next_entry(b, i)?;
                continue;
            }
            _ => {
                let r = scan::ident_at(b, i)?;
                i = r.end;
                (src[r.clone()].to_string(), r)
            }
        };
        let after = scan::skip_trivia(b, i);
        match b.get(after)? {
            b':' => {
                let start = scan::skip_trivia(b, after + 1);
                let end = value_end(b, start);
                entries.push((key.0, start..trim_end(b, start, end)));
                i = end;
            }
            b',' | b'}' => {
                entries.push((key.0, key.1));
                i = after;
            }
            // A method (`getShaders() {…}`) or something else: not an object of data.
            _ => return None,
        }
        i = next_entry(b, i)?;
    }
    if i >= b.len() {
        return None;
    }
    Some(Object {
        open,
        entries,
        callee: callee(src, open),
    })
}

/// The arguments of the call whose `(` is at `open`, each as the range of its expression.
pub fn arguments(src: &str, open: usize) -> Option<Vec<Range<usize>>> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = scan::skip_trivia(b, open + 1);
    while b.get(i) != Some(&b')') {
        let end = value_end(b, i);
        out.push(i..trim_end(b, i, end));
        match b.get(end)? {
            b',' => i = scan::skip_trivia(b, end + 1),
            b')' => i = end,
            _ => return None,
        }
    }
    Some(out)
}

/// Past the `,` after an entry (or at the closing `}`).
fn next_entry(b: &[u8], i: usize) -> Option<usize> {
    let i = scan::skip_trivia(b, i);
    match b.get(i)? {
        b',' => Some(scan::skip_trivia(b, i + 1)),
        b'}' => Some(i),
        _ => None,
    }
}

/// The end of the value expression that starts at `i`: the next `,` or `}` outside brackets.
fn value_end(b: &[u8], mut i: usize) -> usize {
    let mut depth = 0usize;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = scan::line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = scan::comment_end(b, i),
            b'\'' | b'"' => i = scan::string_end(b, i),
            b'`' => i = scan::template(b, i, 0).end,
            b'(' | b'[' | b'{' => {
                depth += 1;
                i += 1;
            }
            b')' | b']' | b'}' if depth > 0 => {
                depth -= 1;
                i += 1;
            }
            b',' | b'}' | b')' | b']' if depth == 0 => return i,
            _ => i += 1,
        }
    }
    b.len()
}

fn trim_end(b: &[u8], start: usize, mut end: usize) -> usize {
    while end > start && b[end - 1].is_ascii_whitespace() {
        end -= 1;
    }
    end
}

/// What the object at `open` is passed to: the callee before the `(` that opens the call, if
/// the object is an argument of one.
fn callee(src: &str, open: usize) -> String {
    let before = src[..open].trim_end();
    // `f({…})`, `new M(device, {…})`: back to the call's `(`, over earlier arguments.
    let Some(paren) = call_paren(before) else {
        return String::new();
    };
    let head = src[..paren].trim_end();
    let start = head
        .char_indices()
        .rev()
        .take_while(|&(_, c)| c.is_ascii_alphanumeric() || c == '_' || c == '$' || c == '.')
        .last()
        .map_or(head.len(), |(i, _)| i);
    let name = &head[start..];
    if head[..start].trim_end().ends_with("new") {
        format!("new {name}")
    } else {
        name.to_string()
    }
}

/// The `(` of the call whose argument list `before` ends in (after `(` or `,`).
fn call_paren(before: &str) -> Option<usize> {
    let b = before.as_bytes();
    if !matches!(b.last(), Some(b'(' | b',')) {
        return None;
    }
    let mut depth = 0usize;
    for i in (0..b.len()).rev() {
        match b[i] {
            b')' | b']' | b'}' => depth += 1,
            b'(' if depth == 0 => return Some(i),
            b'(' | b'[' | b'{' => depth = depth.checked_sub(1)?,
            b';' if depth == 0 => return None,
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn objects_and_callees() {
        let src = "class L { getShaders() { return super.getShaders({vs, fs: frag, modules: [a, b]}); } }\n\
                   const m = new THREE.ShaderMaterial({ uniforms: { t: { value: 1 } }, vertexShader: `x`, ...rest });\n\
                   const n = new Model(device, {id: 'm', vs: VS});\n";
        let found = objects_with(src, &["vs", "vertexShader"]);
        assert_eq!(found.len(), 3, "{found:?}");
        assert_eq!(found[0].callee, "super.getShaders");
        assert_eq!(&src[found[0].get("vs").unwrap()], "vs");
        assert_eq!(&src[found[0].get("fs").unwrap()], "frag");
        assert_eq!(&src[found[0].get("modules").unwrap()], "[a, b]");
        assert_eq!(found[1].callee, "new THREE.ShaderMaterial");
        assert_eq!(&src[found[1].get("vertexShader").unwrap()], "`x`");
        assert_eq!(found[2].callee, "new Model");
        assert_eq!(&src[found[2].get("vs").unwrap()], "VS");
    }
}
