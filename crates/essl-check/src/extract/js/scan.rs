//! The lexical layer of the JavaScript scanner: where comments, string literals and template
//! literals (with their `${…}` parts, nested) end, which is all it takes to find every
//! literal's bounds and to step over what is not code. Regular-expression literals are not
//! recognised: one holding a backtick or a quote could hide the literals after it.

use std::ops::Range;

/// How deep `${…}` and template literals may nest before the scanner stops following them
/// (the rest of the file is then one literal): a bound on its recursion for hostile input.
pub const MAX_NESTING: usize = 64;

/// A template literal: its text parts and `${…}` substitutions, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Template {
    /// The opening backtick.
    pub open: usize,
    /// Just past the closing backtick (the end of the file when it is not closed).
    pub end: usize,
    /// Whether a backtick closes it.
    pub closed: bool,
    /// Its text and substitutions.
    pub parts: Vec<TemplatePart>,
    /// Whether the scanner stopped following nested literals inside it.
    pub too_deep: bool,
}

/// A part of a template literal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TemplatePart {
    /// Raw text (escapes not yet cooked).
    Text(Range<usize>),
    /// The code of a `${…}` substitution (without `${` and `}`).
    Substitution(Range<usize>),
}

/// The end of the line comment at `i`.
pub fn line_end(b: &[u8], i: usize) -> usize {
    b[i..]
        .iter()
        .position(|&c| c == b'\n')
        .map_or(b.len(), |n| i + n)
}

/// The end of the block comment at `i`.
pub fn comment_end(b: &[u8], i: usize) -> usize {
    b[i + 2..]
        .windows(2)
        .position(|w| w == b"*/")
        .map_or(b.len(), |n| i + 2 + n + 2)
}

/// The end of the string literal that opens at `open` (just past its closing quote; at a
/// line break for one that is not closed).
pub fn string_end(b: &[u8], open: usize) -> usize {
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

/// The template literal that opens at `open` (a backtick), `depth` literals deep.
pub fn template(b: &[u8], open: usize, depth: usize) -> Template {
    let mut t = Template {
        open,
        end: b.len(),
        closed: false,
        parts: Vec::new(),
        too_deep: false,
    };
    let mut run = open + 1;
    let mut i = open + 1;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'`' => {
                push_text(&mut t.parts, run, i);
                t.end = i + 1;
                t.closed = true;
                return t;
            }
            b'$' if b.get(i + 1) == Some(&b'{') => {
                push_text(&mut t.parts, run, i);
                if depth >= MAX_NESTING {
                    t.too_deep = true;
                    t.parts.push(TemplatePart::Substitution(i + 2..b.len()));
                    return t;
                }
                let end = code_end(b, i + 2, depth + 1);
                let inner_end = if end > i + 2 && b.get(end - 1) == Some(&b'}') {
                    end - 1
                } else {
                    end
                };
                t.parts.push(TemplatePart::Substitution(i + 2..inner_end));
                i = end;
                run = i;
            }
            _ => i += 1,
        }
    }
    push_text(&mut t.parts, run, b.len().min(i));
    t
}

fn push_text(parts: &mut Vec<TemplatePart>, from: usize, to: usize) {
    if from < to {
        parts.push(TemplatePart::Text(from..to));
    }
}

/// The end of the code of a `${…}` that starts at `i`, `depth` literals deep: just past its
/// closing `}`.
pub fn code_end(b: &[u8], mut i: usize, depth: usize) -> usize {
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

/// The first byte at or after `i` that is not white space or a comment.
pub fn skip_trivia(b: &[u8], mut i: usize) -> usize {
    while i < b.len() {
        match b[i] {
            c if c.is_ascii_whitespace() => i += 1,
            b'/' if b.get(i + 1) == Some(&b'/') => i = line_end(b, i),
            b'/' if b.get(i + 1) == Some(&b'*') => i = comment_end(b, i),
            _ => return i,
        }
    }
    b.len()
}

/// Whether `c` can be part of an identifier.
pub fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_' || c == b'$'
}

/// The identifier at `i`, if one starts there: its range.
pub fn ident_at(b: &[u8], i: usize) -> Option<Range<usize>> {
    let first = *b.get(i)?;
    if !(first.is_ascii_alphabetic() || first == b'_' || first == b'$') {
        return None;
    }
    let end = b[i..]
        .iter()
        .position(|&c| !is_ident(c))
        .map_or(b.len(), |n| i + n);
    Some(i..end)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn template_parts_and_nesting() {
        let s = "`a${b + `c${d}`}e`";
        let t = template(s.as_bytes(), 0, 0);
        assert!(t.closed);
        assert_eq!(t.end, s.len());
        assert_eq!(
            t.parts,
            [
                TemplatePart::Text(1..2),
                TemplatePart::Substitution(4..15),
                TemplatePart::Text(16..17)
            ]
        );
        let deep = format!("`{}", "${`".repeat(100_000));
        let t = template(deep.as_bytes(), 0, 0);
        assert!(!t.closed);
    }
}
