//! `mediump-overflow`: `mediump`/`lowp` arithmetic that overflows 16-bit floats for ordinary
//! values, and divisors that underflow to zero there.

use rustc_hash::FxHashMap as HashMap;

use essl::diagnostic::Diagnostic;
use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf, ScalarKind,
};

use super::rule::declare_rule;
use super::{fmt_num, operands, users, Cx, User};
use crate::analysis::{literal, SCENE, TIME, TYPICAL};
use crate::interval::Interval;
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports operations computed in `mediump` or `lowp` that amplify a value past 65504 — the
    /// largest 16-bit float — for ordinary, modest values of the shader's inputs: the square or power
    /// of one value (`x * x`, `pow(x, 150.0)`, the sum of squares inside `length` and `normalize`), an
    /// exponential (`exp(x)` beyond 11), a scaling by a constant, a division by a small value.
    /// "Ordinary" means uniforms and inputs of magnitude up to 10 with the signs the formulas expect
    /// (distances, densities, exponents positive), matrix entries and texels up to 1, and window
    /// coordinates (`gl_FragCoord.xy`) up to 2048 pixels, which are pixels whatever the scene
    /// (`dot(c, c)` of `c = gl_FragCoord.xy` overflows 256 pixels from the corner); the analysis
    /// follows the shader's own arithmetic from there.
    ///
    /// A varying, uniform or parameter whose name says it holds a position in the scene
    /// (`vViewPosition`, `FragPos`, `u_lightPosition`, `uPointLightLocation` — not one in texture,
    /// screen or clip space: `vUvPos`, `screenPosition`) is taken up to 1000 units from the origin:
    /// a scene measured in pixels (p5, MapLibre) or metres. `normalize(viewPos - FragPos)` then
    /// squares a length past 256, and 65504 with it. A `float` uniform whose name says it holds the
    /// animation's time (`iTime`, `u_time`; not `deltaTime` or `timeScale`) is taken up to 3600
    /// seconds: `iTime * 30.0` passes 65504 once a page has been open an hour. Whether a scene is
    /// that large, or a page open that long, is the program's to know, so what only such values
    /// reach is a note; what modest ones reach too stays a warning.
    ///
    /// A factor the shader alone bounds (a loop's counter, `float(j)` for `j < 20`) counts as a
    /// constant. What overflows only for larger parameters, or through a product of *different*
    /// parameters, depends on values the runtime check sees. An overflow whose only use
    /// saturates it (`clamp(x / eps, 0.0, 1.0)`, `min(x, 1.0)`, a comparison) is not reported.
    ///
    /// It also reports a `mediump`/`lowp` divisor (or argument of `inversesqrt`/`log`) that the shader
    /// keeps away from zero with a guard below 6.1e-5 (`max(d, 1e-6)`): in 16 bits the guard itself
    /// flushes to zero.
    ///
    /// And, as a note, a variable declared `lowp` whose name says it holds a length in pixels or
    /// world units — a width, a blur, an offset, a height, an atlas rectangle (MapLibre's
    /// `in lowp vec4 a_pattern_from`, `lowp float floorwidth`): `lowp` need only hold (−2, 2).
    /// Not a `lowp` colour or opacity, a mix factor named for a length (`u_width_t`), nor what a
    /// `precision lowp float;` default alone makes `lowp`.
    ///
    /// ## Why is this bad?
    /// Desktop GPUs run `mediump` at 32 bits, so the shader looks fine where it is written; phones run
    /// it at 16 bits, where anything above 65504 is infinity, and `inf - inf`, `0 * inf` and `inf / inf`
    /// are NaN. GLSL ES 3.00 guarantees `mediump` only a range of 2^14 (§4.5.2).
    ///
    /// ## Example
    /// ```glsl
    /// precision mediump float;
    /// uniform float u_distance;
    /// …
    /// float falloff = exp(u_distance * 2.0);   // e^20 = 4.9e8 for u_distance = 10
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// uniform highp float u_distance;
    /// …
    /// highp float falloff = exp(u_distance * 2.0);
    /// ```
    /// Declare the operands `highp`, and the variable that keeps the result: an operation takes the
    /// precision of its operands (GLSL ES 3.00 §4.5.2), so a `highp` variable alone still gets a
    /// `mediump` result. Or rescale the computation (work in kilometres, divide before
    /// multiplying). There is no mechanical fix.
    ///
    /// ## What it does not flag
    /// - Operations in `highp`, and products of different parameters (their scale is the parameters',
    ///   which the runtime check sees).
    /// - An overflow every use of which saturates it (`clamp(x / eps, 0.0, 1.0)`, `min(x, 1.0)`, a
    ///   comparison, `step`, `smoothstep`).
    /// - Powers and exponentials of values the shader keeps at most 1 (`pow(clamp(x, 0.0, 1.0), 1.7)`,
    ///   `pow(max(dot(n, h), 0.0), 32.0)` of unit vectors).
    ///
    /// The values it computes with are ordinary ones (magnitude 10): its findings are warnings;
    /// one that only positions hundreds of units from the origin or an hour's time reach is a
    /// note, and so is
    /// a `lowp` length (GPUs that run `lowp` as 16-bit floats hold it; those that
    /// implement the minimum clamp it).
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §4.5.2 Precision Qualifiers (minimum ranges and precisions).
    /// - IEEE 754 binary16: largest finite value 65504, smallest normal 2^-14.
    pub(crate) struct MediumpOverflow {
        id: "mediump-overflow",
        summary: "`mediump`/`lowp` arithmetic that overflows 65504 for ordinary values, a divisor that underflows to 0, or a length declared `lowp`",
        default_level: Level::Warn,
        check: check,
    }
}

/// The largest finite 16-bit float, what `mediump` and `lowp` hold on GPUs that use them.
pub const LIMIT: f64 = 65504.0;

/// The smallest normal 16-bit float (2^-14); smaller values may flush to zero.
pub const MIN_NORMAL: f64 = 6.103515625e-5;

/// Whether the rule looks at an expression of this kind: a product or quotient, a function
/// that can amplify its argument, or one whose argument can underflow to 0 (`inversesqrt`,
/// `log`, `log2`). [`super::candidates`] runs the rule only where one is computed in low
/// precision.
pub(super) fn looks_at(e: &E) -> bool {
    match *e {
        E::Binary { op, .. } => matches!(op, Bo::Multiply | Bo::Divide),
        E::Math { fun, .. } => {
            amplifies(fun) || matches!(fun, Mf::InverseSqrt | Mf::Log | Mf::Log2)
        }
        _ => false,
    }
}

/// The built-in functions that can amplify their argument past 65504: powers, exponentials,
/// the sums of squares inside dot products, lengths and distances.
fn amplifies(fun: Mf) -> bool {
    matches!(
        fun,
        Mf::Pow
            | Mf::Exp
            | Mf::Exp2
            | Mf::Dot
            | Mf::Length
            | Mf::Distance
            | Mf::Normalize
            | Mf::Cosh
            | Mf::Sinh
            | Mf::Fma
            | Mf::Ldexp
    )
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    super::lowp_range::check(cx, MediumpOverflow::RULE.id, out);
    let literal_args = std::cell::OnceCell::new();
    for (id, f) in cx.functions() {
        let uses = Uses {
            cx,
            f,
            id,
            users: std::cell::OnceCell::new(),
        };
        for (h, e) in f.expressions.iter() {
            let span = cx.span(f, h);
            if span.is_empty() || cx.kind(id, h) != Some(ScalarKind::Float) {
                continue;
            }
            underflow(cx, f, id, h, e, out);
            if !cx.prec.is_low(span) {
                continue;
            }
            // Every kind matched here, and in `guarded_operand`, is one `looks_at` accepts.
            let ops: Vec<Handle<E>> = match *e {
                E::Binary {
                    op: Bo::Multiply | Bo::Divide,
                    left,
                    right,
                } => vec![left, right],
                E::Math { fun, .. } if amplifies(fun) => operands(e),
                _ => continue,
            };
            // Before the sound analysis, when the source alone shows a product that shrinks.
            if matches!(
                e,
                E::Binary {
                    op: Bo::Multiply,
                    ..
                }
            ) && ops.iter().any(|o| {
                literal_within_one(cx, f, id, *o, || {
                    literal_args.get_or_init(|| literal_arguments(cx.module))
                })
            }) {
                continue;
            }
            // Before the ordinary-values analysis, which only this asks for.
            if !could_amplify(cx, f, id, e) || bounded_cheaply(cx, id, e, &ops) {
                continue;
            }
            let typ: Vec<Interval> = ops
                .iter()
                .filter_map(|o| cx.typical().num(id, *o).map(|n| n.hull()))
                .collect();
            if typ.len() != ops.len() {
                continue;
            }
            let Some((r, values)) = overflow(cx, f, id, e, &ops, &typ) else {
                continue;
            };
            if guarded_operand(cx, f, h, e).is_some_and(|x| underflows(cx, id, f, x).is_some()) {
                continue; // the underflowing divisor is the finding
            }
            let (up, down) = (r.hi > LIMIT, r.lo < -LIMIT);
            if uses.saturated(h, up, down, 0) {
                continue;
            }
            let p = cx.prec.at(span).map(|p| p.name()).unwrap_or("mediump");
            let peak = fmt_num(if up { r.hi } else { r.lo });
            // Ordinary values reach it: the rule computes with them (no note for one uniform).
            // A scene's scale is the program's: positions of hundreds of units are ordinary in
            // one measured in pixels and never reached in one of a few metres (a note).
            let d = if values.program() {
                Diagnostic::rule_note(MediumpOverflow::RULE.id, values.message(p), span)
            } else {
                Diagnostic::rule_warning(MediumpOverflow::RULE.id, values.message(p), span)
            };
            let d = d
                .with_label(format!("computed in `{p}`: reaches {peak} with {}", values.text()))
                .with_note("mediump and lowp are 16-bit floats on many mobile GPUs: the largest finite value is 65504")
                .with_help("compute it in `highp`, or rescale the operands");
            out.push(d);
        }
    }
}

/// The ordinary values an overflow is found with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Values {
    /// Inputs of magnitude [`TYPICAL`].
    Modest,
    /// Window coordinates (`gl_FragCoord`), up to [`crate::analysis::WINDOW`] pixels.
    Window,
    /// Positions a name says are in a scene, up to [`SCENE`] units from the origin.
    Scene,
    /// A time a name says is the animation's, up to [`TIME`] seconds.
    Time,
}

impl Values {
    /// The values, for the finding's label.
    fn text(self) -> String {
        match self {
            Values::Modest => format!("inputs of magnitude {}", fmt_num(TYPICAL)),
            Values::Window => format!(
                "window coordinates up to {} pixels",
                fmt_num(crate::analysis::WINDOW)
            ),
            Values::Scene => format!(
                "positions up to {} units from the origin (a scene in pixels or metres)",
                fmt_num(SCENE)
            ),
            Values::Time => format!(
                "a time of up to {} seconds (an animation an hour old)",
                fmt_num(TIME)
            ),
        }
    }

    /// The finding's message, for a result in precision `p`.
    fn message(self, p: &str) -> String {
        match self {
            Values::Scene => {
                format!("`{p}` result can overflow 65504 in a scene hundreds of units across")
            }
            Values::Time => {
                format!("`{p}` result can overflow 65504 once the animation has run an hour")
            }
            _ => format!("`{p}` result can overflow 65504 for ordinary values"),
        }
    }

    /// Whether the values are the program's to know (a note): a scene's scale, how long a page
    /// stays open.
    fn program(self) -> bool {
        matches!(self, Values::Scene | Values::Time)
    }
}

/// The ordinary magnitude of an external value with `facts` (a generous bound): window
/// coordinates are pixels (`gl_FragCoord.xy`, [`crate::analysis::WINDOW`]), a time named as
/// such is up to an hour ([`TIME`]), a position named as such is in a scene's units
/// ([`SCENE`]), other inputs are modest ([`TYPICAL`]).
fn magnitude(facts: Facts) -> f64 {
    let named = match named(facts) {
        Some(Values::Time) => TIME,
        Some(_) => SCENE,
        None => TYPICAL,
    };
    if facts.any(Facts::WINDOW) {
        named.max(crate::analysis::WINDOW)
    } else {
        named
    }
}

/// The values a name gives a magnitude that `facts` depend on: a time before a position.
fn named(facts: Facts) -> Option<Values> {
    if facts.any(Facts::TIME) {
        Some(Values::Time)
    } else if facts.any(Facts::SCENE) {
        Some(Values::Scene)
    } else {
        None
    }
}

/// The values an overflow of `ops` that modest values reach is found with: window
/// coordinates where an operand reads `gl_FragCoord`, modest inputs otherwise.
fn unnamed(cx: &Cx, id: usize, ops: &[Handle<E>]) -> Values {
    let window = ops.iter().any(|o| {
        cx.sound()
            .num(id, *o)
            .is_some_and(|n| n.facts.any(Facts::WINDOW))
    });
    if window {
        Values::Window
    } else {
        Values::Modest
    }
}

/// Whether `r` passes 65504 either way.
fn past(r: Interval) -> bool {
    r.hi > LIMIT || r.lo < -LIMIT
}

/// What `e` reaches past 65504 for ordinary values of its operands (`typ`: their ordinary
/// ranges), and with which values. An operand past 65504 already is its own finding — unless
/// only an hour's time or a scene's scale takes it there, and `e` overflows with modest values
/// of those too ([`Cx::modest`]). A finding that only those reach is [`Values::Time`] or
/// [`Values::Scene`]; where modest ones reach it too, it is [`Values::Modest`] or
/// [`Values::Window`].
fn overflow(
    cx: &Cx,
    f: &Function,
    id: usize,
    e: &E,
    ops: &[Handle<E>],
    typ: &[Interval],
) -> Option<(Interval, Values)> {
    let names = ops
        .iter()
        .filter_map(|o| cx.sound().num(id, *o).and_then(|n| named(n.facts)))
        .max_by_key(|v| *v == Values::Time);
    let modest = || {
        let an = cx.modest();
        let typ: Vec<Interval> = ops
            .iter()
            .filter_map(|o| an.num(id, *o).map(|n| n.hull()))
            .collect();
        if typ.len() != ops.len() || typ.iter().any(|i| i.mag() > LIMIT) {
            return None;
        }
        amplified_in(cx, an, f, id, e, &typ)
            .filter(|m| past(*m))
            .map(|m| (m, unnamed(cx, id, ops)))
    };
    if typ.iter().any(|i| i.mag() > LIMIT) {
        return names.and_then(|_| modest());
    }
    let r = amplified(cx, f, id, e, typ).filter(|r| past(*r))?;
    match names {
        Some(values) => Some(modest().unwrap_or((r, values))),
        None => Some((r, unnamed(cx, id, ops))),
    }
}

/// Whether `e` has the shape of an amplification [`amplified`] measures: a product of a value
/// with itself or with a constant (also inside `fma`), a dot product of a vector with itself, or
/// a quotient, power, exponential or length.
fn could_amplify(cx: &Cx, f: &Function, id: usize, e: &E) -> bool {
    let constant = |h: Handle<E>| {
        cx.sound()
            .num(id, h)
            .is_some_and(|n| n.comps().iter().all(|c| c.as_point().is_some()))
    };
    match *e {
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        }
        | E::Math {
            fun: Mf::Fma,
            arg: left,
            arg1: Some(right),
            ..
        } => {
            let fixed = |h| constant(h) || fixed(cx, id, h);
            cx.sound().same(f, id, left, right) || fixed(left) || fixed(right)
        }
        E::Math {
            fun: Mf::Dot,
            arg,
            arg1: Some(b),
            ..
        } => cx.sound().same(f, id, arg, b),
        _ => true,
    }
}

/// Whether `h` is a value the shader alone bounds, whatever its inputs (a loop's counter,
/// `float(j)` for `j < 20`): a factor as fixed as a constant.
fn fixed(cx: &Cx, id: usize, h: Handle<E>) -> bool {
    cx.sound()
        .num(id, h)
        .is_some_and(|n| !n.facts.any(Facts::DEPS) && n.comps().iter().all(|c| c.mag().is_finite()))
}

/// Whether `h` is, in the source, a literal of magnitude at most 1 (`0.5`), or a parameter of a
/// function every call of which passes one (dEQP's `isOk(a, b, 0.05)`): a product with it is
/// bounded as [`bounded_cheaply`] says, and this needs no analysis. `args` gives
/// [`literal_arguments`].
fn literal_within_one<'m>(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    args: impl FnOnce() -> &'m [Vec<Option<f64>>],
) -> bool {
    match f.expressions[h] {
        E::Literal(l) => literal(&l).abs() <= 1.0,
        E::FunctionArgument(i) if id < cx.module.functions.len() => args()
            .get(id)
            .and_then(|a| a.get(i as usize).copied().flatten())
            .is_some_and(|m| m <= 1.0),
        _ => false,
    }
}

/// For each module function (by handle index) and parameter, the largest magnitude of the
/// literals its calls pass there: `None` when some call passes anything else, or when nothing
/// calls the function.
fn literal_arguments(module: &naga::Module) -> Vec<Vec<Option<f64>>> {
    let mut out: Vec<Vec<Option<f64>>> = module
        .functions
        .iter()
        .map(|(_, f)| vec![None; f.arguments.len()])
        .collect();
    let mut called = vec![false; out.len()];
    let callers = module
        .functions
        .iter()
        .map(|(_, f)| f)
        .chain(module.entry_points.iter().map(|ep| &ep.function));
    for caller in callers {
        crate::analysis::each_statement(&caller.body, &mut |st| {
            let naga::Statement::Call {
                function,
                ref arguments,
                ..
            } = *st
            else {
                return;
            };
            let k = function.index();
            let first = !std::mem::replace(&mut called[k], true);
            for (slot, a) in out[k].iter_mut().zip(arguments) {
                let lit = match caller.expressions[*a] {
                    E::Literal(l) => Some(literal(&l).abs()).filter(|m| m.is_finite()),
                    _ => None,
                };
                *slot = match (first, *slot, lit) {
                    (true, _, l) => l,
                    (false, Some(m), Some(l)) => Some(m.max(l)),
                    _ => None,
                };
            }
        });
    }
    out
}

/// Whether a generous bound on the ordinary values of `e`'s operands already keeps it within
/// 65504: each operand a constant or an external value as such (a uniform, input or texel, of
/// magnitude at most [`TYPICAL`], more than the ordinary-values analysis gives any of them).
/// Then the ordinary-values analysis cannot find an overflow there, and need not run.
///
/// A product with a constant of magnitude at most 1 (`0.05 * x`, `0.5 * (a + b)`) is bounded
/// whatever the other operand: it is no larger than that operand, which the rule only
/// considers while it is within 65504 (an operand that overflows already is its own finding).
fn bounded_cheaply(cx: &Cx, id: usize, e: &E, ops: &[Handle<E>]) -> bool {
    let shrinks = |h: Handle<E>| {
        cx.sound().num(id, h).is_some_and(|n| {
            n.comps()
                .iter()
                .all(|c| c.as_point().is_some_and(|x| x.abs() <= 1.0))
        })
    };
    if matches!(
        e,
        E::Binary {
            op: Bo::Multiply,
            ..
        }
    ) && ops.iter().any(|o| shrinks(*o))
    {
        return true;
    }
    let bound = |h: Handle<E>| {
        let n = cx.sound().num(id, h)?;
        if n.comps().iter().all(|c| c.as_point().is_some()) || fixed(cx, id, h) {
            Some((n.hull(), n.n))
        } else if n.facts.has(crate::value::Facts::EXT) {
            let m = magnitude(n.facts);
            Some((Interval::new(-m, m), n.n))
        } else {
            None
        }
    };
    let Some(b) = ops.iter().map(|o| bound(*o)).collect::<Option<Vec<_>>>() else {
        return false;
    };
    let squares = |(i, n): (Interval, u8)| i.sqr().mul(Interval::point(f64::from(n)));
    let r = match (e, &b[..]) {
        (
            E::Binary {
                op: Bo::Multiply, ..
            },
            [x, y],
        ) => x.0.mul(y.0),
        (E::Binary { op: Bo::Divide, .. }, [x, y]) => {
            if y.0.contains(0.0) {
                return true; // the divisor's ordinary values contain 0 too: no amplification
            }
            x.0.div(y.0)
        }
        (E::Math { fun: Mf::Pow, .. }, [x, y]) => {
            x.0.meet(Interval::new(1.0, f64::INFINITY))
                .pow(y.0.meet(Interval::NON_NEGATIVE))
        }
        (E::Math { fun: Mf::Exp, .. }, [x]) => x.0.exp(),
        (E::Math { fun: Mf::Exp2, .. }, [x]) => x.0.exp2(),
        (E::Math { fun: Mf::Sinh, .. }, [x]) => x.0.sinh(),
        (E::Math { fun: Mf::Cosh, .. }, [x]) => x.0.cosh(),
        (E::Math { fun: Mf::Dot, .. }, [x, _]) => squares(*x),
        (
            E::Math {
                fun: Mf::Length | Mf::Normalize,
                ..
            },
            [x],
        ) => squares(*x),
        (
            E::Math {
                fun: Mf::Distance, ..
            },
            [x, y],
        ) => squares((x.0.sub(y.0), x.1.max(y.1))),
        (E::Math { fun: Mf::Fma, .. }, [x, y, z]) => x.0.mul(y.0).add(z.0),
        _ => return false,
    };
    r.is_empty() || r.mag() <= LIMIT
}

/// The range the shader's own amplification gives `e` for ordinary values, when it amplifies:
/// a square or power of one value, an exponential, a scaling by a constant, a division by a
/// value bounded away from 0, the sum of squares inside `length`/`normalize`. A product of
/// different parameters is not an amplification: its scale is the parameters' (the runtime
/// check sees their values).
fn amplified(cx: &Cx, f: &Function, id: usize, e: &E, typ: &[Interval]) -> Option<Interval> {
    amplified_in(cx, cx.typical(), f, id, e, typ)
}

/// [`amplified`], the vector functions reading their operands' components from `an` (the
/// ordinary values [`Cx::typical`] or the modest ones [`Cx::modest`], as `typ` is).
fn amplified_in(
    cx: &Cx,
    an: &crate::analysis::Analysis,
    f: &Function,
    id: usize,
    e: &E,
    typ: &[Interval],
) -> Option<Interval> {
    let constant = |h: Handle<E>| {
        cx.sound()
            .num(id, h)
            .is_some_and(|n| n.comps().iter().all(|c| c.as_point().is_some()))
    };
    let fixed = |h: Handle<E>| constant(h) || fixed(cx, id, h);
    let comps = |h: Handle<E>| -> Option<Vec<Interval>> { Some(an.num(id, h)?.comps().to_vec()) };
    let squares = |h: Handle<E>| {
        comps(h).map(|cs| cs.iter().fold(Interval::point(0.0), |s, c| s.add(c.sqr())))
    };
    match *e {
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => (cx.sound().same(f, id, left, right) || fixed(left) || fixed(right))
            .then(|| typ[0].mul(typ[1])),
        E::Binary {
            op: Bo::Divide,
            left,
            right,
        } => {
            (!typ[1].contains(0.0) && !correlated(cx, id, left, right)).then(|| typ[0].div(typ[1]))
        }
        E::Math { fun: Mf::Pow, .. } => {
            // Growth: a base above 1 to a positive power. A base near 0 with a negative
            // exponent is pow-zero-base's business.
            let r = typ[0]
                .meet(Interval::new(1.0, f64::INFINITY))
                .pow(typ[1].meet(Interval::NON_NEGATIVE));
            (!r.is_empty()).then_some(r)
        }
        E::Math { fun: Mf::Exp, .. } => Some(typ[0].exp()),
        E::Math { fun: Mf::Exp2, .. } => Some(typ[0].exp2()),
        E::Math { fun: Mf::Sinh, .. } => Some(typ[0].sinh()),
        E::Math { fun: Mf::Cosh, .. } => Some(typ[0].cosh()),
        E::Math {
            fun: Mf::Dot,
            arg,
            arg1: Some(b),
            ..
        } => {
            if cx.sound().same(f, id, arg, b) {
                squares(arg)
            } else {
                None
            }
        }
        E::Math {
            fun: Mf::Length | Mf::Normalize,
            arg,
            ..
        } => squares(arg),
        E::Math {
            fun: Mf::Distance,
            arg,
            arg1: Some(b),
            ..
        } => {
            let (x, y) = (comps(arg)?, comps(b)?);
            Some(
                x.iter()
                    .zip(&y)
                    .fold(Interval::point(0.0), |s, (a, b)| s.add(a.sub(*b).sqr())),
            )
        }
        E::Math {
            fun: Mf::Fma,
            arg,
            arg1: Some(b),
            ..
        } => (cx.sound().same(f, id, arg, b) || constant(arg) || constant(b))
            .then(|| typ[0].mul(typ[1]).add(typ[2])),
        _ => None,
    }
}

/// Whether a numerator and a divisor read a uniform in common: `x * x / (4.0 * knee + eps)`
/// with `x` clamped to `[0, 2 * knee]` is small where the divisor is, which the ranges of the
/// two alone do not show.
fn correlated(cx: &Cx, id: usize, num: Handle<E>, den: Handle<E>) -> bool {
    let (a, b) = (cx.origin(&[(id, num)]), cx.origin(&[(id, den)]));
    a.uniforms.iter().any(|u| b.uniforms.contains(u))
}

/// The expressions of a function and who reads each: what [`Uses::saturated`] follows.
struct Uses<'a> {
    cx: &'a Cx<'a>,
    f: &'a Function,
    id: usize,
    /// Who reads each expression: computed when an overflow asks whether its uses saturate it.
    users: std::cell::OnceCell<HashMap<Handle<E>, Vec<User>>>,
}

impl Uses<'_> {
    /// Whether every use of `h` clamps away its overflow (`up`: towards +∞, `down`: towards −∞).
    fn saturated(&self, h: Handle<E>, up: bool, down: bool, depth: u32) -> bool {
        let (cx, f, id) = (self.cx, self.f, self.id);
        let Some(us) = self.users.get_or_init(|| users(f)).get(&h) else {
            return true;
        };
        let bounded = |x: Option<Handle<E>>| {
            x.and_then(|x| cx.typical().num(id, x))
                .is_some_and(|n| n.hull().mag() <= LIMIT)
        };
        us.iter().all(|u| {
            let User::Expr(u) = *u else { return false };
            match f.expressions[u] {
                E::Math {
                    fun: Mf::Clamp,
                    arg,
                    arg1,
                    arg2,
                    ..
                } => arg == h && bounded(arg1) && bounded(arg2),
                E::Math {
                    fun: Mf::Saturate | Mf::Step | Mf::SmoothStep,
                    ..
                } => true,
                E::Math {
                    fun: Mf::Min,
                    arg,
                    arg1,
                    ..
                } => !down && bounded(if arg == h { arg1 } else { Some(arg) }),
                E::Math {
                    fun: Mf::Max,
                    arg,
                    arg1,
                    ..
                } => !up && bounded(if arg == h { arg1 } else { Some(arg) }),
                E::Binary {
                    op:
                        Bo::Less
                        | Bo::LessEqual
                        | Bo::Greater
                        | Bo::GreaterEqual
                        | Bo::Equal
                        | Bo::NotEqual,
                    ..
                } => true,
                E::Splat { .. } if depth < 3 => self.saturated(u, up, down, depth + 1),
                _ => false,
            }
        })
    }
}

/// The operand of `e` that must stay away from zero: a divisor, the argument of `inversesqrt`
/// or `log`.
fn guarded_operand(cx: &Cx, f: &Function, h: Handle<E>, e: &E) -> Option<Handle<E>> {
    match *e {
        E::Binary {
            op: Bo::Divide,
            right,
            ..
        } => Some(cx.operand(f, h, right)),
        E::Math {
            fun: Mf::InverseSqrt | Mf::Log | Mf::Log2,
            arg,
            ..
        } => Some(cx.operand(f, h, arg)),
        _ => None,
    }
}

/// How small a low-precision value kept above zero can be, when that is below the smallest
/// normal 16-bit float.
fn underflows(cx: &Cx, id: usize, f: &Function, x: Handle<E>) -> Option<f64> {
    let span = cx.span(f, x);
    if span.is_empty() || !cx.prec.is_low(span) {
        return None;
    }
    let v = cx.sound().num(id, x)?;
    let m = v
        .comps()
        .iter()
        .map(|c| c.mig())
        .fold(f64::INFINITY, f64::min);
    (m > 0.0 && m < MIN_NORMAL).then_some(m)
}

/// A low-precision divisor (or `inversesqrt`/`log` argument) kept away from zero by less than
/// the smallest normal 16-bit float.
fn underflow(cx: &Cx, f: &Function, id: usize, h: Handle<E>, e: &E, out: &mut Vec<Diagnostic>) {
    let Some(x) = guarded_operand(cx, f, h, e) else {
        return;
    };
    let Some(m) = underflows(cx, id, f, x) else {
        return;
    };
    let span = cx.span(f, x);
    let p = cx.prec.at(span).map(|p| p.name()).unwrap_or("mediump");
    out.push(
        Diagnostic::rule_warning(MediumpOverflow::RULE.id, format!("`{p}` value kept above 0 by less than 6.1e-5 can underflow to 0"), span)
            .with_label(format!("as small as {} in `{p}`, below the smallest normal 16-bit float", fmt_num(m)))
            .with_note("mediump and lowp are 16-bit floats on many mobile GPUs: values below 6.1e-5 may flush to 0")
            .with_help("use a guard of at least 1e-4, or compute it in `highp`"),
    );
}
