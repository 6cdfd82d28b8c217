//! `energetic`: Darboux–Keller integration ended by Stronge's energetic restitution.
//!
//! Termination (Stronge 1991, *Impact Mechanics* 2000; theory §2): the restitution work is
//! `e²` times the magnitude of the compression work,
//!
//! ```text
//! W_n(p_f) = (1 − e²) W_c,     W_c = ∫₀^{p_c} v_n dp_n < 0.
//! ```
//!
//! On the last segment the normal work is quadratic in `p_n`; its root is taken in the
//! cancellation-free form. Since `W_n ≤ 0` and friction work `W_t ≤ 0` under Coulomb's law,
//! `ΔT = W_n + W_t ≤ 0`: this law never gains energy.

use super::darboux_keller::DarbouxKellerPath;
use super::{assemble, checked, checked_brief, ImpactLaw};
use crate::law::LawId;
use crate::planar::{BriefResolution, ContactProblem, LawDetail, Resolution};

/// Energetic restitution on the exact Darboux–Keller path.
///
/// ```
/// use impax::planar::{ContactProblem, laws::{ImpactLaw, Energetic}};
/// let p = ContactProblem::from_entries(2.0, 0.5, 1.5, 0.3, -1.0, 0.3, 0.5).unwrap();
/// let out = Energetic.resolve(&p).unwrap();
/// assert!(out.energy_change < 0.0);
/// assert!((out.work.restitution + 0.25 * out.work.compression).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Energetic;

impl Energetic {
    /// The path and its end `p_f`: `W_n(p_f) − W_c = −e² W_c` past the end of compression
    /// `p_c` (the restitution work `e² |W_c|`).
    #[inline(always)]
    fn end(problem: &ContactProblem) -> (DarbouxKellerPath, f64) {
        let path = DarbouxKellerPath::new(problem);
        let pc = path.first_normal_velocity(0.0);
        let e = problem.restitution();
        let pf = path.restitution_work_reached(pc, -e * e * path.normal_work_to(pc));
        (path, pf)
    }
}

impl ImpactLaw for Energetic {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Energetic
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let (path, pf) = Self::end(problem);
            checked(assemble(
                problem,
                LawId::Energetic,
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
        super::in_units_brief(problem, LawId::Energetic, |problem| {
            let (path, pf) = Self::end(problem);
            checked_brief(path.brief(problem, pf), LawId::Energetic)
        })
    }
}
