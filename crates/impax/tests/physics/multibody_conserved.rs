//! Conserved quantities of spatial free motion (`multibody::conserved`): `∂L/∂q` against
//! central differences; what each symmetry promises (the energy, the momenta of cyclic
//! coordinates, `P_x`, `P_y`, `L_z` of a floating base, all of `P` and `L` without gravity)
//! conserved to the integrator's tolerance along random free motions of solo12 and a brick;
//! the quantities whose symmetry is broken (gravity along `P_z`, the support of a fixed base)
//! visibly changing; and the step budget that stops a state spinning at 10⁷ rad/s.

use super::multibody_models::solo12;
use super::multibody_simulation::{brick, quaternion};
use impax::math::{SplitMix64, Vec3};
use impax::multibody::conserved::{
    lagrangian_gradient, tested_coordinates, track, QuantityKind, Track, TrackOptions, Tracking,
};
use impax::multibody::{kinetic_energy, potential_energy, Model, Workspace};

/// `∂L/∂q_i` by automatic differentiation equals central differences of
/// `L = ½ uᵀ M(q) u − V(q)` (CRBA) on solo12's joints and base position, at random states.
#[test]
fn multibody_conserved_lagrangian_gradient_matches_differences() {
    let model = solo12(true);
    let mut rng = SplitMix64(0x1a9_7a9e);
    let lagrangian = |q: &[f64], u: &[f64]| {
        let mut ws = Workspace::new(&model);
        ws.update(&model, q).unwrap();
        kinetic_energy(&model, &mut ws, u) - potential_energy(&model, &ws).0
    };
    let mut worst = 0.0f64;
    for _ in 0..20 {
        let mut q = model.neutral();
        q[3..7].copy_from_slice(&quaternion(&mut rng));
        for x in q.iter_mut().skip(7) {
            *x = rng.range(-2.0, 2.0);
        }
        let u: Vec<f64> = (0..18).map(|_| rng.range(-2.0, 2.0)).collect();
        for i in tested_coordinates(&model) {
            let d = lagrangian_gradient(&model, &q, &u, i);
            let h = 1e-5;
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[i] += h;
            qm[i] -= h;
            let fd = (lagrangian(&qp, &u) - lagrangian(&qm, &u)) / (2.0 * h);
            let scale = d.magnitude.max(lagrangian(&q, &u).abs());
            worst = worst.max((d.value - fd).abs() / scale);
        }
    }
    assert!(worst < 1e-7, "{worst:e}");
    eprintln!("∂L/∂q against central differences: largest relative difference {worst:.1e}");
}

/// The tracks of a free motion by name.
fn by_name<'a>(tracking: &'a Tracking, name: &str) -> &'a Track {
    tracking
        .tracks
        .iter()
        .find(|t| t.name == name)
        .unwrap_or_else(|| panic!("no track {name}"))
}

/// solo12 flying free without gravity: `P`, `L` about a point and `E` are conserved to the
/// integrator's tolerance, and so are the momenta of `x, y, z`, found cyclic; its joints are
/// not cyclic.
#[test]
fn multibody_conserved_free_flying_robot() {
    let model = solo12(true).with_gravity(0.0).unwrap();
    let mut rng = SplitMix64(0xf1e_e0f1);
    let mut q = model.neutral();
    q[3..7].copy_from_slice(&quaternion(&mut rng));
    for x in q.iter_mut().skip(7) {
        *x = rng.range(-1.5, 1.5);
    }
    let u: Vec<f64> = (0..18).map(|_| rng.range(-2.0, 2.0)).collect();
    let options = TrackOptions {
        duration: 2.0,
        intervals: 200,
        ..TrackOptions::default()
    };
    let about = [Vec3::zeros(), Vec3::new(1.0, -2.0, 0.5)];
    let tracking = track(&model, &q, &u, &about, options).unwrap();
    assert_eq!(tracking.cyclic, [0, 1, 2]);
    let mut worst = 0.0f64;
    for name in [
        "energy",
        "P_x",
        "P_y",
        "P_z",
        "p_vx",
        "p_vy",
        "p_vz",
        "L_x(0, 0, 0)",
        "L_y(0, 0, 0)",
        "L_z(0, 0, 0)",
        "L_x(1, -2, 0.5)",
        "L_z(1, -2, 0.5)",
    ] {
        let t = by_name(&tracking, name);
        assert!(t.conserved(1e-9), "{name}: {:e}", t.relative_deviation());
        worst = worst.max(t.relative_deviation());
    }
    // The joints' momenta change (the legs exchange momentum with the base).
    assert!(!by_name(&tracking, "p_FL_KFE").conserved(1e-3));
    eprintln!(
        "free-flying solo12 over 2 s: energy, P, L, p_x,y,z within {worst:.1e}; {} steps",
        tracking.steps.0
    );
}

/// A brick spinning in flight under gravity: `x`, `y` cyclic, `P_x`, `P_y`, `L_z` and `E`
/// conserved; `P_z`, `L_x`, `L_y` not.
#[test]
fn multibody_conserved_brick_under_gravity() {
    let model = brick();
    let n = (0.81f64 + 0.09 + 0.04 + 0.01).sqrt();
    let q = [0.1, 0.2, 1.0, 0.9 / n, 0.3 / n, -0.2 / n, 0.1 / n];
    let u = [0.5, -0.3, 3.0, 2.0, -1.0, 4.0];
    let options = TrackOptions {
        duration: 1.0,
        intervals: 100,
        ..TrackOptions::default()
    };
    let tracking = track(&model, &q, &u, &[Vec3::zeros()], options).unwrap();
    assert_eq!(tracking.cyclic, [0, 1]);
    for name in ["energy", "P_x", "P_y", "p_vx", "p_vy", "L_z(0, 0, 0)"] {
        let t = by_name(&tracking, name);
        assert!(t.conserved(1e-10), "{name}: {:e}", t.relative_deviation());
    }
    for name in ["P_z", "p_vz", "L_x(0, 0, 0)", "L_y(0, 0, 0)"] {
        let t = by_name(&tracking, name);
        assert!(!t.conserved(1e-3), "{name}: {:e}", t.relative_deviation());
    }
}

/// The fixed-base arm of `examples/mechanisms/arm-3d.toml` swinging: only its energy is
/// conserved (no coordinate is cyclic; the pivot's reactions change `P` and `L`).
#[test]
fn multibody_conserved_fixed_arm_energy_only() {
    let file = impax::scenario::MechanismFile::parse(include_str!(
        "../../../../examples/mechanisms/arm-3d.toml"
    ))
    .unwrap();
    let model = file.spatial().unwrap();
    let (q, u) = (file.q.clone().unwrap(), file.u.clone().unwrap());
    let options = TrackOptions {
        duration: 3.0,
        intervals: 300,
        ..TrackOptions::default()
    };
    let tracking = track(&model, &q, &u, &[Vec3::zeros()], options).unwrap();
    assert!(tracking.cyclic.is_empty(), "{:?}", tracking.cyclic);
    for t in &tracking.tracks {
        let conserved = t.conserved(1e-8);
        assert_eq!(
            conserved,
            t.kind == QuantityKind::Energy,
            "{}: {:e}",
            t.name,
            t.relative_deviation()
        );
    }
    eprintln!(
        "arm-3d over 3 s: energy within {:.1e}",
        by_name(&tracking, "energy").relative_deviation()
    );
}

/// A random state of `model` (a floating base's quaternion drawn, joints in ±1.5 rad, speeds
/// in ±2).
fn random_state(model: &Model, rng: &mut SplitMix64) -> (Vec<f64>, Vec<f64>) {
    let mut q = model.neutral();
    let first = if model.nq() > model.nv() {
        q[3..7].copy_from_slice(&quaternion(rng));
        7
    } else {
        0
    };
    for x in q.iter_mut().skip(first) {
        *x = rng.range(-1.5, 1.5);
    }
    let u = (0..model.nv()).map(|_| rng.range(-2.0, 2.0)).collect();
    (q, u)
}

/// Along random free motions of floating solo12 and a brick, with and without gravity, about
/// random points: every quantity a symmetry conserves stays constant to the integrator's
/// tolerance, and the ones gravity acts on (`P_z`, `L_x`, `L_y`) change.
#[test]
fn multibody_conserved_what_the_symmetries_promise_on_random_motions() {
    let mut rng = SplitMix64(0x0c05_e7ed);
    let (mut worst, mut runs) = (0.0f64, 0);
    for (name, model) in [("solo12", solo12(true)), ("brick", brick())] {
        for g in [9.81, 0.0] {
            let model = model.clone().with_gravity(g).unwrap();
            for _ in 0..3 {
                let (q, u) = random_state(&model, &mut rng);
                let about = [Vec3::new(
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                )];
                let options = TrackOptions {
                    duration: 0.5,
                    intervals: 50,
                    ..TrackOptions::default()
                };
                let tracking = track(&model, &q, &u, &about, options).unwrap();
                let expected: Vec<&str> = tracking
                    .tracks
                    .iter()
                    .filter(|t| t.expected)
                    .map(|t| t.name.as_str())
                    .collect();
                // A floating base's x and y are cyclic, and z without gravity.
                assert_eq!(tracking.cyclic[..2], [0, 1], "{name}");
                assert_eq!(tracking.cyclic.contains(&2), g == 0.0, "{name}");
                for t in tracking.tracks.iter().filter(|t| t.expected) {
                    assert!(
                        t.conserved(1e-9),
                        "{name}, g = {g}: {} {:e}",
                        t.name,
                        t.relative_deviation()
                    );
                    worst = worst.max(t.relative_deviation());
                }
                for t in &tracking.tracks {
                    let broken_by_gravity = match t.kind {
                        QuantityKind::LinearMomentum { axis } => axis == 2,
                        QuantityKind::AngularMomentum { axis, .. } => axis != 2,
                        _ => false,
                    };
                    if broken_by_gravity {
                        assert_eq!(t.expected, g == 0.0, "{name}: {}", t.name);
                        if g > 0.0 {
                            assert!(
                                !t.conserved(1e-3),
                                "{name}: {} {:e}",
                                t.name,
                                t.relative_deviation()
                            );
                        }
                    }
                }
                assert!(expected.contains(&"energy") && expected.contains(&"P_x"));
                runs += 1;
            }
        }
    }
    eprintln!("{runs} random free motions: every expected quantity within {worst:.1e}");
}

/// solo12 on a fixed base: the support breaks every translation and rotation — `P` and `L`
/// change, no coordinate is cyclic, only the energy is expected and conserved.
#[test]
fn multibody_conserved_fixed_base_breaks_momentum() {
    let model = solo12(false);
    let mut rng = SplitMix64(0x000f_18ed);
    for _ in 0..3 {
        let (q, u) = random_state(&model, &mut rng);
        let options = TrackOptions {
            duration: 0.5,
            intervals: 50,
            ..TrackOptions::default()
        };
        let tracking = track(&model, &q, &u, &[Vec3::zeros()], options).unwrap();
        assert!(tracking.cyclic.is_empty(), "{:?}", tracking.cyclic);
        for t in &tracking.tracks {
            assert_eq!(t.expected, t.kind == QuantityKind::Energy, "{}", t.name);
        }
        assert!(by_name(&tracking, "energy").conserved(1e-9));
        for name in ["P_x", "P_y", "P_z", "L_z(0, 0, 0)"] {
            let t = by_name(&tracking, name);
            assert!(!t.conserved(1e-4), "{name}: {:e}", t.relative_deviation());
        }
    }
}

/// The budget: a brick spinning at 10⁷ rad/s cannot be followed over a second; `track` and
/// `simulate` say so after their first thousand steps, naming `duration` and `until`.
#[test]
fn multibody_conserved_and_simulate_stop_a_runaway_spin() {
    use impax::multibody::simulate::{simulate, SimulationOptions};
    use impax::LawId;
    let model = brick();
    let q = [0.0, 0.0, 5.0, 1.0, 0.0, 0.0, 0.0];
    let u = [0.0, 0.0, 0.0, 0.0, 0.0, 1e7];
    let options = TrackOptions {
        duration: 1.0,
        intervals: 10,
        ..TrackOptions::default()
    };
    let e = track(&model, &q, &u, &[], options).unwrap_err().to_string();
    assert!(e.starts_with("duration: 1 is out of range"), "{e}");
    assert!(e.contains("integrator steps"), "{e}");
    let options = SimulationOptions::new(LawId::Energetic, 0.5, 0.5, 1.0);
    let e = simulate(&model, &q, &u, &options).unwrap_err().to_string();
    assert!(e.starts_with("until: 1 is out of range"), "{e}");
    // A sane spin over the same second is followed.
    let u = [0.0, 0.0, 0.0, 0.0, 0.0, 10.0];
    assert!(track(&model, &q, &u, &[], options_of(1.0)).is_ok());
}

fn options_of(duration: f64) -> TrackOptions {
    TrackOptions {
        duration,
        intervals: 10,
        ..TrackOptions::default()
    }
}
