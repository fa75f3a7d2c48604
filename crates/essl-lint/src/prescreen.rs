//! Whether a shader needs lowering for the lints: the rules on naga IR look only at a few kinds
//! of operation ([`crate::rules::candidates`] finds them in the IR), and a shader whose checked
//! module has none of them, nor any built-in whose lowering makes one, is linted on its checked
//! module alone (`uninitialised-read`, `non-uniform-derivative`), without lowering it. On the
//! Vite bench's 200 shaders, 113 have none; lowering was 10.2 M of the 76.0 M instructions of
//! `essl lint` on them.
//!
//! The screen errs towards lowering: any call of a built-in that lowers to a division, a
//! square root, a power or a texel load, any `clamp` (whose constant bounds the IR rule
//! judges), and in a shader that names a low precision any product, or call of a built-in that
//! lowers to one or can amplify or underflow its argument, carried out in low precision
//! (`mediump-overflow` looks at those; the IR's expressions carry the spans of the checked
//! module's, by which [`Precisions`] are looked up). [`crate::lint`] checks in debug
//! builds that nothing the IR screen finds was missed here.

use essl::hir::visit::{self, Visitor};
use essl::hir::{BinaryOp, BuiltinFn, Expr, ExprKind, Init};
use essl::source::Span;
use essl::types::{ScalarKind, Type};
use essl::Shader;

use crate::precision::{names_low_precision, Precisions};

/// Whether any rule on naga IR may have something to look at in `shader` (a shader that did
/// not compile has nothing).
pub fn needs_ir(shader: &Shader) -> bool {
    if !shader.ok() {
        return false;
    }
    let text = shader.file.text();
    let m = &shader.module;
    let low = names_low_precision(text);
    let mut screen = Screen {
        low,
        products: Vec::new(),
        found: false,
    };
    for g in &m.globals {
        if let Some(Init::Expr(e)) = &g.init {
            screen.visit_expr(e);
        }
    }
    for f in &m.functions {
        screen.visit_stmts(&f.body);
    }
    // The precisions only where a product could be in low precision: most shaders that name
    // `mediump` have none that is not already a candidate.
    screen.found || {
        !screen.products.is_empty() && {
            let prec = Precisions::of(m);
            screen.products.iter().any(|s| prec.is_low(*s))
        }
    }
}

struct Screen {
    /// Whether the text names a low precision.
    low: bool,
    /// Where it does: the products and built-in calls that `mediump-overflow` looks at in low
    /// precision ([`low_product`]).
    products: Vec<Span>,
    found: bool,
}

impl Visitor for Screen {
    fn visit_expr(&mut self, e: &Expr) {
        if self.found {
            return;
        }
        let product = match &e.kind {
            ExprKind::Binary(op, ..) | ExprKind::Assign(Some(op), ..) => {
                self.found = matches!(op, BinaryOp::Div | BinaryOp::Mod);
                matches!(op, BinaryOp::Mul)
            }
            ExprKind::Builtin(f, args) => {
                self.found = lowers_to_candidate(*f, args);
                low_product(*f)
            }
            _ => false,
        };
        if product && self.low {
            self.products.push(e.span);
        }
        visit::walk_expr(self, e);
    }
}

/// Whether a call of built-in `f` lowers to what `mediump-overflow` looks at where it is carried
/// out in low precision: a product, or a function that can amplify its argument or underflow it
/// to 0 (a `texture` lookup, a `mix`, a `sin` does neither).
fn low_product(f: BuiltinFn) -> bool {
    use BuiltinFn::*;
    matches!(
        f,
        Pow | Exp
            | Exp2
            | Dot
            | Length
            | Distance
            | Normalize
            | Cosh
            | Sinh
            | InverseSqrt
            | Log
            | Log2
            | Mod
            | FaceForward
            | Reflect
            | Refract
            | MatrixCompMult
            | OuterProduct
    )
}

/// Whether a call of built-in `f` lowers to something the IR rules look at.
fn lowers_to_candidate(f: BuiltinFn, args: &[Expr]) -> bool {
    use BuiltinFn::*;
    match f {
        Pow | Acos | Asin | SmoothStep | Normalize | Sqrt | InverseSqrt | Log | Log2 | Mod
        | Refract | UnpackHalf2x16 | Clamp | TexelFetch | TexelFetchOffset => true,
        Atan => args.len() == 2,
        _ if f.is_texture() => {
            // A projective lookup divides by the last coordinate; an integer texture is read
            // with a texel load.
            let integer = args.first().is_some_and(
                |s| matches!(&s.ty, Type::Sampler(st) if st.kind != ScalarKind::Float),
            );
            integer || f.is_projective()
        }
        _ => false,
    }
}
