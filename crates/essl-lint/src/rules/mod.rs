//! The rules, one module per rule (named for its id, the rule's page the doc comment of its
//! type), and the list they run in. What the rules share is in [`context`] (the analysed
//! shader), [`guards`] (what the conditions around an expression say) and [`rule`] (what a
//! rule is).

mod context;
mod guards;
pub(crate) mod origin;
pub(crate) mod rule;

mod acos_domain;
mod asin_domain;
mod division_by_difference;
mod inverse_trig;
mod mediump_overflow;
mod normalize_zero;
mod pow_negative_base;
mod pow_zero_base;
mod smoothstep_edges;
mod smoothstep_reversed_constant;
mod unused_allow;

pub(crate) use context::{describe, fmt_num, operands, users, Cx, User};
pub(crate) use normalize_zero::orthogonal_cross;
pub use rule::Rule;

/// Every rule, in the order they run.
pub static RULES: &[&Rule] = &[
    &pow_negative_base::PowNegativeBase::RULE,
    &pow_zero_base::PowZeroBase::RULE,
    &acos_domain::AcosDomain::RULE,
    &asin_domain::AsinDomain::RULE,
    &smoothstep_edges::SmoothstepEdges::RULE,
    &smoothstep_reversed_constant::SmoothstepReversedConstant::RULE,
    &division_by_difference::DivisionByDifference::RULE,
    &normalize_zero::NormalizeZero::RULE,
    &mediump_overflow::MediumpOverflow::RULE,
    &unused_allow::UnusedAllow::RULE,
];

/// The id of the rule that reports suppressions silencing nothing.
pub(crate) const UNUSED_ALLOW: &str = "unused-essl-allow";

/// Whether any rule has something to look at in a shader: a `pow`, `acos`, `asin`,
/// `smoothstep` or `normalize` call, a division, or low-precision arithmetic of a kind
/// `mediump-overflow` looks at (the precisions are only looked up when the text names
/// `mediump`, `lowp` or `gl_PointCoord` and such arithmetic is there). Most conformance shaders
/// have none, and then the analysis, which is most of the cost of linting, is not run. Also
/// says whether something besides low-precision arithmetic is there (the rules that read signs
/// and ranges), and gives the precisions back when it looked them up.
pub(crate) fn candidates(
    shader: &essl::Shader,
    module: &naga::Module,
) -> (bool, bool, Option<crate::precision::Precisions>) {
    use naga::{BinaryOperator as Bo, Expression as E, MathFunction as Mf};
    let hard = module.functions.iter().any(|(_, f)| {
        f.expressions.iter().any(|(_, e)| {
            matches!(
                e,
                E::Math {
                    fun: Mf::Pow | Mf::Acos | Mf::Asin | Mf::SmoothStep | Mf::Normalize,
                    ..
                } | E::Binary { op: Bo::Divide, .. }
            )
        })
    });
    if hard {
        return (true, true, None);
    }
    // Without these words (or `gl_PointCoord`, mediump itself), every float is highp.
    let text = shader.file.text();
    if !["mediump", "lowp", "gl_PointCoord"]
        .iter()
        .any(|w| text.contains(w))
    {
        return (false, false, None);
    }
    // The precisions only where the low-precision rule has something to look at (every dEQP
    // fragment shader names `mediump` for its output).
    let looked_at: Vec<(&naga::Function, naga::Handle<naga::Expression>)> = module
        .functions
        .iter()
        .flat_map(|(_, f)| {
            f.expressions
                .iter()
                .filter(|(_, e)| mediump_overflow::looks_at(e))
                .map(move |(h, _)| (f, h))
        })
        .collect();
    if looked_at.is_empty() {
        return (false, false, None);
    }
    let prec = crate::precision::Precisions::of(&shader.module);
    let low = looked_at
        .iter()
        .any(|(f, h)| prec.is_low(essl::source::Span::from(f.expressions.get_span(*h))));
    (low, false, Some(prec))
}

/// The rule with this id.
pub fn rule(id: &str) -> Option<&'static Rule> {
    RULES.iter().copied().find(|r| r.id == id)
}
