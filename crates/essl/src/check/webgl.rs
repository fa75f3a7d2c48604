//! The WebGL specification's own limits on a shader, beyond GLSL ES (WebGL 1.0 and 2.0,
//! "Differences Between WebGL and OpenGL ES", and ANGLE's checks for WebGL shaders), as
//! measured in `tests/oracle/ES100.md`:
//!
//! - structs nested at most 4 levels deep ("Maximum Nesting of Structures in GLSL Shaders");
//! - call chains at most 256 functions deep, counted in every function, called or not (ANGLE's
//!   `MaxCallStackDepth`);
//! - `gl_FragData` indexed with constant zero unless a WebGL 1 shader enabled
//!   `GL_EXT_draw_buffers` (WebGL 2 requires constant zero for GLSL ES 1.00 shaders).
//!
//! Token length, reserved prefixes and the character set are checked where the tokens are
//! read (`preprocess`, `Checker::check_name`); the size of variables in [`super::limits`]; the
//! packing of uniforms and varyings when linking.
//!
//! The checker's `impl` is spread over the files of the `check` module.

use super::Checker;
use crate::builtins::BuiltinVar;
use crate::diagnostic_code::Code;
use crate::hir::{Expr, ExprKind, GlobalKind};
use crate::source::Span;
use crate::target::{Extension, Target};
use crate::types::Type;
use crate::Stage;

/// The deepest nesting of structs WebGL allows: a struct's fields are at level 1.
pub const MAX_STRUCT_NESTING: u32 = 4;
/// The deepest chain of calls ANGLE allows, counting the functions in it.
pub const MAX_CALL_DEPTH: u32 = 256;

impl Checker<'_> {
    /// How deeply structs nest in a value of type `ty`: 0 for a non-struct, 1 for a struct of
    /// plain fields.
    pub(super) fn struct_depth(&self, ty: &Type) -> u32 {
        match ty {
            Type::Array(el, _) => self.struct_depth(el),
            Type::Struct(id) => self.struct_depths.get(id.0 as usize).copied().unwrap_or(1),
            _ => 0,
        }
    }

    /// A struct member of type `ty` named at `span` in a struct being declared: an error when
    /// the new struct would nest more than [`MAX_STRUCT_NESTING`] levels.
    pub(super) fn check_struct_nesting(&mut self, ty: &Type, name: &str, span: Span) {
        let depth = 1 + self.struct_depth(ty);
        if depth <= MAX_STRUCT_NESTING || self.struct_depth(ty) == 0 {
            return;
        }
        let inner = self.type_name(ty);
        let d = self.error(
            Code::StructNestingTooDeep,
            span,
            format!(
                "member `{name}` of type {inner} nests structs {depth} levels deep; WebGL allows \
                 {MAX_STRUCT_NESTING}"
            ),
        );
        d.label = "too deeply nested".into();
        d.notes.push(
            "WebGL counts a struct's own fields as level 1 (WebGL 1.0, \"Maximum Nesting of \
             Structures in GLSL Shaders\")"
                .into(),
        );
        d.help = Some("flatten the innermost structs into their parents".into());
    }

    /// Call chains deeper than [`MAX_CALL_DEPTH`] functions: reported once, at the first
    /// function (callees first) whose chain is too deep. Recursion is reported elsewhere.
    pub(super) fn check_call_depth(&mut self) {
        let n = self.functions.len();
        let mut depth: Vec<Option<u32>> = vec![None; n];
        let mut entered = vec![false; n];
        for start in 0..n {
            let mut stack = vec![(start, false)];
            while let Some((f, expanded)) = stack.pop() {
                if depth[f].is_some() || (entered[f] && !expanded) {
                    continue;
                }
                if !expanded {
                    entered[f] = true;
                    stack.push((f, true));
                    // A callee already entered is on a cycle (reported as recursion).
                    stack.extend(
                        self.functions[f]
                            .calls
                            .iter()
                            .filter(|&&c| !entered[c])
                            .map(|&c| (c, false)),
                    );
                    continue;
                }
                let d = 1 + self.functions[f]
                    .calls
                    .iter()
                    .filter_map(|&c| depth[c])
                    .max()
                    .unwrap_or(0);
                depth[f] = Some(d);
                if d > MAX_CALL_DEPTH {
                    let name = self.functions[f].name.clone();
                    let span = self.functions[f].span;
                    let e = self.error(
                        Code::CallStackTooDeep,
                        span,
                        format!(
                            "`{name}` starts a chain of {d} nested calls; WebGL allows \
                             {MAX_CALL_DEPTH}"
                        ),
                    );
                    e.label = "calls too deeply".into();
                    e.notes
                        .push("ANGLE counts every function, called from `main` or not".into());
                    e.help = Some("inline some of the functions in the chain".into());
                    return;
                }
            }
        }
    }

    /// In GLSL ES 1.00, `gl_FragData[index]`: a WebGL 1 shader needs `GL_EXT_draw_buffers`
    /// for an index other than 0, and WebGL 2 takes constant 0 only. Whether it was reported.
    pub(super) fn check_frag_data_index(&mut self, base: &Expr, index: &Expr) -> bool {
        if !matches!(base.kind, ExprKind::BuiltinVar(BuiltinVar::FragData)) {
            return false;
        }
        let zero = index.as_const().and_then(|c| c.as_int()) == Some(0);
        let enabled = self.lang.target == Target::WebGl1
            && self
                .lang
                .has_at(Extension::WebglDrawBuffers, index.span.start);
        if zero || enabled || (self.lang.target == Target::WebGl1 && index.as_const().is_none()) {
            return false;
        }
        let help = self.extension_help(
            Extension::WebglDrawBuffers,
            "more than one output is part of `WEBGL_draw_buffers`",
        );
        let d = self.error(
            Code::ExtensionRequired,
            index.span,
            "`gl_FragData` can only be indexed with 0 without `GL_EXT_draw_buffers`",
        );
        d.label = "not 0".into();
        d.token = "[]".into();
        d.help = Some(help);
        true
    }

    /// A fragment output indexed with an expression that is not constant (`o[i]`, an array of
    /// outputs or one output's vector components alike): Chromium refuses it (ANGLE's
    /// `addIndexExpression`). An index into an element of an output array (`o[1][i]`) or into a
    /// swizzle is not one. Whether it was reported.
    pub(super) fn check_output_index(&mut self, base: &Expr, index: &Expr) -> bool {
        if self.stage != Stage::Fragment || index.as_const().is_some() {
            return false;
        }
        let ExprKind::Global(g) = base.kind else {
            return false;
        };
        if self.globals[g].kind != GlobalKind::Output {
            return false;
        }
        let d = self.error(
            Code::DynamicOutputIndex,
            index.span,
            "a fragment output can only be indexed with a constant integral expression",
        );
        d.label = "not a constant expression".into();
        d.token = "[".into();
        d.notes.push(
            "WebGL implementations built on ANGLE (Chromium) refuse a run-time index into a \
             fragment output, an array of outputs or one output's components"
                .into(),
        );
        d.help = Some(
            "compute the value in a local and assign the output once, or use a constant index"
                .into(),
        );
        true
    }
}
