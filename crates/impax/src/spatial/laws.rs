//! The spatial laws: `whittaker` and `brach` in closed form, `newton`, `poisson` and
//! `energetic` by the Darboux–Keller integration ([`super::darboux_keller`]), `lcp` by
//! [`super::lcp`].

use super::darboux_keller::{integrate_with, PathEnd, SpatialOptions, Termination};
use super::outcome::{LawDetail, Outcome, PhaseKind, Phases, Resolution};
use super::ContactProblem;
use crate::law::energy::ENERGY_GAIN_ROUND_OFF;
use crate::law::LawId;
use crate::law::{Breakdown, BreakdownReason, Inconsistency, Verdict, WorkSplit};
use crate::math::{norm_of, Vec2, Vec3};

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
fn newton_pn(problem: &ContactProblem, law: LawId, k: Vec2) -> Result<f64, Breakdown> {
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

/// `whittaker` in 3D: Coulomb friction on the total impulse, along the initial slip
/// direction `ŝ0`: `p = p_n (−μ ŝ0, 1)`, `p_n = −(1+e) v_n⁻ / (w_nn − μ w_tn·ŝ0)`.
pub fn whittaker(problem: &ContactProblem) -> Resolution {
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

/// `brach` in 3D: the impulse `p* = W⁻¹ (−v_t⁻, −(1+e) v_n⁻)` that leaves no tangential
/// velocity, used if its ratio `|p*_t|/p*_n ≤ μ`; otherwise the ratio is capped to the cone
/// along `p*_t`: `p_t = μ p_n p*_t/|p*_t|` with Newton's restitution.
pub fn brach(problem: &ContactProblem) -> Resolution {
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

/// `newton`, `poisson` or `energetic` in 3D by the Darboux–Keller integration, with an
/// observer called at every accepted point `(p_n, v)` (for hodographs).
pub fn darboux_keller_observed(
    problem: &ContactProblem,
    law: LawId,
    observe: &mut impl FnMut(f64, Vec3),
) -> Resolution {
    darboux_keller_observed_with(problem, law, &SpatialOptions::default(), observe)
}

/// [`darboux_keller_observed`] with the integration options `opts`.
pub fn darboux_keller_observed_with(
    problem: &ContactProblem,
    law: LawId,
    opts: &SpatialOptions,
    observe: &mut impl FnMut(f64, Vec3),
) -> Resolution {
    darboux_keller(problem, law, opts, true, observe)
}

/// The Darboux–Keller laws, told whether `observe` does anything.
fn darboux_keller(
    problem: &ContactProblem,
    law: LawId,
    opts: &SpatialOptions,
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

/// Resolve a spatial problem with a law (`two-phase`, `smith` and `smith-centre` are planar
/// only and break down with [`BreakdownReason::PlanarOnly`]).
pub fn resolve(law: LawId, problem: &ContactProblem) -> Resolution {
    resolve_with(law, problem, &SpatialOptions::default())
}

/// [`resolve`] with the options `opts` of the Darboux–Keller integration (the other laws
/// ignore them).
///
/// Every law is resolved in the problem's canonical units (`|v_n⁻|` and `w_nn` in `[1, 2)`,
/// powers of two: exact) and the result scaled back: invariant under scaling of the
/// velocities and of `W` (bit for bit for powers of two) wherever its numbers are
/// representable.
///
/// `sequential` (the binary-impact rule of several contacts, [`crate::multi::sequential`])
/// and `lzb` (the multiple-impact law of Liu, Zhao & Brogliato, [`crate::multi::lzb`]) with
/// one contact are `energetic`, its outcome or breakdown labelled `sequential` or `lzb`.
pub fn resolve_with(law: LawId, problem: &ContactProblem, opts: &SpatialOptions) -> Resolution {
    if matches!(law, LawId::Sequential | LawId::Lzb) {
        return match resolve_with(LawId::Energetic, problem, opts) {
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

/// [`resolve_with`] in the units of `problem` as given.
fn resolve_in_units(law: LawId, problem: &ContactProblem, opts: &SpatialOptions) -> Resolution {
    let out = match law {
        LawId::Whittaker => whittaker(problem),
        LawId::Brach => brach(problem),
        LawId::Newton | LawId::Poisson | LawId::Energetic => {
            darboux_keller(problem, law, opts, false, &mut |_, _| {})
        }
        LawId::Lcp => super::lcp::resolve(problem),
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
pub fn hodograph(problem: &ContactProblem, law: LawId) -> Result<Vec<[f64; 4]>, Breakdown> {
    let mut pts = Vec::new();
    darboux_keller_observed(problem, law, &mut |p, v| pts.push([p, v.x, v.y, v.z]))?;
    Ok(pts)
}

impl LawId {
    /// Resolve a spatial (3D) contact-space problem with this law.
    #[inline]
    pub fn resolve3(self, problem: &crate::spatial::ContactProblem) -> crate::spatial::Resolution {
        crate::spatial::laws::resolve(self, problem)
    }

    /// Resolve a spatial (3D) contact-space problem with this law and the options of the
    /// Darboux–Keller integration (tolerance).
    #[inline]
    pub fn resolve3_with(
        self,
        problem: &crate::spatial::ContactProblem,
        opts: &crate::spatial::SpatialOptions,
    ) -> crate::spatial::Resolution {
        crate::spatial::laws::resolve_with(self, problem, opts)
    }
}
