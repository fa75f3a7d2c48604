//! SARIF 2.1.0 output: the diagnostics of several files as one log, for code-scanning services
//! (GitHub code scanning, Azure DevOps, IDE viewers).
//!
//! One run, tool `essl`, with the lint rules as reporting descriptors (id, summary, help in
//! Markdown, default level) and any other code the diagnostics carry (compile errors such as
//! `missing-semicolon`) added as a bare descriptor. Columns count Unicode scalar values, as
//! essl's do (`columnKind: unicodeCodePoints`). Fixes become SARIF `fixes` with their edits as
//! replacements.

use essl::diagnostic::{Applicability, Diagnostic};
use essl::source::{SourceFile, Span};
use serde_json::{json, Value};

use crate::{Level, RULES};

/// The `$schema` of the logs this module writes.
pub const SCHEMA: &str = "https://json.schemastore.org/sarif-2.1.0.json";

/// One file's diagnostics.
#[derive(Clone, Copy, Debug)]
pub struct FileDiagnostics<'a> {
    /// The file (its name becomes the artifact's URI).
    pub file: &'a SourceFile,
    /// What was found in it.
    pub diagnostics: &'a [Diagnostic],
}

/// A relative URI for a file name: `/` separators, reserved characters percent-encoded.
pub fn uri(name: &str) -> String {
    let name = name.replace('\\', "/");
    let mut out = String::new();
    if name.starts_with('/') {
        out.push_str("file://");
    }
    for b in name.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(b as char)
            }
            _ => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

fn region(file: &SourceFile, span: Span) -> Value {
    let s = file.line_col(span.start);
    let e = file.line_col(span.end);
    json!({ "startLine": s.line, "startColumn": s.column, "endLine": e.line, "endColumn": e.column })
}

fn location(file: &SourceFile, index: usize, span: Span, message: Option<&str>) -> Value {
    let mut v = json!({
        "physicalLocation": {
            "artifactLocation": { "uri": uri(file.name()), "index": index },
            "region": region(file, span),
        }
    });
    if let Some(m) = message.filter(|m| !m.is_empty()) {
        v["message"] = json!({ "text": m });
    }
    v
}

fn level(l: Level) -> &'static str {
    match l {
        Level::Allow => "none",
        Level::Note => "note",
        Level::Warn => "warning",
        Level::Deny => "error",
    }
}

/// The SARIF log of the diagnostics of `files`.
pub fn log(files: &[FileDiagnostics]) -> Value {
    let mut rules: Vec<Value> = RULES
        .iter()
        .map(|r| {
            json!({
                "id": r.id,
                "shortDescription": { "text": r.summary },
                "fullDescription": { "text": r.summary },
                "help": { "text": r.summary, "markdown": r.page() },
                "defaultConfiguration": { "level": level(r.default_level) },
                "properties": { "tags": ["numerics"] },
            })
        })
        .collect();
    let mut ids: Vec<&str> = RULES.iter().map(|r| r.id).collect();
    let mut results = Vec::new();
    let mut artifacts = Vec::new();
    for (index, fd) in files.iter().enumerate() {
        artifacts.push(json!({ "location": { "uri": uri(fd.file.name()) } }));
        for d in fd.diagnostics {
            let rule_index = match ids.iter().position(|id| *id == d.code) {
                Some(i) => i,
                None => {
                    ids.push(d.code);
                    rules.push(json!({ "id": d.code }));
                    ids.len() - 1
                }
            };
            let mut text = d.message.clone();
            if let Some(help) = d.help_text(fd.file) {
                text.push_str(&format!(" (help: {help})"));
            }
            let mut r = json!({
                "ruleId": d.code,
                "ruleIndex": rule_index,
                // SARIF's levels share the names: "error", "warning", "note".
                "level": d.severity.as_str(),
                "message": { "text": text },
                "locations": [location(fd.file, index, d.span, Some(&d.label))],
            });
            if !d.secondary.is_empty() {
                r["relatedLocations"] = Value::Array(
                    d.secondary
                        .iter()
                        .enumerate()
                        .map(|(i, l)| {
                            let mut v = location(fd.file, index, l.span, Some(&l.message));
                            v["id"] = json!(i);
                            v
                        })
                        .collect(),
                );
            }
            if let Some(fix) = &d.fix {
                let replacements: Vec<Value> = fix
                    .edits
                    .iter()
                    .map(|e| json!({ "deletedRegion": region(fd.file, e.span), "insertedContent": { "text": e.replacement } }))
                    .collect();
                r["fixes"] = json!([{
                    "description": { "text": fix.message },
                    "artifactChanges": [{ "artifactLocation": { "uri": uri(fd.file.name()), "index": index }, "replacements": replacements }],
                    "properties": { "applicability": if fix.applicability == Applicability::Certain { "certain" } else { "suggested" } },
                }]);
            }
            results.push(r);
        }
    }
    json!({
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": { "driver": {
                "name": "essl",
                "semanticVersion": env!("CARGO_PKG_VERSION"),
                "rules": rules,
            } },
            "artifacts": artifacts,
            "columnKind": "unicodeCodePoints",
            "results": results,
        }],
    })
}

/// [`log`] as pretty-printed JSON.
pub fn to_string(files: &[FileDiagnostics]) -> String {
    serde_json::to_string_pretty(&log(files)).expect("a JSON value serialises")
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic::Fix;

    #[test]
    fn a_log_of_two_files() {
        let a = SourceFile::new("shaders/a b.frag", "float x = acos(d);\n");
        let b = SourceFile::new("b.frag", "é = 1\n");
        let da = vec![Diagnostic::rule_warning(
            "acos-domain",
            "`acos` argument can be outside [-1, 1]",
            Span::new(15, 16),
        )
        .with_label("a dot product")
        .with_secondary(Span::new(6, 7), "here")
        .with_fix(Fix::suggested(
            "clamp",
            Span::new(15, 16),
            "clamp(d, -1.0, 1.0)",
        ))];
        let db = vec![Diagnostic::error(
            essl::diagnostic_code::Code::MissingSemicolon,
            "expected `;`",
            Span::new(6, 6),
        )];
        let v = log(&[
            FileDiagnostics {
                file: &a,
                diagnostics: &da,
            },
            FileDiagnostics {
                file: &b,
                diagnostics: &db,
            },
        ]);
        assert_eq!(v["version"], "2.1.0");
        assert_eq!(v["$schema"], SCHEMA);
        let run = &v["runs"][0];
        assert_eq!(run["tool"]["driver"]["name"], "essl");
        let rules = run["tool"]["driver"]["rules"].as_array().unwrap();
        assert_eq!(rules.len(), RULES.len() + 1);
        assert!(rules[0]["help"]["markdown"]
            .as_str()
            .unwrap()
            .contains("## What it does"));
        assert_eq!(run["artifacts"][0]["location"]["uri"], "shaders/a%20b.frag");
        let r0 = &run["results"][0];
        assert_eq!(r0["ruleId"], "acos-domain");
        assert_eq!(
            rules[r0["ruleIndex"].as_u64().unwrap() as usize]["id"],
            "acos-domain"
        );
        assert_eq!(r0["level"], "warning");
        assert_eq!(
            r0["locations"][0]["physicalLocation"]["region"],
            json!({"startLine": 1, "startColumn": 16, "endLine": 1, "endColumn": 17})
        );
        assert_eq!(r0["locations"][0]["message"]["text"], "a dot product");
        assert_eq!(r0["relatedLocations"][0]["message"]["text"], "here");
        let rep = &r0["fixes"][0]["artifactChanges"][0]["replacements"][0];
        assert_eq!(rep["insertedContent"]["text"], "clamp(d, -1.0, 1.0)");
        let r1 = &run["results"][1];
        assert_eq!(r1["level"], "error");
        assert_eq!(
            rules[r1["ruleIndex"].as_u64().unwrap() as usize]["id"],
            "missing-semicolon"
        );
        // Columns in characters: `é` is one column, two bytes.
        assert_eq!(
            r1["locations"][0]["physicalLocation"]["region"]["startColumn"],
            6
        );
        assert_eq!(
            r1["locations"][0]["physicalLocation"]["artifactLocation"]["index"],
            1
        );
        // The text round-trips as JSON.
        let s = to_string(&[FileDiagnostics {
            file: &a,
            diagnostics: &da,
        }]);
        assert_eq!(
            serde_json::from_str::<Value>(&s).unwrap()["runs"][0]["results"][0]["ruleId"],
            "acos-domain"
        );
    }
}
