//! `#include "FILE"` for `essl lint -I DIR` (and essl.toml's `include`): GLSL ES has no
//! `#include`, so it is opt-in. The included text is put in place of the directive (searched
//! in the including file's folder, then each include folder, in order), the whole is compiled
//! as one shader, and every diagnostic is moved back onto the file its span falls in, so that
//! an error inside an included file is reported at its own line.

use std::path::{Path, PathBuf};

use essl::diagnostic::Diagnostic;
use essl::source::{SourceFile, Span};

use crate::files::read_source;

/// How deep includes may nest.
pub const MAX_DEPTH: usize = 16;

/// A run of the expanded text that comes from one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Segment {
    /// Where it starts and ends in the expanded text.
    start: usize,
    end: usize,
    /// Which file (0: the one compiled).
    file: usize,
    /// Where it starts in that file.
    at: usize,
}

/// A shader with its includes put in place.
#[derive(Debug)]
pub(crate) struct Expanded {
    /// The text to compile.
    pub text: String,
    /// The files it is made of; the first is the shader itself.
    pub files: Vec<SourceFile>,
    segments: Vec<Segment>,
}

/// The `FILE` of an `#include "FILE"` (or `<FILE>`) line, if the line is one.
fn directive(line: &str) -> Option<&str> {
    let rest = line.trim_start().strip_prefix('#')?.trim_start();
    let rest = rest.strip_prefix("include")?.trim();
    let (open, close) = match rest.chars().next()? {
        '"' => ('"', '"'),
        '<' => ('<', '>'),
        _ => return None,
    };
    let inner = rest.strip_prefix(open)?;
    Some(&inner[..inner.find(close)?])
}

/// Whether `text` has an `#include` line.
pub(crate) fn has_include(text: &str) -> bool {
    text.contains("include") && text.lines().any(|l| directive(l).is_some())
}

struct Expander<'a> {
    dirs: &'a [PathBuf],
    out: String,
    files: Vec<SourceFile>,
    segments: Vec<Segment>,
    stack: Vec<PathBuf>,
}

impl Expander<'_> {
    fn file(&mut self, index: usize, dir: &Path) -> Result<(), String> {
        let text = self.files[index].text().to_string();
        let mut from = 0;
        let mut pos = 0;
        for line in text.split_inclusive('\n') {
            let line_start = pos;
            pos += line.len();
            let Some(name) = directive(line) else {
                continue;
            };
            self.copy(index, &text, from, line_start);
            from = pos;
            let path = std::iter::once(dir.to_path_buf())
                .chain(self.dirs.iter().cloned())
                .map(|d| d.join(name))
                .find(|p| p.is_file())
                .ok_or_else(|| {
                    let line_no = text[..line_start].matches('\n').count() + 1;
                    format!(
                        "line {line_no}: `#include \"{name}\"`: no such file in `{}` or the \
                         include folders (-I)",
                        dir.display()
                    )
                })?;
            let key = std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone());
            if self.stack.contains(&key) {
                return Err(format!("`{}` includes itself", path.display()));
            }
            if self.stack.len() >= MAX_DEPTH {
                return Err(format!("includes nest deeper than {MAX_DEPTH}"));
            }
            let body = read_source(&path).map_err(|e| format!("`{}`: {e}", path.display()))?;
            self.files
                .push(SourceFile::new(path.display().to_string(), body));
            self.stack.push(key);
            let sub = self.files.len() - 1;
            let sub_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
            self.file(sub, &sub_dir)?;
            self.stack.pop();
            if !self.out.ends_with('\n') {
                self.out.push('\n');
            }
        }
        self.copy(index, &text, from, text.len());
        Ok(())
    }

    fn copy(&mut self, file: usize, text: &str, from: usize, to: usize) {
        if from < to {
            let start = self.out.len();
            self.out.push_str(&text[from..to]);
            self.segments.push(Segment {
                start,
                end: self.out.len(),
                file,
                at: from,
            });
        }
    }
}

/// Expands the includes of `main` (searched in its folder, then `dirs`); the error names the
/// directive that could not be followed.
pub(crate) fn expand(main: SourceFile, path: &Path, dirs: &[PathBuf]) -> Result<Expanded, String> {
    let mut e = Expander {
        dirs,
        out: String::new(),
        files: vec![main],
        segments: Vec::new(),
        stack: vec![std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())],
    };
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    e.file(0, &dir)?;
    Ok(Expanded {
        text: e.out,
        files: e.files,
        segments: e.segments,
    })
}

impl Expanded {
    /// The segment an offset of the expanded text falls in.
    fn segment(&self, offset: u32) -> Option<Segment> {
        let o = offset as usize;
        self.segments
            .iter()
            .copied()
            .find(|s| s.start <= o && o < s.end)
            .or_else(|| self.segments.last().copied().filter(|s| o >= s.end))
    }

    /// Moves `d` onto the file its span starts in: that file's index and the diagnostic with
    /// its spans in that file (labels and fix edits in another file are dropped).
    fn relocate(&self, mut d: Diagnostic) -> (usize, Diagnostic) {
        let Some(seg) = self.segment(d.span.start) else {
            return (0, d);
        };
        let map = |s: Span| -> Option<Span> {
            let here = self.segment(s.start)?;
            (here == seg).then(|| {
                let end = (s.end as usize).min(seg.end);
                let start = s.start as usize;
                Span::new(
                    (start - seg.start + seg.at) as u32,
                    (end.max(start) - seg.start + seg.at) as u32,
                )
            })
        };
        d.span = map(d.span).unwrap_or(d.span);
        d.secondary.retain_mut(|l| match map(l.span) {
            Some(s) => {
                l.span = s;
                true
            }
            None => false,
        });
        if let Some(fix) = &mut d.fix {
            let mapped: Option<Vec<Span>> = fix.edits.iter().map(|e| map(e.span)).collect();
            match mapped {
                Some(spans) => fix
                    .edits
                    .iter_mut()
                    .zip(spans)
                    .for_each(|(e, s)| e.span = s),
                None => d.fix = None,
            }
        }
        (seg.file, d)
    }

    /// Splits diagnostics of the expanded text into the shader's own and, per included file,
    /// theirs.
    pub(crate) fn split(
        &self,
        diagnostics: Vec<Diagnostic>,
    ) -> (Vec<Diagnostic>, Vec<(SourceFile, Vec<Diagnostic>)>) {
        let mut mine = Vec::new();
        let mut theirs: Vec<(usize, Vec<Diagnostic>)> = Vec::new();
        for d in diagnostics {
            match self.relocate(d) {
                (0, d) => mine.push(d),
                (f, d) => match theirs.iter_mut().find(|(g, _)| *g == f) {
                    Some((_, list)) => list.push(d),
                    None => theirs.push((f, vec![d])),
                },
            }
        }
        let theirs = theirs
            .into_iter()
            .map(|(f, list)| (self.files[f].clone(), list))
            .collect();
        (mine, theirs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic_code::Code;

    #[test]
    fn includes_expand_and_diagnostics_go_home() {
        let dir = tempfile::tempdir().unwrap();
        let inc = dir.path().join("inc");
        std::fs::create_dir_all(&inc).unwrap();
        std::fs::write(inc.join("light.glsl"), "float light() {\n  return 1.0\n}").unwrap();
        let main_path = dir.path().join("a.frag");
        let main = "#version 300 es\n#include \"light.glsl\"\nvoid main() {}\n";
        let e = expand(
            SourceFile::new("a.frag", main),
            &main_path,
            std::slice::from_ref(&inc),
        )
        .unwrap();
        assert_eq!(
            e.text,
            "#version 300 es\nfloat light() {\n  return 1.0\n}\nvoid main() {}\n"
        );
        let at = e.text.find("1.0").unwrap() as u32;
        let tail = e.text.find("void").unwrap() as u32;
        let (mine, theirs) = e.split(vec![
            Diagnostic::error(Code::MissingSemicolon, "m", Span::new(at, at + 3)),
            Diagnostic::error(Code::MissingSemicolon, "m", Span::new(tail, tail + 4)),
        ]);
        assert_eq!(
            mine[0].span,
            Span::new(
                main.find("void").unwrap() as u32,
                main.find("void").unwrap() as u32 + 4
            )
        );
        assert_eq!(theirs.len(), 1);
        let (file, ds) = &theirs[0];
        assert!(file.name().ends_with("light.glsl"));
        assert_eq!(file.slice(ds[0].span), "1.0");
        let missing = expand(SourceFile::new("a.frag", main), &main_path, &[]).unwrap_err();
        assert!(
            missing.contains("line 2: `#include \"light.glsl\"`: no such file"),
            "{missing}"
        );
        std::fs::write(inc.join("light.glsl"), "#include \"light.glsl\"\n").unwrap();
        let looped = expand(SourceFile::new("a.frag", main), &main_path, &[inc]).unwrap_err();
        assert!(looped.contains("includes itself"), "{looped}");
    }
}
