//! The spatial laws, one file each as in the plane: `whittaker` and `brach` in closed form,
//! `newton`, `poisson` and `energetic` by the Darboux–Keller integration
//! ([`super::darboux_keller`]), `lcp` with the circular cone; [`resolve`] dispatches by id.

pub mod brach;
pub mod energetic;
pub mod lcp;
pub mod newton;
pub mod poisson;
pub mod whittaker;

pub use crate::law::ImpactLaw;
pub use brach::Brach;
pub use energetic::Energetic;
pub use lcp::Lcp;
pub use newton::Newton;
pub use poisson::Poisson;
pub use whittaker::Whittaker;

use super::darboux_keller::{integrate_with, PathEnd, Termination};
use super::outcome::{LawDetail, Outcome, PhaseKind, Phases, Resolution};
use super::ContactProblem;
use crate::law::energy::ENERGY_GAIN_ROUND_OFF;
use crate::law::{Breakdown, BreakdownReason, Inconsistency, LawId, Options, Verdict, WorkSplit};
use crate::math::{Vec2, Vec3};

/// Whether `ΔT` is a real gain: it exceeds the round-off of its evaluation
/// `½ (v⁻ + v⁺)·p`, `16 ε Σ_i (|v⁻_i| + |v⁺_i| + (|W| |p|)_i) |p_i|` (the problem's own
/// energy scale; as [`crate::planar::laws::is_energy_gain`]).
pub fn is_energy_gain(
    problem: &ContactProblem,
    energy_change: f64,
    p: Vec3,
    v_after: Vec3,
) -> bool {
    if energy_change <= 0.0 {
        return false;
    }
    let v = problem.velocity();
    let pa = p.abs();
    let scale = (v.abs() + v_after.abs() + problem.w().abs() * pa).dot(&pa);
    energy_change > ENERGY_GAIN_ROUND_OFF * scale
}

pub(crate) fn assemble(
    problem: &ContactProblem,
    law: LawId,
    end: &PathEnd,
    detail: LawDetail,
    inconsistency: Option<Inconsistency>,
) -> Outcome {
    let energy_change = 0.5 * (problem.velocity() + end.velocity).dot(&end.impulse);
    // The integrated laws reach their end to the integration's tolerance, not to round-off:
    // ΔT and the work split W_n + W_t are two evaluations of the same quantity, and a gain
    // must exceed their disagreement too (an elastic frictionless impact, exactly ΔT = 0,
    // came out at ΔT = +2.6e-14 of an energy of 0.33 against works summing to 9e-16).
    let works = end.normal_work + end.friction_work;
    let established = energy_change - 2.0 * (energy_change - works).abs();
    let verdict = if is_energy_gain(problem, established, end.impulse, end.velocity) {
        Verdict::EnergyGained
    } else if inconsistency.is_some() {
        Verdict::InconsistentAssumption
    } else {
        Verdict::Consistent
    };
    Outcome {
        law,
        impulse: end.impulse,
        velocity_after: end.velocity,
        compression_impulse: end.compression_impulse,
        work: WorkSplit {
            compression: end.compression_work,
            restitution: end.normal_work - end.compression_work,
            friction: end.friction_work,
        },
        energy_change,
        phases: end.phases,
        verdict,
        inconsistency,
        detail,
    }
}

/// The closed-form record of a straight path `p = p_n (k, 1)` (`k` a 2-vector).
pub(crate) fn straight(
    problem: &ContactProblem,
    law: LawId,
    kind: PhaseKind,
    k: Vec2,
    pf: f64,
) -> PathEnd {
    let w = problem.w();
    let v = problem.velocity();
    let slope = w * Vec3::new(k.x, k.y, 1.0);
    // Every straight law ends by Newton's rule, v_n(p_f) = −e v_n⁻ ≥ 0, and v_n is linear in
    // p_n: its slope is (1+e)|v_n⁻|/p_f, compression ends at p_c = p_f/(1+e) (at p_f when
    // e = 0), and the normal works are W_c = ½ v_n⁻ p_c and W_n = ½ (1 − e) v_n⁻ p_f — no
    // use of the slope w_nn + w_tn·k, a small difference of large terms for a grazing
    // impact on a strongly coupled W (6 % off in the example of
    // `tests/regression_spatial_lcp_grazing.rs`).
    let e = problem.restitution();
    let (pc, wc, normal_work) = if pf > 0.0 {
        let pc = pf / (1.0 + e);
        (Some(pc), 0.5 * v.z * pc, 0.5 * (1.0 - e) * v.z * pf)
    } else {
        (None, 0.0, 0.0)
    };
    let friction_work = pf * (k.x * (v.x + 0.5 * slope.x * pf) + k.y * (v.y + 0.5 * slope.y * pf));
    let mut phases = Phases::new();
    phases.push(kind, pf);
    let _ = law;
    PathEnd {
        impulse: Vec3::new(k.x * pf, k.y * pf, pf),
        velocity: v + slope * pf,
        compression_impulse: pc,
        compression_work: wc,
        normal_work,
        friction_work,
        phases,
        slip_halt: None,
        second_compression: None,
        steps: 0,
    }
}

/// `p_n = −(1+e) v_n⁻ / (w_nn + w_tn·k)` for a straight path with ratio `k`.
pub(crate) fn newton_pn(problem: &ContactProblem, law: LawId, k: Vec2) -> Result<f64, Breakdown> {
    let den = problem.wnn() + problem.wtn().dot(&k);
    let pf = -(1.0 + problem.restitution()) * problem.velocity().z / den;
    if den > 0.0 && pf.is_finite() {
        Ok(pf)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::NegativeNormalImpulse { denominator: den },
        })
    }
}

/// The Darboux–Keller laws with an observer called at every accepted point `(p_n, v)` (for
/// hodographs), told whether it does anything.
pub(crate) fn darboux_keller(
    problem: &ContactProblem,
    law: LawId,
    opts: &Options,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Resolution {
    let term = match law {
        LawId::Newton => Termination::Newton,
        LawId::Poisson => Termination::Poisson,
        LawId::Energetic => Termination::Energetic,
        _ => {
            return Err(Breakdown {
                law,
                reason: BreakdownReason::PlanarOnly,
            })
        }
    };
    let end = integrate_with(problem, term, opts, observing, observe)
        .map_err(|reason| Breakdown { law, reason })?;
    let detail = LawDetail::DarbouxKeller {
        slip_halt: end.slip_halt,
        second_compression: end.second_compression,
        steps: end.steps,
    };
    Ok(assemble(
        problem,
        law,
        &end,
        detail,
        still_approaching(problem, &end),
    ))
}

/// [`Inconsistency::StillApproaching`] if the impact ends with `v_n⁺` below zero by more
/// than the round-off of `v_n⁻ + (W p)_n`, `16 ε (|v_n⁻| + (|W| |p|)_n)`.
pub(crate) fn still_approaching(problem: &ContactProblem, end: &PathEnd) -> Option<Inconsistency> {
    let vn = end.velocity.z;
    let round_off = 16.0
        * f64::EPSILON
        * (problem.velocity().z.abs() + (problem.w().abs() * end.impulse.abs()).z);
    (vn < -round_off).then_some(Inconsistency::StillApproaching {
        normal_velocity: vn,
    })
}

/// Resolve a spatial problem with a law and the options `opts` (the tolerance of the
/// Darboux–Keller integration; the other laws ignore them). `two-phase`, `smith` and
/// `smith-centre` are planar only and break down with [`BreakdownReason::PlanarOnly`].
///
/// Every law is resolved in the problem's canonical units (`|v_n⁻|` and `w_nn` in `[1, 2)`,
/// powers of two: exact) and the result scaled back: invariant under scaling of the
/// velocities and of `W` (bit for bit for powers of two) wherever its numbers are
/// representable.
///
/// `sequential` (the binary-impact rule of several contacts, [`crate::multi::sequential`])
/// and `lzb` (the multiple-impact law of Liu, Zhao & Brogliato, [`crate::multi::lzb`]) with
/// one contact are `energetic`, its outcome or breakdown labelled `sequential` or `lzb`.
pub fn resolve(law: LawId, problem: &ContactProblem, opts: &Options) -> Resolution {
    if matches!(law, LawId::Sequential | LawId::Lzb) {
        return match resolve(LawId::Energetic, problem, opts) {
            Ok(o) => Ok(Outcome { law, ..o }),
            Err(b) => Err(Breakdown { law, ..b }),
        };
    }
    // (The Darboux–Keller integration chooses its own units, the same way, and scales its
    // path back to the problem's: its works need not be representable in the units of a
    // grazing impact's normal velocity.)
    let canonical = if law.is_darboux_keller() {
        None
    } else {
        problem.canonical_units()
    };
    let out = match canonical {
        None => resolve_in_units(law, problem, opts),
        Some((scaled, u)) => resolve_in_units(law, &scaled, opts)
            .map(|o| o.in_problem_units(u))
            .map_err(|b| b.in_problem_units(u)),
    }?;
    if out.is_finite() {
        Ok(out)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
    }
}

/// [`resolve`] in the units of `problem` as given.
fn resolve_in_units(law: LawId, problem: &ContactProblem, opts: &Options) -> Resolution {
    let out = match law {
        LawId::Whittaker => whittaker::in_units(problem),
        LawId::Brach => brach::in_units(problem),
        LawId::Newton | LawId::Poisson | LawId::Energetic => {
            darboux_keller(problem, law, opts, false, &mut |_, _| {})
        }
        LawId::Lcp => lcp::in_units(problem),
        LawId::Sequential | LawId::Lzb => resolve_in_units(LawId::Energetic, problem, opts)
            .map(|o| Outcome { law, ..o })
            .map_err(|b| Breakdown { law, ..b }),
        LawId::TwoPhase | LawId::Smith | LawId::SmithCentre => Err(Breakdown {
            law,
            reason: BreakdownReason::PlanarOnly,
        }),
    }?;
    if out.is_finite() {
        Ok(out)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
    }
}

/// The slip-velocity path of a Darboux–Keller law, sampled at every accepted integration
/// point: `(p_n, v_t1, v_t2, v_n)` (for plots of the hodograph).
pub fn hodograph(
    problem: &ContactProblem,
    law: LawId,
    opts: &Options,
) -> Result<Vec<[f64; 4]>, Breakdown> {
    let mut pts = Vec::new();
    darboux_keller(problem, law, opts, true, &mut |p, v| {
        pts.push([p, v.x, v.y, v.z])
    })?;
    Ok(pts)
}

impl crate::law::Problem for ContactProblem {
    type Resolution = Resolution;

    #[inline]
    fn resolve_by(&self, law: LawId, options: &Options) -> Resolution {
        resolve(law, self, options)
    }
}
