//! The GLSL source behind the output: where each declaration was, the author's comments, and
//! the blank lines between the author's blocks.
//!
//! essl's IR keeps, for every statement and expression, the span of the GLSL it came from;
//! the WGSL writer gives each line it writes the span of its statement or declaration
//! (`wgsl::Origin`). A comment of the GLSL then goes above the first line written
//! from source after it (a comment on a line of its own), or at the end of the line written
//! from the statement it follows on its line (a trailing comment). The comments before the
//! first declaration describe the file: they go under the output's header. A blank line
//! between two statements of the GLSL is a blank line between them in the output.

use std::collections::HashMap;

use essl::Shader;

use crate::wgsl::{Line, Origin};

/// Where the module-level items were declared, by GLSL name.
#[derive(Clone, Debug, Default)]
pub struct Anchors {
    names: HashMap<String, (usize, u32, u32)>,
    members: HashMap<(String, String), (usize, u32, u32)>,
    mains: HashMap<usize, (u32, u32)>,
}

impl Anchors {
    /// The declarations of `shader`, whose text is source `file`.
    pub(crate) fn add(&mut self, file: usize, shader: &Shader) {
        let m = &shader.module;
        let mut put = |name: &str, span: essl::source::Span| {
            self.names
                .entry(name.to_owned())
                .or_insert((file, span.start, span.end));
        };
        for g in &m.globals {
            put(g.name.as_str(), g.span);
        }
        for b in &m.blocks {
            put(b.name.as_str(), b.span);
            if let Some(i) = &b.instance {
                put(i.as_str(), b.span);
            }
            for (member, ..) in &b.members {
                put(member.as_str(), b.span);
            }
        }
        for f in &m.functions {
            put(f.name.as_str(), f.span);
        }
        if let Some(main) = m.entry {
            let s = m.functions[main].span;
            self.mains.insert(file, (s.start, s.end));
        }
        let text = shader.file.text();
        for s in &m.structs {
            let Some(name) = &s.name else { continue };
            let Some((at, body)) = struct_body(text, name) else {
                continue;
            };
            self.names.entry(name.clone()).or_insert((
                file,
                at as u32,
                at as u32 + name.len() as u32,
            ));
            for member in &s.members {
                if let Some(k) = word(&text[body.clone()], &member.name) {
                    let start = (body.start + k) as u32;
                    self.members.insert(
                        (name.clone(), member.name.clone()),
                        (file, start, start + member.name.len() as u32),
                    );
                }
            }
        }
    }

    /// The declaration a written item's IR name comes from: the name itself, an input's
    /// (`aPos_in`), a sampler's (`material_diffuse` is `material.diffuse`).
    pub(crate) fn lookup(&self, name: &str) -> Option<Origin> {
        if name.starts_with("_essl") || name.is_empty() {
            return None;
        }
        let mut candidates = vec![name.to_owned()];
        if let Some(n) = name.strip_suffix("_in") {
            candidates.push(n.to_owned());
        }
        if let Some(k) = name.find(['[', '.']) {
            candidates.push(name[..k].to_owned());
        }
        let mut n = name;
        while let Some(k) = n.rfind('_') {
            n = &n[..k];
            if !n.is_empty() {
                candidates.push(n.to_owned());
            }
        }
        candidates
            .iter()
            .find_map(|c| self.names.get(c))
            .map(|&(file, start, end)| Origin::Source { file, start, end })
    }

    /// A struct member's declaration.
    pub(crate) fn member(&self, strukt: &str, member: &str) -> Option<Origin> {
        self.members
            .get(&(strukt.to_owned(), member.to_owned()))
            .map(|&(file, start, end)| Origin::Source { file, start, end })
    }

    /// Where file `file`'s `main` is.
    pub(crate) fn main(&self, file: usize) -> Option<Origin> {
        self.mains
            .get(&file)
            .map(|&(start, end)| Origin::Source { file, start, end })
    }
}

/// Where `struct NAME` is, and its body's byte range.
fn struct_body(text: &str, name: &str) -> Option<(usize, std::ops::Range<usize>)> {
    let code = code_mask(text);
    let mut from = 0;
    while let Some(k) = text[from..].find("struct") {
        let at = from + k;
        from = at + 6;
        if !code[at] {
            continue;
        }
        let rest = &text[at + 6..];
        let trimmed = rest.trim_start();
        if !trimmed.starts_with(name) {
            continue;
        }
        let after = &trimmed[name.len()..];
        if after.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_') {
            continue;
        }
        let name_at = at + 6 + (rest.len() - trimmed.len());
        let open = name_at + name.len() + after.find('{')?;
        let close = open + text[open..].find('}')?;
        return Some((name_at, open + 1..close));
    }
    None
}

/// The first place `name` stands as a whole word in `text`, outside comments.
fn word(text: &str, name: &str) -> Option<usize> {
    let code = code_mask(text);
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    text.match_indices(name).map(|(i, _)| i).find(|&i| {
        code[i]
            && !text[..i].chars().next_back().is_some_and(ident)
            && !text[i + name.len()..].chars().next().is_some_and(ident)
    })
}

/// For each byte, whether it is outside comments.
fn code_mask(text: &str) -> Vec<bool> {
    let mut mask = vec![true; text.len() + 1];
    for c in comments(text) {
        for m in &mut mask[c.start as usize..c.end as usize] {
            *m = false;
        }
    }
    mask
}

/// A comment of the GLSL: consecutive `//` lines are one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Comment {
    pub start: u32,
    pub end: u32,
    /// Its lines, without `//` (or `/*`, `*/`).
    pub lines: Vec<String>,
    /// Whether only white space comes before it on its first line.
    pub own_line: bool,
}

/// The comments of a GLSL text.
pub(crate) fn comments(text: &str) -> Vec<Comment> {
    let b = text.as_bytes();
    let mut out: Vec<Comment> = Vec::new();
    let mut i = 0;
    while i + 1 < b.len() {
        if b[i] == b'/' && b[i + 1] == b'/' {
            let end = text[i..].find(['\n', '\r']).map_or(text.len(), |n| i + n);
            let own_line = line_before(text, i).trim().is_empty();
            let body = text[i + 2..end].trim_end().to_owned();
            // A `//` line right under another own-line `//` comment continues it.
            let joins = own_line
                && out
                    .last()
                    .is_some_and(|c| c.own_line && only_space_newline(&text[c.end as usize..i]));
            if joins {
                let last = out.last_mut().expect("a comment");
                last.end = end as u32;
                last.lines.push(body);
            } else {
                out.push(Comment {
                    start: i as u32,
                    end: end as u32,
                    lines: vec![body],
                    own_line,
                });
            }
            i = end;
        } else if b[i] == b'/' && b[i + 1] == b'*' {
            let end = text[i + 2..]
                .find("*/")
                .map_or(text.len(), |n| i + 2 + n + 2);
            let own_line = line_before(text, i).trim().is_empty();
            let inner = text[i + 2..end.saturating_sub(2).max(i + 2)].to_owned();
            let mut lines: Vec<String> = inner
                .lines()
                .map(|l| {
                    let t = l.trim();
                    let t = t.strip_prefix('*').unwrap_or(t);
                    format!(" {}", t.trim()).trim_end().to_owned()
                })
                .collect();
            while lines.first().is_some_and(|l| l.trim().is_empty()) {
                lines.remove(0);
            }
            while lines.last().is_some_and(|l| l.trim().is_empty()) {
                lines.pop();
            }
            if !lines.is_empty() {
                out.push(Comment {
                    start: i as u32,
                    end: end as u32,
                    lines,
                    own_line,
                });
            }
            i = end;
        } else {
            i += 1;
        }
    }
    out
}

fn line_before(text: &str, at: usize) -> &str {
    let start = text[..at].rfind(['\n', '\r']).map_or(0, |k| k + 1);
    &text[start..at]
}

/// White space holding exactly one line break.
fn only_space_newline(s: &str) -> bool {
    s.trim().is_empty() && s.matches('\n').count() == 1
}

/// Whether `s` holds an empty line (two line breaks with only white space between).
fn has_blank_line(s: &str) -> bool {
    let mut breaks = 0;
    for c in s.chars() {
        match c {
            '\n' => {
                breaks += 1;
                if breaks >= 2 {
                    return true;
                }
            }
            c if c.is_whitespace() => {}
            _ => breaks = 0,
        }
    }
    false
}

/// The offset of the first declaration: after the `#` lines, `precision` statements and
/// comments that open the file.
fn first_code(text: &str) -> usize {
    let mask = code_mask(text);
    let mut i = 0;
    let b = text.as_bytes();
    while i < b.len() {
        if !mask[i] || b[i].is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let rest = &text[i..];
        if rest.starts_with('#') || rest.starts_with("precision") {
            i += rest.find([';', '\n']).map_or(rest.len(), |n| n + 1);
            continue;
        }
        return i;
    }
    text.len()
}

/// A GLSL source and its comments.
pub(crate) struct SourceText<'a> {
    pub text: &'a str,
    comments: Vec<Comment>,
    /// How many of the comments open the file (its description, for the output's header).
    header: usize,
}

impl<'a> SourceText<'a> {
    pub(crate) fn new(text: &'a str) -> SourceText<'a> {
        let comments = comments(text);
        let code = first_code(text);
        let mut header = comments
            .iter()
            .take_while(|c| c.end as usize <= code)
            .count();
        // A one-line comment right above the first declaration is that declaration's.
        if let Some(last) = header.checked_sub(1).map(|k| &comments[k]) {
            let between = &text[last.end as usize..code];
            if last.lines.len() == 1 && only_space_newline(between) {
                header -= 1;
            }
        }
        SourceText {
            text,
            comments,
            header,
        }
    }

    /// The comments that open the file.
    pub(crate) fn header(&self) -> Vec<String> {
        self.comments[..self.header]
            .iter()
            .flat_map(|c| c.lines.iter().cloned())
            .collect()
    }

    /// Whether an own-line comment ends on the line just above the one `at` is on (the
    /// comment is about what is declared there).
    pub(crate) fn commented(&self, at: u32) -> bool {
        self.comments[self.header..].iter().any(|c| {
            c.own_line
                && c.end <= at
                && only_space_newline(&self.text[c.end as usize..line_start(self.text, at)])
        })
    }
}

fn line_start(text: &str, at: u32) -> usize {
    text[..at as usize].rfind(['\n', '\r']).map_or(0, |k| k + 1)
}

/// Where a comment goes.
enum Place {
    Above(usize),
    After(usize),
    End,
}

/// The text of the lines with the author's comments (when `comments`) and blank lines put
/// back, and essl's notes above their lines.
pub(crate) fn assemble(lines: &[Line], sources: &[SourceText], comments: bool) -> String {
    let mut above: HashMap<usize, Vec<&Comment>> = HashMap::new();
    let mut after: HashMap<usize, Vec<&Comment>> = HashMap::new();
    let mut end: Vec<&Comment> = Vec::new();
    if comments {
        for (file, src) in sources.iter().enumerate() {
            for c in &src.comments[src.header..] {
                match place(lines, src, file, c) {
                    Place::Above(i) => above.entry(i).or_default().push(c),
                    Place::After(i) => after.entry(i).or_default().push(c),
                    Place::End => end.push(c),
                }
            }
        }
    }
    let mut out = String::new();
    // The end of the last statement at each indentation of the enclosing blocks: a blank
    // line of the source between it and the next statement is kept.
    let mut prev: Vec<Option<(usize, u32)>> = Vec::new();
    let mut last_blank = true;
    for (i, line) in lines.iter().enumerate() {
        let indent = "    ".repeat(line.indent);
        let before = if line.origin == Origin::Continued {
            None
        } else {
            prev.resize(prev.len().max(line.indent + 1), None);
            prev.truncate(line.indent + 1);
            prev[line.indent].take()
        };
        if let Origin::Source { file, start, end } = line.origin {
            let first = above
                .get(&i)
                .and_then(|cs| cs.first())
                .map_or(start, |c| c.start.min(start));
            if let Some((pf, pend)) = before {
                let src = sources.get(file).map_or("", |s| s.text);
                if pf == file
                    && line.indent > 0
                    && !last_blank
                    && pend <= first
                    && has_blank_line(src.get(pend as usize..first as usize).unwrap_or(""))
                {
                    out.push('\n');
                }
            }
            prev[line.indent] = Some((file, end));
        }
        for c in above.get(&i).into_iter().flatten() {
            for l in &c.lines {
                out.push_str(&format!("{indent}//{l}\n"));
            }
        }
        for note in &line.notes {
            for l in wrap(note, 96usize.saturating_sub(indent.len() + 3)) {
                out.push_str(&format!("{indent}// {l}\n"));
            }
        }
        out.push_str(&indent);
        out.push_str(&line.text);
        for c in after.get(&i).into_iter().flatten() {
            out.push_str(&format!(" //{}", c.lines.join(" ")));
        }
        out.push('\n');
        last_blank = line.text.is_empty() || line.text.ends_with('{');
    }
    if !end.is_empty() {
        out.push('\n');
        for c in end {
            for l in &c.lines {
                out.push_str(&format!("//{l}\n"));
            }
        }
    }
    out
}

/// Where comment `c` of source `file` goes among the lines.
fn place(lines: &[Line], src: &SourceText, file: usize, c: &Comment) -> Place {
    if !c.own_line {
        // At the end of the line written from the statement it follows on its line.
        let line_start = src.text[..c.start as usize]
            .rfind(['\n', '\r'])
            .map_or(0, |k| k + 1) as u32;
        let on_line = lines.iter().enumerate().filter(|(_, l)| {
            matches!(l.origin, Origin::Source { file: f, start, .. } if f == file && start >= line_start && start < c.start)
        });
        if let Some((i, _)) = on_line.max_by_key(|(_, l)| match l.origin {
            Origin::Source { start, .. } => start,
            _ => 0,
        }) {
            return Place::After(i);
        }
    }
    let next = lines.iter().enumerate().filter(|(_, l)| {
        matches!(l.origin, Origin::Source { file: f, start, .. } if f == file && start >= c.end)
    });
    match next.min_by_key(|(i, l)| match l.origin {
        Origin::Source { start, .. } => (start, *i),
        _ => (u32::MAX, *i),
    }) {
        Some((i, _)) => Place::Above(i),
        None => Place::End,
    }
}

/// Words of `text` in lines of at most `width` characters (a longer word stands alone).
pub(crate) fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split_whitespace() {
        let last = lines.last_mut().expect("one line");
        if !last.is_empty() && last.len() + 1 + word.len() > width.max(20) {
            lines.push(word.to_owned());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_are_found_and_joined() {
        let text = "#version 300 es\n// a\n// b\nfloat x; // c\n/* d\n * e */\nvoid main() {}\n";
        let cs = comments(text);
        assert_eq!(cs.len(), 3, "{cs:?}");
        assert_eq!(cs[0].lines, [" a", " b"]);
        assert!(cs[0].own_line);
        assert_eq!(cs[1].lines, [" c"]);
        assert!(!cs[1].own_line);
        assert_eq!(cs[2].lines, [" d", " e"]);
        assert_eq!(first_code(text), text.find("float").unwrap());
    }

    #[test]
    fn blank_lines() {
        assert!(has_blank_line(";\n\n    x"));
        assert!(has_blank_line(";\n  \n    x"));
        assert!(!has_blank_line(";\n    x"));
    }
}
