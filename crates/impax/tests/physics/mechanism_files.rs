//! The built-in planar mechanisms as mechanism files (`examples/mechanisms/*.toml`): each file
//! is the built-in in joint coordinates, and agrees with it to 1e-12 at random states —
//! energies, mass matrix, equations of motion and every contact's problem — under the change
//! of coordinates `q_file = T q + c` the file's joints make (relative angles), and its own
//! state is the built-in's default state.

use impax::math::SplitMix64;
use impax::mechanism::builtin::RingPendulum;
use impax::mechanism::builtin::{CartPendulum, DoublePendulum, Rod, Sphere};
use impax::mechanism::impact::MechanismImpact;
use impax::mechanism::linkage::Linkage;
use impax::mechanism::{dynamics, Mechanism};
use impax::scenario::{MechanismFile, MechanismSpec};
use nalgebra::{DMatrix, DVector};

fn example(name: &str) -> MechanismFile {
    let path = format!(
        "{}/../../examples/mechanisms/{name}.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the example file");
    MechanismFile::parse(&text).expect("parses")
}

fn close(a: f64, b: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * scale.max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// The file's linkage against the built-in at `n` random built-in states `(q, u)`, with
/// `q_file = T q` and `u_file = T u` (a linear change of coordinates).
fn agree<B: Mechanism>(
    file: &Linkage,
    builtin: &B,
    t: &DMatrix<f64>,
    states: impl Fn(&mut SplitMix64) -> (Vec<f64>, Vec<f64>),
    contacts: &[(usize, usize)],
) {
    let mut rng = SplitMix64(0x00f1_1e5e);
    for _ in 0..200 {
        let (q, u) = states(&mut rng);
        let qf: Vec<f64> = (t * DVector::from_column_slice(&q))
            .iter()
            .copied()
            .collect();
        let uf: Vec<f64> = (t * DVector::from_column_slice(&u))
            .iter()
            .copied()
            .collect();
        let t_b = dynamics::kinetic_energy(builtin, &q, &u);
        close(dynamics::kinetic_energy(file, &qf, &uf), t_b, t_b, "T");
        let v_b = dynamics::potential_energy(builtin, &q);
        close(
            dynamics::potential_energy(file, &qf),
            v_b,
            t_b + v_b.abs(),
            "V",
        );
        // M_file = T⁻ᵀ M T⁻¹, i.e. Tᵀ M_file T = M.
        let m = dynamics::mass_matrix(builtin, &q);
        let mf = t.transpose() * dynamics::mass_matrix(file, &qf) * t;
        assert!((mf - &m).abs().max() <= 1e-12 * m.abs().max(), "M");
        // The equations of motion: u̇_file = T u̇.
        let a = t * dynamics::accelerations(builtin, &q, &u).unwrap();
        let af = dynamics::accelerations(file, &qf, &uf).unwrap();
        assert!(
            (af - &a).abs().max() <= 1e-11 * a.abs().max().max(1.0),
            "accelerations"
        );
        for &(kf, kb) in contacts {
            let ib = MechanismImpact::new(builtin, &q, &u, kb).unwrap();
            let i_f = MechanismImpact::new(file, &qf, &uf, kf).unwrap();
            let w = ib.inverse_inertia();
            assert!(
                (i_f.inverse_inertia() - w).abs().max() <= 1e-12 * w.abs().max(),
                "W"
            );
            let v = ib.contact_velocity();
            assert!((i_f.contact_velocity() - v).abs().max() <= 1e-12 * v.abs().max().max(1.0));
        }
    }
}

fn angles(rng: &mut SplitMix64, n: usize) -> Vec<f64> {
    (0..n).map(|_| rng.range(-3.0, 3.0)).collect()
}

#[test]
fn double_pendulum() {
    let file = example("double-pendulum");
    let linkage = file.planar().unwrap();
    // Relative angles: q_file = (θ1, θ2 − θ1).
    let t = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, -1.0, 1.0]);
    let builtin = DoublePendulum::new(1.0, 1.0, 1.0, 1.0, 9.81, 0.0).unwrap();
    let states = |rng: &mut SplitMix64| (angles(rng, 2), angles(rng, 2));
    agree(&linkage, &builtin, &t, states, &[(0, 0), (1, 1)]);
    // The file's state is the built-in's default, (30°, 0) with rates (−1, 2).
    let built = MechanismSpec {
        mechanism: "double-pendulum".into(),
        file: Some(file),
        ..MechanismSpec::default()
    }
    .build()
    .unwrap();
    let a = 30f64.to_radians();
    assert!((built.q[0] - a).abs() < 1e-15 && (built.q[1] + a).abs() < 1e-15);
    assert_eq!(built.u, vec![-1.0, 3.0]);
    // Its floor passes through the tip, as the built-in's.
    let reference = MechanismSpec {
        mechanism: "double-pendulum".into(),
        ..MechanismSpec::default()
    }
    .build()
    .unwrap();
    close(
        dynamics::gap(&built.mechanism, 0, &built.q),
        dynamics::gap(&reference.mechanism, 0, &reference.q),
        1.0,
        "gap of the tip",
    );
    close(
        dynamics::gap(&built.mechanism, 1, &built.q),
        dynamics::gap(&reference.mechanism, 1, &reference.q),
        1.0,
        "gap of the elbow",
    );
}

#[test]
fn ring_pendulum() {
    let linkage = example("ring-pendulum").planar().unwrap();
    // The hinge turns with the ring: q_file = (x, φ + x/R), R = 1.
    let t = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 1.0, 1.0]);
    let builtin = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    let states = |rng: &mut SplitMix64| (angles(rng, 2), angles(rng, 2));
    agree(&linkage, &builtin, &t, states, &[]);
}

#[test]
fn cart_pendulum() {
    let linkage = example("cart-pendulum").planar().unwrap();
    let builtin = CartPendulum::new(1.0, 1.0, 1.0, 9.81).unwrap();
    let states = |rng: &mut SplitMix64| (angles(rng, 2), angles(rng, 2));
    agree(&linkage, &builtin, &DMatrix::identity(2, 2), states, &[]);
}

#[test]
fn sphere_and_rod() {
    let sphere = example("sphere").planar().unwrap();
    let builtin = Sphere::new(1.0, 1.0, 9.81, 0.0).unwrap();
    let states = |rng: &mut SplitMix64| (angles(rng, 3), angles(rng, 3));
    agree(
        &sphere,
        &builtin,
        &DMatrix::identity(3, 3),
        states,
        &[(0, 0)],
    );
    let rod = example("rod").planar().unwrap();
    let builtin = Rod::new(1.0, 1.0, 9.81, 0.0).unwrap();
    agree(
        &rod,
        &builtin,
        &DMatrix::identity(3, 3),
        states,
        &[(0, 0), (1, 1)],
    );
}

/// Bad files are refused with the field and the reason.
#[test]
fn errors_name_their_field() {
    let base = std::fs::read_to_string(format!(
        "{}/../../examples/mechanisms/double-pendulum.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let cases = [
        (
            "parent = \"rod 1\"",
            "parent = \"rod 3\"",
            "joint[theta2].parent",
        ),
        (
            "type = \"revolute\"\nparent = \"rod 1\"",
            "type = \"hinge\"\nparent = \"rod 1\"",
            "joint[theta2].type",
        ),
        (
            "mass = 1.0\ninertia = 0.08333333333333333\ncom",
            "mass = -1.0\ninertia = 0.08333333333333333\ncom",
            "body[rod 1].mass",
        ),
        (
            "point = [0.0, -0.5]\n\n[[contact]]",
            "point = [0.0, -0.5, 1.0]\n\n[[contact]]",
            "contact[tip of rod 2].point",
        ),
        (
            "child_at = [0.0, 0.5]          # rod 1",
            "axis = [1.0, 0.0]\nchild_at = [0.0, 0.5]          # rod 1",
            "joint[theta1].axis",
        ),
    ];
    for (from, to, field) in cases {
        assert!(base.contains(from), "{from}");
        let text = base.replacen(from, to, 1);
        let err = MechanismFile::parse(&text)
            .and_then(|f| f.planar().map(|_| ()))
            .unwrap_err();
        assert_eq!(err.field(), field, "{err}");
    }
    // An unknown key is a syntax error with its line.
    let err = MechanismFile::parse(&base.replacen("mass = 1.0", "mass = 1.0\ncolour = 3", 1))
        .unwrap_err();
    assert!(err.to_string().contains("colour"), "{err}");
    // A body no joint places.
    let text = base.replacen("child = \"rod 2\"", "child = \"rod 1\"", 1);
    let err = MechanismFile::parse(&text).unwrap().planar().unwrap_err();
    assert_eq!(err.field(), "joint[theta2].child", "{err}");
}
