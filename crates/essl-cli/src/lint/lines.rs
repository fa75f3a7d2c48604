//! The one-line formats: `--format concise` (`FILE:LINE:COL: severity[code]: message`) and
//! `--format github` (GitHub Actions workflow commands, shown as annotations on a pull
//! request's lines), and `--statistics` (how often each code occurs).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use essl::diagnostic::{Diagnostic, Severity};
use essl::source::SourceFile;

use super::options::Format;
use super::results::LintResults;

/// The line of one diagnostic in `format` (`concise` or `github`); `file` is `None` for a link
/// diagnostic that points into no shader, which is then placed at `fallback`'s first line.
pub(crate) fn line(
    format: Format,
    file: Option<&SourceFile>,
    fallback: &str,
    d: &Diagnostic,
) -> String {
    let (name, start, end) = match file {
        Some(f) => (
            f.name().to_string(),
            f.line_col(d.span.start),
            f.line_col(d.span.end),
        ),
        None => {
            let one = essl::source::LineCol { line: 1, column: 1 };
            (fallback.to_string(), one, one)
        }
    };
    let mut message = d.message.clone();
    if let Some(help) = file.and_then(|f| d.help_text(f)).or_else(|| d.help.clone()) {
        message.push_str(&format!(" (help: {help})"));
    }
    if format == Format::Github {
        let level = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            _ => "notice",
        };
        format!(
            "::{level} title=essl ({code}),file={file},line={},col={},endLine={},endColumn={}::{}\n",
            start.line,
            start.column,
            end.line,
            end.column,
            escape_data(&message),
            code = escape_property(d.code),
            file = escape_property(&name),
        )
    } else {
        format!(
            "{name}:{}:{}: {}[{}]: {message}\n",
            start.line,
            start.column,
            d.severity.as_str(),
            d.code
        )
    }
}

/// A workflow command's message: `%`, CR and LF escaped.
fn escape_data(s: &str) -> String {
    s.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// A workflow command's property value: also `:` and `,`.
fn escape_property(s: &str) -> String {
    escape_data(s).replace(':', "%3A").replace(',', "%2C")
}

/// `--statistics`: one line per code, most frequent first — the count, the code, its
/// severity, and `[*]` where `--fix` can repair some (a certain fix exists).
pub(crate) fn statistics(results: &LintResults) -> String {
    let mut counts: BTreeMap<(&str, &str), usize> = BTreeMap::new();
    let codes = results
        .files
        .iter()
        .flat_map(|f| f.codes.iter())
        .chain(results.programs.iter().flat_map(|p| p.codes.iter()));
    for (code, severity) in codes {
        *counts.entry((code, severity.as_str())).or_default() += 1;
    }
    let mut rows: Vec<((&str, &str), usize)> = counts.into_iter().collect();
    rows.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let mut out = String::new();
    for ((code, severity), n) in rows {
        let _ = writeln!(out, "{n:>5}  {code:<32} {severity}");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic_code::Code;
    use essl::source::Span;

    #[test]
    fn concise_and_github() {
        let file = SourceFile::new("a,b.frag", "void main() {\n  x = 1\n}\n");
        let d = Diagnostic::error(Code::MissingSemicolon, "expected `;`", Span::new(20, 21))
            .with_help("add it");
        assert_eq!(
            line(Format::Concise, Some(&file), "", &d),
            "a,b.frag:2:7: error[missing-semicolon]: expected `;` (help: add it)\n"
        );
        assert_eq!(
            line(Format::Github, Some(&file), "", &d),
            "::error title=essl (missing-semicolon),file=a%2Cb.frag,line=2,col=7,endLine=2,\
             endColumn=8::expected `;` (help: add it)\n"
        );
    }
}
