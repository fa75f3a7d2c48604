//! Appendix A of GLSL ES 1.00 as WebGL enforces it (WebGL 1.0 §"Supported GLSL Constructs",
//! ANGLE's checks for WebGL shaders of version 100, in both WebGL versions):
//!
//! - `while` and `do`-`while` loops are not allowed;
//! - a `for` loop has the form `for (TYPE i = CONST; i OP CONST; STEP)`, with one `int` or
//!   `float` index declared and initialized in the header, OP one of `<`, `<=`, `>`, `>=`,
//!   `==`, `!=` with the index on the left, and STEP one of `i++`, `i--`, `++i`, `--i`,
//!   `i += CONST`, `i -= CONST`;
//! - the body does not write the index (no assignment, no `out`/`inout` argument);
//! - every index into an array, matrix or vector is a constant-index-expression: constants and
//!   the indices of the enclosing loops, combined by operators, constructors and built-in
//!   functions (no user function) — except where a vertex shader indexes a uniform directly.
//!
//! Measured in `tests/oracle/ES100.md` ("Appendix A"). The checker's `impl` is spread over the
//! files of the `check` module; this one holds these rules.

use super::Checker;
use crate::ast::BinaryOp;
use crate::diagnostic_code::Code;
use crate::hir::{Cond, Expr, ExprKind, GlobalKind, LocalId, Stmt, StmtKind};
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

impl Checker<'_> {
    /// A `while` or `do`-`while` loop (`keyword`) in GLSL ES 1.00.
    pub(super) fn es100_unsupported_loop(&mut self, keyword: &str, span: Span) {
        if !self.lang.es100 {
            return;
        }
        let d = self.error(
            Code::UnsupportedLoop,
            span,
            format!("`{keyword}` loops are not allowed in GLSL ES 1.00 for WebGL"),
        );
        d.label = format!("a `{keyword}` loop");
        d.token = keyword.into();
        d.notes.push(
            "WebGL supports only the `for` loops of GLSL ES 1.00 Appendix A, whose trip count \
             is known when compiling"
                .into(),
        );
        d.help = Some(
            "write a `for` loop with a constant bound and `break` out of it, e.g. \
             `for (int i = 0; i < 64; i++) { if (!(cond)) break; … }`"
                .into(),
        );
    }

    /// Checks a `for` loop's header in GLSL ES 1.00; its index when the header is valid.
    pub(super) fn es100_for_header(
        &mut self,
        init: &[Stmt],
        cond: Option<&Cond>,
        step: Option<&Expr>,
        span: Span,
    ) -> Option<LocalId> {
        if !self.lang.es100 {
            return None;
        }
        let problem = match self.for_index(init) {
            Err(p) => Err(p),
            Ok(index) => for_condition(cond, index)
                .and_then(|()| for_step(step, index))
                .map(|()| index),
        };
        match problem {
            Ok(index) => Some(index),
            Err((msg, at)) => {
                let at = at.unwrap_or(span);
                let d = self.error(Code::UnsupportedLoop, at, msg);
                d.label = "not a loop header of GLSL ES 1.00 Appendix A".into();
                d.token = "for".into();
                d.notes.push(
                    "WebGL requires `for (TYPE i = CONST; i OP CONST; i++)` (or `i--`, `++i`, \
                     `--i`, `i += CONST`, `i -= CONST`), with an `int` or `float` index"
                        .into(),
                );
                None
            }
        }
    }

    /// The loop index a `for` init declares: one `int` or `float` local with a constant
    /// initializer.
    fn for_index(&self, init: &[Stmt]) -> Result<LocalId, (String, Option<Span>)> {
        let first = init.first();
        let (id, value) = match (init.len(), first.map(|s| &s.kind)) {
            (0, _) => {
                return Err((
                    "the loop needs an index declared in its header".into(),
                    None,
                ))
            }
            (1, Some(StmtKind::Local(id, Some(value)))) => (*id, value),
            _ => {
                return Err((
                    "the header must declare one loop index with an initializer".into(),
                    first.map(|s| s.span),
                ))
            }
        };
        let local = &self.fctx.as_ref().expect("in a function").locals[id];
        if !matches!(local.ty, Type::Scalar(ScalarKind::Int | ScalarKind::Float)) {
            return Err((
                format!(
                    "a loop index must be an `int` or a `float`, not `{}`",
                    local.ty.display(&self.structs)
                ),
                Some(local.span),
            ));
        }
        if value.as_const().is_none() {
            return Err((
                format!(
                    "the loop index `{}` must start at a constant expression",
                    local.name
                ),
                Some(value.span),
            ));
        }
        Ok(id)
    }

    /// Whether `l` is the index of an enclosing `for` loop (GLSL ES 1.00).
    fn is_loop_index(&self, l: LocalId) -> bool {
        self.fctx
            .as_ref()
            .is_some_and(|f| f.loop_indices.contains(&l))
    }

    /// In GLSL ES 1.00, an error when `e` (an assignment's target, an `out` argument) is an
    /// enclosing loop's index. Whether it was reported.
    pub(super) fn es100_writes_loop_index(&mut self, e: &Expr) -> bool {
        let ExprKind::Local(l) = e.kind else {
            return false;
        };
        if !self.lang.es100 || !self.is_loop_index(l) {
            return false;
        }
        let name = self.fctx.as_ref().expect("in a function").locals[l]
            .name
            .clone();
        let d = self.error(
            Code::LoopIndexAssigned,
            e.span,
            format!("the loop index `{name}` cannot be written in the loop's body"),
        );
        d.label = "writes the loop index".into();
        d.notes.push(
            "GLSL ES 1.00 Appendix A, which WebGL enforces, keeps a loop's trip count fixed".into(),
        );
        d.help = Some(format!("copy it to a local first: `int j = {name};`"));
        true
    }

    /// In GLSL ES 1.00, an error when `index` (into `base`) is not a constant-index-expression
    /// and `base` is not a uniform a vertex shader indexes. Whether it was reported.
    pub(super) fn es100_check_index(&mut self, base: &Expr, index: &Expr) -> bool {
        if !self.lang.es100 || index.as_const().is_some() {
            return false;
        }
        if self.stage == Stage::Vertex {
            if let ExprKind::Global(g) = base.kind {
                if self.globals[g].kind == GlobalKind::Uniform {
                    return false;
                }
            }
        }
        let Some((why, at)) = self.not_constant_index(index) else {
            return false;
        };
        let d = self.error(Code::NonConstantIndex, at, why);
        d.label = "not a constant-index-expression".into();
        d.token = "[".into();
        d.notes.push(
            "WebGL allows only constant-index-expressions as indices in GLSL ES 1.00: \
             constants and loop indices (Appendix A §5); a vertex shader may index its uniforms \
             with anything"
                .into(),
        );
        d.help = Some(
            "index with a `for` loop's index, or select the element with `if`s over the \
             possible indices; `#version 300 es` (WebGL 2) lifts the restriction"
                .into(),
        );
        true
    }

    /// Why an expression is not a constant-index-expression, and where.
    fn not_constant_index(&self, e: &Expr) -> Option<(String, Span)> {
        match &e.kind {
            ExprKind::Const(_) | ExprKind::Error => None,
            ExprKind::Local(l) if self.is_loop_index(*l) => None,
            ExprKind::Local(l) => {
                let name = &self.fctx.as_ref()?.locals[*l].name;
                Some((
                    format!("`{name}` is neither a constant nor a loop index"),
                    e.span,
                ))
            }
            ExprKind::Param(i) => {
                let f = self.fctx.as_ref()?.func;
                let name = &self.functions[f].params[*i].name;
                Some((format!("parameter `{name}` is not a constant"), e.span))
            }
            ExprKind::Global(g) => Some((
                format!("`{}` is not a constant", self.globals[*g].name),
                e.span,
            )),
            ExprKind::BuiltinVar(v) => Some((format!("`{}` is not a constant", v.name()), e.span)),
            ExprKind::Call(..) => Some((
                "an index cannot contain a call to a user function".into(),
                e.span,
            )),
            ExprKind::BlockMember(..) => {
                Some(("a uniform block member is not a constant".into(), e.span))
            }
            ExprKind::Unary(_, a)
            | ExprKind::IncDec(_, _, a)
            | ExprKind::Member(a, _)
            | ExprKind::Swizzle(a, _) => self.not_constant_index(a),
            ExprKind::Binary(_, a, b)
            | ExprKind::Assign(_, a, b)
            | ExprKind::Comma(a, b)
            | ExprKind::Index(a, b) => self
                .not_constant_index(a)
                .or_else(|| self.not_constant_index(b)),
            ExprKind::Select(c, a, b) => self
                .not_constant_index(c)
                .or_else(|| self.not_constant_index(a))
                .or_else(|| self.not_constant_index(b)),
            ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
                args.iter().find_map(|a| self.not_constant_index(a))
            }
        }
    }

    /// Runs `body` with `index` marked as an enclosing loop's index.
    pub(super) fn with_loop_index<T>(
        &mut self,
        index: Option<LocalId>,
        body: impl FnOnce(&mut Self) -> T,
    ) -> T {
        if let (Some(i), Some(f)) = (index, self.fctx.as_mut()) {
            f.loop_indices.push(i);
        }
        let out = body(self);
        if let (Some(_), Some(f)) = (index, self.fctx.as_mut()) {
            f.loop_indices.pop();
        }
        out
    }
}

/// `index OP CONST`.
fn for_condition(cond: Option<&Cond>, index: LocalId) -> Result<(), (String, Option<Span>)> {
    let e = match cond {
        None => return Err(("the loop needs a condition on its index".into(), None)),
        Some(Cond::Expr(e)) => e,
        Some(Cond::Decl(..)) => {
            return Err((
                "a loop condition cannot declare a variable here".into(),
                None,
            ))
        }
    };
    use BinaryOp::*;
    let ExprKind::Binary(op, l, r) = &e.kind else {
        return Err((
            "the condition must compare the loop index with a constant".into(),
            Some(e.span),
        ));
    };
    if !matches!(op, Less | Greater | LessEq | GreaterEq | Eq | NotEq) {
        return Err((
            format!("`{}` is not a comparison of the loop index", op.as_str()),
            Some(e.span),
        ));
    }
    if !matches!(l.kind, ExprKind::Local(i) if i == index) {
        return Err((
            "the loop index must be on the left of the comparison".into(),
            Some(l.span),
        ));
    }
    if r.as_const().is_none() {
        return Err((
            "the loop index must be compared with a constant expression".into(),
            Some(r.span),
        ));
    }
    Ok(())
}

/// `i++`, `i--`, `++i`, `--i`, `i += CONST`, `i -= CONST`.
fn for_step(step: Option<&Expr>, index: LocalId) -> Result<(), (String, Option<Span>)> {
    let Some(e) = step else {
        return Err(("the loop needs a step that changes its index".into(), None));
    };
    let is_index = |x: &Expr| matches!(x.kind, ExprKind::Local(i) if i == index);
    match &e.kind {
        ExprKind::IncDec(_, _, x) if is_index(x) => Ok(()),
        ExprKind::Assign(Some(BinaryOp::Add | BinaryOp::Sub), x, v) if is_index(x) => {
            if v.as_const().is_some() {
                Ok(())
            } else {
                Err((
                    "the loop index must change by a constant expression".into(),
                    Some(v.span),
                ))
            }
        }
        _ => Err((
            "the step must be `i++`, `i--`, `++i`, `--i`, `i += CONST` or `i -= CONST` on the \
             loop index"
                .into(),
            Some(e.span),
        )),
    }
}
