//! What a rule is: its id, summary, default level, documentation page and check; and
//! [`declare_rule!`], which makes a rule from a type whose doc comment is the rule's page.

use essl::diagnostic::Diagnostic;

use super::Cx;
use crate::Level;

/// A lint rule: its id, what it reports in one line, its default level and its documentation.
pub struct Rule {
    /// The stable kebab-case id (`pow-negative-base`), the diagnostics' code.
    pub id: &'static str,
    /// One line: what the rule reports.
    pub summary: &'static str,
    /// The level when options do not say.
    pub default_level: Level,
    /// The rule's page in Markdown: *What it does*, *Why is this bad?*, *Example*,
    /// *Use instead*, *References* (`docs/lints/<id>.md` is this text). It is the doc comment
    /// of the rule's type, after a blank line.
    pub doc: &'static str,
    pub(crate) check: fn(&Cx, &mut Vec<Diagnostic>),
}

impl std::fmt::Debug for Rule {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Rule")
            .field("id", &self.id)
            .field("default_level", &self.default_level)
            .finish()
    }
}

impl Rule {
    /// The rule's documentation page, as `docs/lints/<id>.md` holds it.
    pub fn page(&self) -> String {
        let id = self.id;
        let levels = if self.default_level == Level::Note {
            format!(
                "its findings are notes, which `essl lint --show-notes` prints; `--warn {id}` \
                 makes them warnings, `--deny {id}` errors, `--allow {id}` silences it"
            )
        } else {
            format!(
                "`--deny {id}` makes its warnings errors, `--note {id}` notes, `--allow {id}` \
                 silences it; its notes (one uniform out of range) show with `--show-notes`"
            )
        };
        format!(
            "# {id}\n\n{}\n\nDefault level: **{}** ({levels}; `// essl-allow: {id}` on a line, \
             or on the line before, silences one finding).\n\n{}",
            self.summary,
            self.default_level.as_str(),
            self.doc.trim_start()
        )
    }
}

/// The length of [`page_text`]'s result for these doc lines.
pub(crate) const fn page_len(lines: &[&str]) -> usize {
    let mut n = 1;
    let mut i = 0;
    while i < lines.len() {
        let b = lines[i].as_bytes();
        n += b.len() + 1;
        if !b.is_empty() && b[0] == b' ' {
            n -= 1;
        }
        i += 1;
    }
    n
}

/// The text of a doc comment given as the lines rustdoc keeps (`/// text` is `" text"`): a
/// newline, then each line without the one space after `///`, each ended by a newline. `N` is
/// [`page_len`] of the lines.
pub(crate) const fn page_text<const N: usize>(lines: &[&str]) -> [u8; N] {
    let mut out = [0u8; N];
    out[0] = b'\n';
    let mut at = 1;
    let mut i = 0;
    while i < lines.len() {
        let b = lines[i].as_bytes();
        let mut j = if !b.is_empty() && b[0] == b' ' { 1 } else { 0 };
        while j < b.len() {
            out[at] = b[j];
            at += 1;
            j += 1;
        }
        out[at] = b'\n';
        at += 1;
        i += 1;
    }
    out
}

/// Declares a rule the way ruff declares a violation: a unit type whose doc comment is the
/// rule's documentation page (*What it does*, *Why is this bad?*, *Example*, *Use instead*,
/// *References*), and `<Type>::RULE`, the [`Rule`] with that page as its `doc`.
macro_rules! declare_rule {
    (
        $(#[doc = $doc:literal])*
        $vis:vis struct $name:ident {
            id: $id:literal,
            summary: $summary:literal,
            default_level: $level:expr,
            check: $check:path $(,)?
        }
    ) => {
        $(#[doc = $doc])*
        $vis struct $name;

        impl $name {
            /// The rule, with this type's documentation as its page.
            pub(crate) const RULE: $crate::rules::Rule = $crate::rules::Rule {
                id: $id,
                summary: $summary,
                default_level: $level,
                doc: {
                    const LINES: &[&str] = &[$($doc),*];
                    const BYTES: [u8; $crate::rules::rule::page_len(LINES)] =
                        $crate::rules::rule::page_text(LINES);
                    match ::std::str::from_utf8(&BYTES) {
                        Ok(text) => text,
                        Err(_) => panic!("a doc comment is UTF-8"),
                    }
                },
                check: $check,
            };
        }
    };
}

pub(crate) use declare_rule;
