//! `unused-essl-allow`: an `// essl-allow: RULE` comment that silences nothing.

use essl::diagnostic::Diagnostic;

use super::rule::declare_rule;
use super::Cx;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports a rule named in an `// essl-allow: RULE` (or `// essl-allow-file: RULE`) comment
    /// when that rule reports nothing on the comment's line or the line after it (in the whole
    /// file, for `essl-allow-file`), as ruff reports an unused `# noqa`.
    ///
    /// ## Why is this bad?
    /// A suppression outlives the code it was written for: after the hazard is fixed, it stays
    /// and would silently hide the next finding on that line.
    ///
    /// ## Example
    /// ```glsl
    /// // essl-allow: pow-negative-base
    /// float f = pow(max(d, 0.0), 2.5);   // the base is never negative: nothing to allow
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float f = pow(max(d, 0.0), 2.5);
    /// ```
    ///
    /// ## What it does not flag
    /// - A comment naming a rule that is not run (`--allow RULE`, `[rules] RULE = "allow"`).
    /// - Any comment in a shader that does not compile: its lints did not run.
    ///
    /// ## References
    /// - ruff's `unused-noqa` (RUF100), the same check for `# noqa` comments.
    pub(crate) struct UnusedAllow {
        id: "unused-essl-allow",
        summary: "an `// essl-allow: RULE` comment that silences nothing",
        default_level: Level::Warn,
        check: check_nothing,
    }
}

/// The rule has nothing to look at in the IR: [`crate::lint`] reports it from the
/// suppressions that silenced no finding.
fn check_nothing(_: &Cx, _: &mut Vec<Diagnostic>) {}
