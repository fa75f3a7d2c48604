//! The user's original text, spans into it, and line/column lookup (columns in characters).

use std::fmt;

/// A byte range into the user's original source text.
///
/// Every token, syntax node, diagnostic and naga IR span refers to the original text, so
/// messages always point where the user looks, whatever the front end rewrote on the way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

impl Span {
    /// A span from `start` to `end` (bytes).
    pub fn new(start: u32, end: u32) -> Span {
        Span { start, end }
    }

    /// An empty span at `offset`.
    pub fn empty(offset: u32) -> Span {
        Span {
            start: offset,
            end: offset,
        }
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// The empty span at the end of this one.
    pub fn end_point(self) -> Span {
        Span::empty(self.end)
    }

    /// Length in bytes.
    pub fn len(self) -> u32 {
        self.end - self.start
    }

    /// Whether the span is empty.
    pub fn is_empty(self) -> bool {
        self.start == self.end
    }

    /// The byte range, for slicing.
    pub fn range(self) -> std::ops::Range<usize> {
        self.start as usize..self.end as usize
    }
}

impl From<Span> for naga::Span {
    fn from(s: Span) -> naga::Span {
        naga::Span::new(s.start, s.end)
    }
}

impl From<naga::Span> for Span {
    fn from(s: naga::Span) -> Span {
        match s.to_range() {
            Some(r) => Span::new(r.start as u32, r.end as u32),
            None => Span::default(),
        }
    }
}

/// A 1-based line and column, the column counted in characters (not bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct LineCol {
    /// 1-based line number.
    pub line: u32,
    /// 1-based column, in Unicode scalar values.
    pub column: u32,
}

impl fmt::Display for LineCol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// A named source text with a line index.
#[derive(Clone, Debug)]
pub struct SourceFile {
    name: String,
    text: String,
    /// Where each line starts, found on first use: a shader that compiles cleanly is never
    /// asked for a line.
    line_starts: std::sync::OnceLock<Vec<u32>>,
    /// Whether the text is ASCII: then a column is a byte distance, found without counting
    /// characters (which would make a diagnostic on a long line cost the line's length).
    ascii: bool,
}

impl SourceFile {
    /// Wraps a source text. Line breaks are `\n`, `\r\n` or a lone `\r`, as GLSL counts them.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> SourceFile {
        let text = text.into();
        SourceFile {
            name: name.into(),
            ascii: text.is_ascii(),
            text,
            line_starts: std::sync::OnceLock::new(),
        }
    }

    /// Where each line starts.
    fn line_starts(&self) -> &[u32] {
        self.line_starts.get_or_init(|| {
            let bytes = self.text.as_bytes();
            // About one line per 24 bytes of a shader: one allocation for most files.
            let mut line_starts = Vec::with_capacity(bytes.len() / 24 + 2);
            line_starts.push(0u32);
            // Each line break found with `memchr2` (a vectorised search), not byte by byte.
            let mut i = 0;
            while let Some(at) = memchr::memchr2(b'\n', b'\r', &bytes[i..]) {
                let at = i + at;
                i = if bytes[at] == b'\r' && bytes.get(at + 1) == Some(&b'\n') {
                    at + 2
                } else {
                    at + 1
                };
                line_starts.push(i as u32);
            }
            line_starts
        })
    }

    /// The file's name as given.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The whole text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The text a span covers (empty if the span is out of range).
    pub fn slice(&self, span: Span) -> &str {
        self.text.get(span.range()).unwrap_or("")
    }

    /// Number of lines (a trailing line break starts a last, empty line).
    pub fn line_count(&self) -> usize {
        self.line_starts().len()
    }

    /// 0-based line index of a byte offset.
    pub fn line_index(&self, offset: u32) -> usize {
        match self.line_starts().binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i - 1,
        }
    }

    /// 1-based line of a byte offset.
    pub fn line_of(&self, offset: u32) -> u32 {
        self.line_index(offset) as u32 + 1
    }

    /// Byte offset where a 0-based line starts.
    pub fn line_start(&self, line_index: usize) -> u32 {
        self.line_starts()
            .get(line_index)
            .copied()
            .unwrap_or(self.text.len() as u32)
    }

    /// The byte range of a 0-based line, without its line break.
    pub fn line_range(&self, line_index: usize) -> std::ops::Range<usize> {
        let start = self.line_start(line_index) as usize;
        let mut end = self.line_start(line_index + 1) as usize;
        let bytes = self.text.as_bytes();
        while end > start && matches!(bytes[end - 1], b'\n' | b'\r') {
            end -= 1;
        }
        start..end
    }

    /// The text of a 0-based line, without its line break.
    pub fn line_text(&self, line_index: usize) -> &str {
        &self.text[self.line_range(line_index)]
    }

    /// 1-based line and character column of a byte offset (clamped to the text).
    pub fn line_col(&self, offset: u32) -> LineCol {
        let offset = (offset as usize).min(self.text.len());
        let mut offset = offset;
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.line_index(offset as u32);
        let start = self.line_starts()[line] as usize;
        let column = if self.ascii {
            (offset - start) as u32 + 1
        } else {
            self.text[start..offset].chars().count() as u32 + 1
        };
        LineCol {
            line: line as u32 + 1,
            column,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SourceFile;

    #[test]
    fn lines_end_at_lf_crlf_and_a_lone_cr() {
        let f = SourceFile::new("t", "a\nb\r\nc\rd\r\r\n");
        let starts: Vec<u32> = (0..f.line_count()).map(|l| f.line_start(l)).collect();
        assert_eq!(starts, [0, 2, 5, 7, 9, 11]);
        assert_eq!(f.line_text(1), "b");
        assert_eq!(f.line_of(6), 3);
        let empty = SourceFile::new("t", "");
        assert_eq!(empty.line_count(), 1);
    }
}
