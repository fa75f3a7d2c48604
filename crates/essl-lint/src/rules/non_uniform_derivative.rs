//! `non-uniform-derivative`: a derivative or an implicit-LOD texture lookup under control flow
//! that varies between pixels.

use essl::diagnostic::Diagnostic;

use super::rule::declare_rule;
use super::Cx;
use crate::uniformity::divergent_derivatives;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports, in a fragment shader, `dFdx`, `dFdy`, `fwidth` and the texture lookups that choose
    /// their mipmap level from derivatives (`texture`, `textureProj`, `textureOffset`,
    /// `textureProjOffset`; GLSL ES 1.00's `texture2D`, `textureCube`, …) where control flow depends
    /// on values that differ between pixels: inside an `if`, loop, `switch` or `?:` whose condition
    /// reads an input, `gl_FragCoord`, a texel or anything computed from them; after a `break`,
    /// `continue` or `return` some pixels take; in the right side of `&&`/`||`; in a function
    /// called from such a place (the finding names the call); and, as a note, after a `discard`
    /// some pixels take, there and in the functions called after it (Cesium's billboard reads its
    /// SDF atlas in `getDistance`, called after its depth test's `discard`).
    ///
    /// ## Why is this bad?
    /// GPUs shade pixels in 2×2 quads and take derivatives as differences between neighbours.
    /// Where only some pixels of a quad run the code, the others' values are stale or missing, so
    /// GLSL ES 3.00 leaves derivatives — and the level of detail of an implicit-LOD lookup — undefined
    /// there (§8.9). The visible result is the wrong mipmap along the edges of the branch: seams
    /// one pixel wide, sparkles, a ray-marched or parallax-mapped surface that blurs at random.
    ///
    /// ## Example
    /// ```glsl
    /// if (v_uv.x > 0.5) {
    ///     color = texture(u_detail, v_uv * 8.0);
    /// }
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// vec4 detail = texture(u_detail, v_uv * 8.0);   // every pixel of the quad runs it
    /// if (v_uv.x > 0.5) {
    ///     color = detail;
    /// }
    /// ```
    /// or keep the lookup in the branch with the derivatives taken before it:
    /// `textureGrad(u_detail, uv, dFdx(uv), dFdy(uv))` with `dFdx(uv)` and `dFdy(uv)` computed above
    /// the `if`, or `textureLod` where the level is known. There is no mechanical fix.
    ///
    /// ## What it does not flag
    /// - Control flow that depends only on uniforms and constants (`if (u_useMap)`, a loop to a
    ///   uniform count): every pixel of a draw takes the same path.
    /// - `textureLod`, `textureGrad`, `texelFetch`, `textureSize`, and lookups in vertex shaders (no
    ///   derivatives there).
    /// - Control flow on a variable written after `if (…) discard;`: the pixels still running
    ///   agree on it.
    ///
    /// Severity: a warning; a note after `if (…) discard;` with a varying condition, which the
    /// specification leaves undefined in the same way but GPUs keep working in practice: they
    /// run a quad's discarded pixels on as helpers, so the neighbours' derivatives stay defined
    /// — on drivers that end them instead (SPIR-V's `OpKill`), lookups after the `discard` take
    /// the wrong level along its edges. Alpha testing is written that way everywhere; the note
    /// says where a lookup could move above the `discard`.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.9 Texture Lookup Functions ("implicit derivatives … are
    ///   undefined within non-uniform control flow") and §8.9 Fragment Processing Functions
    ///   (derivatives).
    pub(crate) struct NonUniformDerivative {
        id: "non-uniform-derivative",
        summary: "a derivative or implicit-LOD texture lookup under control flow that varies between pixels",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for f in divergent_derivatives(cx.hir) {
        let name = cx
            .text(f.span)
            .split('(')
            .next()
            .unwrap_or("")
            .trim()
            .to_string();
        let derivative = matches!(
            f.op,
            essl::hir::BuiltinFn::DFdx | essl::hir::BuiltinFn::DFdy | essl::hir::BuiltinFn::Fwidth
        );
        let message = if derivative {
            format!("`{name}` under control flow that varies between pixels, where derivatives are undefined")
        } else {
            format!("`{name}` takes its mipmap level from derivatives, undefined under control flow that varies between pixels")
        };
        let mut d = Diagnostic::rule_warning(NonUniformDerivative::RULE.id, message, f.span)
            .with_label("not every pixel of the 2×2 quad runs this")
            .with_note("GLSL ES 3.00 §8.9: implicit derivatives are undefined in non-uniform control flow")
            .with_help(if derivative {
                "take the derivative before the branch and use the value inside it"
            } else {
                "do the lookup before the branch, or use `textureGrad` with derivatives taken before it (`textureLod` where the level is known)"
            });
        if !f.why.span.is_empty() {
            d = d.with_secondary(f.why.span, f.why.what);
        }
        if f.after_discard {
            d.severity = essl::diagnostic::Severity::Note;
            d.message = if derivative {
                format!(
                    "`{name}` after a `discard` some pixels take, where derivatives are undefined"
                )
            } else {
                format!("`{name}` takes its mipmap level from derivatives, undefined after a `discard` some pixels take")
            };
            d.help = Some(if derivative {
                "take the derivative before the `discard`".to_string()
            } else {
                "do the lookup before the `discard`, or use `textureGrad` with derivatives taken before it (`textureLod` where the level is known)".to_string()
            });
            d = d.with_note("most GPUs keep a quad's discarded pixels running as helpers, which keeps the level right in practice; drivers that end them (SPIR-V's `OpKill`) do not");
        }
        out.push(d);
    }
}
