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
//! | `lcp` | [`lcp`] | engines' velocity-level LCP: `v_n⁺ = −e v_n⁻`, friction against `v_t⁺` |

pub mod brach;
pub(crate) mod darboux_keller;
pub mod energetic;
pub mod lcp;
pub mod newton;
pub mod poisson;
pub mod smith;
pub mod two_phase;
pub mod whittaker;

pub use crate::law::ImpactLaw;
pub use brach::Brach;
pub use energetic::Energetic;
pub use lcp::Lcp;
pub use newton::Newton;
pub use poisson::Poisson;
pub use smith::Smith;
pub use two_phase::TwoPhase;
pub use whittaker::Whittaker;

use super::outcome::{BriefResolution, LawDetail, Outcome, OutcomeBrief, PhaseKind, Resolution};
use super::path::{line_summary, ImpulsePath, PathSummary};
use super::ContactProblem;
use crate::law::LawId;
use crate::law::{Breakdown, BreakdownReason, Inconsistency, Verdict, WorkSplit};
use crate::math::Vec2;

pub use crate::law::energy::ENERGY_GAIN_ROUND_OFF;

impl crate::law::Problem for ContactProblem {
    type Resolution = Resolution;

    /// The planar laws are exact: `options` changes nothing.
    #[inline]
    fn resolve_by(&self, law: LawId, _options: &crate::law::Options) -> Resolution {
        let problem = self;
        match law {
            LawId::Whittaker => Whittaker.resolve(problem),
            LawId::TwoPhase => TwoPhase.resolve(problem),
            LawId::Smith => Smith::SLIP.resolve(problem),
            LawId::SmithCentre => Err(Breakdown {
                law,
                reason: BreakdownReason::NeedsBody,
            }),
            LawId::Brach => Brach.resolve(problem),
            LawId::Newton => Newton.resolve(problem),
            LawId::Poisson => Poisson.resolve(problem),
            LawId::Energetic => Energetic.resolve(problem),
            LawId::Lcp => Lcp.resolve(problem),
            LawId::Sequential => crate::multi::sequential::OneContact.resolve(problem),
            LawId::Lzb => crate::multi::lzb::OneContact.resolve(problem),
        }
    }
}

/// Whether `energy_change = ΔT` of the impulse `p` (taking `v⁻` to `v⁺`) is a real gain: it
/// exceeds the round-off of its own evaluation.
///
/// `ΔT = ½ (v⁻ + v⁺)·p` is formed from `v⁺ = v⁻ + W p`, whose components carry round-off
/// of order `ε (|v⁻| + |W| |p|)`; the bound is therefore relative to the problem's own energy
/// scale, the size of the terms of `ΔT`,
///
/// ```text
/// ΔT > 16 ε Σ_i (|v⁻_i| + |v⁺_i| + (|W| |p|)_i) |p_i|,
/// ```
///
/// and does not depend on the units (masses, speeds) of the problem: a gain of `10⁻¹³` of
/// the approach energy is a gain, however large the mass. `tests/regression_energy_gain_*`
/// hold the cases that set it: an elastic stick with an ill-conditioned `W` (exactly
/// `ΔT = 0`, round-off up to `10⁻¹⁶ |p|² |W|`) and small true gains of Whittaker's rule.
#[inline]
pub fn is_energy_gain(
    problem: &ContactProblem,
    energy_change: f64,
    p: Vec2,
    v_after: Vec2,
) -> bool {
    if energy_change <= 0.0 {
        return false;
    }
    let v = problem.velocity();
    let (a, b, c) = (problem.wtt(), problem.wtn().abs(), problem.wnn());
    let (pt, pn) = (p.x.abs(), p.y.abs());
    let scale = (v.x.abs() + v_after.x.abs() + a * pt + b * pn) * pt
        + (v.y.abs() + v_after.y.abs() + b * pt + c * pn) * pn;
    energy_change > ENERGY_GAIN_ROUND_OFF * scale
}

/// Resolve `problem` with `law`, in units where its normal velocity and `W_nn` are near one
/// when they are not ([`ContactProblem::in_units`]), and the result scaled back: every law is
/// invariant under scaling of the velocity and of `W` (masses) wherever its numbers are
/// representable (e.g. `energetic` keeps its restitution at `v_n⁻ = −1e-300`, where the
/// compression work `∝ v_n²` underflows). `law` receives the factors of velocity and `W`
/// (for a reference velocity of its own, as `smith-centre`'s).
#[inline(always)]
pub(crate) fn in_units(
    problem: &ContactProblem,
    law: impl Fn(&ContactProblem, f64, f64) -> Resolution,
) -> Resolution {
    match problem.in_units() {
        None => law(problem, 1.0, 1.0),
        // Back in the problem's units a number may overflow (e.g. friction work ∝ W_tt p_t²
        // with W_nn = 1e-231): that is the breakdown `overflow`, as for any law.
        Some((scaled, u)) => match law(&scaled, u.a, u.b) {
            Ok(o) => checked(o.in_problem_units(u)),
            Err(b) => Err(b.in_problem_units(u)),
        },
    }
}

/// [`in_units`] for the brief of an outcome of the law `id`.
#[inline(always)]
pub(crate) fn in_units_brief(
    problem: &ContactProblem,
    id: LawId,
    law: impl Fn(&ContactProblem) -> BriefResolution,
) -> BriefResolution {
    match problem.in_units() {
        None => law(problem),
        Some((scaled, u)) => match law(&scaled) {
            Ok(o) => checked_brief(o.in_problem_units(u), id),
            Err(b) => Err(b.in_problem_units(u)),
        },
    }
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

/// The outcome as the law's result, or the breakdown [`BreakdownReason::Overflow`] if one of
/// its numbers is not finite (e.g. `whittaker` with `μ = 1e200`: `ΔT ≈ ½ W_tt (μ p_n)²`
/// overflows) — never infinities reported as numbers.
#[inline]
pub(crate) fn checked(out: Outcome) -> Resolution {
    if out.is_finite() {
        Ok(out)
    } else {
        Err(Breakdown {
            law: out.law,
            reason: BreakdownReason::Overflow,
        })
    }
}

/// As [`checked`] for the brief of an outcome (only `ΔT` is a number there).
#[inline]
pub(crate) fn checked_brief(brief: OutcomeBrief, law: LawId) -> BriefResolution {
    if brief.energy_change.is_finite() {
        Ok(brief)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
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
    assemble(problem, law, path.summarize(pf), detail, inconsistency)
}

/// As [`finish`] for a straight path `p = p_n (ratio, 1)` (the algebraic laws).
#[inline]
pub(crate) fn finish_line(
    problem: &ContactProblem,
    law: LawId,
    kind: PhaseKind,
    ratio: f64,
    pf: f64,
    detail: LawDetail,
    inconsistency: Option<Inconsistency>,
) -> Outcome {
    assemble(
        problem,
        law,
        line_summary(problem, kind, ratio, pf),
        detail,
        inconsistency,
    )
}

/// `ΔT` and the verdict of the impulse `p` that ends at the contact velocity `v⁺` (from the
/// law's path): `ΔT = ½ (v⁻ + v⁺)·p`, then [`Verdict::EnergyGained`] if
/// [`is_energy_gain`], else [`Verdict::InconsistentAssumption`] if the law's assumption is
/// contradicted, else [`Verdict::Consistent`]. Shared by the outcome record and its brief.
#[inline(always)]
pub(crate) fn energy_and_verdict(
    problem: &ContactProblem,
    impulse: Vec2,
    velocity_after: Vec2,
    inconsistent: bool,
) -> (f64, Verdict) {
    // ΔT = ½ (v⁻ + v⁺)·p with v⁺ from the path (exact zeros at a halt): better conditioned
    // than v⁻·p + ½ pᵀ W p, to which it is identical.
    let energy_change = 0.5 * (problem.velocity() + velocity_after).dot(&impulse);
    let verdict = if is_energy_gain(problem, energy_change, impulse, velocity_after) {
        Verdict::EnergyGained
    } else if inconsistent {
        Verdict::InconsistentAssumption
    } else {
        Verdict::Consistent
    };
    (energy_change, verdict)
}

#[inline]
pub(crate) fn assemble(
    problem: &ContactProblem,
    law: LawId,
    sum: PathSummary,
    detail: LawDetail,
    inconsistency: Option<Inconsistency>,
) -> Outcome {
    let impulse = sum.impulse;
    let work = WorkSplit {
        compression: sum.compression_work,
        restitution: sum.normal_work - sum.compression_work,
        friction: sum.friction_work,
    };
    let (energy_change, verdict) =
        energy_and_verdict(problem, impulse, sum.velocity, inconsistency.is_some());
    Outcome {
        law,
        impulse,
        // From the path: exact zeros where the slip halted (equal to v⁻ + W p up to round-off).
        velocity_after: sum.velocity,
        compression_impulse: sum.compression_impulse,
        work,
        energy_change,
        phases: sum.phases,
        verdict,
        inconsistency,
        detail,
    }
}
