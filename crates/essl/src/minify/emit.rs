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
    let a_word = is_word_char(last);
    let a_number = a.starts_with(|c: char| c.is_ascii_digit())
        || (a.starts_with('.') && a.len() > 1 && a.as_bytes()[1].is_ascii_digit());
    if a_word && (is_word_char(first) || (a_number && first == '.')) {
        return true;
    }
    // A number that ends in an exponent's `e` would take a following sign.
    if a_number && matches!(last, 'e' | 'E') && matches!(first, '+' | '-') {
        return true;
    }
    // `.5` after a name or number would join it.
    if a_word && first == '.' && b.len() > 1 && b.as_bytes()[1].is_ascii_digit() {
        return true;
    }
    if !a.is_ascii() || !b.is_ascii() || !PUNCTS.contains(&a) {
        return !a_word && !PUNCTS.contains(&a);
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
    use super::needs_space;

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
