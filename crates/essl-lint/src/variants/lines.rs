//! The directive lines of a text, read with a line scanner: the groups inside skipped groups
//! matter to [`super::flags`], and the preprocessor does not evaluate them.

use essl::source::Span;

/// A directive line: its name (`ifdef`, `define`…), the text after it, its span and where the
/// next line starts.
pub(super) struct Line {
    pub name: String,
    pub args: String,
    pub span: Span,
    pub next: u32,
}

/// The directive lines of `text`, outside block comments; a line continued with `\` is read
/// up to its first break (conditionals are one-line in practice).
pub(super) fn directive_lines(text: &str) -> Vec<Line> {
    let mut out = Vec::new();
    let mut in_comment = false;
    let mut at = 0usize;
    for raw in text.split_inclusive('\n') {
        let start = at;
        at += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        let code = strip_comments(line, &mut in_comment);
        let t = code.trim_start();
        let Some(rest) = t.strip_prefix('#') else {
            continue;
        };
        let rest = rest.trim_start();
        let end = rest
            .find(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .unwrap_or(rest.len());
        out.push(Line {
            name: rest[..end].to_string(),
            args: rest[end..].to_string(),
            span: Span::new(start as u32, (start + line.len()) as u32),
            next: at as u32,
        });
    }
    out
}

/// `line` without its comments, tracking whether a block comment stays open past it.
pub(super) fn strip_comments<'a>(
    line: &'a str,
    in_comment: &mut bool,
) -> std::borrow::Cow<'a, str> {
    if !*in_comment && !line.contains("/*") {
        return match line.find("//") {
            Some(i) => line[..i].into(),
            None => line.into(),
        };
    }
    let mut out = String::new();
    let mut rest = line;
    loop {
        if *in_comment {
            match rest.find("*/") {
                Some(i) => {
                    *in_comment = false;
                    rest = &rest[i + 2..];
                    out.push(' ');
                }
                None => return out.into(),
            }
        } else {
            let block = rest.find("/*");
            let line_c = rest.find("//");
            match (block, line_c) {
                (Some(b), l) if l.is_none_or(|l| b < l) => {
                    out.push_str(&rest[..b]);
                    *in_comment = true;
                    rest = &rest[b + 2..];
                }
                (_, Some(l)) => {
                    out.push_str(&rest[..l]);
                    return out.into();
                }
                _ => {
                    out.push_str(rest);
                    return out.into();
                }
            }
        }
    }
}

/// The identifiers of a directive's text with whether a `!` applies to each (`!NAME`,
/// `!defined(NAME)`, `!defined NAME`).
pub(super) fn identifiers(args: &str) -> impl Iterator<Item = (&str, bool)> {
    let bytes = args.as_bytes();
    let mut i = 0;
    let mut negated = false;
    std::iter::from_fn(move || {
        while i < bytes.len() {
            let c = bytes[i];
            if c.is_ascii_alphabetic() || c == b'_' {
                let start = i;
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                let w = &args[start..i];
                if w == "defined" {
                    continue;
                }
                let n = std::mem::take(&mut negated);
                return Some((w, n));
            }
            if c.is_ascii_digit() {
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'.') {
                    i += 1;
                }
                negated = false;
                continue;
            }
            match c {
                b'!' if bytes.get(i + 1) != Some(&b'=') => negated = true,
                b'(' | b' ' | b'\t' => {}
                _ => negated = false,
            }
            i += 1;
        }
        None
    })
}

/// The first name of an `#ifdef`/`#ifndef`.
pub(super) fn first_name(args: &str) -> Vec<String> {
    identifiers(args)
        .next()
        .map(|(w, _)| vec![w.to_string()])
        .unwrap_or_default()
}

/// The names an `#if`/`#elif` tests, split into those whose definition turns the group on and
/// those whose definition turns it off.
pub(super) fn tested(args: &str) -> (Vec<String>, Vec<String>) {
    let (mut on, mut off) = (Vec::new(), Vec::new());
    for (w, negated) in identifiers(args) {
        if negated {
            off.push(w.to_string());
        } else {
            on.push(w.to_string());
        }
    }
    (on, off)
}
