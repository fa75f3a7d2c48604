//! `texel-fetch-range`: `texelFetch` coordinates or level that can leave the texture.

use essl::diagnostic::Diagnostic;
use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::guards::Guards;
use super::rule::declare_rule;
use super::{fmt_num, Cx};
use crate::symbolic::resolve;
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `texelFetch` and `texelFetchOffset` whose texel coordinates or level can leave the
    /// texture:
    ///
    /// - a coordinate the shader's own arithmetic can make negative — a neighbour of the current
    ///   texel, `ivec2(gl_FragCoord.xy) - ivec2(1, 0)`, is −1 on the first column;
    /// - a coordinate one or more texels past another without a clamp to the size —
    ///   `texel + ivec2(1, 0)` is past the last column when `texel` is on it;
    /// - a level that can be negative;
    /// - coordinates scaled by the size of one level (`ivec2(v_uv * vec2(textureSize(t, 0)))`)
    ///   read at a level that can be above it (`texelFetch(t, c, int(u_lod))`): past the smaller
    ///   level's size for most pixels (a mip viewer, a texture inspector).
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `texelFetch` undefined outside the level's size (§8.9); WebGL 2.0 defines
    /// it to return 0 (§5.31 "Texel Fetches"), so a blur, an edge detector or a convolution that
    /// reads its neighbours with `texelFetch` darkens (or makes transparent) the border of the image
    /// on every browser, and reads whatever memory is there on a native driver.
    ///
    /// ## Example
    /// ```glsl
    /// ivec2 p = ivec2(gl_FragCoord.xy);
    /// vec4 left = texelFetch(u_image, p - ivec2(1, 0), 0);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// ivec2 p = ivec2(gl_FragCoord.xy);
    /// ivec2 last = textureSize(u_image, 0) - 1;
    /// vec4 left = texelFetch(u_image, clamp(p - ivec2(1, 0), ivec2(0), last), 0);
    /// ```
    /// There is no mechanical fix: whether the border repeats, mirrors or reads zero is a choice.
    ///
    /// ## What it does not flag
    /// - Coordinates the shader keeps in range: `clamp(p, ivec2(0), textureSize(t, 0) - 1)`, `max(p,
    ///   0)`, `min(p + 1, size - 1)`, or a guard (`if (p.x > 0)`).
    /// - `2 * p + k` with every component of `k` below 2 (`texelFetch(src, 2 * p + ivec2(1, 0), 0)`):
    ///   a texel of a level twice the size of the one `p` indexes, as a mip reduction reads its
    ///   2×2 block.
    /// - A coordinate from an input or a uniform as such (`ivec2(gl_FragCoord.xy)`, `ivec2(v_uv *
    ///   size)`): whether it fits the texture is the host's choice of sizes.
    /// - Coordinates scaled by one level's size and brought to the level read by a shift or a
    ///   division (`ivec2(v_uv * vec2(textureSize(t, 0))) >> lod`), or by the size of the level
    ///   read itself (`textureSize(t, lod)`).
    /// - `texture` and `textureLod` on integer samplers: the wrap modes define every coordinate
    ///   there.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.9 Texture Lookup Functions (texelFetch: "undefined" outside
    ///   the level's size).
    /// - WebGL 2.0 specification, §5.31 Texel Fetches ("must return zero").
    pub(crate) struct TexelFetchRange {
        id: "texel-fetch-range",
        summary: "`texelFetch` coordinates or level that the shader's arithmetic can take outside the texture",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::ImageLoad {
                coordinate, level, ..
            } = *e
            else {
                continue;
            };
            let span = cx.span(f, h);
            if span.is_empty() || !cx.text(span).starts_with("texelFetch") {
                continue;
            }
            let g = cx.guards(f, id, h);
            let negative = |x: Handle<E>| {
                cx.refined(f, id, x, &g).and_then(|n| {
                    let lo = n.hull().lo;
                    (lo < 0.0 && !n.facts.has(Facts::NN)).then_some(lo)
                })
            };
            let coord_negative =
                negative(coordinate).filter(|_| !guarded(cx, f, id, coordinate, &g, Side::Low));
            let (what, at, lo) = if let Some(lo) = coord_negative {
                ("coordinate", coordinate, Some(lo))
            } else if let Some(lo) = level.and_then(negative) {
                ("level", level.unwrap_or(coordinate), Some(lo))
            } else if past_a_texel(cx, f, id, coordinate)
                && !guarded(cx, f, id, coordinate, &g, Side::High)
            {
                ("coordinate", coordinate, None)
            } else {
                if let Some(d) = level_mismatch(cx, f, id, h) {
                    out.push(d);
                }
                continue;
            };
            let label = match lo {
                Some(lo) if lo > -1e6 => {
                    format!("this {what} can be as low as {}", fmt_num(lo))
                }
                Some(_) => format!("this {what} can be negative"),
                None => {
                    "past the last texel where the texel it offsets is on the last row or column"
                        .to_string()
                }
            };
            let mut d = Diagnostic::rule_warning(
                TexelFetchRange::RULE.id,
                format!("`texelFetch` {what} can leave the texture, where `texelFetch` is undefined (WebGL returns 0)"),
                span,
            )
            .with_label(label)
            .with_note("GLSL ES 3.00 §8.9: texelFetch is undefined outside the level; WebGL 2.0 §5.31 returns 0")
            .with_help("clamp the coordinates to `[0, textureSize(sampler, lod) - 1]`");
            let s = cx.span(f, at);
            if !s.is_empty() && s != span {
                d = d.with_secondary(s, what);
            }
            out.push(cx.grade(d, &[(id, at)]));
        }
    }
}

/// Which end of the texture a guard keeps a coordinate from.
#[derive(Clone, Copy, PartialEq)]
enum Side {
    /// Below 0.
    Low,
    /// Past the last texel.
    High,
}

/// Whether the guards keep coordinate `c` (`p ± k`, or `p` itself) in range on `side`: in every
/// component that moves that way, a comparison of that component of `p` (`if (p.x > 0)`,
/// `p.y < size.y - 1`) or of the whole coordinate (`all(greaterThanEqual(c, ivec2(0)))`,
/// `all(lessThan(c, size))`).
fn guarded(cx: &Cx, f: &Function, id: usize, c: Handle<E>, g: &Guards, side: Side) -> bool {
    let same = |a: Handle<E>, b: Handle<E>| cx.sound().same(f, id, a, b);
    let bounds = |x: Handle<E>| {
        g.relations.iter().any(|&(op, l, r)| {
            let (low, high) = (
                matches!(op, Bo::Greater | Bo::GreaterEqual),
                matches!(op, Bo::Less | Bo::LessEqual),
            );
            (same(l, x) && (side == Side::Low && low || side == Side::High && high))
                || (same(r, x) && (side == Side::Low && high || side == Side::High && low))
        })
    };
    if bounds(c) {
        return true;
    }
    let r = resolve(f, cx.sound(), id, c);
    let (base, k, sign) = match f.expressions[r] {
        E::Binary {
            op: Bo::Add,
            left,
            right,
        } => (left, right, 1.0),
        E::Binary {
            op: Bo::Subtract,
            left,
            right,
        } => (left, right, -1.0),
        _ => return false,
    };
    let Some(offset) = cx.sound().num(id, k) else {
        return false;
    };
    let moved: Vec<usize> = (0..offset.n as usize)
        .filter(|&i| {
            let o = offset.c[i].lo * sign;
            side == Side::Low && o < 0.0 || side == Side::High && o > 0.0
        })
        .collect();
    !moved.is_empty()
        && moved.iter().all(|&i| {
            g.relations.iter().any(|&(op, l, rr)| {
                let part = |x: Handle<E>| {
                    matches!(f.expressions[x], E::AccessIndex { base: b, index } if index as usize == i && same(b, base))
                };
                let (low, high) = (
                    matches!(op, Bo::Greater | Bo::GreaterEqual),
                    matches!(op, Bo::Less | Bo::LessEqual),
                );
                (part(l) && (side == Side::Low && low || side == Side::High && high))
                    || (part(rr) && (side == Side::Low && high || side == Side::High && low))
            })
        })
}

/// Whether `c` is `p + k` with a constant `k` positive in some component and nothing bounding
/// the sum above (no `min` or `clamp` around it).
fn past_a_texel(cx: &Cx, f: &Function, id: usize, c: Handle<E>) -> bool {
    let r = resolve(f, cx.sound(), id, c);
    let E::Binary {
        op: Bo::Add,
        left,
        right,
    } = f.expressions[r]
    else {
        return false;
    };
    let positive = |x: Handle<E>| {
        cx.sound().num(id, x).is_some_and(|n| {
            n.comps().iter().all(|c| c.as_point().is_some()) && n.comps().iter().any(|c| c.lo > 0.0)
        })
    };
    let bounded = |x: Handle<E>| {
        matches!(
            f.expressions[resolve(f, cx.sound(), id, x)],
            E::Math {
                fun: Mf::Min | Mf::Clamp,
                ..
            }
        )
    };
    // `2 * p + k` with k below 2: a texel of a level twice the size of the one `p` indexes
    // (a mip reduction reading its 2×2 block).
    let scaled = |base: Handle<E>, k: Handle<E>| {
        let E::Binary {
            op: Bo::Multiply,
            left: a,
            right: b,
        } = f.expressions[resolve(f, cx.sound(), id, base)]
        else {
            return false;
        };
        let factor = [a, b].into_iter().find_map(|x| {
            let n = cx.sound().num(id, x)?;
            n.comps()
                .iter()
                .map(|c| c.as_point())
                .collect::<Option<Vec<f64>>>()
        });
        let offset = cx.sound().num(id, k).map(|n| n.hull().hi);
        matches!((factor, offset), (Some(fs), Some(o)) if fs.iter().all(|f| *f > o))
    };
    (positive(right) && !bounded(left) && !scaled(left, right))
        || (positive(left) && !bounded(right) && !scaled(right, left))
}

/// The finding for `texelFetch(t, c, level)` (`h`) whose coordinates `c` scale with the size of
/// another level of `t` (`ivec2(v_uv * vec2(textureSize(t, 0)))` read at a level that can be
/// above 0): past that level's size for most pixels. Coordinates divided or shifted by anything
/// but a constant are left alone (`>> lod` scales them down to the level).
fn level_mismatch(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> Option<Diagnostic> {
    let E::ImageLoad {
        image,
        coordinate,
        level: Some(level),
        ..
    } = f.expressions[h]
    else {
        return None;
    };
    let an = cx.sound();
    let (query, sized) = size_query(cx, f, id, coordinate, image, 0)?;
    let at = an.num(id, sized)?.hull().as_point()?;
    let lv = an.num(id, level)?.hull();
    if an.same(f, id, level, sized) || lv.hi <= at {
        return None;
    }
    let span = cx.span(f, h);
    let d = Diagnostic::rule_warning(
        TexelFetchRange::RULE.id,
        "`texelFetch` coordinates scaled by one level's size, read at another level, where `texelFetch` is undefined (WebGL returns 0)",
        span,
    )
    .with_label(format!(
        "read at this level, which can be above {}: a smaller level, whose size the coordinates pass",
        fmt_num(at)
    ))
    .with_secondary(cx.span(f, query), format!("the size of level {}", fmt_num(at)))
    .with_note("GLSL ES 3.00 §8.9: texelFetch is undefined outside the level; WebGL 2.0 §5.31 returns 0")
    .with_help("scale the coordinates by the size of the level read: `textureSize(sampler, lod)`");
    // A warning even where a uniform alone sets the level: choosing a level above the one the
    // coordinates were scaled for is what the parameter is for.
    Some(d)
}

/// A `textureSize(image, level)` query the coordinate `c` scales with, and its level: followed
/// through arithmetic other than a division or shift by a non-constant.
fn size_query(
    cx: &Cx,
    f: &Function,
    id: usize,
    c: Handle<E>,
    image: Handle<E>,
    depth: u32,
) -> Option<(Handle<E>, Handle<E>)> {
    if depth > 12 {
        return None;
    }
    let c = resolve(f, cx.sound(), id, c);
    match f.expressions[c] {
        E::ImageQuery {
            image: qi,
            query: naga::ImageQuery::Size { level: Some(ql) },
        } if same_image(f, qi, image) => Some((c, ql)),
        E::Binary {
            op: Bo::Divide | Bo::ShiftRight,
            left,
            right,
        } => {
            let constant = cx
                .sound()
                .num(id, right)
                .is_some_and(|n| n.comps().iter().all(|x| x.as_point().is_some()));
            if constant {
                size_query(cx, f, id, left, image, depth + 1)
            } else {
                None
            }
        }
        ref e => super::context::operands(e)
            .into_iter()
            .find_map(|o| size_query(cx, f, id, o, image, depth + 1)),
    }
}

/// Whether two image expressions name the same global texture.
fn same_image(f: &Function, a: Handle<E>, b: Handle<E>) -> bool {
    a == b
        || matches!(
            (&f.expressions[a], &f.expressions[b]),
            (E::GlobalVariable(x), E::GlobalVariable(y)) if x == y
        )
}
