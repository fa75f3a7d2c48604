//! Splits the original text into preprocessing tokens.
//!
//! Line continuations (`\` before a line break) are removed before comments and tokens are
//! recognised, as GLSL ES 3.00 specifies; comments become whitespace. A U+00A0 no-break space
//! (what a web page leaves in a copied shader) is treated as a space so that lexing goes on,
//! and reported once per line: an error outside comments (WebGL rejects it), a warning inside
//! one (harmless, but fixable). Other characters outside GLSL's character set become
//! [`PpKind::Invalid`] tokens for the preprocessor to report where they are not skipped.

use crate::diagnostic_code::Code;
use crate::Name;

use crate::diagnostic::{Applicability, Diagnostic, Edit, Fix};
use crate::source::{SourceFile, Span};

/// A punctuator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Punct {
    LeftParen,
    RightParen,
    LeftBracket,
    RightBracket,
    LeftBrace,
    RightBrace,
    Dot,
    Comma,
    Colon,
    Semicolon,
    Question,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    Bang,
    Tilde,
    Ampersand,
    Pipe,
    Caret,
    Less,
    Greater,
    Equal,
    LessEqual,
    GreaterEqual,
    EqualEqual,
    BangEqual,
    AndAnd,
    OrOr,
    XorXor,
    LeftShift,
    RightShift,
    PlusPlus,
    MinusMinus,
    PlusEqual,
    MinusEqual,
    StarEqual,
    SlashEqual,
    PercentEqual,
    AmpersandEqual,
    PipeEqual,
    CaretEqual,
    LeftShiftEqual,
    RightShiftEqual,
    /// `#`, only meaningful to the preprocessor.
    Hash,
    /// `##`, only meaningful to the preprocessor. The last variant: the lexer sizes a table of
    /// punctuator texts by it.
    HashHash,
}

impl Punct {
    /// The punctuator's text.
    pub fn as_str(self) -> &'static str {
        use Punct::*;
        match self {
            LeftParen => "(",
            RightParen => ")",
            LeftBracket => "[",
            RightBracket => "]",
            LeftBrace => "{",
            RightBrace => "}",
            Dot => ".",
            Comma => ",",
            Colon => ":",
            Semicolon => ";",
            Question => "?",
            Plus => "+",
            Minus => "-",
            Star => "*",
            Slash => "/",
            Percent => "%",
            Bang => "!",
            Tilde => "~",
            Ampersand => "&",
            Pipe => "|",
            Caret => "^",
            Less => "<",
            Greater => ">",
            Equal => "=",
            LessEqual => "<=",
            GreaterEqual => ">=",
            EqualEqual => "==",
            BangEqual => "!=",
            AndAnd => "&&",
            OrOr => "||",
            XorXor => "^^",
            LeftShift => "<<",
            RightShift => ">>",
            PlusPlus => "++",
            MinusMinus => "--",
            PlusEqual => "+=",
            MinusEqual => "-=",
            StarEqual => "*=",
            SlashEqual => "/=",
            PercentEqual => "%=",
            AmpersandEqual => "&=",
            PipeEqual => "|=",
            CaretEqual => "^=",
            LeftShiftEqual => "<<=",
            RightShiftEqual => ">>=",
            Hash => "#",
            HashHash => "##",
        }
    }
}

/// What a preprocessing token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PpKind {
    /// An identifier or keyword.
    Ident,
    /// A preprocessing number (`1`, `0x1F`, `1.5e3`, `2u`, `3.0f`; also malformed ones).
    Number,
    /// A punctuator.
    Punct(Punct),
    /// A character outside GLSL ES's character set.
    Invalid(char),
    /// The end of a (logical) line.
    Newline,
    /// The end of the text.
    Eof,
}

/// A preprocessing token.
#[derive(Clone, Debug, PartialEq)]
pub struct PpToken {
    /// What it is.
    pub kind: PpKind,
    /// Where it is in the original text (for a token from a macro expansion: where the macro
    /// was invoked).
    pub span: Span,
    /// Its text (line continuations inside it removed).
    pub text: Name,
    /// Whitespace or a comment precedes it on its line.
    pub space_before: bool,
    /// It comes from a macro expansion.
    pub from_macro: bool,
}

impl PpToken {
    /// Whether the token is the punctuator `p`.
    pub fn is(&self, p: Punct) -> bool {
        self.kind == PpKind::Punct(p)
    }

    /// Whether the token is the identifier `name`.
    pub fn is_ident(&self, name: &str) -> bool {
        self.kind == PpKind::Ident && &*self.text == name
    }
}

/// The output of the lexer.
#[derive(Debug, Default)]
pub struct Lexed {
    /// The tokens, with a [`PpKind::Newline`] at the end of each logical line and a final
    /// [`PpKind::Eof`].
    pub tokens: Vec<PpToken>,
    /// Diagnostics: no-break spaces, unterminated comments.
    pub diagnostics: Vec<Diagnostic>,
}

/// Characters of the text with line continuations removed.
struct Cursor<'a> {
    bytes: &'a [u8],
    text: &'a str,
    pos: usize,
    /// A line continuation was skipped since this was last cleared (at a token's start): the
    /// token's text is not a slice of the original and must be joined.
    joined: bool,
}

impl<'a> Cursor<'a> {
    /// Skips line continuations at the current position.
    fn skip_continuations(&mut self) {
        loop {
            if self.bytes.get(self.pos) == Some(&b'\\') {
                match (self.bytes.get(self.pos + 1), self.bytes.get(self.pos + 2)) {
                    (Some(b'\n'), _) => self.pos += 2,
                    (Some(b'\r'), Some(b'\n')) => self.pos += 3,
                    (Some(b'\r'), _) => self.pos += 2,
                    _ => return,
                }
                self.joined = true;
            } else {
                return;
            }
        }
    }

    /// The next character. An ASCII byte other than `\\` is its own character with no
    /// continuation before it: no decoding.
    fn peek(&mut self) -> Option<char> {
        match self.bytes.get(self.pos) {
            Some(&b) if b.is_ascii() && b != b'\\' => Some(b as char),
            _ => {
                self.skip_continuations();
                self.text[self.pos..].chars().next()
            }
        }
    }

    fn bump(&mut self) -> Option<char> {
        if let Some(&b) = self.bytes.get(self.pos) {
            if b.is_ascii() && b != b'\\' {
                self.pos += 1;
                return Some(b as char);
            }
        }
        self.skip_continuations();
        let c = self.text[self.pos..].chars().next()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    /// Advances past the bytes for which `f` holds, stopping at a line continuation's `\\` or
    /// a byte that is not ASCII: what the caller then reads through [`Cursor::peek`].
    fn skip_ascii(&mut self, f: impl Fn(u8) -> bool) {
        let rest = &self.bytes[self.pos..];
        self.pos += rest
            .iter()
            .position(|&b| !(b.is_ascii() && b != b'\\' && f(b)))
            .unwrap_or(rest.len());
    }

    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(c) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Advances past the ASCII bytes for which `f` holds, then (at a line continuation) on
    /// through [`Cursor::eat_while`]: a name or a number is scanned byte by byte unless a
    /// continuation splits it.
    fn eat_ascii_while(&mut self, f: impl Fn(u8) -> bool) {
        let rest = &self.bytes[self.pos..];
        self.pos += rest.iter().position(|&b| !f(b)).unwrap_or(rest.len());
        if self.bytes.get(self.pos) == Some(&b'\\') {
            self.eat_while(|c| c.is_ascii() && f(c as u8));
        }
    }

    /// Advances past the characters for which `f` holds.
    fn eat_while(&mut self, f: impl Fn(char) -> bool) {
        while let Some(c) = self.peek() {
            if f(c) {
                self.bump();
            } else {
                break;
            }
        }
    }
}

/// Whether a character is GLSL whitespace (not counting line breaks).
fn is_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\u{0B}' | '\u{0C}')
}

/// Lexes a source text into preprocessing tokens.
pub fn lex(file: &SourceFile) -> Lexed {
    let text = file.text();
    let mut cur = Cursor {
        bytes: text.as_bytes(),
        text,
        pos: 0,
        joined: false,
    };
    let mut out = Lexed {
        // dEQP's shaders take 3.2 bytes a token at the median (newlines counted), 2.0 at the
        // densest: a third of the length made a fifth of them grow (and copy) the vector.
        tokens: Vec::with_capacity(text.len() / 2 + 2),
        diagnostics: Vec::new(),
    };
    let mut names = Interner {
        long: rustc_hash::FxHashMap::default(),
    };
    let newline = Name::new_static("\n");
    // No-break spaces per physical line: (span, inside a comment).
    let mut nbsp: Vec<(Span, bool)> = Vec::new();
    let mut space_before = false;

    loop {
        let start = {
            cur.skip_continuations();
            cur.joined = false;
            cur.pos
        };
        let Some(c) = cur.bump() else { break };
        match c {
            '\n' | '\r' => {
                if c == '\r' {
                    cur.eat('\n');
                }
                out.tokens.push(PpToken {
                    kind: PpKind::Newline,
                    span: Span::new(start as u32, cur.pos as u32),
                    text: newline.clone(),
                    space_before,
                    from_macro: false,
                });
                space_before = false;
            }
            c if is_space(c) => {
                cur.skip_ascii(|b| is_space(b as char));
                space_before = true;
            }
            '\u{A0}' => {
                nbsp.push((Span::new(start as u32, cur.pos as u32), false));
                space_before = true;
            }
            '/' if cur.peek() == Some('/') => {
                line_comment(&mut cur, &mut nbsp);
                space_before = true;
            }
            '/' if cur.peek() == Some('*') => {
                cur.bump();
                block_comment(&mut cur, start, &mut nbsp, &mut out.diagnostics);
                space_before = true;
            }
            c if c.is_ascii_alphabetic() || c == '_' => {
                cur.eat_ascii_while(|b| b.is_ascii_alphanumeric() || b == b'_');
                let text = names.text(text, start, &cur);
                push(
                    &mut out,
                    PpKind::Ident,
                    start,
                    cur.pos,
                    text,
                    &mut space_before,
                );
            }
            c if c.is_ascii_digit()
                || (c == '.' && cur.peek().is_some_and(|d| d.is_ascii_digit())) =>
            {
                number(&mut cur, c);
                let text = names.text(text, start, &cur);
                push(
                    &mut out,
                    PpKind::Number,
                    start,
                    cur.pos,
                    text,
                    &mut space_before,
                );
            }
            c => {
                let (kind, s) = match punct(c, &mut cur) {
                    Some(p) => (PpKind::Punct(p), Name::new_static(p.as_str())),
                    None => (PpKind::Invalid(c), names.text(text, start, &cur)),
                };
                push(&mut out, kind, start, cur.pos, s, &mut space_before);
            }
        }
    }
    finish(&mut out, text.len() as u32, space_before, newline);
    report_nbsp(file, &nbsp, &mut out.diagnostics);
    out
}

/// A line comment after its `/`: to the end of the line (continuations included). No-break
/// spaces in it go to `nbsp`.
fn line_comment(cur: &mut Cursor<'_>, nbsp: &mut Vec<(Span, bool)>) {
    loop {
        cur.skip_ascii(|b| b != b'\n' && b != b'\r');
        let Some(c) = cur.peek() else { break };
        if c == '\n' || c == '\r' {
            break;
        }
        let at = cur.pos;
        cur.bump();
        if c == '\u{A0}' {
            nbsp.push((Span::new(at as u32, cur.pos as u32), true));
        }
    }
}

/// A block comment after its `/*` (which starts at `start`): to the `*/`, or reported as
/// unterminated. No-break spaces in it go to `nbsp`.
fn block_comment(
    cur: &mut Cursor<'_>,
    start: usize,
    nbsp: &mut Vec<(Span, bool)>,
    diagnostics: &mut Vec<Diagnostic>,
) {
    let mut closed = false;
    loop {
        cur.skip_ascii(|b| b != b'*');
        let Some(c) = cur.bump() else { break };
        if c == '*' && cur.peek() == Some('/') {
            cur.bump();
            closed = true;
            break;
        }
        if c == '\u{A0}' {
            let at = cur.pos - c.len_utf8();
            nbsp.push((Span::new(at as u32, cur.pos as u32), true));
        }
    }
    if !closed {
        diagnostics.push(
            Diagnostic::error(
                Code::UnterminatedComment,
                "unterminated `/*` comment",
                Span::new(start as u32, start as u32 + 2),
            )
            .with_label("this comment is never closed")
            .with_help("close it with `*/`")
            .with_token("/*"),
        );
    }
}

/// Moves past the rest of a preprocessing number that starts with `first`: digits, letters,
/// `_`, `.`, and a sign after a decimal exponent's `e`.
fn number(cur: &mut Cursor<'_>, first: char) {
    let mut prev = first;
    let mut second = true;
    let mut hex = false;
    while let Some(c) = cur.peek() {
        let exponent_sign = (c == '+' || c == '-') && (prev == 'e' || prev == 'E') && !hex;
        if c.is_ascii_alphanumeric() || c == '_' || c == '.' || exponent_sign {
            hex |= second && first == '0' && (c == 'x' || c == 'X');
            second = false;
            cur.bump();
            prev = c;
        } else {
            break;
        }
    }
}

/// Ends the token list: a line break after a last line without one (`newline`: the text
/// `"\n"`), then the end of input.
fn finish(out: &mut Lexed, end: u32, space_before: bool, newline: Name) {
    // A last line without a line break still ends.
    if out.tokens.last().is_some_and(|t| t.kind != PpKind::Newline) {
        out.tokens.push(PpToken {
            kind: PpKind::Newline,
            span: Span::empty(end),
            text: newline,
            space_before,
            from_macro: false,
        });
    }
    out.tokens.push(PpToken {
        kind: PpKind::Eof,
        span: Span::empty(end),
        text: Name::default(),
        space_before: false,
        from_macro: false,
    });
}

fn push(out: &mut Lexed, kind: PpKind, start: usize, end: usize, text: Name, space: &mut bool) {
    out.tokens.push(PpToken {
        kind,
        span: Span::new(start as u32, end as u32),
        text,
        space_before: *space,
        from_macro: false,
    });
    *space = false;
}

/// Token texts: up to [`Name::INLINE_CAP`] bytes (nearly every token) copied inline, with no
/// hashing and no allocation; longer texts shared, one `Arc` per distinct text of a file.
struct Interner<'a> {
    long: rustc_hash::FxHashMap<&'a str, Name>,
}

impl<'a> Interner<'a> {
    /// The text of the token from `start` to the cursor, with line continuations removed
    /// (rare: then the text is not shared).
    fn text(&mut self, text: &'a str, start: usize, cur: &Cursor<'_>) -> Name {
        let raw = &text[start..cur.pos];
        if cur.joined {
            let joined = raw.replace(['\\', '\n', '\r'], "");
            if !joined.is_empty() {
                return Name::from(joined);
            }
        }
        self.intern(raw)
    }

    fn intern(&mut self, s: &'a str) -> Name {
        if s.len() <= Name::INLINE_CAP {
            return Name::new_inline(s);
        }
        self.long.entry(s).or_insert_with(|| Name::from(s)).clone()
    }
}

fn punct(c: char, cur: &mut Cursor<'_>) -> Option<Punct> {
    use Punct::*;
    let p = match c {
        '(' => LeftParen,
        ')' => RightParen,
        '[' => LeftBracket,
        ']' => RightBracket,
        '{' => LeftBrace,
        '}' => RightBrace,
        '.' => Dot,
        ',' => Comma,
        ':' => Colon,
        ';' => Semicolon,
        '?' => Question,
        '~' => Tilde,
        '#' => {
            if cur.eat('#') {
                HashHash
            } else {
                Hash
            }
        }
        '+' => {
            if cur.eat('+') {
                PlusPlus
            } else if cur.eat('=') {
                PlusEqual
            } else {
                Plus
            }
        }
        '-' => {
            if cur.eat('-') {
                MinusMinus
            } else if cur.eat('=') {
                MinusEqual
            } else {
                Minus
            }
        }
        '*' => {
            if cur.eat('=') {
                StarEqual
            } else {
                Star
            }
        }
        '/' => {
            if cur.eat('=') {
                SlashEqual
            } else {
                Slash
            }
        }
        '%' => {
            if cur.eat('=') {
                PercentEqual
            } else {
                Percent
            }
        }
        '!' => {
            if cur.eat('=') {
                BangEqual
            } else {
                Bang
            }
        }
        '=' => {
            if cur.eat('=') {
                EqualEqual
            } else {
                Equal
            }
        }
        '&' => {
            if cur.eat('&') {
                AndAnd
            } else if cur.eat('=') {
                AmpersandEqual
            } else {
                Ampersand
            }
        }
        '|' => {
            if cur.eat('|') {
                OrOr
            } else if cur.eat('=') {
                PipeEqual
            } else {
                Pipe
            }
        }
        '^' => {
            if cur.eat('^') {
                XorXor
            } else if cur.eat('=') {
                CaretEqual
            } else {
                Caret
            }
        }
        '<' => {
            if cur.peek() == Some('<') {
                cur.bump();
                if cur.eat('=') {
                    LeftShiftEqual
                } else {
                    LeftShift
                }
            } else if cur.eat('=') {
                LessEqual
            } else {
                Less
            }
        }
        '>' => {
            if cur.peek() == Some('>') {
                cur.bump();
                if cur.eat('=') {
                    RightShiftEqual
                } else {
                    RightShift
                }
            } else if cur.eat('=') {
                GreaterEqual
            } else {
                Greater
            }
        }
        _ => return None,
    };
    Some(p)
}

/// How many no-break spaces of one line are labelled besides the first.
const MAX_NBSP_LABELS: usize = 8;

/// Runs of adjacent no-break spaces: (span of the run, how many).
fn runs(group: &[(Span, bool)]) -> Vec<(Span, usize)> {
    let mut out: Vec<(Span, usize)> = Vec::new();
    for (s, _) in group {
        match out.last_mut() {
            Some((run, n)) if run.end == s.start => {
                run.end = s.end;
                *n += 1;
            }
            _ => out.push((*s, 1)),
        }
    }
    out
}

/// Reports no-break spaces: one diagnostic per line, an error when one is outside a comment
/// (WebGL rejects it there), else a warning; each with a certain fix that replaces them all
/// on that line with plain spaces.
fn report_nbsp(file: &SourceFile, nbsp: &[(Span, bool)], diagnostics: &mut Vec<Diagnostic>) {
    let mut i = 0;
    while i < nbsp.len() {
        let line = file.line_index(nbsp[i].0.start);
        let mut j = i;
        while j < nbsp.len() && file.line_index(nbsp[j].0.start) == line {
            j += 1;
        }
        let group = &nbsp[i..j];
        let in_code: Vec<&(Span, bool)> = group.iter().filter(|(_, c)| !c).collect();
        let primary = in_code.first().map(|(s, _)| *s).unwrap_or(group[0].0);
        let count = group.len();
        let (mut d, what) = if in_code.is_empty() {
            (
                Diagnostic::warning(
                    Code::NoBreakSpace,
                    "no-break space (U+00A0) in a comment",
                    primary,
                ),
                "harmless in a comment, but invisible and easy to copy into code",
            )
        } else {
            (
                Diagnostic::error(
                    Code::NoBreakSpace,
                    "no-break space (U+00A0) is not allowed in GLSL ES source",
                    primary,
                ),
                "GLSL ES allows only space, tab, vertical tab and form feed as white space",
            )
        };
        if !in_code.is_empty() && file.line_text(line).trim_start().starts_with("#version") {
            d = d.with_note(
                "on the `#version` line this is the serious one: WebGL2 does not recognise the directive, compiles the shader as GLSL ES 1.00, and then rejects every `in`/`out` (Chromium reports `'?' : unexpected token` on line 1)",
            );
        }
        d = d
            .with_label(if count == 1 {
                "this looks like a space but is U+00A0".to_string()
            } else {
                format!("this looks like a space but is U+00A0 ({count} on this line)")
            })
            .with_note(what)
            .with_token("?")
            .with_fix(Fix {
                message: if count == 1 {
                    "replace it with a space".into()
                } else {
                    format!("replace all {count} with spaces")
                },
                edits: runs(group)
                    .into_iter()
                    .map(|(span, n)| Edit {
                        span,
                        replacement: " ".repeat(n),
                    })
                    .collect(),
                applicability: Applicability::Certain,
            });
        // A few more places on the line are shown; the label gives the count.
        for (s, _) in group
            .iter()
            .filter(|(s, _)| *s != primary)
            .take(MAX_NBSP_LABELS)
        {
            d = d.with_secondary(*s, "");
        }
        diagnostics.push(d);
        i = j;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<(PpKind, String)> {
        let f = SourceFile::new("t", src);
        lex(&f)
            .tokens
            .into_iter()
            .map(|t| (t.kind, t.text.to_string()))
            .collect()
    }

    #[test]
    fn punctuators_take_the_longest_match() {
        let k = kinds("a<<=b>>c^^d");
        let texts: Vec<&str> = k.iter().map(|(_, t)| t.as_str()).collect();
        assert_eq!(texts, ["a", "<<=", "b", ">>", "c", "^^", "d", "\n", ""]);
    }

    #[test]
    fn numbers_include_exponent_signs_and_suffixes() {
        let k = kinds("1.5e-3f 0x1Fu .5 1e+x");
        let nums: Vec<&str> = k
            .iter()
            .filter(|(k, _)| *k == PpKind::Number)
            .map(|(_, t)| t.as_str())
            .collect();
        assert_eq!(nums, ["1.5e-3f", "0x1Fu", ".5", "1e+x"]);
    }

    #[test]
    fn line_continuation_joins_tokens_and_lines() {
        let k = kinds("fo\\\no bar\\\r\n baz");
        let texts: Vec<&str> = k.iter().map(|(_, t)| t.as_str()).collect();
        assert_eq!(texts, ["foo", "bar", "baz", "\n", ""]);
    }

    #[test]
    fn continuations_split_every_kind_of_token() {
        let k = kinds("a+\\\n=b 1.\\\n5e\\\n-3 ab\\\r\ncd x\\\n");
        let texts: Vec<&str> = k.iter().map(|(_, t)| t.as_str()).collect();
        assert_eq!(texts, ["a", "+=", "b", "1.5e-3", "abcd", "x", "\n", ""]);
        // A backslash before anything but a line break is a character of its own.
        let k = kinds("ab\\ c a\u{e9}");
        assert_eq!(
            k[..4],
            [
                (PpKind::Ident, "ab".into()),
                (PpKind::Invalid('\\'), "\\".into()),
                (PpKind::Ident, "c".into()),
                (PpKind::Ident, "a".into()),
            ]
        );
        assert_eq!(k[4], (PpKind::Invalid('\u{e9}'), "\u{e9}".into()));
    }

    #[test]
    fn comments_are_space_and_unterminated_is_an_error() {
        let f = SourceFile::new("t", "a/*x\ny*/b // c\nd /* e");
        let l = lex(&f);
        let texts: Vec<&str> = l.tokens.iter().map(|t| &*t.text).collect();
        assert_eq!(texts, ["a", "b", "\n", "d", "\n", ""]);
        assert!(l.tokens[1].space_before);
        assert_eq!(l.diagnostics.len(), 1);
        assert_eq!(l.diagnostics[0].code, "unterminated-comment");
    }

    #[test]
    fn continuations_inside_comments_and_white_space_are_removed_first() {
        // A line comment goes on past a continuation; `*\` + line break + `/` closes a block
        // comment; a continuation inside a run of blanks leaves one blank.
        let f = SourceFile::new("t", "a // c \\\n still c\nb /* * *\\\n/ c\t \\\n\td");
        let tokens = lex(&f).tokens;
        let texts: Vec<&str> = tokens.iter().map(|t| &*t.text).collect();
        assert_eq!(texts, ["a", "\n", "b", "c", "d", "\n", ""]);
        assert!(tokens[3].space_before && tokens[4].space_before);
        assert_eq!(tokens[4].span, Span::new(36, 37));
    }

    #[test]
    fn no_break_spaces_are_one_diagnostic_per_line() {
        let f = SourceFile::new(
            "t",
            "#version 300 es \u{a0}\n\u{a0} x;\u{a0}\u{a0}\n// c\u{a0}\n",
        );
        let l = lex(&f);
        let sev: Vec<_> = l
            .diagnostics
            .iter()
            .map(|d| (d.severity, d.fix.as_ref().unwrap().edits.len()))
            .collect();
        use crate::diagnostic::Severity::*;
        // One edit per run of adjacent no-break spaces: line 2 has one, then a run of two.
        assert_eq!(sev, [(Error, 1), (Error, 2), (Warning, 1)]);
        let run = &l.diagnostics[1].fix.as_ref().unwrap().edits[1];
        assert_eq!(
            (run.span.end - run.span.start, &*run.replacement),
            (4, "  ")
        );
        // Lexing goes on as if they were spaces.
        let idents: Vec<&str> = l
            .tokens
            .iter()
            .filter(|t| t.kind == PpKind::Ident)
            .map(|t| &*t.text)
            .collect();
        assert_eq!(idents, ["version", "es", "x"]);
    }

    #[test]
    fn invalid_characters_become_tokens() {
        let k = kinds("a $ b");
        assert_eq!(k[1].0, PpKind::Invalid('$'));
    }
}
