//! The rules, one module per rule (named for its id, the rule's page the doc comment of its
//! type), and the list they run in. What the rules share is in [`context`] (the analysed
//! shader), [`guards`] (what the conditions around an expression say) and [`rule`] (what a
//! rule is).

mod clip_space;
mod context;
mod derivatives;
mod domain;
mod flat;
mod gradient;
mod guards;
mod lowp_range;
pub(crate) mod origin;
mod parameters;
mod residual;
pub(crate) mod rule;
mod settings;
mod unlit;
mod vanishing;

mod acos_domain;
mod asin_domain;
mod clamp_bounds;
mod division_by_difference;
mod domain_atan2;
mod domain_integer_division;
mod domain_inversesqrt;
mod domain_log;
mod domain_sqrt;
mod inverse_trig;
mod mediump_overflow;
mod mediump_time;
mod non_uniform_derivative;
mod normalize_zero;
mod pow_negative_base;
mod pow_zero_base;
mod smoothstep_edges;
mod smoothstep_reversed_constant;
mod texel_fetch_range;
mod uninitialised_read;
mod unused_allow;

pub(crate) use context::{computed_from, describe, fmt_num, operands, users, Cx, User};
pub(crate) use division_by_difference::ZERO_DIVISOR;
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
    &clamp_bounds::ClampBounds::RULE,
    &division_by_difference::DivisionByDifference::RULE,
    &normalize_zero::NormalizeZero::RULE,
    &domain_sqrt::DomainSqrt::RULE,
    &domain_inversesqrt::DomainInversesqrt::RULE,
    &domain_log::DomainLog::RULE,
    &domain_atan2::DomainAtan2::RULE,
    &domain_integer_division::DomainIntegerDivision::RULE,
    &mediump_overflow::MediumpOverflow::RULE,
    &mediump_time::MediumpTime::RULE,
    &texel_fetch_range::TexelFetchRange::RULE,
    &uninitialised_read::UninitialisedRead::RULE,
    &non_uniform_derivative::NonUniformDerivative::RULE,
    &unused_allow::UnusedAllow::RULE,
];

/// The rules that read the checked module (HIR) only: they run on every shader, whether or not
/// the value analysis has anything to look at.
pub(crate) const HIR_RULES: &[&str] = &[
    "uninitialised-read",
    "non-uniform-derivative",
    "mediump-time",
];

/// The id of the rule that reports suppressions silencing nothing.
pub(crate) const UNUSED_ALLOW: &str = "unused-essl-allow";

/// Whether any rule has something to look at in a shader: a `pow`, `acos`, `asin`,
/// `smoothstep` or `normalize` call, a division, a `clamp` of a constant or with reversed
/// constant bounds, or low-precision arithmetic of a kind
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
        f.expressions.iter().any(|(_, e)| match e {
            E::Math {
                fun:
                    Mf::Pow
                    | Mf::Acos
                    | Mf::Asin
                    | Mf::SmoothStep
                    | Mf::Normalize
                    | Mf::Sqrt
                    | Mf::InverseSqrt
                    | Mf::Log
                    | Mf::Log2
                    | Mf::Atan2,
                ..
            }
            | E::Binary {
                op: Bo::Divide | Bo::Modulo,
                ..
            }
            | E::ImageLoad { .. } => true,
            E::Math { fun: Mf::Clamp, .. } => clamp_bounds::suspect(module, f, e),
            _ => false,
        })
    });
    if hard {
        return (true, true, None);
    }
    if !crate::precision::names_low_precision(shader.file.text()) {
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
