//! `domain-sqrt`: `sqrt(x)` of a value the shader's own arithmetic can make negative.

use essl::diagnostic::Diagnostic;
use naga::MathFunction as Mf;

use super::domain::{check, Domain};
use super::rule::declare_rule;
use super::Cx;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `sqrt(x)` where the shader's own arithmetic can make `x` negative: a difference, a
    /// dot product, `1.0 - d * d` of a dot product `d` of unit vectors (negative through rounding
    /// alone, since `d` can exceed 1 by an ulp). The same value analysis as `pow-negative-base`
    /// follows what a variable holds from statement to statement and what the enclosing
    /// conditions say.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `sqrt(x)` undefined for `x < 0` (§8.2); GPUs return NaN, and a NaN in
    /// a colour or a position shows as black pixels, holes in a mesh, or garbage after blending.
    /// `sqrt(1.0 - NdotV * NdotV)` (a sine from a cosine, Smith's visibility terms, refraction) is
    /// the classic: the cosine of two normalised vectors is 1.0000001 often enough that grazing or
    /// head-on pixels flicker black.
    ///
    /// ## Example
    /// ```glsl
    /// float sinTheta = sqrt(1.0 - NdotV * NdotV);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float sinTheta = sqrt(max(1.0 - NdotV * NdotV, 0.0));
    /// ```
    /// The suggested fix wraps the argument in `max(…, 0.0)`: it changes nothing where `x ≥ 0`.
    ///
    /// ## What it does not flag
    /// - An argument the shader keeps non-negative: `max(x, 0.0)`, `clamp`, `abs`, `x * x`,
    ///   `dot(v, v)`, `length(v)`, sums of such, or a guard (`if (x > 0.0)`, `x > 0.0 ? sqrt(x) :
    ///   0.0`).
    /// - A uniform, input or texel as such (`sqrt(u_radius)`, `sqrt(v_t)`): valid values are the
    ///   caller's and the runtime check's business.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard (rounding
    /// included, which says so in the message); a note, naming the uniform, when one uniform alone
    /// (with constants) does — `sqrt(u_r - 1.0)` needs `u_r < 1`, and essl-gl's validation mode
    /// checks it at draw time.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.2 Exponential Functions: sqrt "Results are undefined if
    ///   x < 0."
    pub(crate) struct DomainSqrt {
        id: "domain-sqrt",
        summary: "`sqrt(x)` of a value the shader's own arithmetic (or rounding) can make negative",
        default_level: Level::Warn,
        check: check_sqrt,
    }
}

fn check_sqrt(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let d = Domain {
        fun: Mf::Sqrt,
        name: "sqrt",
        zero: false,
        spec: "GLSL ES 3.00 §8.2: sqrt(x) is undefined if x < 0",
    };
    check(cx, out, &[d], &DomainSqrt::RULE);
}
