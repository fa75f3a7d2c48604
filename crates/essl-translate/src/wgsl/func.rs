//! One function's context: what each expression becomes ([`super::bake`]), where each local
//! is declared ([`super::decls`]), which loops are `for`s ([`super::loops`]), and the names
//! of its arguments, locals and `let`s.

use std::collections::HashMap;

use naga::proc::NameKey;
use naga::{Expression, Handle, LocalVariable, Statement};

use super::analysis::{Pos, Shape, User};
use super::bake::{self, Bakes, Fate};
use super::decls::{Decl, Decls};
use super::loops::{self, LoopForm};
use super::names::{sanitize, Scope};
use super::types::TypeNames;
use super::Env;
use crate::TranslateError;

/// Everything the writer knows about one function.
pub(crate) struct FnCtx<'a> {
    pub env: &'a Env<'a>,
    pub shape: &'a Shape<'a>,
    pub bakes: Bakes,
    pub decls: Decls,
    pub loops: HashMap<Pos, LoopForm>,
    pub names: &'a super::names::ModuleNames,
    /// Which source the function's spans point into.
    pub file: Option<usize>,
    args: Vec<String>,
    locals: HashMap<Handle<LocalVariable>, String>,
    lets: HashMap<Handle<Expression>, String>,
    aliases: HashMap<Handle<Expression>, String>,
    /// `let NAME = uniforms.NAME;` at the top: (name, member).
    pub alias_lines: Vec<(String, u32)>,
    /// Locals whose value is a copy of an out-argument temporary: (local, temporary). The
    /// temporary takes the local's name and the copy is not written.
    pub merged: HashMap<Handle<LocalVariable>, Handle<LocalVariable>>,
}

impl<'a> FnCtx<'a> {
    /// Plans a function.
    pub(crate) fn new(env: &'a Env<'a>, shape: &'a Shape<'a>, file: Option<usize>) -> FnCtx<'a> {
        let bakes = bake::bakes(shape, &env.writes);
        let decls = Decls::new(shape, &bakes);
        let loops = loops::loop_forms(shape, &bakes, &decls);
        let mut cx = FnCtx {
            env,
            shape,
            bakes,
            decls,
            loops,
            names: &env.names,
            file,
            args: Vec::new(),
            locals: HashMap::new(),
            lets: HashMap::new(),
            aliases: HashMap::new(),
            alias_lines: Vec::new(),
            merged: HashMap::new(),
        };
        cx.merged = cx.copies_out();
        cx.name_everything();
        cx
    }

    /// `var _essl_t: T; f(&_essl_t); let x = _essl_t;` (essl's temporary for an `out`
    /// argument) is `var x: T; f(&x);`: the locals declared by copying a temporary that a
    /// call wrote and nothing else uses.
    fn copies_out(&self) -> HashMap<Handle<LocalVariable>, Handle<LocalVariable>> {
        let f = self.shape.function;
        let mut out = HashMap::new();
        for (&at, &l) in &self.decls.at {
            if !matches!(
                self.decls.decl.get(&l),
                Some(Decl::At { constant: true, .. })
            ) {
                continue;
            }
            let Some(Statement::Store { value, .. }) = self.shape.statement(at) else {
                continue;
            };
            let Expression::Load { pointer } = *self.shape.expr(*value) else {
                continue;
            };
            let Expression::LocalVariable(t) = *self.shape.expr(pointer) else {
                continue;
            };
            let temporary = f.local_variables[t]
                .name
                .as_deref()
                .is_some_and(|n| n.starts_with("_essl_"));
            let refs = &self.decls.refs[&t];
            let written_by_call = refs.len() == 2
                && refs[1] == at
                && refs[0].block == at.block
                && matches!(self.shape.statement(refs[0]), Some(Statement::Call { arguments, .. })
                    if arguments.iter().any(|a| *self.shape.expr(*a) == Expression::LocalVariable(t)));
            let stores = f
                .expressions
                .iter()
                .filter(|(_, e)| **e == Expression::LocalVariable(t))
                .count();
            if temporary
                && written_by_call
                && stores <= 2
                && self.bakes.fate[value.index()] == Fate::Inline
            {
                out.insert(l, t);
            }
        }
        out
    }

    fn name_everything(&mut self) {
        let f = self.shape.function;
        let mut scope = Scope::new(&self.names.taken);
        let mut argument_locals: HashMap<u32, Handle<LocalVariable>> = HashMap::new();
        for (l, d) in &self.decls.decl {
            if let Decl::Argument { argument, .. } = *d {
                argument_locals.insert(argument, *l);
            }
        }
        // A parameter the function writes is copied into a local of its name: the argument
        // takes `_in`, the local (which the body reads) the name.
        let mut copied: HashMap<u32, String> = HashMap::new();
        for (&at, &l) in &self.decls.at {
            if let Some(Statement::Store { value, .. }) = self.shape.statement(at) {
                if let Expression::FunctionArgument(k) = *self.shape.expr(*value) {
                    let name = f.local_variables[l].name.clone();
                    if name.is_some() && name == f.arguments[k as usize].name {
                        copied.insert(k, format!("{}_in", name.unwrap_or_default()));
                    }
                }
            }
        }
        for (k, arg) in f.arguments.iter().enumerate() {
            let local = argument_locals.get(&(k as u32)).copied();
            let wanted = match (local, copied.get(&(k as u32))) {
                (Some(l), _) => f.local_variables[l].name.clone(),
                (None, Some(n)) => Some(n.clone()),
                (None, None) => arg.name.clone(),
            };
            let name = scope.name(wanted.as_deref().unwrap_or("arg"));
            if let Some(l) = local {
                self.locals.insert(l, name.clone());
            }
            self.args.push(name);
        }
        if self.env.module_scope_uniforms {
            self.name_aliases(&mut scope);
        }
        self.name_locals(&mut scope);
        for (h, _) in f.expressions.iter() {
            if self.bakes.fate[h.index()] == Fate::Bake {
                let wanted = f
                    .named_expressions
                    .get(&h)
                    .cloned()
                    .unwrap_or_else(|| format!("_e{}", h.index()));
                self.lets.insert(h, scope.name(&wanted));
            }
        }
    }

    /// Locals get their GLSL names; two with the same name share it when their scopes do not
    /// overlap (two `for (var i …)` loops).
    fn name_locals(&mut self, scope: &mut Scope) {
        let f = self.shape.function;
        let mut holders: HashMap<String, Vec<usize>> = HashMap::new();
        let temporaries: HashMap<Handle<LocalVariable>, Handle<LocalVariable>> =
            self.merged.iter().map(|(l, t)| (*t, *l)).collect();
        for (l, _) in f.local_variables.iter() {
            if self.locals.contains_key(&l)
                || self.decls.decl.get(&l) == Some(&Decl::Unused)
                || self.merged.contains_key(&l)
            {
                continue;
            }
            let named_as = temporaries.get(&l).map_or(l, |x| *x);
            let local = &f.local_variables[named_as];
            let wanted = sanitize(local.name.as_deref().unwrap_or("local"));
            let block = self.scope_block(l);
            let shareable = holders.get(&wanted).is_some_and(|bs| {
                bs.iter().all(|b| {
                    *b != 0
                        && block != 0
                        && !self.shape.within(*b, block)
                        && !self.shape.within(block, *b)
                })
            });
            let name = if shareable {
                scope.reuse(&wanted);
                wanted.clone()
            } else {
                scope.name(&wanted)
            };
            if name == wanted {
                holders.entry(wanted).or_default().push(block);
            }
            if named_as != l {
                self.locals.insert(named_as, name.clone());
            }
            self.locals.insert(l, name);
        }
    }

    /// The block a local's name is visible in (0: the whole function).
    fn scope_block(&self, l: Handle<LocalVariable>) -> usize {
        let Some(at) = self.decls.scope(l) else {
            return 0;
        };
        for (pos, form) in &self.loops {
            if form.init == Some(at) {
                if let Some(Statement::Loop { body, .. }) = self.shape.statement(*pos) {
                    return self.shape.id(body);
                }
            }
        }
        at.block
    }

    /// `let light = uniforms.light;` for each loose uniform the function reads only whole or
    /// by constant member and index (a dynamic index of a `let` matrix is not WGSL).
    fn name_aliases(&mut self, scope: &mut Scope) {
        let Some(buffer) = self.env.uniforms else {
            return;
        };
        let f = self.shape.function;
        let ty = self.shape.module.global_variables[buffer].ty;
        let shadowed = |name: &str| {
            f.local_variables
                .iter()
                .any(|(_, l)| l.name.as_deref() == Some(name))
                || f.arguments.iter().any(|a| a.name.as_deref() == Some(name))
        };
        let mut by_member: HashMap<u32, (Vec<Handle<Expression>>, bool)> = HashMap::new();
        for (h, e) in f.expressions.iter() {
            if let Expression::AccessIndex { base, index } = *e {
                if matches!(*self.shape.expr(base), Expression::GlobalVariable(g) if g == buffer) {
                    let entry = by_member.entry(index).or_insert((Vec::new(), true));
                    entry.0.push(h);
                    entry.1 &= self.read_only_chain(h);
                }
            }
        }
        let mut members: Vec<_> = by_member.into_iter().collect();
        members.sort_by_key(|(k, _)| *k);
        for (k, (exprs, ok)) in members {
            let name = self.names.get(NameKey::StructMember(ty, k)).to_owned();
            if !ok || name.starts_with('_') || !scope.free(&name) || shadowed(&name) {
                continue;
            }
            scope.reuse(&name);
            for h in exprs {
                self.aliases.insert(h, name.clone());
            }
            self.alias_lines.push((name, k));
        }
    }

    /// Whether every use of a pointer only loads from it, through constant accesses.
    fn read_only_chain(&self, h: Handle<Expression>) -> bool {
        self.shape.users[h.index()].iter().all(|u| match *u {
            User::Expr(u) => match *self.shape.expr(u) {
                Expression::Load { .. } => true,
                Expression::AccessIndex { .. } => self.read_only_chain(u),
                _ => false,
            },
            User::Stmt(_) => false,
        })
    }

    /// The `let` name of a baked expression.
    pub(crate) fn baked_name(&self, h: Handle<Expression>) -> Option<&str> {
        if self.bakes.fate[h.index()] == Fate::Bake {
            self.lets.get(&h).map(String::as_str)
        } else {
            None
        }
    }

    /// The alias of a uniform member (module-scope uniforms).
    pub(crate) fn alias(&self, h: Handle<Expression>) -> Option<&str> {
        self.aliases.get(&h).map(String::as_str)
    }

    /// An argument's name.
    pub(crate) fn argument_name(&self, k: u32) -> &str {
        self.args.get(k as usize).map_or("arg", String::as_str)
    }

    /// A local's name.
    pub(crate) fn local_name(&self, l: Handle<LocalVariable>) -> &str {
        self.locals.get(&l).map_or("local", String::as_str)
    }

    /// A type, spelled.
    pub(crate) fn type_name(&self, ty: Handle<naga::Type>) -> String {
        self.types().name(ty)
    }

    /// The type speller.
    pub(crate) fn types(&self) -> TypeNames<'_> {
        self.env.types()
    }

    /// The error for what the writer does not write (the module then goes through naga's).
    pub(crate) fn unsupported(&self, what: String) -> TranslateError {
        TranslateError::Write {
            target: "wgsl",
            stage: "this",
            message: format!("essl's WGSL writer does not write {what}"),
        }
    }

    /// Whether the statement at `pos` writes nothing (a folded-in or moved statement).
    pub(crate) fn silent_emit(&self, range: &naga::Range<Expression>) -> bool {
        range
            .clone()
            .all(|h| self.bakes.fate[h.index()] != Fate::Bake)
    }
}
