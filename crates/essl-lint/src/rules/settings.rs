//! Values that are 0 whenever the settings they are made of are: a setting uniform as such
//! ([`is_setting`]: a count, a length, a radius, a fade), a multiple or quotient of one, and a
//! blend of several — `mix(fadeA, fadeB, t)`, `(w.y - w.x) * k + w.x`, `a * (1.0 - t) + b *
//! t` — which is 0 for every pixel or vertex once each setting in it is. A user who sets a
//! fade or a wavelength to 0 reaches that; the division by it is then undefined for the whole
//! draw, whatever the weights.

use naga::{BinaryOperator as Bo, Expression as E, MathFunction as Mf};

use super::Cx;
use crate::analysis::names::is_setting;

/// The settings an expression vanishes with, by name (each once, in the order met), and whether
/// the expression is the one setting itself.
pub(super) struct Settings {
    /// The settings' names.
    pub names: Vec<String>,
    /// Whether the expression is the setting as such.
    pub itself: bool,
}

/// How deep [`settings_of`] follows operands, locals and arguments.
const MAX_DEPTH: u32 = 8;

/// How many expressions one [`settings_of`] visits at most: stores, callers and both sides of
/// sums branch, and the depth alone would bound the walk only exponentially.
const MAX_STEPS: u32 = 256;

/// The settings expression `h` of function `id` is 0 with: a setting itself, a multiple or
/// quotient of one, or a sum, difference or `mix` whose parts each vanish with settings —
/// through locals, conversions and the arguments of calls.
pub(super) fn settings_of(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    h: naga::Handle<E>,
) -> Option<Settings> {
    let mut names = Vec::new();
    let steps = std::cell::Cell::new(MAX_STEPS);
    walk(cx, f, id, h, 0, &mut names, &steps)?;
    Some(Settings {
        itself: names.len() == 1 && is_uniform(cx, id, h),
        names,
    })
}

/// Whether `h` is a per-draw external value (a uniform as such).
fn is_uniform(cx: &Cx, id: usize, h: naga::Handle<E>) -> bool {
    cx.sound()
        .num(id, h)
        .is_some_and(|n| n.facts.has(crate::value::Facts::EXT) && n.facts.per_draw())
}

/// Adds the settings `h` vanishes with to `names`; `None` where it does not vanish with
/// settings alone.
fn walk(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    h: naga::Handle<E>,
    depth: u32,
    names: &mut Vec<String>,
    steps: &std::cell::Cell<u32>,
) -> Option<()> {
    if depth > MAX_DEPTH || steps.get() == 0 {
        return None;
    }
    steps.set(steps.get() - 1);
    let n = cx.sound().num(id, h)?;
    if !n.comps().iter().any(|c| c.contains(0.0)) {
        return None;
    }
    if is_uniform(cx, id, h) {
        let name = cx.origin(&[(id, h)]).single_uniform()?.to_string();
        if !is_setting(&name) {
            return None;
        }
        if !names.contains(&name) {
            names.push(name);
        }
        return Some(());
    }
    let go =
        |x: naga::Handle<E>, names: &mut Vec<String>| walk(cx, f, id, x, depth + 1, names, steps);
    match f.expressions[h] {
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => {
            // Either factor: try the left one on a copy, so that a miss adds no name.
            let mut mine = names.clone();
            if go(left, &mut mine).is_some() {
                *names = mine;
                Some(())
            } else {
                go(right, names)
            }
        }
        E::Binary {
            op: Bo::Divide,
            left,
            ..
        } => go(left, names),
        E::Binary {
            op: Bo::Add | Bo::Subtract,
            left,
            right,
        } => {
            go(left, names)?;
            go(right, names)
        }
        E::Math {
            fun: Mf::Mix,
            arg,
            arg1: Some(b),
            ..
        } => {
            go(arg, names)?;
            go(b, names)
        }
        E::Splat { value: x, .. }
        | E::Swizzle { vector: x, .. }
        | E::AccessIndex { base: x, .. }
        | E::As { expr: x, .. } => go(x, names),
        E::Load { pointer } => {
            // What calls write through it replaces a start value (`float x;` starts at 0).
            let by_calls = written_by_calls(cx, f, id, pointer);
            let start = |x: &naga::Handle<E>| {
                matches!(
                    f.expressions[*x],
                    E::Literal(_) | E::ZeroValue(_) | E::Constant(_)
                )
            };
            let keep_start = by_calls.is_empty();
            let stored = cx.stored(f, id, pointer).into_iter();
            let own = stored
                .filter(|x| keep_start || !start(x))
                .map(|x| (id, f, x));
            own.chain(by_calls).find_map(|(at, g, x)| {
                let mut mine = names.clone();
                walk(cx, g, at, x, depth + 1, &mut mine, steps)?;
                *names = mine;
                Some(())
            })
        }
        E::FunctionArgument(i) if id < cx.module.functions.len() => {
            cx.flows().callers(id).iter().find_map(|(caller, args)| {
                let g = crate::analysis::function(cx.module, *caller);
                let mut mine = names.clone();
                walk(
                    cx,
                    g,
                    *caller,
                    *args.get(i as usize)?,
                    depth + 1,
                    &mut mine,
                    steps,
                )?;
                *names = mine;
                Some(())
            })
        }
        _ => None,
    }
}

/// The values the functions that function `id` (`f`) calls with the local `pointer` as an
/// argument store through it (an `out` parameter: Babylon's generated blocks return their
/// results so), each with its function's id and the function.
fn written_by_calls<'a>(
    cx: &Cx<'a>,
    f: &naga::Function,
    id: usize,
    pointer: naga::Handle<E>,
) -> Vec<(usize, &'a naga::Function, naga::Handle<E>)> {
    let E::LocalVariable(local) = f.expressions[pointer] else {
        return Vec::new();
    };
    cx.flows()
        .written_through(id, local.index())
        .filter(|&(c, _)| c < cx.module.functions.len())
        .map(|(c, v)| (c, crate::analysis::function(cx.module, c), v))
        .collect()
}

/// The uniform `d`, as the one setting of [`Settings`], where the division `h` (`x / d`) snaps
/// to a grid of step `d`: `floor(x / d) * d` (or `ceil`, `round`, `trunc`; a pixelation's cell
/// size, a posterisation's step). Whatever its name, such a step is a setting a user may set to 0 — pixi's pixelate
/// size, Phaser's blocky size — and the quotient is then ±∞ or NaN for the whole draw.
pub(super) fn grid_step(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    h: naga::Handle<E>,
    d: naga::Handle<E>,
) -> Option<Settings> {
    if !is_uniform(cx, id, d) {
        return None;
    }
    let name = cx.origin(&[(id, d)]).single_uniform()?.to_string();
    // Written so: `mod(x, d)`, which is `x - d * floor(x / d)` in the module, has its
    // operations at the span of the call, and is not a grid's step.
    let snapped = f.expressions.iter().find_map(|(r, e)| match *e {
        E::Math {
            fun: Mf::Floor | Mf::Ceil | Mf::Round | Mf::Trunc,
            arg,
            ..
        } if arg == h => Some(r),
        _ => None,
    })?;
    if cx.span(f, snapped) == cx.span(f, h) {
        return None;
    }
    let same = |x: naga::Handle<E>| cx.sound().same(f, id, x, d);
    f.expressions
        .iter()
        .any(|(_, e)| {
            matches!(*e, E::Binary { op: Bo::Multiply, left, right }
            if (left == snapped && same(right)) || (right == snapped && same(left)))
        })
        .then(|| Settings {
            names: vec![name],
            itself: true,
        })
}
