//! The value-range analysis: abstract interpretation of a validated naga module.
//!
//! Every expression of every function gets a [`Val`]: intervals per component and [`Facts`].
//! Memory is flow-insensitive: each variable (a local, a private global, a pointer parameter)
//! holds the join of every value ever stored into it, and a load reads that join. Calls are
//! context-insensitive: a function's parameters hold the join of the arguments of every call,
//! its result the join of every `return`, and a pointer parameter shares its cell with the
//! variables callers pass. The whole module is iterated to a fixpoint, with widening of the
//! variables' cells after a few rounds so that loops terminate. Parameters and results join
//! without widening: GLSL ES has no recursion, so every cycle of the fixpoint passes through a
//! variable, and a result widened on its own would stay infinite when the loop that computes it
//! is bounded (a ray march's distance, [`growth`]). A function called from one place is walked
//! at that call, so most modules take one round (2,134 of the 2,214 analyses of dEQP's shaders).
//!
//! External values are unknown: uniforms, the entry point's inputs and texels are `(−∞, ∞)`
//! in [`Mode::Sound`]. [`Mode::Typical`] runs the same analysis with external values of
//! ordinary magnitude and the signs formulas expect (`[0, 10]`, matrix entries and texels in
//! `[0, 1]`): what the
//! `mediump` rule needs to ask "does this overflow for ordinary parameter values?".
//!
//! [`Analysis`]'s `impl` is spread over the submodules by concern, which is why they use one
//! another's methods:
//! - `calls`: the result of a call from that call's own arguments (the last round), and the
//!   walk of a function called from one place at that call (every round);
//! - `statements`: the walk over a function's statements (emits, stores, calls, returns, the
//!   `if` conditions that refine what the branches load);
//! - `memory`: the cells variables hold, and the shapes of external and unknown values;
//! - `flow`: what a variable holds at each point of the walk (strong updates);
//! - `conditions`: what a comparison says about the values it compares;
//! - `eval`: the value of each expression;
//! - `same`: whether two expressions certainly have the same value;
//! - `relational`: relations intervals lose (an offset at most a vector's smallest component, a
//!   monotone function of one variable);
//! - `binary`: the arithmetic operators, on numbers and on matrices;
//! - `algebra`: signs intervals lose in polynomial shapes (squares in products, completed
//!   squares);
//! - `math`: the built-in functions, by family;
//! - `names`: what an input's name says it holds (a colour, a normal).
//! - `series` and `growth`: bounds widening cannot find, for the sum of a geometric series and
//!   for a variable loops with a fixed count of iterations grow.

mod algebra;
mod binary;
mod calls;
mod conditions;
mod eval;
mod flow;
mod growth;
mod math;
mod memory;
pub(crate) mod names;
mod relational;
mod same;
mod series;
mod statements;

use rustc_hash::FxHashMap as HashMap;

use essl::lower::{FunctionTypes, Lowered};
use naga::{Expression as E, Function, Handle};

use crate::value::{Num, Val};

pub(crate) use conditions::condition_atoms;
pub use conditions::{integral, refine_num, relation, Refinement};
pub(crate) use eval::WINDOW;
pub(crate) use flow::root_global;
pub use memory::{const_value, literal};
pub(crate) use names::{SCENE, TIME};
pub(crate) use statements::{diverges, each_statement, operands};

use memory::write;
use statements::single_stores;

/// The magnitude of an ordinary external value in [`Mode::Typical`]: modest, so that what
/// overflows there overflows for values any scene uses (larger magnitudes are the runtime
/// check's to judge, with the actual values).
pub const TYPICAL: f64 = 10.0;
/// The magnitude of an ordinary external matrix entry in [`Mode::Typical`] (rotations, scales
/// and normal matrices; translations reach vectors through `M * vec4(p, 1.0)`).
pub const TYPICAL_MATRIX: f64 = 1.0;

/// Relative slack for GPU approximations of transcendental functions (a few ulps of `highp`).
pub const EPS: f64 = 1.0 / (1u64 << 20) as f64;

/// Rounds before joins become widenings. Every value a loop carries that grows takes this many
/// rounds plus two; at 3 (from 6) the findings on both lint corpora are the same and `essl
/// lint` of the Vite bench's 200 shaders runs 3.3 % fewer instructions (85.0 M against 82.2 M at
/// `c942ea9`, callgrind); at 2, two `sqrt` findings of Cesium's importance sampling appear.
const WIDEN_AFTER: usize = 3;
/// A bound on rounds (widening converges long before).
const MAX_ROUNDS: usize = 40;

/// What external values are assumed to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Anything: the analysis is sound for every value.
    Sound,
    /// Ordinary magnitudes (`[0, TYPICAL]`, matrix entries and texels in `[0, 1]`).
    Typical,
}

/// A variable the analysis tracks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Root {
    /// A local variable: (function, local index).
    Local(usize, usize),
    /// A global variable.
    Global(usize),
    /// The cell behind a pointer parameter: (function, argument index).
    Arg(usize, usize),
}

/// A path step standing for any index (a dynamic index into a vector or matrix).
pub const ANY: u32 = u32::MAX;

/// A part of a variable: its root and the member / column / component indices to it (array
/// elements are summarised: their index is always 0).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Place {
    /// The variable.
    pub root: Root,
    /// The indices.
    pub path: Vec<u32>,
}

/// What the analysis knows about one function.
#[derive(Clone, Debug, Default)]
pub struct FnFacts {
    /// The value of each expression (by handle index).
    pub values: Vec<Val>,
    /// The place each pointer expression points to.
    pub places: Vec<Option<Place>>,
    /// The `Emit` statement that evaluates each expression (0: none).
    pub emit: Vec<u32>,
    /// Locals stored exactly once, outside loops, never passed by pointer: the stored value.
    pub single_store: HashMap<usize, Handle<E>>,
    /// Every value stored whole into a local that is never stored in part or passed by pointer.
    pub stores: HashMap<usize, Vec<Handle<E>>>,
    /// Whether this is an entry point (the wrapper essl generates, not user code).
    pub entry: bool,
    /// For each load, the version of the variable it reads (0: not followed); two loads with
    /// the same version read the same value.
    pub load_version: Vec<u32>,
    /// The accumulators of geometric series, by local index ([`series`]).
    series: HashMap<usize, series::Series>,
    /// The accumulators loops with bounded iteration counts grow, by local index ([`growth`]).
    growth: HashMap<usize, growth::Growth>,
}

/// The analysis of a whole module.
#[derive(Debug)]
pub struct Analysis {
    /// The assumption about external values.
    pub mode: Mode,
    /// Per function (module functions by handle index, then entry points).
    pub functions: Vec<FnFacts>,
    memory: HashMap<Root, Val>,
    args: Vec<Vec<Val>>,
    results: Vec<Val>,
    changed: bool,
    widening: bool,
    emit_counter: u32,
    /// What the enclosing `if` conditions say about scalar places, where they hold.
    refine: Vec<(Place, Refinement)>,
    /// What the walk knows variables hold at the current statement ([`flow`]).
    current: flow::Current,
    /// The private globals each function may write.
    global_writes: Vec<rustc_hash::FxHashSet<usize>>,
    /// The last version [`flow`] gave a variable.
    version_counter: u32,
    /// The value a whole store into a local gave it, by the version the store made.
    version_stores: HashMap<u32, Handle<E>>,
    /// The results of calls from their own arguments ([`calls`]).
    calls: calls::Calls,
    /// The functions walked at their only call ([`calls`]).
    at_call: calls::AtCall,
    /// What user functions read this round (cells, parameters, call results): a later change
    /// to one of them in the same round makes the round `stale`.
    reads: std::cell::RefCell<Reads>,
    /// Whether something read this round changed after it was read (another round is needed).
    stale: bool,
    /// Whether the walk is in an entry point (whose reads only copy outputs).
    walking_entry: bool,
    /// The rounds the walk took to its fixpoint.
    rounds: usize,
    /// The ratio each series' bound last used, by function and accumulator ([`series`]).
    series_ratio: HashMap<(usize, usize), Option<crate::interval::Interval>>,
    /// The step bound each accumulator's bound last used, by function and accumulator, and how
    /// many times it changed ([`growth`]).
    growth_step: HashMap<(usize, usize), growth::Steps>,
    /// Whether, in [`Mode::Typical`], a name gives a position or a time its larger magnitude
    /// ([`names`]).
    named_magnitudes: bool,
    /// What the name of each global says, then those of its members where it is a block
    /// (empty for private globals).
    uniform_names: Vec<Vec<names::Said>>,
    /// What the name of each parameter of each function says.
    arg_names: Vec<Vec<names::Said>>,
}

/// What user functions read in one round of the walk.
#[derive(Debug, Default)]
struct Reads {
    roots: rustc_hash::FxHashSet<Root>,
    args: rustc_hash::FxHashSet<usize>,
    results: rustc_hash::FxHashSet<usize>,
}

/// The function with index `id` (module functions first, then entry points).
pub fn function(module: &naga::Module, id: usize) -> &Function {
    match module.functions.iter().nth(id) {
        Some((_, f)) => f,
        None => &module.entry_points[id - module.functions.len()].function,
    }
}

/// The function being evaluated: what the statement walk, the expression evaluation and the
/// operator rules all read.
#[derive(Clone, Copy)]
struct Site<'a> {
    /// The module.
    module: &'a naga::Module,
    /// The module lowered, with its expressions' types.
    info: &'a Lowered,
    /// The types of the function's expressions.
    types: FunctionTypes<'a>,
    /// The function.
    f: &'a Function,
    /// Its index (module functions first, then entry points).
    id: usize,
}

impl<'a> Site<'a> {
    /// The type of expression `h`.
    fn ty(&self, h: Handle<E>) -> &'a naga::TypeInner {
        self.types.ty(h)
    }
}

impl Analysis {
    /// Analyses a lowered module (validated or typed); `per_call`: with the last round that
    /// gives each call the result of its own arguments (what signs and ranges of results need;
    /// magnitudes of ordinary values do not).
    pub fn run_for(info: &Lowered, mode: Mode, per_call: bool) -> Analysis {
        Analysis::run_with(info, mode, per_call, true)
    }

    /// [`Mode::Typical`] with every external value of modest magnitude, whatever its name says
    /// (a position, a time): what an overflow that names reach needs of them.
    pub fn run_modest(info: &Lowered) -> Analysis {
        Analysis::run_with(info, Mode::Typical, false, false)
    }

    /// [`Analysis::run_for`]; `named_magnitudes`: whether names give magnitudes.
    fn run_with(info: &Lowered, mode: Mode, per_call: bool, named_magnitudes: bool) -> Analysis {
        let module = &info.module;
        let count = module.functions.len() + module.entry_points.len();
        let mut a = Analysis {
            mode,
            functions: vec![FnFacts::default(); count],
            memory: HashMap::default(),
            args: (0..count)
                .map(|id| vec![Val::Bot; function(module, id).arguments.len()])
                .collect(),
            results: vec![Val::Bot; count],
            changed: false,
            widening: false,
            emit_counter: 0,
            refine: Vec::new(),
            current: flow::Current::default(),
            global_writes: flow::global_writes(module),
            version_counter: 0,
            version_stores: HashMap::default(),
            calls: calls::Calls::default(),
            at_call: calls::AtCall::new(module),
            reads: Default::default(),
            stale: false,
            walking_entry: false,
            rounds: 0,
            series_ratio: HashMap::default(),
            growth_step: HashMap::default(),
            named_magnitudes,
            uniform_names: module
                .global_variables
                .iter()
                .map(|(_, g)| match (g.space, &module.types[g.ty].inner) {
                    (naga::AddressSpace::Private, _) => Vec::new(),
                    (_, naga::TypeInner::Struct { members, .. }) => {
                        std::iter::once(names::Said::default())
                            .chain(
                                members
                                    .iter()
                                    .map(|m| names::said(module, m.name.as_deref(), m.ty)),
                            )
                            .collect()
                    }
                    _ => vec![names::said(module, g.name.as_deref(), g.ty)],
                })
                .collect(),
            arg_names: (0..count)
                .map(|id| {
                    let f = function(module, id);
                    f.arguments
                        .iter()
                        .map(|a| names::said(module, a.name.as_deref(), a.ty))
                        .collect()
                })
                .collect(),
        };
        for id in 0..count {
            let f = function(module, id);
            let (single, stores) = single_stores(f);
            a.functions[id].single_store = single;
            a.functions[id].stores = stores;
            // The stores and loops both bounds read: walked once, where there is a loop.
            if series::has_loop(&f.body) {
                let w = series::Walk::of(f);
                a.functions[id].series = series::find(f, &w);
                a.functions[id].growth = growth::find(f, &w);
            }
            a.functions[id].entry = id >= module.functions.len();
        }
        // Private globals start with their initialiser.
        for (h, g) in module.global_variables.iter() {
            if let Some(init) = g.init {
                let v = const_value(module, init);
                let root = Root::Global(h.index());
                let mut cell = a.cell(module, root);
                write(&mut cell, &[], &v, false);
                a.memory.insert(root, cell);
            }
        }
        for round in 0..MAX_ROUNDS {
            a.changed = false;
            a.stale = false;
            a.reads.replace(Reads::default());
            a.widening = round >= WIDEN_AFTER;
            a.at_call.start_round();
            a.rounds = round + 1;
            // Callers after callees is the order naga keeps; entry points last. Walking the
            // entry points first gives the inputs their values before `main_` reads them; a
            // function called from one place has been walked at that call.
            let order = (module.functions.len()..count).chain(0..module.functions.len());
            for id in order {
                if !a.at_call.walked[id] {
                    a.run_function(module, info, id);
                }
            }
            // Nothing changed, or nothing that was read changed after it was read: the next
            // round would read and compute the same (one round for straight-line code).
            if !a.changed || !a.stale {
                break;
            }
        }
        // At the fixpoint, one more round gives each call the result of its own arguments
        // (when some call passes any).
        if !per_call || !calls::with_arguments(module) {
            return a;
        }
        a.calls.precise = true;
        a.widening = false;
        // A function that calls nothing computes what it did at the fixpoint: its parameters,
        // the cells and the results it reads are the same.
        let order: Vec<usize> = (module.functions.len()..count)
            .chain(0..module.functions.len())
            .filter(|&id| calls::calls_any(function(module, id)))
            .collect();
        for id in order {
            a.run_function(module, info, id);
        }
        a
    }

    /// The value of expression `h` of function `id`.
    pub fn value(&self, id: usize, h: Handle<E>) -> &Val {
        self.functions[id]
            .values
            .get(h.index())
            .unwrap_or(&Val::Bot)
    }

    /// The scalar or vector value of expression `h` of function `id`, if it has one.
    pub fn num(&self, id: usize, h: Handle<E>) -> Option<&Num> {
        self.value(id, h).num().filter(|n| !n.is_bottom())
    }
}
