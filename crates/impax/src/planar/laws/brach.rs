//! `brach`: Brach's 1989 impulse-ratio law.
//!
//! Newton restitution on the normal velocity; the friction ratio is the one of the impulse
//! that leaves no tangential velocity (theory §3),
//!
//! ```text
//! W p* = (−v_t⁻, −(1+e) v_n⁻),   μ0 = p*_t / p*_n,
//! ```
//!
//! used as it is if `|μ0| ≤ μ`, otherwise capped to `μ sign(μ0)` with
//! `p_n = −(1+e) v_n⁻ / (W_nn + μ sign(μ0) W_tn)`. When `p*_n ≤ 0` no compressive impulse
//! stops the slip; the ratio is taken as beyond the cone, `μ sign(p*_t)` (with `μ = 0`:
//! frictionless Newton restitution, as every law gives without friction).

use super::{checked, finish_line, newton_normal_impulse, ImpactLaw};
use crate::law::LawId;
use crate::math::sign;
use crate::planar::{
    Breakdown, BreakdownReason, ContactProblem, LawDetail, PhaseKind, Resolution, SlipDirection,
};

/// Brach's law. See the [module docs](self).
#[derive(Debug, Clone, Copy, Default)]
pub struct Brach;

impl ImpactLaw for Brach {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Brach
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let law = LawId::Brach;
            let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
            let v = problem.velocity();
            let mu = problem.friction();
            let target_n = -(1.0 + problem.restitution()) * v.y;
            let det = a * c - b * b;
            // p* = W⁻¹ (−v_t, target_n)
            let pt_star = (c * -v.x - b * target_n) / det;
            let pn_star = (-b * -v.x + a * target_n) / det;
            // With p*_n ≤ 0 no compressive impulse can stop the slip: the ratio is beyond any
            // cone, in the direction of p*_t.
            let sticking = pn_star > 0.0;
            let ratio = if sticking {
                pt_star / pn_star
            } else {
                f64::INFINITY * sign(pt_star)
            };
            if sticking && ratio.abs() <= mu {
                let mut out = finish_line(
                    problem,
                    law,
                    PhaseKind::Stick,
                    ratio,
                    pn_star,
                    LawDetail::Brach {
                        ratio: Some(ratio),
                        capped: false,
                    },
                    None,
                );
                // p* is defined by v_t⁺ = 0: keep that exact rather than its round-off.
                out.velocity_after.x = 0.0;
                return checked(out);
            }
            let k = mu * sign(ratio);
            let pf = newton_normal_impulse(problem, k).map_err(|denominator| Breakdown {
                law,
                reason: BreakdownReason::NegativeNormalImpulse { denominator },
            })?;
            // Friction along −ŝ means slip along −sign(k) (frictionless: the initial slip).
            let dir = if k != 0.0 {
                SlipDirection::of(-k)
            } else {
                SlipDirection::of(v.x)
            };
            checked(finish_line(
                problem,
                law,
                PhaseKind::Slip(dir),
                k,
                pf,
                LawDetail::Brach {
                    ratio: sticking.then_some(ratio),
                    capped: true,
                },
                None,
            ))
        })
    }
}
