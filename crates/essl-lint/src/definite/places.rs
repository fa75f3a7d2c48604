//! The parts of a variable a place selects and a read needs: a vector's components, a struct's
//! members (up to 8), one bit for anything else; and what a read of them finds written.

use essl::hir::{self, Expr, ExprKind};
use essl::types::Type;

use super::{State, Var, Walk};

/// The mask of all of a variable of type `t`: one bit per vector component or per member of a
/// struct of at most 8, one otherwise.
pub(super) fn full_mask(m: &hir::Module, t: &Type) -> u8 {
    match t {
        Type::Vector(_, n) => (1u8 << n) - 1,
        Type::Struct(id) => match m.structs.get(id.0 as usize).map(|s| s.members.len()) {
            Some(n @ 1..=8) => ((1u16 << n) - 1) as u8,
            _ => 1,
        },
        _ => 1,
    }
}

impl<'a> Walk<'a> {
    /// Whether `st` has the `bits` of `v` written on every path: for a struct, those of its
    /// members some path has written before, or any member where none has been; a variable the
    /// walk does not track always is.
    pub(super) fn written(&self, st: &State, v: Var, bits: u8) -> bool {
        let (Some(i), Some(all)) = (self.layout.slot(v), self.mask(v)) else {
            return true;
        };
        let have = st.get(i);
        if all != 1 && self.is_struct(v) {
            let needed = bits & self.ever[i];
            return if needed == 0 {
                have & bits != 0
            } else {
                have & needed == needed
            };
        }
        have & bits == bits
    }

    /// The names of the members of struct variable `v` among `bits` that some path has written
    /// before and another leaves unwritten (empty for anything else).
    pub(super) fn unwritten_members(&self, st: &State, v: Var, bits: u8) -> Vec<String> {
        let Some(Type::Struct(id)) = self.type_of(v) else {
            return Vec::new();
        };
        let Some(def) = self.m.structs.get(id.0 as usize) else {
            return Vec::new();
        };
        let Some(i) = self.layout.slot(v) else {
            return Vec::new();
        };
        let missing = bits & self.ever[i] & !st.get(i);
        (0..def.members.len().min(8))
            .filter(|&i| missing & (1 << i) != 0)
            .map(|i| def.members[i].name.clone())
            .collect()
    }

    /// Whether `v` is of a struct type (tracked member by member where [`full_mask`] says).
    pub(super) fn is_struct(&self, v: Var) -> bool {
        matches!(self.type_of(v), Some(Type::Struct(_)))
    }

    /// The declared type of `v` (none for a built-in output or the result).
    pub(super) fn type_of(&self, v: Var) -> Option<&'a Type> {
        let m = self.m;
        let f = &m.functions[self.fid];
        match v {
            Var::Local(i) => f.locals.get(i).map(|l| &l.ty),
            Var::Param(i) => f.params.get(i).map(|p| &p.ty),
            Var::Global(g) => m.globals.get(g).map(|g| &g.ty),
            Var::Builtin(_) | Var::Result => None,
        }
    }

    /// The variable an expression names, if it is one the walk knows.
    pub(super) fn var_of(&self, e: &Expr) -> Option<Var> {
        let v = match e.kind {
            ExprKind::Local(i) => Var::Local(i),
            ExprKind::Param(i) => Var::Param(i),
            ExprKind::Global(g) => Var::Global(g),
            ExprKind::BuiltinVar(b) => Var::Builtin(b),
            _ => return None,
        };
        self.mask(v).map(|_| v)
    }

    /// The variable and the bits a place expression (`v`, `v.xz`, `v[1]`, `a[i].m`) selects;
    /// the index expressions inside it are read.
    pub(super) fn place(&mut self, e: &Expr, st: &mut State) -> Option<(Var, u8)> {
        if let Some(v) = self.var_of(e) {
            return Some((v, self.mask(v)?));
        }
        match &e.kind {
            ExprKind::Swizzle(base, comps) => {
                let (v, all) = self.place(base, st)?;
                // Components of a struct's member: the member's bit.
                if all.count_ones() == 1 || self.var_of(base).is_none() {
                    return Some((v, all));
                }
                Some((v, comps.iter().fold(0u8, |m, c| m | (1 << c)) & all))
            }
            ExprKind::Index(base, index) => {
                self.expr(index, st);
                let (v, all) = self.place(base, st)?;
                // An element of a struct's member: the member's bit.
                if self.var_of(base).is_none() {
                    return Some((v, all));
                }
                let bit = match (all, index.as_const().and_then(|c| c.as_int())) {
                    (1, _) => 1,
                    (_, Some(i)) if (0..8).contains(&i) => (1u8 << i) & all,
                    _ => self.counter_bits(index).map_or(all, |b| b & all),
                };
                Some((v, bit))
            }
            ExprKind::Member(base, i) => {
                let (v, all) = self.place(base, st)?;
                // A member of the struct variable itself has its bit; deeper, the bits of the
                // outermost member.
                let bit = if self.var_of(base).is_some() && all != 1 {
                    (1u8 << (*i).min(7)) & all
                } else {
                    all
                };
                Some((v, bit))
            }
            // A variable the walk does not track.
            ExprKind::Local(_)
            | ExprKind::Param(_)
            | ExprKind::Global(_)
            | ExprKind::BuiltinVar(_) => None,
            _ => {
                self.expr(e, st);
                None
            }
        }
    }

    /// The components an index that is an enclosing loop's counter selects, one bit per
    /// value the counter takes there (`None`: not a counter, or a value past a vector's end).
    pub(super) fn counter_bits(&self, index: &Expr) -> Option<u8> {
        let ExprKind::Local(i) = index.kind else {
            return None;
        };
        let &(_, lo, hi) = self.counters.iter().rev().find(|c| c.0 == i)?;
        ((0..8).contains(&lo) && (0..8).contains(&hi))
            .then(|| (lo..=hi).fold(0u8, |m, k| m | (1 << k)))
    }
}
