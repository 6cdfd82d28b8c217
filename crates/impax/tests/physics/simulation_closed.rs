//! Contacts that stay closed in the simulation: a rod dropped at any angle comes to rest lying
//! flat, never below the floor, its energy ledger closed; a block and a rod sliding flat on
//! the floor decelerate at `μ g` and stop at `v²/(2 μ g)` (closed form); the velocity-product
//! terms of the contact rows against central differences; a double pendulum comes to rest
//! with its tip on the floor.

use impax::law::LawId;
use impax::mechanism::builtin::{Block, Cradle, DoublePendulum, Rod, Sphere};
use impax::mechanism::{dynamics, Mechanism};
use impax::simulation::scenarios::{double_pendulum_drop, rod_drop, Initial};
use impax::simulation::{simulate, EventKind, Mode, Regime, Run, SimulationOptions, StopReason};
use nalgebra::DVector;

const G: f64 = 9.81;

/// The deepest penetration of any contact over the samples and impacts of a run, in units of
/// the contact's touching tolerance (≤ 1 passes).
fn worst_penetration<M: Mechanism>(m: &M, run: &Run) -> f64 {
    let states = run
        .samples
        .iter()
        .map(|s| s.q.as_slice())
        .chain(run.impacts.iter().map(|i| i.q.as_slice()));
    let mut worst: f64 = 0.0;
    for q in states {
        for k in 0..m.contacts().len() {
            worst = worst.max(-dynamics::gap(m, k, q) / dynamics::touching_tolerance(m, k, q));
        }
    }
    worst
}

fn run(init: &Initial, law: LawId, mu: f64, e: f64, until: f64) -> Run {
    simulate(
        &init.mechanism,
        &init.q,
        &init.u,
        &SimulationOptions::new(law, mu, e, until),
    )
    .unwrap()
}

/// A unit rod dropped from 0.5 m at 0°, 10°, 50° and 89° with several `e` and `μ`: the run
/// ends at rest lying flat on the floor (θ ≡ 0 mod π within 1e-6, y = 0 within the touching
/// tolerance), no sample has an end below the floor, and the energy ledger closes:
/// `T + V` at the end equals the initial one plus the impacts' `ΔT` and the friction's work
/// while sliding, to the integration's tolerance (the projections and completions of
/// accumulations change it by less than 1e-8 of the drop's energy).
#[test]
fn rod_drops_end_at_rest_lying_flat_with_the_ledger_closed() {
    let mut worst_residual: f64 = 0.0;
    let mut worst_corrections: f64 = 0.0;
    for angle in [0.0, 10.0, 50.0, 89.0] {
        for e in [0.0, 0.3, 0.5] {
            for mu in [0.0, 0.3, 1.0] {
                let init = rod_drop(1.0, 1.0, f64::to_radians(angle), 0.5, G).unwrap();
                let r = run(&init, LawId::Energetic, mu, e, 4.0);
                let what = format!("{angle}°, e = {e}, μ = {mu}");
                assert_eq!(r.stop, StopReason::Rest, "{what}");
                let last = r.samples.last().unwrap();
                assert_eq!(last.mode, Mode::Rest, "{what}");
                assert!(last.u.iter().all(|&v| v == 0.0), "{what}");
                let turns = last.q[2] / std::f64::consts::PI;
                assert!(
                    (turns - turns.round()).abs() * std::f64::consts::PI < 1e-6,
                    "{what}: θ = {}",
                    last.q[2]
                );
                let m = &init.mechanism;
                let tol = dynamics::touching_tolerance(m, 0, &last.q);
                assert!(last.q[1].abs() <= tol, "{what}: y = {}", last.q[1]);
                for k in 0..2 {
                    assert!(dynamics::gap(m, k, &last.q).abs() <= tol, "{what}");
                }
                assert!(worst_penetration(m, &r) <= 1.0, "{what}");
                // The ledger: the impacts' ΔT as recorded, the end as the last sample's.
                let l = &r.ledger;
                let e0 = dynamics::potential_energy(m, &init.q); // dropped from rest
                assert!((l.initial - e0).abs() <= 1e-15 * e0, "{what}");
                let impacts: f64 = r.impacts.iter().map(|i| i.energy_change).sum();
                assert_eq!(l.impacts, impacts);
                assert_eq!(l.end, last.kinetic + last.potential);
                let residual = (l.end - l.initial - l.impacts - l.contact_work).abs() / e0;
                assert!(residual <= 1e-8, "{what}: {residual:e} ({l:?})");
                assert!(l.residual().abs() <= 1e-12 * e0, "{what}: {l:?}");
                assert!(
                    l.contact_work <= 1e-12 * e0,
                    "{what}: friction does no positive work"
                );
                worst_residual = worst_residual.max(l.residual().abs() / e0);
                worst_corrections = worst_corrections.max(l.corrections.abs() / e0);
            }
        }
    }
    println!(
        "36 rod drops at rest lying flat; ledger residual ≤ {worst_residual:.1e}, corrections ≤ {worst_corrections:.1e} of the drop's energy"
    );
}

/// The default rod drop (30°, μ = e = 0.5): its closing events are named and the rod ends where
/// both ends rest, after impacts at both ends together under `lcp`.
#[test]
fn the_default_rod_drop_closes_both_ends_and_rests() {
    let init = rod_drop(1.0, 1.0, 30f64.to_radians(), 0.5, G).unwrap();
    let r = run(&init, LawId::Energetic, 0.5, 0.5, 3.0);
    assert_eq!(r.stop, StopReason::Rest);
    let closes: Vec<usize> = r
        .events
        .iter()
        .filter_map(|(_, e)| match e {
            EventKind::Closes { contact, .. } => Some(*contact),
            _ => None,
        })
        .collect();
    assert!(closes.contains(&0) && closes.contains(&1), "{closes:?}");
    let multi: Vec<_> = r.impacts.iter().filter(|i| i.contacts.len() == 2).collect();
    assert!(!multi.is_empty());
    for i in multi {
        assert_eq!(i.law, LawId::Lcp);
        assert_eq!(i.contacts[0], i.contact);
        assert_eq!(i.outcome.contacts.len(), 2);
    }
    for i in r.impacts.iter().filter(|i| i.contacts.len() == 1) {
        assert_eq!(i.law, LawId::Energetic);
    }
}

/// Under `sequential` (a multi-contact law) the impacts at both ends use it.
#[test]
fn a_multi_contact_law_is_used_for_impacts_at_several_contacts() {
    let init = rod_drop(1.0, 1.0, 0.0, 0.5, G).unwrap();
    let r = run(&init, LawId::Sequential, 0.5, 0.5, 3.0);
    assert_eq!(r.impacts[0].contacts, vec![0, 1]);
    assert_eq!(r.impacts[0].law, LawId::Sequential);
    assert_eq!(r.stop, StopReason::Rest);
}

/// A block (half-width 0.5, half-height 0.1: it cannot tip, μ h < b) sliding on the floor at
/// `v0 = 2` with `μ = 0.4`: `x(t) = v0 t − ½ μ g t²`, `ẋ = v0 − μ g t`, at rest at
/// `t* = v0/(μ g)`, `x* = v0²/(2 μ g)`; the friction's work is the kinetic energy `½ m v0²`.
#[test]
fn a_block_sliding_on_the_floor_decelerates_at_mu_g_and_stops() {
    let (v0, mu) = (2.0, 0.4);
    let block = Block::new(1.0, 0.5, 0.1, G, 0.0).unwrap();
    let r = simulate(
        &block,
        &[0.0, 0.1, 0.0],
        &[v0, 0.0, 0.0],
        &SimulationOptions::new(LawId::Energetic, mu, 0.5, 2.0),
    )
    .unwrap();
    assert_eq!(r.stop, StopReason::Rest);
    let t_stop = v0 / (mu * G);
    assert!(
        (r.end_time - t_stop).abs() <= 1e-12 * t_stop,
        "{}",
        r.end_time
    );
    let mut worst: f64 = 0.0;
    for s in &r.samples {
        let t = s.t.min(t_stop);
        worst = worst
            .max((s.q[0] - (v0 * t - 0.5 * mu * G * t * t)).abs())
            .max((s.u[0] - (v0 - mu * G * t)).abs())
            .max(s.q[1] - 0.1)
            .max(s.q[2].abs());
        if s.mode == Mode::Contact {
            assert!(s.u[0] >= -1e-15, "{s:?}");
        }
    }
    println!("sliding block against the closed form: worst difference {worst:.1e}");
    assert!(worst < 1e-12, "{worst:e}");
    // Both corners closed sliding at the start, sticking at the stop.
    assert!(r.events.contains(&(
        0.0,
        EventKind::Closes {
            contact: 0,
            regime: Regime::Slip(impax::planar::SlipDirection::Positive)
        }
    )));
    assert!(r.events.iter().any(|(t, e)| *t == r.end_time
        && matches!(
            e,
            EventKind::Regime {
                regime: Regime::Stick,
                ..
            }
        )));
    let l = &r.ledger;
    assert!((l.contact_work + 0.5 * v0 * v0).abs() < 1e-12, "{l:?}");
    assert!(l.residual().abs() < 1e-12);
}

/// A rod lying flat on the floor sliding at `v0`: it stops after `v0²/(2 μ g)` (its ends share
/// the weight and the friction equally).
#[test]
fn a_rod_sliding_flat_stops_at_v_squared_over_two_mu_g() {
    let rod = Rod::new(2.0, 1.5, G, 0.0).unwrap();
    for (v0, mu) in [(2.0, 0.4), (-1.0, 0.7), (3.0, 0.1)] {
        let r = simulate(
            &rod,
            &[0.0, 0.0, 0.0],
            &[v0, 0.0, 0.0],
            &SimulationOptions::new(LawId::Energetic, mu, 0.5, 10.0),
        )
        .unwrap();
        assert_eq!(r.stop, StopReason::Rest);
        let last = r.samples.last().unwrap();
        let d = v0 * v0.abs() / (2.0 * mu * G);
        assert!(
            (last.q[0] - d).abs() < 1e-12 * d.abs(),
            "{} vs {d}",
            last.q[0]
        );
        assert!((r.end_time - v0.abs() / (mu * G)).abs() < 1e-12);
        assert!(last.q[1].abs() < 1e-15 && last.q[2].abs() < 1e-15);
    }
}

/// `J̇ u` of the contact rows (tangent, normal) from one hyper-dual pass equals the central
/// difference `(J(q + h u) − J(q − h u)) u / 2h` for a rod, a block, a sphere, a double
/// pendulum and a cradle at random states; the normal term equals `φ̈` of `gap_rates` at
/// `u̇ = 0`.
/// The rows `J u`, the products `J̇ u` and `φ̈` at `u̇ = 0` of contact `k` at `q`.
type Rows<'a> = dyn Fn(&[f64], usize) -> (DVector<f64>, [f64; 2], f64) + 'a;

#[test]
fn contact_velocity_products_match_central_differences() {
    let mut rng = impax::math::SplitMix64(5);
    let mut worst: f64 = 0.0;
    let check = |m: &Rows, q: &[f64], u: &[f64], k: usize, worst: &mut f64| {
        let h = 1e-5;
        let plus: Vec<f64> = q.iter().zip(u).map(|(a, b)| a + h * b).collect();
        let minus: Vec<f64> = q.iter().zip(u).map(|(a, b)| a - h * b).collect();
        let (jp, _, _) = m(&plus, k);
        let (jm, _, _) = m(&minus, k);
        let (_, exact, phi_dd) = m(q, k);
        let scale = 1.0 + exact[0].abs().max(exact[1].abs());
        for r in 0..2 {
            let fd = (jp[r] - jm[r]) / (2.0 * h);
            *worst = worst.max((fd - exact[r]).abs() / scale);
            assert!(
                (fd - exact[r]).abs() < 1e-6 * scale,
                "row {r}: {fd} vs {}",
                exact[r]
            );
        }
        assert!((phi_dd - exact[1]).abs() <= 1e-12 * scale);
    };
    fn of<'a, M: Mechanism>(
        m: &'a M,
        u: &[f64],
    ) -> impl Fn(&[f64], usize) -> (DVector<f64>, [f64; 2], f64) + 'a {
        let u = u.to_vec();
        move |q: &[f64], k: usize| {
            let kin = dynamics::kinematics(m, q);
            let j = dynamics::contact_jacobian_of(m, k, q, &kin);
            let ju = &j * DVector::from_column_slice(&u);
            let zero = vec![0.0; u.len()];
            let [_, _, phi_dd] = dynamics::gap_rates(m, k, q, &u, &zero);
            (ju, dynamics::contact_velocity_products(m, k, q, &u), phi_dd)
        }
    }
    for _ in 0..20 {
        let mut r = |a: f64, b: f64| rng.range(a, b);
        let u3 = [r(-2.0, 2.0), r(-2.0, 2.0), r(-5.0, 5.0)];
        let q3 = [r(-1.0, 1.0), r(0.5, 2.0), r(-3.0, 3.0)];
        let rod = Rod::new(1.3, 0.8, G, 0.0).unwrap();
        let block = Block::new(2.0, 0.3, 0.7, G, 0.0).unwrap();
        let sphere = Sphere::new(1.0, 0.4, G, 0.0).unwrap();
        for k in 0..2 {
            check(&of(&rod, &u3), &q3, &u3, k, &mut worst);
        }
        for k in 0..4 {
            check(&of(&block, &u3), &q3, &u3, k, &mut worst);
        }
        check(&of(&sphere, &u3), &q3, &u3, 0, &mut worst);
        let dp = DoublePendulum::new(1.0, 0.7, 1.0, 0.8, G, -1.5).unwrap();
        let (q2, u2) = ([r(-3.0, 3.0), r(-3.0, 3.0)], [r(-3.0, 3.0), r(-3.0, 3.0)]);
        for k in 0..2 {
            check(&of(&dp, &u2), &q2, &u2, k, &mut worst);
        }
        let cradle = Cradle::new(3, 1.0, 0.5).unwrap();
        let q9: Vec<f64> = (0..9).map(|i| i as f64 * 0.4 + r(-0.1, 0.1)).collect();
        let u9: Vec<f64> = (0..9).map(|_| r(-2.0, 2.0)).collect();
        for k in 0..2 {
            check(&of(&cradle, &u9), &q9, &u9, k, &mut worst);
        }
    }
    println!("J̇u against central differences: worst relative {worst:.1e}");
}

/// Kane's double pendulum dropped onto the floor (μ = e = 0.5) comes to rest with its tip on
/// the floor, held there by the tip's force (a static equilibrium: the closed contact's force
/// balances gravity with no acceleration), and no contact went below the floor.
#[test]
fn a_double_pendulum_drop_comes_to_rest_on_its_tip() {
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
    let r = run(&init, LawId::Energetic, 0.5, 0.5, 3.0);
    assert_eq!(r.stop, StopReason::Rest);
    let m = &init.mechanism;
    let last = r.samples.last().unwrap();
    let tol = dynamics::touching_tolerance(m, 0, &last.q);
    assert!(dynamics::gap(m, 0, &last.q).abs() <= tol);
    assert!(worst_penetration(m, &r) <= 1.0);
    assert!(r
        .events
        .iter()
        .any(|(_, e)| matches!(e, EventKind::Closes { contact: 0, .. })));
    assert!(r.ledger.residual().abs() < 1e-9);
}
