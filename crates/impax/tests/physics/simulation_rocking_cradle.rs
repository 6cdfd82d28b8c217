//! Impacts at several contacts in the simulation: Housner's rocking block and Newton's
//! cradle.
//!
//! **Rocking block** (Housner 1963). A uniform rectangle (half-width `b`, half-height `h`,
//! `R = √(b² + h²)`, `α = atan(b/h)`, `I_G = m R²/3`, about a corner `I_O = 4 m R²/3`) released
//! from rest at the tilt `θ₀ < α` on corner A rocks about A, B strikes, it rocks about B, …
//! With `e = 0` and enough friction every impact conserves the angular momentum about the
//! striking corner: `ω⁺/ω⁻ = r = 1 − (3/2) sin²α`. Between impacts the rocking conserves
//! `T + V`, so the block returns to the flat position with the speed it left it at: the
//! `k`-th impact has `|ω_k⁻| = r^(k−1) ω₁`, `½ I_O ω₁² = m g R (cos(α − θ₀) − cos α)`, and the
//! tilt after it peaks where `m g R cos(α − θ_max) = m g h + ½ I_O ω_k⁺²`.
//!
//! **Cradle.** Equal balls (`e = 1`, frictionless): with gaps, binary impacts pass the velocity
//! down the row, `(0, …, 0, v0)`; touching, the first ball strikes the row at once, one
//! impact at every contact, which `lcp` resolves to its own answer (for three balls
//! `(−1/3, 2/3, 2/3) v0`, theory §6) and `sequential` to `(0, …, 0, v0)`.

use impax::law::LawId;
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::{dynamics, Mechanism};
use impax::multi::scenarios::Cradle as CradleImpact;
use impax::simulation::scenarios::{cradle, rocking_block};
use impax::simulation::{simulate, SimulationOptions, StopReason};

const G: f64 = 9.81;

#[test]
fn the_rocking_block_follows_housner_impact_by_impact() {
    for (b, h, tilt_deg) in [(0.2, 0.6, 10.0), (0.25, 1.0, 8.0), (0.1, 0.5, 5.0)] {
        let init = rocking_block(1.0, b, h, f64::to_radians(tilt_deg), 0.0, G).unwrap();
        let BuiltIn::Block(block) = &init.mechanism else {
            unreachable!()
        };
        let r_housner = block.housner_ratio();
        let run = simulate(
            &init.mechanism,
            &init.q,
            &init.u,
            &SimulationOptions::new(LawId::Energetic, 1.0, 0.0, 20.0),
        )
        .unwrap();
        let (rr, alpha) = (b.hypot(h), b.atan2(h));
        let i_o = 4.0 * rr * rr / 3.0;
        let theta0 = f64::to_radians(tilt_deg);
        let omega1 = (2.0 * G * rr * ((alpha - theta0).cos() - alpha.cos()) / i_o).sqrt();
        assert!(run.impacts.len() > 20, "{}", run.impacts.len());
        let (mut worst_ratio, mut worst_decay, mut worst_peak): (f64, f64, f64) = (0.0, 0.0, 0.0);
        for (k, imp) in run.impacts.iter().enumerate() {
            // Both bottom corners in every impact (the striking one first), under lcp.
            assert_eq!(imp.contacts.len(), 2);
            assert_eq!(imp.law, LawId::Lcp);
            let (w0, w1) = (imp.u_before[2], imp.u_after[2]);
            worst_ratio = worst_ratio.max((w1 / w0 - r_housner).abs());
            // The rocking between impacts conserves T + V to the integration's tolerance: an
            // absolute error in |ω|, measured against ω₁.
            let expected = omega1 * r_housner.powi(k as i32);
            worst_decay = worst_decay.max((w0.abs() - expected).abs() / omega1);
            // The peak tilt before the next impact, from the samples.
            if let Some(next) = run.impacts.get(k + 1) {
                let peak = run
                    .samples
                    .iter()
                    .filter(|s| s.t > imp.time && s.t < next.time)
                    .map(|s| s.q[2].abs())
                    .fold(0.0, f64::max);
                let c = (h + i_o * w1 * w1 / (2.0 * G)) / rr;
                let theta_max = alpha - c.acos();
                // The samples never pass the peak, and miss it by at most ½ |θ̈| Δt² (the
                // angular acceleration about a corner is at most 3g/(4R)).
                let dt = 20.0 / 1000.0;
                assert!(peak <= theta_max + 1e-12, "{peak} > {theta_max}");
                worst_peak = worst_peak.max((theta_max - peak) / (0.5 * 0.75 * G / rr * dt * dt));
            }
        }
        println!(
            "block b = {b}, h = {h}, {tilt_deg}°: {} impacts; ω⁺/ω⁻ vs Housner {r_housner:.6}: {worst_ratio:.1e}; |ω⁻| vs r^k ω₁: {worst_decay:.1e} of ω₁; peak tilt missed by {worst_peak:.2} of the sampling bound",
            run.impacts.len()
        );
        assert!(worst_ratio < 1e-12, "{worst_ratio:e}");
        assert!(worst_decay < 1e-9, "{worst_decay:e}");
        assert!(worst_peak <= 1.0, "{worst_peak:e}");
        // The rocking ends at rest, flat on both bottom corners.
        assert_eq!(run.stop, StopReason::Rest);
        let last = run.samples.last().unwrap();
        let m = &init.mechanism;
        for k in 0..2 {
            assert!(
                dynamics::gap(m, k, &last.q).abs() <= dynamics::touching_tolerance(m, k, &last.q)
            );
        }
        assert!(run.ledger.residual().abs() < 1e-10);
    }
}

/// The block with too little friction slides at the impact (its corner does not stick):
/// Housner's ratio, which assumes no slip, no longer holds, and energy still never rises.
#[test]
fn with_little_friction_the_block_slides_and_housner_does_not_hold() {
    let init = rocking_block(1.0, 0.2, 0.6, 10f64.to_radians(), 0.0, G).unwrap();
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Energetic, 0.05, 0.0, 2.0),
    )
    .unwrap();
    let first = &run.impacts[0];
    let ratio = first.u_after[2] / first.u_before[2];
    assert!((ratio - 0.85).abs() > 1e-3, "{ratio}");
    for imp in &run.impacts {
        assert!(imp.energy_change <= 1e-12 * imp.kinetic_before);
    }
}

fn final_velocities(run: &impax::simulation::Run, balls: usize) -> Vec<f64> {
    let last = run.samples.last().unwrap();
    (0..balls).map(|i| last.u[3 * i]).collect()
}

#[test]
fn a_cradle_with_gaps_passes_the_velocity_down_the_row() {
    for n in [2, 3, 5] {
        for law in [
            LawId::Energetic,
            LawId::Newton,
            LawId::Sequential,
            LawId::Lcp,
        ] {
            let init = cradle(n, 1.0, 0.5, 1.5, 0.1).unwrap();
            let run = simulate(
                &init.mechanism,
                &init.q,
                &init.u,
                &SimulationOptions::new(law, 0.0, 1.0, 2.0),
            )
            .unwrap();
            assert_eq!(run.impacts.len(), n - 1, "{law}, {n} balls");
            for (k, imp) in run.impacts.iter().enumerate() {
                // Binary impacts, one contact each, at times 0.1 k/1.5 apart.
                assert_eq!(imp.contacts, vec![k]);
                assert!((imp.time - 0.1 * (k + 1) as f64 / 1.5).abs() < 1e-12);
            }
            let v = final_velocities(&run, n);
            for (i, x) in v.iter().enumerate() {
                let expected = if i == n - 1 { 1.5 } else { 0.0 };
                assert!((x - expected).abs() < 1e-12, "{law}, {n} balls: {v:?}");
            }
        }
    }
}

#[test]
fn a_touching_cradle_is_one_impact_at_every_contact() {
    for n in [3, 4, 6] {
        // lcp (and a one-contact law, which falls back to lcp) give the LCP answer of the
        // same system resolved on its own.
        let alone = CradleImpact {
            balls: n,
            mass: 1.0,
            radius: 0.5,
            v0: 1.0,
        }
        .build()
        .unwrap();
        let problem = alone.impact.problem(&[0.0], &[1.0]).unwrap();
        let lcp = alone.impact.resolve(LawId::Lcp, &problem).unwrap();
        let expected = lcp.velocities_after.unwrap();
        for law in [LawId::Lcp, LawId::Energetic] {
            let init = cradle(n, 1.0, 0.5, 1.0, 0.0).unwrap();
            let run = simulate(
                &init.mechanism,
                &init.q,
                &init.u,
                &SimulationOptions::new(law, 0.0, 1.0, 1.0),
            )
            .unwrap();
            assert_eq!(run.impacts.len(), 1, "{law}, {n} balls");
            let imp = &run.impacts[0];
            assert_eq!(imp.time, 0.0);
            assert_eq!(imp.contacts, (0..n - 1).collect::<Vec<_>>());
            assert_eq!(imp.law, LawId::Lcp);
            for (a, b) in imp.u_after.iter().zip(&expected) {
                assert!(
                    (a - b).abs() < 1e-12,
                    "{law}, {n}: {:?} vs {expected:?}",
                    imp.u_after
                );
            }
            assert_eq!(run.stop, StopReason::TimeLimit);
        }
        if n == 3 {
            let v: Vec<f64> = (0..3).map(|i| expected[3 * i]).collect();
            for (a, b) in v.iter().zip([-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0]) {
                assert!((a - b).abs() < 1e-12, "{v:?}");
            }
        }
        // sequential: the textbook cradle.
        let init = cradle(n, 1.0, 0.5, 1.0, 0.0).unwrap();
        let run = simulate(
            &init.mechanism,
            &init.q,
            &init.u,
            &SimulationOptions::new(LawId::Sequential, 0.0, 1.0, 1.0),
        )
        .unwrap();
        assert_eq!(run.impacts[0].law, LawId::Sequential);
        let v = final_velocities(&run, n);
        for (i, x) in v.iter().enumerate() {
            let expected = if i == n - 1 { 1.0 } else { 0.0 };
            assert!((x - expected).abs() < 1e-12, "sequential, {n} balls: {v:?}");
        }
        // Momentum and energy (e = 1, frictionless) across the run.
        let m = &init.mechanism;
        let last = run.samples.last().unwrap();
        let p: f64 = (0..n).map(|i| last.u[3 * i]).sum();
        assert!((p - 1.0).abs() < 1e-12);
        let t = dynamics::kinetic_energy(m, &last.q, &last.u);
        assert!((t - 0.5).abs() < 1e-12);
        assert!(m.contacts().len() == n - 1);
    }
}

/// More contacts at once than `lcp` takes (6): a touching cradle of 8 balls under a
/// one-contact law stops with `unsupported-contact`; under `sequential` it runs.
#[test]
fn more_touching_contacts_than_lcp_takes_is_unsupported_unless_sequential() {
    let init = cradle(8, 1.0, 0.5, 1.0, 0.0).unwrap();
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Energetic, 0.0, 1.0, 1.0),
    )
    .unwrap();
    assert_eq!(
        run.stop,
        StopReason::UnsupportedContact {
            contact: 0,
            touching: (1..7).collect()
        }
    );
    let run = simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(LawId::Sequential, 0.0, 1.0, 1.0),
    )
    .unwrap();
    assert_eq!(run.stop, StopReason::TimeLimit);
    assert!((final_velocities(&run, 8)[7] - 1.0).abs() < 1e-12);
}
