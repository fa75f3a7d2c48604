//! Values a function takes from its callers, or a vertex shader from its vertex data: a
//! parameter or an attribute, or what is 0 wherever they are — sums, differences, products,
//! quotients by constants, `length`, `abs`, `dot`, `min`, `max`, `tan`, `sin`, the ends of a
//! `mix` — of parameters (or of attributes) and constants: `2.0 * s * s`, `iMax - iMin`,
//! `1.0 - b`, `tan(fov / 2.0)`, `dot(b - a, b - a)`. Where the callers pass inputs as such, the
//! function's contract is left to whoever calls it (lygia's `gaussian(d, s)`, `map(v, iMin,
//! iMax)`, `perspective(fov, aspect, near, far)`).
//!
//! The value analysis knows nothing of such a parameter: the rules leave a hazard that needs
//! particular values of an input to whoever supplies them. A reviewer of the function still
//! flags it — a blur of sigma 0, a collapsed input range, a near plane at the far plane are
//! values callers pass — so `division-by-difference` reports the division as a note naming the
//! parameters, and `domain-log`, `domain-inversesqrt`, `pow-zero-base` and `domain-atan2` the
//! same of their arguments. A vertex shader's attributes are the host's data in the same way
//! (a particle of life 0, a vertex whose skinning weights are all 0); a fragment shader's
//! varyings are not: an interpolated value crosses 0 on a line of pixels at most.
//!
//! Left out, as a reviewer leaves them: a value that is not 0 for ordinary, non-negative
//! inputs (`x + 0.155`, `ior + 1.0`), the `w` of a `vec4` as a divisor (a homogeneous
//! coordinate, positive in front of the camera), a parameter whose name says what is never 0
//! (`ior`, `shutterSpeed`, a number `base`), and a lone parameter whose name says it holds a
//! size the host computes from the canvas or a texture, or a multiple of one
//! (`1.0 / texResolution`, `floor(v * res) / res`) — but not its difference with a constant
//! (`0.5 / (res - 1.0)`, 0 for a texture one texel wide).

use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf, TypeInner,
    UnaryOperator,
};

use super::Cx;
use crate::value::Facts;

/// How deep [`leaves`] follows an expression's operands.
const MAX_DEPTH: u32 = 10;

/// Words of a parameter's name that say it holds a size the host computes.
const HOST_SIZE: &[&str] = &[
    "resolution",
    "resolutions",
    "res",
    "size",
    "pixel",
    "texel",
    "viewport",
    "screen",
    "canvas",
    "dimensions",
];

/// A value built from a function's parameters or a vertex shader's attributes.
pub(super) struct CallerValue {
    /// The parameters, by name, in the order found, each once.
    pub names: Vec<String>,
    /// Whether it is a difference of two of them (`iMax - iMin`), 0 where they are equal.
    pub difference: bool,
    /// Whether the names are a vertex shader's attributes rather than parameters.
    pub attribute: bool,
    /// Whether it is 0 where they take some value other than 0 (a sum with a constant).
    pub offset: bool,
}

impl CallerValue {
    /// The names, each in backticks, separated by commas.
    pub fn list(&self) -> String {
        let quoted: Vec<String> = self.names.iter().map(|n| format!("`{n}`")).collect();
        quoted.join(", ")
    }

    /// Both values together (`y` and `x` of an `atan`): their names once each; `None` where
    /// one is built from parameters and the other from attributes.
    pub fn and(mut self, other: CallerValue) -> Option<CallerValue> {
        if self.attribute != other.attribute {
            return None;
        }
        for n in other.names {
            if !self.names.contains(&n) {
                self.names.push(n);
            }
        }
        self.difference = false;
        self.offset |= other.offset;
        Some(self)
    }

    /// A lone name as a message names what is 0: "the parameter `t`, which a caller may pass
    /// as 0", "the attribute `a_size`, which a vertex may hold as 0"; "a value of the
    /// parameter `mu`, 0 for some arguments" where a sum with a constant makes it 0 at
    /// another value.
    pub fn lone(&self, name: &str) -> String {
        match (self.attribute, self.offset) {
            (true, false) => format!("the attribute `{name}`, which a vertex may hold as 0"),
            (false, false) => format!("the parameter `{name}`, which a caller may pass as 0"),
            (true, true) => format!("a value of the attribute `{name}`, 0 for some vertices"),
            (false, true) => format!("a value of the parameter `{name}`, 0 for some arguments"),
        }
    }

    /// Why the finding is a note, not a warning.
    pub fn why(&self) -> &'static str {
        if self.attribute {
            "attributes are the host's vertex data, which the shader does not show: keep them from 0 where they are written, or guard here"
        } else {
            "the callers here pass inputs as such, whose values the shader does not know: the function's guard, or its callers'"
        }
    }
}

/// What [`leaves`] has found: the leaves, and the locals it has read (a store that reads the
/// local it writes is not followed again).
#[derive(Default, Clone)]
struct Walk {
    leaves: Vec<Leaf>,
    locals: Vec<(usize, Handle<E>)>,
    /// Whether a sum or difference with a non-zero constant was crossed: the value is 0
    /// where the leaves take some value, not necessarily 0 (`1.0 + g * g - 2.0 * g * mu`).
    offset: bool,
}

/// The function [`leaves`] walks, and where it was called from: a called function's
/// parameters are the arguments of the call, read in the caller's frame.
#[derive(Clone, Copy)]
struct Frame<'a> {
    f: &'a Function,
    id: usize,
    call: Option<(&'a Frame<'a>, &'a [Handle<E>])>,
}

/// What a value is built from.
#[derive(Clone, Copy)]
enum Leaf {
    /// A parameter of the function.
    Parameter(u32),
    /// A vertex shader's attribute (the private copy the entry point makes).
    Attribute(Handle<naga::GlobalVariable>),
}

/// Words of a parameter's name that say its value is never 0 by what it is: an index of
/// refraction (at least 1), an exposure time, the base of a number system.
const NEVER_ZERO: &[&str] = &["ior", "shutter", "base"];

/// Words of an attribute's name that say its `vec4` is a position, whose `w` is a homogeneous
/// coordinate.
const POSITION: &[&str] = &["position", "pos", "vertex", "clip", "homogeneous", "world"];

/// The parameters (or attributes) value `d` of function `id` is built from, with constants
/// only, where the callers pass inputs as such and ordinary values make it 0; `None` where it is
/// not such a value.
pub(super) fn caller_value(cx: &Cx, f: &Function, id: usize, d: Handle<E>) -> Option<CallerValue> {
    let v = cx.sound().num(id, d)?;
    // A uniform may reach it only as a `mix` weight, which [`leaves`] does not follow.
    if !v.facts.any(Facts::INPUT) || v.facts.any(Facts::TEXTURE) {
        return None;
    }
    let mut walk = Walk::default();
    let top = Frame { f, id, call: None };
    if !leaves(cx, &top, d, 0, &mut walk) || walk.leaves.is_empty() {
        return None;
    }
    let offset = walk.offset;
    let params = walk.leaves;
    let attribute = params.iter().all(|l| matches!(l, Leaf::Attribute(_)));
    if !attribute && params.iter().any(|l| matches!(l, Leaf::Attribute(_))) {
        return None;
    }
    let typical = cx.typical().num(id, d)?;
    if !typical.comps().iter().any(|c| c.contains(0.0)) {
        return None;
    }
    let mut names: Vec<String> = Vec::new();
    for leaf in params {
        let name = match leaf {
            Leaf::Parameter(i) => f.arguments[i as usize].name.clone(),
            Leaf::Attribute(g) => cx.module.global_variables[g].name.clone(),
        }
        .unwrap_or_default();
        if !names.contains(&name) {
            names.push(name);
        }
    }
    let top = &f.expressions[crate::symbolic::resolve(f, cx.sound(), id, d)];
    // `p.xyz / p.w`: the `w` of a homogeneous coordinate, positive in front of the camera;
    // but not the last of four values a vertex packs in an attribute that is no position
    // (MapLibre's `a_dasharray_from.w`, a dash pattern's length).
    if let E::AccessIndex { base, index: 3 } = *top {
        let packed = attribute
            && !names
                .iter()
                .any(|n| crate::analysis::names::says_any(n, POSITION));
        if is_vec4(cx, id, base) && !packed {
            return None;
        }
    }
    let sum = matches!(
        top,
        E::Binary {
            op: Bo::Add | Bo::Subtract,
            ..
        }
    );
    // A size itself, or a multiple of it (`1.0 / res`), is not 0 while anything is drawn; a
    // difference with a constant (`res - 1.0`) is, for an ordinary size. An attribute's size
    // or ratio is the vertex data's, not the canvas's (MapLibre's `a_pixel_ratio_from`, 0 for
    // a pattern missing from the atlas).
    if let [name] = &names[..] {
        let host = crate::analysis::names::says_any(name, HOST_SIZE)
            && !crate::analysis::names::is_setting(name);
        if !sum && !attribute && host {
            return None;
        }
    }
    if names
        .iter()
        .any(|n| crate::analysis::names::says_any(n, NEVER_ZERO))
    {
        return None;
    }
    // `iMax - iMin`, `length(b - a)`: 0 where the two are equal.
    let inner = match *top {
        E::Math {
            fun: Mf::Length,
            arg,
            ..
        } => &f.expressions[crate::symbolic::resolve(f, cx.sound(), id, arg)],
        _ => top,
    };
    let difference = names.len() == 2
        && matches!(
            inner,
            E::Binary {
                op: Bo::Subtract,
                ..
            }
        );
    Some(CallerValue {
        names,
        difference,
        attribute,
        offset,
    })
}

/// Whether `h` is built from parameters that every call passes an external value as such and
/// a vertex shader's attributes as such (pushed to `out`), and constants, with `+`, `-`, `*`,
/// negation, `length`, swizzles, components, constructors, conversions and locals.
fn leaves(cx: &Cx, fr: &Frame, h: Handle<E>, depth: u32, out: &mut Walk) -> bool {
    let (f, id) = (fr.f, fr.id);
    if depth > MAX_DEPTH {
        return false;
    }
    let go = |x: Handle<E>, out: &mut Walk| leaves(cx, fr, x, depth + 1, out);
    let as_such = |x: Handle<E>| {
        cx.sound().num(id, x).is_some_and(|v| {
            v.facts.has(Facts::EXT)
                && v.facts.any(Facts::INPUT)
                && !v.facts.any(Facts::UNIFORM.with(Facts::TEXTURE))
        })
    };
    // Uniforms and constants only: the same for every vertex and pixel of a draw.
    let per_draw = |x: Handle<E>| cx.sound().num(id, x).is_some_and(|v| v.facts.per_draw());
    match f.expressions[h] {
        E::Literal(_) | E::Constant(_) | E::ZeroValue(_) => true,
        // In a called function, the call's argument (`unpack_mix_vec2(a_floorwidth, t)`).
        E::FunctionArgument(i) if fr.call.is_some() => {
            let (caller, args) = fr.call.unwrap();
            args.get(i as usize)
                .is_some_and(|&a| leaves(cx, caller, a, depth + 1, out))
        }
        // A parameter every call passes an input as such.
        E::FunctionArgument(i) if as_such(h) => {
            out.leaves.push(Leaf::Parameter(i));
            true
        }
        E::FunctionArgument(i) => from_callers(cx, id, i as usize, depth, out),
        E::CallResult(callee) => returned(cx, fr, h, callee.index(), depth, out),
        E::Load { pointer } if vertex_input(cx, f, pointer).is_some() => {
            out.leaves
                .extend(vertex_input(cx, f, pointer).map(Leaf::Attribute));
            as_such(h)
        }
        // 0 where their arguments are (`length`, `abs`, `tan(fov / 2.0)`), or where both are
        // (`dot(d, d)`, `max(NoL, NoV)`, `min`).
        E::Math {
            fun: Mf::Length | Mf::Abs | Mf::Tan | Mf::Sin | Mf::Asin | Mf::Atan,
            arg,
            arg1: None,
            ..
        } => go(arg, out),
        E::Math {
            fun: Mf::Dot | Mf::Min | Mf::Max,
            arg,
            arg1: Some(b),
            ..
        } => go(arg, out) && go(b, out),
        // `mix(a, b, t)` is 0 where `a` and `b` are, whatever `t` is.
        E::Math {
            fun: Mf::Mix,
            arg,
            arg1: Some(b),
            ..
        } => go(arg, out) && go(b, out),
        // A product with a per-draw value (`u_scale * display_size`) is 0 wherever the other
        // factor is.
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } if per_draw(right) => go(left, out),
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } if per_draw(left) => go(right, out),
        // Any other product is 0 wherever one factor is.
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => product(cx, fr, left, right, depth, out),
        E::Binary {
            op: Bo::Add | Bo::Subtract,
            left,
            right,
        } => {
            let constant = |x: Handle<E>| {
                cx.sound()
                    .num(id, x)
                    .and_then(|n| n.hull().as_point())
                    .is_some_and(|c| c != 0.0)
            };
            if constant(left) || constant(right) {
                out.offset = true;
            }
            go(left, out) && go(right, out)
        }
        E::Unary {
            op: UnaryOperator::Negate,
            expr,
        } => go(expr, out),
        E::AccessIndex { base: x, .. }
        | E::Swizzle { vector: x, .. }
        | E::Splat { value: x, .. }
        | E::As { expr: x, .. } => go(x, out),
        E::Compose { ref components, .. } => components.iter().all(|&c| go(c, out)),
        // A local's stores; one that reads the local itself (`st = st * 2.0 - 1.0`) adds
        // nothing the others do not.
        // A vertex shader's output (or another private global) written in this function only:
        // what is stored into it (MapLibre's `floorwidth = unpack_mix_vec2(a_floorwidth, t)`).
        E::Load { pointer } if matches!(f.expressions[pointer], E::GlobalVariable(_)) => {
            let E::GlobalVariable(g) = f.expressions[pointer] else {
                return false;
            };
            if cx.module.global_variables[g].space != naga::AddressSpace::Private {
                return false;
            }
            if out.locals.contains(&(id, pointer)) {
                return true;
            }
            out.locals.push((id, pointer));
            let stores = cx.flows().global_stores(g.index());
            !stores.is_empty() && stores.iter().all(|&(at, v)| at == id && go(v, out))
        }
        E::Load { pointer } if out.locals.contains(&(id, pointer)) => true,
        E::Load { pointer } => {
            // The store that reaches this load on every path, where the walk knows it (`t`
            // in `vec3 t = b - a; float l = length(t); t /= l;`).
            if let Some(v) = cx.sound().reaching_store(id, h) {
                return go(v, out);
            }
            out.locals.push((id, pointer));
            let stored = cx.stored(f, id, pointer);
            !stored.is_empty() && stored.into_iter().all(|x| go(x, out))
        }
        // A quotient (`fov / 2.0`, `p / (r * r)`) is 0 where the dividend is, and a positive
        // power (`pow(dist, 2.0)`) where its base is.
        E::Binary {
            op: Bo::Divide,
            left,
            ..
        } => go(left, out),
        E::Math {
            fun: Mf::Pow,
            arg,
            arg1: Some(e),
            ..
        } if cx
            .sound()
            .num(id, e)
            .is_some_and(|n| n.comps().iter().all(|c| c.lo > 0.0)) =>
        {
            go(arg, out)
        }
        _ => false,
    }
}

/// Whether a product of `left` and `right` is built as [`leaves`] asks: both factors, or one,
/// 0 wherever it is, whatever the other is (`pow(l, 0.5) * t` of a weight `t` a caller passes).
/// One factor alone is not vertex data (a position's depth, `scale / -mvPosition.z`, is as
/// positive as a homogeneous `w`), nor 0 only where its parameters take some value other than
/// 0 (`0.31 - temp * k`), which the other factor may keep out of reach (lygia's white
/// balance). Each factor is walked once, from what was found before it.
fn product(
    cx: &Cx,
    fr: &Frame,
    left: Handle<E>,
    right: Handle<E>,
    depth: u32,
    out: &mut Walk,
) -> bool {
    let mut l = out.clone();
    let mut r = out.clone();
    let lo = leaves(cx, fr, left, depth + 1, &mut l);
    let ro = leaves(cx, fr, right, depth + 1, &mut r);
    let before = out.leaves.len();
    let alone = |w: &Walk| {
        !w.offset
            && w.leaves[before..]
                .iter()
                .all(|l| matches!(l, Leaf::Parameter(_)))
    };
    match (lo, ro) {
        (true, true) => {
            l.leaves.extend_from_slice(&r.leaves[before..]);
            l.locals.extend(r.locals.into_iter().skip(out.locals.len()));
            l.offset |= r.offset;
            *out = l;
            true
        }
        (true, false) if alone(&l) => {
            *out = l;
            true
        }
        (false, true) if alone(&r) => {
            *out = r;
            true
        }
        _ => false,
    }
}

/// Whether parameter `i` of function `id` is, at every call, a value of a vertex shader's
/// attributes (MapLibre's `get_pattern_pos(…, display_size, …)` of a pattern's corners):
/// those attributes join `out`.
fn from_callers(cx: &Cx, id: usize, i: usize, depth: u32, out: &mut Walk) -> bool {
    if id >= cx.module.functions.len() {
        return false;
    }
    let callers = cx.flows().callers(id);
    !callers.is_empty()
        && callers.iter().all(|(caller, args)| {
            let Some(&a) = args.get(i) else {
                return false;
            };
            let up = Frame {
                f: crate::analysis::function(cx.module, *caller),
                id: *caller,
                call: None,
            };
            let from = out.leaves.len();
            leaves(cx, &up, a, depth + 1, out)
                && out.leaves[from..]
                    .iter()
                    .all(|l| matches!(l, Leaf::Attribute(_)))
        })
}

/// Whether every value function `callee` returns to the call `h` of frame `fr` is built as
/// [`leaves`] asks, its parameters read as the call's arguments.
fn returned(cx: &Cx, fr: &Frame, h: Handle<E>, callee: usize, depth: u32, out: &mut Walk) -> bool {
    let Some(args) = cx.flows().arguments(fr.id, h) else {
        return false;
    };
    let inner = Frame {
        f: crate::analysis::function(cx.module, callee),
        id: callee,
        call: Some((fr, args)),
    };
    let returns = cx.flows().returns(callee);
    !returns.is_empty()
        && returns
            .iter()
            .all(|&r| leaves(cx, &inner, r, depth + 1, out))
}

/// Whether expression `h` of function `id` is a 4-component vector.
fn is_vec4(cx: &Cx, id: usize, h: Handle<E>) -> bool {
    matches!(
        cx.info.ty(id, h),
        TypeInner::Vector {
            size: naga::VectorSize::Quad,
            ..
        }
    )
}

/// Whether private global `g` is the entry point's copy of an input: every store into it is
/// in the entry point, of one of its arguments (an output the shader computes is not).
fn input_copy(cx: &Cx, g: Handle<naga::GlobalVariable>) -> bool {
    let entry = cx.module.functions.len();
    let Some(ep) = cx.module.entry_points.first() else {
        return false;
    };
    let stores = cx.flows().global_stores(g.index());
    !stores.is_empty()
        && stores.iter().all(|&(at, v)| {
            if at != entry {
                return false;
            }
            // A component of a struct argument, or a conversion (`gl_VertexID`, naga's `u32`).
            let mut x = v;
            while let E::AccessIndex { base: inner, .. } | E::As { expr: inner, .. } =
                ep.function.expressions[x]
            {
                x = inner;
            }
            matches!(ep.function.expressions[x], E::FunctionArgument(_))
        })
}

/// A private global a load from `pointer` reads, whole or a component, in a vertex shader: an
/// input's copy or a value the shader keeps there (what [`super::vanishing`] takes for vertex
/// data).
pub(super) fn vertex_private(
    cx: &Cx,
    f: &Function,
    pointer: Handle<E>,
) -> Option<Handle<naga::GlobalVariable>> {
    let ep = cx.module.entry_points.first()?;
    if ep.stage != naga::ShaderStage::Vertex {
        return None;
    }
    let mut p = pointer;
    while let E::AccessIndex { base, .. } = f.expressions[p] {
        p = base;
    }
    let E::GlobalVariable(g) = f.expressions[p] else {
        return None;
    };
    (cx.module.global_variables[g].space == naga::AddressSpace::Private).then_some(g)
}

/// The attribute a load from `pointer` reads, in a vertex shader: a private global that is the
/// entry point's copy of an input, whole or a component.
pub(super) fn vertex_input(
    cx: &Cx,
    f: &Function,
    pointer: Handle<E>,
) -> Option<Handle<naga::GlobalVariable>> {
    vertex_private(cx, f, pointer).filter(|&g| input_copy(cx, g))
}

/// The parameter (its expression) `x` is as such where it is used by `call`: the argument, or
/// a local holding it where every other store into the local is computed from `call` itself
/// (`a = normalize(a)`, a parameter the function writes).
pub(super) fn parameter_itself(
    cx: &Cx,
    f: &Function,
    id: usize,
    call: Handle<E>,
    x: Handle<E>,
) -> Option<Handle<E>> {
    let top = crate::symbolic::resolve(f, cx.sound(), id, x);
    if matches!(f.expressions[top], E::FunctionArgument(_)) {
        return Some(top);
    }
    let E::Load { pointer } = f.expressions[x] else {
        return None;
    };
    let stored = cx.stored(f, id, pointer);
    let param = *stored
        .iter()
        .find(|v| matches!(f.expressions[**v], E::FunctionArgument(_)))?;
    stored
        .iter()
        .all(|&v| v == param || super::computed_from(f, v, call))
        .then_some(param)
}
