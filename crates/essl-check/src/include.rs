//! `#include "FILE"` (or `<FILE>`), where a project asks for it: each directive is replaced by
//! the file it names (searched in the including file's folder, then in each include folder, in
//! order), recursively, and the result is an [`Assembly`] that knows which file every byte
//! came from, so that a diagnostic in an included file is reported at its own line and a fix
//! edits that file.
//!
//! GLSL ES has no `#include`: without include folders (`-I`, essl.toml's `include`) the
//! directive stays in the text and the front end reports it, as a browser would.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::diagnostic::{Diagnostic, Severity};
use essl::source::{SourceFile, Span};

use crate::assembly::Assembly;
use crate::codes::CheckCode;
use crate::read::{Files, ReadError};

/// How deep includes may nest.
pub const MAX_DEPTH: usize = 16;

/// A diagnostic in one file.
pub type InFile = (Arc<SourceFile>, Diagnostic);

/// The name of an `#include "FILE"` (or `<FILE>`) line and its byte range in the line, if the
/// line is one.
fn directive(line: &str) -> Option<(&str, std::ops::Range<usize>)> {
    let body = line.trim_start();
    let lead = line.len() - body.len();
    let rest = body.strip_prefix('#')?.trim_start();
    let rest = rest.strip_prefix("include")?;
    if !rest.starts_with([' ', '\t', '"', '<']) {
        return None;
    }
    let rest = rest.trim();
    let close = match rest.chars().next()? {
        '"' => '"',
        '<' => '>',
        _ => return None,
    };
    let inner = &rest[1..];
    let name = &inner[..inner.find(close)?];
    let end = line.trim_end().len();
    Some((name, lead..end))
}

/// Whether `text` has an `#include` line.
pub fn has_include(text: &str) -> bool {
    text.contains("include") && text.lines().any(|l| directive(l).is_some())
}

struct Expander<'a> {
    dirs: &'a [PathBuf],
    files: &'a Files,
    out: Assembly,
    /// The files being expanded, outermost first (canonical paths).
    stack: Vec<PathBuf>,
    errors: Vec<InFile>,
}

impl Expander<'_> {
    /// Copies `src` (the text of the file at the top of the stack, in folder `dir`) into the
    /// output with its includes in place.
    fn expand(&mut self, src: &Assembly, dir: &Path) {
        let text = src.text();
        let (mut from, mut pos) = (0, 0);
        for line in text.split_inclusive('\n') {
            let line_start = pos;
            pos += line.len();
            let Some((name, range)) = directive(line) else {
                continue;
            };
            self.out.extend_from(src, from..line_start);
            from = pos;
            let span = Span::new(
                (line_start + range.start) as u32,
                (line_start + range.end) as u32,
            );
            let report = |code: CheckCode, message: String| {
                let (f, span) = src.map_span(span).unwrap_or((0, span));
                let d = Diagnostic::new(Severity::Error, code.as_str(), message, span);
                (src.files()[f as usize].clone(), d)
            };
            let Some(path) = std::iter::once(dir)
                .chain(self.dirs.iter().map(PathBuf::as_path))
                .map(|d| d.join(name))
                .find(|p| self.files.exists(p))
            else {
                let mut searched = format!("`{}` (the including file's folder)", display_dir(dir));
                for d in self.dirs {
                    searched.push_str(&format!(", `{}`", display_dir(d)));
                }
                let (f, d) = report(
                    CheckCode::IncludeNotFound,
                    format!("cannot find `{name}`: searched {searched}"),
                );
                let d = d.with_help(
                    "add the folder that holds it with `-I DIR`, or to `include = [...]` in \
                     essl.toml",
                );
                self.errors.push((f, d));
                continue;
            };
            let key = std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone());
            if let Some(at) = self.stack.iter().position(|p| *p == key) {
                let chain: Vec<String> = self.stack[at..]
                    .iter()
                    .chain(std::iter::once(&key))
                    .map(|p| format!("`{}`", file_name(p)))
                    .collect();
                let e = report(
                    CheckCode::IncludeCycle,
                    format!("`{name}` includes itself: {}", chain.join(" → ")),
                );
                self.errors.push(e);
                continue;
            }
            if self.stack.len() > MAX_DEPTH {
                let e = report(
                    CheckCode::IncludeTooDeep,
                    format!("includes nest deeper than {MAX_DEPTH} files here"),
                );
                self.errors.push(e);
                continue;
            }
            let file = match self.files.read(&path) {
                Ok(f) => f,
                Err(e) => {
                    let e = report(CheckCode::IncludeUnreadable, unreadable(name, &e));
                    self.errors.push(e);
                    continue;
                }
            };
            self.stack.push(key);
            let sub_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
            self.expand(&Assembly::whole(file), &sub_dir);
            self.stack.pop();
            if !self.out.text().ends_with('\n') && !self.out.text().is_empty() {
                let near = (line_start + range.end).min(text.len());
                let (f, s) = src.map_span(Span::empty(near as u32)).unwrap_or_default();
                let file = src.files()[f as usize].clone();
                let f = self.out.file_index(&file);
                self.out.generated("\n", f, s.start as usize);
            }
        }
        self.out.extend_from(src, from..text.len());
    }
}

fn unreadable(name: &str, e: &ReadError) -> String {
    format!("`{name}` cannot be read: {e}")
}

fn display_dir(d: &Path) -> String {
    if d.as_os_str().is_empty() {
        ".".to_string()
    } else {
        d.display().to_string()
    }
}

fn file_name(p: &Path) -> String {
    p.file_name().map_or_else(
        || p.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// Expands the includes of `src`, the text of the file at `path` (searched in its folder, then
/// `dirs`), reading through `files`. The errors are each a diagnostic at its directive, in the
/// file that holds the directive.
pub fn expand(
    src: &Assembly,
    path: &Path,
    dirs: &[PathBuf],
    files: &Files,
) -> Result<Assembly, Vec<InFile>> {
    let mut e = Expander {
        dirs,
        files,
        out: Assembly::default(),
        stack: vec![std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())],
        errors: Vec::new(),
    };
    // The shader's own file comes first among the assembly's files, even where it starts
    // with an `#include`.
    if let Some(first) = src.files().first() {
        e.out.file_index(first);
    }
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    e.expand(src, &dir);
    if e.errors.is_empty() {
        Ok(e.out)
    } else {
        Err(e.errors)
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
        let files = Files::disk();
        let src = Assembly::whole(Arc::new(SourceFile::new("a.frag", main)));
        let e = expand(&src, &main_path, std::slice::from_ref(&inc), &files).unwrap();
        assert_eq!(
            e.text(),
            "#version 300 es\nfloat light() {\n  return 1.0\n}\nvoid main() {}\n"
        );
        let at = e.text().find("1.0").unwrap() as u32;
        let tail = e.text().find("void").unwrap() as u32;
        let (f, d) = e.map_diagnostic(Diagnostic::error(
            Code::MissingSemicolon,
            "m",
            Span::new(at, at + 3),
        ));
        assert!(e.files()[f as usize].name().ends_with("light.glsl"));
        assert_eq!(e.files()[f as usize].slice(d.span), "1.0");
        let (f, d) = e.map_diagnostic(Diagnostic::error(
            Code::MissingSemicolon,
            "m",
            Span::new(tail, tail + 4),
        ));
        assert_eq!(f, 0);
        let void = main.find("void").unwrap() as u32;
        assert_eq!(d.span, Span::new(void, void + 4));

        let missing = expand(&src, &main_path, &[], &files).unwrap_err();
        assert_eq!(missing.len(), 1);
        assert_eq!(missing[0].1.code, "include-not-found");
        assert_eq!(
            missing[0].0.slice(missing[0].1.span),
            "#include \"light.glsl\""
        );
        std::fs::write(inc.join("light.glsl"), "#include \"light.glsl\"\n").unwrap();
        let looped = expand(&src, &main_path, &[inc], &Files::disk()).unwrap_err();
        assert_eq!(looped[0].1.code, "include-cycle");
        assert!(looped[0].1.message.contains("includes itself"));
    }

    #[test]
    fn directives() {
        assert_eq!(directive("#include \"a.glsl\"\n").unwrap().0, "a.glsl");
        assert_eq!(directive("  # include <b>").unwrap(), ("b", 2..15));
        assert!(directive("#includes \"a\"").is_none());
        assert!(directive("#include a").is_none());
    }
}
