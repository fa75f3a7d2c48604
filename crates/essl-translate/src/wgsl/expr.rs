//! Expressions, with the parentheses WGSL's grammar needs and no others.
//!
//! WGSL's grammar is stricter than C's: `&&` and `||` do not mix, a bitwise operator's
//! operands are unary expressions (`(a & b) == c`), a shift's too, and comparisons do not
//! chain. Each written expression carries its level (below), and an operand is put in
//! parentheses only when its level is below what the grammar wants there. Literals are bare
//! (`0.5`) unless both operands of an operation would be abstract (WGSL would then compute
//! in abstract precision, not in `f32` as the IR does), or a conversion needs a type.

use naga::{BinaryOperator as B, Expression, Handle, TypeInner};

use super::bake::Fate;
use super::doc::Doc;
use super::func::FnCtx;
use super::types::{literal, matrix, scalar, vector, LiteralForm};
use super::Env;
use crate::TranslateError;

/// `||`
const OR: u8 = 1;
/// `&&`
const AND: u8 = 2;
/// `&`, `|`, `^`
const BIT: u8 = 3;
/// `==`, `<`…
const REL: u8 = 4;
/// `<<`, `>>`
const SHIFT: u8 = 5;
/// `+`, `-`
const ADD: u8 = 6;
/// `*`, `/`, `%`
const MUL: u8 = 7;
/// `-x`, `!x`, `*p`, `&x`
pub(crate) const UNARY: u8 = 8;
/// Names, literals, calls, `x.y`, `x[i]`, `(…)`.
pub(crate) const POSTFIX: u8 = 9;

/// A written expression.
pub(crate) struct W {
    pub doc: Doc,
    pub level: u8,
    /// The operator, for a binary expression (`a & b & c` chains without parentheses).
    op: Option<B>,
    /// Whether it is an abstract literal (takes its type from its context).
    pub abstract_: bool,
}

impl W {
    fn new(doc: Doc, level: u8) -> W {
        W {
            doc,
            level,
            op: None,
            abstract_: false,
        }
    }

    fn text(s: impl Into<String>) -> W {
        W::new(Doc::text(s), POSTFIX)
    }

    /// In parentheses when its level is below `need` (and it is not a chain of `same`).
    pub(crate) fn at(self, need: u8, same: Option<B>) -> Doc {
        if self.level >= need || (same.is_some() && self.op == same) {
            self.doc
        } else {
            Doc::Cat(vec![Doc::text("("), self.doc, Doc::text(")")])
        }
    }
}

/// How an expression of pointer type is wanted (as naga's WGSL writer says it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Indirection {
    /// A WGSL pointer (`&x`, or a pointer argument `p`).
    Ordinary,
    /// A WGSL reference (`x`, `*p`): what a load reads and a store writes.
    Reference,
}

type Result<T> = std::result::Result<T, TranslateError>;

impl FnCtx<'_> {
    /// The text of an expression as a value; `concrete` when it must not be an abstract
    /// literal.
    pub(crate) fn value(&self, h: Handle<Expression>, concrete: bool) -> Result<W> {
        if let Some(name) = self.baked_name(h) {
            return Ok(W::text(name));
        }
        self.definition(h, concrete)
    }

    /// The text of an expression itself, even when it has a `let` (for that `let`).
    pub(crate) fn definition(&self, h: Handle<Expression>, concrete: bool) -> Result<W> {
        if !self.shape.is_pointer(h) {
            return self.plain(h, concrete);
        }
        self.place(h, Indirection::Ordinary, concrete)
    }

    /// The expression as a pointer or reference, as `want`ed.
    pub(crate) fn place(
        &self,
        h: Handle<Expression>,
        want: Indirection,
        concrete: bool,
    ) -> Result<W> {
        if let Some(name) = self.baked_name(h) {
            return Ok(W::text(name));
        }
        if !self.shape.is_pointer(h) {
            return self.plain(h, concrete);
        }
        let plain = self.indirection(h);
        let w = self.plain(h, concrete)?;
        Ok(match (want, plain) {
            (Indirection::Ordinary, Indirection::Reference) => {
                W::new(Doc::Cat(vec![Doc::text("&"), w.at(UNARY, None)]), UNARY)
            }
            (Indirection::Reference, Indirection::Ordinary) => {
                W::new(Doc::Cat(vec![Doc::text("*"), w.at(UNARY, None)]), UNARY)
            }
            _ => w,
        })
    }

    /// What the plain text of a pointer expression is: a reference (a variable, or an access
    /// into one) or a pointer (an argument).
    fn indirection(&self, h: Handle<Expression>) -> Indirection {
        match *self.shape.expr(h) {
            Expression::LocalVariable(_) => Indirection::Reference,
            Expression::GlobalVariable(g) => match self.shape.module.global_variables[g].space {
                naga::AddressSpace::Handle => Indirection::Ordinary,
                _ => Indirection::Reference,
            },
            Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => {
                if self.shape.is_pointer(base) {
                    Indirection::Reference
                } else {
                    Indirection::Ordinary
                }
            }
            _ => Indirection::Ordinary,
        }
    }

    /// The text of an expression, without `&` or `*`.
    fn plain(&self, h: Handle<Expression>, concrete: bool) -> Result<W> {
        if let Some(alias) = self.alias(h) {
            return Ok(W::text(alias));
        }
        let e = self.shape.expr(h);
        Ok(match *e {
            Expression::Literal(l) => literal_w(l, concrete),
            Expression::Constant(c) => {
                let named = &self.shape.module.constants[c];
                if named.name.is_some() {
                    W::text(self.names.get(naga::proc::NameKey::Constant(c)))
                } else {
                    constant(self.env, named.init, concrete)?
                }
            }
            Expression::ZeroValue(ty) => zero(self.env, ty, concrete),
            Expression::Compose { ty, ref components } => self.compose(h, ty, components)?,
            Expression::Splat { value, .. } => {
                let ty = self.type_of(h);
                W::new(
                    Doc::List {
                        head: ty,
                        args: vec![self.value(value, false)?.doc],
                    },
                    POSTFIX,
                )
            }
            Expression::Access { base, index } => {
                let b = self
                    .place(base, Indirection::Reference, false)?
                    .at(POSTFIX, None);
                let i = self.value(index, false)?.doc;
                W::new(
                    Doc::Cat(vec![b, Doc::text("["), i, Doc::text("]")]),
                    POSTFIX,
                )
            }
            Expression::AccessIndex { base, index } => self.access_index(h, base, index)?,
            Expression::Swizzle {
                size,
                vector,
                pattern,
            } if self.identity_swizzle(size, vector, &pattern) => self.value(vector, concrete)?,
            Expression::Swizzle {
                size,
                vector,
                pattern,
            } => {
                let b = self.value(vector, false)?.at(POSTFIX, None);
                let set = self.letters(h);
                let letters: String = pattern[..size as usize]
                    .iter()
                    .map(|c| set[*c as usize])
                    .collect();
                W::new(Doc::Cat(vec![b, Doc::text(format!(".{letters}"))]), POSTFIX)
            }
            Expression::FunctionArgument(k) => W::text(self.argument_name(k)),
            Expression::GlobalVariable(g) => {
                W::text(self.names.get(naga::proc::NameKey::GlobalVariable(g)))
            }
            Expression::LocalVariable(l) => W::text(self.local_name(l)),
            Expression::Load { pointer } => {
                self.place(pointer, Indirection::Reference, concrete)?
            }
            Expression::Unary { op, expr } => self.unary(op, expr, concrete)?,
            Expression::Binary { op, left, right } => self.binary(op, left, right)?,
            Expression::Select {
                condition,
                accept,
                reject,
            } => {
                let r = self.value(reject, concrete)?;
                let a = self.value(accept, false)?;
                let abstract_ = r.abstract_ && a.abstract_;
                let c = self.value(condition, false)?;
                let mut w = call("select", vec![r.doc, a.doc, c.doc]);
                w.abstract_ = abstract_;
                w
            }
            Expression::Math {
                fun,
                arg,
                arg1,
                arg2,
                arg3,
            } => self.math(fun, [Some(arg), arg1, arg2, arg3])?,
            Expression::As {
                expr,
                kind,
                convert,
            } => self.convert(expr, kind, convert)?,
            Expression::Derivative { axis, ctrl, expr } => {
                use naga::{DerivativeAxis as A, DerivativeControl as C};
                let base = match axis {
                    A::X => "dpdx",
                    A::Y => "dpdy",
                    A::Width => "fwidth",
                };
                let suffix = match ctrl {
                    C::Coarse => "Coarse",
                    C::Fine => "Fine",
                    C::None => "",
                };
                call(
                    &format!("{base}{suffix}"),
                    vec![self.value(expr, false)?.doc],
                )
            }
            Expression::Relational { fun, argument } => {
                let name = match fun {
                    naga::RelationalFunction::All => "all",
                    naga::RelationalFunction::Any => "any",
                    other => return Err(self.unsupported(format!("{other:?}"))),
                };
                call(name, vec![self.value(argument, false)?.doc])
            }
            Expression::CallResult(_) => self.call_result(h)?,
            Expression::ArrayLength(x) => call(
                "arrayLength",
                vec![self.place(x, Indirection::Ordinary, false)?.doc],
            ),
            Expression::ImageSample { .. }
            | Expression::ImageLoad { .. }
            | Expression::ImageQuery { .. } => self.image(e)?,
            ref other => return Err(self.unsupported(format!("{other:?}"))),
        })
    }

    /// A constructor: swizzle runs as swizzles (`vec4f(v, 1.0)`), all-equal literal
    /// components once (`vec3f(0.0)`), a whole swizzle without its constructor.
    fn compose(
        &self,
        h: Handle<Expression>,
        ty: Handle<naga::Type>,
        components: &[Handle<Expression>],
    ) -> Result<W> {
        let head = self.type_name(ty);
        if let Some(copy) = self.struct_copy(&head, components)? {
            return Ok(copy);
        }
        let runs = self.shape.runs.get(&h);
        let mut args = Vec::new();
        let mut k = 0;
        while k < components.len() {
            if let Some(run) = runs.and_then(|rs| rs.iter().find(|r| r.start == k)) {
                let base = if run.load {
                    self.place(run.base, Indirection::Reference, false)?
                } else {
                    self.value(run.base, false)?
                };
                let whole = self.vector_size(run.base) == Some(run.pattern.len())
                    && run
                        .pattern
                        .iter()
                        .enumerate()
                        .all(|(i, c)| *c as usize == i);
                if whole {
                    args.push(base.doc);
                } else {
                    let letters: String = run
                        .pattern
                        .iter()
                        .map(|c| ['x', 'y', 'z', 'w'][*c as usize])
                        .collect();
                    args.push(Doc::Cat(vec![
                        base.at(POSTFIX, None),
                        Doc::text(format!(".{letters}")),
                    ]));
                }
                if run.start == 0 && run.pattern.len() == components.len() {
                    // `vec3(v4)`: the swizzle is the value.
                    return Ok(W::new(args.pop().expect("the run"), POSTFIX));
                }
                k += run.pattern.len();
                continue;
            }
            args.push(self.value(components[k], false)?.doc);
            k += 1;
        }
        let vector = matches!(self.shape.module.types[ty].inner, TypeInner::Vector { .. });
        let first = components.first().map(|c| self.shape.expr(*c));
        if vector
            && runs.is_none()
            && matches!(first, Some(Expression::Literal(_)))
            && components
                .iter()
                .all(|c| Some(self.shape.expr(*c)) == first)
        {
            args.truncate(1);
        }
        Ok(W::new(Doc::List { head, args }, POSTFIX))
    }

    /// The component letters the GLSL wrote at `h` (`.rgb` stays `.rgb`; WGSL has no `.stp`).
    fn letters(&self, h: Handle<Expression>) -> [char; 4] {
        const XYZW: [char; 4] = ['x', 'y', 'z', 'w'];
        let span = self.shape.function.expressions.get_span(h);
        let (Some(file), Some(range)) = (self.file, span.to_range()) else {
            return XYZW;
        };
        let Some(text) = self.env.texts.get(file).and_then(|t| t.get(range)) else {
            return XYZW;
        };
        let tail = text.rsplit('.').next().unwrap_or("");
        if !tail.is_empty() && tail.chars().all(|c| "rgba".contains(c)) {
            ['r', 'g', 'b', 'a']
        } else {
            XYZW
        }
    }

    /// `S(v.a, v.b, …)` of every member of a `v` whose type is written as `S` (a std140
    /// copy of `S`): `v`.
    fn struct_copy(&self, head: &str, components: &[Handle<Expression>]) -> Result<Option<W>> {
        let mut base = None;
        for (i, &c) in components.iter().enumerate() {
            let (b, load) = match *self.shape.expr(c) {
                Expression::AccessIndex { base, index } if index as usize == i => (base, false),
                Expression::Load { pointer } => match *self.shape.expr(pointer) {
                    Expression::AccessIndex { base, index } if index as usize == i => (base, true),
                    _ => return Ok(None),
                },
                _ => return Ok(None),
            };
            if base.is_some_and(|x| x != (b, load)) || self.bakes.fate[c.index()] == Fate::Bake {
                return Ok(None);
            }
            base = Some((b, load));
        }
        let Some((b, load)) = base else {
            return Ok(None);
        };
        let struct_ty = match (load, self.shape.ty(b)) {
            (true, TypeInner::Pointer { base, .. }) => Some(*base),
            (false, _) => self.shape.info[b].ty.handle(),
            _ => None,
        };
        let count = struct_ty.and_then(|t| match &self.shape.module.types[t].inner {
            TypeInner::Struct { members, .. } => Some(members.len()),
            _ => None,
        });
        if count != Some(components.len())
            || struct_ty.map(|t| self.type_name(t)).as_deref() != Some(head)
        {
            return Ok(None);
        }
        Ok(Some(if load {
            self.place(b, Indirection::Reference, false)?
        } else {
            self.value(b, false)?
        }))
    }

    /// The scalar of a `Splat` written where it is used.
    fn splatted(&self, h: Handle<Expression>) -> Option<Handle<Expression>> {
        match *self.shape.expr(h) {
            Expression::Splat { value, .. } if self.baked_name(h).is_none() => Some(value),
            _ => None,
        }
    }

    fn is_vector(&self, h: Handle<Expression>) -> bool {
        matches!(self.shape.ty(h), TypeInner::Vector { .. })
    }

    /// Whether a swizzle takes every component in order (`v.xyzw` of a `vec4`).
    pub(crate) fn identity_swizzle(
        &self,
        size: naga::VectorSize,
        vector: Handle<Expression>,
        pattern: &[naga::SwizzleComponent; 4],
    ) -> bool {
        self.vector_size(vector) == Some(size as usize)
            && pattern[..size as usize]
                .iter()
                .enumerate()
                .all(|(i, c)| *c as usize == i)
    }

    fn vector_size(&self, h: Handle<Expression>) -> Option<usize> {
        match *self.shape.ty(h) {
            TypeInner::Vector { size, .. } => Some(size as usize),
            TypeInner::Pointer { base, .. } => match self.shape.module.types[base].inner {
                TypeInner::Vector { size, .. } => Some(size as usize),
                _ => None,
            },
            TypeInner::ValuePointer { size, .. } => size.map(|s| s as usize),
            _ => None,
        }
    }

    fn access_index(
        &self,
        h: Handle<Expression>,
        base: Handle<Expression>,
        index: u32,
    ) -> Result<W> {
        let b = self
            .place(base, Indirection::Reference, false)?
            .at(POSTFIX, None);
        let mut inner = self.shape.ty(base);
        let mut struct_ty = self.shape.info[base].ty.handle();
        if let TypeInner::Pointer { base: t, .. } = *inner {
            inner = &self.shape.module.types[t].inner;
            struct_ty = Some(t);
        }
        let suffix = match *inner {
            TypeInner::Vector { .. } | TypeInner::ValuePointer { size: Some(_), .. } => {
                format!(".{}", self.letters(h)[index as usize])
            }
            TypeInner::Struct { .. } => {
                let ty = struct_ty.ok_or_else(|| self.unsupported("an unnamed struct".into()))?;
                format!(
                    ".{}",
                    self.names.get(naga::proc::NameKey::StructMember(ty, index))
                )
            }
            _ => format!("[{index}]"),
        };
        Ok(W::new(Doc::Cat(vec![b, Doc::text(suffix)]), POSTFIX))
    }

    fn unary(
        &self,
        op: naga::UnaryOperator,
        expr: Handle<Expression>,
        concrete: bool,
    ) -> Result<W> {
        let sign = match op {
            naga::UnaryOperator::Negate => "-",
            naga::UnaryOperator::LogicalNot => "!",
            naga::UnaryOperator::BitwiseNot => "~",
        };
        let inner = self.value(expr, concrete)?;
        let abstract_ = inner.abstract_;
        let starts_with_sign = inner.doc.flat().starts_with(['-', '!', '~', '&', '*']);
        let operand = if starts_with_sign && sign == "-" {
            Doc::Cat(vec![Doc::text("("), inner.doc, Doc::text(")")])
        } else {
            inner.at(UNARY, None)
        };
        let mut w = W::new(Doc::Cat(vec![Doc::text(sign), operand]), UNARY);
        w.abstract_ = abstract_;
        Ok(w)
    }

    fn binary(&self, op: B, left: Handle<Expression>, right: Handle<Expression>) -> Result<W> {
        let (text, level) = match op {
            B::Add => ("+", ADD),
            B::Subtract => ("-", ADD),
            B::Multiply => ("*", MUL),
            B::Divide => ("/", MUL),
            B::Modulo => ("%", MUL),
            B::Equal => ("==", REL),
            B::NotEqual => ("!=", REL),
            B::Less => ("<", REL),
            B::LessEqual => ("<=", REL),
            B::Greater => (">", REL),
            B::GreaterEqual => (">=", REL),
            B::And => ("&", BIT),
            B::ExclusiveOr => ("^", BIT),
            B::InclusiveOr => ("|", BIT),
            B::LogicalAnd => ("&&", AND),
            B::LogicalOr => ("||", OR),
            B::ShiftLeft => ("<<", SHIFT),
            B::ShiftRight => (">>", SHIFT),
        };
        // WGSL has `v * s` and `v + s`: a splatted operand is the scalar.
        let arithmetic = matches!(
            op,
            B::Add | B::Subtract | B::Multiply | B::Divide | B::Modulo
        );
        let (left, right) = match (arithmetic, self.splatted(left), self.splatted(right)) {
            (true, Some(s), None) if self.is_vector(right) => (s, right),
            (true, None, Some(s)) if self.is_vector(left) => (left, s),
            _ => (left, right),
        };
        let r = self.value(right, false)?;
        // Two abstract literals would be computed in abstract precision: type the left one.
        let l = self.value(left, r.abstract_ || level == SHIFT)?;
        let (l_need, r_need, chain) = match level {
            MUL => (MUL, UNARY, None),
            ADD => (ADD, MUL, None),
            SHIFT => (UNARY, UNARY, None),
            REL => (SHIFT, SHIFT, None),
            BIT => (UNARY, UNARY, Some(op)),
            _ => (REL, REL, Some(op)),
        };
        // A chain of one level (`a * b / c`) is one list of operands, to break where long.
        let bare = l.level >= l_need || (chain.is_some() && l.op == chain);
        let same_level =
            bare && l.level == level && l.op.is_some() && (level >= ADD || l.op == Some(op));
        let right = r.at(r_need, None);
        let doc = match l.doc {
            Doc::Ops { first, mut rest } if same_level => {
                rest.push((text.to_owned(), right));
                Doc::Ops { first, rest }
            }
            _ => Doc::Ops {
                first: Box::new(l.at(l_need, chain)),
                rest: vec![(text.to_owned(), right)],
            },
        };
        Ok(W {
            doc,
            level,
            op: Some(op),
            abstract_: false,
        })
    }

    fn math(&self, fun: naga::MathFunction, args: [Option<Handle<Expression>>; 4]) -> Result<W> {
        use naga::common::wgsl::TryToWgsl;
        let name = fun
            .try_to_wgsl()
            .ok_or_else(|| self.unsupported(format!("{fun:?}")))?;
        let mut args: Vec<Handle<Expression>> = args.into_iter().flatten().collect();
        // `mix(a, b, t)` takes a scalar `t` for vectors.
        if fun == naga::MathFunction::Mix && args.len() == 3 && self.is_vector(args[0]) {
            if let Some(s) = self.splatted(args[2]) {
                args[2] = s;
            }
        }
        let mut written = Vec::new();
        for a in &args {
            written.push(self.value(*a, false)?);
        }
        if written.iter().all(|w| w.abstract_) {
            // An abstract call would be evaluated in abstract precision.
            written[0] = self.value(args[0], true)?;
        }
        Ok(call(name, written.into_iter().map(|w| w.doc).collect()))
    }

    fn convert(
        &self,
        expr: Handle<Expression>,
        kind: naga::ScalarKind,
        convert: Option<u8>,
    ) -> Result<W> {
        // `vec4(v, 0, 1)`: an integer literal made a float is the float literal.
        if let (Expression::Literal(l), Some(4), None) =
            (self.shape.expr(expr), convert, self.baked_name(expr))
        {
            let folded = match (*l, kind) {
                (naga::Literal::I32(v), naga::ScalarKind::Float) if v.unsigned_abs() < 1 << 24 => {
                    Some(naga::Literal::F32(v as f32))
                }
                (naga::Literal::U32(v), naga::ScalarKind::Float) if v < 1 << 24 => {
                    Some(naga::Literal::F32(v as f32))
                }
                (naga::Literal::I32(v), naga::ScalarKind::Uint) if v >= 0 => {
                    Some(naga::Literal::U32(v as u32))
                }
                (naga::Literal::U32(v), naga::ScalarKind::Sint) if v <= i32::MAX as u32 => {
                    Some(naga::Literal::I32(v as i32))
                }
                _ => None,
            };
            if let Some(l) = folded {
                return Ok(literal_w(l, false));
            }
        }
        let inner = self.value(expr, true)?;
        let ty = self.shape.ty(expr);
        let target = |width: u8| naga::Scalar { kind, width };
        let head = match (ty, convert) {
            (TypeInner::Scalar(_), Some(w)) => scalar(target(w)).to_owned(),
            (&TypeInner::Vector { size, .. }, Some(w)) => vector(size, target(w)),
            (&TypeInner::Matrix { columns, rows, .. }, Some(w)) => matrix(columns, rows, target(w)),
            (TypeInner::Scalar(s), None) => format!("bitcast<{}>", scalar(target(s.width))),
            (&TypeInner::Vector { size, scalar: s }, None) => {
                format!("bitcast<{}>", vector(size, target(s.width)))
            }
            _ => return Err(self.unsupported("a conversion".into())),
        };
        Ok(call(&head, vec![inner.doc]))
    }

    /// A call whose result is written where it is used.
    fn call_result(&self, h: Handle<Expression>) -> Result<W> {
        let at =
            self.shape.evaluated[h.index()].ok_or_else(|| self.unsupported("a call".into()))?;
        match self.shape.statement(at) {
            Some(naga::Statement::Call {
                function,
                arguments,
                ..
            }) => Ok(W::new(self.call_doc(*function, arguments)?, POSTFIX)),
            _ => Err(self.unsupported("a call".into())),
        }
    }

    /// `f(a, &b)`.
    pub(crate) fn call_doc(
        &self,
        function: Handle<naga::Function>,
        arguments: &[Handle<Expression>],
    ) -> Result<Doc> {
        let name = self
            .names
            .get(naga::proc::NameKey::Function(function))
            .to_owned();
        let args = arguments
            .iter()
            .map(|a| Ok(self.place(*a, Indirection::Ordinary, false)?.doc))
            .collect::<Result<Vec<_>>>()?;
        Ok(Doc::List { head: name, args })
    }

    /// The type of an expression's value, spelled.
    pub(crate) fn type_of(&self, h: Handle<Expression>) -> String {
        match &self.shape.info[h].ty {
            naga::proc::TypeResolution::Handle(t) => self.type_name(*t),
            naga::proc::TypeResolution::Value(inner) => self.types().inner(inner),
        }
    }
}

fn literal_w(l: naga::Literal, concrete: bool) -> W {
    let form = if concrete {
        LiteralForm::Typed
    } else {
        LiteralForm::Bare
    };
    let text = literal(l, form);
    let level = if text.starts_with('-') {
        UNARY
    } else {
        POSTFIX
    };
    let abstract_ = !concrete
        && matches!(l, naga::Literal::F32(_) | naga::Literal::I32(_))
        && !text.ends_with('f')
        && !text.starts_with("i32(");
    W {
        doc: Doc::text(text),
        level,
        op: None,
        abstract_,
    }
}

/// A constant expression of the module (an unnamed constant's value, an initializer).
pub(crate) fn constant(env: &Env, h: Handle<Expression>, concrete: bool) -> Result<W> {
    let module = env.module;
    Ok(match module.global_expressions[h] {
        Expression::Literal(l) => literal_w(l, concrete),
        Expression::Constant(c) => match &module.constants[c].name {
            Some(_) => W::text(env.names.get(naga::proc::NameKey::Constant(c))),
            None => constant(env, module.constants[c].init, concrete)?,
        },
        Expression::ZeroValue(ty) => zero(env, ty, concrete),
        Expression::Compose { ty, ref components } => {
            let mut args = components
                .iter()
                .map(|c| Ok(constant(env, *c, false)?.doc))
                .collect::<Result<Vec<_>>>()?;
            let first = components.first().map(|c| &module.global_expressions[*c]);
            let vector = matches!(module.types[ty].inner, TypeInner::Vector { .. });
            if vector
                && matches!(first, Some(Expression::Literal(_)))
                && components
                    .iter()
                    .all(|c| Some(&module.global_expressions[*c]) == first)
            {
                args.truncate(1);
            }
            W::new(
                Doc::List {
                    head: env.types().name(ty),
                    args,
                },
                POSTFIX,
            )
        }
        Expression::Splat { size, value } => {
            let inner = constant(env, value, false)?;
            let s = match module.global_expressions[value] {
                Expression::Literal(l) => l.scalar(),
                _ => naga::Scalar::F32,
            };
            W::new(
                Doc::List {
                    head: vector(size, s),
                    args: vec![inner.doc],
                },
                POSTFIX,
            )
        }
        ref other => {
            return Err(TranslateError::Write {
                target: "wgsl",
                stage: "this",
                message: format!("essl's WGSL writer does not write the constant {other:?}"),
            })
        }
    })
}

/// A zero value: `0.0`, `0`, `0u`, `false`, or `T()`.
fn zero(env: &Env, ty: Handle<naga::Type>, concrete: bool) -> W {
    let l = match env.module.types[ty].inner {
        TypeInner::Scalar(s) => match s.kind {
            naga::ScalarKind::Float if s.width == 4 => Some(naga::Literal::F32(0.0)),
            naga::ScalarKind::Sint => Some(naga::Literal::I32(0)),
            naga::ScalarKind::Uint => Some(naga::Literal::U32(0)),
            naga::ScalarKind::Bool => Some(naga::Literal::Bool(false)),
            _ => None,
        },
        _ => None,
    };
    match l {
        Some(l) => literal_w(l, concrete),
        None => W::text(format!("{}()", env.types().name(ty))),
    }
}

/// `name(args)`.
pub(crate) fn call(name: &str, args: Vec<Doc>) -> W {
    W::new(
        Doc::List {
            head: name.to_owned(),
            args,
        },
        POSTFIX,
    )
}
