//! What an `if`'s condition says about the walk: the writes made wherever it is true (the
//! right side of `&&`, a `bool` local set from such a condition), and the uniforms it requires
//! (`if (u_isText && u_isHalo)`), under which earlier writes made under the same uniforms count.

use essl::hir::{self, BinaryOp, Expr, ExprKind, GlobalKind, Stmt};

use super::{meet_opt, Key, State, Walk};

impl Walk<'_> {
    /// What is written wherever `e` is true (`None`: nowhere known), from `st` before `e`:
    /// both sides of `&&`, either of `||`, and what a local's assignment recorded.
    pub(super) fn when_true(&mut self, e: &Expr, st: &State) -> Option<State> {
        match &e.kind {
            ExprKind::Binary(BinaryOp::And, a, b) => {
                let sa = self.when_true(a, st)?;
                self.when_true(b, &sa)
            }
            ExprKind::Binary(BinaryOp::Or, a, b) => {
                let ta = self.when_true(a, st);
                let mut sa = st.clone();
                self.expr(a, &mut sa);
                meet_opt(ta, self.when_true(b, &sa))
            }
            _ => {
                let mut s = st.clone();
                self.expr(e, &mut s);
                if let ExprKind::Local(l) = e.kind {
                    if let Some(t) = self.truth.get(&l) {
                        s.join(t);
                    }
                }
                Some(s)
            }
        }
    }

    /// Whether [`Walk::when_true`] can know more of `e` than the state after it: only for
    /// `&&`, `||` and a local with a recorded truth. Elsewhere it is that state, and the walk
    /// skips it rather than walk `e` twice.
    pub(super) fn says_more(&self, e: &Expr) -> bool {
        match e.kind {
            ExprKind::Binary(BinaryOp::And | BinaryOp::Or, ..) => true,
            ExprKind::Local(l) => self.truth.contains_key(&l),
            _ => false,
        }
    }

    /// The uniforms a condition requires when it is `pol` (through `!` and `&&`); empty when it
    /// tests anything else.
    pub(super) fn keys(&self, c: &Expr, pol: bool) -> Vec<Key> {
        let mut out = Vec::new();
        if self.collect_keys(c, pol, &mut out) {
            out
        } else {
            Vec::new()
        }
    }

    fn collect_keys(&self, c: &Expr, pol: bool, out: &mut Vec<Key>) -> bool {
        match &c.kind {
            ExprKind::Global(g) if self.m.globals[*g].kind == GlobalKind::Uniform => {
                out.push((usize::MAX, *g, pol));
                true
            }
            ExprKind::BlockMember(b, None, m) => {
                out.push((*b, *m, pol));
                true
            }
            ExprKind::Unary(hir::UnaryOp::Not, x) => self.collect_keys(x, !pol, out),
            ExprKind::Binary(BinaryOp::And, a, b) if pol => {
                self.collect_keys(a, true, out) & self.collect_keys(b, true, out)
            }
            // A failing `||` is a conjunction of failures.
            ExprKind::Binary(BinaryOp::Or, a, b) if !pol => {
                self.collect_keys(a, false, out) & self.collect_keys(b, false, out)
            }
            _ => false,
        }
    }

    /// Walks the branch of an `if` taken when the condition requires the uniforms `keys`
    /// (none: it tests something else), from `st` with the writes made earlier under conditions
    /// that the enclosing ones and `keys` include.
    pub(super) fn branch(&mut self, ss: &[Stmt], st: &State, keys: &[Key]) -> Option<State> {
        if keys.is_empty() {
            self.loose += 1;
            let out = self.stmts(ss, st.clone());
            self.loose -= 1;
            return out;
        }
        let depth = self.context.len();
        self.context.extend_from_slice(keys);
        let mut start = st.clone();
        for (need, i, bits) in &self.guarded {
            if need.iter().all(|k| self.context.contains(k)) {
                start.add(*i, *bits);
            }
        }
        let out = self.stmts(ss, start);
        self.context.truncate(depth);
        out
    }
}
