//! Copying IR from one place to another: every handle an expression or statement holds,
//! mapped through tables built while the arenas are copied (in order, so that a range of
//! expressions stays a range).

use naga::{
    Block, Constant, Expression, Function, GlobalVariable, Handle, LocalVariable, Range,
    SampleLevel, Statement, Type,
};

/// Old handle index → new handle, for each kind of handle.
#[derive(Default)]
pub(crate) struct Maps {
    pub exprs: Vec<Handle<Expression>>,
    pub locals: Vec<Handle<LocalVariable>>,
    /// `None`: types, globals, constants and functions keep their handles.
    pub module: Option<ModuleMaps>,
}

/// The handles of module-level items in another module.
#[derive(Default)]
pub(crate) struct ModuleMaps {
    pub types: Vec<Handle<Type>>,
    pub globals: Vec<Handle<GlobalVariable>>,
    pub constants: Vec<Handle<Constant>>,
    pub functions: Vec<Option<Handle<Function>>>,
}

impl Maps {
    fn e(&self, h: Handle<Expression>) -> Handle<Expression> {
        self.exprs[h.index()]
    }

    fn oe(&self, h: Option<Handle<Expression>>) -> Option<Handle<Expression>> {
        h.map(|h| self.e(h))
    }

    pub(crate) fn ty(&self, h: Handle<Type>) -> Handle<Type> {
        self.module.as_ref().map_or(h, |m| m.types[h.index()])
    }

    fn global(&self, h: Handle<GlobalVariable>) -> Handle<GlobalVariable> {
        self.module.as_ref().map_or(h, |m| m.globals[h.index()])
    }

    fn constant(&self, h: Handle<Constant>) -> Handle<Constant> {
        self.module.as_ref().map_or(h, |m| m.constants[h.index()])
    }

    fn function(&self, h: Handle<Function>) -> Option<Handle<Function>> {
        match &self.module {
            Some(m) => m.functions[h.index()],
            None => Some(h),
        }
    }

    /// The expression with its handles mapped; `None` for what a WebGL shader never holds.
    pub(crate) fn expression(&self, e: &Expression) -> Option<Expression> {
        use Expression as E;
        Some(match *e {
            E::Literal(l) => E::Literal(l),
            E::Constant(c) => E::Constant(self.constant(c)),
            E::ZeroValue(t) => E::ZeroValue(self.ty(t)),
            E::Compose { ty, ref components } => E::Compose {
                ty: self.ty(ty),
                components: components.iter().map(|c| self.e(*c)).collect(),
            },
            E::Access { base, index } => E::Access {
                base: self.e(base),
                index: self.e(index),
            },
            E::AccessIndex { base, index } => E::AccessIndex {
                base: self.e(base),
                index,
            },
            E::Splat { size, value } => E::Splat {
                size,
                value: self.e(value),
            },
            E::Swizzle {
                size,
                vector,
                pattern,
            } => E::Swizzle {
                size,
                vector: self.e(vector),
                pattern,
            },
            E::FunctionArgument(k) => E::FunctionArgument(k),
            E::GlobalVariable(g) => E::GlobalVariable(self.global(g)),
            E::LocalVariable(l) => E::LocalVariable(self.locals[l.index()]),
            E::Load { pointer } => E::Load {
                pointer: self.e(pointer),
            },
            E::ImageSample {
                image,
                sampler,
                gather,
                coordinate,
                array_index,
                offset,
                level,
                depth_ref,
                clamp_to_edge,
            } => E::ImageSample {
                image: self.e(image),
                sampler: self.e(sampler),
                gather,
                coordinate: self.e(coordinate),
                array_index: self.oe(array_index),
                offset: self.oe(offset),
                level: match level {
                    SampleLevel::Exact(x) => SampleLevel::Exact(self.e(x)),
                    SampleLevel::Bias(x) => SampleLevel::Bias(self.e(x)),
                    SampleLevel::Gradient { x, y } => SampleLevel::Gradient {
                        x: self.e(x),
                        y: self.e(y),
                    },
                    other => other,
                },
                depth_ref: self.oe(depth_ref),
                clamp_to_edge,
            },
            E::ImageLoad {
                image,
                coordinate,
                array_index,
                sample,
                level,
            } => E::ImageLoad {
                image: self.e(image),
                coordinate: self.e(coordinate),
                array_index: self.oe(array_index),
                sample: self.oe(sample),
                level: self.oe(level),
            },
            E::ImageQuery { image, query } => E::ImageQuery {
                image: self.e(image),
                query: match query {
                    naga::ImageQuery::Size { level } => naga::ImageQuery::Size {
                        level: self.oe(level),
                    },
                    other => other,
                },
            },
            E::Unary { op, expr } => E::Unary {
                op,
                expr: self.e(expr),
            },
            E::Binary { op, left, right } => E::Binary {
                op,
                left: self.e(left),
                right: self.e(right),
            },
            E::Select {
                condition,
                accept,
                reject,
            } => E::Select {
                condition: self.e(condition),
                accept: self.e(accept),
                reject: self.e(reject),
            },
            E::Derivative { axis, ctrl, expr } => E::Derivative {
                axis,
                ctrl,
                expr: self.e(expr),
            },
            E::Relational { fun, argument } => E::Relational {
                fun,
                argument: self.e(argument),
            },
            E::Math {
                fun,
                arg,
                arg1,
                arg2,
                arg3,
            } => E::Math {
                fun,
                arg: self.e(arg),
                arg1: self.oe(arg1),
                arg2: self.oe(arg2),
                arg3: self.oe(arg3),
            },
            E::As {
                expr,
                kind,
                convert,
            } => E::As {
                expr: self.e(expr),
                kind,
                convert,
            },
            E::CallResult(f) => E::CallResult(self.function(f)?),
            E::ArrayLength(x) => E::ArrayLength(self.e(x)),
            _ => return None,
        })
    }

    /// The block with its handles mapped.
    pub(crate) fn block(&self, b: &Block) -> Option<Block> {
        let mut out = Block::with_capacity(b.len());
        for (s, span) in b.span_iter() {
            out.push(self.statement(s)?, *span);
        }
        Some(out)
    }

    fn statement(&self, s: &Statement) -> Option<Statement> {
        use Statement as S;
        Some(match *s {
            S::Emit(ref range) => match range.first_and_last() {
                Some((first, last)) => S::Emit(Range::new_from_bounds(self.e(first), self.e(last))),
                None => S::Emit(range.clone()),
            },
            S::Block(ref b) => S::Block(self.block(b)?),
            S::If {
                condition,
                ref accept,
                ref reject,
            } => S::If {
                condition: self.e(condition),
                accept: self.block(accept)?,
                reject: self.block(reject)?,
            },
            S::Switch {
                selector,
                ref cases,
            } => S::Switch {
                selector: self.e(selector),
                cases: cases
                    .iter()
                    .map(|c| {
                        Some(naga::SwitchCase {
                            value: c.value,
                            body: self.block(&c.body)?,
                            fall_through: c.fall_through,
                        })
                    })
                    .collect::<Option<Vec<_>>>()?,
            },
            S::Loop {
                ref body,
                ref continuing,
                break_if,
            } => S::Loop {
                body: self.block(body)?,
                continuing: self.block(continuing)?,
                break_if: self.oe(break_if),
            },
            S::Break => S::Break,
            S::Continue => S::Continue,
            S::Return { value } => S::Return {
                value: self.oe(value),
            },
            S::Kill => S::Kill,
            S::Store { pointer, value } => S::Store {
                pointer: self.e(pointer),
                value: self.e(value),
            },
            S::ImageStore {
                image,
                coordinate,
                array_index,
                value,
            } => S::ImageStore {
                image: self.e(image),
                coordinate: self.e(coordinate),
                array_index: self.oe(array_index),
                value: self.e(value),
            },
            S::Call {
                function,
                ref arguments,
                result,
            } => S::Call {
                function: self.function(function)?,
                arguments: arguments.iter().map(|a| self.e(*a)).collect(),
                result: self.oe(result),
            },
            _ => return None,
        })
    }

    /// A function of another module, with its handles mapped into this one's (its
    /// expressions and locals copied in order).
    pub(crate) fn function_from(&mut self, f: &Function) -> Option<Function> {
        let mut out = Function {
            name: f.name.clone(),
            arguments: f
                .arguments
                .iter()
                .map(|a| naga::FunctionArgument {
                    name: a.name.clone(),
                    ty: self.ty(a.ty),
                    binding: a.binding.clone(),
                })
                .collect(),
            result: f.result.as_ref().map(|r| naga::FunctionResult {
                ty: self.ty(r.ty),
                binding: r.binding.clone(),
            }),
            ..Function::default()
        };
        self.locals.clear();
        self.exprs.clear();
        for (l, local) in f.local_variables.iter() {
            let h = out.local_variables.append(
                naga::LocalVariable {
                    name: local.name.clone(),
                    ty: self.ty(local.ty),
                    init: None,
                },
                f.local_variables.get_span(l),
            );
            self.locals.push(h);
        }
        for (h, e) in f.expressions.iter() {
            let mapped = self.expression(e)?;
            let new = out.expressions.append(mapped, f.expressions.get_span(h));
            self.exprs.push(new);
        }
        for (l, local) in f.local_variables.iter() {
            if let Some(init) = local.init {
                out.local_variables.get_mut(self.locals[l.index()]).init = Some(self.e(init));
            }
        }
        for (h, name) in f.named_expressions.iter() {
            out.named_expressions.insert(self.e(*h), name.clone());
        }
        out.body = self.block(&f.body)?;
        Some(out)
    }
}
