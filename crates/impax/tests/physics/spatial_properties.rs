//! Property tests (proptest) of the spatial (3D) laws (theory §5).
//!
//! * `energetic` never gains energy: `ΔT ≤ 1e-12 · ½ v⁻ᵀW⁻¹v⁻ + 16 ε · Σᵢ (|v⁻ᵢ| + |v⁺ᵢ|) |pᵢ|`
//!   and its verdict is never `EnergyGained` — 50,000 random problems in total (four blocks
//!   of 12,500). The bound: the law's `ΔT` is evaluated as `½ (v⁻ + v⁺)·p`, whose rounding
//!   error is a few ε times the sum of the magnitudes of its terms (the second term, which
//!   dominates for ill-conditioned `W`, where `ΔT` is a small difference of large terms);
//!   the first term is the library's own gain threshold and covers the integrator's error
//!   (relative tolerance 1e-13 of the velocity and impulse scales). The same cases check
//!   Stronge's definition `W_r = −e² W_c`, the work signs `W_c ≤ 0`, `W_t ≤ 0`, the energy
//!   identity `ΔT = W_c + W_r + W_t = v⁻·p + ½ pᵀWp` (recomputed here) and `v⁺ = v⁻ + W p`;
//! * the energy identity, `v⁺ = v⁻ + W p` and `p_n ≥ 0` for every 3D law, and the work signs
//!   `W_c ≤ 0`, `W_t ≤ 0` for `newton` and `poisson`;
//! * rotation of the tangent plane (`problem.rotated(θ)`): `|p_t|`, `p_n`, `ΔT` unchanged,
//!   `p_t` rotated by `θ`, slip angles shifted by `θ`, breakdowns unchanged (all five laws);
//! * isotropic `W_tt` with `w_tn = 0`: no swirl (every `Slip { from, to }` has
//!   `from == to`) and `p_t` anti-parallel to `v_t⁻` (all five laws);
//! * frictionless (`μ = 0`): every law succeeds with `p_t = 0` exactly and
//!   `p_n = −(1+e) v_n⁻ / w_nn`;
//! * plastic (`e = 0`): every law ends at the end of compression, `compression_impulse =
//!   Some(p_n)`;
//! * `w_tn = 0`: `newton`, `poisson` and `energetic` give the same impulse.
//!
//! Cases: 4 × 12,500 (energetic), 250 (every law; rotation), 2,000 (each special case).
//! Tolerances: 1e-12 relative to the size of the terms for the closed-form laws, 1e-9 for
//! the integrated ones. The direction at a halt is not compared under rotation (see
//! `regression_spatial_halt_direction.rs`).
//!
//! Random problems: `W_tt = R diag(d1, d2) Rᵀ` (`d1 ∈ [0.1, 10]`, anisotropy up to 100,
//! about 13 % isotropic), `w_tn = ρ √w_nn W_tt^{1/2} û` of every direction with
//! `ρ ∈ [0, 0.999]` (about 17 % zero), `w_nn ∈ [0.1, 10]`; `|v_t⁻| ∈ [1e-3, 10]` in every
//! direction (about 7 % exactly zero), `v_n ∈ [−2, −0.01]`, `μ ∈ [0, 2]` and `e ∈ [0, 1]`
//! (each end about 8 %).

use impax::math::{Mat3, Vec3};
use impax::planar::Verdict;
use impax::spatial::{sticking_ratio, ContactProblem, Outcome, PhaseKind};
use impax::LawId;
use proptest::prelude::*;
// Failures are not persisted (`failure_persistence: None`): the problems are printed in the
// failure message, and the suite leaves no files behind.
use std::f64::consts::{PI, TAU};

const LAWS: [LawId; 5] = [
    LawId::Whittaker,
    LawId::Brach,
    LawId::Newton,
    LawId::Poisson,
    LawId::Energetic,
];

// ---------------------------------------------------------------------------------------
// Strategies

/// `(log d1, log anisotropy, θ, log w_nn, ρ, angle of û)`.
type RawW = (f64, f64, f64, f64, f64, f64);
/// `(log |v_t|, angle of v_t, v_n, μ, e)`.
type RawV = (f64, f64, f64, f64, f64);

fn raw_w() -> impl Strategy<Value = RawW> {
    (
        -1.0f64..1.0,
        -0.3f64..2.0,
        0.0f64..PI,
        -1.0f64..1.0,
        -0.2f64..0.999,
        0.0f64..TAU,
    )
}

fn raw_v() -> impl Strategy<Value = RawV> {
    (
        -3.25f64..1.0,
        0.0f64..TAU,
        -2.0f64..-0.01,
        -0.2f64..2.2,
        -0.1f64..1.1,
    )
}

/// Pinned entries.
#[derive(Clone, Copy, Default)]
struct Pin {
    /// `W_tt = d1 I`, `w_tn = 0`.
    isotropic_uncoupled: bool,
    /// `w_tn = 0`.
    uncoupled: bool,
    frictionless: bool,
    plastic: bool,
}

fn build((w, v): (RawW, RawV), pin: Pin) -> ContactProblem {
    let (x1, xa, th, xn, rho, ang) = w;
    let (xv, phi, vn, mu, e) = v;
    let d1 = 10f64.powf(x1);
    let d2 = if pin.isotropic_uncoupled {
        d1
    } else {
        d1 * 10f64.powf(xa.max(0.0))
    };
    let (s, c) = th.sin_cos();
    let a00 = c * c * d1 + s * s * d2;
    let a01 = c * s * (d1 - d2);
    let a11 = s * s * d1 + c * c * d2;
    let (r1, r2) = (d1.sqrt(), d2.sqrt());
    let h00 = c * c * r1 + s * s * r2;
    let h01 = c * s * (r1 - r2);
    let h11 = s * s * r1 + c * c * r2;
    let wnn = 10f64.powf(xn);
    let rho = if pin.isotropic_uncoupled || pin.uncoupled {
        0.0
    } else {
        rho.max(0.0)
    };
    let k = rho * wnn.sqrt();
    let (uy, ux) = ang.sin_cos();
    let wt = [k * (h00 * ux + h01 * uy), k * (h01 * ux + h11 * uy)];
    let m = if xv < -3.0 { 0.0 } else { 10f64.powf(xv) };
    let mu = if pin.frictionless {
        0.0
    } else {
        mu.clamp(0.0, 2.0)
    };
    let e = if pin.plastic { 0.0 } else { e.clamp(0.0, 1.0) };
    ContactProblem::from_upper(
        [a00, a01, wt[0], a11, wt[1], wnn],
        [m * phi.cos(), m * phi.sin(), vn],
        mu,
        e,
    )
    .expect("valid by construction")
}

fn problem_with(pin: Pin) -> impl Strategy<Value = ContactProblem> {
    (raw_w(), raw_v()).prop_map(move |r| build(r, pin))
}

/// Problems on either side of the stick limit by a hair: `μ = |W_tt⁻¹ w_tn| (1 + ε)`,
/// `|ε| ∈ [1e-12, 1e-2]` of either sign, `e = 0` (there the slip nearly freezes: the
/// centripetal and centrifugal rays nearly coincide and the field nearly vanishes on them).
fn marginal_problem() -> impl Strategy<Value = ContactProblem> {
    (
        problem_with(Pin {
            plastic: true,
            ..Pin::default()
        }),
        -12.0f64..-2.0,
        any::<bool>(),
    )
        .prop_filter_map("uncoupled (no stick limit)", |(p, x, above)| {
            let limit = sticking_ratio(&p).norm();
            let eps = 10f64.powf(x).copysign(if above { 1.0 } else { -1.0 });
            (limit > 1e-6)
                .then(|| ContactProblem::new(*p.w(), p.velocity(), limit * (1.0 + eps), 0.0).ok())
                .flatten()
        })
}

fn problem() -> impl Strategy<Value = ContactProblem> {
    problem_with(Pin::default())
}

// ---------------------------------------------------------------------------------------
// Helpers

fn abs_w(p: &ContactProblem) -> Mat3 {
    p.w().abs()
}

/// `v⁻·p + ½ pᵀ W p`, recomputed here.
fn energy_of(p: &ContactProblem, q: Vec3) -> f64 {
    p.velocity().dot(&q) + 0.5 * q.dot(&(p.w() * q))
}

/// The size of the terms of `ΔT`: `|v⁻|·|p| + ½ |p|ᵀ|W||p|`.
fn energy_scale(p: &ContactProblem, q: Vec3) -> f64 {
    let qa = q.abs();
    p.velocity().abs().dot(&qa) + 0.5 * qa.dot(&(abs_w(p) * qa))
}

/// The size of the terms of `v⁻ + W p`.
fn velocity_scale(p: &ContactProblem, q: Vec3) -> f64 {
    (p.velocity().abs() + abs_w(p) * q.abs()).max()
}

/// The energy-gain bound (see the header).
fn gain_bound(p: &ContactProblem, o: &Outcome) -> f64 {
    let terms = (p.velocity().abs() + o.velocity_after.abs()).dot(&o.impulse.abs());
    1e-12 * p.approach_energy() + 16.0 * f64::EPSILON * terms
}

/// The checks made on every `energetic` resolution.
fn check_energetic(p: &ContactProblem) -> Result<(), TestCaseError> {
    let o = LawId::Energetic
        .resolve(p)
        .map_err(|b| TestCaseError::fail(format!("energetic broke down ({b}) for {p:?}")))?;
    prop_assert!(
        o.energy_change <= gain_bound(p, &o),
        "ΔT = {:e} > bound {:e} (approach energy {:e}) for {:?}",
        o.energy_change,
        gain_bound(p, &o),
        p.approach_energy(),
        p
    );
    prop_assert!(
        o.verdict != Verdict::EnergyGained,
        "verdict {:?} for {p:?}",
        o.verdict
    );
    check_identities(p, &o)?;
    let scale = energy_scale(p, o.impulse);
    let e = p.restitution();
    prop_assert!(
        (o.work.restitution + e * e * o.work.compression).abs() <= 1e-9 * scale,
        "W_r = {:e} vs −e² W_c = {:e} for {p:?}",
        o.work.restitution,
        -e * e * o.work.compression
    );
    Ok(())
}

/// Energy identity, `v⁺ = v⁻ + W p`, `p_n ≥ 0`, and (Darboux–Keller laws) the work signs.
fn check_identities(p: &ContactProblem, o: &Outcome) -> Result<(), TestCaseError> {
    let law = o.law;
    let scale = energy_scale(p, o.impulse);
    let tol = if law.is_darboux_keller() { 1e-9 } else { 1e-12 };
    let direct = energy_of(p, o.impulse);
    prop_assert!(
        (o.energy_change - direct).abs() <= tol * scale,
        "{law}: ΔT {:e} vs v⁻·p + ½pᵀWp {:e} for {p:?}",
        o.energy_change,
        direct
    );
    prop_assert!(
        (o.energy_change - o.work.total()).abs() <= tol * scale,
        "{law}: ΔT {:e} vs W_c + W_r + W_t {:e} ({:?}) for {p:?}",
        o.energy_change,
        o.work.total(),
        o.work
    );
    let va = p.velocity_after(o.impulse);
    prop_assert!(
        (va - o.velocity_after).abs().max() <= tol * velocity_scale(p, o.impulse),
        "{law}: velocity after {:?} vs v⁻ + W p = {va:?} for {p:?}",
        o.velocity_after
    );
    prop_assert!(o.impulse.z >= 0.0, "{law}: p_n = {} for {p:?}", o.impulse.z);
    if law.is_darboux_keller() {
        prop_assert!(
            o.work.compression <= 0.0,
            "{law}: W_c = {:e} for {p:?}",
            o.work.compression
        );
        prop_assert!(
            o.work.friction <= 1e-12 * scale,
            "{law}: W_t = {:e} for {p:?}",
            o.work.friction
        );
        prop_assert!(
            o.compression_impulse.is_some(),
            "{law}: no compression end for {p:?}"
        );
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Energetic: 50,000 cases in four blocks (run in parallel by the test harness).

proptest! {
    #![proptest_config(ProptestConfig { cases: 12_500, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn energetic_never_gains_energy_1_of_4(p in problem()) {
        check_energetic(&p)?;
    }

    #[test]
    fn energetic_never_gains_energy_2_of_4(p in problem()) {
        check_energetic(&p)?;
    }

    #[test]
    fn energetic_never_gains_energy_3_of_4(p in problem()) {
        check_energetic(&p)?;
    }

    #[test]
    fn energetic_never_gains_energy_4_of_4(p in problem()) {
        check_energetic(&p)?;
    }
}

// ---------------------------------------------------------------------------------------
// Every law

proptest! {
    #![proptest_config(ProptestConfig { cases: 250, failure_persistence: None, ..ProptestConfig::default() })]

    /// `ΔT` three ways, `v⁺ = v⁻ + W p`, `p_n ≥ 0`, work signs (DK laws).
    #[test]
    fn energy_identity_and_work_signs_for_every_law(p in problem()) {
        for law in LAWS {
            let Ok(o) = law.resolve(&p) else {
                prop_assert!(!law.is_darboux_keller(), "{law} broke down for {p:?}");
                continue;
            };
            check_identities(&p, &o)?;
        }
    }

    /// Rotating the tangent plane by `θ` rotates `p_t` and the slip angles and changes
    /// nothing else.
    #[test]
    fn rotation_of_the_tangent_plane(p in problem(), theta in 0.0f64..TAU) {
        let q = p.rotated(theta).expect("a rotated valid problem is valid");
        let (s, c) = theta.sin_cos();
        for law in LAWS {
            let (a, b) = match (law.resolve(&p), law.resolve(&q)) {
                (Ok(a), Ok(b)) => (a, b),
                (Err(a), Err(b)) => {
                    prop_assert_eq!(a.reason.id(), b.reason.id());
                    continue;
                }
                (a, b) => {
                    return Err(TestCaseError::fail(format!(
                        "{law}: {:?} vs rotated {:?} for {p:?}, θ = {theta}",
                        a.map(|o| o.impulse), b.map(|o| o.impulse)
                    )));
                }
            };
            let tol = if law.is_darboux_keller() { 1e-9 } else { 1e-11 };
            let pn = a.impulse.norm();
            let rot = Vec3::new(c * a.impulse.x - s * a.impulse.y, s * a.impulse.x + c * a.impulse.y, a.impulse.z);
            prop_assert!((rot - b.impulse).norm() <= tol * pn,
                "{law}: R p = {rot:?} vs p(rotated) = {:?} for {p:?}, θ = {theta}", b.impulse);
            prop_assert!((a.impulse.xy().norm() - b.impulse.xy().norm()).abs() <= tol * pn,
                "{law}: |p_t| {} vs {}", a.impulse.xy().norm(), b.impulse.xy().norm());
            prop_assert!((a.impulse.z - b.impulse.z).abs() <= tol * pn,
                "{law}: p_n {} vs {}", a.impulse.z, b.impulse.z);
            let es = energy_scale(&p, a.impulse);
            prop_assert!((a.energy_change - b.energy_change).abs() <= tol * es,
                "{law}: ΔT {:e} vs {:e}", a.energy_change, b.energy_change);
            // Slip angles turn with the plane (where they are well defined).
            let (pa, pb) = (a.phases.as_slice(), b.phases.as_slice());
            prop_assert_eq!(pa.len(), pb.len(), "{}: phases {} vs {}", law, a.phases.summary(), b.phases.summary());
            let turned = |x: f64, y: f64| {
                let d = (y - x - theta).rem_euclid(TAU);
                d.min(TAU - d) <= 1e-6
            };
            // The direction at a halt (a slip phase followed by another) is reported by the
            // library as the last integrated direction, not the limit ray (see
            // `regression_spatial_halt_direction.rs`): compared only at the end of the impact.
            for (i, (x, y)) in pa.iter().zip(pb).enumerate() {
                let halted = i + 1 < pa.len();
                let ok = match (x.kind, y.kind) {
                    (PhaseKind::Slip { from: f1, to: t1 }, PhaseKind::Slip { from: f2, to: t2 }) => {
                        turned(f1, f2) && (halted || turned(t1, t2))
                    }
                    (PhaseKind::Resumed { angle: a1 }, PhaseKind::Resumed { angle: a2 }) => turned(a1, a2),
                    (k1, k2) => k1 == k2,
                };
                prop_assert!(ok, "{}: phases {:?} vs rotated {:?} (θ = {}) for {:?}", law, x, y, theta, p);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, failure_persistence: None, ..ProptestConfig::default() })]

    /// Isotropic `W_tt`, `w_tn = 0`: the slip field is radial, nothing swirls.
    #[test]
    fn isotropic_uncoupled_problems_do_not_swirl(
        p in problem_with(Pin { isotropic_uncoupled: true, ..Pin::default() })
    ) {
        let vt = p.velocity().xy();
        for law in LAWS {
            let o = law.resolve(&p).map_err(|b| TestCaseError::fail(format!("{b} for {p:?}")))?;
            for ph in o.phases.as_slice() {
                if let PhaseKind::Slip { from, to } = ph.kind {
                    prop_assert!(from == to, "{}: slip turned from {} to {} ({}) for {:?}",
                        law, from, to, o.phases.summary(), p);
                }
            }
            let pt = o.impulse.xy();
            if vt.norm() == 0.0 || p.friction() == 0.0 {
                prop_assert!(pt.norm() == 0.0, "{law}: p_t = {pt:?} without slip or friction");
            } else {
                let cross = pt.x * vt.y - pt.y * vt.x;
                prop_assert!(cross.abs() <= 1e-14 * pt.norm() * vt.norm(),
                    "{law}: p_t = {pt:?} not parallel to v_t⁻ = {vt:?} for {p:?}");
                prop_assert!(pt.dot(&vt) < 0.0, "{law}: p_t = {pt:?} not against v_t⁻ = {vt:?}");
            }
        }
    }

    /// `μ = 0`: no tangential impulse at all, `p_n = −(1+e) v_n⁻ / w_nn`, for every law.
    #[test]
    fn frictionless_laws_give_the_normal_impulse(
        p in problem_with(Pin { frictionless: true, ..Pin::default() })
    ) {
        let expect = -(1.0 + p.restitution()) * p.velocity().z / p.wnn();
        for law in LAWS {
            let o = law.resolve(&p).map_err(|b| TestCaseError::fail(format!("{b} for {p:?}")))?;
            prop_assert!(o.impulse.x == 0.0 && o.impulse.y == 0.0,
                "{law}: p_t = {:?} with μ = 0 for {p:?}", o.impulse.xy());
            prop_assert!((o.impulse.z - expect).abs() <= 1e-12 * expect,
                "{law}: p_n = {} vs {expect} for {p:?}", o.impulse.z);
        }
    }

    /// `e = 0`: every law ends exactly where compression ends.
    #[test]
    fn plastic_impacts_end_at_the_end_of_compression(
        p in problem_with(Pin { plastic: true, ..Pin::default() })
    ) {
        for law in LAWS {
            let Ok(o) = law.resolve(&p) else {
                prop_assert!(!law.is_darboux_keller(), "{law} broke down for {p:?}");
                continue;
            };
            let pc = o.compression_impulse;
            prop_assert!(pc.is_some_and(|pc| (pc - o.impulse.z).abs() <= 1e-12 * o.impulse.norm()),
                "{law}: e = 0 but p_n = {} and compression impulse {pc:?} for {p:?}", o.impulse.z);
            prop_assert!(o.velocity_after.z.abs() <= 1e-12 * velocity_scale(&p, o.impulse),
                "{law}: e = 0 but v_n⁺ = {:e}", o.velocity_after.z);
        }
    }

    /// Stick failing or holding by a hair: the Darboux–Keller laws still resolve (the slip
    /// halts, then sticks or resumes along a ray whose rate nearly vanishes), and end where
    /// compression ends (`e = 0`).
    #[test]
    fn marginal_stick_resolves(p in marginal_problem()) {
        for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
            let o = law.resolve(&p).map_err(|b| TestCaseError::fail(format!("{law}: {b} for {p:?}")))?;
            let pc = o.compression_impulse;
            prop_assert!(pc.is_some_and(|pc| (pc - o.impulse.z).abs() <= 1e-12 * o.impulse.norm()),
                "{law}: p_n = {} and compression impulse {pc:?} for {p:?}", o.impulse.z);
        }
    }

    /// `w_tn = 0`: `dv_n/dp_n = w_nn` throughout, the three terminations coincide.
    #[test]
    fn uncoupled_darboux_keller_laws_coincide(
        p in problem_with(Pin { uncoupled: true, ..Pin::default() })
    ) {
        let n = LawId::Newton.resolve(&p).map_err(|b| TestCaseError::fail(format!("{b}")))?;
        for law in [LawId::Poisson, LawId::Energetic] {
            let o = law.resolve(&p).map_err(|b| TestCaseError::fail(format!("{b}")))?;
            prop_assert!((o.impulse - n.impulse).norm() <= 1e-9 * n.impulse.norm(),
                "{law}: {:?} vs newton {:?} for {p:?}", o.impulse, n.impulse);
        }
    }
}
