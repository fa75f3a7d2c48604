//! Which `in` parameters a function writes. GLSL lets a function assign its `in` parameters,
//! so the lowering copies each into a local; a scalar or vector parameter the body never
//! writes is read straight from its argument instead, which leaves the lowered function (and
//! what naga validates and the lints walk) a local, a store and a load per use smaller.

use crate::builtins::BuiltinFn;
use crate::hir::visit::{self, Visitor};
use crate::hir::{self, Expr, ExprKind, ParamMode};
use crate::types::Type;

/// For each parameter of `f`: whether it can be read from its argument — an `in` scalar or
/// vector that nothing in the body assigns, increments, or passes as an `out` or `inout`
/// argument (or as `modf`'s second argument).
pub(super) fn read_in_place(m: &hir::Module, f: &hir::Function) -> Vec<bool> {
    let mut w = Writes {
        module: m,
        written: vec![false; f.params.len()],
    };
    w.visit_stmts(&f.body);
    f.params
        .iter()
        .zip(&w.written)
        .map(|(p, &written)| {
            !written
                && p.mode == ParamMode::In
                && matches!(p.ty, Type::Scalar(_) | Type::Vector(..))
        })
        .collect()
}

/// The parameters a body writes.
struct Writes<'m> {
    module: &'m hir::Module,
    written: Vec<bool>,
}

impl Writes<'_> {
    /// Marks the parameter that the write target `e` is (part of).
    fn target(&mut self, e: &Expr) {
        if let ExprKind::Param(i) = e.write_root().kind {
            if let Some(w) = self.written.get_mut(i) {
                *w = true;
            }
        }
    }
}

impl Visitor for Writes<'_> {
    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Assign(_, l, _) | ExprKind::IncDec(_, _, l) => self.target(l),
            ExprKind::Call(id, args) => {
                if let Some(callee) = self.module.functions.get(*id) {
                    for (a, p) in args.iter().zip(&callee.params) {
                        if p.mode != ParamMode::In {
                            self.target(a);
                        }
                    }
                }
            }
            ExprKind::Builtin(BuiltinFn::Modf, args) => {
                if let Some(a) = args.get(1) {
                    self.target(a);
                }
            }
            _ => {}
        }
        visit::walk_expr(self, e);
    }
}

#[cfg(test)]
mod tests {
    use crate::source::SourceFile;
    use crate::{compile, CompileOptions, Stage};

    /// The local variables of the lowered function `f` of a fragment shader with `funcs`
    /// (which define `f(float, float, float, vec2, float[2])`), besides the lowering's own
    /// temporaries (`_essl_…`).
    fn locals_of_f(funcs: &str) -> Vec<String> {
        let text = format!(
            "#version 300 es\nprecision highp float;\nin float v;\nout vec4 o;\n{funcs}\n\
             void main() {{ o = vec4(f(v, v, v, vec2(v), float[2](v, v))); }}\n"
        );
        let s = compile(
            SourceFile::new("t.frag", text),
            Stage::Fragment,
            &CompileOptions::default(),
        );
        let m = &s.naga.as_ref().expect("compiles").module;
        let (_, f) = m
            .functions
            .iter()
            .find(|(_, f)| f.name.as_deref() == Some("f_"))
            .expect("f is lowered");
        f.local_variables
            .iter()
            .filter_map(|(_, l)| l.name.clone())
            .filter(|n| !n.starts_with("_essl_"))
            .collect()
    }

    #[test]
    fn written_and_aggregate_parameters_get_a_local_copy() {
        let funcs = "void g(inout float x) { x += 1.0; }\n\
                     float f(float a, float b, float c, vec2 d, float e[2]) {\n\
                       a = 2.0;\n\
                       g(b);\n\
                       float r = modf(d.x, c);\n\
                       return a + b + c + r + d.y + e[0];\n\
                     }";
        // `a` assigned, `b` passed as `inout`, `c` as `modf`'s `out`, `e` an array; `d` is
        // only read.
        assert_eq!(locals_of_f(funcs), ["a", "b", "c", "e", "r"]);
    }

    #[test]
    fn parameters_only_read_are_read_from_the_arguments() {
        let funcs = "float f(float a, float b, float c, vec2 d, float e[2]) {\n\
                       return a * b + c + d.x + d[int(a)] + e[1];\n\
                     }";
        assert_eq!(locals_of_f(funcs), ["e"]);
    }
}
