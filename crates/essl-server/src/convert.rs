//! Between essl's byte offsets and the protocol's positions (0-based line, UTF-16 column), and
//! between `file://` URIs and paths; and essl's diagnostics as the protocol's.

use std::path::{Path, PathBuf};
use std::str::FromStr;

use essl::diagnostic::Diagnostic;
use essl::source::{SourceFile, Span};
use lsp_types::{
    DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Position, Range,
    Uri,
};

/// Where a shader's text lies in the document the editor shows: the document's text and the
/// byte offset the shader starts at (0 for a shader file; a `<script>` body or a template
/// literal for a shader inside an HTML or JS file).
#[derive(Clone, Copy, Debug)]
pub struct Place<'a> {
    /// The document's text.
    pub doc: &'a SourceFile,
    /// Where the shader starts in it.
    pub base: u32,
    /// The shader's length.
    pub len: u32,
}

impl<'a> Place<'a> {
    /// A shader that is the whole document.
    pub fn whole(doc: &'a SourceFile) -> Place<'a> {
        Place {
            doc,
            base: 0,
            len: doc.text().len() as u32,
        }
    }

    /// The shader's offset at a document position, when the position is inside the shader
    /// (its end included).
    pub fn offset(&self, pos: Position) -> Option<u32> {
        let o = offset(self.doc, pos);
        (o >= self.base && o <= self.base + self.len).then(|| o - self.base)
    }

    /// The document range of a span of the shader.
    pub fn range(&self, span: Span) -> Range {
        range(
            self.doc,
            Span::new(span.start + self.base, span.end + self.base),
        )
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

/// An essl diagnostic of the shader `file`, which lies at `place` in the document `uri`, as the
/// protocol's: the code, the message with its notes and help (as the command line prints
/// them), and the secondary labels as related information.
pub fn diagnostic(
    place: Place<'_>,
    file: &SourceFile,
    uri: &Uri,
    d: &Diagnostic,
) -> lsp_types::Diagnostic {
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
    if let Some(help) = d.help_text(file) {
        message.push_str(&format!("\nhelp: {help}"));
    }
    let related: Vec<DiagnosticRelatedInformation> = d
        .secondary
        .iter()
        .map(|l| DiagnosticRelatedInformation {
            location: Location::new(uri.clone(), place.range(l.span)),
            message: if l.message.is_empty() {
                "here".to_string()
            } else {
                l.message.clone()
            },
        })
        .collect();
    lsp_types::Diagnostic {
        range: place.range(d.span),
        severity: Some(severity),
        code: Some(NumberOrString::String(d.code.to_string())),
        source: Some("essl".to_string()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        ..lsp_types::Diagnostic::default()
    }
}

/// A link diagnostic of a program, on the shader `file` it points into: as [`diagnostic`], its
/// message starting `program: `.
pub fn link_diagnostic(
    place: Place<'_>,
    file: &SourceFile,
    uri: &Uri,
    d: &Diagnostic,
) -> lsp_types::Diagnostic {
    let mut converted = diagnostic(place, file, uri, d);
    converted.message = format!("program: {}", converted.message);
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
