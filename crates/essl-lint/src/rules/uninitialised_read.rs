//! `uninitialised-read`: a variable read before any write to it, on some path.

use essl::diagnostic::{Diagnostic, Fix};
use essl::hir::GlobalKind;
use essl::types::{ScalarKind, Type};

use super::rule::declare_rule;
use super::Cx;
use crate::definite::{uninitialised_reads, Var};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports a read of a variable that some path reaches before any write to it: a local declared
    /// without a value (`float d;`) and assigned only in some branches, only in a loop that may not
    /// run, only in some components (`v.xy = …` before reading all of `v`; `v[i] = …` in a loop
    /// whose counter stops short of a component, `for (int i = 0; i < 3; i++)` then `v.a`; a
    /// struct's member written under an `if` only, then the struct read whole — p5's
    /// `if (uSpecular) lr.specular = …; lr.diffuse = …; return lr;` — or a member read that no
    /// path writes), or
    /// passed as an `inout` argument to a function that reads the parameter before writing it; an
    /// `out` parameter read before the function writes it, or left unwritten on some path through
    /// a `void` function (the caller's variable is then undefined); and in `main` (and the
    /// functions it calls) a global declared without a value or a shader output — declared (`out
    /// vec4 o`) or built in (`gl_FragColor`, `gl_FragData`, `gl_Position`, `gl_PointSize`,
    /// `gl_FragDepth`) — read before it is written (vtk.js's `if (gl_FragData[0].a <= 0.0)
    /// discard;` where its template's tags write nothing). And a function that returns a value
    /// whose end control can reach without a `return`, reported at the statement control leaves
    /// after: lygia's palette lookups `for (int i = 0; i < N; i++) if (i == index) return t[i];`,
    /// whose caller reads an undefined result for an index outside the table (a function only
    /// declared here, without a body, is the linked program's business).
    ///
    /// ## Why is this bad?
    /// GLSL ES leaves a variable without an initializer undefined until it is written (GLSL ES 3.00
    /// §4.3, GLSL ES 1.00 §4.3). WebGL implementations set it to zero (WebGL 1.0 §"Initial values
    /// for GLSL local and global variables", which WebGL 2.0 keeps), so in a browser the read gives
    /// 0 — rarely the value the code means where a branch was forgotten (`float shadow; if (inFrustum)
    /// shadow = …;` is 0, full shadow, outside the frustum) — and the same shader on a native GLES
    /// driver, or translated by a tool that does not zero its variables, reads garbage.
    ///
    /// ## Example
    /// ```glsl
    /// float shadow;
    /// if (inFrustum) {
    ///     shadow = texture(u_shadowMap, coord.xyz);
    /// }
    /// color *= shadow;
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float shadow = 1.0;
    /// if (inFrustum) {
    ///     shadow = texture(u_shadowMap, coord.xyz);
    /// }
    /// color *= shadow;
    /// ```
    /// The suggested fix initialises the variable to zero (`float d = 0.0;`), which is what WebGL
    /// gives it today; where another value is meant (1.0 for a light factor), write that instead.
    ///
    /// ## What it does not flag
    /// - A variable written on every path before the read: both branches of an `if`, every case of a
    ///   `switch` with a `default`, the body of a loop whose constant bounds make it run
    ///   (`for (int i = 0; i < 4; i++)`), an `out` argument of a call, all components of a vector
    ///   written one by one.
    /// - An array or matrix once any part of it is written (which parts a dynamic index writes
    ///   is not followed), and every component of a vector written through a dynamic index other
    ///   than a loop counter with constant bounds (`v[k] = …` for a uniform `k`).
    /// - A struct read whole (passed, copied, returned) with members no path has written yet,
    ///   once another member is: an engine fills the members its configuration uses (three.js's
    ///   `PhysicalMaterial` under `USE_CLEARCOAT`, `USE_SHEEN`) and passes the struct to
    ///   functions that read those only. Structs of more than 8 members count as written once
    ///   any part is.
    /// - An `inout` argument the callee writes before reading, and an `out` parameter left unset by a
    ///   function that returns a value (`bool hit(…, out float t)`): the result says whether it is
    ///   set.
    /// - A read under an `if` on uniforms of a variable written earlier under an `if` on the same
    ///   uniforms (`if (u_isText) c = …;` then `if (u_isText && u_isHalo) use(c);`), both outside
    ///   loops, switches and other `if`s: every pixel of a draw takes both branches or neither.
    /// - A read in the branch of an `if` whose condition, or a `bool` local set once at the top of
    ///   the function from it, is true only where the write ran: `if (a && f(x, out m)) use(m);`,
    ///   `bool rotate = !b && f(x, out m); … if (rotate) use(m);`.
    /// - Other paths that cannot run are not told apart from those that can: a read guarded by the
    ///   same condition on a per-pixel value as the write, or in a loop (`if (i > 0) use(prev);
    ///   prev = x;`), is reported; initialise the variable.
    ///
    /// Severity: a warning.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §4.3 Storage Qualifiers (variables without an initializer).
    /// - WebGL 1.0 specification, §"Initial values for GLSL local and global variables".
    pub(crate) struct UninitialisedRead {
        id: "uninitialised-read",
        summary: "a variable read before any write to it on some path, or a function's end reached without a `return` (undefined in GLSL ES; zero in WebGL, garbage elsewhere)",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let m = cx.hir;
    for r in uninitialised_reads(m) {
        let f = &m.functions[r.function];
        if r.var == Var::Result {
            out.push(no_return(f, r.span));
            continue;
        }
        let (what, name, decl, ty) = match r.var {
            Var::Local(i) => {
                let l = &f.locals[i];
                ("variable", l.name.as_str(), l.span, Some(&l.ty))
            }
            Var::Param(i) => {
                let p = &f.params[i];
                ("`out` parameter", p.name.as_str(), p.span, None)
            }
            Var::Global(g) => {
                let gl = &m.globals[g];
                let output = gl.kind == GlobalKind::Output;
                let what = if output { "output" } else { "global" };
                (what, gl.name.as_str(), gl.span, (!output).then_some(&gl.ty))
            }
            Var::Builtin(b) => ("output", b.name(), essl::source::Span::default(), None),
            Var::Result => continue, // above
        };
        let unwritten_out = matches!(r.var, Var::Param(_)) && cx.text(r.span) != name;
        let (message, label) = if unwritten_out {
            (
                format!("`out` parameter `{name}` is not written on some path: the caller's variable is left undefined"),
                "some path reaches this exit without writing it",
            )
        } else if !r.members.is_empty() {
            let list: Vec<String> = r.members.iter().map(|m| format!("`{name}.{m}`")).collect();
            (
                format!(
                    "{what} `{name}` is read whole before {} is written on some path",
                    list.join(" and ")
                ),
                "read here: some path reaches it without writing that member",
            )
        } else {
            (
                format!("{what} `{name}` is read before it is written on some path"),
                "read here: some path reaches it without a write",
            )
        };
        let mut d = Diagnostic::rule_warning(UninitialisedRead::RULE.id, message, r.span)
            .with_label(label)
        .with_note("GLSL ES 3.00 §4.3: its value is undefined until written (WebGL gives 0, other drivers garbage)");
        if !decl.is_empty() && decl != r.span {
            d = d.with_secondary(decl, "declared here without a value");
        }
        if let Some(call) = r.through {
            d = d.with_secondary(call, "reached through this call in `main`");
        }
        match ty.and_then(zero_of) {
            Some(zero) if !decl.is_empty() && cx.text(decl) == name => {
                d = d
                    .with_help(format!(
                        "initialise it where it is declared: `{name} = {zero}`"
                    ))
                    .with_fix(Fix::suggested(
                        format!("initialise `{name}` to {zero}"),
                        decl,
                        format!("{name} = {zero}"),
                    ));
            }
            _ if !r.members.is_empty() => {
                let list: Vec<String> = r.members.iter().map(|m| format!("`{name}.{m}`")).collect();
                d = d.with_help(format!(
                    "write {} on every path before the read (an `else` for the `if` that writes it), or initialise `{name}`",
                    list.join(" and ")
                ));
            }
            _ => d = d.with_help("write it on every path before the read, or initialise it"),
        }
        out.push(d);
    }
}

/// The finding for a function that returns a value and whose end control can reach without a
/// `return` (after a loop that returns from inside, an `if` without `else`): the call's result
/// is undefined.
fn no_return(f: &essl::hir::Function, at: essl::source::Span) -> Diagnostic {
    let name = f.name.as_str();
    Diagnostic::rule_warning(
        UninitialisedRead::RULE.id,
        format!("`{name}` can reach its end without returning a value: the caller reads an undefined result"),
        at,
    )
    .with_label("control can leave the function after this without `return`")
    .with_secondary(f.span, "returns a value")
    .with_note("GLSL ES 3.00 §6.1: a function that returns a value must return one on every path; the result is undefined otherwise")
    .with_help("end the function with a `return` of a fallback value")
}

/// The zero of a scalar, vector or matrix type, as GLSL.
fn zero_of(t: &Type) -> Option<String> {
    let kind = match t {
        Type::Scalar(k) | Type::Vector(k, _) => *k,
        Type::Matrix { .. } => ScalarKind::Float,
        _ => return None,
    };
    let (prefix, zero) = match kind {
        ScalarKind::Float => ("", "0.0"),
        ScalarKind::Int => ("i", "0"),
        ScalarKind::Uint => ("u", "0u"),
        ScalarKind::Bool => ("b", "false"),
    };
    Some(match t {
        Type::Scalar(_) => zero.to_string(),
        Type::Vector(_, n) => format!("{prefix}vec{n}({zero})"),
        Type::Matrix { cols, rows } if cols == rows => format!("mat{cols}(0.0)"),
        Type::Matrix { cols, rows } => format!("mat{cols}x{rows}(0.0)"),
        _ => return None,
    })
}
