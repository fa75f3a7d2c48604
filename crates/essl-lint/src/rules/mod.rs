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
];

/// The rule with this id.
pub fn rule(id: &str) -> Option<&'static Rule> {
    RULES.iter().copied().find(|r| r.id == id)
}
