//! Whether a vector is a finite-difference gradient of an image: each component a weighted sum
//! of reads of one channel of one texture (directly, or through one sampling function) whose
//! weights sum to 0. A Sobel or central-difference gradient is then the zero vector wherever the
//! image is flat — whole regions of any picture — which `normalize-zero` reports.

use naga::{Expression as E, Function, Handle, Statement};

use super::Cx;
use crate::analysis::each_statement;
use crate::symbolic::{resolve, Sym};
use crate::value::Facts;

/// Where a texel read comes from: the texture (or the function that samples it) and the channel.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Source {
    /// `texture(image, …)` of the global `image`, component `channel`.
    Image(Handle<naga::GlobalVariable>, u32),
    /// A call of `function` (which samples a texture), component `channel` of its result.
    Call(Handle<naga::Function>, u32),
}

/// Whether `h` (a vector) is a gradient of one texture: every component a zero-sum weighted sum
/// of reads of one channel of it, built with `vecN(gx, gy)` or by writing each component of a
/// local (`g.x = …; g.y = …;`).
pub(super) fn texel_gradient(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> bool {
    let r = resolve(f, cx.sound(), id, h);
    let components: Vec<Handle<E>> = match f.expressions[r] {
        E::Compose { ref components, .. } => components.clone(),
        E::Load { pointer } => match f.expressions[pointer] {
            E::LocalVariable(l) => match component_stores(cx, f, id, l) {
                Some(c) => c,
                None => return false,
            },
            _ => return false,
        },
        _ => return false,
    };
    let sym = cx.sym(id, f);
    let mut source = None;
    components.len() >= 2
        && components
            .iter()
            .all(|&c| zero_sum(cx, f, id, &sym, c, &mut source))
}

/// The values written into each component of local `l` (`l.x = a; l.y = b;`), in order, where
/// every component is written exactly once and the whole local only with a constant (its
/// initial `vec2(0.0)`).
fn component_stores(
    cx: &Cx,
    f: &Function,
    id: usize,
    l: Handle<naga::LocalVariable>,
) -> Option<Vec<Handle<E>>> {
    let constant = |v: Handle<E>| {
        cx.sound()
            .num(id, v)
            .is_some_and(|n| n.comps().iter().all(|c| c.as_point().is_some()))
    };
    let mut parts: Vec<Option<Handle<E>>> = Vec::new();
    let mut whole = false;
    let mut twice = false;
    each_statement(&f.body, &mut |st| {
        let Statement::Store { pointer, value } = *st else {
            return;
        };
        match f.expressions[pointer] {
            E::LocalVariable(v) if v == l => whole |= !constant(value),
            E::AccessIndex { base, index } if f.expressions[base] == E::LocalVariable(l) => {
                let i = index as usize;
                if parts.len() <= i {
                    parts.resize(i + 1, None);
                }
                twice |= parts[i].is_some();
                parts[i] = Some(value);
            }
            _ => {}
        }
    });
    let size = match cx.module.types[f.local_variables[l].ty].inner {
        naga::TypeInner::Vector { size, .. } => size as usize,
        _ => return None,
    };
    if whole || twice || parts.len() != size {
        return None;
    }
    parts.into_iter().collect()
}

/// Whether `h` is a weighted sum of two or more reads of one channel of one texture, with
/// constant weights that sum to 0 (its linear form, `Sym::terms`); `source` is the texture
/// every component reads.
fn zero_sum(
    cx: &Cx,
    f: &Function,
    id: usize,
    sym: &Sym,
    h: Handle<E>,
    source: &mut Option<Source>,
) -> bool {
    let (terms, constant) = sym.terms(h);
    if constant != 0.0 || terms.len() < 2 {
        return false;
    }
    for &(leaf, _) in &terms {
        match read(cx, f, id, leaf) {
            Some(s) if source.is_none_or(|t| t == s) => *source = Some(s),
            _ => return false,
        }
    }
    let sum: f64 = terms.iter().map(|(_, k)| k).sum();
    sum.abs() < 1e-9
}

/// The texture and channel a scalar texel read `h` comes from: `texture(t, uv).r`, `.r` of a
/// call whose result is a texel (`sampleClamp2edge(t, uv).r`), or a call that returns one
/// channel (`luma(uv)`).
fn read(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> Option<Source> {
    if !cx
        .sound()
        .num(id, h)
        .is_some_and(|n| n.n == 1 && n.facts.any(Facts::TEXTURE))
    {
        return None;
    }
    let (base, index) = match f.expressions[h] {
        E::AccessIndex { base, index } => (base, index),
        // A function returning one channel (`float luma(vec2 uv)`).
        E::CallResult(fun) => return Some(Source::Call(fun, u32::MAX)),
        _ => return None,
    };
    match f.expressions[resolve(f, cx.sound(), id, base)] {
        E::ImageSample { image, .. } => match f.expressions[image] {
            E::GlobalVariable(g) => Some(Source::Image(g, index)),
            _ => None,
        },
        E::CallResult(fun) => Some(Source::Call(fun, index)),
        _ => None,
    }
}
