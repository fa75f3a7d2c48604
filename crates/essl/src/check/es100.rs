//! Where GLSL ES 1.00 differs from 3.00 in what the checker reports, and the help it offers when
//! a shader mixes the two languages (`texture2D` in a `#version 300 es` shader, `%` in a GLSL
//! ES 1.00 one). The loop and indexing rules of Appendix A are in [`super::appendix_a`].
//!
//! The checker's `impl` is spread over the files of the `check` module; this one holds the
//! helpers the others call where the language version matters.

use super::Checker;
use crate::ast::BinaryOp;
use crate::builtins::{BuiltinVar, Signature};
use crate::diagnostic::{Diagnostic, Fix, Label};
use crate::diagnostic_code::Code;
use crate::source::Span;
use crate::target::{Extension, Target};
use crate::Stage;

/// What GLSL ES 1.00 offers instead of a GLSL ES 3.00 operator.
fn es100_operator_help(op: &str) -> &'static str {
    match op {
        "%" | "%=" => "use `mod(x, y)` on floats",
        "<<" | ">>" | "<<=" | ">>=" => "multiply or divide by a power of two",
        _ => "GLSL ES 1.00 has no bitwise operators: write the arithmetic out, or port the shader to `#version 300 es`",
    }
}

impl Checker<'_> {
    /// Reports a GLSL ES 3.00 feature (`what`, a phrase) used in a GLSL ES 1.00 shader; the
    /// caller completes the diagnostic.
    pub(super) fn not_in_es100(&mut self, span: Span, what: &str) -> &mut Diagnostic {
        let d = self.error(
            Code::NotInEs100,
            span,
            format!("{what} is GLSL ES 3.00: this shader is GLSL ES 1.00"),
        );
        d.label = "not in GLSL ES 1.00".into();
        d.notes
            .push("a shader without `#version 300 es` on its first line is GLSL ES 1.00".into());
        d
    }

    /// In GLSL ES 1.00, an error for the `%`, bitwise and shift operators (`op` as written);
    /// whether one was reported.
    pub(super) fn es100_operator(&mut self, op: &str, span: Span) -> bool {
        if !self.lang.es100 {
            return false;
        }
        let what = match op {
            "%" | "%=" => "the integer modulus operator",
            "<<" | ">>" | "<<=" | ">>=" => "the shift operator",
            _ => "the bitwise operator",
        };
        let d = self.not_in_es100(span, &format!("{what} `{op}`"));
        d.token = op.into();
        d.help = Some(es100_operator_help(op).into());
        true
    }

    /// The help for a built-in variable of the other language version, or of an extension the
    /// shader has not enabled.
    pub(super) fn other_language_builtin(&self, name: &str) -> Option<String> {
        if self.lang.es100 {
            return match name {
                "gl_FragDepth" | "gl_FragDepthEXT" => Some(self.extension_help(
                    Extension::ExtFragDepth,
                    "GLSL ES 1.00 writes the depth to `gl_FragDepthEXT`",
                )),
                "gl_VertexID" | "gl_InstanceID" => Some(format!(
                    "`{name}` is GLSL ES 3.00: start the shader with `#version 300 es` (WebGL 2)"
                )),
                "gl_MaxVertexOutputVectors" | "gl_MaxFragmentInputVectors" => {
                    Some("GLSL ES 1.00 has `gl_MaxVaryingVectors`".into())
                }
                _ => None,
            };
        }
        match name {
            "gl_FragDepthEXT" => Some("GLSL ES 3.00 calls it `gl_FragDepth`".into()),
            "gl_MaxVaryingVectors" => Some(
                "GLSL ES 3.00 has `gl_MaxVertexOutputVectors` and `gl_MaxFragmentInputVectors`"
                    .into(),
            ),
            _ => None,
        }
    }

    /// How to get a WebGL 1 extension's feature, after `intro` (a sentence).
    pub(super) fn extension_help(&self, e: Extension, intro: &str) -> String {
        let directive = format!("#extension {} : enable", e.directive_name());
        match self.lang.target {
            Target::WebGl2 => format!(
                "{intro}, which needs `{directive}` in a WebGL 1 context; WebGL 2 offers it to \
                 `#version 300 es` shaders only"
            ),
            Target::WebGl1 if !self.lang.context_has(e) => format!(
                "{intro}: the WebGL 1 context must enable `{}` (`getExtension`) and the shader \
                 must say `{directive}`",
                e.webgl_name()
            ),
            Target::WebGl1 => format!("{intro}: add `{directive}` at the top of the shader"),
        }
    }

    /// Reports a built-in overload the shader may not use here: one of a WebGL 1 extension it
    /// has not enabled, or one for the other stage. Whether it was reported.
    pub(super) fn builtin_unavailable(&mut self, name: &str, sig: &Signature, at: Span) -> bool {
        if let Some(e) = sig.extension {
            if !self.lang.has_at(e, at.start) {
                let help =
                    self.extension_help(e, &format!("`{name}` is part of `{}`", e.webgl_name()));
                let at_top = Span::empty(0);
                let fixable = self.lang.target == Target::WebGl1 && self.lang.context_has(e);
                let help = if fixable {
                    format!(
                        "`{name}` is part of `{}`: enable it at the top of the shader",
                        e.webgl_name()
                    )
                } else {
                    help
                };
                let d = self.error(
                    Code::ExtensionRequired,
                    at,
                    format!("`{name}` needs the `{}` extension", e.webgl_name()),
                );
                d.label = "extension not enabled".into();
                d.help = Some(help);
                if fixable {
                    d.fix = Some(Fix::suggested(
                        format!("enable `{}`", e.directive_name()),
                        at_top,
                        format!("#extension {} : enable\n", e.directive_name()),
                    ));
                }
                return true;
            }
        }
        if sig.vertex_only && self.stage != Stage::Vertex {
            let help = self.extension_help(
                Extension::ExtShaderTextureLod,
                &format!("a fragment shader calls it `{name}EXT`"),
            );
            let d = self.error(
                Code::FragmentOnlyBuiltin,
                at,
                format!("`{name}` is only available in vertex shaders in GLSL ES 1.00"),
            );
            d.label = "not available in a fragment shader".into();
            d.help = Some(help);
            return true;
        }
        false
    }

    /// Records a use of `gl_FragColor` or `gl_FragData` (GLSL ES 1.00 allows one of them).
    pub(super) fn note_fragment_output(&mut self, v: BuiltinVar, span: Span) {
        let slot = match v {
            BuiltinVar::FragColor => &mut self.frag_color_use,
            BuiltinVar::FragData => &mut self.frag_data_use,
            _ => return,
        };
        if slot.is_none() {
            *slot = Some(span);
        }
    }

    /// A fragment shader may use `gl_FragColor` or `gl_FragData`, not both.
    pub(super) fn check_frag_color_and_data(&mut self) {
        let (Some(color), Some(data)) = (self.frag_color_use, self.frag_data_use) else {
            return;
        };
        let (first, second, second_name) = if color.start < data.start {
            (color, data, "gl_FragData")
        } else {
            (data, color, "gl_FragColor")
        };
        let d = self.error(
            Code::FragColorAndFragData,
            second,
            "a fragment shader cannot use both `gl_FragColor` and `gl_FragData`",
        );
        d.label = format!("`{second_name}` here");
        d.secondary.push(Label {
            span: first,
            message: "the other one here".into(),
        });
        d.help = Some(
            "write all outputs through `gl_FragData[n]`, or the single one through `gl_FragColor`"
                .into(),
        );
    }

    /// In GLSL ES 1.00, whether a binary operator is one of GLSL ES 3.00's integer operators.
    pub(super) fn is_es300_operator(op: BinaryOp) -> bool {
        use BinaryOp::*;
        matches!(op, Mod | Shl | Shr | BitAnd | BitOr | BitXor)
    }
}

impl Checker<'_> {
    /// In GLSL ES 1.00, `=`, `==` and `!=` are not defined on arrays and on structs containing
    /// arrays (GLSL ES 1.00 §5.7–5.9). Whether `e` is such an operand (reported).
    pub(super) fn es100_array_operand(
        &mut self,
        e: &crate::hir::Expr,
        op: &str,
        span: Span,
    ) -> bool {
        if !self.lang.es100 {
            return false;
        }
        let what = if e.ty.is_array() {
            "arrays"
        } else if matches!(e.ty, crate::types::Type::Struct(_))
            && e.ty.contains_array(&self.structs)
        {
            "structs containing arrays"
        } else {
            return false;
        };
        let d = self.error(
            Code::NotInEs100,
            span,
            format!("`{op}` is not defined on {what} in GLSL ES 1.00"),
        );
        d.label = format!("an operand is one of the {what}");
        d.token = op.into();
        d.help = Some(if op == "=" {
            "assign the elements one by one".into()
        } else {
            "compare the elements one by one".into()
        });
        true
    }
}
