//! Between essl's byte offsets and the protocol's positions (0-based line, UTF-16 column), and
//! between `file://` URIs and paths; and essl's diagnostics as the protocol's.

use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::Arc;

use essl::diagnostic::Diagnostic;
use essl::source::{SourceFile, Span};
use essl_check::Assembly;
use lsp_types::{
    DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Position, Range,
    Uri,
};

/// Where a shader's text lies in the document the editor shows: the document's text and the
/// map from the shader's assembled text to it (the whole document for a shader file; a
/// `<script>` body or a template literal's value for a shader inside an HTML or JS file).
#[derive(Clone, Copy, Debug)]
pub struct Place<'a> {
    /// The document's text.
    pub doc: &'a Arc<SourceFile>,
    /// The shader's text and where it came from.
    pub assembly: &'a Assembly,
}

impl Place<'_> {
    /// The shader's offset at a document position, when the position is inside the shader
    /// (its end included).
    pub fn offset(&self, pos: Position) -> Option<u32> {
        self.assembly
            .offset_in_text(self.doc, offset(self.doc, pos))
    }

    /// The document range of a span of the shader, when the span lies in the document (not
    /// in a file the shader includes, nor in code a preset adds).
    pub fn range(&self, span: Span) -> Option<Range> {
        let (file, span) = self.assembly.map_span(span)?;
        let file = self.assembly.files().get(file as usize)?;
        Arc::ptr_eq(file, self.doc).then(|| range(self.doc, span))
    }
}

/// The protocol position of a byte offset (clamped to the text).
pub fn position(file: &SourceFile, offset: u32) -> Position {
    let text = file.text();
    let mut offset = (offset as usize).min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let line = file.line_index(offset as u32);
    let start = file.line_start(line) as usize;
    let character = text[start..offset].encode_utf16().count() as u32;
    Position {
        line: line as u32,
        character,
    }
}

/// The protocol range of a span.
pub fn range(file: &SourceFile, span: Span) -> Range {
    Range {
        start: position(file, span.start),
        end: position(file, span.end),
    }
}

/// The byte offset of a protocol position (a line past the end is the end of the text; a
/// column past the line's end is its end).
pub fn offset(file: &SourceFile, pos: Position) -> u32 {
    let line = pos.line as usize;
    if line >= file.line_count() {
        return file.text().len() as u32;
    }
    let range = file.line_range(line);
    let text = &file.text()[range.clone()];
    let mut units = 0u32;
    for (i, c) in text.char_indices() {
        if units >= pos.character || c == '\n' || c == '\r' {
            return (range.start + i) as u32;
        }
        units += c.len_utf16() as u32;
    }
    range.end as u32
}

/// The path a `file://` URI names (percent-escapes decoded), if it is one.
pub fn uri_to_path(uri: &Uri) -> Option<PathBuf> {
    let s = uri.as_str();
    let rest = s.strip_prefix("file://")?;
    let path = rest.find('/').map(|i| &rest[i..])?;
    let bytes = path.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let Ok(b) = u8::from_str_radix(&path[i + 1..i + 3], 16) {
                out.push(b);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8(out).ok().map(PathBuf::from)
}

/// The `file://` URI of an absolute path.
pub fn path_to_uri(path: &Path) -> Option<Uri> {
    let mut s = String::from("file://");
    for b in path.to_str()?.bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    Uri::from_str(&s).ok()
}

/// An essl diagnostic on the document `doc` (spans in its text) as the protocol's: the code,
/// the message with its notes and help (as the command line prints them), and the secondary
/// labels as related information.
pub fn diagnostic(doc: &SourceFile, uri: &Uri, d: &Diagnostic) -> lsp_types::Diagnostic {
    let severity = match d.severity {
        essl::diagnostic::Severity::Error => DiagnosticSeverity::ERROR,
        essl::diagnostic::Severity::Warning => DiagnosticSeverity::WARNING,
        _ => DiagnosticSeverity::INFORMATION,
    };
    let mut message = d.message.clone();
    if !d.label.is_empty() {
        message.push_str(&format!(" ({})", d.label));
    }
    for note in &d.notes {
        message.push_str(&format!("\nnote: {note}"));
    }
    if let Some(help) = d.help_text(doc) {
        message.push_str(&format!("\nhelp: {help}"));
    }
    let related: Vec<DiagnosticRelatedInformation> = d
        .secondary
        .iter()
        .map(|l| DiagnosticRelatedInformation {
            location: Location::new(uri.clone(), range(doc, l.span)),
            message: if l.message.is_empty() {
                "here".to_string()
            } else {
                l.message.clone()
            },
        })
        .collect();
    lsp_types::Diagnostic {
        range: range(doc, d.span),
        severity: Some(severity),
        code: Some(NumberOrString::String(d.code.to_string())),
        source: Some("essl".to_string()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        ..lsp_types::Diagnostic::default()
    }
}

/// A link diagnostic of a program, on the document it points into: as [`diagnostic`], its
/// message starting `program: `.
pub fn link_diagnostic(doc: &SourceFile, uri: &Uri, d: &Diagnostic) -> lsp_types::Diagnostic {
    let mut converted = diagnostic(doc, uri, d);
    converted.message = format!("program: {}", converted.message);
    converted
}

/// A diagnostic in a file the shader includes, shown on the document at the shader's start
/// (`start`), its message naming the file's line, and its place there as related information.
pub fn elsewhere(
    doc: &SourceFile,
    start: u32,
    file: &SourceFile,
    d: &Diagnostic,
) -> lsp_types::Diagnostic {
    let lc = file.line_col(d.span.start);
    let there = Path::new(file.name());
    let absolute = std::fs::canonicalize(there).unwrap_or_else(|_| there.to_path_buf());
    let uri = path_to_uri(&absolute);
    let mut converted = match &uri {
        Some(u) => diagnostic(file, u, d),
        None => diagnostic(file, &Uri::from_str("file:///").expect("a URI"), d),
    };
    converted.message = format!(
        "in {}:{}:{}: {}",
        file.name(),
        lc.line,
        lc.column,
        converted.message
    );
    converted.related_information = uri.map(|u| {
        vec![DiagnosticRelatedInformation {
            location: Location::new(u, range(file, d.span)),
            message: "here".to_string(),
        }]
    });
    converted.range = range(doc, Span::empty(start));
    converted
}
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_count_utf16_units() {
        let file = SourceFile::new("a", "ab\n\u{e9}\u{1F600}x\n");
        let x = file.text().find('x').unwrap() as u32;
        assert_eq!(position(&file, x), Position::new(1, 3));
        assert_eq!(offset(&file, Position::new(1, 3)), x);
        assert_eq!(offset(&file, Position::new(0, 99)), 2);
        assert_eq!(offset(&file, Position::new(9, 0)), file.text().len() as u32);
    }

    #[test]
    fn uris_and_paths() {
        let path = Path::new("/tmp/a b/c#.frag");
        let uri = path_to_uri(path).unwrap();
        assert_eq!(uri.as_str(), "file:///tmp/a%20b/c%23.frag");
        assert_eq!(uri_to_path(&uri).unwrap(), path);
    }
}
