//! The shape of one function, as the writer needs it: where each block sits, where each
//! expression is evaluated (its `Emit`, or its `Call`), who uses it, and which components of
//! a constructor are a swizzle of one vector (`vec4(v.x, v.y, v.z, 1.0)` is `vec4f(v, 1.0)`).
//!
//! naga evaluates an expression where an `Emit` statement covers it; a `Load` reads memory
//! there, and a call happens at its `Call` statement. The writer may write an expression
//! where it is used instead (the [`super::bake`] rules say when that keeps its value), so it
//! needs both places.

use std::collections::HashMap;

use naga::{Expression, Function, Handle, Module, Statement, TypeInner};

/// A block of the function: its index in [`Shape::blocks`].
pub(crate) type BlockId = usize;

/// A statement: its block and its index there. A loop's `break if` is the statement after
/// the last of its `continuing` block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) struct Pos {
    pub block: BlockId,
    pub index: usize,
}

/// Where a block is.
#[derive(Clone, Debug)]
pub(crate) struct BlockInfo {
    /// The statement holding it (none for the body).
    pub parent: Option<Pos>,
    /// Whether it is a loop's body or `continuing`.
    pub in_loop: bool,
}

/// A use of an expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum User {
    /// An operand of another expression.
    Expr(Handle<Expression>),
    /// An operand of a statement.
    Stmt(Pos),
}

/// Components `start..start + pattern.len()` of a constructor, written as one swizzle of
/// `base` (a vector value, or with `load` a pointer to a vector).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Run {
    pub start: usize,
    pub base: Handle<Expression>,
    pub pattern: Vec<u32>,
    pub load: bool,
}

/// The shape of one function.
pub(crate) struct Shape<'a> {
    pub module: &'a Module,
    pub function: &'a Function,
    pub info: &'a naga::valid::FunctionInfo,
    pub blocks: Vec<BlockInfo>,
    /// Block ids by the block's address.
    ids: HashMap<*const naga::Block, BlockId>,
    /// The statements of each block (as the function holds them).
    pub statements: Vec<Vec<&'a Statement>>,
    /// The spans of each block's statements.
    pub spans: Vec<Vec<naga::Span>>,
    /// Where each expression is evaluated: its `Emit`, or the `Call` of a call's result.
    pub evaluated: Vec<Option<Pos>>,
    /// The uses of each expression.
    pub users: Vec<Vec<User>>,
    /// Swizzle runs of each constructor.
    pub runs: HashMap<Handle<Expression>, Vec<Run>>,
    /// The expressions written as part of a run (not on their own).
    pub in_run: Vec<bool>,
}

impl<'a> Shape<'a> {
    /// Analyses a function.
    pub(crate) fn new(
        module: &'a Module,
        function: &'a Function,
        info: &'a naga::valid::FunctionInfo,
    ) -> Shape<'a> {
        let n = function.expressions.len();
        let mut shape = Shape {
            module,
            function,
            info,
            blocks: Vec::new(),
            ids: HashMap::new(),
            statements: Vec::new(),
            spans: Vec::new(),
            evaluated: vec![None; n],
            users: vec![Vec::new(); n],
            runs: HashMap::new(),
            in_run: vec![false; n],
        };
        shape.walk(&function.body, None, false);
        for (h, e) in function.expressions.iter() {
            for o in operands(e) {
                shape.users[o.index()].push(User::Expr(h));
            }
        }
        shape.find_runs();
        shape
    }

    fn walk(&mut self, block: &'a naga::Block, parent: Option<Pos>, in_loop: bool) -> BlockId {
        let id = self.blocks.len();
        self.blocks.push(BlockInfo { parent, in_loop });
        self.ids.insert(block as *const _, id);
        self.statements.push(block.iter().collect());
        self.spans
            .push(block.span_iter().map(|(_, s)| *s).collect());
        for (index, s) in block.iter().enumerate() {
            let pos = Pos { block: id, index };
            for o in statement_operands(s) {
                self.users[o.index()].push(User::Stmt(pos));
            }
            match s {
                Statement::Emit(range) => {
                    for h in range.clone() {
                        self.evaluated[h.index()] = Some(pos);
                    }
                }
                Statement::Call {
                    result: Some(r), ..
                } => self.evaluated[r.index()] = Some(pos),
                Statement::Block(b) => {
                    self.walk(b, Some(pos), false);
                }
                Statement::If { accept, reject, .. } => {
                    self.walk(accept, Some(pos), false);
                    self.walk(reject, Some(pos), false);
                }
                Statement::Switch { cases, .. } => {
                    for c in cases {
                        self.walk(&c.body, Some(pos), false);
                    }
                }
                Statement::Loop {
                    body,
                    continuing,
                    break_if,
                } => {
                    self.walk(body, Some(pos), true);
                    let c = self.walk(continuing, Some(pos), true);
                    if let Some(b) = break_if {
                        let at = Pos {
                            block: c,
                            index: continuing.len(),
                        };
                        self.users[b.index()].push(User::Stmt(at));
                    }
                }
                _ => {}
            }
        }
        id
    }

    /// The id of a block of this function.
    pub(crate) fn id(&self, block: &naga::Block) -> BlockId {
        self.ids[&(block as *const _)]
    }

    /// The expression.
    pub(crate) fn expr(&self, h: Handle<Expression>) -> &'a Expression {
        &self.function.expressions[h]
    }

    /// The inner type of an expression's value.
    pub(crate) fn ty(&self, h: Handle<Expression>) -> &'a TypeInner {
        self.info[h].ty.inner_with(&self.module.types)
    }

    /// Whether the expression's value is a pointer (a reference, in WGSL).
    pub(crate) fn is_pointer(&self, h: Handle<Expression>) -> bool {
        matches!(
            self.ty(h),
            TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
        )
    }

    /// The statement at `pos` (none for a `break if`).
    pub(crate) fn statement(&self, pos: Pos) -> Option<&'a Statement> {
        self.statements[pos.block].get(pos.index).copied()
    }

    /// Whether block `inner` is `outer` or inside it.
    pub(crate) fn within(&self, inner: BlockId, outer: BlockId) -> bool {
        let mut b = inner;
        loop {
            if b == outer {
                return true;
            }
            match self.blocks[b].parent {
                Some(p) => b = p.block,
                None => return false,
            }
        }
    }

    /// The statement of block `outer` that holds position `pos` (itself when `pos` is in
    /// `outer`); none when `pos` is not inside `outer`.
    pub(crate) fn holder(&self, pos: Pos, outer: BlockId) -> Option<usize> {
        let mut p = pos;
        loop {
            if p.block == outer {
                return Some(p.index);
            }
            p = self.blocks[p.block].parent?;
        }
    }

    /// The variable, argument or global a pointer expression points into.
    pub(crate) fn root(&self, mut h: Handle<Expression>) -> Option<Root> {
        loop {
            match *self.expr(h) {
                Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => h = base,
                Expression::LocalVariable(l) => return Some(Root::Local(l)),
                Expression::GlobalVariable(g) => return Some(Root::Global(g)),
                Expression::FunctionArgument(a) => return Some(Root::Argument(a)),
                _ => return None,
            }
        }
    }

    fn find_runs(&mut self) {
        for (h, e) in self.function.expressions.iter() {
            let Expression::Compose { ty, components } = e else {
                continue;
            };
            if !matches!(self.module.types[*ty].inner, TypeInner::Vector { .. }) {
                continue;
            }
            let parts: Vec<Option<(Handle<Expression>, u32, bool)>> =
                components.iter().map(|&c| self.component(c, h)).collect();
            let mut runs = Vec::new();
            let mut k = 0;
            while k < parts.len() {
                let Some((base, _, load)) = parts[k] else {
                    k += 1;
                    continue;
                };
                let mut end = k + 1;
                while end < parts.len()
                    && parts[end].is_some_and(|(b, _, l)| b == base && l == load)
                {
                    end += 1;
                }
                if end - k >= 2 {
                    let pattern = parts[k..end]
                        .iter()
                        .map(|p| p.expect("in the run").1)
                        .collect();
                    runs.push(Run {
                        start: k,
                        base,
                        pattern,
                        load,
                    });
                    for &c in &components[k..end] {
                        self.in_run[c.index()] = true;
                        if load {
                            if let Expression::Load { pointer } = *self.expr(c) {
                                self.in_run[pointer.index()] = true;
                            }
                        }
                    }
                }
                k = end;
            }
            if !runs.is_empty() {
                self.runs.insert(h, runs);
            }
        }
    }

    /// A constructor component that is one component of a vector: (vector, index, through a
    /// load), when nothing else uses it.
    fn component(
        &self,
        c: Handle<Expression>,
        compose: Handle<Expression>,
    ) -> Option<(Handle<Expression>, u32, bool)> {
        if self.users[c.index()] != [User::Expr(compose)] {
            return None;
        }
        match *self.expr(c) {
            Expression::AccessIndex { base, index }
                if matches!(self.ty(base), TypeInner::Vector { .. }) =>
            {
                Some((base, index, false))
            }
            Expression::Load { pointer } if self.users[pointer.index()] == [User::Expr(c)] => {
                match *self.expr(pointer) {
                    Expression::AccessIndex { base, index } if self.points_to_vector(base) => {
                        Some((base, index, true))
                    }
                    _ => None,
                }
            }
            _ => None,
        }
    }

    fn points_to_vector(&self, h: Handle<Expression>) -> bool {
        match *self.ty(h) {
            TypeInner::Pointer { base, .. } => {
                matches!(self.module.types[base].inner, TypeInner::Vector { .. })
            }
            TypeInner::ValuePointer { size, .. } => size.is_some(),
            _ => false,
        }
    }
}

/// What a pointer points into.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Root {
    Local(Handle<naga::LocalVariable>),
    Global(Handle<naga::GlobalVariable>),
    Argument(u32),
}

/// The expressions an expression reads.
pub(crate) fn operands(e: &Expression) -> Vec<Handle<Expression>> {
    use naga::SampleLevel as L;
    let mut v = Vec::new();
    match *e {
        Expression::Compose { ref components, .. } => v.extend(components.iter().copied()),
        Expression::Access { base, index } => v.extend([base, index]),
        Expression::AccessIndex { base, .. } => v.push(base),
        Expression::Splat { value, .. } => v.push(value),
        Expression::Swizzle { vector, .. } => v.push(vector),
        Expression::Load { pointer } => v.push(pointer),
        Expression::ImageSample {
            image,
            sampler,
            coordinate,
            array_index,
            offset,
            level,
            depth_ref,
            ..
        } => {
            v.extend([image, sampler, coordinate]);
            v.extend(array_index);
            v.extend(offset);
            match level {
                L::Exact(x) | L::Bias(x) => v.push(x),
                L::Gradient { x, y } => v.extend([x, y]),
                L::Auto | L::Zero => {}
            }
            v.extend(depth_ref);
        }
        Expression::ImageLoad {
            image,
            coordinate,
            array_index,
            sample,
            level,
        } => {
            v.extend([image, coordinate]);
            v.extend(array_index);
            v.extend(sample);
            v.extend(level);
        }
        Expression::ImageQuery { image, query } => {
            v.push(image);
            if let naga::ImageQuery::Size { level: Some(l) } = query {
                v.push(l);
            }
        }
        Expression::Unary { expr, .. } => v.push(expr),
        Expression::Binary { left, right, .. } => v.extend([left, right]),
        Expression::Select {
            condition,
            accept,
            reject,
        } => v.extend([condition, accept, reject]),
        Expression::Derivative { expr, .. } => v.push(expr),
        Expression::Relational { argument, .. } => v.push(argument),
        Expression::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => {
            v.push(arg);
            v.extend(arg1);
            v.extend(arg2);
            v.extend(arg3);
        }
        Expression::As { expr, .. } => v.push(expr),
        Expression::ArrayLength(x) => v.push(x),
        _ => {}
    }
    v
}

/// The expressions a statement reads directly (not those of nested blocks).
pub(crate) fn statement_operands(s: &Statement) -> Vec<Handle<Expression>> {
    match *s {
        Statement::If { condition, .. } => vec![condition],
        Statement::Switch { selector, .. } => vec![selector],
        Statement::Return { value } => value.into_iter().collect(),
        Statement::Store { pointer, value } => vec![pointer, value],
        Statement::ImageStore {
            image,
            coordinate,
            array_index,
            value,
        } => {
            let mut v = vec![image, coordinate];
            v.extend(array_index);
            v.push(value);
            v
        }
        Statement::Call { ref arguments, .. } => arguments.clone(),
        _ => Vec::new(),
    }
}

/// Whether the writer can express every statement and expression of the function (what a
/// WebGL shader lowers to); the module is written by naga's writer otherwise.
pub(crate) fn supported(f: &Function) -> bool {
    let exprs = f.expressions.iter().all(|(_, e)| {
        !matches!(
            e,
            Expression::AtomicResult { .. }
                | Expression::WorkGroupUniformLoadResult { .. }
                | Expression::RayQueryVertexPositions { .. }
                | Expression::RayQueryProceedResult
                | Expression::RayQueryGetIntersection { .. }
                | Expression::SubgroupBallotResult
                | Expression::SubgroupOperationResult { .. }
                | Expression::CooperativeLoad { .. }
                | Expression::CooperativeMultiplyAdd { .. }
                | Expression::Override(_)
        )
    });
    exprs && block_supported(&f.body)
}

fn block_supported(b: &naga::Block) -> bool {
    b.iter().all(|s| match s {
        Statement::Emit(_)
        | Statement::Break
        | Statement::Continue
        | Statement::Return { .. }
        | Statement::Kill
        | Statement::Store { .. }
        | Statement::Call { .. } => true,
        Statement::Block(b) => block_supported(b),
        Statement::If { accept, reject, .. } => block_supported(accept) && block_supported(reject),
        Statement::Switch { cases, .. } => cases
            .iter()
            .all(|c| (c.body.is_empty() || !c.fall_through) && block_supported(&c.body)),
        Statement::Loop {
            body, continuing, ..
        } => block_supported(body) && block_supported(continuing),
        _ => false,
    })
}
