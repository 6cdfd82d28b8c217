//! The planar impact laws, one file each, all behind [`ImpactLaw`].
//!
//! | id | file | rule |
//! |---|---|---|
//! | `whittaker` | [`whittaker`] | `p_t = −μ s0 p_n`, Newton restitution |
//! | `two-phase` | [`two_phase`] | friction reversed once the slip halts |
//! | `smith` | [`smith`] | `p_t = −μ η p_n`, η from slip before/after |
//! | `brach` | [`brach`] | sticking ratio capped to the cone |
//! | `newton` | [`newton`] | Darboux–Keller, `v_n⁺ = −e v_n⁻` |
//! | `poisson` | [`poisson`] | Darboux–Keller, `p_f = (1+e) p_c` |
//! | `energetic` | [`energetic`] | Darboux–Keller, `W_r = −e² W_c` |

pub mod brach;
pub mod darboux_keller;
pub mod energetic;
pub mod newton;
pub mod poisson;
pub mod smith;
pub mod two_phase;
pub mod whittaker;

pub use crate::law::ImpactLaw;
pub use brach::Brach;
pub use energetic::Energetic;
pub use newton::Newton;
pub use poisson::Poisson;
pub use smith::Smith;
pub use two_phase::TwoPhase;
pub use whittaker::Whittaker;

use super::outcome::{Inconsistency, LawDetail, Outcome, Verdict, WorkSplit};
use super::path::ImpulsePath;
use super::ContactProblem;
use crate::law::LawId;

/// Relative tolerance, on the scale of [`ContactProblem::approach_energy`], above which a
/// rise of kinetic energy is reported as a gain (below it is round-off).
pub const ENERGY_GAIN_TOL: f64 = 1e-12;

/// Whether `energy_change` is a real gain for this problem (beyond round-off).
#[inline]
pub fn is_energy_gain(problem: &ContactProblem, energy_change: f64) -> bool {
    energy_change > ENERGY_GAIN_TOL * problem.approach_energy()
}

/// The normal impulse Newton's rule asks of a straight path with friction ratio `k`:
/// `p_n = −(1+e) v_n⁻ / (W_nn + k W_tn)`; `Err(denominator)` when it is not positive.
#[inline]
pub(crate) fn newton_normal_impulse(problem: &ContactProblem, ratio: f64) -> Result<f64, f64> {
    let den = problem.wnn() + ratio * problem.wtn();
    let pf = -(1.0 + problem.restitution()) * problem.velocity().y / den;
    if den > 0.0 && pf.is_finite() {
        Ok(pf)
    } else {
        Err(den)
    }
}

/// Assemble the common outcome record of a law whose impulse path ends at `pf`.
#[inline]
pub(crate) fn finish(
    problem: &ContactProblem,
    law: LawId,
    path: &ImpulsePath,
    pf: f64,
    detail: LawDetail,
    inconsistency: Option<Inconsistency>,
) -> Outcome {
    let impulse = path.impulse_at(pf);
    // From the path: exact zeros where the slip halted (equal to v⁻ + W p up to round-off).
    let velocity_after = path.velocity_at(pf);
    let compression_impulse = path.first_normal_velocity(0.0).filter(|&pc| pc <= pf);
    let compression = path.normal_work_to(compression_impulse.unwrap_or(pf));
    let work = WorkSplit {
        compression,
        restitution: path.normal_work_to(pf) - compression,
        friction: path.friction_work_to(pf),
    };
    let energy_change = problem.energy_change(impulse);
    let verdict = if is_energy_gain(problem, energy_change) {
        Verdict::EnergyGained
    } else if inconsistency.is_some() {
        Verdict::InconsistentAssumption
    } else {
        Verdict::Consistent
    };
    Outcome {
        law,
        impulse,
        velocity_after,
        compression_impulse,
        work,
        energy_change,
        phases: path.phases_to(pf),
        verdict,
        inconsistency,
        detail,
    }
}
