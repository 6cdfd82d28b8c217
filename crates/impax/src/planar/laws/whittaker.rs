//! `whittaker`: Coulomb friction on the total impulses (Whittaker 1904, Routh 1905).
//!
//! Paper A eq. 7, Kane & Levinson 1985 (theory §3):
//!
//! ```text
//! p = p_n (−μ s0, 1),   s0 = sign(v_t⁻),
//! p_n = −(1+e) v_n⁻ / (W_nn − μ s0 W_tn)          (Newton restitution on the total)
//! ```
//!
//! If the denominator is not positive the rule demands a negative normal impulse: a
//! [`BreakdownReason::NegativeNormalImpulse`]. The rule ignores any halt or reversal of the
//! slip during the impact; when the slip has reversed by the end, the outcome carries
//! [`Inconsistency::SlipReversed`], and the energy may rise (Kane's paradox).

use super::{checked, finish_line, newton_normal_impulse, ImpactLaw};
use crate::law::LawId;
use crate::planar::{
    Breakdown, BreakdownReason, ContactProblem, Inconsistency, LawDetail, PhaseKind, Resolution,
    SlipDirection,
};

/// Whittaker's rule. See the [module docs](self).
///
/// ```
/// use impax::planar::{ContactProblem, laws::{ImpactLaw, Whittaker}};
/// let a = 30f64.to_radians();
/// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
/// let out = Whittaker.resolve(&p).unwrap();
/// // Paper A eq. 13 at γ = 0: ΔT/T0 = 2ΔT (m = v0 = 1) ≈ 0.2424 > 0.
/// assert!((2.0 * out.energy_change - 0.242403).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Whittaker;

impl ImpactLaw for Whittaker {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Whittaker
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let dir = SlipDirection::of(problem.velocity().x);
            let ratio = -problem.friction() * dir.sign();
            let pf = newton_normal_impulse(problem, ratio).map_err(|denominator| Breakdown {
                law: LawId::Whittaker,
                reason: BreakdownReason::NegativeNormalImpulse { denominator },
            })?;
            let v = problem.velocity();
            let slip_after = v.x + (problem.wtt() * ratio + problem.wtn()) * pf;
            let inconsistency = (dir != SlipDirection::None
                && problem.friction() > 0.0
                && slip_after * dir.sign() < 0.0)
                .then_some(Inconsistency::SlipReversed { slip_after });
            checked(finish_line(
                problem,
                LawId::Whittaker,
                PhaseKind::Slip(dir),
                ratio,
                pf,
                LawDetail::None,
                inconsistency,
            ))
        })
    }
}
