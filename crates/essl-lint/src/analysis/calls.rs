//! The result of a call from that call's own arguments.
//!
//! Parameters hold the join of what every call passes, so the result every call sees is the
//! function's result for any of those arguments: `float lum(vec3 c) { return dot(c, W); }`
//! called once with a signed vector gives a signed result at the call with a colour too. Once
//! the module is at its fixpoint, a last round walks each called function again for each call,
//! with that call's arguments as its parameters (the callee's own values, the cells and the
//! other calls untouched): the call's result is what the function returns for them — its range,
//! sign, unit length, whether it can be zero. Distinct argument values are walked once
//! (memoised), calls nest to a bounded depth, and the walks share a bounded budget of
//! expressions; beyond it, or for a function with pointer parameters, a call gets the join.

use naga::{Expression as E, Handle};

use super::{function, Analysis, Site};
use crate::value::Val;

/// How deep calls of calls are walked with their own arguments.
const MAX_DEPTH: usize = 3;
/// The most expressions all such walks of one analysis evaluate.
const BUDGET: usize = 200_000;

/// What the last round of the analysis keeps to give each call its own result.
#[derive(Debug, Default)]
pub(super) struct Calls {
    /// Whether calls get their own results (the last round).
    pub precise: bool,
    /// The results of the functions being walked for one call, innermost last.
    pub results: Vec<Val>,
    /// (function, arguments, result) of the calls walked so far.
    memo: Vec<(usize, Vec<Val>, Val)>,
    /// Expressions the walks have evaluated.
    spent: usize,
}

impl Calls {
    /// Whether a walk for one call is under way (stores then change no cell).
    pub fn walking(&self) -> bool {
        !self.results.is_empty()
    }
}

/// Whether some function of the module takes arguments (so that a call passes some).
pub(super) fn with_arguments(module: &naga::Module) -> bool {
    module
        .functions
        .iter()
        .any(|(_, f)| !f.arguments.is_empty())
}

impl Analysis {
    /// The result of calling function `c` with `arguments` (of the caller at `s`), walked with
    /// those arguments; `None` where the join of every call's result stands.
    pub(super) fn call_result(
        &mut self,
        s: Site,
        c: usize,
        arguments: &[Handle<E>],
    ) -> Option<Val> {
        if !self.calls.precise || self.calls.results.len() >= MAX_DEPTH {
            return None;
        }
        let callee = function(s.module, c);
        let by_value = callee
            .arguments
            .iter()
            .all(|a| !matches!(s.module.types[a.ty].inner, naga::TypeInner::Pointer { .. }));
        if !by_value || c >= s.module.functions.len() {
            return None;
        }
        let args: Vec<Val> = arguments
            .iter()
            .map(|a| self.functions[s.id].values[a.index()].clone())
            .collect();
        if args == self.args[c] || args.iter().any(Val::is_bot) {
            return None;
        }
        if let Some((_, _, r)) = self
            .calls
            .memo
            .iter()
            .find(|(f, a, _)| *f == c && *a == args)
        {
            return Some(r.clone());
        }
        let cost = callee.expressions.len();
        if self.calls.spent + cost > BUDGET {
            return None;
        }
        self.calls.spent += cost;
        let saved_args = std::mem::replace(&mut self.args[c], args.clone());
        let saved_facts = self.functions[c].clone();
        let saved_current = std::mem::take(&mut self.current);
        let saved_refine = std::mem::take(&mut self.refine);
        let saved_entry = self.walking_entry;
        self.calls.results.push(Val::Bot);
        self.run_function(s.module, s.info, c);
        let result = self.calls.results.pop().unwrap_or(Val::Bot);
        self.walking_entry = saved_entry;
        self.args[c] = saved_args;
        self.functions[c] = saved_facts;
        self.current = saved_current;
        self.refine = saved_refine;
        self.calls.memo.push((c, args, result.clone()));
        Some(result)
    }
}
