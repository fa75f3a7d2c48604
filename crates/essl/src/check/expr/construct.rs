//! Constructors: `vec4(...)`, `mat3(...)`, struct and array constructors.
//!
//! A constructor is checked in steps: the arguments on their own (no `void`, no samplers), then
//! their number and types against the constructed type's shape; a constant constructor folds.

use super::{constant, error_expr, is_error};
use crate::check::fold;
use crate::check::Checker;
use crate::diagnostic_code::Code;
use crate::hir::{ConstValue, Expr, ExprKind};
use crate::source::Span;
use crate::types::{StructId, Type};

/// Why a constructor is invalid.
enum Rejected {
    /// To be reported at the constructor (`invalid-constructor`) with this message and label.
    Here(String, &'static str),
    /// Already reported at the offending argument.
    Reported,
}

impl Checker<'_> {
    pub(super) fn construct(
        &mut self,
        ty: Type,
        args: Vec<Expr>,
        span: Span,
        type_span: Span,
    ) -> Expr {
        if args.iter().any(is_error) {
            return error_expr(span);
        }
        // The type's name is only formatted for an error message.
        let checked = self
            .constructor_arguments(&ty, &args)
            .and_then(|()| self.constructor_shape(ty, &args));
        let ty = match checked {
            Ok(ty) => ty,
            Err(Rejected::Here(msg, label)) => {
                let token = self.file.slice(type_span).to_string();
                let d = self.error(Code::InvalidConstructor, span, msg);
                d.label = label.into();
                d.token = token;
                return error_expr(span);
            }
            Err(Rejected::Reported) => return error_expr(span),
        };
        let consts: Option<Vec<&ConstValue>> = args.iter().map(|a| a.as_const()).collect();
        if let Some(cs) = consts {
            let tys: Vec<&Type> = args.iter().map(|a| &a.ty).collect();
            let mut warnings = Vec::new();
            if let Some(v) = fold::construct(&ty, &cs, &tys, &mut warnings) {
                let token = self.file.slice(type_span).to_string();
                for w in warnings {
                    self.fold_warning(w, &token, span);
                }
                return constant(v, ty, span);
            }
        }
        Expr {
            kind: ExprKind::Construct(args),
            ty,
            span,
        }
    }

    /// The arguments on their own: there are some, and none is `void` or holds a sampler.
    fn constructor_arguments(&self, ty: &Type, args: &[Expr]) -> Result<(), Rejected> {
        if args.is_empty() {
            return Err(Rejected::Here(
                format!("a {} constructor needs arguments", self.type_name(ty)),
                "no arguments",
            ));
        }
        for a in args {
            if a.ty == Type::Void {
                return Err(Rejected::Here(
                    "a `void` value cannot be a constructor argument".into(),
                    "void argument",
                ));
            }
            if a.ty.contains_sampler(&self.structs) {
                return Err(Rejected::Here(
                    "samplers cannot be constructor arguments".into(),
                    "sampler argument",
                ));
            }
        }
        Ok(())
    }

    /// The arguments against the constructed type's shape; the type constructed (an unsized
    /// array gets its size from the arguments).
    fn constructor_shape(&mut self, ty: Type, args: &[Expr]) -> Result<Type, Rejected> {
        match &ty {
            Type::Void | Type::Sampler(_) => Err(Rejected::Here(
                format!("{} has no constructor", self.type_name(&ty)),
                "no constructor",
            )),
            Type::Array(el, n) => self.array_constructor(&ty, el, *n, args),
            Type::Struct(id) => {
                self.struct_constructor(&ty, *id, args)?;
                Ok(ty)
            }
            Type::Scalar(_) => {
                self.scalar_constructor(&ty, args)?;
                Ok(ty)
            }
            Type::Vector(..) | Type::Matrix { .. } => {
                vector_matrix_constructor(&ty, args)?;
                Ok(ty)
            }
        }
    }

    /// `T[n](...)`: `n` elements of type `T` (any number when the size is left out).
    fn array_constructor(
        &mut self,
        ty: &Type,
        el: &Type,
        n: u32,
        args: &[Expr],
    ) -> Result<Type, Rejected> {
        if n != 0 && args.len() != n as usize {
            let tname = self.type_name(ty);
            return Err(Rejected::Here(
                format!("{tname} needs {n} arguments, not {}", args.len()),
                "wrong number of elements",
            ));
        }
        if let Some(bad) = args.iter().find(|a| a.ty != *el) {
            let (e, b) = (self.type_name(el), self.type_name(&bad.ty));
            let bspan = bad.span;
            let d = self.error(
                Code::InvalidConstructor,
                bspan,
                format!("array elements must be {e}, not {b}"),
            );
            d.label = format!("this is {b}");
            return Err(Rejected::Reported);
        }
        Ok(Type::Array(Box::new(el.clone()), args.len() as u32))
    }

    /// `S(...)`: one argument per member, of the member's type.
    fn struct_constructor(
        &mut self,
        ty: &Type,
        id: StructId,
        args: &[Expr],
    ) -> Result<(), Rejected> {
        let members = self.structs[id.0 as usize].members.clone();
        if members.len() != args.len() {
            let tname = self.type_name(ty);
            return Err(Rejected::Here(
                format!(
                    "{tname} has {} members but {} arguments are given",
                    members.len(),
                    args.len()
                ),
                "wrong number of arguments",
            ));
        }
        for (m, a) in members.iter().zip(args) {
            if m.ty != a.ty {
                let (want, got) = (self.type_name(&m.ty), self.type_name(&a.ty));
                let aspan = a.span;
                let d = self.error(
                    Code::InvalidConstructor,
                    aspan,
                    format!("member `{}` is {want}, not {got}", m.name),
                );
                d.label = format!("this is {got}");
                return Err(Rejected::Reported);
            }
        }
        Ok(())
    }

    /// `float(x)` and the like: one scalar, vector or matrix argument.
    fn scalar_constructor(&self, ty: &Type, args: &[Expr]) -> Result<(), Rejected> {
        let tname = || self.type_name(ty);
        if args.len() != 1 {
            return Err(Rejected::Here(
                format!("a {} constructor takes one argument", tname()),
                "too many arguments",
            ));
        }
        if !args[0].ty.is_numeric_basic() {
            let t = self.type_name(&args[0].ty);
            return Err(Rejected::Here(
                format!("cannot construct {} from {t}", tname()),
                "not a scalar, vector or matrix",
            ));
        }
        Ok(())
    }
}

/// `vecN(...)` and `matCxR(...)`: scalars, vectors and matrices with enough components and no
/// unused argument; a matrix argument only alone.
fn vector_matrix_constructor(ty: &Type, args: &[Expr]) -> Result<(), Rejected> {
    // A vector's or matrix's name does not depend on the struct table.
    let tname = format_args!("`{}`", ty.display(&[]));
    let needed = ty.component_count().unwrap_or(0);
    let is_matrix = matches!(ty, Type::Matrix { .. });
    if args.iter().any(|a| !a.ty.is_numeric_basic()) {
        return Err(Rejected::Here(
            format!("{tname} can only be built from scalars, vectors and matrices"),
            "invalid argument type",
        ));
    }
    let single = args.len() == 1;
    if is_matrix && !single && args.iter().any(|a| matches!(a.ty, Type::Matrix { .. })) {
        return Err(Rejected::Here(
            format!("a matrix argument must be the only argument of a {tname} constructor"),
            "matrix among other arguments",
        ));
    }
    if single
        && (args[0].ty.is_scalar() || (is_matrix && matches!(args[0].ty, Type::Matrix { .. })))
    {
        return Ok(());
    }
    let total: u32 = args
        .iter()
        .map(|a| a.ty.component_count().unwrap_or(0))
        .sum();
    let before_last: u32 = args[..args.len() - 1]
        .iter()
        .map(|a| a.ty.component_count().unwrap_or(0))
        .sum();
    if single && !is_matrix && total >= needed {
        // vecN(vecM) with M >= N, vecN(matrix) with enough components.
        Ok(())
    } else if total < needed {
        Err(Rejected::Here(
            format!("{tname} needs {needed} components, but the arguments have {total}"),
            "not enough components",
        ))
    } else if before_last >= needed {
        Err(Rejected::Here(
            format!("too many arguments for {tname}: the last argument is not used"),
            "too many arguments",
        ))
    } else {
        Ok(())
    }
}
