//! `brach` in 3D (Brach 1989, with the cone circular).

use super::{assemble, newton_pn, straight};
use crate::law::{Breakdown, BreakdownReason, ImpactLaw, LawId, Options};
use crate::math::{norm_of, Vec2, Vec3};
use crate::spatial::{ContactProblem, LawDetail, Outcome, PhaseKind, Resolution};

/// `brach` in 3D: the impulse `p* = W⁻¹ (−v_t⁻, −(1+e) v_n⁻)` that leaves no tangential
/// velocity, used if its ratio `|p*_t|/p*_n ≤ μ`; otherwise the ratio is capped to the cone
/// along `p*_t`: `p_t = μ p_n p*_t/|p*_t|` with Newton's restitution.
///
/// Through [`ImpactLaw::resolve`] (or `LawId::Brach.resolve`) in the problem's canonical
/// units, scaled back ([`super::resolve`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Brach;

impl ImpactLaw for Brach {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Brach
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Brach, problem, &Options::default())
    }
}

/// [`Brach`] in the units of `problem` as given.
pub(super) fn in_units(problem: &ContactProblem) -> Resolution {
    let law = LawId::Brach;
    let v = problem.velocity();
    let mu = problem.friction();
    let target = Vec3::new(-v.x, -v.y, -(1.0 + problem.restitution()) * v.z);
    let star = problem
        .w()
        .cholesky()
        .map(|c| c.solve(&target))
        .ok_or(Breakdown {
            law,
            reason: BreakdownReason::NoSeparation,
        })?;
    let pt = star.xy();
    let sticking = star.z > 0.0;
    let ratio = if sticking {
        norm_of(pt) / star.z
    } else {
        f64::INFINITY
    };
    if sticking && ratio <= mu {
        let mut end = straight(problem, law, PhaseKind::Stick, pt / star.z, star.z);
        end.velocity.x = 0.0;
        end.velocity.y = 0.0;
        return Ok(assemble(
            problem,
            law,
            &end,
            LawDetail::Brach {
                ratio: Some(ratio),
                capped: false,
            },
            None,
        ));
    }
    let dir = if norm_of(pt) > 0.0 {
        pt / norm_of(pt)
    } else {
        Vec2::zeros()
    };
    let k = mu * dir;
    let pf = newton_pn(problem, law, k)?;
    let a = (-dir.y).atan2(-dir.x);
    let kind = if mu > 0.0 && norm_of(pt) > 0.0 {
        PhaseKind::Slip { from: a, to: a }
    } else if v.x != 0.0 || v.y != 0.0 {
        // Frictionless: label by the initial slip, as the planar law does.
        let a0 = v.y.atan2(v.x);
        PhaseKind::Slip { from: a0, to: a0 }
    } else {
        PhaseKind::NoSlip
    };
    let end = straight(problem, law, kind, k, pf);
    Ok(assemble(
        problem,
        law,
        &end,
        LawDetail::Brach {
            ratio: sticking.then_some(ratio),
            capped: true,
        },
        None,
    ))
}
