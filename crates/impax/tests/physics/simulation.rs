//! Event-driven simulation: the first bounce against the single-impact solvers, apex heights
//! e^(2k) h0, backspin reversal, the Zeno time of a bouncing ball, energy never rising under
//! `energetic`, determinism, bad input.

use impax::math::Vec2;
use impax::mechanism::impact::MechanismImpact;
use impax::planar::bodies::{self, BodyImpact, BodyState, Side};
use impax::simulation::scenarios::{bouncing_ball, double_pendulum_drop, rod_drop};
use impax::simulation::{simulate, EventKind, Mode, SimulationOptions, StopReason};
use impax::LawId;
use proptest::prelude::*;

const G: f64 = 9.81;

#[test]
fn first_bounce_equals_the_single_impact_for_the_same_state() {
    let (speed, alpha, gamma, h, r) = (2.0, 30f64.to_radians(), 0.4, 0.5, 0.1);
    let init = bouncing_ball(1.0, r, h, speed, alpha, gamma, G, false).unwrap();
    for law in [
        LawId::Whittaker,
        LawId::Smith,
        LawId::Brach,
        LawId::Newton,
        LawId::Poisson,
        LawId::Energetic,
    ] {
        let opts = SimulationOptions::new(law, 0.4, 0.7, 0.5);
        let run = simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap();
        let first = &run.impacts[0];
        // Time of the first contact: h = v_y t + g t²/2 with v_y = speed cos α downward.
        let vy = speed * alpha.cos();
        let t1 = (-vy + (vy * vy + 2.0 * G * h).sqrt()) / G;
        assert!(
            (first.time - t1).abs() < 1e-13,
            "{law}: {} vs {t1}",
            first.time
        );
        // The same state through the planar body solver (what `impax compare` uses).
        let u = &first.u_before;
        let body = BodyImpact::on_fixed_surface(
            bodies::sphere(1.0, r, Side::Below).unwrap(),
            BodyState {
                velocity: Vec2::new(u[0], u[1]),
                omega: u[2],
            },
        );
        let problem = body.problem(0.4, 0.7).unwrap();
        let direct = body.resolve(law, &problem).unwrap();
        let after = &first.u_after;
        let scale = 1.0 + u.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        assert!(
            (after[0] - direct.body_after.velocity.x).abs() < 1e-13 * scale,
            "{law}"
        );
        assert!(
            (after[1] - direct.body_after.velocity.y).abs() < 1e-13 * scale,
            "{law}"
        );
        assert!(
            (after[2] - direct.body_after.omega).abs() < 1e-12 * scale,
            "{law}"
        );
        assert!((first.energy_change - direct.outcome.energy_change).abs() < 1e-13 * scale * scale);
    }
}

#[test]
fn apex_heights_of_a_frictionless_ball_follow_e_to_the_2k() {
    let (h0, e) = (1.0, 0.8);
    let init = bouncing_ball(1.0, 0.1, h0, 0.0, 0.0, 0.0, G, false).unwrap();
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Energetic, 0.0, e, 3.0),
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for (k, imp) in run.impacts.iter().enumerate().take(12) {
        let up = imp.struck().velocity_after.y;
        let apex = up * up / (2.0 * G);
        let expected = e.powi(2 * (k as i32 + 1)) * h0;
        worst = worst.max((apex - expected).abs() / expected);
    }
    println!("apex heights vs e^(2k) h0 over 12 bounces: worst relative {worst:.1e}");
    assert!(worst < 1e-12, "{worst:e}");
    // And the apex reached by the sampled trajectory after the first bounce.
    let t_a = run.impacts[0].time;
    let t_b = run.impacts[1].time;
    let top = run
        .samples
        .iter()
        .filter(|s| s.t > t_a && s.t < t_b)
        .map(|s| s.q[1] - 0.1)
        .fold(0.0, f64::max);
    assert!((top - e * e * h0).abs() < 2e-3, "sampled apex {top}");
}

#[test]
fn zeno_time_of_a_vertical_bouncing_ball_is_the_geometric_sum() {
    for (h0, e) in [(1.0, 0.8), (0.3, 0.5), (2.0, 0.9)] {
        let init = bouncing_ball(1.0, 0.1, h0, 0.0, 0.0, 0.0, G, false).unwrap();
        let until = 40.0;
        let run = simulate(
            &init.mechanism,
            &init.q,
            &init.u,
            &SimulationOptions::new(LawId::Energetic, 0.3, e, until),
        )
        .unwrap();
        let v1 = (2.0 * G * h0).sqrt();
        let t_inf = v1 / G + 2.0 * e * v1 / (G * (1.0 - e));
        let limit = run
            .events
            .iter()
            .find_map(|(_, ev)| match ev {
                EventKind::Zeno { limit_time, .. } => Some(*limit_time),
                _ => None,
            })
            .expect("an accumulation of impacts");
        println!(
            "h0 = {h0}, e = {e}: t∞ = {limit:.12} vs {t_inf:.12} ({:.1e}), {} impacts",
            limit - t_inf,
            run.impacts.len()
        );
        assert!((limit - t_inf).abs() <= 1e-9, "{limit} vs {t_inf}");
        assert_eq!(run.stop, StopReason::Rest);
        assert_eq!(run.end_time, limit);
    }
}

#[test]
fn a_ball_with_backspin_reverses_when_the_law_says_so() {
    // Thrown forward (+x) with strong backspin: γ = 2 (the slip at contact is v0 (sin α + γ)).
    let (speed, alpha, r) = (2.0, 30f64.to_radians(), 0.1);
    for (gamma, mu) in [(2.0, 0.6), (2.0, 0.05), (0.0, 0.6)] {
        let init = bouncing_ball(1.0, r, 0.3, speed, alpha, gamma, G, false).unwrap();
        let run = simulate(
            &init.mechanism,
            &init.q,
            &init.u,
            &SimulationOptions::new(LawId::Energetic, mu, 0.6, 1.0),
        )
        .unwrap();
        let first = &run.impacts[0];
        // What the single impact says (Darboux–Keller, energetic).
        let imp = MechanismImpact::new(&init.mechanism, &first.q, &first.u_before, 0).unwrap();
        let predicted = imp
            .resolve(LawId::Energetic, mu, 0.6)
            .unwrap()
            .velocities_after
            .unwrap()[0];
        assert_eq!(first.u_after[0].signum(), predicted.signum());
        let reverses = predicted < 0.0;
        // The trajectory after the bounce moves backwards exactly when predicted.
        let before = run.samples.iter().rfind(|s| s.t <= first.time).unwrap().q[0];
        let later = run
            .samples
            .iter()
            .find(|s| s.t > first.time + 0.1)
            .unwrap()
            .q[0];
        assert_eq!(later < before, reverses, "γ = {gamma}, μ = {mu}");
        if gamma == 2.0 && mu == 0.6 {
            assert!(reverses, "strong backspin with high friction must reverse");
        }
        if gamma == 0.0 {
            assert!(!reverses);
        }
    }
}

#[test]
fn a_spinning_ball_ends_rolling_and_whittaker_shows_the_gain() {
    // The seed's impact (α = 30°, e = 0.7, μ = 0.4, γ = 0) as a bouncing ball.
    let init = bouncing_ball(1.0, 0.1, 0.2, 1.0, 30f64.to_radians(), 0.0, G, false).unwrap();
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Energetic, 0.4, 0.7, 3.0),
    )
    .unwrap();
    assert!(run
        .events
        .iter()
        .any(|(_, e)| matches!(e, EventKind::Zeno { .. })));
    assert!(run.events.iter().any(|(_, e)| *e == EventKind::Rolling));
    assert_eq!(run.stop, StopReason::TimeLimit);
    let last = run.samples.last().unwrap();
    assert_eq!(last.mode, Mode::Rolling);
    assert!(
        (last.u[0] + 0.1 * last.u[2]).abs() < 1e-14,
        "no slip while rolling"
    );
    let w = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Whittaker, 0.4, 0.7, 3.0),
    )
    .unwrap();
    assert!(
        w.impacts.iter().any(|i| i.energy_change > 0.0),
        "Whittaker's rule gains energy at an impact"
    );
}

fn energy_never_rises(run: &impax::simulation::Run) -> f64 {
    // Across impacts: ΔT ≤ 0 (V is continuous). Along flight: T + V constant to tolerance.
    let mut worst: f64 = f64::NEG_INFINITY;
    for imp in &run.impacts {
        worst = worst.max(imp.energy_change / imp.kinetic_before.max(1e-300));
    }
    worst
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn energetic_never_raises_the_energy(
        alpha in 0.0..1.4f64, gamma in -3.0..3.0f64, mu in 0.0..1.5f64, e in 0.0..=1.0f64,
        angle in -1.5..1.5f64, a1 in 1.2..2.6f64, a2 in 1.2..2.6f64,
    ) {
        let opts = SimulationOptions::new(LawId::Energetic, mu, e, 1.5);
        let ball = bouncing_ball(1.0, 0.1, 0.3, 2.0, alpha, gamma, G, false).unwrap();
        let rod = rod_drop(1.0, 1.0, angle, 0.2, G).unwrap();
        let dp = double_pendulum_drop(1.0, 0.5, 1.0, 0.8, G, -1.4, [a1, -a2], [0.0, 0.0]).unwrap();
        for init in [ball, rod, dp] {
            let run = simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap();
            let worst = energy_never_rises(&run);
            prop_assert!(worst <= 1e-12, "ΔT/T⁻ = {worst:e}");
            // Total energy T + V never rises along the whole sampled run (flight conserves it
            // to the integrator's tolerance; impacts and sliding dissipate).
            let e0 = run.samples[0].kinetic + run.samples[0].potential;
            let scale = e0.abs() + run.samples[0].kinetic + 10.0;
            for s in &run.samples {
                prop_assert!(s.kinetic + s.potential <= e0 + 1e-8 * scale);
            }
        }
    }
}

#[test]
fn runs_are_deterministic() {
    let init = rod_drop(1.0, 1.0, 0.7, 0.3, G).unwrap();
    let opts = SimulationOptions::new(LawId::Poisson, 0.5, 0.6, 2.0);
    let a = simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap();
    let b = simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap();
    assert_eq!(a, b);
    assert!(!a.impacts.is_empty());
}

#[test]
fn double_pendulum_drop_hits_the_floor_and_stops_with_a_reason() {
    let init = double_pendulum_drop(
        1.0,
        1.0,
        1.0,
        1.0,
        G,
        -1.5,
        [90f64.to_radians(); 2],
        [0.0, 0.0],
    )
    .unwrap();
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Energetic, 0.5, 0.5, 3.0),
    )
    .unwrap();
    assert!(!run.impacts.is_empty());
    // At each impact the tip is on the floor: y_tip = −cos θ1 − cos θ2 = −1.5.
    for imp in &run.impacts {
        let tip = -imp.q[0].cos() - imp.q[1].cos();
        assert!((tip + 1.5).abs() < 1e-12, "tip at {tip}");
        assert!(imp.contact_velocity_before().y < 0.0);
    }
    assert!(run.stop == StopReason::Rest, "{:?}", run.stop);
}

#[test]
fn bad_simulations_are_errors() {
    assert!(bouncing_ball(1.0, 0.1, -1.0, 1.0, 0.0, 0.0, G, false).is_err());
    assert!(bouncing_ball(1.0, 0.0, 1.0, 1.0, 0.0, 0.0, G, false).is_err());
    assert!(bouncing_ball(1.0, 0.1, 1.0, f64::NAN, 0.0, 0.0, G, false).is_err());
    let init = bouncing_ball(1.0, 0.1, 1.0, 1.0, 0.0, 0.0, G, false).unwrap();
    for opts in [
        SimulationOptions::new(LawId::Energetic, 0.3, 0.5, -1.0),
        SimulationOptions::new(LawId::Energetic, -0.3, 0.5, 1.0),
        SimulationOptions::new(LawId::Energetic, 0.3, 1.5, 1.0),
        SimulationOptions::new(LawId::SmithCentre, 0.3, 0.5, 1.0),
        SimulationOptions {
            sample_interval: 1e-9,
            ..SimulationOptions::new(LawId::Energetic, 0.3, 0.5, 1.0)
        },
    ] {
        assert!(
            simulate(&init.mechanism, &init.q, &init.u, &opts).is_err(),
            "{opts:?}"
        );
    }
    // Starting below the floor.
    let opts = SimulationOptions::new(LawId::Energetic, 0.3, 0.5, 1.0);
    assert!(simulate(&init.mechanism, &[0.0, 0.05, 0.0], &init.u, &opts).is_err());
}
