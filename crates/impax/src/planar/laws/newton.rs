//! `newton`: Darboux–Keller integration ended by kinematic restitution.
//!
//! Termination (theory §2): the first `p_f` after compression with `v_n(p_f) = −e v_n⁻`
//! (Newton 1686). With slip reversal during restitution this rule can raise the kinetic
//! energy (Stronge 1991); the outcome then says [`Verdict::EnergyGained`](crate::planar::Verdict).

use super::darboux_keller::DarbouxKellerPath;
use super::{assemble, checked, checked_brief, ImpactLaw};
use crate::law::LawId;
use crate::planar::{BriefResolution, ContactProblem, LawDetail, Resolution};

/// Kinematic restitution on the exact Darboux–Keller path.
///
/// ```
/// use impax::planar::{ContactProblem, laws::{ImpactLaw, Newton}};
/// let a = 30f64.to_radians();
/// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
/// let out = Newton.resolve(&p).unwrap();
/// assert!((out.velocity_after.y - 0.7 * a.cos()).abs() < 1e-15);
/// assert_eq!(out.velocity_after.x, 0.0); // the slip halts and the sphere rolls
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Newton;

impl Newton {
    /// The path and its end: the first `p_f` with `v_n(p_f) = −e v_n⁻`.
    #[inline(always)]
    fn end(problem: &ContactProblem) -> (DarbouxKellerPath, f64) {
        let path = DarbouxKellerPath::new(problem);
        let pf = path.first_normal_velocity(-problem.restitution() * problem.velocity().y);
        (path, pf)
    }
}

impl ImpactLaw for Newton {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Newton
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let (path, pf) = Self::end(problem);
            checked(assemble(
                problem,
                LawId::Newton,
                path.summarize(pf),
                LawDetail::DarbouxKeller {
                    slip_halt: path.slip_halt().filter(|&ps| ps < pf),
                },
                None,
            ))
        })
    }

    #[inline]
    fn resolve_brief(&self, problem: &ContactProblem) -> BriefResolution {
        super::in_units_brief(problem, LawId::Newton, |problem| {
            let (path, pf) = Self::end(problem);
            checked_brief(path.brief(problem, pf), LawId::Newton)
        })
    }
}
