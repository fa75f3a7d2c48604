//! Template literals in JavaScript or TypeScript that hold shaders: those whose text starts
//! with `#version` (after white space, which is left out of the shader as twgl leaves it out),
//! and those tagged `glsl` (`` glsl`…` ``) or marked `/* glsl */`.
//!
//! A small scanner, not a parser: it skips comments, quoted strings and template literals
//! (with their `${…}` parts, nested), which is all it takes to find every literal's bounds.
//! Regular-expression literals are not recognised; one holding a backtick or a quote could
//! hide the literals after it.

use super::{Embedded, Skip};

/// The shaders in `text`, a script; `base` is added to every range (the script's offset in
/// its page).
pub fn extract(text: &str, base: usize) -> Vec<Embedded> {
    let b = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = comment_end(b, i),
            b'\'' | b'"' => i = string_end(b, i),
            b'`' => {
                let literal = template(b, i, 0);
                if let Some(e) = shader(text, i, &literal, base) {
                    found.push(e);
                }
                i = literal.end;
            }
            _ => i += 1,
        }
    }
    found
}

/// How deep `${…}` and template literals may nest before the scanner stops following them
/// (the rest of the file is then one literal): a bound on its recursion for hostile input.
const MAX_NESTING: usize = 64;

/// A template literal's bounds: its text is `open + 1..end - 1`.
struct Literal {
    end: usize,
    closed: bool,
    interpolated: bool,
    escaped: bool,
}

fn line_end(b: &[u8], i: usize) -> usize {
    b[i..]
        .iter()
        .position(|&c| c == b'\n')
        .map_or(b.len(), |n| i + n)
}

fn comment_end(b: &[u8], i: usize) -> usize {
    b[i + 2..]
        .windows(2)
        .position(|w| w == b"*/")
        .map_or(b.len(), |n| i + 2 + n + 2)
}

fn string_end(b: &[u8], open: usize) -> usize {
    let quote = b[open];
    let mut i = open + 1;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'\n' => return i,
            c if c == quote => return i + 1,
            _ => i += 1,
        }
    }
    b.len()
}

/// The literal that opens at `open` (a backtick), `depth` literals deep.
fn template(b: &[u8], open: usize, depth: usize) -> Literal {
    let mut literal = Literal {
        end: b.len(),
        closed: false,
        interpolated: false,
        escaped: false,
    };
    let mut i = open + 1;
    while i < b.len() {
        match b[i] {
            b'\\' => {
                literal.escaped = true;
                i += 2;
            }
            b'`' => {
                literal.end = i + 1;
                literal.closed = true;
                return literal;
            }
            b'$' if b.get(i + 1) == Some(&b'{') => {
                literal.interpolated = true;
                if depth >= MAX_NESTING {
                    return literal;
                }
                i = code_end(b, i + 2, depth + 1);
            }
            _ => i += 1,
        }
    }
    literal
}

/// The end of the code of a `${…}` that starts at `i`, `depth` literals deep: just past its
/// closing `}`.
fn code_end(b: &[u8], mut i: usize, depth: usize) -> usize {
    let mut braces = 0usize;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => i = line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = comment_end(b, i),
            b'\'' | b'"' => i = string_end(b, i),
            b'`' => i = template(b, i, depth).end,
            b'{' => {
                braces += 1;
                i += 1;
            }
            b'}' if braces == 0 => return i + 1,
            b'}' => {
                braces -= 1;
                i += 1;
            }
            _ => i += 1,
        }
    }
    b.len()
}

/// The literal at `open` as a shader, if it is one.
fn shader(text: &str, open: usize, literal: &Literal, base: usize) -> Option<Embedded> {
    let content_end = if literal.closed {
        literal.end - 1
    } else {
        literal.end
    };
    let body = &text[open + 1..content_end];
    let (tagged, name) = context(&text[..open]);
    if !tagged && !body.trim_start().starts_with("#version") {
        return None;
    }
    // White space before `#version` is left out, as twgl's `createProgramInfo` does before
    // compiling: `` `\n  #version 300 es …` `` compiles in the page.
    let lead = if body.trim_start().starts_with("#version") {
        body.len() - body.trim_start().len()
    } else {
        0
    };
    let skip = if literal.interpolated {
        Some(Skip::Interpolated)
    } else if literal.escaped {
        Some(Skip::Escapes)
    } else {
        None
    };
    Some(Embedded {
        range: base + open + 1 + lead..base + content_end,
        stage: None,
        name,
        skip,
    })
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

    fn shaders(text: &str) -> Vec<(String, Option<String>, Option<Skip>)> {
        extract(text, 0)
            .into_iter()
            .map(|e| (text[e.range].to_string(), e.name, e.skip))
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
                    gl.shaderSource(s, `#version 300 es\\n`);\n";
        let found = shaders(text);
        assert_eq!(found.len(), 5, "{found:?}");
        assert_eq!(found[0].0, "#version 300 es\nvoid main() {}");
        assert_eq!(found[0].1.as_deref(), Some("vs"));
        assert_eq!(found[1].1.as_deref(), Some("fs"));
        assert_eq!(found[2].1.as_deref(), Some("x"));
        assert_eq!(found[3].2, Some(Skip::Interpolated));
        assert_eq!(found[4].2, Some(Skip::Escapes));
    }

    #[test]
    fn deep_nesting_is_bounded() {
        let deep = format!("a = `#version 300 es\n{}", "${`".repeat(100_000));
        let found = shaders(&deep);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].2, Some(Skip::Interpolated));
    }

    #[test]
    fn interpolations_nest_and_unclosed_literals_end_the_file() {
        let found = shaders("a = `#version 300 es\n${f(`x${'}'}`)}`; b = `#version");
        assert_eq!(found.len(), 2);
        assert_eq!(found[0].2, Some(Skip::Interpolated));
        assert_eq!(found[1].0, "#version");
    }
}
