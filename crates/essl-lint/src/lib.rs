//! essl-lint: lints for shaders that WebGL2 compiles but that render NaN or garbage for ordinary
//! parameter values — `pow` of a negative dot product, `acos` of a dot product that rounding
//! pushes past 1, `smoothstep` with equal edges, a division by `u_innerLimit - u_outerLimit`,
//! `normalize(cross(up, dir))`, `mediump` overflow.
//!
//! The rules run on the validated naga IR that [`essl::compile`] produces, where every
//! expression's span points into the user's text. A small interval analysis
//! (`analysis::Analysis`) gives every expression a range per component and facts such as
//! "unit length" or "non-negative whenever the uniforms are", so that guarded code —
//! `pow(max(dot(n, h), 0.0), s)`, `acos(clamp(c, -1.0, 1.0))` — is not reported.
//!
//! ```
//! use essl::source::SourceFile;
//! use essl::{compile, CompileOptions, Stage};
//!
//! let text = "#version 300 es\nprecision highp float;\nin vec3 n; in vec3 h;\nuniform float s;\nout vec4 o;\n\
//!             void main() { o = vec4(pow(dot(normalize(n), normalize(h)), s)); }\n";
//! let shader = compile(SourceFile::new("a.frag", text), Stage::Fragment, &CompileOptions::default());
//! let found = essl_lint::lint(&shader, &essl_lint::LintOptions::default());
//! assert_eq!(found[0].code, "pow-negative-base");
//! ```
//!
//! A finding is a warning, or a note where one uniform alone, out of the range the shader was
//! written for, reaches the hazard (and every finding of a note-level rule); notes are reported
//! only when [`LintOptions::notes`] asks. [`LintOptions`] sets each rule's [`Level`] (allow,
//! note, warn, deny; `all` for every rule). A comment `// essl-allow: RULE` on the line of the
//! finding or on the line before silences it there, `// essl-allow-file: RULE` in the whole file.
//!
//! What the rules cannot decide statically because it depends on uniform values — equal
//! `smoothstep` edges, a zero `u_lightDirection` given to `normalize`, `u_shininess <= 0` —
//! [`preconditions`] exports as conditions on the uniforms ([`precondition`]), for a renderer
//! to check with the values it draws with (`essl-gl`'s validation mode).

#![warn(missing_docs)]

mod analysis;
mod definite;
mod interval;
mod precision;
pub mod precondition;
mod prescreen;
mod rules;
pub mod sarif;
mod suppress;
mod symbolic;
mod uniformity;
mod value;
pub mod variants;

use essl::diagnostic::{self, Diagnostic, Severity};
use essl::Shader;

pub use precondition::{preconditions, Condition, Precondition, Term, UniformRef};
pub use prescreen::needs_ir;
pub use rules::{rule, Rule, RULES};

/// What to do with a rule's findings.
///
/// A rule reports each finding as a warning (a hazard the shader's own values reach: a signed
/// dot product, a difference of two varyings or of two parameters set independently) or as a
/// note (a hazard only one uniform out of its plausible range reaches, named in the message: the
/// runtime check's business). The level decides what becomes of them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Level {
    /// Not reported.
    Allow,
    /// Every finding reported as a note ([`LintOptions::notes`] shows them).
    Note,
    /// Warnings reported as warnings, notes as notes (the default): `essl lint` still succeeds.
    Warn,
    /// Warnings reported as errors (`essl lint` fails), notes as notes.
    Deny,
}

impl Level {
    /// `"allow"`, `"note"`, `"warn"` or `"deny"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Level::Allow => "allow",
            Level::Note => "note",
            Level::Warn => "warn",
            Level::Deny => "deny",
        }
    }

    /// The severity a finding the rule reports with `severity` gets at this level (`None`:
    /// not reported).
    pub fn severity(self, severity: Severity) -> Option<Severity> {
        match (self, severity) {
            (Level::Allow, _) => None,
            (Level::Note, _) | (_, Severity::Note) => Some(Severity::Note),
            (Level::Deny, _) => Some(Severity::Error),
            (Level::Warn, s) => Some(s),
        }
    }
}

/// A rule name that no rule has.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownRule(pub String);

impl std::fmt::Display for UnknownRule {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "unknown lint rule `{}` (known: all, {})",
            self.0,
            RULES.iter().map(|r| r.id).collect::<Vec<_>>().join(", ")
        )
    }
}

impl std::error::Error for UnknownRule {}

/// Which rules run, and how loud they are: `--allow RULE` / `--deny RULE`, in order (a later
/// setting of the same rule wins; `all` names every rule); and whether notes are reported
/// (off by default: an editor shows them, `essl lint --show-notes` prints them).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LintOptions {
    overrides: Vec<(String, Level)>,
    notes: bool,
}

impl LintOptions {
    /// Every rule at its default level.
    pub fn new() -> LintOptions {
        LintOptions::default()
    }

    /// Sets a rule's level (`all`: every rule's); an unknown name is an error.
    pub fn set(&mut self, rule_id: &str, level: Level) -> Result<(), UnknownRule> {
        if rule_id != "all" && rule(rule_id).is_none() {
            return Err(UnknownRule(rule_id.to_string()));
        }
        self.overrides.push((rule_id.to_string(), level));
        Ok(())
    }

    /// Silences a rule (`all`: every rule). Unknown names are kept and match nothing; use
    /// [`LintOptions::set`] to reject them.
    pub fn allow(mut self, rule_id: &str) -> LintOptions {
        self.overrides.push((rule_id.to_string(), Level::Allow));
        self
    }

    /// Reports every finding of a rule as a note.
    pub fn note(mut self, rule_id: &str) -> LintOptions {
        self.overrides.push((rule_id.to_string(), Level::Note));
        self
    }

    /// Reports notes (`true`) or leaves them out (`false`, the default).
    pub fn notes(mut self, on: bool) -> LintOptions {
        self.notes = on;
        self
    }

    /// Whether notes are reported.
    pub fn shows_notes(&self) -> bool {
        self.notes
    }

    /// Reports a rule as a warning.
    pub fn warn(mut self, rule_id: &str) -> LintOptions {
        self.overrides.push((rule_id.to_string(), Level::Warn));
        self
    }

    /// Reports a rule as an error.
    pub fn deny(mut self, rule_id: &str) -> LintOptions {
        self.overrides.push((rule_id.to_string(), Level::Deny));
        self
    }

    /// Whether a rule that reads the shader's naga IR is reported under these options: where
    /// none is (`--allow all`), a shader is not lowered for the lints, whatever [`needs_ir`]
    /// says.
    pub fn reads_ir(&self) -> bool {
        RULES
            .iter()
            .any(|r| !rules::HIR_RULES.contains(&r.id) && self.reports(r))
    }

    /// Whether a rule's findings are reported: it is not allowed, and it is not at the level
    /// of notes while notes are left out.
    fn reports(&self, r: &Rule) -> bool {
        match self.level(r) {
            Level::Allow => false,
            Level::Note => self.notes,
            _ => true,
        }
    }

    /// The level of a rule under these options.
    pub fn level(&self, r: &Rule) -> Level {
        self.overrides
            .iter()
            .rev()
            .find(|(id, _)| id == "all" || id == r.id)
            .map(|(_, l)| *l)
            .unwrap_or(r.default_level)
    }
}

/// Lowers `shader` to naga IR (typed, not validated) where a rule on the IR that `options`
/// reports has something to look at ([`LintOptions::reads_ir`], [`needs_ir`]): what a check does
/// before [`lint`].
pub fn lower_for_lints(shader: &mut Shader, options: &LintOptions) {
    if options.reads_ir() && needs_ir(shader) {
        shader.lower_typed();
    }
}

/// Lints a compiled shader: every finding of every rule that is not allowed, in source order,
/// with the severity its rule's level gives it ([`Level::severity`]); notes only when
/// [`LintOptions::notes`] asks for them.
///
/// A shader that did not compile has no findings: its errors come first. The rules on naga IR
/// read the shader lowered ([`Shader::lower_typed`], where [`needs_ir`] says they have something
/// to look at); on a shader not lowered only the rules on its checked module run.
pub fn lint(shader: &Shader, options: &LintOptions) -> Vec<Diagnostic> {
    // The analysis is most of the cost: skip it when no rule would look at it.
    let reported = |r: &Rule| options.reports(r);
    if !RULES.iter().any(|r| reported(r)) {
        return Vec::new();
    }
    if !shader.ok() {
        return Vec::new();
    }
    let allowed = suppress::Allowed::scan(&shader.file);
    let mut out = Vec::new();
    let (worth_it, signs, prec) = match shader.naga.as_ref() {
        Some(lowered) => rules::candidates(shader, &lowered.module),
        None => (false, false, None),
    };
    debug_assert!(
        !worth_it || needs_ir(shader),
        "the screen missed a candidate"
    );
    // The rules on the checked module run on every shader; the others only where the value
    // analysis has something to look at.
    let runs = |r: &Rule| reported(r) && (worth_it || rules::HIR_RULES.contains(&r.id));
    let cx = RULES.iter().any(|r| runs(r)).then(|| {
        let prec = match (worth_it, prec) {
            (_, Some(p)) => p,
            (true, None) => precision::Precisions::of(&shader.module),
            (false, None) => precision::Precisions::default(),
        };
        rules::Cx::with_precisions(shader, prec, signs)
    });
    if let Some(cx) = &cx {
        for r in RULES {
            if !runs(r) {
                continue;
            }
            let level = options.level(r);
            let mut found = Vec::new();
            (r.check)(cx, &mut found);
            for mut d in found {
                if allowed.silences(&shader.file, d.span, r.id) {
                    continue;
                }
                match level.severity(d.severity) {
                    Some(Severity::Note) if !options.notes => {}
                    Some(s) => {
                        d.severity = s;
                        out.push(d);
                    }
                    None => {}
                }
            }
        }
    } else if worth_it {
        // No rule ran: nothing was looked at, so nothing is unused.
        return Vec::new();
    }
    out.extend(unused_allows(&allowed, options, &reported));
    shader.label_expansions(&mut out);
    out.dedup_by(|a, b| a.code == b.code && a.span == b.span);
    diagnostic::sort(&mut out);
    let mut seen = std::collections::HashSet::new();
    out.retain(|d| seen.insert((d.code, d.span)));
    out
}

/// The suppressions that silenced nothing, as `unused-essl-allow` findings (when that rule is
/// reported). A suppression of a rule that is not run is left alone.
fn unused_allows(
    allowed: &suppress::Allowed,
    options: &LintOptions,
    reported: &dyn Fn(&Rule) -> bool,
) -> Vec<Diagnostic> {
    let Some(unused) = rule(rules::UNUSED_ALLOW).filter(|r| reported(r)) else {
        return Vec::new();
    };
    let severity = match options.level(unused).severity(Severity::Warning) {
        Some(Severity::Note) if !options.notes => return Vec::new(),
        Some(s) => s,
        None => return Vec::new(),
    };
    allowed
        .entries
        .iter()
        .filter(|e| !e.used.get() && e.rule != rules::UNUSED_ALLOW)
        .filter(|e| e.rule == "all" || rule(&e.rule).is_some_and(reported))
        .map(|e| {
            let mut d = Diagnostic::rule_warning(
                rules::UNUSED_ALLOW,
                format!("`essl-allow: {}` silences nothing here", e.rule),
                e.span,
            )
            .with_label("no finding of this rule on this line or the next")
            .with_help("remove it: the hazard it was written for is gone");
            d.severity = severity;
            d
        })
        .collect()
}

/// The analysis of every expression of the user's functions, one line each (span text, value):
/// for debugging the analysis.
#[doc(hidden)]
pub fn dump(shader: &Shader) -> String {
    use std::fmt::Write;
    let Some(cx) = rules::Cx::new(shader) else {
        return String::new();
    };
    let mut s = String::new();
    for (id, f) in cx.functions() {
        let _ = writeln!(s, "fn {}", f.name.as_deref().unwrap_or("?"));
        for (h, e) in f.expressions.iter() {
            let span = cx.span(f, h);
            let v = cx.sound().value(id, h);
            let _ = writeln!(
                s,
                "  {:?} {:?} `{}` = {:?}",
                h,
                std::mem::discriminant(e),
                cx.text(span).replace('\n', " "),
                v
            );
        }
    }
    s
}
