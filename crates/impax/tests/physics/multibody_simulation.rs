//! The spatial simulation (`impax::multibody::simulate`) against closed forms and its own
//! ledger: a free sphere bouncing with restitution `e` (apex heights in the ratio `e²`, the
//! first impact at the free-fall time), a brick and a rod dropped at random angles (no sample
//! below the floor, the energy ledger balanced, `energetic` never gaining energy), and solo12
//! dropped on its feet (the first foot impact at the free-fall time of its lowest foot, and a
//! named stop).

use super::multibody_models::{solo12, FEET};
use impax::math::{Mat3, SplitMix64, Vec3};
use impax::multibody::simulate::{simulate, Persistence, Run, SimulationOptions, StopReason};
use impax::multibody::{
    contact_position, forward_kinematics, Body, BodyPose, ContactPoint, Joint, Model,
};
use impax::LawId;

const G: f64 = 9.81;

/// A free body with the given contacts (points in its frame), under gravity, floor `z = 0`.
fn free_body(mass: f64, inertia: Vec3, contacts: &[(&str, Vec3, f64)]) -> Model {
    let body = Body::new("body", mass, Vec3::zeros(), Mat3::from_diagonal(&inertia));
    let contacts = contacts
        .iter()
        .map(|(n, p, r)| ContactPoint::new(n, 0, *p, *r))
        .collect();
    Model::new(vec![body], vec![Joint::free("root", 0)], contacts).unwrap()
}

/// A ball of mass 1 and radius 0.1 (`I = 2/5 m r²`), its contact its lowest point.
fn ball() -> Model {
    let i = 0.4 * 0.01;
    free_body(1.0, Vec3::new(i, i, i), &[("bottom", Vec3::zeros(), 0.1)])
}

/// A brick 0.4 × 0.2 × 0.1 m of 1 kg with its eight corners as contacts.
pub(super) fn brick() -> Model {
    let (a, b, c) = (0.2, 0.1, 0.05);
    let m = 1.0;
    let inertia = Vec3::new(
        m * (b * b + c * c) / 3.0,
        m * (a * a + c * c) / 3.0,
        m * (a * a + b * b) / 3.0,
    );
    let names: Vec<String> = (0..8).map(|i| format!("corner {i}")).collect();
    let corners: Vec<(&str, Vec3, f64)> = (0..8)
        .map(|i| {
            let s = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
            (
                names[i].as_str(),
                Vec3::new(s(1) * a, s(2) * b, s(4) * c),
                0.0,
            )
        })
        .collect();
    free_body(m, inertia, &corners)
}

/// A rod of length 1 and radius 0.02 along its x axis, its two ends as contacts.
fn rod() -> Model {
    let (m, l, r) = (1.0, 1.0, 0.02);
    let across = m * (3.0 * r * r + l * l) / 12.0;
    free_body(
        m,
        Vec3::new(m * r * r / 2.0, across, across),
        &[
            ("end A", Vec3::new(-0.5, 0.0, 0.0), 0.0),
            ("end B", Vec3::new(0.5, 0.0, 0.0), 0.0),
        ],
    )
}

/// Every contact's height at `q`.
fn heights(model: &Model, q: &[f64]) -> Vec<f64> {
    let mut poses = vec![BodyPose::identity(); model.bodies().len()];
    forward_kinematics(model, q, &mut poses);
    (0..model.contacts().len())
        .map(|k| contact_position(model, &poses, k)[2])
        .collect()
}

/// The lowest gap over the run's samples.
fn lowest_gap(model: &Model, run: &Run) -> f64 {
    run.samples
        .iter()
        .flat_map(|s| heights(model, &s.q))
        .fold(f64::INFINITY, f64::min)
        - model.floor()
}

/// A random unit quaternion `(w, x, y, z)`.
pub(super) fn quaternion(rng: &mut SplitMix64) -> [f64; 4] {
    loop {
        let q = [0; 4].map(|_| rng.range(-1.0, 1.0));
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n > 0.1 && n < 1.0 {
            return q.map(|x| x / n);
        }
    }
}

/// A state of a free body dropped with its lowest contact `height` above the floor.
fn dropped(model: &Model, rng: &mut SplitMix64, height: f64, speed: f64) -> (Vec<f64>, Vec<f64>) {
    let mut q = model.neutral();
    q[3..7].copy_from_slice(&quaternion(rng));
    let low = heights(model, &q).into_iter().fold(f64::INFINITY, f64::min);
    q[2] += height - low;
    let u: Vec<f64> = (0..6).map(|_| speed * rng.range(-1.0, 1.0)).collect();
    (q, u)
}

/// A ball dropped from 1 m bounces with `e`: each bounce leaves at `e` times the speed it
/// arrived with, so the apex heights `v⁺²/2g` fall by `e²` (to 1e-9 over 20 bounces); the
/// first impact is at the free-fall time `√(2h/g)`; the bounces accumulate and the run stops
/// naming the contact; the ledger balances.
#[test]
fn multibody_simulation_sphere_bounces_with_restitution() {
    let model = ball();
    let e = 0.8;
    let q = [0.3, -0.2, 1.1, 1.0, 0.0, 0.0, 0.0];
    let options = SimulationOptions::new(LawId::Energetic, 0.3, e, 5.0);
    let run = simulate(&model, &q, &[0.0; 6], &options).unwrap();
    let fall = (2.0 * 1.0 / G).sqrt();
    assert!(
        (run.impacts[0].time - fall).abs() < 1e-12,
        "{}",
        run.impacts[0].time - fall
    );
    assert!(run.impacts.len() > 20, "{} impacts", run.impacts.len());
    let apex: Vec<f64> = run
        .impacts
        .iter()
        .map(|i| i.u_after[2] * i.u_after[2] / (2.0 * G))
        .collect();
    let mut worst = 0.0f64;
    for k in 0..20 {
        worst = worst.max((apex[k + 1] / apex[k] - e * e).abs());
    }
    assert!(worst < 1e-9, "apex ratio off e² by {worst:e}");
    let StopReason::PersistentContact { contact, cause } = &run.stop else {
        panic!("{:?}", run.stop)
    };
    assert_eq!(*contact, 0);
    let Persistence::Accumulation { limit_time, ratio } = cause else {
        panic!("{cause:?}")
    };
    assert!((ratio - e).abs() < 1e-4 * e, "ratio {ratio}");
    // The bouncing ball's t∞ = t₁ + 2 e v₁ / (g (1 − e)), v₁ = √(2 g h).
    let v1 = (2.0 * G).sqrt();
    let t_inf = fall + 2.0 * e * v1 / (G * (1.0 - e));
    assert!((limit_time - t_inf).abs() < 1e-6, "{limit_time} vs {t_inf}");
    assert!(lowest_gap(&model, &run) > -1e-12);
    let l = run.ledger;
    assert!(l.residual().abs() < 1e-9 * l.initial, "{l:?}");
    assert!(l.drift.abs() < 1e-9 * l.initial, "{l:?}");
    eprintln!(
        "sphere: {} impacts, apex ratio within {worst:.1e} of e², first impact {:.1e} off √(2h/g), ledger residual {:.1e}, drift {:.1e}, {} steps",
        run.impacts.len(),
        run.impacts[0].time - fall,
        l.residual(),
        l.drift,
        run.steps.0
    );
}

/// A brick and a rod dropped at random orientations, heights and speeds, with random `μ` and
/// `e`, under `energetic`: no sample has a corner below the floor, the ledger balances to 1e-9
/// of the initial energy, no impact gains energy, and every run ends by a named reason.
#[test]
fn multibody_simulation_random_drops_never_gain_energy() {
    let mut rng = SplitMix64(0x5eed_0d20_9f11);
    let (mut impacts, mut multi, mut lowest, mut residual) = (0usize, 0usize, 0.0f64, 0.0f64);
    let mut stops = std::collections::BTreeMap::new();
    for drop in 0..60 {
        let model = if drop % 2 == 0 { brick() } else { rod() };
        let height = rng.range(0.05, 0.5);
        let (q, u) = dropped(&model, &mut rng, height, 2.0);
        let (mu, e) = (rng.range(0.0, 1.2), rng.range(0.0, 1.0));
        let options = SimulationOptions::new(LawId::Energetic, mu, e, 2.0);
        let run = simulate(&model, &q, &u, &options)
            .unwrap_or_else(|err| panic!("drop {drop}: {err}\nq = {q:?}\nu = {u:?}"));
        for i in &run.impacts {
            let scale = i.kinetic_before;
            assert!(
                i.law_energy_change <= 1e-12 * scale && i.energy_change <= 1e-12 * scale,
                "drop {drop}: impact at {} gains {} ({} from the speeds), law {}",
                i.time,
                i.law_energy_change,
                i.energy_change,
                i.law
            );
            multi += usize::from(i.contacts.len() > 1);
        }
        impacts += run.impacts.len();
        let low = lowest_gap(&model, &run);
        assert!(
            low > -1e-10,
            "drop {drop}: a sample {low:e} below the floor"
        );
        lowest = lowest.min(low);
        let l = run.ledger;
        assert!(
            l.residual().abs() < 1e-9 * l.initial,
            "drop {drop}: ledger {l:?}"
        );
        residual = residual.max(l.residual().abs() / l.initial);
        *stops.entry(run.stop.id()).or_insert(0) += 1;
    }
    eprintln!(
        "60 drops: {impacts} impacts ({multi} at several contacts), lowest sample {lowest:.1e}, largest ledger residual {residual:.1e} of T + V, stops {stops:?}"
    );
}

/// solo12 (floating base) released at rest with its lowest foot `h` above the floor falls
/// without rotating (uniform gravity moves every body alike): that foot strikes first, at
/// `√(2h/g)`. With `e = 0` the feet are left on the floor, and the run stops where one stays,
/// naming it.
#[test]
fn multibody_simulation_solo12_first_foot_at_free_fall_time() {
    let model = solo12(true);
    let mut q = model.neutral();
    // Each leg bent differently: hip, knee per leg (the feet at different heights).
    let legs = [
        [0.1, 0.7, -1.4],
        [-0.1, 0.8, -1.6],
        [0.0, -0.6, 1.2],
        [0.05, -0.9, 1.7],
    ];
    for (leg, angles) in legs.iter().enumerate() {
        q[7 + 3 * leg..10 + 3 * leg].copy_from_slice(angles);
    }
    let h0 = heights(&model, &q);
    let (lowest, low) = h0
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map(|(k, z)| (k, *z))
        .unwrap();
    let h = 0.2;
    q[2] += h - low;
    for e in [0.0, 0.5] {
        let options = SimulationOptions::new(LawId::Energetic, 0.8, e, 1.5);
        let run = simulate(&model, &q, &[0.0; 18], &options).unwrap();
        let first = &run.impacts[0];
        assert_eq!(first.contacts, vec![lowest], "{}", FEET[lowest]);
        let fall = (2.0 * h / G).sqrt();
        assert!(
            (first.time - fall).abs() < 1e-10,
            "{} vs {fall}",
            first.time
        );
        // Until the impact the base neither turns nor moves sideways.
        let before = &first.u_before;
        assert!(before[..2]
            .iter()
            .chain(&before[3..])
            .all(|x| x.abs() < 1e-9));
        assert!(lowest_gap(&model, &run) > -1e-10);
        let l = run.ledger;
        assert!(l.residual().abs() < 1e-9 * l.initial.abs(), "{l:?}");
        if e == 0.0 {
            // A plastic impact leaves its foot on the floor with zero normal velocity: the run
            // goes on while that foot's normal acceleration lifts it (the leg swung by the
            // impulse), and stops at the first foot that stays pressed.
            let StopReason::PersistentContact { contact, cause } = &run.stop else {
                panic!("{:?}", run.stop)
            };
            assert_eq!(*cause, Persistence::Closed);
            assert!(run.impacts.last().unwrap().contacts.contains(contact));
            assert!(run
                .impacts
                .iter()
                .all(|i| i
                    .outcome
                    .contacts
                    .iter()
                    .all(|c| c.velocity_after.z.abs() < 1e-12)));
        }
        assert_ne!(run.stop, StopReason::TimeLimit, "e = {e}");
        eprintln!(
            "solo12 e = {e}: first impact ({}) {:.1e} off √(2h/g); {} impacts; stop {:?} at {:.6}; ledger residual {:.1e}, drift {:.1e}; quaternion drift {:.1e}",
            FEET[lowest],
            first.time - fall,
            run.impacts.len(),
            run.stop,
            run.end_time,
            l.residual(),
            l.drift,
            run.quaternion_drift
        );
    }
}
