//! Regression: the planar simulation depended on the unit of mass, and a hopeless run spent
//! its whole step budget before failing.
//!
//! Found by an adversarial run of the command line: `impax simulate rocking-block --until 0.5
//! --mass 2.7e60` gave no answer within a minute (the debug build) and failed with
//! "integration: too many steps" after 23 s in the release build; from `--mass 1e12` on it
//! failed so, and at `--mass 1e6` it took ten times as long as at 1. The work of the closed
//! contacts' forces, integrated with the motion, was judged against the integrator's
//! absolute tolerance (1e-14) in the problem's units of energy: its round-off (`∝ m`) alone
//! made every step fail. The work is now integrated in units of the run's energy scale. And
//! `impax simulate` of a cart-pendulum spinning at 10⁷ rad/s for 0.3 s ran its million steps
//! (8 s) before failing with the same message; the run's steps now have the budget the 3D run
//! has, with its early verdict naming `until`.
//!
//! A rod of 1 µm (`impax simulate rod-drop --length 1e-6 --height 5e-7`) was refused: "mass
//! matrix: must be positive definite, but singular" — its `M_θθ = m l²/12 ≈ 8e-14 m` was
//! judged against the largest diagonal entry, `m`, in other units. A pivot is now judged
//! against its own coordinate's diagonal entry.
//!
//! Expected: the motion of a mechanism does not depend on the unit of mass — the same
//! positions at every sample, the same impacts at the same times, the energies and the
//! ledger scaled by the factor — from 1e-30 to 1e60; a run that cannot finish is refused
//! after its first thousand steps, naming `until`.

use impax::law::LawId;
use impax::mechanism::builtin::CartPendulum;
use impax::simulation::scenarios::{rocking_block, rod_drop};
use impax::simulation::{simulate, SimulationOptions};

#[test]
fn the_rocking_block_moves_alike_in_every_unit_of_mass() {
    let opts = SimulationOptions::new(LawId::Energetic, 1.0, 0.0, 0.5);
    let run_of = |m: f64| {
        let init = rocking_block(m, 0.2, 0.6, f64::to_radians(10.0), 0.0, 9.81).unwrap();
        simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap()
    };
    let base = run_of(1.0);
    assert!(!base.impacts.is_empty());
    for m in [2f64.powi(40), 1e6, 1e12, 2.7312176019499322e60, 1e-30] {
        let run = run_of(m);
        assert_eq!(run.stop.id(), base.stop.id(), "mass {m:e}");
        assert_eq!(run.impacts.len(), base.impacts.len(), "mass {m:e}");
        for (a, b) in base.impacts.iter().zip(&run.impacts) {
            assert!(
                (a.time - b.time).abs() < 1e-9,
                "mass {m:e}: {} vs {}",
                a.time,
                b.time
            );
        }
        assert_eq!(run.samples.len(), base.samples.len(), "mass {m:e}");
        for (a, b) in base.samples.iter().zip(&run.samples) {
            for (x, y) in a.q.iter().zip(&b.q) {
                assert!(
                    (x - y).abs() < 1e-9,
                    "mass {m:e} at t = {}: {x} vs {y}",
                    a.t
                );
            }
        }
        let (l0, l) = (&base.ledger, &run.ledger);
        assert!((l.initial / m - l0.initial).abs() < 1e-12 * l0.initial);
        assert!((l.end / m - l0.end).abs() < 1e-9 * l0.initial);
        assert!(l.residual().abs() < 1e-9 * l.initial, "mass {m:e}: {l:?}");
    }
}

#[test]
fn a_run_that_cannot_finish_is_refused_early_naming_until() {
    let cart = CartPendulum::new(1.0, 1.0, 1.0, 9.81).unwrap();
    let opts = SimulationOptions::new(LawId::Energetic, 1.0, 0.0, 0.3);
    let err = simulate(&cart, &[0.0, 0.5], &[0.5, 1e7], &opts).unwrap_err();
    assert_eq!(err.field(), "until", "{err}");
    // The early verdict (a projection from the first thousand steps), not the spent budget.
    assert!(err.to_string().contains("at its pace so far"), "{err}");
}

#[test]
fn a_rod_of_a_micrometre_falls_as_one_of_a_metre_in_its_own_time() {
    // Lengths × s: times × √s, energies × s (g and m fixed).
    let s = 1e-6;
    let run_of = |l: f64, until: f64| {
        let init = rod_drop(1.0, l, f64::to_radians(30.0), 0.5 * l, 9.81).unwrap();
        let opts = SimulationOptions::new(LawId::Energetic, 0.5, 0.0, until);
        simulate(&init.mechanism, &init.q, &init.u, &opts).unwrap()
    };
    let (big, small) = (run_of(1.0, 3.0), run_of(s, 3.0 * s.sqrt()));
    assert_eq!(small.stop.id(), "rest");
    assert_eq!(big.stop.id(), small.stop.id());
    assert_eq!(big.impacts.len(), small.impacts.len());
    for (a, b) in big.impacts.iter().zip(&small.impacts) {
        assert!(
            (a.time * s.sqrt() - b.time).abs() < 1e-9 * s.sqrt(),
            "{a:?} vs {b:?}"
        );
    }
    assert!((big.end_time * s.sqrt() - small.end_time).abs() < 1e-9 * s.sqrt());
    assert!((big.ledger.initial * s - small.ledger.initial).abs() < 1e-12 * s);
}

/// Found beside the above: `impax compare ball-ball-wall --v0 1e-200` printed `T+/T-` as
/// `NaN` (and JSON `null`) for every law, the kinetic energy `5e-401` underflowing to 0; the
/// header printed `v0` with two hundred digits. Velocities whose kinetic energy is below
/// `1e-290` are now refused naming `u`, as those above `1e300` were; `1e-120` works.
#[test]
fn a_kinetic_energy_below_representable_is_refused_naming_u() {
    use impax::multi::scenarios::BallBallWall;
    let tiny = BallBallWall {
        v0: 1e-200,
        ..BallBallWall::default()
    };
    let err = tiny.build().unwrap_err();
    assert_eq!(err.field(), "u", "{err}");
    let small = BallBallWall {
        v0: 1e-120,
        ..BallBallWall::default()
    }
    .build()
    .unwrap();
    assert!(
        small.description.contains("v0 = 1e-120"),
        "{}",
        small.description
    );
}
