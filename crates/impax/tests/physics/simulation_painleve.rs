//! Painlevé's paradox in the simulation: a uniform rod sliding on one end over a rough floor.
//!
//! **The bound, from the rod's equations.** A uniform rod (mass `m`, length `l`,
//! `I = m l²/12`) at the angle `θ` from the floor, its end A at `r = −(l/2)(cos θ, sin θ)` from
//! the centre on the floor, sliding with `v_t < 0` (towards `−x`): the floor pushes with `N`
//! and friction `F = +μ N` (against the slip). Then
//!
//! ```text
//! m ẍ = μ N,   m ÿ = N − m g,   I θ̈ = r_x N − r_y F = (l/2)(μ sin θ − cos θ) N
//! ÿ_A = ÿ − (l/2)(cos θ θ̈ − sin θ θ̇²)
//!     = −g + (l/2) sin θ θ̇²  +  (N/m) (1 + 3 cos²θ − 3 μ sin θ cos θ)
//! ```
//!
//! The coefficient of `N` is negative when `μ > μ_P(θ) = (1 + 3 cos²θ)/(3 sin θ cos θ)`, least
//! `4/3` at `tan θ = 2`. With it negative, `0 ≤ N ⊥ ÿ_A ≥ 0` has no solution when the free
//! part `−g + (l/2) sin θ θ̇²` is negative (the inconsistent case) and two (`N = 0`, the end
//! leaving, and a positive `N`) when it is positive (the indeterminate case): Génot & Brogliato
//! 1999. The simulation must stop there, naming the contact and the number of solutions,
//! and not integrate through; below the bound the contact closes and slides.

use impax::law::LawId;
use impax::mechanism::builtin::Rod;
use impax::planar::SlipDirection;
use impax::simulation::{simulate, EventKind, Regime, Run, SimulationOptions, StopReason};

const G: f64 = 9.81;

/// `μ_P(θ) = (1 + 3 cos²θ)/(3 sin θ cos θ)`.
fn painleve_bound(theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    (1.0 + 3.0 * c * c) / (3.0 * s * c)
}

/// The unit rod at `θ` with end A on the floor, A sliding at `−1` along the floor and
/// `θ̇ = omega`, A's normal velocity zero.
fn sliding_rod(theta: f64, omega: f64, mu: f64) -> Run {
    let rod = Rod::new(1.0, 1.0, G, 0.0).unwrap();
    let (s, c) = theta.sin_cos();
    let q = [0.5 * c, 0.5 * s, theta];
    // v_A = v + ω ẑ × r, r = −½ (c, s): v_Ax = v_x + ω s/2, v_Ay = v_y − ω c/2.
    let u = [-1.0 - 0.5 * omega * s, 0.5 * omega * c, omega];
    simulate(
        &rod,
        &q,
        &u,
        &SimulationOptions::new(LawId::Energetic, mu, 0.5, 0.5),
    )
    .unwrap()
}

#[test]
fn the_bound_is_four_thirds_at_tan_theta_two() {
    let best = 2f64.atan();
    assert!((painleve_bound(best) - 4.0 / 3.0).abs() < 1e-15);
    for d in [-0.1, -0.01, 0.01, 0.1] {
        assert!(painleve_bound(best + d) > 4.0 / 3.0);
    }
}

#[test]
fn above_the_bound_with_the_end_pressed_the_problem_has_no_solution() {
    let theta = 2f64.atan();
    let r = sliding_rod(theta, 0.0, 1.5);
    assert_eq!(
        r.stop,
        StopReason::Painleve {
            contact: 0,
            solutions: 0
        }
    );
    // It stops at once, without integrating.
    assert_eq!(r.end_time, 0.0);
    assert_eq!(r.steps, (0, 0));
    assert!(r.impacts.is_empty());
    assert_eq!(r.samples.last().unwrap().t, 0.0);
}

#[test]
fn above_the_bound_with_the_end_flung_up_the_problem_has_two_solutions() {
    // θ̇² > 2g/(l sin θ): the free normal acceleration of A is positive.
    let theta = 2f64.atan();
    for omega in [5.0, -5.0] {
        assert!(omega * omega > 2.0 * G / theta.sin());
        let r = sliding_rod(theta, omega, 1.5);
        assert_eq!(
            r.stop,
            StopReason::Painleve {
                contact: 0,
                solutions: 2
            },
            "θ̇ = {omega}"
        );
        assert_eq!(r.end_time, 0.0);
    }
}

#[test]
fn the_bound_separates_sliding_from_painleve_at_several_angles() {
    for deg in [45.0, 55.0, 63.43, 70.0, 80.0] {
        let theta = f64::to_radians(deg);
        let bound = painleve_bound(theta);
        let above = sliding_rod(theta, 0.0, bound * 1.01);
        assert_eq!(
            above.stop,
            StopReason::Painleve {
                contact: 0,
                solutions: 0
            },
            "{deg}°, μ = 1.01 μ_P"
        );
        let below = sliding_rod(theta, 0.0, bound * 0.99);
        assert!(
            !matches!(below.stop, StopReason::Painleve { .. }) || below.end_time > 0.0,
            "{deg}°, μ = 0.99 μ_P: {:?}",
            below.stop
        );
        // Below the bound the end closes, sliding (towards −x).
        assert_eq!(
            below.events[0],
            (
                0.0,
                EventKind::Closes {
                    contact: 0,
                    regime: Regime::Slip(SlipDirection::Negative)
                }
            ),
            "{deg}°"
        );
    }
}

#[test]
fn the_mirror_image_is_detected_the_same_way() {
    // Reflect x → −x: θ → π − θ, the lower end A on the right, sliding towards +x.
    let theta = 2f64.atan();
    let rod = Rod::new(1.0, 1.0, G, 0.0).unwrap();
    let (s, c) = theta.sin_cos();
    let q = [-0.5 * c, 0.5 * s, std::f64::consts::PI - theta];
    let r = simulate(
        &rod,
        &q,
        &[1.0, 0.0, 0.0],
        &SimulationOptions::new(LawId::Energetic, 1.5, 0.5, 0.5),
    )
    .unwrap();
    assert_eq!(
        r.stop,
        StopReason::Painleve {
            contact: 0,
            solutions: 0
        }
    );
    // Sliding the other way (the end trailing) there is no paradox at any μ.
    let r = simulate(
        &rod,
        &q,
        &[-1.0, 0.0, 0.0],
        &SimulationOptions::new(LawId::Energetic, 5.0, 0.5, 0.5),
    )
    .unwrap();
    assert!(
        !matches!(r.stop, StopReason::Painleve { .. }),
        "{:?}",
        r.stop
    );
}

/// Sliding below the bound everywhere it goes, the rod never meets the paradox: while its end
/// slides, the coefficient `1 + 3 cos²θ − 3 μ sin θ cos θ ŝ` of every sample is positive (the
/// simulation never integrates a sliding regime with a negative one).
#[test]
fn sliding_samples_have_a_positive_force_coefficient() {
    for (deg, mu) in [(40.0, 1.0), (63.43, 1.3), (75.0, 1.2)] {
        let r = sliding_rod(f64::to_radians(deg), 0.0, mu);
        for s in r
            .samples
            .iter()
            .filter(|s| s.mode == impax::simulation::Mode::Contact)
        {
            let th = s.q[2];
            let slip = s.u[0] + 0.5 * s.u[2] * th.sin();
            if slip.abs() > 1e-9 {
                let coefficient =
                    1.0 + 3.0 * th.cos().powi(2) + 3.0 * mu * th.sin() * th.cos() * slip.signum();
                assert!(
                    coefficient > 0.0,
                    "{deg}°, μ = {mu}: {coefficient} at t = {}",
                    s.t
                );
            }
        }
    }
}
