//! Expressions made of literals, whose value essl can compute without running the script: a
//! template literal (its `${…}` substitutions naming constants), a string, a number, `a + b`,
//! `[…].join(sep)`, and objects of those (for `${ALIGN.start}`); and their value as
//! [`Piece`]s that map every byte back to the file.

use std::ops::Range;

use super::super::{text_of, Piece};
use super::cook::cook;
use super::scan::{self, Template, TemplatePart};

/// An expression of literals.
#[derive(Clone, Debug)]
pub enum Expr {
    /// A template literal.
    Template(Template),
    /// A string literal (its quotes included).
    Str(Range<usize>),
    /// A number literal.
    Number(Range<usize>),
    /// A name, or a member of one (`ALIGN.start`): a constant to look up.
    Name(Range<usize>),
    /// `a + b + …`.
    Concat(Vec<Expr>),
    /// `[a, b, …].join(separator)`.
    Join(Vec<Expr>, Box<Expr>),
    /// `{key: value, …}`.
    Object(Vec<(String, Expr)>),
}

/// Why an expression's value is not known.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Unknown {
    /// A substitution or a name that is not a constant of literals: its text.
    Name(String),
    /// An escape JavaScript rejects.
    Escape,
    /// Names that refer to each other more deeply than essl follows.
    TooDeep,
}

/// The value of a name, as the caller finds it (`None`: not a constant essl can compute).
pub type Lookup<'a> = dyn Fn(&str, usize) -> Result<Vec<Piece>, Unknown> + 'a;

/// The literal expression that starts at `at`, and where it ends; `allow_names` lets a name
/// stand as an operand of `+` (a shader is never a bare name, but a constant can be).
pub fn parse(b: &[u8], at: usize) -> Option<(Expr, usize)> {
    let (first, mut end) = primary(b, at, false)?;
    let mut items = vec![first];
    loop {
        let plus = scan::skip_trivia(b, end);
        if b.get(plus) != Some(&b'+') || matches!(b.get(plus + 1), Some(b'+' | b'=')) {
            break;
        }
        match primary(b, scan::skip_trivia(b, plus + 1), true) {
            Some((e, e_end)) => {
                items.push(e);
                end = e_end;
            }
            None => return None,
        }
    }
    let expr = if items.len() == 1 {
        items.pop()?
    } else {
        Expr::Concat(items)
    };
    Some((expr, end))
}

/// Whether the script changes a literal's value before it is used: the expression that ends
/// at `end` is followed by a method call (`` `…`.replace('{TYPE}', type) ``). Trimming
/// white space (`.trim()`, `.trimStart()`, `.trimEnd()`) leaves the shader's text as written.
pub fn rewritten(b: &[u8], end: usize) -> bool {
    let mut i = scan::skip_trivia(b, end);
    while b.get(i) == Some(&b'.') {
        let Some(name) = scan::ident_at(b, scan::skip_trivia(b, i + 1)) else {
            return false;
        };
        let open = scan::skip_trivia(b, name.end);
        if b.get(open) != Some(&b'(') {
            return false;
        }
        let trim = matches!(&b[name.clone()], b"trim" | b"trimStart" | b"trimEnd");
        let close = scan::skip_trivia(b, open + 1);
        if !trim || b.get(close) != Some(&b')') {
            return true;
        }
        i = scan::skip_trivia(b, close + 1);
    }
    false
}

/// A literal, an array joined, an object, or (where `names`) a name.
fn primary(b: &[u8], at: usize, names: bool) -> Option<(Expr, usize)> {
    match *b.get(at)? {
        b'`' => {
            let t = scan::template(b, at, 0);
            let end = t.end;
            t.closed.then_some((Expr::Template(t), end))
        }
        b'\'' | b'"' => {
            let end = scan::string_end(b, at);
            (b.get(end - 1) == Some(&b[at]) && end > at + 1).then_some((Expr::Str(at..end), end))
        }
        b'0'..=b'9' | b'.' => {
            let end = b[at..]
                .iter()
                .position(|c| !(c.is_ascii_alphanumeric() || *c == b'.' || *c == b'_'))
                .map_or(b.len(), |n| at + n);
            Some((Expr::Number(at..end), end))
        }
        b'[' => join(b, at),
        b'{' => object(b, at),
        _ if names => {
            let mut r = scan::ident_at(b, at)?;
            while b.get(r.end) == Some(&b'.') {
                let next = scan::ident_at(b, r.end + 1)?;
                r.end = next.end;
            }
            // A call or an index is not a constant: `f()`, `a[0]`.
            if matches!(b.get(scan::skip_trivia(b, r.end)), Some(b'(' | b'[')) {
                return None;
            }
            Some((Expr::Name(r.clone()), r.end))
        }
        _ => None,
    }
}

/// `[a, b, …].join(separator)` at `at` (a `[`).
fn join(b: &[u8], at: usize) -> Option<(Expr, usize)> {
    let mut items = Vec::new();
    let mut i = scan::skip_trivia(b, at + 1);
    while b.get(i) != Some(&b']') {
        let (e, end) = parse(b, i)?;
        items.push(e);
        i = scan::skip_trivia(b, end);
        match b.get(i)? {
            b',' => i = scan::skip_trivia(b, i + 1),
            b']' => {}
            _ => return None,
        }
    }
    let i = scan::skip_trivia(b, i + 1);
    let i = scan::skip_trivia(b, expect(b, i, b".")?);
    let i = scan::skip_trivia(b, expect(b, i, b"join")?);
    let i = scan::skip_trivia(b, expect(b, i, b"(")?);
    let (separator, end) = parse(b, i)?;
    let end = expect(b, scan::skip_trivia(b, end), b")")?;
    Some((Expr::Join(items, Box::new(separator)), end))
}

/// `{key: value, …}` at `at`: keys as names or strings, values literals.
fn object(b: &[u8], at: usize) -> Option<(Expr, usize)> {
    let mut fields = Vec::new();
    let mut i = scan::skip_trivia(b, at + 1);
    while b.get(i) != Some(&b'}') {
        let key = match *b.get(i)? {
            b'\'' | b'"' => {
                let end = scan::string_end(b, i);
                let k = std::str::from_utf8(&b[i + 1..end - 1]).ok()?.to_string();
                i = end;
                k
            }
            _ => {
                let r = scan::ident_at(b, i)?;
                i = r.end;
                std::str::from_utf8(&b[r]).ok()?.to_string()
            }
        };
        let colon = expect(b, scan::skip_trivia(b, i), b":")?;
        let (value, end) = parse(b, scan::skip_trivia(b, colon))?;
        fields.push((key, value));
        i = scan::skip_trivia(b, end);
        match b.get(i)? {
            b',' => i = scan::skip_trivia(b, i + 1),
            b'}' => {}
            _ => return None,
        }
    }
    Some((Expr::Object(fields), i + 1))
}

fn expect(b: &[u8], at: usize, what: &[u8]) -> Option<usize> {
    b.get(at..at + what.len())
        .filter(|s| *s == what)
        .map(|_| at + what.len())
}

impl Expr {
    /// The value of the expression as pieces of `src`, names looked up through `lookup`
    /// (`depth`: how many names deep this expression is).
    pub fn pieces(&self, src: &str, lookup: &Lookup, depth: usize) -> Result<Vec<Piece>, Unknown> {
        let mut out = Vec::new();
        self.push(src, lookup, depth, &mut out)?;
        Ok(out)
    }

    fn push(
        &self,
        src: &str,
        lookup: &Lookup,
        depth: usize,
        out: &mut Vec<Piece>,
    ) -> Result<(), Unknown> {
        match self {
            Expr::Template(t) => {
                for part in &t.parts {
                    match part {
                        TemplatePart::Text(r) => {
                            cook(src, r.clone(), true, out).map_err(|_| Unknown::Escape)?
                        }
                        TemplatePart::Substitution(r) => {
                            let code = src[r.clone()].trim();
                            if is_name(code) {
                                out.extend(lookup(code, depth + 1)?);
                                continue;
                            }
                            // A literal written in the substitution: `${1.0}`, `${'x'}`.
                            let b = src.as_bytes();
                            let start = scan::skip_trivia(b, r.start);
                            match parse(b, start) {
                                Some((e, end)) if scan::skip_trivia(b, end) >= r.end => {
                                    e.push(src, lookup, depth, out)?
                                }
                                _ => return Err(Unknown::Name(code.to_string())),
                            }
                        }
                    }
                }
            }
            Expr::Str(r) => {
                cook(src, r.start + 1..r.end - 1, false, out).map_err(|_| Unknown::Escape)?
            }
            Expr::Number(r) => {
                let raw = &src[r.clone()];
                match js_number(raw) {
                    Some(v) if v == raw => out.push(Piece::Raw(r.clone())),
                    Some(v) => out.push(Piece::Cooked {
                        raw: r.clone(),
                        value: v,
                    }),
                    None => return Err(Unknown::Name(raw.to_string())),
                }
            }
            Expr::Name(r) => out.extend(lookup(&src[r.clone()], depth + 1)?),
            Expr::Concat(items) => {
                for e in items {
                    e.push(src, lookup, depth, out)?;
                }
            }
            Expr::Join(items, separator) => {
                let sep = separator.pieces(src, lookup, depth)?;
                let sep_text = text_of(src, &sep);
                for (k, e) in items.iter().enumerate() {
                    if k > 0 {
                        let at = out.last().map_or(0, end_of);
                        out.push(Piece::Added {
                            text: sep_text.clone(),
                            at,
                        });
                    }
                    e.push(src, lookup, depth, out)?;
                }
            }
            Expr::Object(_) => return Err(Unknown::Name("an object".into())),
        }
        Ok(())
    }

    /// The byte where the expression's text starts (inside its first literal).
    pub fn start(&self) -> usize {
        match self {
            Expr::Template(t) => t.open + 1,
            Expr::Str(r) => r.start + 1,
            Expr::Number(r) | Expr::Name(r) => r.start,
            Expr::Concat(items) | Expr::Join(items, _) => items.first().map_or(0, Expr::start),
            Expr::Object(_) => 0,
        }
    }

    /// The names its template literals' substitutions are (`${NAME}`, `${A.b}`).
    pub fn substitutions<'s>(&self, src: &'s str) -> Vec<&'s str> {
        match self {
            Expr::Template(t) => t
                .parts
                .iter()
                .filter_map(|p| match p {
                    TemplatePart::Substitution(r) => Some(src[r.clone()].trim()),
                    TemplatePart::Text(_) => None,
                })
                .filter(|code| is_name(code))
                .collect(),
            Expr::Concat(items) | Expr::Join(items, _) => {
                items.iter().flat_map(|e| e.substitutions(src)).collect()
            }
            _ => Vec::new(),
        }
    }

    /// Whether the expression is a template literal.
    pub fn is_template(&self) -> bool {
        matches!(self, Expr::Template(_))
    }

    /// The raw text of its first literal, for telling whether an expression whose value is
    /// not known would have been a shader.
    pub fn first_text<'s>(&self, src: &'s str) -> &'s str {
        match self {
            Expr::Template(t) => match t.parts.first() {
                Some(TemplatePart::Text(r)) => &src[r.clone()],
                _ => "",
            },
            Expr::Str(r) => &src[r.start + 1..r.end - 1],
            Expr::Concat(items) | Expr::Join(items, _) => {
                items.first().map_or("", |e| e.first_text(src))
            }
            _ => "",
        }
    }
}

/// The end of the file bytes a piece stands for.
fn end_of(p: &Piece) -> usize {
    match p {
        Piece::Raw(r) => r.end,
        Piece::Cooked { raw, .. } => raw.end,
        Piece::Added { at, .. } => *at,
        Piece::From { .. } => 0,
    }
}

/// Whether `code` is a name or a member of one (`a`, `a.b.c`).
fn is_name(code: &str) -> bool {
    !code.is_empty()
        && code.split('.').all(|part| {
            let b = part.as_bytes();
            scan::ident_at(b, 0).is_some_and(|r| r.end == b.len())
        })
}

/// How JavaScript writes a number literal's value as a string (`1.0` → `1`, `0x10` → `16`),
/// for the literals shaders interpolate; `None` for what it does not handle.
fn js_number(raw: &str) -> Option<String> {
    let clean = raw.replace('_', "");
    let value = if let Some(hex) = clean.strip_prefix("0x").or(clean.strip_prefix("0X")) {
        i64::from_str_radix(hex, 16).ok()? as f64
    } else if let Some(bin) = clean.strip_prefix("0b").or(clean.strip_prefix("0B")) {
        i64::from_str_radix(bin, 2).ok()? as f64
    } else if let Some(oct) = clean.strip_prefix("0o").or(clean.strip_prefix("0O")) {
        i64::from_str_radix(oct, 8).ok()? as f64
    } else {
        clean.parse::<f64>().ok()?
    };
    if value.fract() == 0.0 && value.abs() < 1e21 {
        Some(format!("{}", value as i64))
    } else {
        // Rust's shortest round-trip form matches JavaScript's for ordinary magnitudes.
        Some(format!("{value}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(src: &str) -> Result<String, Unknown> {
        let (e, _) = parse(src.as_bytes(), 0).unwrap();
        let lookup = |name: &str, _: usize| -> Result<Vec<Piece>, Unknown> {
            match name {
                "N" => Ok(vec![Piece::Added {
                    text: "7".into(),
                    at: 0,
                }]),
                other => Err(Unknown::Name(other.into())),
            }
        };
        e.pieces(src, &lookup, 0).map(|p| text_of(src, &p))
    }

    #[test]
    fn values() {
        assert_eq!(value("`a${N}b`").unwrap(), "a7b");
        assert_eq!(value("'a\\n' + \"b\" + `c`").unwrap(), "a\nbc");
        assert_eq!(value("['x', 'y'].join('\\n')").unwrap(), "x\ny");
        assert_eq!(
            value("[\n 'x', // c\n 'y',\n].join(\"\\n\")").unwrap(),
            "x\ny"
        );
        assert_eq!(value("`${1.0}${0x10}${2.5}${'x'}`").unwrap(), "1162.5x");
        assert_eq!(value("`${f(x)}`"), Err(Unknown::Name("f(x)".into())));
        assert_eq!(value("'a' + N").unwrap(), "a7");
        assert!(parse(b"'a' + f()", 0).is_none());
        assert_eq!(js_number("1.0").unwrap(), "1");
        assert_eq!(js_number("0x10").unwrap(), "16");
        assert_eq!(js_number("2.5").unwrap(), "2.5");
    }
}
