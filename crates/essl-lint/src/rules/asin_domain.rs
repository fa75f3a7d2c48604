//! `asin-domain`: `asin(x)` of an argument that can leave `[-1, 1]`.

use essl::diagnostic::Diagnostic;
use naga::MathFunction as Mf;

use super::rule::declare_rule;
use super::{inverse_trig, Cx};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `asin(x)` where the shader computes `x` and cannot guarantee `-1 ≤ x ≤ 1` — a dot
    /// product or a component of unit vectors, or a component over the vector's length
    /// (`asin(p.y / length(p))`), which rounding can push to `1.0000001`. A uniform as
    /// such is not reported.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `asin(x)` undefined for `|x| > 1` (§8.1); GPUs return NaN, which then
    /// spreads through every value computed from the angle.
    ///
    /// ## Example
    /// ```glsl
    /// float lat = asin(normalize(p).y);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float lat = asin(clamp(normalize(p).y, -1.0, 1.0));
    /// ```
    ///
    /// ## What it does not flag
    /// - An argument the shader clamps (`clamp(c, -1.0, 1.0)`), `sin`/`cos` of anything, or one a guard
    ///   keeps in range.
    /// - A uniform or input as such: the runtime check validates uniform values.
    ///
    /// A component of a normalised vector or a dot product of unit vectors is in [-1, 1] in exact
    /// arithmetic only: it is reported, with a message that says rounding is the cause and the clamp as
    /// the fix.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.1 Angle and Trigonometry Functions: asin "Results are undefined
    ///   if |x| > 1."
    pub(crate) struct AsinDomain {
        id: "asin-domain",
        summary: "`asin(x)` of a value that rounding or arithmetic can push past ±1",
        default_level: Level::Warn,
        check: check_asin,
    }
}

fn check_asin(cx: &Cx, out: &mut Vec<Diagnostic>) {
    inverse_trig::check(cx, out, Mf::Asin, &AsinDomain::RULE);
}
