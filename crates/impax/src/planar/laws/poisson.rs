//! `poisson`: Darboux–Keller integration ended by kinetic restitution.
//!
//! Termination (Poisson 1817; theory §2): `p_f = (1 + e) p_c`, the restitution impulse is `e`
//! times the compression impulse.

use super::darboux_keller::DarbouxKellerPath;
use super::{assemble, checked, checked_brief, ImpactLaw};
use crate::law::LawId;
use crate::planar::{BriefResolution, ContactProblem, LawDetail, Resolution};

/// Kinetic restitution on the exact Darboux–Keller path.
///
/// ```
/// use impax::planar::{ContactProblem, laws::{ImpactLaw, Poisson}};
/// let p = ContactProblem::from_entries(2.0, 0.5, 1.5, 0.3, -1.0, 0.3, 0.5).unwrap();
/// let out = Poisson.resolve(&p).unwrap();
/// let pc = out.compression_impulse.unwrap();
/// assert!((out.impulse.y - 1.5 * pc).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Poisson;

impl Poisson {
    /// The path and its end `p_f = (1 + e) p_c`.
    #[inline(always)]
    fn end(problem: &ContactProblem) -> (DarbouxKellerPath, f64) {
        let path = DarbouxKellerPath::new(problem);
        let pf = (1.0 + problem.restitution()) * path.first_normal_velocity(0.0);
        (path, pf)
    }
}

impl ImpactLaw for Poisson {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Poisson
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let (path, pf) = Self::end(problem);
            checked(assemble(
                problem,
                LawId::Poisson,
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
        super::in_units_brief(problem, LawId::Poisson, |problem| {
            let (path, pf) = Self::end(problem);
            checked_brief(path.brief(problem, pf), LawId::Poisson)
        })
    }
}
