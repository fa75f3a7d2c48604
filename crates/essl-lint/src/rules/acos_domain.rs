//! `acos-domain`: `acos(x)` of an argument that can leave `[-1, 1]`.

use essl::diagnostic::Diagnostic;
use naga::MathFunction as Mf;

use super::rule::declare_rule;
use super::{inverse_trig, Cx};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `acos(x)` where the shader computes `x` and cannot guarantee `-1 ≤ x ≤ 1`. The classic
    /// case is the cosine of an angle as a dot product of unit vectors: mathematically in `[-1, 1]`,
    /// but `normalize` and `dot` round, and the result can be `1.0000001`; likewise a component
    /// over the vector's length (`acos(p.z / length(p))`, a polar angle), and a component of a
    /// normal (`acos(normal.z)` of an input whose name says it holds one: a unit vector, in
    /// `[-1, 1]` only as exactly as it was normalised). An argument that is a uniform as such
    /// (`acos(u_coneCos)`) is not reported: the runtime check validates uniform values.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `acos(x)` undefined for `|x| > 1` (§8.1); GPUs return NaN. The NaN appears
    /// exactly where the two vectors are (anti)parallel — the centre of a spot light, the pixel that
    /// faces the light — and turns the texture coordinate computed from the angle into NaN, so the
    /// lookup returns garbage.
    ///
    /// ## Example
    /// ```glsl
    /// float upCos = dot(light.direction, spotLightEx.up);
    /// float upAngle = acos(upCos);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float upAngle = acos(clamp(upCos, -1.0, 1.0));
    /// ```
    /// The fix is suggested (`clamp(…, -1.0, 1.0)`); it changes nothing where the argument was in range.
    ///
    /// ## What it does not flag
    /// - An argument the shader clamps (`clamp(c, -1.0, 1.0)`, `min(max(c, -1.0), 1.0)`, `sin`/`cos` of
    ///   anything) or a guard keeps in range (`abs(c) <= 1.0 ? acos(c) : 0.0`).
    /// - A uniform or input as such (`acos(u_coneCos)`, `acos(v_t)`): the runtime check validates
    ///   uniform values, and an input's range is its producer's.
    ///
    /// A dot product of unit vectors is in [-1, 1] in exact arithmetic only: it is reported, with a
    /// message that says rounding is the cause and the clamp as the fix.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.1 Angle and Trigonometry Functions: acos "Results are undefined
    ///   if |x| > 1."
    /// - Article 003 (A-Frame projected-texture spot lights): `acos(dot(light.direction, spotLightEx.up))`.
    pub(crate) struct AcosDomain {
        id: "acos-domain",
        summary: "`acos(x)` of a value that rounding or arithmetic can push past ±1",
        default_level: Level::Warn,
        check: check_acos,
    }
}

fn check_acos(cx: &Cx, out: &mut Vec<Diagnostic>) {
    inverse_trig::check(cx, out, Mf::Acos, &AcosDomain::RULE);
}
