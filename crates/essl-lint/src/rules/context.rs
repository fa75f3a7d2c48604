//! What the rules share: the analysed shader ([`Cx`]), who reads each expression, and how
//! numbers and intervals read in messages.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use essl::source::{SourceFile, Span};
use essl::Shader;
use naga::{Block, Expression as E, Function, Handle, MathFunction as Mf, Statement};

pub(crate) use crate::analysis::operands;
use crate::analysis::{self, Analysis, Mode};
use crate::interval::Interval;
use crate::precision::Precisions;
use crate::symbolic::{self, Sym};

/// A call of a built-in function (see [`Cx::math_calls`]).
pub struct MathCall<'a> {
    /// The function's id.
    pub id: usize,
    /// The function.
    pub f: &'a Function,
    /// The call.
    pub call: Handle<E>,
    /// Its span.
    pub span: Span,
    /// Its arguments as the user wrote them.
    pub args: Vec<Handle<E>>,
}

/// A `pow(x, y)` call (see [`Cx::pow_calls`]).
pub struct PowCall<'a> {
    /// The function's id.
    pub id: usize,
    /// The function.
    pub f: &'a Function,
    /// The call.
    pub call: Handle<E>,
    /// Its span.
    pub span: Span,
    /// Its base.
    pub base: Handle<E>,
    /// Its exponent.
    pub exp: Handle<E>,
}

/// A shader analysed for the rules.
pub struct Cx<'a> {
    /// The shader's text.
    pub file: &'a SourceFile,
    /// Its naga IR.
    pub module: &'a naga::Module,
    /// The checked module the IR was lowered from (statements as the user wrote them).
    pub hir: &'a essl::hir::Module,
    /// The IR with its expressions' types.
    pub info: &'a essl::lower::Lowered,
    /// The analysis with any external value: computed on first use ([`Cx::sound`]).
    sound: std::cell::OnceCell<Analysis>,
    /// The analysis with ordinary external values: computed on first use ([`Cx::typical`]),
    /// since only low-precision arithmetic asks for it.
    typical: std::cell::OnceCell<Analysis>,
    /// [`Cx::typical`] without the magnitudes names give: computed on first use
    /// ([`Cx::modest`]).
    modest: std::cell::OnceCell<Analysis>,
    /// Precisions by span.
    pub prec: Precisions,
    /// Private globals that user functions write.
    pub written: HashSet<usize>,
    /// Calls, returns and stores, for [`Cx::origin`]: computed on first use.
    pub(crate) flows: std::cell::OnceCell<super::origin::Flows>,
    /// Whether the sound analysis gives each call its own result.
    per_call: bool,
}

/// What a shader not lowered is read through: an empty module, which only the rules on the
/// checked module are run with ([`crate::needs_ir`] found nothing for the others).
fn unlowered() -> &'static essl::lower::Lowered {
    static EMPTY: std::sync::OnceLock<essl::lower::Lowered> = std::sync::OnceLock::new();
    EMPTY.get_or_init(|| {
        essl::lower::Lowered::typified(naga::Module::default(), essl::Stage::Fragment)
            .expect("an empty module has no expression to type")
    })
}

impl<'a> Cx<'a> {
    /// Analyses a shader that compiled; `None` when it has no naga IR.
    pub fn new(shader: &'a Shader) -> Option<Cx<'a>> {
        shader.naga.as_ref()?;
        Some(Cx::with_precisions(
            shader,
            Precisions::of(&shader.module),
            true,
        ))
    }

    /// [`Cx::new`] with the precisions already looked up; `per_call`: whether the sound
    /// analysis gives each call its own result. A shader not lowered is read through an empty
    /// module: only the rules on the checked module may be run with it.
    pub fn with_precisions(shader: &'a Shader, prec: Precisions, per_call: bool) -> Cx<'a> {
        let info = shader.naga.as_ref().unwrap_or_else(|| unlowered());
        let module = &info.module;
        let mut written = HashSet::default();
        for (_, f) in module.functions.iter() {
            collect_written(f, &f.body, &mut written);
        }
        Cx {
            file: &shader.file,
            module,
            hir: &shader.module,
            info,
            sound: std::cell::OnceCell::new(),
            typical: std::cell::OnceCell::new(),
            modest: std::cell::OnceCell::new(),
            prec,
            written,
            flows: std::cell::OnceCell::new(),
            per_call,
        }
    }

    /// The analysis with any external value, which every rule reads (`mediump-overflow` for
    /// the shape of an expression only: there each call's own result is left out unless a rule
    /// that reads signs and ranges has something to look at).
    pub fn sound(&self) -> &Analysis {
        self.sound
            .get_or_init(|| Analysis::run_for(self.info, Mode::Sound, self.per_call))
    }

    /// The analysis with ordinary external values (`[0, TYPICAL]`, matrix entries and texels in
    /// `[0, 1]`).
    pub fn typical(&self) -> &Analysis {
        self.typical
            .get_or_init(|| Analysis::run_for(self.info, Mode::Typical, false))
    }

    /// The analysis with ordinary external values all of modest magnitude, positions and times
    /// included ([`Analysis::run_modest`]).
    pub fn modest(&self) -> &Analysis {
        self.modest.get_or_init(|| Analysis::run_modest(self.info))
    }

    /// The user's functions (not the entry-point wrapper): (index, function).
    pub fn functions(&self) -> impl Iterator<Item = (usize, &'a Function)> + '_ {
        let m = self.module;
        (0..m.functions.len()).map(move |id| (id, analysis::function(m, id)))
    }

    /// The scalar kind of an expression of function `id`.
    pub fn kind(&self, id: usize, h: Handle<E>) -> Option<naga::ScalarKind> {
        self.info.ty(id, h).scalar_kind()
    }

    /// Whether expression `h` of function `id` is a matrix.
    pub fn is_matrix(&self, id: usize, h: Handle<E>) -> bool {
        matches!(self.info.ty(id, h), naga::TypeInner::Matrix { .. })
    }

    /// Every call of the built-in `fun` with a span in the source, its arguments through
    /// [`Cx::operand`].
    pub fn math_calls(&self, fun: Mf) -> Vec<MathCall<'a>> {
        let mut out = Vec::new();
        for (id, f) in self.functions() {
            for (h, e) in f.expressions.iter() {
                let E::Math {
                    fun: g,
                    arg,
                    arg1,
                    arg2,
                    arg3,
                } = *e
                else {
                    continue;
                };
                let span = self.span(f, h);
                if g != fun || span.is_empty() {
                    continue;
                }
                let args = [Some(arg), arg1, arg2, arg3]
                    .into_iter()
                    .flatten()
                    .map(|a| self.operand(f, h, a))
                    .collect();
                out.push(MathCall {
                    id,
                    f,
                    call: h,
                    span,
                    args,
                });
            }
        }
        out
    }

    /// Every `pow(x, y)` call with a span in the source: (function id, function, the call,
    /// its span, its base, its exponent), base and exponent through [`Cx::operand`].
    pub fn pow_calls(&self) -> Vec<PowCall<'a>> {
        self.math_calls(Mf::Pow)
            .into_iter()
            .filter(|c| c.args.len() == 2)
            .map(|c| PowCall {
                id: c.id,
                f: c.f,
                call: c.call,
                span: c.span,
                base: c.args[0],
                exp: c.args[1],
            })
            .collect()
    }

    /// The source span of an expression.
    pub fn span(&self, f: &Function, h: Handle<E>) -> Span {
        Span::from(f.expressions.get_span(h))
    }

    /// The text of a span.
    pub fn text(&self, span: Span) -> &'a str {
        self.file.slice(span)
    }

    /// The operand `h` of `parent` as the user wrote it: through the splats the lowering adds
    /// to widen a scalar argument (they carry the call's span).
    pub fn operand(&self, f: &Function, parent: Handle<E>, mut h: Handle<E>) -> Handle<E> {
        let ps = self.span(f, parent);
        while let E::Splat { value, .. } = f.expressions[h] {
            let s = self.span(f, h);
            if s == ps || s.is_empty() {
                h = value;
            } else {
                break;
            }
        }
        h
    }

    /// The symbolic view of function `id`.
    pub fn sym(&'a self, id: usize, f: &'a Function) -> Sym<'a> {
        Sym::new(self.module, f, id, self.sound(), &self.written)
    }

    /// Whether an expression has no side effects and no calls (so that a fix may repeat it).
    pub fn pure(&self, f: &Function, h: Handle<E>) -> bool {
        let mut stack = vec![h];
        let mut n = 0;
        while let Some(x) = stack.pop() {
            n += 1;
            if n > 64 {
                return false;
            }
            match &f.expressions[x] {
                E::CallResult(_) => return false,
                E::Binary { left, right, .. } => stack.extend([*left, *right]),
                E::Unary { expr, .. }
                | E::As { expr, .. }
                | E::Splat { value: expr, .. }
                | E::Swizzle { vector: expr, .. } => stack.push(*expr),
                E::AccessIndex { base, .. } => stack.push(*base),
                E::Access { base, index } => stack.extend([*base, *index]),
                E::Load { pointer } => stack.push(*pointer),
                E::Math {
                    arg,
                    arg1,
                    arg2,
                    arg3,
                    ..
                } => stack.extend([Some(*arg), *arg1, *arg2, *arg3].into_iter().flatten()),
                E::Compose { components, .. } => stack.extend(components.iter().copied()),
                E::Select {
                    condition,
                    accept,
                    reject,
                } => stack.extend([*condition, *accept, *reject]),
                _ => {}
            }
        }
        true
    }

    /// What kind of value `h` is, in a few words ("this dot product").
    pub fn what(&self, f: &Function, id: usize, h: Handle<E>) -> String {
        let named = match f.expressions[h] {
            E::Load { pointer } => match f.expressions[pointer] {
                E::LocalVariable(l) => f.local_variables[l]
                    .name
                    .clone()
                    .filter(|n| !n.starts_with("_essl")),
                _ => None,
            },
            _ => None,
        };
        let r = symbolic::resolve(f, self.sound(), id, h);
        let kind = match f.expressions[r] {
            E::Math { fun: Mf::Dot, .. } => Some("a dot product"),
            E::Math { fun: Mf::Cross, .. } => Some("a cross product"),
            E::Binary {
                op: naga::BinaryOperator::Subtract,
                ..
            } => Some("a difference"),
            _ => None,
        };
        match (named, kind) {
            (Some(n), Some(k)) => format!("`{n}`, {k},"),
            (Some(n), None) => format!("`{n}`"),
            (None, Some(k)) => format!("this {}", &k[k.find(' ').map_or(0, |i| i + 1)..]),
            (None, None) => "this".to_string(),
        }
    }
}

fn collect_written(f: &Function, b: &naga::Block, out: &mut HashSet<usize>) {
    use analysis::root_global;
    analysis::each_statement(b, &mut |s| match s {
        Statement::Store { pointer, .. } => out.extend(root_global(f, *pointer)),
        Statement::Call { arguments, .. } => {
            out.extend(arguments.iter().filter_map(|a| root_global(f, *a)));
        }
        _ => {}
    });
}

/// A number as people read it: five significant digits (so that rounding slack does not
/// show), no trailing zeros, `∞`.
pub fn fmt_num(x: f64) -> String {
    if x.is_infinite() {
        return if x > 0.0 {
            "+∞".into()
        } else {
            "-∞".into()
        };
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = 5 - 1 - x.abs().log10().floor() as i32;
    let p = 10f64.powi(digits.clamp(-30, 30));
    let r = (x * p).round() / p;
    let s = format!("{r}");
    if s.contains('e') {
        format!("{x:e}")
    } else {
        s
    }
}

/// An interval as people read it: `[-1, 1]`.
pub fn describe(i: Interval) -> String {
    if i.is_empty() {
        return "nothing".into();
    }
    format!("[{}, {}]", fmt_num(i.lo), fmt_num(i.hi))
}

/// Who reads an expression's value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum User {
    /// An expression.
    Expr(Handle<E>),
    /// A statement.
    Stmt,
}

/// Whether expression `x` of `f` is `d` or is computed from it (through operands, not locals).
pub fn computed_from(f: &Function, x: Handle<E>, d: Handle<E>) -> bool {
    let mut work = vec![x];
    let mut steps = 0;
    while let Some(h) = work.pop() {
        steps += 1;
        if h == d {
            return true;
        }
        // Operands precede their users: nothing before `d` is computed from it.
        if h < d || steps > 256 {
            continue;
        }
        work.extend(operands(&f.expressions[h]));
    }
    false
}

/// Who reads each expression of a function.
pub fn users(f: &Function) -> HashMap<Handle<E>, Vec<User>> {
    let mut map: HashMap<Handle<E>, Vec<User>> = HashMap::default();
    for (h, e) in f.expressions.iter() {
        for o in operands(e) {
            map.entry(o).or_default().push(User::Expr(h));
        }
    }
    fn walk(b: &Block, map: &mut HashMap<Handle<E>, Vec<User>>) {
        for s in b.iter() {
            let mut read = |h: &Handle<E>| map.entry(*h).or_default().push(User::Stmt);
            match s {
                Statement::Store { value, .. } => read(value),
                Statement::Return { value: Some(v) } => read(v),
                Statement::Call { arguments, .. } => arguments.iter().for_each(read),
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => {
                    read(condition);
                    walk(accept, map);
                    walk(reject, map);
                }
                Statement::Switch { selector, cases } => {
                    read(selector);
                    for c in cases {
                        walk(&c.body, map);
                    }
                }
                Statement::Loop {
                    body,
                    continuing,
                    break_if,
                } => {
                    if let Some(b) = break_if {
                        read(b);
                    }
                    walk(body, map);
                    walk(continuing, map);
                }
                Statement::Block(b) => walk(b, map),
                _ => {}
            }
        }
    }
    walk(&f.body, &mut map);
    map
}
