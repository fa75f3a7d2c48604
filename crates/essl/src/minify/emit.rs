//! Printing the lexed tokens back as text with the least white space that keeps them the same
//! tokens: a space only between two words (names, keywords, numbers) or where two punctuators
//! would run into a longer one (`a - -b`, `a / *`), directives on lines of their own.

use rustc_hash::FxHashMap;

use crate::lex::{PpKind, PpToken, Punct};
use crate::Name;

/// One logical line of the original text (line continuations joined, comments gone).
pub(super) struct Line<'a> {
    /// Its tokens, without the final newline.
    pub tokens: &'a [PpToken],
    /// Whether it is a preprocessor directive (its first token is `#`).
    pub directive: bool,
}

impl Line<'_> {
    /// Whether the line is `#define …`.
    pub fn is_define(&self) -> bool {
        self.directive && self.tokens.get(1).is_some_and(|t| t.is_ident("define"))
    }
}

/// Splits lexed tokens into logical lines.
pub(super) fn lines(tokens: &[PpToken]) -> Vec<Line<'_>> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, t) in tokens.iter().enumerate() {
        let end = t.kind == PpKind::Eof;
        if (end && start < i) || t.kind == PpKind::Newline {
            let line = &tokens[start..i];
            out.push(Line {
                tokens: line,
                directive: line.first().is_some_and(|t| t.is(Punct::Hash)),
            });
            start = i + 1;
        }
    }
    out
}

/// Whether the identifier at `i` of a line is a field or swizzle (`v.xy`, `light.color`): the
/// token before it is `.`.
pub(super) fn after_dot(tokens: &[PpToken], i: usize) -> bool {
    i > 0 && tokens[i - 1].is(Punct::Dot)
}

/// The text of the lines, names renamed by `rename`. `keep_lines` keeps every line break
/// (for a shader that reads `__LINE__`).
pub(super) fn print(
    lines: &[Line<'_>],
    rename: &FxHashMap<Name, Name>,
    keep_lines: bool,
) -> String {
    let mut out = String::new();
    let mut prev: Option<&str> = None;
    for line in lines {
        if line.directive && line.tokens.len() > 1 {
            if !out.is_empty() && !out.ends_with('\n') {
                out.push('\n');
            }
            prev = None;
        }
        let define = line.is_define();
        for (i, t) in line.tokens.iter().enumerate() {
            let text = match rename.get(&t.text) {
                Some(new) if t.kind == PpKind::Ident && !after_dot(line.tokens, i) => new.as_str(),
                _ if t.kind == PpKind::Number && !line.directive => shorter_float(&t.text),
                _ => t.text.as_str(),
            };
            // `#define F(x)` is a function-like macro, `#define F (x)` an object-like one.
            let keep_space = define && i == 3 && t.space_before;
            if let Some(p) = prev {
                if keep_space || needs_space(p, text) {
                    out.push(' ');
                }
            }
            if line.directive && line.tokens.len() == 1 {
                // `#` alone: the null directive, which does nothing.
                break;
            }
            out.push_str(text);
            prev = Some(text);
        }
        if (line.directive && line.tokens.len() > 1) || keep_lines {
            out.push('\n');
            prev = None;
        }
    }
    out
}

/// A decimal float literal without the zeros that do not change its value (`1.0` → `1.`,
/// `0.50` → `.5`); any other number as it is (integers, exponents, suffixes). Directives keep
/// their numbers: `#if` takes no floats, and `#version 100` is no float.
fn shorter_float(text: &str) -> &str {
    let Some((int, frac)) = text.split_once('.') else {
        return text;
    };
    if !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_digit()) {
        return text;
    }
    let int = int.trim_start_matches('0');
    let frac = frac.trim_end_matches('0');
    let start = text.len() - int.len() - 1 - text.split_once('.').map_or(0, |(_, f)| f.len());
    // `int` ends at the dot and `frac` starts after it: the shortened literal is one slice.
    let short = &text[start..start + int.len() + 1 + frac.len()];
    if short == "." {
        "0."
    } else {
        short
    }
}

/// Every punctuator's text.
const PUNCTS: &[&str] = &[
    "(", ")", "[", "]", "{", "}", ".", ",", ":", ";", "?", "+", "-", "*", "/", "%", "!", "~", "&",
    "|", "^", "<", ">", "=", "<=", ">=", "==", "!=", "&&", "||", "^^", "<<", ">>", "++", "--",
    "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "#", "##",
];

fn is_word_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Whether `a` then `b`, printed with nothing between them, would lex as other tokens.
pub(super) fn needs_space(a: &str, b: &str) -> bool {
    let (Some(last), Some(first)) = (a.chars().last(), b.chars().next()) else {
        return false;
    };
    let a_number = a.starts_with(|c: char| c.is_ascii_digit())
        || (a.starts_with('.') && a.len() > 1 && a.as_bytes()[1].is_ascii_digit());
    if a_number {
        // A number takes any word character or `.` after it, and a sign after an exponent's
        // `e`.
        return is_word_char(first)
            || first == '.'
            || (matches!(last, 'e' | 'E') && matches!(first, '+' | '-'));
    }
    let a_word = is_word_char(last);
    if a_word {
        // `.5` after a name would join it; `.x` would not.
        return is_word_char(first)
            || (first == '.' && b.len() > 1 && b.as_bytes()[1].is_ascii_digit());
    }
    if !a.is_ascii() || !b.is_ascii() || !PUNCTS.contains(&a) {
        // Around a character outside GLSL's set (only in skipped code): a space.
        return !PUNCTS.contains(&a);
    }
    if a.ends_with('/') && matches!(first, '/' | '*') {
        return true;
    }
    let joined: String = [a, b].concat();
    PUNCTS
        .iter()
        .any(|p| p.len() > a.len() && joined.starts_with(p))
}

#[cfg(test)]
mod tests {
    use super::{needs_space, shorter_float};

    #[test]
    fn float_literals_lose_needless_zeros() {
        for (a, b) in [
            ("1.0", "1."),
            ("0.5", ".5"),
            ("0.0", "0."),
            ("0.", "0."),
            ("10.250", "10.25"),
            ("007.0", "7."),
            (".5", ".5"),
            ("1", "1"),
            ("0", "0"),
            ("1.0e5", "1.0e5"),
            ("2.0f", "2.0f"),
            ("0x10", "0x10"),
            ("1u", "1u"),
        ] {
            assert_eq!(shorter_float(a), b, "{a}");
        }
    }

    #[test]
    fn spaces_only_where_tokens_would_join() {
        assert!(needs_space("float", "x"));
        assert!(needs_space("return", "1"));
        assert!(needs_space("1", "u"));
        assert!(needs_space("1.0", ".5"));
        assert!(needs_space("x", ".5"));
        assert!(needs_space("-", "-"));
        assert!(needs_space("+", "+"));
        assert!(needs_space("+", "++"));
        assert!(needs_space("<", "<="));
        assert!(needs_space("/", "*"));
        assert!(needs_space("&", "&"));
        assert!(needs_space("#", "#"));
        assert!(needs_space("1e", "+"));
        assert!(needs_space("1.", "x"));
        assert!(!needs_space("1.", ";"));
        assert!(!needs_space("1.", ")"));
        assert!(!needs_space("x", "+"));
        assert!(!needs_space("(", "x"));
        assert!(!needs_space(")", "{"));
        assert!(!needs_space("=", "-"));
        assert!(needs_space("-", "="));
        assert!(!needs_space("x", ".y"));
        assert!(!needs_space("1.5", "*"));
        assert!(!needs_space("#", "define"));
    }
}
