//! Whether two expressions certainly have the same value: the same handle, or the same
//! operation on operands that are the same, or loads of a place that cannot have changed
//! between them (the same `Emit`, a local stored once, an external uniform).

use naga::{Expression as E, Function, Handle};

use super::{Analysis, Root, ANY};
use crate::value::Facts;

impl Analysis {
    /// Whether two pointers into the same variable select the same part: the same constant
    /// indices, and dynamic indices of the same value.
    fn same_pointer(
        &self,
        f: &Function,
        id: usize,
        a: Handle<E>,
        b: Handle<E>,
        depth: u32,
    ) -> bool {
        if a == b {
            return true;
        }
        match (&f.expressions[a], &f.expressions[b]) {
            (
                E::Access {
                    base: b1,
                    index: i1,
                },
                E::Access {
                    base: b2,
                    index: i2,
                },
            ) => {
                self.same_depth(f, id, *i1, *i2, depth + 1)
                    && self.same_pointer(f, id, *b1, *b2, depth)
            }
            (
                E::AccessIndex {
                    base: b1,
                    index: i1,
                },
                E::AccessIndex {
                    base: b2,
                    index: i2,
                },
            ) => i1 == i2 && self.same_pointer(f, id, *b1, *b2, depth),
            (E::LocalVariable(x), E::LocalVariable(y)) => x == y,
            (E::GlobalVariable(x), E::GlobalVariable(y)) => x == y,
            (E::FunctionArgument(x), E::FunctionArgument(y)) => x == y,
            _ => false,
        }
    }

    /// Whether two expressions of a function certainly have the same value.
    pub fn same(&self, f: &Function, id: usize, a: Handle<E>, b: Handle<E>) -> bool {
        self.same_depth(f, id, a, b, 0)
    }

    fn same_depth(&self, f: &Function, id: usize, a: Handle<E>, b: Handle<E>, depth: u32) -> bool {
        if a == b {
            return true;
        }
        if depth > 6 {
            return false;
        }
        let ff = &self.functions[id];
        let s = |x: Handle<E>, y: Handle<E>| self.same_depth(f, id, x, y, depth + 1);
        match (&f.expressions[a], &f.expressions[b]) {
            (E::Load { pointer: pa }, E::Load { pointer: pb }) => {
                let (Some(x), Some(y)) = (&ff.places[pa.index()], &ff.places[pb.index()]) else {
                    return false;
                };
                if x != y || x.path.contains(&ANY) && !self.same_pointer(f, id, *pa, *pb, depth) {
                    return false;
                }
                if let Root::Local(_, l) = x.root {
                    if x.path.is_empty() && ff.single_store.contains_key(&l) {
                        return true;
                    }
                }
                let same_emit = ff.emit[a.index()] != 0 && ff.emit[a.index()] == ff.emit[b.index()];
                if x.path.contains(&ANY) {
                    let version = ff.load_version[a.index()];
                    return same_emit || version != 0 && version == ff.load_version[b.index()];
                }
                let version = ff.load_version[a.index()];
                same_emit
                    || version != 0 && version == ff.load_version[b.index()]
                    || self.functions[id].values[a.index()].facts().has(Facts::EXT)
                        && matches!(x.root, Root::Global(_))
            }
            (
                E::Binary {
                    op: o1,
                    left: l1,
                    right: r1,
                },
                E::Binary {
                    op: o2,
                    left: l2,
                    right: r2,
                },
            ) => o1 == o2 && s(*l1, *l2) && s(*r1, *r2),
            (E::Unary { op: o1, expr: x1 }, E::Unary { op: o2, expr: x2 }) => {
                o1 == o2 && s(*x1, *x2)
            }
            (
                E::Math {
                    fun: f1,
                    arg: a1,
                    arg1: b1,
                    arg2: c1,
                    ..
                },
                E::Math {
                    fun: f2,
                    arg: a2,
                    arg1: b2,
                    arg2: c2,
                    ..
                },
            ) => {
                let opt = |x: &Option<Handle<E>>, y: &Option<Handle<E>>| match (x, y) {
                    (None, None) => true,
                    (Some(x), Some(y)) => s(*x, *y),
                    _ => false,
                };
                f1 == f2 && s(*a1, *a2) && opt(b1, b2) && opt(c1, c2)
            }
            (
                E::AccessIndex {
                    base: b1,
                    index: i1,
                },
                E::AccessIndex {
                    base: b2,
                    index: i2,
                },
            ) => i1 == i2 && s(*b1, *b2),
            (
                E::Swizzle {
                    size: z1,
                    vector: v1,
                    pattern: p1,
                },
                E::Swizzle {
                    size: z2,
                    vector: v2,
                    pattern: p2,
                },
            ) => z1 == z2 && p1 == p2 && s(*v1, *v2),
            (
                E::Splat {
                    size: z1,
                    value: v1,
                },
                E::Splat {
                    size: z2,
                    value: v2,
                },
            ) => z1 == z2 && s(*v1, *v2),
            (
                E::As {
                    expr: x1,
                    kind: k1,
                    convert: c1,
                },
                E::As {
                    expr: x2,
                    kind: k2,
                    convert: c2,
                },
            ) => k1 == k2 && c1 == c2 && s(*x1, *x2),
            (E::Literal(x), E::Literal(y)) => x == y,
            (E::Constant(x), E::Constant(y)) => x == y,
            (E::FunctionArgument(x), E::FunctionArgument(y)) => x == y,
            _ => false,
        }
    }
}
