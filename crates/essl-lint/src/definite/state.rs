//! The walk's state: for each variable, the bits written on every path so far — one byte a
//! variable, at a slot fixed for the function walked. A branch copies the state and a join
//! meets two of them; both are a few dozen bytes copied or combined, where a map keyed by
//! variable cost an allocation and a hash per entry.

use essl::hir::BuiltinVar;

use super::{Var, BUILTIN_OUTPUTS};

/// Where a function's variables have their slots: its locals, then its parameters, then the
/// module's globals, then the built-in outputs. The function's result has none.
#[derive(Clone, Copy, Debug)]
pub(super) struct Layout {
    params: usize,
    globals: usize,
    builtins: usize,
    len: usize,
}

impl Layout {
    /// The layout for a function with `locals` locals and `params` parameters in a module with
    /// `globals` globals.
    pub(super) fn new(locals: usize, params: usize, globals: usize) -> Layout {
        let builtins = locals + params + globals;
        Layout {
            params: locals,
            globals: locals + params,
            builtins,
            len: builtins + BUILTIN_OUTPUTS.len(),
        }
    }

    /// The number of slots.
    pub(super) fn len(&self) -> usize {
        self.len
    }

    /// The slot of `v` (none for the result, or an index past the function's or module's).
    pub(super) fn slot(&self, v: Var) -> Option<usize> {
        let (base, end, i) = match v {
            Var::Local(i) => (0, self.params, i),
            Var::Param(i) => (self.params, self.globals, i),
            Var::Global(i) => (self.globals, self.builtins, i),
            Var::Builtin(b) => (self.builtins, self.len, builtin_index(b)?),
            Var::Result => return None,
        };
        (base + i < end).then_some(base + i)
    }
}

/// The index of a built-in output in [`BUILTIN_OUTPUTS`].
fn builtin_index(b: BuiltinVar) -> Option<usize> {
    BUILTIN_OUTPUTS.iter().position(|(x, _)| *x == b)
}

/// The bits of each variable written on every path so far, by slot.
#[derive(Clone, Debug, Default)]
pub(super) struct State(Vec<u8>);

impl State {
    /// Nothing written, for `len` slots.
    pub(super) fn new(len: usize) -> State {
        State(vec![0; len])
    }

    /// The bits written at `slot`.
    pub(super) fn get(&self, slot: usize) -> u8 {
        self.0.get(slot).copied().unwrap_or(0)
    }

    /// Sets the bits at `slot`.
    pub(super) fn set(&mut self, slot: usize, bits: u8) {
        if let Some(b) = self.0.get_mut(slot) {
            *b = bits;
        }
    }

    /// Adds `bits` at `slot`.
    pub(super) fn add(&mut self, slot: usize, bits: u8) {
        if let Some(b) = self.0.get_mut(slot) {
            *b |= bits;
        }
    }

    /// Adds everything `other` has written.
    pub(super) fn join(&mut self, other: &State) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a |= b;
        }
    }

    /// The slots with bits written, and their bits.
    pub(super) fn iter(&self) -> impl Iterator<Item = (usize, u8)> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter(|(_, b)| **b != 0)
            .map(|(i, b)| (i, *b))
    }

    /// What is written on both paths.
    pub(super) fn meet(&self, other: &State) -> State {
        State(self.0.iter().zip(&other.0).map(|(a, b)| a & b).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_variable_has_a_slot_of_its_own() {
        let layout = Layout::new(2, 1, 3);
        let vars = [
            Var::Local(0),
            Var::Local(1),
            Var::Param(0),
            Var::Global(0),
            Var::Global(2),
            Var::Builtin(BuiltinVar::FragColor),
            Var::Builtin(BuiltinVar::PointSize),
        ];
        let mut slots: Vec<usize> = vars.iter().filter_map(|v| layout.slot(*v)).collect();
        assert_eq!(slots.len(), vars.len());
        assert!(slots.iter().all(|&s| s < layout.len()));
        slots.sort_unstable();
        slots.dedup();
        assert_eq!(slots.len(), vars.len());
        // Past the function's or the module's variables, and the result: no slot.
        for v in [Var::Local(2), Var::Param(1), Var::Global(3), Var::Result] {
            assert_eq!(layout.slot(v), None, "{v:?}");
        }
    }

    #[test]
    fn a_join_of_paths_keeps_what_both_wrote() {
        let mut a = State::new(3);
        let mut b = State::new(3);
        a.add(0, 0b011);
        a.set(1, 1);
        b.add(0, 0b110);
        b.add(2, 1);
        let m = a.meet(&b);
        assert_eq!((m.get(0), m.get(1), m.get(2)), (0b010, 0, 0));
        a.join(&b);
        assert_eq!(a.iter().collect::<Vec<_>>(), [(0, 0b111), (1, 1), (2, 1)]);
    }
}
