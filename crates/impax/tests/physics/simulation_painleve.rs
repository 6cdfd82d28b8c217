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
//!
//! **Reaching the bound while sliding.** The bound depends on the angle, so a rod sliding
//! below it can reach it as it turns (from `θ < atan 2`, `θ` increasing towards the root
//! `θ_P` of `μ_P(θ) = μ`). Write `d = 1 + 3 cos²θ − 3 μ sin θ cos θ` (the force's
//! coefficient) and `q = g − (l/2) sin θ θ̇²` (minus the free normal acceleration), so that
//! `N/m = q/d`, `θ̈ = 6 (μ sin θ − cos θ) q/(l d)`, and
//!
//! ```text
//! ḋ = d'(θ) θ̇,     q̇ = −(l/2) cos θ θ̇³ − 6 sin θ θ̇ (μ sin θ − cos θ) q/d.
//! ```
//!
//! Near `θ_P`, with `τ = t_P − t` and `d ≈ −d'(θ_P) θ̇ τ`: `dq/dτ = a + β q/τ`
//! (`a = (l/2) cos θ θ̇³`), whose solutions are `q = a τ/(1 − β) + C τ^β` with
//!
//! ```text
//! β = 2 sin θ_P (μ sin θ_P − cos θ_P) / (2 sin θ_P cos θ_P + μ (cos²θ_P − sin²θ_P)).
//! ```
//!
//! With `β > 1` (`4/3 < μ < μ_C = 8/(3√3) ≈ 1.5396`, where `β = 1`) `q` vanishes before
//! `d`: the normal force falls to zero and the end lifts off just short of the bound, which
//! is then never reached while sliding. With `β < 1` (`μ > μ_C`) a rod that keeps `q > 0`
//! reaches `d = q = 0` at a finite time `t_P`, its normal force growing as `τ^(β−1)` without
//! bound (its impulse finite): Génot & Brogliato's singular point, the "dynamic jam", past
//! which the rigid-body equations do not say how the motion goes on (a tangential impact, a
//! lift-off or a slip into the indeterminate region). The simulation must stop there with
//! `painleve` at `t_P`, not integrate through. `t_P` comes from an independent integration of
//! the sliding rod's equations multiplied by `d` (time `s`, `dt/ds = d`: regular through the
//! singular point, which the path approaches as `s` grows). Regression: the simulation failed
//! there with an error ("the step size underflowed") instead of reporting the paradox.

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

/// The lower root `θ_P < atan 2` of `μ_P(θ) = μ` (`μ > 4/3`).
fn lower_root(mu: f64) -> f64 {
    let (mut lo, mut hi) = (1e-6, 2f64.atan());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if painleve_bound(mid) > mu {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// `β` at the bound (module docs): above 1 the end lifts off short of the bound, below 1 it
/// reaches it while sliding.
fn beta(mu: f64) -> f64 {
    let (s, c) = lower_root(mu).sin_cos();
    2.0 * s * (mu * s - c) / (2.0 * s * c + mu * (c * c - s * s))
}

/// The unit rod's sliding equations (end A on the floor, slipping towards −x) multiplied by
/// `d`, in `s` (`dt/ds = d`), for the state `(θ, θ̇, ẋ, t)`; with `d` and `q`.
fn sliding_field(y: &[f64; 4], mu: f64) -> ([f64; 4], f64, f64) {
    let (s, c) = y[0].sin_cos();
    let d = 1.0 + 3.0 * c * c - 3.0 * mu * s * c;
    let q = G - 0.5 * s * y[1] * y[1];
    ([y[1] * d, 6.0 * (mu * s - c) * q, mu * q, d], d, q)
}

fn rk4(y: &[f64; 4], h: f64, mu: f64) -> [f64; 4] {
    let at = |k: &[f64; 4], f: f64| std::array::from_fn::<f64, 4, _>(|i| y[i] + f * h * k[i]);
    let k1 = sliding_field(y, mu).0;
    let k2 = sliding_field(&at(&k1, 0.5), mu).0;
    let k3 = sliding_field(&at(&k2, 0.5), mu).0;
    let k4 = sliding_field(&at(&k3, 1.0), mu).0;
    std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// How the sliding of the independent integration ends.
#[derive(Debug, PartialEq)]
enum SlideEnd {
    /// The normal force vanished (`q = 0`, `d > 0`): lift-off.
    Lift,
    /// `d` and `q` reached zero together: the singular point.
    Jam,
    /// The slip halted.
    Halt,
}

/// The independent integration (classical Runge–Kutta in `s`, step `ds`) of the rod of
/// [`sliding_rod_with`] until its slide ends; the state `(θ, θ̇, ẋ, t)` there (a lift-off
/// located by bisection in the last step).
fn slide(theta: f64, omega: f64, va: f64, mu: f64, ds: f64) -> (SlideEnd, [f64; 4]) {
    let mut y = [theta, omega, va - 0.5 * omega * theta.sin(), 0.0];
    for _ in 0..10_000_000 {
        let d = sliding_field(&y, mu).1;
        if y[2] + 0.5 * y[0].sin() * y[1] >= 0.0 {
            return (SlideEnd::Halt, y);
        }
        if d < 1e-13 {
            return (SlideEnd::Jam, y);
        }
        let next = rk4(&y, ds, mu);
        if sliding_field(&next, mu).2 <= 0.0 {
            let (mut lo, mut hi) = (0.0, ds);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if sliding_field(&rk4(&y, mid, mu), mu).2 > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            assert!(d > 0.0);
            return (SlideEnd::Lift, rk4(&y, lo, mu));
        }
        y = next;
    }
    panic!("the slide does not end");
}

/// The unit rod at `θ` with end A on the floor sliding at `va < 0` and `θ̇ = omega`, until
/// `until`.
fn sliding_rod_with(theta: f64, omega: f64, va: f64, mu: f64, until: f64) -> Run {
    let rod = Rod::new(1.0, 1.0, G, 0.0).unwrap();
    let (s, c) = theta.sin_cos();
    let q = [0.5 * c, 0.5 * s, theta];
    let u = [va - 0.5 * omega * s, 0.5 * omega * c, omega];
    simulate(
        &rod,
        &q,
        &u,
        &SimulationOptions::new(LawId::Energetic, mu, 0.5, until),
    )
    .unwrap()
}

/// Above `μ_C` a rod starting to slide below the bound reaches it as it turns: the run stops
/// with `painleve` when it gets there (the independent integration's `t_P`, `θ_P`), and
/// nothing after that instant is integrated.
#[test]
fn a_rod_turning_into_the_bound_while_sliding_stops_there() {
    let mu_c = 8.0 / (3.0 * 3f64.sqrt());
    assert!((beta(mu_c) - 1.0).abs() < 1e-9, "{}", beta(mu_c));
    let (mu, theta0, omega, va) = (2.0, 30f64.to_radians(), 2.0, -10.0);
    assert!(beta(mu) < 1.0);
    // It starts well below the bound (μ_P(30°) = 2.5).
    assert!(painleve_bound(theta0) > 1.2 * mu);
    let theta_p = lower_root(mu);
    let (end, at) = slide(theta0, omega, va, mu, 1e-4);
    assert_eq!(end, SlideEnd::Jam);
    let t_p = at[3];
    // There, still sliding, on the bound (θ_P) with zero free normal acceleration.
    assert!((at[0] - theta_p).abs() < 1e-7, "{} vs {}", at[0], theta_p);
    let q = sliding_field(&at, mu).2;
    assert!(q > 0.0 && q < 1e-3 * G, "{q}");
    assert!(at[2] + 0.5 * at[0].sin() * at[1] < -4.0);
    assert!(theta_p - theta0 > 7f64.to_radians());
    let r = sliding_rod_with(theta0, omega, va, mu, 0.2);
    assert_eq!(
        r.stop,
        StopReason::Painleve {
            contact: 0,
            solutions: 0
        }
    );
    assert!((r.end_time - t_p).abs() < 1e-9, "{} vs {t_p}", r.end_time);
    // It slid all the way, and nothing past t_P was integrated.
    assert_eq!(
        r.events,
        vec![(
            0.0,
            EventKind::Closes {
                contact: 0,
                regime: Regime::Slip(SlipDirection::Negative)
            }
        )]
    );
    assert!(r.impacts.is_empty());
    let last = r.samples.last().unwrap();
    assert_eq!(last.t, r.end_time);
    assert!((last.q[2] - theta_p).abs() < 1e-6, "{}", last.q[2]);
    for s in &r.samples {
        assert!(s.t <= r.end_time);
        assert!(s.q[2] <= theta_p + 1e-9, "θ = {} at t = {}", s.q[2], s.t);
    }
}

/// Between `4/3` and `μ_C` the same rod never reaches the bound while sliding: its normal
/// force vanishes just short of it and the end lifts off (no paradox); the run records the
/// lift-off at the independent integration's instant and flies on.
#[test]
fn below_the_critical_friction_the_end_lifts_off_short_of_the_bound() {
    let (mu, theta0, omega, va) = (1.5, 45f64.to_radians(), 3.0, -3.0);
    assert!(beta(mu) > 1.0 && mu > 4.0 / 3.0);
    assert!(painleve_bound(theta0) > mu);
    let (end, at) = slide(theta0, omega, va, mu, 1e-4);
    assert_eq!(end, SlideEnd::Lift);
    // Just short of the bound: d small but positive.
    let d = sliding_field(&at, mu).1;
    assert!(d > 0.0 && d < 1e-3, "{d}");
    let r = sliding_rod_with(theta0, omega, va, mu, 0.1);
    assert_eq!(r.stop, StopReason::TimeLimit);
    let (t, kind) = &r.events[1];
    assert_eq!(*kind, EventKind::Opens { contact: 0 });
    assert!((t - at[3]).abs() < 1e-8, "{t} vs {}", at[3]);
}
