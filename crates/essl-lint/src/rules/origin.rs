//! Where a value comes from: the uniforms it reads, and whether per-vertex or per-pixel values
//! (inputs, built-ins, texels) reach it — what decides a finding's severity.
//!
//! A hazard that one uniform alone reaches, with constants (`pow(r, u_power - 1.0)`,
//! `x / (u_resolution - 1.0)`, `smoothstep(cos(u_angle), 1.0, d)`), needs that uniform out of
//! the range the shader was written for: the finding is a note naming it, and the runtime check
//! (essl-gl's validation mode) is the follow-up. Values the shader itself produces — a dot
//! product, a difference of two varyings, two parameters set independently — give warnings.
//!
//! The walk follows an expression's operands back through locals (every store into them), the
//! arguments of every call of a function, the `return`s of a called function and private
//! globals (every store, or the entry point's copy of an input), with a bound on its length.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use naga::{Block, Expression as E, Function, Handle, Statement, TypeInner};

use super::context::operands;
use super::Cx;
use crate::analysis;

/// The most expressions one walk visits.
const MAX_STEPS: usize = 512;

/// Where a value comes from.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Origin {
    /// The uniforms it reads (WebGL names, `[*]` for any array element), in the order found.
    pub uniforms: Vec<String>,
    /// The inputs (attributes, varyings, built-ins) it reads, by the entry point's variable.
    pub inputs: Vec<String>,
    /// Whether texels reach it.
    pub texels: bool,
    /// Whether the walk could not follow every part (a pointer parameter, a long chain).
    pub unknown: bool,
}

impl Origin {
    /// The one uniform a value is computed from with constants only, if it is.
    pub fn single_uniform(&self) -> Option<&str> {
        match (
            &self.uniforms[..],
            self.inputs.is_empty(),
            self.texels,
            self.unknown,
        ) {
            ([u], true, false, false) => Some(u),
            _ => None,
        }
    }
}

/// Who calls each function with which arguments, what each function returns, and what is
/// stored into each variable: what [`Cx::origin`] follows.
#[derive(Debug, Default)]
pub struct Flows {
    /// Per function: (caller, the call's arguments).
    calls: Vec<Vec<(usize, Vec<Handle<E>>)>>,
    /// Per (caller, call result): the callee and the call's place in its `calls`.
    results: HashMap<(usize, Handle<E>), (usize, usize)>,
    /// Per function: the values it returns.
    returns: Vec<Vec<Handle<E>>>,
    /// Per function: the values stored into each local, with the part stored (empty: whole).
    locals: Vec<HashMap<usize, Vec<PartStore>>>,
    /// Per private global: (function, value) of every store into it, whole or in part.
    globals: HashMap<usize, Vec<(usize, Handle<E>)>>,
    /// Per function: the values stored whole through each pointer parameter (an `out` one).
    outs: Vec<HashMap<u32, Vec<Handle<E>>>>,
    /// Per (function, local): (callee, argument) of every call that passes the local's pointer.
    passed: HashMap<(usize, usize), Vec<(usize, u32)>>,
}

impl Flows {
    /// The calls of function `id`: (caller, the call's arguments).
    pub(crate) fn callers(&self, id: usize) -> &[(usize, Vec<Handle<E>>)] {
        self.calls.get(id).map_or(&[], Vec::as_slice)
    }

    /// The arguments of the call in function `caller` whose result is `result`.
    pub(crate) fn arguments(&self, caller: usize, result: Handle<E>) -> Option<&[Handle<E>]> {
        let &(callee, at) = self.results.get(&(caller, result))?;
        Some(&self.calls[callee][at].1)
    }

    /// The values stored whole into local `l` of function `id` (its initialiser aside).
    pub(crate) fn whole_stores(&self, id: usize, l: usize) -> impl Iterator<Item = Handle<E>> + '_ {
        let stores = self.locals.get(id).and_then(|m| m.get(&l));
        stores
            .into_iter()
            .flatten()
            .filter(|(at, _)| at.is_empty())
            .map(|(_, v)| *v)
    }

    /// The stores into private global `g`: (function, value).
    pub(crate) fn global_stores(&self, g: usize) -> &[(usize, Handle<E>)] {
        self.globals.get(&g).map_or(&[], Vec::as_slice)
    }

    /// What the calls of function `id` that pass local `l`'s pointer store through it:
    /// (callee, value), an `out` parameter's values.
    pub(crate) fn written_through(
        &self,
        id: usize,
        l: usize,
    ) -> impl Iterator<Item = (usize, Handle<E>)> + '_ {
        let calls = self.passed.get(&(id, l));
        calls.into_iter().flatten().flat_map(move |&(callee, j)| {
            let values = self.outs.get(callee).and_then(|m| m.get(&j));
            values.into_iter().flatten().map(move |v| (callee, *v))
        })
    }

    /// The values function `id` returns.
    pub(crate) fn returns(&self, id: usize) -> &[Handle<E>] {
        self.returns.get(id).map_or(&[], Vec::as_slice)
    }

    /// The flows of a module.
    pub fn of(module: &naga::Module) -> Flows {
        let count = module.functions.len() + module.entry_points.len();
        let mut fl = Flows {
            calls: vec![Vec::new(); count],
            results: HashMap::default(),
            returns: vec![Vec::new(); count],
            locals: vec![HashMap::default(); count],
            globals: HashMap::default(),
            outs: vec![HashMap::default(); count],
            passed: HashMap::default(),
        };
        for id in 0..count {
            let f = analysis::function(module, id);
            fl.walk(f, id, &f.body);
        }
        fl
    }

    fn walk(&mut self, f: &Function, id: usize, b: &Block) {
        for s in b.iter() {
            match s {
                Statement::Store { pointer, value } => match root(f, *pointer) {
                    Some(Root::Local(l)) => {
                        let at = constant_path(f, *pointer);
                        self.locals[id].entry(l).or_default().push((at, *value));
                    }
                    Some(Root::Global(g)) => {
                        self.globals.entry(g).or_default().push((id, *value));
                    }
                    None => {
                        // Whole through a pointer parameter: an `out` parameter's value.
                        if let E::FunctionArgument(j) = f.expressions[*pointer] {
                            self.outs[id].entry(j).or_default().push(*value);
                        }
                    }
                },
                Statement::Call {
                    function,
                    arguments,
                    result,
                } => {
                    let callee = function.index();
                    for (j, a) in arguments.iter().enumerate() {
                        if let E::LocalVariable(l) = f.expressions[*a] {
                            let at = self.passed.entry((id, l.index())).or_default();
                            at.push((callee, j as u32));
                        }
                    }
                    if let Some(c) = self.calls.get_mut(callee) {
                        if let Some(r) = result {
                            self.results.insert((id, *r), (callee, c.len()));
                        }
                        c.push((id, arguments.clone()));
                    }
                }
                Statement::Return { value: Some(v) } => self.returns[id].push(*v),
                Statement::Block(b) => self.walk(f, id, b),
                Statement::If { accept, reject, .. } => {
                    self.walk(f, id, accept);
                    self.walk(f, id, reject);
                }
                Statement::Switch { cases, .. } => {
                    for c in cases {
                        self.walk(f, id, &c.body);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    self.walk(f, id, body);
                    self.walk(f, id, continuing);
                }
                _ => {}
            }
        }
    }
}

/// A store into a local: the part written (the constant indices from the variable; empty for
/// the whole variable) and the value.
type PartStore = (Vec<u32>, Handle<E>);

enum Root {
    Local(usize),
    Global(usize),
}

/// The constant indices from a variable to the part a pointer points to (stopping at a dynamic
/// index: the store may write any element from there).
fn constant_path(f: &Function, mut p: Handle<E>) -> Vec<u32> {
    let mut out = Vec::new();
    loop {
        match f.expressions[p] {
            E::AccessIndex { base, index } => {
                out.push(index);
                p = base;
            }
            E::Access { base, .. } => {
                out.clear();
                p = base;
            }
            _ => break,
        }
    }
    out.reverse();
    out
}

fn root(f: &Function, mut p: Handle<E>) -> Option<Root> {
    loop {
        match f.expressions[p] {
            E::LocalVariable(l) => return Some(Root::Local(l.index())),
            E::GlobalVariable(g) => return Some(Root::Global(g.index())),
            E::Access { base, .. } | E::AccessIndex { base, .. } => p = base,
            _ => return None,
        }
    }
}

impl Cx<'_> {
    /// The module's calls, returns and stores: computed on first use.
    pub(crate) fn flows(&self) -> &Flows {
        self.flows.get_or_init(|| Flows::of(self.module))
    }

    /// Where the values of expressions (function id, expression) come from, together.
    pub fn origin(&self, start: &[(usize, Handle<E>)]) -> Origin {
        let flows = self.flows();
        let mut out = Origin::default();
        let mut seen: HashSet<Item> = HashSet::default();
        let mut work: Vec<Item> = start.iter().map(|&(id, h)| (id, h, Vec::new())).collect();
        while let Some(item) = work.pop() {
            if seen.len() > MAX_STEPS {
                out.unknown = true;
                break;
            }
            if seen.insert(item.clone()) {
                self.step(flows, item, &mut out, &mut work);
            }
        }
        out
    }

    /// One step back from an expression: what it reads, with the part of it (`path`) the
    /// value at risk is.
    fn step(&self, flows: &Flows, (id, h, path): Item, out: &mut Origin, work: &mut Vec<Item>) {
        let f = analysis::function(self.module, id);
        let whole = |x: Handle<E>| (id, x, Vec::new());
        match f.expressions[h] {
            E::FunctionArgument(i) if id >= self.module.functions.len() => {
                push(&mut out.inputs, format!("input {i}"));
            }
            E::FunctionArgument(i) => {
                if self.is_pointer(id, h) {
                    out.unknown = true;
                    return;
                }
                for (caller, args) in &flows.calls[id] {
                    if let Some(a) = args.get(i as usize) {
                        work.push((*caller, *a, path.clone()));
                    }
                }
            }
            E::CallResult(c) => {
                let c = c.index();
                work.extend(flows.returns[c].iter().map(|v| (c, *v, path.clone())));
            }
            E::Load { pointer } => self.load_origin(flows, id, f, pointer, path, out, work),
            E::ImageSample { .. } | E::ImageLoad { .. } => out.texels = true,
            E::AccessIndex { base, index } => {
                work.push((id, base, [vec![index], path].concat()));
            }
            E::Swizzle {
                vector, pattern, ..
            } => match path.split_first() {
                Some((&i, rest)) => {
                    let c = pattern.get(i as usize).map_or(0, |c| *c as u32);
                    work.push((id, vector, [vec![c], rest.to_vec()].concat()));
                }
                None => work.push(whole(vector)),
            },
            E::Compose { ref components, .. } => match path.split_first() {
                Some((&i, rest)) => match self.component_of(id, components, i) {
                    Some((c, j)) => {
                        let inner = if self.is_scalar(id, c) {
                            Vec::new()
                        } else {
                            vec![j]
                        };
                        work.push((id, c, [inner, rest.to_vec()].concat()));
                    }
                    None => work.extend(components.iter().map(|c| whole(*c))),
                },
                None => work.extend(components.iter().map(|c| whole(*c))),
            },
            E::Binary { left, right, .. } => {
                for x in [left, right] {
                    let keep = if self.is_scalar(id, x) {
                        Vec::new()
                    } else {
                        path.clone()
                    };
                    work.push((id, x, keep));
                }
            }
            E::Unary { expr, .. } => work.push((id, expr, path)),
            ref e => work.extend(operands(e).into_iter().map(whole)),
        }
    }

    /// Which component of a vector `Compose` holds its element `i`: (the component, the
    /// element inside it); for a struct or a matrix, component `i` itself.
    fn component_of(
        &self,
        id: usize,
        components: &[Handle<E>],
        i: u32,
    ) -> Option<(Handle<E>, u32)> {
        let mut at = 0u32;
        for &c in components {
            let n = match self.type_of(id, c) {
                TypeInner::Scalar(_) => 1,
                TypeInner::Vector { size, .. } => *size as u32,
                _ => return components.get(i as usize).map(|c| (*c, 0)),
            };
            if i < at + n {
                return Some((c, i - at));
            }
            at += n;
        }
        None
    }

    fn type_of(&self, id: usize, h: Handle<E>) -> &TypeInner {
        self.info.ty(id, h)
    }

    fn is_scalar(&self, id: usize, h: Handle<E>) -> bool {
        matches!(self.type_of(id, h), TypeInner::Scalar(_))
    }

    fn is_pointer(&self, id: usize, h: Handle<E>) -> bool {
        matches!(
            self.type_of(id, h),
            TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
        )
    }

    /// What a load reads: a uniform, an input the entry point copied, or what was stored.
    #[allow(clippy::too_many_arguments)]
    fn load_origin(
        &self,
        flows: &Flows,
        id: usize,
        f: &Function,
        pointer: Handle<E>,
        path: Vec<u32>,
        out: &mut Origin,
        work: &mut Vec<Item>,
    ) {
        // Dynamic indices are values too.
        let mut p = pointer;
        loop {
            match f.expressions[p] {
                E::Access { base, index } => {
                    work.push((id, index, Vec::new()));
                    p = base;
                }
                E::AccessIndex { base, .. } => p = base,
                _ => break,
            }
        }
        match f.expressions[p] {
            E::LocalVariable(l) => match flows.locals[id].get(&l.index()) {
                Some(stores) => {
                    for (at, v) in stores {
                        // A store into a part the value at risk is not in does not reach it.
                        let n = at.len().min(path.len());
                        if at[..n] == path[..n] {
                            let rest = path.get(at.len()..).map_or(Vec::new(), <[u32]>::to_vec);
                            work.push((id, *v, rest));
                        }
                    }
                }
                None => out.unknown = true,
            },
            E::GlobalVariable(g) => {
                let gv = &self.module.global_variables[g];
                if gv.space != naga::AddressSpace::Private {
                    if gv.space == naga::AddressSpace::Uniform {
                        push(&mut out.uniforms, self.uniform_name(f, pointer, &path));
                    } else {
                        out.unknown = true;
                    }
                    return;
                }
                let stores = flows.globals.get(&g.index()).map_or(&[][..], |v| &v[..]);
                let entries = self.module.functions.len();
                if stores.iter().all(|(fid, _)| *fid >= entries) {
                    // Written only by the entry point: an input, a built-in.
                    let name = gv.name.clone().unwrap_or_else(|| "input".to_string());
                    push(&mut out.inputs, name);
                } else {
                    work.extend(stores.iter().map(|(fid, v)| (*fid, *v, Vec::new())));
                }
            }
            _ => out.unknown = true,
        }
    }

    /// The WebGL name of the part `path` of the uniform a pointer points into
    /// (`light.cutOff`, `u_lights[*].pos`, `u_range.y`): struct members by name, array elements
    /// as `[i]` (`[*]` for a dynamic index), vector components as `.x`…
    fn uniform_name(&self, f: &Function, pointer: Handle<E>, path: &[u32]) -> String {
        let mut steps = Vec::new();
        let mut p = pointer;
        let global = loop {
            match f.expressions[p] {
                E::Access { base, .. } => {
                    steps.push(None);
                    p = base;
                }
                E::AccessIndex { base, index } => {
                    steps.push(Some(index));
                    p = base;
                }
                E::GlobalVariable(g) => break g,
                _ => return "a uniform".to_string(),
            }
        };
        steps.reverse();
        steps.extend(path.iter().map(|i| Some(*i)));
        let gv = &self.module.global_variables[global];
        let mut ty = gv.ty;
        // Blocks (essl's default block, named blocks) hold uniforms as members.
        let mut name = match self.module.types[ty].inner {
            TypeInner::Struct { .. } => String::new(),
            _ => gv.name.clone().unwrap_or_default(),
        };
        for step in steps {
            match &self.module.types[ty].inner {
                TypeInner::Struct { members, .. } => {
                    let Some(m) = step.and_then(|i| members.get(i as usize)) else {
                        break;
                    };
                    if !name.is_empty() {
                        name.push('.');
                    }
                    name.push_str(m.name.as_deref().unwrap_or("?"));
                    ty = m.ty;
                }
                TypeInner::Array { base, .. } => {
                    match step {
                        Some(i) => name.push_str(&format!("[{i}]")),
                        None => name.push_str("[*]"),
                    }
                    ty = *base;
                }
                TypeInner::Vector { .. } | TypeInner::Matrix { .. } => {
                    if let Some(i) = step {
                        name.push_str(&format!(".{}", ["x", "y", "z", "w"][i.min(3) as usize]));
                    }
                    break;
                }
                _ => break,
            }
        }
        if name.is_empty() {
            gv.name.clone().unwrap_or_else(|| "a uniform".to_string())
        } else {
            name
        }
    }
}

/// A step of the walk: (function, expression, the part of its value that matters).
type Item = (usize, Handle<E>, Vec<u32>);

fn push(list: &mut Vec<String>, name: String) {
    if !list.contains(&name) {
        list.push(name);
    }
}

impl Cx<'_> {
    /// Makes `d` a note when one uniform alone, with constants, reaches the values at risk: the
    /// hazard needs that value out of the range the shader was written for, and the message
    /// names it.
    pub(crate) fn grade(
        &self,
        mut d: essl::diagnostic::Diagnostic,
        at_risk: &[(usize, Handle<E>)],
    ) -> essl::diagnostic::Diagnostic {
        if let Some(name) = self.origin(at_risk).single_uniform() {
            d.severity = essl::diagnostic::Severity::Note;
            d.message = format!(
                "{}, only when `{name}` is out of the range the shader expects",
                d.message
            );
            d = d.with_note(format!(
                "`{name}` alone reaches it: essl-gl's validation mode checks the value at each draw"
            ));
        }
        d
    }
}
