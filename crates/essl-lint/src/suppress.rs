//! In-source suppressions: `// essl-allow: RULE[, RULE…]` on the line of a finding, or on the
//! line before it, silences those rules there (`all` silences every rule), as clippy's
//! `#[allow]` and ruff's `# noqa` do; `// essl-allow-file: RULE[, RULE…]` anywhere silences
//! them in the whole file. Each suppression remembers whether it silenced anything, so that
//! one that silences nothing is reported (`unused-essl-allow`).

use std::cell::Cell;

use essl::source::{SourceFile, Span};

/// The marker that starts a suppression inside a comment.
pub const MARKER: &str = "essl-allow:";

/// The marker of a suppression for the whole file.
pub const FILE_MARKER: &str = "essl-allow-file:";

/// One rule named in a suppression comment.
#[derive(Clone, Debug)]
pub struct Entry {
    /// The 0-based line of the comment.
    pub line: usize,
    /// The rule (`all`: every rule).
    pub rule: String,
    /// Where the rule's name is written.
    pub span: Span,
    /// Whether the comment is `essl-allow-file:`.
    pub whole_file: bool,
    /// Whether it silenced a finding.
    pub used: Cell<bool>,
}

/// The suppressions of one file.
#[derive(Clone, Debug, Default)]
pub struct Allowed {
    /// Every rule named, in source order.
    pub entries: Vec<Entry>,
}

/// The rules named after `marker` at byte `at` of line `i`, with their spans.
fn rules_after(file: &SourceFile, i: usize, at: usize, marker: &str) -> Vec<(String, Span)> {
    let text = file.line_text(i);
    let base = file.line_start(i) as usize + at + marker.len();
    let rest = &text[at + marker.len()..];
    let mut out = Vec::new();
    let mut offset = 0;
    for word in rest.split(|c: char| c == ',' || c.is_whitespace()) {
        let start = offset;
        offset += word.len() + 1;
        if word.is_empty() {
            continue;
        }
        if !word
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
        {
            break;
        }
        let s = (base + start) as u32;
        out.push((word.to_string(), Span::new(s, s + word.len() as u32)));
    }
    out
}

impl Allowed {
    /// Finds every `essl-allow:` and `essl-allow-file:` inside a `//` or `/* */` comment.
    pub fn scan(file: &SourceFile) -> Allowed {
        let mut entries = Vec::new();
        // One search of the whole text first: most files have no suppression at all.
        if !file.text().contains("essl-allow") {
            return Allowed { entries };
        }
        for i in 0..file.line_count() {
            let text = file.line_text(i);
            for (marker, whole_file) in [(MARKER, false), (FILE_MARKER, true)] {
                let Some(at) = text.find(marker) else {
                    continue;
                };
                let before = &text[..at];
                if !before.contains("//") && !before.contains("/*") {
                    continue;
                }
                for (rule, span) in rules_after(file, i, at, marker) {
                    entries.push(Entry {
                        line: i,
                        rule,
                        span,
                        whole_file,
                        used: Cell::new(false),
                    });
                }
            }
        }
        Allowed { entries }
    }

    /// Whether a finding of `rule` at `span` is silenced (and, if so, by which suppressions:
    /// they are marked used).
    pub fn silences(&self, file: &SourceFile, span: Span, rule: &str) -> bool {
        let line = file.line_index(span.start);
        let mut hit = false;
        for e in &self.entries {
            let here = e.whole_file || e.line == line || e.line + 1 == line;
            if here && (e.rule == rule || e.rule == "all") {
                e.used.set(true);
                hit = true;
            }
        }
        hit
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_rules_in_comments_on_the_line_and_the_line_before() {
        let file = SourceFile::new("a.frag", "// essl-allow: acos-domain, pow-zero-base\nx = 1; // essl-allow: all\ny = 2;\nz = 3; essl-allow: acos-domain\n");
        let a = Allowed::scan(&file);
        let at = |line: usize| Span::empty(file.line_start(line));
        assert!(a.silences(&file, at(0), "acos-domain"));
        assert!(a.silences(&file, at(1), "pow-zero-base"));
        assert!(a.silences(&file, at(1), "normalize-zero"));
        assert!(a.silences(&file, at(2), "normalize-zero"));
        assert!(!a.silences(&file, at(3), "acos-domain"));
        assert_eq!(a.entries.len(), 3);
        assert_eq!(file.slice(a.entries[1].span), "pow-zero-base");
        assert!(a.entries.iter().all(|e| e.used.get()));
    }

    #[test]
    fn file_level_allows_reach_every_line() {
        let file = SourceFile::new("a.frag", "x;\ny;\n/* essl-allow-file: acos-domain */\nz;\n");
        let a = Allowed::scan(&file);
        assert!(a.silences(&file, Span::empty(0), "acos-domain"));
        assert!(!a.silences(&file, Span::empty(0), "asin-domain"));
        assert!(a.entries[0].whole_file);
    }
}
