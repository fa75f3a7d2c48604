//! `domain-log`: `log(x)` or `log2(x)` of a value that can be negative, or 0 over a region.

use essl::diagnostic::Diagnostic;
use naga::MathFunction as Mf;

use super::domain::{check, Domain};
use super::rule::declare_rule;
use super::Cx;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `log(x)` and `log2(x)` where the shader's own arithmetic can make `x` negative, or
    /// where `x` is 0 over a whole region of ordinary inputs: a luminance or a colour channel read
    /// from a texture (0 wherever it is black), a value that saturates at 0 (`max(d, 0.0)`, a clamp),
    /// or a per-draw value (uniforms and constants) that can be 0 — a uniform itself included, as
    /// a note naming it: 0 is an ordinary value of a blurriness or a roughness (three.js's
    /// `log2(1.16 * roughness)` of `backgroundBlurriness`, 0 by default).
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `log(x)` and `log2(x)` undefined for `x ≤ 0` (§8.2): at 0 GPUs return
    /// −∞ (and NaN once it is multiplied by 0 or subtracted from itself), below 0 NaN. Tone mappers
    /// and exposure adaptation take `log` of a luminance that is 0 on every black pixel; the usual
    /// `log(lum + 1e-4)` is what keeps them finite.
    ///
    /// ## Example
    /// ```glsl
    /// float logLum = log(dot(texture(u_hdr, v_uv).rgb, vec3(0.2126, 0.7152, 0.0722)));
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float logLum = log(max(dot(texture(u_hdr, v_uv).rgb, vec3(0.2126, 0.7152, 0.0722)), 1e-6));
    /// ```
    /// The suggested fix floors the argument at `1e-6` (`1e-4` in `mediump`/`lowp`, above the
    /// smallest normal `mediump` number).
    ///
    /// ## What it does not flag
    /// - A per-pixel value that reaches 0 only at isolated points (a difference of varyings).
    /// - An argument kept positive: `max(x, 1e-6)`, `x + 1e-4` of a non-negative `x`, `exp(x)`,
    ///   or under a guard (`if (lum > 0.0)`).
    /// - An input as such: valid values are the caller's business (but see the notes on
    ///   parameters and attributes below). A uniform is taken to be
    ///   non-negative, not non-zero: `log2(u_x)` is a note, `log2(abs(u_m[1][0]))` too (0, an
    ///   entry of an identity matrix, is an ordinary value).
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard (rounding
    /// included, which says so in the message); a note, naming the uniform, when one uniform alone
    /// (with constants) does. A note, naming them, where the argument is built from a function's
    /// parameters alone and its callers pass inputs as such, or from a vertex shader's attributes,
    /// and ordinary values make it 0: lygia's `k2rgb(t)` takes `log(t)` of a temperature its
    /// documented range starts at 0.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.2 Exponential Functions: log and log2 "Results are
    ///   undefined if x <= 0."
    pub(crate) struct DomainLog {
        id: "domain-log",
        summary: "`log(x)` or `log2(x)` of a value that can be negative, or 0 over a region of ordinary inputs",
        default_level: Level::Warn,
        check: check_log,
    }
}

fn check_log(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let ds = [
        Domain {
            fun: Mf::Log,
            name: "log",
            zero: true,
            spec: "GLSL ES 3.00 §8.2: log(x) is undefined if x <= 0",
        },
        Domain {
            fun: Mf::Log2,
            name: "log2",
            zero: true,
            spec: "GLSL ES 3.00 §8.2: log2(x) is undefined if x <= 0",
        },
    ];
    check(cx, out, &ds, &DomainLog::RULE);
}
