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
//!
//! During the rounds to the fixpoint, a function that only one call statement names is walked
//! at that call, once the call has passed its arguments ([`AtCall`]). Walking callees first
//! (naga's order) would read parameters their callers have not passed yet, and callers first
//! would read results not yet returned: either makes a second round of nearly every module
//! with a helper function.

use naga::{Expression as E, Handle};

use super::statements::each_statement;
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

/// How deep walks at a call nest before the rest wait for the round's order: a bound on the
/// analysis's recursion whatever the depth of the call graph (each level takes about 2 KiB of
/// stack in an optimised build, 4.5 KiB in an unoptimised one, measured on x86-64).
const MAX_NESTED: usize = 64;

/// Which functions the current round walks at their call.
#[derive(Debug, Default)]
pub(super) struct AtCall {
    /// How many call statements name each function (by index).
    sites: Vec<u32>,
    /// The functions walked this round.
    pub walked: Vec<bool>,
    /// How many walks at a call are under way.
    nested: usize,
}

impl AtCall {
    /// Counts the call statements of `module` naming each of its functions.
    pub fn new(module: &naga::Module) -> AtCall {
        let count = module.functions.len() + module.entry_points.len();
        let mut sites = vec![0; count];
        for id in 0..count {
            each_statement(&function(module, id).body, &mut |s| {
                if let naga::Statement::Call { function, .. } = s {
                    if let Some(n) = sites.get_mut(function.index()) {
                        *n += 1;
                    }
                }
            });
        }
        AtCall {
            sites,
            walked: vec![false; count],
            nested: 0,
        }
    }

    /// Starts a round: nothing is walked yet.
    pub fn start_round(&mut self) {
        self.walked.fill(false);
    }
}

/// Whether some function of the module takes arguments (so that a call passes some).
pub(super) fn with_arguments(module: &naga::Module) -> bool {
    module
        .functions
        .iter()
        .any(|(_, f)| !f.arguments.is_empty())
}

/// Whether function `f` has a call statement.
pub(super) fn calls_any(f: &naga::Function) -> bool {
    let mut any = false;
    each_statement(&f.body, &mut |s| {
        any |= matches!(s, naga::Statement::Call { .. });
    });
    any
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
        self.calls.results.push(Val::Bot);
        self.walk_inside(s, c);
        let result = self.calls.results.pop().unwrap_or(Val::Bot);
        self.args[c] = saved_args;
        self.functions[c] = saved_facts;
        self.calls.memo.push((c, args, result.clone()));
        Some(result)
    }

    /// Walks function `c` at a call of the function at `s`, when that is the only call naming
    /// `c` and the round has not walked it yet (its parameters now hold every argument).
    pub(super) fn walk_at_call(&mut self, s: Site, c: usize) {
        let at = &self.at_call;
        if self.calls.precise
            || c >= s.module.functions.len()
            || at.sites[c] != 1
            || at.walked[c]
            || at.nested >= MAX_NESTED
        {
            return;
        }
        self.at_call.nested += 1;
        self.walk_inside(s, c);
        self.at_call.nested -= 1;
    }

    /// Walks function `c` in the middle of the walk of the function at `s`, which then goes on
    /// with what it knew: its variables' current values, its `if` refinements, whether it is
    /// an entry point.
    fn walk_inside(&mut self, s: Site, c: usize) {
        let saved_current = std::mem::take(&mut self.current);
        let saved_refine = std::mem::take(&mut self.refine);
        let saved_entry = self.walking_entry;
        self.run_function(s.module, s.info, c);
        self.walking_entry = saved_entry;
        self.current = saved_current;
        self.refine = saved_refine;
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Analysis, Mode};
    use essl::source::SourceFile;
    use essl::{compile, CompileOptions, Stage};

    /// The rounds the analysis of fragment shader `text` takes to its fixpoint.
    fn rounds(text: &str) -> usize {
        let text =
            format!("#version 300 es\nprecision highp float;\nin float v_x;\nout vec4 o;\n{text}");
        let s = compile(
            SourceFile::new("t.frag", text),
            Stage::Fragment,
            &CompileOptions::default(),
        );
        let lowered = s.naga.as_ref().expect("compiles");
        Analysis::run_for(lowered, Mode::Sound, true).rounds
    }

    #[test]
    fn a_function_called_once_is_walked_at_its_call() {
        let text = "float sq(float x) { return x * x; }\n\
                    float lum(float x) { return sq(x) + 1.0; }\n\
                    void main() { o = vec4(lum(v_x)); }\n";
        assert_eq!(rounds(text), 1);
    }

    #[test]
    fn a_function_called_twice_takes_a_second_round() {
        let text = "float sq(float x) { return x * x; }\n\
                    void main() { o = vec4(sq(v_x) + sq(2.0)); }\n";
        assert_eq!(rounds(text), 2);
    }

    /// `main` calling a chain of `n` functions, each calling the next once.
    fn chain(n: usize) -> String {
        let mut text = String::from("float f0(float x) { return x + 1.0; }\n");
        for i in 1..n {
            text += &format!("float f{i}(float x) {{ return f{}(x) * 0.5; }}\n", i - 1);
        }
        text + &format!("void main() {{ o = vec4(f{}(v_x)); }}\n", n - 1)
    }

    #[test]
    fn a_chain_of_calls_is_walked_in_one_round() {
        assert_eq!(rounds(&chain(40)), 1);
    }

    #[test]
    fn calls_nested_deeper_than_the_bound_wait_for_later_rounds() {
        let r = rounds(&chain(2 * super::MAX_NESTED));
        assert!(r > 1 && r <= super::super::MAX_ROUNDS, "{r} rounds");
    }
}
