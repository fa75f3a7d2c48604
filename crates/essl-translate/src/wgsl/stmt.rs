//! Statements: declarations where GLSL had them, `x += y` and `i++` where the IR stores an
//! operation on the value it loads from the same place, `else if` chains, `for` and `while`
//! loops, and no `return;` at the end of a function.

use naga::{BinaryOperator as B, Expression, Handle, Statement};

use super::analysis::Pos;
use super::bake::Fate;
use super::decls::Decl;
use super::doc::Doc;
use super::expr::{Indirection, UNARY};
use super::func::FnCtx;
use super::{Line, Origin};
use crate::TranslateError;

type Result<T> = std::result::Result<T, TranslateError>;

impl FnCtx<'_> {
    /// The function's body, one level in.
    pub(crate) fn body(&self, out: &mut Vec<Line>) -> Result<()> {
        let uniforms = self.env.uniforms.map(|g| {
            self.names
                .get(naga::proc::NameKey::GlobalVariable(g))
                .to_owned()
        });
        if let Some(u) = uniforms {
            for (name, _) in &self.alias_lines {
                out.push(Line::new(
                    1,
                    format!("let {name} = {u}.{name};"),
                    Origin::None,
                ));
            }
        }
        self.block(&self.shape.function.body, 1, 0, true, out)
    }

    /// The statements of `block` from `start`, at `indent`.
    fn block(
        &self,
        block: &naga::Block,
        indent: usize,
        start: usize,
        top: bool,
        out: &mut Vec<Line>,
    ) -> Result<()> {
        let id = self.shape.id(block);
        let spans = &self.shape.spans[id];
        let last = block.len().saturating_sub(1);
        for (i, s) in block.iter().enumerate().skip(start) {
            let pos = Pos {
                block: id,
                index: i,
            };
            let span = spans[i];
            self.declare_before(pos, indent, out)?;
            if self.loops.values().any(|f| f.init == Some(pos)) {
                continue;
            }
            match s {
                Statement::Emit(range) => {
                    for h in range.clone() {
                        let Some(name) = self.baked_name(h) else {
                            continue;
                        };
                        let value = self.definition(h, false)?.doc;
                        let doc = Doc::Cat(vec![
                            Doc::text(format!("let {name} = ")),
                            value,
                            Doc::text(";"),
                        ]);
                        let span = self.shape.function.expressions.get_span(h);
                        self.push(out, indent, doc, span, self.note(h));
                    }
                }
                Statement::Return { value: None } if top && i == last => {}
                Statement::Return { value } => {
                    let doc = match value {
                        Some(v) => Doc::Cat(vec![
                            Doc::text("return "),
                            self.value(*v, false)?.doc,
                            Doc::text(";"),
                        ]),
                        None => Doc::text("return;"),
                    };
                    self.push(out, indent, doc, span, Vec::new());
                }
                Statement::Kill => self.push(out, indent, Doc::text("discard;"), span, Vec::new()),
                Statement::Break => self.push(out, indent, Doc::text("break;"), span, Vec::new()),
                Statement::Continue => {
                    self.push(out, indent, Doc::text("continue;"), span, Vec::new())
                }
                // `if c { { … } }`: GLSL's braces around a body that is one block.
                Statement::Block(b) if self.sole(block, i) => {
                    self.block(b, indent, 0, false, out)?;
                }
                Statement::Block(b) => {
                    self.push(out, indent, Doc::text("{"), span, Vec::new());
                    self.block(b, indent + 1, 0, false, out)?;
                    out.push(Line::new(indent, "}".into(), Origin::Continued));
                }
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => self.if_chain(*condition, accept, reject, indent, span, out)?,
                Statement::Switch { selector, cases } => {
                    self.switch(*selector, cases, indent, span, out)?
                }
                Statement::Loop {
                    body,
                    continuing,
                    break_if,
                } => self.loop_(pos, body, continuing, *break_if, indent, span, out)?,
                Statement::Store { .. } | Statement::Call { .. } | Statement::ImageStore { .. } => {
                    if let Some(doc) = self.simple(pos)? {
                        let notes = match s {
                            Statement::Store { value, .. } if self.baked_name(*value).is_none() => {
                                self.note(*value)
                            }
                            _ => Vec::new(),
                        };
                        self.push(
                            out,
                            indent,
                            Doc::Cat(vec![doc, Doc::text(";")]),
                            span,
                            notes,
                        );
                    }
                }
                other => return Err(self.unsupported(format!("{other:?}"))),
            }
        }
        Ok(())
    }

    /// Whether statement `i` is all the block writes (the others are `Emit`s that write
    /// nothing, and nothing is declared before them).
    fn sole(&self, block: &naga::Block, i: usize) -> bool {
        let id = self.shape.id(block);
        block.iter().enumerate().all(|(k, s)| {
            !self.decls.before.contains_key(&Pos {
                block: id,
                index: k,
            }) && (k == i || matches!(s, Statement::Emit(r) if self.silent_emit(r)))
        })
    }

    /// `var NAME: T;` for the locals declared before the statement at `pos`.
    fn declare_before(&self, pos: Pos, indent: usize, out: &mut Vec<Line>) -> Result<()> {
        let Some(locals) = self.decls.before.get(&pos) else {
            return Ok(());
        };
        for &l in locals {
            let local = &self.shape.function.local_variables[l];
            let ty = self.type_name(local.ty);
            let name = self.local_name(l);
            let doc = match local.init {
                Some(init) => Doc::Cat(vec![
                    Doc::text(format!("var {name}: {ty} = ")),
                    self.value(init, false)?.doc,
                    Doc::text(";"),
                ]),
                None => Doc::text(format!("var {name}: {ty};")),
            };
            let span = self.shape.function.local_variables.get_span(l);
            self.push(out, indent, doc, span, Vec::new());
        }
        Ok(())
    }

    /// A store, call or texture store, without its `;` (none when nothing is written).
    fn simple(&self, pos: Pos) -> Result<Option<Doc>> {
        Ok(Some(match self.shape.statement(pos) {
            Some(Statement::Store { pointer, value }) => {
                if let Some(super::analysis::Root::Local(l)) = self.shape.root(*pointer) {
                    if self.decls.decl.get(&l) == Some(&Decl::Unused) {
                        return Ok(None);
                    }
                }
                if let Some(&l) = self.decls.at.get(&pos) {
                    if self.merged.contains_key(&l) {
                        return Ok(None);
                    }
                    match self.decls.decl.get(&l) {
                        Some(Decl::Argument { .. }) => return Ok(None),
                        Some(&Decl::At { constant, .. }) => {
                            let keyword = if constant { "let" } else { "var" };
                            let name = self.local_name(l);
                            return Ok(Some(Doc::Cat(vec![
                                Doc::text(format!("{keyword} {name} = ")),
                                self.value(*value, false)?.doc,
                            ])));
                        }
                        _ => {}
                    }
                }
                let place = self.place(*pointer, Indirection::Reference, false)?.doc;
                match self.compound(*pointer, *value) {
                    Some((op, right)) => {
                        if let Some(inc) = self.increment(op, right) {
                            Doc::Cat(vec![place, Doc::text(inc)])
                        } else {
                            Doc::Cat(vec![
                                place,
                                Doc::text(format!(" {}= ", op_text(op))),
                                self.value(right, false)?.doc,
                            ])
                        }
                    }
                    None => Doc::Cat(vec![
                        place,
                        Doc::text(" = "),
                        self.value(*value, false)?.doc,
                    ]),
                }
            }
            Some(Statement::Call {
                function,
                arguments,
                result,
            }) => {
                let call = self.call_doc(*function, arguments)?;
                match result.map(|r| (r, self.bakes.fate[r.index()])) {
                    Some((_, Fate::Inline)) => return Ok(None),
                    Some((r, Fate::Bake)) => {
                        let name = self.baked_name(r).unwrap_or("_");
                        Doc::Cat(vec![Doc::text(format!("let {name} = ")), call])
                    }
                    _ => call,
                }
            }
            Some(Statement::ImageStore {
                image,
                coordinate,
                array_index,
                value,
            }) => {
                let mut args = vec![
                    self.value(*image, false)?.doc,
                    self.value(*coordinate, false)?.doc,
                ];
                if let Some(a) = array_index {
                    args.push(self.value(*a, false)?.doc);
                }
                args.push(self.value(*value, false)?.doc);
                Doc::List {
                    head: "textureStore".into(),
                    args,
                }
            }
            _ => return Ok(None),
        }))
    }

    /// `x = x op y` as `x op= y`: (op, y).
    fn compound(
        &self,
        pointer: Handle<Expression>,
        value: Handle<Expression>,
    ) -> Option<(B, Handle<Expression>)> {
        if self.bakes.fate[value.index()] != Fate::Inline {
            return None;
        }
        let Expression::Binary { op, left, right } = *self.shape.expr(value) else {
            return None;
        };
        let arithmetic = matches!(
            op,
            B::Add
                | B::Subtract
                | B::Multiply
                | B::Divide
                | B::Modulo
                | B::And
                | B::InclusiveOr
                | B::ExclusiveOr
                | B::ShiftLeft
                | B::ShiftRight
        );
        let left = match *self.shape.expr(left) {
            Expression::Swizzle {
                size,
                vector,
                ref pattern,
            } if self.bakes.fate[left.index()] == Fate::Inline
                && self.identity_swizzle(size, vector, pattern) =>
            {
                vector
            }
            _ => left,
        };
        let Expression::Load { pointer: loaded } = *self.shape.expr(left) else {
            return None;
        };
        // `x op= y` reads `x` after `y`: only when no call in `y` may store to `x`.
        let root = self.shape.root(pointer);
        (arithmetic
            && self.bakes.fate[left.index()] == Fate::Inline
            && self.same_place(pointer, loaded)
            && !root.is_some_and(|r| self.calls_writing(right, r)))
        .then_some((op, right))
    }

    /// `++` or `--` for adding or subtracting an integer 1.
    fn increment(&self, op: B, right: Handle<Expression>) -> Option<&'static str> {
        let one = matches!(
            self.shape.expr(right),
            Expression::Literal(naga::Literal::I32(1) | naga::Literal::U32(1))
        );
        match op {
            B::Add if one => Some("++"),
            B::Subtract if one => Some("--"),
            _ => None,
        }
    }

    /// Whether two pointer expressions name the same place.
    fn same_place(&self, a: Handle<Expression>, b: Handle<Expression>) -> bool {
        if a == b {
            return true;
        }
        match (self.shape.expr(a), self.shape.expr(b)) {
            (Expression::LocalVariable(x), Expression::LocalVariable(y)) => x == y,
            (Expression::GlobalVariable(x), Expression::GlobalVariable(y)) => x == y,
            (Expression::FunctionArgument(x), Expression::FunctionArgument(y)) => x == y,
            (
                Expression::AccessIndex {
                    base: b1,
                    index: i1,
                },
                Expression::AccessIndex {
                    base: b2,
                    index: i2,
                },
            ) => i1 == i2 && self.same_place(*b1, *b2),
            (
                Expression::Access {
                    base: b1,
                    index: x1,
                },
                Expression::Access {
                    base: b2,
                    index: x2,
                },
            ) => x1 == x2 && self.same_place(*b1, *b2),
            _ => false,
        }
    }

    /// Whether the text of `h` holds a call that may store to `root`.
    fn calls_writing(&self, h: Handle<Expression>, root: super::analysis::Root) -> bool {
        if self.bakes.fate[h.index()] == Fate::Bake {
            return false;
        }
        match self.shape.expr(h) {
            Expression::CallResult(f) => {
                let global = matches!(root, super::analysis::Root::Global(g)
                    if self.env.writes.get(f).is_some_and(|w| w.contains(&g)));
                let through_argument =
                    match self.shape.evaluated[h.index()].and_then(|p| self.shape.statement(p)) {
                        Some(Statement::Call { arguments, .. }) => arguments.iter().any(|a| {
                            self.shape.is_pointer(*a) && self.shape.root(*a) == Some(root)
                        }),
                        _ => true,
                    };
                global || through_argument
            }
            e => super::analysis::operands(e)
                .into_iter()
                .any(|o| self.calls_writing(o, root)),
        }
    }

    /// `if … { } else if … { } else { }`.
    fn if_chain(
        &self,
        condition: Handle<Expression>,
        accept: &naga::Block,
        reject: &naga::Block,
        indent: usize,
        span: naga::Span,
        out: &mut Vec<Line>,
    ) -> Result<()> {
        let cond = self.value(condition, false)?.doc;
        self.push(
            out,
            indent,
            Doc::Cat(vec![Doc::text("if "), cond, Doc::text(" {")]),
            span,
            Vec::new(),
        );
        self.block(accept, indent + 1, 0, false, out)?;
        let mut reject = reject;
        loop {
            if reject.is_empty() {
                out.push(Line::new(indent, "}".into(), Origin::Continued));
                return Ok(());
            }
            if let Some((c, a, r)) = self.else_if(reject) {
                let cond = self.value(c, false)?.doc;
                let doc = Doc::Cat(vec![Doc::text("} else if "), cond, Doc::text(" {")]);
                self.push(out, indent, doc, naga::Span::UNDEFINED, Vec::new());
                self.block(a, indent + 1, 0, false, out)?;
                reject = r;
                continue;
            }
            out.push(Line::new(indent, "} else {".into(), Origin::Continued));
            self.block(reject, indent + 1, 0, false, out)?;
            out.push(Line::new(indent, "}".into(), Origin::Continued));
            return Ok(());
        }
    }

    /// An `else` block that is one `if` (after `Emit`s that write nothing).
    fn else_if<'b>(
        &self,
        block: &'b naga::Block,
    ) -> Option<(Handle<Expression>, &'b naga::Block, &'b naga::Block)> {
        let id = self.shape.id(block);
        let mut found = None;
        for (i, s) in block.iter().enumerate() {
            if self.decls.before.contains_key(&Pos {
                block: id,
                index: i,
            }) {
                return None;
            }
            match s {
                Statement::Emit(range) if self.silent_emit(range) => {}
                Statement::If {
                    condition,
                    accept,
                    reject,
                } if found.is_none() => found = Some((*condition, accept, reject)),
                _ => return None,
            }
        }
        found
    }

    fn switch(
        &self,
        selector: Handle<Expression>,
        cases: &[naga::SwitchCase],
        indent: usize,
        span: naga::Span,
        out: &mut Vec<Line>,
    ) -> Result<()> {
        let sel = self.value(selector, false)?.doc;
        self.push(
            out,
            indent,
            Doc::Cat(vec![Doc::text("switch "), sel, Doc::text(" {")]),
            span,
            Vec::new(),
        );
        let mut labels: Vec<String> = Vec::new();
        for case in cases {
            labels.push(match case.value {
                naga::SwitchValue::I32(v) => v.to_string(),
                naga::SwitchValue::U32(v) => format!("{v}u"),
                naga::SwitchValue::Default => "default".into(),
            });
            if case.fall_through {
                continue;
            }
            let head = match &labels[..] {
                [d] if d == "default" => "default".to_owned(),
                _ => format!("case {}", labels.join(", ")),
            };
            labels.clear();
            if case.body.is_empty() {
                out.push(Line::new(
                    indent + 1,
                    format!("{head}: {{}}"),
                    Origin::Continued,
                ));
                continue;
            }
            out.push(Line::new(
                indent + 1,
                format!("{head}: {{"),
                Origin::Continued,
            ));
            self.block(&case.body, indent + 2, 0, false, out)?;
            out.push(Line::new(indent + 1, "}".into(), Origin::Continued));
        }
        out.push(Line::new(indent, "}".into(), Origin::Continued));
        Ok(())
    }

    #[allow(clippy::too_many_arguments)]
    fn loop_(
        &self,
        pos: Pos,
        body: &naga::Block,
        continuing: &naga::Block,
        break_if: Option<Handle<Expression>>,
        indent: usize,
        span: naga::Span,
        out: &mut Vec<Line>,
    ) -> Result<()> {
        if let Some(form) = self.loops.get(&pos) {
            let (c, negate) = form.cond;
            let cond = self.value(c, false)?;
            let cond = if negate {
                Doc::Cat(vec![Doc::text("!"), cond.at(UNARY, None)])
            } else {
                cond.doc
            };
            let head = if form.init.is_some() || form.update.is_some() {
                let init = match form.init {
                    Some(p) => self.simple(p)?.unwrap_or(Doc::text("")),
                    None => Doc::text(""),
                };
                let update = match form.update {
                    Some(p) => self.simple(p)?.unwrap_or(Doc::text("")),
                    None => Doc::text(""),
                };
                let span = match form.init {
                    Some(p) => self.span_at(p),
                    None => span,
                };
                (
                    Doc::Cat(vec![
                        Doc::text("for ("),
                        init,
                        Doc::text("; "),
                        cond,
                        Doc::text("; "),
                        update,
                        Doc::text(") {"),
                    ]),
                    span,
                )
            } else {
                (
                    Doc::Cat(vec![Doc::text("while "), cond, Doc::text(" {")]),
                    span,
                )
            };
            self.push(out, indent, head.0, head.1, Vec::new());
            self.block(body, indent + 1, form.skip, false, out)?;
            out.push(Line::new(indent, "}".into(), Origin::Continued));
            return Ok(());
        }
        self.push(out, indent, Doc::text("loop {"), span, Vec::new());
        self.block(body, indent + 1, 0, false, out)?;
        if !continuing.is_empty() || break_if.is_some() {
            out.push(Line::new(
                indent + 1,
                "continuing {".into(),
                Origin::Continued,
            ));
            self.block(continuing, indent + 2, 0, false, out)?;
            if let Some(b) = break_if {
                let doc = Doc::Cat(vec![
                    Doc::text("break if "),
                    self.value(b, false)?.doc,
                    Doc::text(";"),
                ]);
                self.push(out, indent + 2, doc, naga::Span::UNDEFINED, Vec::new());
            }
            out.push(Line::new(indent + 1, "}".into(), Origin::Continued));
        }
        out.push(Line::new(indent, "}".into(), Origin::Continued));
        Ok(())
    }

    fn span_at(&self, pos: Pos) -> naga::Span {
        self.shape.spans[pos.block]
            .get(pos.index)
            .copied()
            .unwrap_or(naga::Span::UNDEFINED)
    }

    /// The notes (essl's comments) for a named expression written here.
    fn note(&self, h: Handle<Expression>) -> Vec<String> {
        self.shape
            .function
            .named_expressions
            .get(&h)
            .and_then(|n| (self.env.note_for)(n))
            .into_iter()
            .collect()
    }

    /// Pushes the lines of a statement.
    pub(crate) fn push(
        &self,
        out: &mut Vec<Line>,
        indent: usize,
        doc: Doc,
        span: naga::Span,
        notes: Vec<String>,
    ) {
        let origin = match (self.file, span.to_range()) {
            (Some(file), Some(r)) if span.is_defined() => Origin::Source {
                file,
                start: r.start as u32,
                end: r.end as u32,
            },
            _ => Origin::None,
        };
        push_doc(out, indent, doc, origin, notes);
    }
}

/// Pushes the lines of a piece of text: the first with its origin and notes, the rest as its
/// continuation.
pub(crate) fn push_doc(
    out: &mut Vec<Line>,
    indent: usize,
    doc: Doc,
    origin: Origin,
    notes: Vec<String>,
) {
    let lines = doc.lines(indent * 4, indent * 4, 0);
    for (i, l) in lines.into_iter().enumerate() {
        if i == 0 {
            let mut line = Line::new(indent, l, origin);
            line.notes = notes.clone();
            out.push(line);
        } else {
            out.push(Line::new(0, l, Origin::Continued));
        }
    }
}

fn op_text(op: B) -> &'static str {
    match op {
        B::Add => "+",
        B::Subtract => "-",
        B::Multiply => "*",
        B::Divide => "/",
        B::Modulo => "%",
        B::And => "&",
        B::InclusiveOr => "|",
        B::ExclusiveOr => "^",
        B::ShiftLeft => "<<",
        B::ShiftRight => ">>",
        _ => "?",
    }
}
