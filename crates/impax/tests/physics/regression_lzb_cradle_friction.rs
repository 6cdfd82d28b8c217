//! Regression: planar `lzb` broke down (`too-many-steps`) on an 8-ball inelastic Newton's
//! cradle with friction.
//!
//! Reproducer: `impax compare cradle --balls 8 --restitution 0.5 --friction 0.1 --law lzb`
//! (found through the explorer): 20,000 integration steps, then the breakdown, for any
//! `μ > 0` with 8 balls; the same cradle without friction, and every cradle of 3 to 7 balls,
//! resolved at once.
//!
//! Cause: where contacts with friction are at rest, `lzb` chooses their stick or slip by
//! trying every assignment, but only for six of them; the seventh and eighth were set
//! slipping whatever the friction they needed. The 8-ball cradle is the first built-in case
//! with seven contacts at rest together (they all stick, needing no friction). Each time a
//! contact joined or a slip halted, the seventh contact in the list was forced to slip with
//! a zero normal force, its friction pushed its neighbour into slipping too, the slips halted
//! at once, and the next choice forced them again: thousands of halts a hair apart. Now the
//! contacts past the sixth take the regime the all-stick solve gives them (stick inside their
//! cone, else slip against the friction needed), and the enumeration of the first six checks
//! them too.
//!
//! Expected physics, on every cradle of `N = 2 … 9` balls (up to the eight contacts `lzb`
//! takes), `e ∈ {0, 0.5, 1}`, `μ ∈ {0, 0.1, 0.5}`: the balls lie on one line through their
//! centres, so the normal impulses give no tangential velocity at any contact (`W_tn = 0`),
//! the contacts stick with no tangential impulse and friction does no work; the velocities
//! after are those without friction, momentum is conserved (`Σ u_i⁺ = v0`), energy is never
//! gained (kept for `e = 1`; the balls move on together at `v0/N` for `e = 0`), no contact
//! approaches at the end and the balls leave in order (`u_1⁺ ≤ u_2⁺ ≤ … ≤ u_N⁺`, to the
//! round-off at which `lzb` calls an inelastic exchange settled).

use impax::multi::scenarios::Cradle;
use impax::multi::{MultiOutcome, SystemOutcome};
use impax::planar::Verdict;
use impax::LawId;

/// `lzb` on the cradle of `balls` balls (m = 1, r = 0.5, v0 = 1) with `μ` and `e`.
fn cradle(balls: usize, mu: f64, e: f64) -> (SystemOutcome, MultiOutcome) {
    let sc = Cradle {
        balls,
        ..Cradle::default()
    }
    .build()
    .unwrap();
    let p = sc.impact.problem(&[mu], &[e]).unwrap();
    let out = sc.impact.resolve(LawId::Lzb, &p).unwrap();
    let o = out
        .resolution
        .clone()
        .unwrap_or_else(|b| panic!("{balls} balls, μ = {mu}, e = {e}: {b}"));
    (out, o)
}

/// The reproducer: 8 balls, `e = 0.5`, `μ = 0.1` settles as without friction.
#[test]
fn an_inelastic_cradle_with_friction_settles_as_without() {
    let (a, _) = cradle(8, 0.1, 0.5);
    let (b, _) = cradle(8, 0.0, 0.5);
    let (ua, ub) = (a.velocities_after.unwrap(), b.velocities_after.unwrap());
    for (x, y) in ua.iter().zip(&ub) {
        assert!((x - y).abs() < 1e-9, "{ua:?} vs {ub:?}");
    }
}

#[test]
fn every_cradle_with_friction_resolves_as_without() {
    let v0 = 1.0;
    for n in 2..=9 {
        for e in [0.0, 0.5, 1.0] {
            let (plain, _) = cradle(n, 0.0, e);
            let u0 = plain.velocities_after.unwrap();
            for mu in [0.0, 0.1, 0.5] {
                let case = format!("{n} balls, e = {e}, μ = {mu}");
                let (out, o) = cradle(n, mu, e);
                let u = out.velocities_after.unwrap();
                let x: Vec<f64> = (0..n).map(|b| u[3 * b]).collect();
                // Friction does nothing: no tangential impulse, no friction work, the
                // velocities of the frictionless cradle, no ball moving sideways or turning.
                for c in &o.contacts {
                    assert!(c.impulse.x.abs() < 1e-15, "{case}: {:?}", c.impulse);
                    assert!(c.work.friction.abs() < 1e-15, "{case}: {:?}", c.work);
                }
                for (a, b) in u.iter().zip(&u0) {
                    assert!((a - b).abs() < 1e-12 * v0, "{case}: {u:?} vs {u0:?}");
                }
                for b in 0..n {
                    assert!(u[3 * b + 1].abs() < 1e-15 && u[3 * b + 2].abs() < 1e-15);
                }
                // Momentum, energy, the order of the balls, no contact approaching.
                let momentum: f64 = x.iter().sum();
                assert!((momentum - v0).abs() < 1e-12 * v0, "{case}: {x:?}");
                let t0 = 0.5 * v0 * v0;
                assert_ne!(o.verdict, Verdict::EnergyGained, "{case}");
                assert!(
                    o.energy_change <= 1e-10 * t0,
                    "{case}: ΔT = {:e}",
                    o.energy_change
                );
                let dt = out.energy_change_from_velocities.unwrap();
                assert!((dt - o.energy_change).abs() < 1e-10 * t0, "{case}");
                if e == 1.0 {
                    assert!(o.energy_change.abs() < 1e-10 * t0, "{case}: ΔT = {dt:e}");
                }
                if e == 0.0 {
                    // Perfectly plastic: the balls move on together.
                    for xi in &x {
                        assert!((xi - v0 / n as f64).abs() < 1e-8 * v0, "{case}: {x:?}");
                    }
                }
                for b in 0..n - 1 {
                    assert!(x[b] <= x[b + 1] + 1e-9 * v0, "{case}: {x:?}");
                }
                for c in &o.contacts {
                    assert!(c.velocity_after.y >= -1e-9 * v0, "{case}: {c:?}");
                }
            }
        }
    }
}
