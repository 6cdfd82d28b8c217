//! `two-phase`: Whittaker's rule applied piecewise, friction reversed once the slip halts.
//!
//! Paper A §3 (eqs. 16–23), the scheme it attributes to Keller 1986: the slip halts at the
//! normal impulse `p'` found with Whittaker's slope (eq. 21 for the sphere),
//!
//! ```text
//! p' = −v_t⁻ / (W_tt k1 + W_tn),   k1 = −μ s0,
//! ```
//!
//! after which the friction ratio is *assumed* to be `k2 = +μ s0` (a reversal). Newton's
//! restitution on the total then gives (eqs. 17, 22)
//!
//! ```text
//! p_t = μ s0 (P − 2p'),   P = (−(1+e) v_n⁻ + 2 μ s0 W_tn p') / (W_nn + μ s0 W_tn).
//! ```
//!
//! If Whittaker's own impulse ends before `p'`, the slip never halts and the scheme is
//! Whittaker's rule. The assumption is checked afterwards: if the final slip keeps the
//! initial direction the outcome carries [`Inconsistency::ReversalDidNotHappen`] (paper A
//! finds `v_Px⁺ > 0` for the seed's sphere).
//!
//! For a body with `W_tn = 0` (the sphere) the reversed impulse is the mirror image of
//! Whittaker's about the sticking impulse `p_t = −v_t⁻/W_tt`, so the two rules give the
//! *same* `ΔT`.

use super::{checked, finish, finish_line, newton_normal_impulse, ImpactLaw};
use crate::law::LawId;
use crate::planar::path::ImpulsePath;
use crate::planar::{
    Breakdown, BreakdownReason, ContactProblem, Inconsistency, LawDetail, PhaseKind, Resolution,
    SlipDirection,
};

/// The two-phase scheme of paper A §3. See the [module docs](self).
#[derive(Debug, Clone, Copy, Default)]
pub struct TwoPhase;

impl ImpactLaw for TwoPhase {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::TwoPhase
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let law = LawId::TwoPhase;
            let (a, b) = (problem.wtt(), problem.wtn());
            let mu = problem.friction();
            let v = problem.velocity();
            let dir = SlipDirection::of(v.x);
            let s0 = dir.sign();
            let k1 = -mu * s0;
            let dvt = a * k1 + b;
            let switch = -v.x / dvt;
            let halts =
                dir != SlipDirection::None && mu > 0.0 && switch.is_finite() && switch > 0.0;
            let whittaker = newton_normal_impulse(problem, k1);
            if !halts || matches!(whittaker, Ok(pw) if pw <= switch) {
                // The slip does not halt before Whittaker's impulse ends: one phase.
                let pf = whittaker.map_err(|denominator| Breakdown {
                    law,
                    reason: BreakdownReason::NegativeNormalImpulse { denominator },
                })?;
                return checked(finish_line(
                    problem,
                    law,
                    PhaseKind::Slip(dir),
                    k1,
                    pf,
                    LawDetail::TwoPhase {
                        switch_impulse: None,
                    },
                    None,
                ));
            }
            let den = problem.wnn() + mu * s0 * b;
            let total = (-(1.0 + problem.restitution()) * v.y + 2.0 * mu * s0 * b * switch) / den;
            if den.is_nan() || den <= 0.0 || !total.is_finite() {
                return Err(Breakdown {
                    law,
                    reason: BreakdownReason::NegativeNormalImpulse { denominator: den },
                });
            }
            if total < switch {
                return Err(Breakdown {
                    law,
                    reason: BreakdownReason::NoConsistentSplit {
                        switch_impulse: switch,
                        total_impulse: total,
                    },
                });
            }
            let reversed = if s0 > 0.0 {
                SlipDirection::Negative
            } else {
                SlipDirection::Positive
            };
            let mut path = ImpulsePath::new(problem);
            path.push(PhaseKind::Slip(dir), k1, switch);
            path.push_from_rest(PhaseKind::Slip(reversed), -k1, f64::INFINITY);
            let slip_after = path.velocity_at(total).x;
            let inconsistency = (slip_after * s0 > 0.0)
                .then_some(Inconsistency::ReversalDidNotHappen { slip_after });
            checked(finish(
                problem,
                law,
                &path,
                total,
                LawDetail::TwoPhase {
                    switch_impulse: Some(switch),
                },
                inconsistency,
            ))
        })
    }
}
