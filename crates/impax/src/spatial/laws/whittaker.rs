//! `whittaker` in 3D (paper A eq. 7 and Kane & Levinson 1985, with the slip a 2-vector).

use super::{assemble, newton_pn, straight};
use crate::law::{ImpactLaw, Inconsistency, LawId, Options};
use crate::math::{norm_of, Vec2};
use crate::spatial::{ContactProblem, LawDetail, Outcome, PhaseKind, Resolution};

/// `whittaker` in 3D: Coulomb friction on the total impulse, along the initial slip
/// direction `ŝ0`: `p = p_n (−μ ŝ0, 1)`, `p_n = −(1+e) v_n⁻ / (w_nn − μ w_tn·ŝ0)`.
///
/// Through [`ImpactLaw::resolve`] (or `LawId::Whittaker.resolve`) in the problem's canonical
/// units, scaled back ([`super::resolve`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Whittaker;

impl ImpactLaw for Whittaker {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Whittaker
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Whittaker, problem, &Options::default())
    }
}

/// [`Whittaker`] in the units of `problem` as given.
pub(super) fn in_units(problem: &ContactProblem) -> Resolution {
    let law = LawId::Whittaker;
    let vt = problem.velocity().xy();
    let sigma = norm_of(vt);
    let (s0, kind) = if sigma > 0.0 {
        let s = vt / sigma;
        let a = s.y.atan2(s.x);
        (s, PhaseKind::Slip { from: a, to: a })
    } else {
        (Vec2::zeros(), PhaseKind::NoSlip)
    };
    let k = -problem.friction() * s0;
    let pf = newton_pn(problem, law, k)?;
    let end = straight(problem, law, kind, k, pf);
    let slip_after = end.velocity.xy().dot(&s0);
    let inconsistency = (sigma > 0.0 && problem.friction() > 0.0 && slip_after < 0.0)
        .then_some(Inconsistency::SlipReversed { slip_after });
    Ok(assemble(problem, law, &end, LawDetail::None, inconsistency))
}
