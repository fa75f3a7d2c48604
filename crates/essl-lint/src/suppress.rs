//! In-source suppressions: `// essl-allow: RULE[, RULE…]` on the line of a finding, or on the
//! line before it, silences those rules there (`all` silences every rule), as clippy's
//! `#[allow]` and ruff's `# noqa` do.

use std::collections::HashMap;

use essl::source::{SourceFile, Span};

/// The marker that starts a suppression inside a comment.
pub const MARKER: &str = "essl-allow:";

/// The suppressions of one file: rule names by 0-based line.
#[derive(Clone, Debug, Default)]
pub struct Allowed {
    lines: HashMap<usize, Vec<String>>,
}

impl Allowed {
    /// Finds every `essl-allow:` inside a `//` or `/* */` comment.
    pub fn scan(file: &SourceFile) -> Allowed {
        let mut lines = HashMap::new();
        // One search of the whole text first: most files have no suppression at all.
        if !file.text().contains(MARKER) {
            return Allowed { lines };
        }
        for i in 0..file.line_count() {
            let text = file.line_text(i);
            let Some(at) = text.find(MARKER) else {
                continue;
            };
            let before = &text[..at];
            if !before.contains("//") && !before.contains("/*") {
                continue;
            }
            let rules: Vec<String> = text[at + MARKER.len()..]
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|s| !s.is_empty())
                .take_while(|s| {
                    s.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
                })
                .map(str::to_string)
                .collect();
            if !rules.is_empty() {
                lines.insert(i, rules);
            }
        }
        Allowed { lines }
    }

    /// Whether a finding of `rule` at `span` is silenced.
    pub fn silences(&self, file: &SourceFile, span: Span, rule: &str) -> bool {
        let line = file.line_index(span.start);
        let hit = |l: usize| {
            self.lines
                .get(&l)
                .is_some_and(|rs| rs.iter().any(|r| r == rule || r == "all"))
        };
        hit(line) || (line > 0 && hit(line - 1))
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
    }
}
