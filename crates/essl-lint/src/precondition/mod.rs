//! Uniform preconditions: what the static rules leave to run time, as conditions on uniform
//! values that a renderer can evaluate with the values it is about to draw with.
//!
//! The static rules take a uniform's value to be valid — `normalize(u_lightDirection)`,
//! `pow(…, u_shininess)` and `acos(u_coneCos)` are not reported, and
//! `smoothstep(u_outerLimit, u_innerLimit, d)` is reported but cannot be decided. For each such
//! expression [`preconditions`] runs the same analysis (`crate::analysis`, the guards and
//! the symbolic facts the rules use) and, where the value at risk is computed from uniforms and
//! constants only, exports it as a [`Term`] over the uniforms it reads, in a [`Condition`]:
//!
//! | rule | condition | from |
//! |---|---|---|
//! | `smoothstep-edges` | [`Condition::Less`]`(edge0, edge1)` | `smoothstep` whose edges the shader does not order |
//! | `division-by-difference` | [`Condition::NotEqual`]`(a, b)` | `x / (a - b)` not kept away from 0 |
//! | `division-by-zero` | [`Condition::NonZero`]`(d)` | any other divisor computed from uniforms (`gl_FragCoord.xy / u_viewport`) |
//! | `normalize-zero` | [`Condition::NonZeroVector`]`(v)`, [`Condition::NotParallel`]`(a, b)` | `normalize(v)`, `normalize(cross(a, b))` |
//! | `pow-zero-base` | [`Condition::Positive`]`(y)`, [`Condition::PowBaseZero`] | `pow(x, y)` with a base that can be 0 |
//! | `pow-negative-base` | [`Condition::NonNegative`]`(x)` | `pow(x, y)` with a base from uniforms |
//! | `acos-domain`, `asin-domain` | [`Condition::WithinUnit`]`(x)` | `acos(x)`, `asin(x)` of a value from uniforms |
//! | `non-finite-uniform` | [`Condition::Finite`]`(u)` | every uniform the shader reads |
//!
//! Values passed to a function are followed through its call sites (one precondition per call
//! site whose arguments differ), so three.js's `getSpotAttenuation(spotLight.coneCos,
//! spotLight.penumbraCos, …)` gives `spotLights[0].coneCos < spotLights[0].penumbraCos`.
//! A dynamic index (`u_lights[i]`) becomes [`PathStep::AnyIndex`]: the condition holds for
//! every element.
//!
//! ```
//! use essl::source::SourceFile;
//! use essl::{compile, CompileOptions, Stage};
//!
//! let text = "#version 300 es\nprecision highp float;\nin float d;\nuniform float u_inner;\n\
//!             uniform float u_outer;\nout vec4 o;\n\
//!             void main() { o = vec4(smoothstep(u_outer, u_inner, d)); }\n";
//! let shader = compile(SourceFile::new("a.frag", text), Stage::Fragment, &CompileOptions::default());
//! let pre = essl_lint::preconditions(&shader);
//! let edges = pre.iter().find(|p| p.rule == "smoothstep-edges").unwrap();
//! assert_eq!(edges.condition.to_string(), "u_outer < u_inner");
//! assert_eq!(edges.uniform_names(), ["u_outer", "u_inner"]);
//! ```
//!
//! The parts: `uniform`, `value`, `term` and `condition` are the exported vocabulary (what a
//! renderer evaluates); `extract` follows an expression back to the uniforms it is computed
//! from, and `checks` says, per kind of expression at risk, which condition it needs.

mod checks;
mod condition;
mod extract;
mod term;
mod uniform;
mod value;

use essl::source::{SourceFile, Span};
use essl::{Shader, Stage};

pub use condition::{Condition, Outcome};
pub use term::{BinOp, Func, Term};
pub use uniform::{PathStep, UniformRef};
pub use value::{Precision, Value};

use crate::rules::{Cx, RULES};
use extract::Extractor;

/// The name essl's lowering gives the struct that holds the default uniform block.
const DEFAULT_BLOCK: &str = "_essl_uniforms";
/// The most call-site contexts followed for one function.
const MAX_CONTEXTS: usize = 32;
/// The deepest call chain followed.
const MAX_CALL_DEPTH: u32 = 6;

/// The rule id of the runtime-only check of a divisor computed from uniforms.
pub const DIVISION_BY_ZERO: &str = "division-by-zero";
/// The rule id of the runtime-only check that every uniform value is finite.
pub const NON_FINITE_UNIFORM: &str = "non-finite-uniform";

/// A condition on uniform values that an expression of the shader needs, found by the
/// analysis the static rules use.
#[derive(Clone, Debug, PartialEq)]
pub struct Precondition {
    /// The rule: a static rule's id (`smoothstep-edges`, …), or a runtime-only one
    /// ([`DIVISION_BY_ZERO`], [`NON_FINITE_UNIFORM`]).
    pub rule: &'static str,
    /// What must hold.
    pub condition: Condition,
    /// The expression at risk (the static rule's span where it has a finding): into the
    /// shader's text.
    pub span: Span,
    /// The shader's stage.
    pub stage: Stage,
    /// The calls through which the uniform values reach [`Precondition::span`], outermost
    /// first (empty when the expression reads the uniforms itself).
    pub call_sites: Vec<Span>,
    /// The precision the expression is computed in.
    pub precision: Precision,
    /// What goes wrong when the condition fails, in a sentence.
    pub message: String,
    /// Whether the static lint reports a finding of the same rule at this expression (the
    /// hazard is reported either way; the runtime check says when it happens).
    pub reported: bool,
}

impl Precondition {
    /// The uniforms the condition reads, in order.
    pub fn uniforms(&self) -> Vec<&UniformRef> {
        self.condition.uniforms()
    }

    /// The WebGL names of the uniforms the condition reads (`[*]` for any element).
    pub fn uniform_names(&self) -> Vec<String> {
        self.uniforms().iter().map(|u| u.name(None)).collect()
    }

    /// Whether the condition is on every element of an array (a dynamic index).
    pub fn has_any_index(&self) -> bool {
        self.uniforms().iter().any(|u| u.has_any_index())
    }

    /// Evaluates the condition: see [`Condition::check`].
    pub fn check(&self, uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>) -> Outcome {
        self.condition.check(self.precision, uniforms)
    }

    /// One line: `file:line:col rule: condition (message)`.
    pub fn describe(&self, file: &SourceFile) -> String {
        let lc = file.line_col(self.span.start);
        format!(
            "{}:{}:{} {}: {} — {}",
            file.name(),
            lc.line,
            lc.column,
            self.rule,
            self.condition,
            self.message
        )
    }
}

/// The uniform preconditions of a compiled shader, in source order (a shader that did not
/// compile has none). Every one is a condition on the values of uniforms of the default block
/// (what `uniform*` sets); members of uniform blocks are not followed.
pub fn preconditions(shader: &Shader) -> Vec<Precondition> {
    let Some(cx) = Cx::new(shader) else {
        return Vec::new();
    };
    let ex = Extractor::new(&cx, shader.stage);
    let mut out = Vec::new();
    for (id, f) in cx.functions() {
        ex.function(id, f, &mut out);
    }
    ex.finite(&mut out);
    // What the static rules report, to say which preconditions they also flag.
    let mut found = Vec::new();
    for r in RULES {
        (r.check)(&cx, &mut found);
    }
    for p in &mut out {
        p.reported = found
            .iter()
            .any(|d| d.code == p.rule && d.span.start < p.span.end && p.span.start < d.span.end);
    }
    let mut seen = Vec::new();
    out.retain(|p| {
        let key = (p.rule, p.span, p.condition.clone());
        if seen.contains(&key) {
            false
        } else {
            seen.push(key);
            true
        }
    });
    out.sort_by_key(|p| (p.span.start, p.span.end, p.rule));
    out
}

#[cfg(test)]
mod tests {
    use super::value::round_f16;
    use super::*;

    #[test]
    fn f16_rounding() {
        assert_eq!(round_f16(1.0), 1.0);
        assert_eq!(round_f16(65504.0), 65504.0);
        assert_eq!(round_f16(65519.0), 65504.0);
        assert_eq!(round_f16(65520.0), f64::INFINITY);
        assert_eq!(round_f16(0.1), 0.0999755859375);
        // 0.9 and 0.9001 are the same 16-bit float.
        assert_eq!(round_f16(0.9), round_f16(0.9001));
        assert_eq!(round_f16(2f64.powi(-24)), 2f64.powi(-24));
        assert_eq!(round_f16(2f64.powi(-26)), 0.0);
    }

    #[test]
    fn covers_names() {
        let r = UniformRef {
            base: "lights".into(),
            path: vec![PathStep::AnyIndex, PathStep::Member("cutOff".into())],
        };
        assert_eq!(r.name(None), "lights[*].cutOff");
        assert_eq!(r.name(Some(2)), "lights[2].cutOff");
        assert!(r.covers("lights[2].cutOff"));
        assert!(!r.covers("lights[2].cutOffX"));
        assert!(!r.covers("lights[].cutOff"));
        assert!(!r.covers("lights[2].outerCutOff"));
        let whole = UniformRef::new("light");
        assert!(whole.covers("light.cutOff"));
        assert!(whole.covers("light"));
        assert!(!whole.covers("lightColor"));
        assert!(UniformRef::new("u_w").covers("u_w[3]"));
    }

    #[test]
    fn conditions() {
        let u = |n: &str| Term::Uniform(UniformRef::new(n));
        let vals = |a: f64, b: f64| {
            move |r: &UniformRef| Some(Value::scalar(if r.base == "a" { a } else { b }))
        };
        let less = Condition::Less(u("a"), u("b"));
        assert_eq!(
            less.check(Precision::High, &mut vals(0.5, 0.9)),
            Outcome::Holds
        );
        let Outcome::Violated(why) = less.check(Precision::High, &mut vals(0.9, 0.9)) else {
            panic!()
        };
        assert!(why.contains("equal"), "{why}");
        let Outcome::Violated(why) = less.check(Precision::High, &mut vals(0.95, 0.9)) else {
            panic!()
        };
        assert!(why.contains("swapped"), "{why}");
        let ne = Condition::NotEqual(u("a"), u("b"));
        assert_eq!(
            ne.check(Precision::High, &mut vals(0.9, 0.9001)),
            Outcome::Holds
        );
        assert!(matches!(
            ne.check(Precision::Low, &mut vals(0.9, 0.9001)),
            Outcome::Violated(_)
        ));
        let pos = Condition::Positive(u("a"));
        assert!(matches!(
            pos.check(Precision::High, &mut vals(f64::NAN, 0.0)),
            Outcome::Violated(_)
        ));
        assert_eq!(pos.check(Precision::High, &mut |_| None), Outcome::Unknown);
    }

    #[test]
    fn vectors() {
        let u = |n: &str| Term::Uniform(UniformRef::new(n));
        let v = |x: [f64; 3], y: [f64; 3]| {
            move |r: &UniformRef| Some(Value::new(if r.base == "a" { &x } else { &y }))
        };
        let nz = Condition::NonZeroVector(u("a"));
        assert!(matches!(
            nz.check(Precision::High, &mut v([0.0; 3], [0.0; 3])),
            Outcome::Violated(_)
        ));
        assert_eq!(
            nz.check(Precision::High, &mut v([0.0, -1.0, 0.0], [0.0; 3])),
            Outcome::Holds
        );
        // 0.005 is fine in highp; its square flushes in mediump.
        assert_eq!(
            nz.check(Precision::High, &mut v([0.005, 0.0, 0.0], [0.0; 3])),
            Outcome::Holds
        );
        assert!(matches!(
            nz.check(Precision::Low, &mut v([0.005, 0.0, 0.0], [0.0; 3])),
            Outcome::Violated(_)
        ));
        let par = Condition::NotParallel(u("a"), u("b"));
        assert!(matches!(
            par.check(Precision::High, &mut v([0.0, 1.0, 0.0], [0.0, -2.0, 0.0])),
            Outcome::Violated(_)
        ));
        assert_eq!(
            par.check(Precision::High, &mut v([0.0, 1.0, 0.0], [0.0, -1.0, 0.1])),
            Outcome::Holds
        );
        let t = Term::Binary(BinOp::Sub, Box::new(u("a")), Box::new(u("b")));
        assert_eq!(t.to_string(), "a - b");
        let t = Term::Binary(
            BinOp::Mul,
            Box::new(Term::Const(Value::scalar(2.0))),
            Box::new(t),
        );
        assert_eq!(t.to_string(), "2 * (a - b)");
    }
}
