//! A shader's text assembled from pieces of other texts, and the map back to them.
//!
//! What essl compiles is not always a file as written: a shader inside an HTML page is a range
//! of the page; one inside a JavaScript template literal is the string JavaScript computes,
//! where `\n` in the file is one line break; `#include` puts other files in place; a preset
//! adds code a library prepends. An [`Assembly`] is that text with, for every byte, where it
//! came from, so that a diagnostic found in the text is reported at the file and line the
//! author wrote, and a fix edits the author's file, or is refused where it would land in text
//! that no file holds as written.

use std::sync::Arc;

use essl::diagnostic::Diagnostic;
use essl::source::{SourceFile, Span};

/// Where a run of the assembled text comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Bytes copied unchanged from a file, starting at `at`.
    Verbatim { file: u32, at: u32 },
    /// Text that stands for the file's raw bytes `raw_start..raw_end` without being them: the
    /// value of an escape sequence (`\n` for a line break, `\u{41}` for `A`, a line
    /// continuation for nothing).
    Cooked {
        file: u32,
        raw_start: u32,
        raw_end: u32,
    },
    /// Text no file holds (a library's prelude, a generated function); positions inside it are
    /// reported at `near` in `file`.
    Generated { file: u32, near: u32 },
}

/// One run of the assembled text and its origin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Piece {
    start: u32,
    end: u32,
    kind: Kind,
}

/// What a fix would edit that no file holds as written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unfixable {
    /// Text an escape sequence of a string or template literal stands for.
    Escape,
    /// Text added by a preset or an assembler.
    Generated,
    /// Text in another file than the diagnostic's.
    OtherFile,
}

impl Unfixable {
    /// Why, in the words of a note.
    pub fn reason(self) -> &'static str {
        match self {
            Unfixable::Escape => {
                "the fix is not applied: it would edit text that a `\\` escape of the string \
                 stands for"
            }
            Unfixable::Generated => {
                "the fix is not applied: it would edit code that is added to the shader, not \
                 written in the file"
            }
            Unfixable::OtherFile => "the fix is not applied: its edits fall in more than one file",
        }
    }
}

/// A text assembled from pieces of files, with the map back to them.
#[derive(Clone, Debug, Default)]
pub struct Assembly {
    text: String,
    files: Vec<Arc<SourceFile>>,
    pieces: Vec<Piece>,
}

impl Assembly {
    /// The whole of `file`, as it is.
    pub fn whole(file: Arc<SourceFile>) -> Assembly {
        let len = file.text().len();
        let mut a = Assembly::default();
        let f = a.file_index(&file);
        a.verbatim(f, 0..len);
        a
    }

    /// The bytes `range` of `file`, as they are (a shader inside an HTML page).
    pub fn range(file: Arc<SourceFile>, range: std::ops::Range<usize>) -> Assembly {
        let mut a = Assembly::default();
        let f = a.file_index(&file);
        a.verbatim(f, range);
        a
    }

    /// The assembled text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The files the text comes from, in the order they were first used: the first is the one
    /// the text starts in (the shader's own file, or its host).
    pub fn files(&self) -> &[Arc<SourceFile>] {
        &self.files
    }

    /// The index of `file` among [`Assembly::files`], added if it is new.
    pub fn file_index(&mut self, file: &Arc<SourceFile>) -> u32 {
        match self.files.iter().position(|f| Arc::ptr_eq(f, file)) {
            Some(i) => i as u32,
            None => {
                self.files.push(file.clone());
                (self.files.len() - 1) as u32
            }
        }
    }

    fn push(&mut self, text: &str, kind: Kind) {
        if text.is_empty() && !matches!(kind, Kind::Cooked { .. }) {
            return;
        }
        let start = self.text.len() as u32;
        self.text.push_str(text);
        let end = self.text.len() as u32;
        // A verbatim run that continues the previous one extends it.
        if let (
            Some(Piece {
                end: last_end,
                kind: Kind::Verbatim { file, at },
                start: last_start,
            }),
            Kind::Verbatim {
                file: new_file,
                at: new_at,
            },
        ) = (self.pieces.last_mut(), kind)
        {
            if *file == new_file && *at + (*last_end - *last_start) == new_at {
                *last_end = end;
                return;
            }
        }
        self.pieces.push(Piece { start, end, kind });
    }

    /// Appends the bytes `range` of file `file` (an index from [`Assembly::file_index`]).
    pub fn verbatim(&mut self, file: u32, range: std::ops::Range<usize>) {
        let text = self.files[file as usize].text()[range.clone()].to_string();
        self.push(
            &text,
            Kind::Verbatim {
                file,
                at: range.start as u32,
            },
        );
    }

    /// Appends `cooked`, the value of the raw bytes `raw` of file `file` (an escape sequence).
    pub fn cooked(&mut self, file: u32, raw: std::ops::Range<usize>, cooked: &str) {
        self.push(
            cooked,
            Kind::Cooked {
                file,
                raw_start: raw.start as u32,
                raw_end: raw.end as u32,
            },
        );
    }

    /// Appends text that no file holds; what is found in it is reported at byte `near` of
    /// file `file`.
    pub fn generated(&mut self, text: &str, file: u32, near: usize) {
        self.push(
            text,
            Kind::Generated {
                file,
                near: near as u32,
            },
        );
    }

    /// Appends the bytes `range` of another assembly, with their origins.
    pub fn extend_from(&mut self, other: &Assembly, range: std::ops::Range<usize>) {
        let (lo, hi) = (range.start as u32, range.end as u32);
        let first = other.piece_at(lo).unwrap_or(other.pieces.len());
        for p in &other.pieces[first..] {
            if p.start >= hi && !(p.start == hi && p.end == hi && lo == hi) {
                break;
            }
            let (s, e) = (p.start.max(lo), p.end.min(hi));
            if s > e {
                continue;
            }
            let text = &other.text[s as usize..e as usize];
            let kind = match p.kind {
                Kind::Verbatim { file, at } => Kind::Verbatim {
                    file: self.file_index(&other.files[file as usize]),
                    at: at + (s - p.start),
                },
                Kind::Cooked {
                    file,
                    raw_start,
                    raw_end,
                } => Kind::Cooked {
                    file: self.file_index(&other.files[file as usize]),
                    raw_start,
                    raw_end,
                },
                Kind::Generated { file, near } => Kind::Generated {
                    file: self.file_index(&other.files[file as usize]),
                    near,
                },
            };
            if s == e && !matches!(kind, Kind::Cooked { .. }) {
                continue;
            }
            self.push(text, kind);
        }
    }

    /// The index of the piece holding byte `offset` (the last piece for the end of the text).
    fn piece_at(&self, offset: u32) -> Option<usize> {
        if self.pieces.is_empty() {
            return None;
        }
        // The first piece that ends past `offset`; empty pieces (a line continuation) at
        // `offset` come before the text that follows them.
        let i = self.pieces.partition_point(|p| p.end <= offset);
        Some(i.min(self.pieces.len() - 1))
    }

    /// Where byte `offset` of the text comes from: a file and a byte in it, and whether the
    /// byte is there as written.
    fn locate(&self, offset: u32, end_of_span: bool) -> Option<(u32, u32, Kind)> {
        let i = self.piece_at(offset)?;
        // The end of a span is the end of the byte before it.
        let i = if end_of_span && i > 0 && self.pieces[i].start == offset {
            i - 1
        } else {
            i
        };
        let p = self.pieces[i];
        let at = match p.kind {
            Kind::Verbatim { file, at } => {
                (file, at + offset.clamp(p.start, p.end) - p.start, p.kind)
            }
            Kind::Cooked {
                file,
                raw_start,
                raw_end,
            } => {
                let at = if end_of_span || offset > p.start {
                    raw_end
                } else {
                    raw_start
                };
                (file, at, p.kind)
            }
            Kind::Generated { file, near } => (file, near, p.kind),
        };
        Some(at)
    }

    /// A span of the text as a span of one file, if both ends fall in the same file (the end
    /// is moved to the start's piece otherwise).
    pub fn map_span(&self, span: Span) -> Option<(u32, Span)> {
        let (file, start, kind) = self.locate(span.start, false)?;
        let end = match self.locate(span.end.max(span.start), !span.is_empty()) {
            Some((f, end, _)) if f == file && end >= start && !generated(kind) => end,
            _ => match kind {
                Kind::Verbatim { at, .. } => {
                    let i = self.piece_at(span.start)?;
                    let p = self.pieces[i];
                    (at + p.end - p.start).max(start)
                }
                _ => start,
            },
        };
        Some((file, Span::new(start, end)))
    }

    /// Where byte `offset` of `file` is in the text, if the text holds it as written: the
    /// inverse of the map, for an editor asking about a position in the host file.
    pub fn offset_in_text(&self, file: &Arc<SourceFile>, offset: u32) -> Option<u32> {
        let f = self.files.iter().position(|x| Arc::ptr_eq(x, file))? as u32;
        self.pieces.iter().find_map(|p| match p.kind {
            Kind::Verbatim { file, at }
                if file == f && at <= offset && offset <= at + (p.end - p.start) =>
            {
                Some(p.start + offset - at)
            }
            Kind::Cooked {
                file,
                raw_start,
                raw_end,
            } if file == f && raw_start <= offset && offset < raw_end => Some(p.start),
            _ => None,
        })
    }

    /// Whether byte `offset` of the text is text no file holds (a library's prelude, a join's
    /// separator, a chunk's assumed `#version`).
    pub fn is_generated(&self, offset: u32) -> bool {
        self.piece_at(offset)
            .is_some_and(|i| generated(self.pieces[i].kind))
    }

    /// Whether the text is exactly one file's text from its start: no map is needed.
    pub fn is_whole_file(&self) -> bool {
        self.files.len() == 1
            && self.text.len() == self.files[0].text().len()
            && matches!(
                self.pieces.as_slice(),
                [Piece {
                    kind: Kind::Verbatim { at: 0, .. },
                    ..
                }]
            )
    }

    /// Moves a diagnostic found in the text onto the file its primary span falls in: that
    /// file's index and the diagnostic with every span in that file. A secondary label in
    /// another file becomes a note naming its place; a fix that would edit text no file holds
    /// as written, or another file, is dropped, with a note that says why.
    pub fn map_diagnostic(&self, mut d: Diagnostic) -> (u32, Diagnostic) {
        let Some((file, span)) = self.map_span(d.span) else {
            return (0, d);
        };
        let generated_at = self.piece_at(d.span.start).map(|i| self.pieces[i].kind);
        if let Some(Kind::Generated { .. }) = generated_at {
            let line = line_of(&self.text, d.span.start as usize);
            d.notes.push(format!(
                "in code added to the shader, not written here: `{}`",
                line.trim()
            ));
        }
        d.span = span;
        let mut notes = Vec::new();
        d.secondary.retain_mut(|l| match self.map_span(l.span) {
            Some((f, s)) if f == file => {
                l.span = s;
                true
            }
            Some((f, s)) => {
                let other = &self.files[f as usize];
                let lc = other.line_col(s.start);
                notes.push(format!(
                    "{}: {}:{}:{}",
                    l.message,
                    other.name(),
                    lc.line,
                    lc.column
                ));
                false
            }
            None => false,
        });
        d.notes.extend(notes);
        if let Some(fix) = &d.fix {
            let mut why = None;
            let mut spans = Vec::with_capacity(fix.edits.len());
            for e in &fix.edits {
                match self.map_edit(e.span, file) {
                    Ok(s) => spans.push(s),
                    Err(w) => {
                        why = Some(w);
                        break;
                    }
                }
            }
            match why {
                None => {
                    if let Some(fix) = &mut d.fix {
                        for (e, s) in fix.edits.iter_mut().zip(spans) {
                            e.span = s;
                        }
                    }
                }
                Some(w) => {
                    d.fix = None;
                    d.notes.push(w.reason().to_string());
                }
            }
        }
        (file, d)
    }

    /// An edit's span in `file`, if every byte it replaces (or the point it inserts at) is
    /// there as written.
    fn map_edit(&self, span: Span, file: u32) -> Result<Span, Unfixable> {
        let i = self.piece_at(span.start).ok_or(Unfixable::Generated)?;
        let p = self.pieces[i];
        // An insertion at the start of a piece may go at the end of the one before, if that
        // one is verbatim.
        let p = if span.is_empty() && span.start == p.start && !is_verbatim(p.kind) && i > 0 {
            self.pieces[i - 1]
        } else {
            p
        };
        match p.kind {
            Kind::Verbatim { file: f, at } if span.end <= p.end && span.start >= p.start => {
                if f != file {
                    return Err(Unfixable::OtherFile);
                }
                Ok(Span::new(
                    at + span.start - p.start,
                    at + span.end - p.start,
                ))
            }
            Kind::Verbatim { .. } => Err(Unfixable::Escape),
            Kind::Cooked { .. } => Err(Unfixable::Escape),
            Kind::Generated { .. } => Err(Unfixable::Generated),
        }
    }
}

fn is_verbatim(kind: Kind) -> bool {
    matches!(kind, Kind::Verbatim { .. })
}

fn generated(kind: Kind) -> bool {
    matches!(kind, Kind::Generated { .. })
}

/// The line of `text` that holds byte `at`.
fn line_of(text: &str, at: usize) -> &str {
    let at = at.min(text.len());
    let start = text[..at].rfind('\n').map_or(0, |n| n + 1);
    let end = text[at..].find('\n').map_or(text.len(), |n| at + n);
    &text[start..end]
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic::Fix;
    use essl::diagnostic_code::Code;

    fn file(name: &str, text: &str) -> Arc<SourceFile> {
        Arc::new(SourceFile::new(name, text))
    }

    #[test]
    fn a_range_of_a_host_maps_by_its_offset() {
        let page = file("p.html", "<script>void main() {}</script>");
        let a = Assembly::range(page.clone(), 8..22);
        assert_eq!(a.text(), "void main() {}");
        assert_eq!(a.map_span(Span::new(5, 9)), Some((0, Span::new(13, 17))));
        assert_eq!(a.offset_in_text(&page, 13), Some(5));
        assert_eq!(a.offset_in_text(&page, 2), None);
        assert!(!a.is_whole_file());
        assert!(Assembly::whole(page).is_whole_file());
    }

    #[test]
    fn escapes_map_to_their_raw_text_and_refuse_fixes() {
        // `a\nb` in a file: the text is `a`, a line break, `b`.
        let js = file("a.js", "x = 'a\\nb';");
        let mut a = Assembly::default();
        let f = a.file_index(&js);
        a.verbatim(f, 5..6);
        a.cooked(f, 6..8, "\n");
        a.verbatim(f, 8..9);
        assert_eq!(a.text(), "a\nb");
        assert_eq!(a.map_span(Span::new(2, 3)), Some((0, Span::new(8, 9))));
        assert_eq!(a.map_span(Span::new(0, 3)), Some((0, Span::new(5, 9))));
        let d = Diagnostic::error(Code::MissingSemicolon, "m", Span::new(2, 3))
            .with_fix(Fix::certain("insert `;`", Span::new(3, 3), ";"));
        let (_, moved) = a.map_diagnostic(d);
        assert_eq!(moved.fix.unwrap().edits[0].span, Span::new(9, 9));
        let d = Diagnostic::error(Code::MissingSemicolon, "m", Span::new(0, 1))
            .with_fix(Fix::certain("replace", Span::new(1, 2), " "));
        let (_, moved) = a.map_diagnostic(d);
        assert!(moved.fix.is_none());
        assert!(moved.notes[0].contains("escape"), "{:?}", moved.notes);
    }

    #[test]
    fn pieces_of_other_assemblies_keep_their_origins() {
        let main = file("a.frag", "A\n#include \"b\"\nC\n");
        let inc = file("b", "B\n");
        let base = Assembly::whole(main.clone());
        let mut a = Assembly::default();
        a.extend_from(&base, 0..2);
        a.extend_from(&Assembly::whole(inc.clone()), 0..2);
        a.extend_from(&base, 15..17);
        assert_eq!(a.text(), "A\nB\nC\n");
        assert_eq!(a.files().len(), 2);
        assert_eq!(a.map_span(Span::new(2, 3)), Some((1, Span::new(0, 1))));
        assert_eq!(a.map_span(Span::new(4, 5)), Some((0, Span::new(15, 16))));
        let d = Diagnostic::error(Code::MissingSemicolon, "m", Span::new(4, 5))
            .with_secondary(Span::new(2, 3), "declared here");
        let (f, moved) = a.map_diagnostic(d);
        assert_eq!(f, 0);
        assert!(moved.secondary.is_empty());
        assert_eq!(moved.notes, ["declared here: b:1:1"]);
    }

    #[test]
    fn generated_text_reports_near_its_anchor() {
        let main = file("a.frag", "void main() {}\n");
        let mut a = Assembly::default();
        let f = a.file_index(&main);
        a.generated("uniform mat4 m;\n", f, 0);
        a.verbatim(f, 0..15);
        let d = Diagnostic::error(Code::MissingSemicolon, "m", Span::new(8, 12));
        let (_, moved) = a.map_diagnostic(d);
        assert_eq!(moved.span, Span::new(0, 0));
        assert!(moved.notes[0].contains("uniform mat4 m;"));
        assert_eq!(a.map_span(Span::new(16, 20)), Some((0, Span::new(0, 4))));
    }
}
