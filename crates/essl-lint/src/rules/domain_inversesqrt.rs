//! `domain-inversesqrt`: `inversesqrt(x)` of a value that can be negative, or 0 over a region.

use essl::diagnostic::Diagnostic;
use naga::MathFunction as Mf;

use super::domain::{check, Domain};
use super::rule::declare_rule;
use super::Cx;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `inversesqrt(x)` where the shader's own arithmetic can make `x` negative, or where `x`
    /// is 0 over a whole region of ordinary inputs: a value that saturates at 0 (`max(d, 0.0)`, a
    /// clamp, `step`), a texel (0 wherever the texture is black), a product with such a value, or a
    /// per-draw value (uniforms and constants) that can be 0 — then it is 0 for the whole draw.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `inversesqrt(x)` undefined for `x ≤ 0` (§8.2): at 0 GPUs return +∞, and
    /// the first multiplication by 0 after it (`v * inversesqrt(dot(v, v))` of the zero vector)
    /// makes NaN; below 0 it is NaN outright.
    ///
    /// ## Example
    /// ```glsl
    /// float k = inversesqrt(max(dot(n, l), 0.0));
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float k = inversesqrt(max(dot(n, l), 1e-6));
    /// ```
    /// The suggested fix floors the argument at `1e-6` (`1e-4` in `mediump`/`lowp`, above the
    /// smallest normal `mediump` number).
    ///
    /// ## What it does not flag
    /// - A per-pixel value that crosses 0 only at isolated points: `inversesqrt(dot(d, d))` of a
    ///   difference of varyings (zero only at the pixel where the two points meet), the normalising
    ///   `inversesqrt(dot(n, n))` of an interpolated normal.
    /// - An argument kept positive: `max(x, 1e-6)`, `x + 1e-4` of a non-negative `x`, `dot(v, v)`
    ///   of a valid (non-zero) uniform direction, or under a guard (`if (x > 0.0)`).
    /// - An input as such: valid values are the caller's business. A uniform is taken to be
    ///   non-negative, not non-zero: `inversesqrt(u_x)` is a note naming it.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does. A note, naming them, where the
    /// argument is built from a function's parameters alone and its callers pass inputs as such,
    /// or from a vertex shader's attributes, and ordinary values make it 0.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.2 Exponential Functions: inversesqrt "Results are undefined
    ///   if x <= 0."
    pub(crate) struct DomainInversesqrt {
        id: "domain-inversesqrt",
        summary: "`inversesqrt(x)` of a value that can be negative, or 0 over a region of ordinary inputs",
        default_level: Level::Warn,
        check: check_inversesqrt,
    }
}

fn check_inversesqrt(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let d = Domain {
        fun: Mf::InverseSqrt,
        name: "inversesqrt",
        zero: true,
        spec: "GLSL ES 3.00 §8.2: inversesqrt(x) is undefined if x <= 0",
    };
    check(cx, out, &[d], &DomainInversesqrt::RULE);
}
