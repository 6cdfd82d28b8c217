//! Mechanisms by automatic differentiation: mass matrices against hand derivations and finite
//! differences, equations of motion against energy conservation and the small-oscillation
//! frequency, impacts against the momentum balance and the body solvers, conserved quantities.

use impax::math::Vec2;
use impax::mechanism::builtin::{CartPendulum, DoublePendulum, RingPendulum, Rod, Sphere};
use impax::mechanism::conserved::{self, Noether, QuantityKind, Symmetry, TrackOptions};
use impax::mechanism::dynamics;
use impax::mechanism::impact::MechanismImpact;
use impax::mechanism::{Dual64, Mechanism, Pose};
use impax::ode::Tolerances;
use impax::planar::bodies::{self, BodyImpact, BodyState};
use impax::LawId;
use nalgebra::DMatrix;
use proptest::prelude::*;
use proptest::strategy::ValueTree;

fn assert_close(a: &DMatrix<f64>, b: &DMatrix<f64>, tol: f64, what: &str) {
    let scale = b.amax().max(1.0);
    let err = (a - b).amax();
    assert!(
        err <= tol * scale,
        "{what}: |Δ| = {err:e}\nAD {a}\nhand {b}"
    );
}

#[test]
fn mass_matrix_of_free_bodies_is_diag_m_m_i() {
    let s = Sphere::new(2.0, 0.5, 9.81, 0.0).unwrap();
    let m = dynamics::mass_matrix(&s, &[0.3, 1.0, 0.7]);
    assert_close(
        &m,
        &DMatrix::from_diagonal(&nalgebra::dvector![2.0, 2.0, 0.4 * 2.0 * 0.25]),
        1e-15,
        "sphere",
    );
    let r = Rod::new(3.0, 2.0, 9.81, 0.0).unwrap();
    let m = dynamics::mass_matrix(&r, &[0.0, 1.0, 0.9]);
    assert_close(
        &m,
        &DMatrix::from_diagonal(&nalgebra::dvector![3.0, 3.0, 3.0 * 4.0 / 12.0]),
        1e-15,
        "rod",
    );
}

fn double_pendulum_hand(m1: f64, m2: f64, l1: f64, l2: f64, q: [f64; 2]) -> DMatrix<f64> {
    let c = (q[0] - q[1]).cos();
    DMatrix::from_row_slice(
        2,
        2,
        &[
            (m1 / 3.0 + m2) * l1 * l1,
            0.5 * m2 * l1 * l2 * c,
            0.5 * m2 * l1 * l2 * c,
            m2 * l2 * l2 / 3.0,
        ],
    )
}

/// Hand-derived equations of motion of the double pendulum (Lagrange):
/// `M(q) q̈ = −C(q) q̇² − ∂V/∂q` with `C₁₂ = m₂ l₁ l₂ sin(θ₁−θ₂)/2`.
fn double_pendulum_accel(
    m1: f64,
    m2: f64,
    l1: f64,
    l2: f64,
    g: f64,
    q: [f64; 2],
    u: [f64; 2],
) -> [f64; 2] {
    let m = double_pendulum_hand(m1, m2, l1, l2, q);
    let s = (q[0] - q[1]).sin();
    let k = 0.5 * m2 * l1 * l2 * s;
    let r1 = -k * u[1] * u[1] - (0.5 * m1 + m2) * g * l1 * q[0].sin();
    let r2 = k * u[0] * u[0] - 0.5 * m2 * g * l2 * q[1].sin();
    let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
    [
        (m[(1, 1)] * r1 - m[(0, 1)] * r2) / det,
        (m[(0, 0)] * r2 - m[(1, 0)] * r1) / det,
    ]
}

#[test]
fn double_pendulum_mass_matrix_and_dynamics_match_hand_derivation() {
    let (m1, m2, l1, l2, g) = (1.3, 0.7, 0.9, 1.4, 9.81);
    let dp = DoublePendulum::new(m1, m2, l1, l2, g, -3.0).unwrap();
    for &(a, b, u1, u2) in &[
        (0.3, -1.2, 0.5, 2.0),
        (2.5, 0.1, -3.0, 1.0),
        (-0.7, 2.9, 0.0, 0.0),
    ] {
        let m = dynamics::mass_matrix(&dp, &[a, b]);
        assert_close(
            &m,
            &double_pendulum_hand(m1, m2, l1, l2, [a, b]),
            1e-14,
            "double pendulum M",
        );
        let acc = dynamics::accelerations(&dp, &[a, b], &[u1, u2]).unwrap();
        let hand = double_pendulum_accel(m1, m2, l1, l2, g, [a, b], [u1, u2]);
        for i in 0..2 {
            assert!(
                (acc[i] - hand[i]).abs() <= 1e-12 * (1.0 + hand[i].abs()),
                "q̈[{i}]: {} vs {}",
                acc[i],
                hand[i]
            );
        }
    }
}

#[test]
fn pendulum_mass_matrices_match_their_lagrangians() {
    let (big, r, m, l) = (1.7, 0.8, 0.6, 1.3);
    let ring = RingPendulum::new(big, r, m, l, 9.81).unwrap();
    let cart = CartPendulum::new(big, m, l, 9.81).unwrap();
    for phi in [0.0f64, 0.4, 2.0, -2.8] {
        let c = phi.cos();
        let hand = DMatrix::from_row_slice(2, 2, &[2.0 * big + m, m * l * c, m * l * c, m * l * l]);
        assert_close(
            &dynamics::mass_matrix(&ring, &[0.3, phi]),
            &hand,
            1e-14,
            "ring-pendulum M",
        );
        let hand = DMatrix::from_row_slice(2, 2, &[big + m, m * l * c, m * l * c, m * l * l]);
        assert_close(
            &dynamics::mass_matrix(&cart, &[0.3, phi]),
            &hand,
            1e-14,
            "cart-pendulum M",
        );
    }
}

/// Central finite differences of the poses: the Jacobian (h = 1e-6) and the velocity
/// products J̇u = d/ds [J(q + s u) u] (h = 1e-4).
fn finite_difference_check<M: Mechanism>(m: &M, q: &[f64], u: &[f64]) {
    let n = m.dof();
    let nb = m.bodies().len();
    let poses = |q: &[f64]| {
        let mut p = vec![Pose::new(0.0, 0.0, 0.0); nb];
        m.poses(q, &mut p);
        p
    };
    let kin = dynamics::kinematics(m, q);
    let h = 1e-6;
    for i in 0..n {
        let (mut qp, mut qm) = (q.to_vec(), q.to_vec());
        qp[i] += h;
        qm[i] -= h;
        let (pp, pm) = (poses(&qp), poses(&qm));
        for b in 0..nb {
            let fd = [
                (pp[b].x - pm[b].x) / (2.0 * h),
                (pp[b].y - pm[b].y) / (2.0 * h),
                (pp[b].angle - pm[b].angle) / (2.0 * h),
            ];
            for (r, fd) in fd.iter().enumerate() {
                let ad = kin.jacobians[b][(r, i)];
                assert!(
                    (ad - fd).abs() < 1e-8 * (1.0 + ad.abs()),
                    "J[{b}][{r},{i}] AD {ad} FD {fd}"
                );
            }
        }
    }
    let jac_u =
        |q: &[f64]| -> Vec<[f64; 3]> { dynamics::body_velocities(&dynamics::kinematics(m, q), u) };
    let h = 1e-4;
    let qp: Vec<f64> = q.iter().zip(u).map(|(a, b)| a + h * b).collect();
    let qm: Vec<f64> = q.iter().zip(u).map(|(a, b)| a - h * b).collect();
    let (vp, vm) = (jac_u(&qp), jac_u(&qm));
    let ad = dynamics::velocity_products(m, q, u);
    for b in 0..nb {
        for r in 0..3 {
            let fd = (vp[b][r] - vm[b][r]) / (2.0 * h);
            assert!(
                (ad[b][r] - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                "J̇u[{b}][{r}] AD {} FD {fd}",
                ad[b][r]
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn automatic_derivatives_match_finite_differences(
        a in -3.0..3.0f64, b in -3.0..3.0f64, c in -3.0..3.0f64,
        u1 in -3.0..3.0f64, u2 in -3.0..3.0f64, u3 in -3.0..3.0f64,
    ) {
        let dp = DoublePendulum::new(1.0, 0.5, 1.2, 0.8, 9.81, -2.0).unwrap();
        finite_difference_check(&dp, &[a, b], &[u1, u2]);
        let ring = RingPendulum::new(1.0, 0.5, 2.0, 0.7, 9.81).unwrap();
        finite_difference_check(&ring, &[a, b], &[u1, u2]);
        let rod = Rod::new(1.0, 2.0, 9.81, -5.0).unwrap();
        finite_difference_check(&rod, &[a, b, c], &[u1, u2, u3]);
    }
}

fn energy_drift<M: Mechanism>(m: &M, q: &[f64], u: &[f64]) -> f64 {
    let opts = TrackOptions {
        duration: 10.0,
        intervals: 200,
        tolerances: Tolerances::TIGHT,
    };
    let tr = conserved::track(m, q, u, &[], &[], opts).unwrap();
    let e = tr
        .tracks
        .iter()
        .find(|t| t.kind == QuantityKind::Energy)
        .unwrap();
    e.largest_deviation() / e.initial().abs()
}

#[test]
fn free_motion_conserves_energy_over_ten_seconds() {
    let dp = DoublePendulum::new(1.0, 1.0, 1.0, 1.0, 9.81, -3.0).unwrap();
    // A chaotic double pendulum (started near the top); energy measured from the floor so
    // that "relative" is against a positive total.
    let dp_drift = energy_drift(&dp, &[2.0, -1.0], &[1.0, 3.0]);
    let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    let ring_drift = energy_drift(&ring, &[0.0, 1.2], &[0.5, -1.0]);
    let cart = CartPendulum::new(2.0, 1.0, 0.5, 9.81).unwrap();
    let cart_drift = energy_drift(&cart, &[0.0, 2.5], &[0.0, 0.0]);
    println!("relative energy drift over 10 s: double pendulum {dp_drift:.2e}, ring-pendulum {ring_drift:.2e}, cart-pendulum {cart_drift:.2e}");
    for d in [dp_drift, ring_drift, cart_drift] {
        assert!(d <= 1e-9, "energy drift {d:e}");
    }
}

/// Period of small oscillations from the zero crossings of φ(t), against 2π/ω.
fn measured_period<M: Mechanism>(m: &M, phi0: f64) -> f64 {
    let opts = TrackOptions {
        duration: 20.0,
        intervals: 1,
        tolerances: Tolerances::TIGHT,
    };
    // Integrate directly with dense output to locate the upward zero crossings of φ.
    let mut y = vec![0.0, phi0, 0.0, 0.0];
    let mut ode = impax::ode::Dopri5::new(4, opts.tolerances).unwrap();
    let mut crossings = Vec::new();
    let mut buf = [0.0; 4];
    ode.integrate(
        |_, y, dy| dynamics::state_derivative(m, y, dy),
        0.0,
        &mut y,
        opts.duration,
        |s| {
            if s.y0[1] < 0.0 && s.y1[1] >= 0.0 {
                let (mut a, mut b) = (s.t0, s.t1);
                for _ in 0..100 {
                    let mid = 0.5 * (a + b);
                    s.interpolate(mid, &mut buf);
                    if buf[1] < 0.0 {
                        a = mid
                    } else {
                        b = mid
                    }
                }
                crossings.push(0.5 * (a + b));
            }
            None
        },
    )
    .unwrap();
    let k = crossings.len();
    assert!(k >= 3, "too few oscillations");
    (crossings[k - 1] - crossings[0]) / (k - 1) as f64
}

#[test]
fn ring_pendulum_small_oscillations_have_omega2_3g_over_2l() {
    let (g, l) = (9.81, 0.75);
    let ring = RingPendulum::new(1.0, 1.0, 1.0, l, g).unwrap();
    assert!((ring.small_oscillation_omega2() - 1.5 * g / l).abs() < 1e-14);
    let period = measured_period(&ring, 1e-3);
    let expected = 2.0 * std::f64::consts::PI / (1.5 * g / l).sqrt();
    let rel = (period - expected).abs() / expected;
    println!("ring-pendulum period {period:.12} vs 2π/ω {expected:.12}: relative {rel:.1e}");
    // Amplitude correction φ0²/16 ≈ 6e-8 plus the crossing location's dense output.
    assert!(rel < 5e-7, "relative period error {rel:e}");
    // Unequal masses: ω² = (g/l)(2M + m)/(2M).
    let ring = RingPendulum::new(2.0, 1.0, 0.5, l, g).unwrap();
    let expected = 2.0 * std::f64::consts::PI / ring.small_oscillation_omega2().sqrt();
    let rel = (measured_period(&ring, 1e-3) - expected).abs() / expected;
    assert!(rel < 5e-7, "relative period error {rel:e}");
}

#[test]
fn mechanism_impact_of_a_sphere_equals_the_body_solver() {
    let sphere = Sphere::new(1.0, 1.0, 9.81, 0.0).unwrap();
    let alpha = 30f64.to_radians();
    let (q, u) = ([0.0, 1.0, 0.0], [alpha.sin(), -alpha.cos(), 0.0]);
    let imp = MechanismImpact::new(&sphere, &q, &u, 0).unwrap();
    let body = BodyImpact::on_fixed_surface(
        bodies::sphere(1.0, 1.0, impax::planar::bodies::Side::Below).unwrap(),
        BodyState {
            velocity: Vec2::new(alpha.sin(), -alpha.cos()),
            omega: 0.0,
        },
    );
    let (w1, w2) = (imp.inverse_inertia(), body.inverse_inertia());
    assert!((w1 - w2).amax() < 1e-15, "{w1} vs {w2}");
    assert!((imp.contact_velocity() - body.contact_velocity()).amax() < 1e-15);
    for law in LawId::CONTACT_SPACE {
        let a = imp.resolve(law, 0.4, 0.7).unwrap();
        let b = law.resolve(&body.problem(0.4, 0.7).unwrap());
        match (&a.resolution, &b) {
            (Ok(x), Ok(y)) => assert!((x.impulse - y.impulse).amax() < 1e-14, "{law:?}"),
            (Err(_), Err(_)) => {}
            _ => panic!("{law:?}: one solver applies the law, the other does not"),
        }
    }
}

/// A double pendulum with its floor at the tip, `q`, `u`, `μ`, `e`.
type DoublePendulumCase = (DoublePendulum, [f64; 2], [f64; 2], f64, f64);

fn random_double_pendulum_impacts(count: usize) -> Vec<DoublePendulumCase> {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = (
        (0.2..3.0f64, 0.2..3.0f64, 0.2..3.0f64, 0.2..3.0f64),
        (-1.5..1.5f64, -1.5..1.5f64),
        (-5.0..5.0f64, -5.0..5.0f64),
        (0.0..2.0f64, 0.0..=1.0f64),
    );
    let mut out = Vec::new();
    while out.len() < count {
        let ((m1, m2, l1, l2), (a, b), (u1, u2), (mu, e)) =
            strategy.new_tree(&mut runner).unwrap().current();
        let mut dp = DoublePendulum::new(m1, m2, l1, l2, 9.81, 0.0).unwrap();
        dp.put_floor_at_tip([a, b]);
        let imp = MechanismImpact::new(&dp, &[a, b], &[u1, u2], 0).unwrap();
        // Keep approaching states only (v_n < 0).
        if imp.contact_velocity().y < -1e-3 {
            out.push((dp, [a, b], [u1, u2], mu, e));
        }
    }
    out
}

#[test]
fn double_pendulum_impacts_balance_momentum_and_energy() {
    let mut worst_energy: f64 = 0.0;
    let mut worst_momentum: f64 = 0.0;
    for (dp, q, u, mu, e) in random_double_pendulum_impacts(2000) {
        let imp = MechanismImpact::new(&dp, &q, &u, 0).unwrap();
        let t0 = imp.energy_before();
        for law in LawId::CONTACT_SPACE {
            let o = imp.resolve(law, mu, e).unwrap();
            let Ok(out) = &o.resolution else { continue };
            let after = o.velocities_after.as_ref().unwrap();
            // ΔT from contact space and from the generalized velocities.
            let de = o.energy_change_from_velocities.unwrap();
            // Relative to the energies involved (near-aligned rods make W nearly singular and
            // the impulses, and the non-dissipative laws' ΔT, huge).
            let rel = (de - out.energy_change).abs() / (t0 + t0 + de.abs());
            worst_energy = worst_energy.max(rel);
            // M (u⁺ − u⁻) = Jᵀ p.
            let du = nalgebra::DVector::from_iterator(2, after.iter().zip(&u).map(|(a, b)| a - b));
            let lhs = imp.mass_matrix() * du;
            let rhs = imp.jacobian().transpose() * nalgebra::dvector![out.impulse.x, out.impulse.y];
            worst_momentum = worst_momentum.max((lhs - &rhs).amax() / rhs.amax().max(1e-300));
            // The contact velocity after is J u⁺.
            let v_after = imp.jacobian() * nalgebra::DVector::from_column_slice(after);
            assert!(
                (v_after[1] - out.velocity_after.y).abs()
                    <= 1e-9 * (1.0 + out.velocity_after.y.abs())
            );
        }
    }
    println!("2000 double-pendulum impacts × 7 laws: ΔT sides agree to {worst_energy:.1e} of T⁻ + T⁺, momentum balance to {worst_momentum:.1e}");
    // Nearly aligned rods make W nearly singular; the two sides then differ by its
    // condition number times round-off.
    assert!(worst_energy < 1e-10, "{worst_energy:e}");
    assert!(worst_momentum < 1e-11, "{worst_momentum:e}");
}

#[test]
fn energetic_never_gains_energy_on_the_double_pendulum_and_whittaker_does() {
    let cases = random_double_pendulum_impacts(20_000);
    let (mut gains, mut worst) = (0usize, f64::NEG_INFINITY);
    for (dp, q, u, mu, e) in &cases {
        let imp = MechanismImpact::new(dp, q, u, 0).unwrap();
        let t0 = imp.energy_before();
        let en = imp.resolve(LawId::Energetic, *mu, *e).unwrap();
        let de = en.energy_change_from_velocities.unwrap();
        worst = worst.max(de / t0);
        assert!(
            de <= 1e-12 * t0,
            "energetic gains {de:e} at {q:?} {u:?} μ={mu} e={e}"
        );
        if let Ok(w) = imp.resolve(LawId::Whittaker, *mu, *e).unwrap().resolution {
            if w.energy_change > 1e-12 * t0 {
                gains += 1;
            }
        }
    }
    println!(
        "{} random double-pendulum impacts: energetic max ΔT/T⁻ = {worst:.3e}; whittaker gains energy in {gains} ({:.1} %)",
        cases.len(),
        100.0 * gains as f64 / cases.len() as f64
    );
    assert!(
        gains > 0,
        "Whittaker's rule should gain energy somewhere (Kane's paradox)"
    );
}

#[test]
fn kanes_paradox_on_the_documented_double_pendulum_case() {
    // impax compare double-pendulum --angles-deg 30,0 --rates -1,2 --friction 0.5 --restitution 0.5
    let q = [30f64.to_radians(), 0.0];
    let dp = DoublePendulum::unit_at(q);
    let imp = MechanismImpact::new(&dp, &q, &[-1.0, 2.0], 0).unwrap();
    assert!(imp.gap().abs() < 1e-15);
    let w = imp.resolve(LawId::Whittaker, 0.5, 0.5).unwrap();
    assert!(w.resolution.unwrap().energy_change > 0.0);
    for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
        let o = imp.resolve(law, 0.5, 0.5).unwrap();
        assert!(o.resolution.unwrap().energy_change < 0.0, "{law:?}");
    }
}

#[test]
fn ring_pendulum_conserves_p_x_energy_and_the_boost_but_not_p_x_momentum() {
    let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    let tr = conserved::track(
        &ring,
        &[0.0, 0.6],
        &[0.4, 0.0],
        &ring.symmetries(),
        &[Vec2::zeros()],
        TrackOptions::default(),
    )
    .unwrap();
    assert_eq!(tr.cyclic, vec![0]);
    let get = |name: &str| tr.tracks.iter().find(|t| t.name == name).unwrap();
    for name in ["p_x", "energy", "boost x", "translation x"] {
        assert!(
            get(name).conserved(1e-9),
            "{name}: {:e}",
            get(name).relative_deviation()
        );
    }
    for name in ["P_x", "p_phi", "P_y", "L(0, 0)"] {
        assert!(
            get(name).relative_deviation() > 1e-2,
            "{name} should change"
        );
    }
    // p_x = P_x + M ẋ at every sample (ring of mass M = 1).
    let px = &get("p_x").values;
    let big_px = &get("P_x").values;
    assert!((px[0] - big_px[0] - 0.4).abs() < 1e-14);
}

#[test]
fn cart_pendulum_cyclic_integral_is_the_momentum() {
    let cart = CartPendulum::new(2.0, 1.0, 0.8, 9.81).unwrap();
    let tr = conserved::track(
        &cart,
        &[0.0, 1.0],
        &[0.3, -0.5],
        &cart.symmetries(),
        &[],
        TrackOptions::default(),
    )
    .unwrap();
    assert_eq!(tr.cyclic, vec![0]);
    let get = |name: &str| tr.tracks.iter().find(|t| t.name == name).unwrap();
    for name in ["p_x", "P_x", "energy", "boost x"] {
        assert!(
            get(name).conserved(1e-9),
            "{name}: {:e}",
            get(name).relative_deviation()
        );
    }
    for (a, b) in get("p_x").values.iter().zip(&get("P_x").values) {
        assert!((a - b).abs() < 1e-12 * (1.0 + a.abs()));
    }
}

#[test]
fn a_wrong_gauge_is_not_a_symmetry() {
    let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    let boost_without_gauge = Noether::new(
        "boost x without gauge",
        |_q: &[Dual64], t: Dual64, xi: &mut [Dual64]| {
            xi[0] = t;
            xi[1] = Dual64::from(0.0);
        },
        |_q: &[Dual64], _t: Dual64| Dual64::from(0.0),
    );
    let check = conserved::verify_symmetry(
        &ring,
        &boost_without_gauge,
        &[0.0, 0.5],
        &[0.3, 0.1],
        0.0,
        16,
    )
    .unwrap();
    assert!(!check.holds(), "{check:?}");
    // Translation of φ is not a symmetry either (gravity).
    let rot = Noether::translation("translation phi", 1);
    assert!(
        !conserved::verify_symmetry(&ring, &rot, &[0.0, 0.5], &[0.3, 0.1], 0.0, 16)
            .unwrap()
            .holds()
    );
    for s in ring.symmetries() {
        let s: &dyn Symmetry = s.as_ref();
        assert!(
            conserved::verify_symmetry(&ring, s, &[0.0, 0.5], &[0.3, 0.1], 0.0, 16)
                .unwrap()
                .holds()
        );
    }
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    assert!(DoublePendulum::new(-1.0, 1.0, 1.0, 1.0, 9.81, 0.0).is_err());
    assert!(DoublePendulum::new(1.0, 1.0, f64::NAN, 1.0, 9.81, 0.0).is_err());
    assert!(RingPendulum::new(1.0, 1.0, 1.0, 1.0, -9.81).is_err());
    let dp = DoublePendulum::unit_at([0.3, 0.1]);
    assert!(MechanismImpact::new(&dp, &[0.3], &[1.0, 1.0], 0).is_err());
    assert!(MechanismImpact::new(&dp, &[0.3, f64::INFINITY], &[1.0, 1.0], 0).is_err());
    assert!(MechanismImpact::new(&dp, &[0.3, 0.1], &[1.0, 1.0], 3).is_err());
    let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    assert!(MechanismImpact::new(&ring, &[0.0, 0.1], &[1.0, 1.0], 0).is_err());
    // Receding contact: the contact problem rejects it.
    let imp = MechanismImpact::new(&dp, &[0.3, 0.1], &[1.0, 1.0], 0).unwrap();
    if imp.contact_velocity().y >= 0.0 {
        assert!(imp.resolve(LawId::Energetic, 0.5, 0.5).is_err());
    }
    let bad = TrackOptions {
        duration: -1.0,
        ..TrackOptions::default()
    };
    assert!(conserved::track(&ring, &[0.0, 0.1], &[0.0, 0.0], &[], &[], bad).is_err());
}

#[test]
fn whittaker_gains_energy_on_the_double_pendulum_above_a_friction_threshold() {
    // The documented region: at θ = (30°, 0°), u = (−1, 2) rad/s, unit rods, e = 0.5,
    // Whittaker's rule gains energy exactly for μ above a threshold μ* (ΔT(μ) changes sign
    // once on [0, 2]); the Darboux–Keller laws never do.
    let q = [30f64.to_radians(), 0.0];
    let dp = DoublePendulum::unit_at(q);
    let imp = MechanismImpact::new(&dp, &q, &[-1.0, 2.0], 0).unwrap();
    let gain = |mu: f64| {
        imp.resolve(LawId::Whittaker, mu, 0.5)
            .unwrap()
            .resolution
            .map(|o| o.energy_change)
            .unwrap()
    };
    let (mut lo, mut hi) = (0.0, 2.0);
    assert!(gain(lo) < 0.0 && gain(hi) > 0.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if gain(mid) > 0.0 {
            hi = mid
        } else {
            lo = mid
        }
    }
    println!(
        "whittaker gains energy on the documented double-pendulum state (e = 0.5) for μ > {hi:.6}"
    );
    assert!(hi > 0.43 && hi < 0.45, "μ* = {hi}");
    for i in 0..=200 {
        let mu = 0.01 * i as f64;
        assert_eq!(gain(mu) > 0.0, mu > hi, "μ = {mu}");
        for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
            let de = imp
                .resolve(law, mu, 0.5)
                .unwrap()
                .energy_change_from_velocities
                .unwrap();
            assert!(de < 0.0, "{law:?} at μ = {mu}");
        }
    }
}
