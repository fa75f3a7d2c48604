//! The value JavaScript computes for the text of a string or template literal: escape
//! sequences (`\n`, `\t`, `\x41`, `\u{1F600}`, line continuations, …) replaced by what they
//! stand for, and in a template, a raw `\r\n` or `\r` read as `\n` — each as a [`Piece`] that
//! knows which bytes of the file it came from.

use std::ops::Range;

use super::super::Piece;

/// Why a literal's value cannot be computed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CookError {
    /// An escape JavaScript refuses in this literal (an octal escape in a template).
    Invalid(usize),
    /// An escape for half of a UTF-16 surrogate pair with no other half.
    LoneSurrogate(usize),
}

/// Appends the pieces of the text `range` of `src`, the body of a template (`template`) or of a
/// string literal, to `out`.
pub fn cook(
    src: &str,
    range: Range<usize>,
    template: bool,
    out: &mut Vec<Piece>,
) -> Result<(), CookError> {
    let b = src.as_bytes();
    let mut run = range.start;
    let mut i = range.start;
    let flush = |out: &mut Vec<Piece>, from: usize, to: usize| {
        if from < to {
            match out.last_mut() {
                Some(Piece::Raw(r)) if r.end == from => r.end = to,
                _ => out.push(Piece::Raw(from..to)),
            }
        }
    };
    while i < range.end {
        match b[i] {
            b'\\' => {
                flush(out, run, i);
                let (len, value) = escape(src, i, template)?;
                out.push(Piece::Cooked {
                    raw: i..i + len,
                    value,
                });
                i += len;
                run = i;
            }
            b'\r' if template => {
                flush(out, run, i);
                let len = if b.get(i + 1) == Some(&b'\n') { 2 } else { 1 };
                out.push(Piece::Cooked {
                    raw: i..i + len,
                    value: "\n".into(),
                });
                i += len;
                run = i;
            }
            _ => i += 1,
        }
    }
    flush(out, run, range.end);
    Ok(())
}

/// The escape sequence at `at` (a `\`): its length in bytes and its value.
fn escape(src: &str, at: usize, template: bool) -> Result<(usize, String), CookError> {
    let rest = &src[at + 1..];
    let Some(c) = rest.chars().next() else {
        return Ok((1, String::new()));
    };
    let simple = |v: &str| Ok((2, v.to_string()));
    match c {
        // Line continuations stand for nothing.
        '\n' | '\u{2028}' | '\u{2029}' => Ok((1 + c.len_utf8(), String::new())),
        '\r' if rest.as_bytes().get(1) == Some(&b'\n') => Ok((3, String::new())),
        '\r' => Ok((2, String::new())),
        'n' => simple("\n"),
        't' => simple("\t"),
        'r' => simple("\r"),
        'b' => simple("\u{8}"),
        'f' => simple("\u{c}"),
        'v' => simple("\u{b}"),
        '0' if !rest[1..].starts_with(|d: char| d.is_ascii_digit()) => simple("\0"),
        '0'..='9' if template => Err(CookError::Invalid(at)),
        '0'..='7' => {
            // A legacy octal escape of a string: up to three digits, at most 0o377.
            let digits: String = rest
                .chars()
                .take(3)
                .take_while(|d| ('0'..='7').contains(d))
                .collect();
            let mut n = 0u32;
            let mut used = 0;
            for d in digits.chars() {
                let next = n * 8 + d.to_digit(8).unwrap_or(0);
                if next > 0o377 {
                    break;
                }
                n = next;
                used += 1;
            }
            Ok((
                1 + used,
                char::from_u32(n).map(String::from).unwrap_or_default(),
            ))
        }
        'x' => {
            let hex = rest
                .get(1..3)
                .filter(|h| h.chars().all(|d| d.is_ascii_hexdigit()));
            match hex.and_then(|h| u32::from_str_radix(h, 16).ok()) {
                Some(n) => Ok((4, char::from_u32(n).map(String::from).unwrap_or_default())),
                None => Err(CookError::Invalid(at)),
            }
        }
        'u' => unicode(src, at),
        other => Ok((1 + other.len_utf8(), other.to_string())),
    }
}

/// `\uHHHH` (with its low surrogate, for a high one) or `\u{H…}` at `at`.
fn unicode(src: &str, at: usize) -> Result<(usize, String), CookError> {
    let rest = &src[at + 2..];
    if let Some(braced) = rest.strip_prefix('{') {
        let end = braced.find('}').ok_or(CookError::Invalid(at))?;
        let n = u32::from_str_radix(&braced[..end], 16).map_err(|_| CookError::Invalid(at))?;
        let c = char::from_u32(n).ok_or(CookError::Invalid(at))?;
        return Ok((2 + 1 + end + 1, c.to_string()));
    }
    let unit = |s: &str| -> Option<u32> {
        let h = s.get(..4)?;
        h.chars()
            .all(|d| d.is_ascii_hexdigit())
            .then(|| u32::from_str_radix(h, 16).ok())
            .flatten()
    };
    let first = unit(rest).ok_or(CookError::Invalid(at))?;
    if let Some(c) = char::from_u32(first) {
        return Ok((6, c.to_string()));
    }
    // A high surrogate must be followed by `\uDC00`–`\uDFFF`.
    let low = rest[4..]
        .strip_prefix("\\u")
        .and_then(unit)
        .filter(|l| (0xDC00..0xE000).contains(l) && (0xD800..0xDC00).contains(&first));
    match low {
        Some(l) => {
            let n = 0x10000 + ((first - 0xD800) << 10) + (l - 0xDC00);
            let c = char::from_u32(n).ok_or(CookError::LoneSurrogate(at))?;
            Ok((12, c.to_string()))
        }
        None => Err(CookError::LoneSurrogate(at)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cooked(src: &str, template: bool) -> (String, Vec<Piece>) {
        let mut out = Vec::new();
        cook(src, 0..src.len(), template, &mut out).unwrap();
        (super::super::super::text_of(src, &out), out)
    }

    #[test]
    fn every_escape_form() {
        assert_eq!(cooked("a\\nb\\tc", true).0, "a\nb\tc");
        assert_eq!(cooked("\\\n#version", true).0, "#version");
        assert_eq!(cooked("x\\\r\ny", true).0, "xy");
        assert_eq!(
            cooked("\\x41\\u0042\\u{43}\\u{1F600}", true).0,
            "ABC\u{1F600}"
        );
        assert_eq!(cooked("\\uD83D\\uDE00", true).0, "\u{1F600}");
        assert_eq!(cooked("\\`\\$\\{\\\\\\'", true).0, "`${\\'");
        assert_eq!(cooked("a\r\nb\rc", true).0, "a\nb\nc");
        assert_eq!(cooked("a\r\nb", false).0, "a\r\nb");
        assert_eq!(cooked("\\101", false).0, "A");
        assert_eq!(cooked("\\0", true).0, "\0");
        let mut out = Vec::new();
        assert_eq!(
            cook("\\101", 0..4, true, &mut out),
            Err(CookError::Invalid(0))
        );
        assert_eq!(
            cook("\\uD83D", 0..6, true, &mut out),
            Err(CookError::LoneSurrogate(0))
        );
    }

    #[test]
    fn pieces_know_their_bytes() {
        let (_, pieces) = cooked("ab\\ncd", true);
        assert_eq!(
            pieces,
            [
                Piece::Raw(0..2),
                Piece::Cooked {
                    raw: 2..4,
                    value: "\n".into()
                },
                Piece::Raw(4..6)
            ]
        );
    }
}
