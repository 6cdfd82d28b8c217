//! The spatial multibody algorithms against independent computations (theory §4, §7): the
//! mass matrix by CRBA, the point Jacobians and the bias forces by RNEA, each against
//! forward-mode automatic differentiation of the generic forward kinematics, over random
//! states of a hand-written tree with every joint kind and of solo12 (fixed and floating
//! base) and ur5; and a spatial double pendulum swinging in a plane against the planar
//! built-in `DoublePendulum`.

use super::multibody_models::*;
use impax::math::Mat3;
use impax::math::{SplitMix64, Vec3};
use impax::mechanism::builtin::DoublePendulum;
use impax::mechanism::dynamics;
use impax::mechanism::impact::MechanismImpact;
use impax::multibody::{
    bias_forces, contact_space, crba, forward_dynamics_in, inverse_dynamics, point_jacobian, Body,
    ContactPoint, Joint, Model, Placement, Workspace,
};
use nalgebra::DMatrix;

/// The models under test, with a name for messages.
fn models() -> Vec<(&'static str, Model)> {
    vec![
        ("hand tree, fixed base", hand_tree(false, 1)),
        ("hand tree, floating base", hand_tree(true, 2)),
        ("solo12, fixed base", solo12(false)),
        ("solo12, floating base", solo12(true)),
        ("ur5", ur5()),
    ]
}

const STATES: usize = 40;

#[test]
fn multibody_crba_equals_automatic_differentiation() {
    let mut worst: f64 = 0.0;
    for (name, model) in models() {
        let mut rng = SplitMix64(7);
        let mut ws = Workspace::new(&model);
        for _ in 0..STATES {
            let (q, _) = random_state(&model, &mut rng);
            ws.update(&model, &q).unwrap();
            let m = crba(&model, &mut ws).clone();
            let reference = mass_matrix_ad(&model, &q);
            let err = relative_error(&m, &reference);
            assert!(err < 1e-12, "{name}: |M_crba − M_ad| / |M| = {err:e}");
            assert_eq!(m, m.transpose(), "{name}: M symmetric");
            worst = worst.max(err);
        }
    }
    println!("CRBA vs AD: worst relative error {worst:.2e}");
}

#[test]
fn multibody_point_jacobians_equal_automatic_differentiation() {
    let mut worst: f64 = 0.0;
    for (name, model) in models() {
        let mut rng = SplitMix64(8);
        let mut ws = Workspace::new(&model);
        for _ in 0..STATES {
            let (q, _) = random_state(&model, &mut rng);
            ws.update(&model, &q).unwrap();
            for b in 0..model.bodies().len() {
                let x = Vec3::new(
                    rng.range(-0.3, 0.3),
                    rng.range(-0.3, 0.3),
                    rng.range(-0.3, 0.3),
                );
                let j = point_jacobian(&model, &ws, b, &x);
                let reference = point_jacobian_ad(&model, &q, b, &x);
                let err = (&j - &reference).amax() / reference.amax().max(1e-300);
                assert!(
                    err < 1e-12 || reference.amax() == 0.0,
                    "{name}, body {b}: {err:e}"
                );
                worst = worst.max(if reference.amax() == 0.0 {
                    j.amax()
                } else {
                    err
                });
            }
        }
    }
    println!("point Jacobians vs AD: worst relative error {worst:.2e}");
}

/// The contact Jacobian is the Jacobian of the body's material point at the bottom of the
/// round foot (`point − r e_z` in the world), and `W = J M⁻¹ Jᵀ`, `v = J u` follow.
#[test]
fn multibody_contact_space_equals_automatic_differentiation() {
    let (mut worst, mut worst_w): (f64, f64) = (0.0, 0.0);
    for (name, model) in models() {
        let mut rng = SplitMix64(9);
        let mut ws = Workspace::new(&model);
        for _ in 0..STATES {
            let (q, u) = random_state(&model, &mut rng);
            ws.update(&model, &q).unwrap();
            let poses = poses_f64(&model, &q);
            for (k, c) in model.contacts().iter().enumerate() {
                let Ok(space) = contact_space(&model, &mut ws, k, &u) else {
                    panic!("{name}: contact {k}");
                };
                let r = poses[c.body].rotation_matrix();
                let material = c.point - r.transpose() * Vec3::z() * c.radius;
                let j = point_jacobian_ad(&model, &q, c.body, &material);
                let m = mass_matrix_ad(&model, &q);
                let jd = DMatrix::from_fn(3, model.nv(), |i, k| j[(i, k)]);
                let w = &jd * m.clone().cholesky().unwrap().solve(&jd.transpose());
                let e_j = (&space.jacobian - &j).amax() / j.amax();
                let e_w =
                    DMatrix::from_fn(3, 3, |i, k| space.w[(i, k)] - w[(i, k)]).amax() / w.amax();
                let v = &jd * nalgebra::DVector::from_column_slice(&u);
                let e_v = (0..3)
                    .map(|i| (space.velocity[i] - v[i]).abs())
                    .fold(0.0, f64::max)
                    / v.amax();
                assert!(e_j < 1e-12 && e_v < 1e-12, "{name}: J {e_j:e}, v {e_v:e}");
                assert!(e_w < 1e-12, "{name}: W {e_w:e}");
                worst = worst.max(e_j).max(e_v);
                worst_w = worst_w.max(e_w);
            }
        }
    }
    println!("contact J and v vs AD: worst relative error {worst:.2e}; W {worst_w:.2e}");
}

#[test]
fn multibody_rnea_bias_equals_newton_euler_by_hyper_duals() {
    let mut worst: f64 = 0.0;
    for (name, model) in models() {
        let mut rng = SplitMix64(10);
        let mut ws = Workspace::new(&model);
        let mut bias = vec![0.0; model.nv()];
        for _ in 0..STATES {
            let (q, u) = random_state(&model, &mut rng);
            ws.update(&model, &q).unwrap();
            bias_forces(&model, &mut ws, &u, &mut bias);
            let reference = bias_ad(&model, &q, &u);
            let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let err = bias
                .iter()
                .zip(&reference)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
                / scale;
            assert!(err < 1e-12, "{name}: bias {err:e}");
            worst = worst.max(err);
        }
    }
    println!("RNEA bias vs hyper-dual Newton–Euler: worst relative error {worst:.2e}");
}

/// `τ(u̇) − τ(0) = M u̇` (RNEA against CRBA), and forward dynamics inverts inverse dynamics.
#[test]
fn multibody_rnea_and_crba_agree_and_forward_dynamics_inverts() {
    let mut worst: f64 = 0.0;
    for (name, model) in models() {
        let mut rng = SplitMix64(11);
        let mut ws = Workspace::new(&model);
        let n = model.nv();
        let (mut tau, mut bias, mut back) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for _ in 0..STATES {
            let (q, u) = random_state(&model, &mut rng);
            let udot: Vec<f64> = (0..n).map(|_| rng.range(-5.0, 5.0)).collect();
            ws.update(&model, &q).unwrap();
            inverse_dynamics(&model, &mut ws, &u, &udot, &mut tau);
            bias_forces(&model, &mut ws, &u, &mut bias);
            let m = crba(&model, &mut ws).clone();
            let mu = &m * nalgebra::DVector::from_column_slice(&udot);
            let scale = mu.amax();
            let err = (0..n)
                .map(|i| (tau[i] - bias[i] - mu[i]).abs())
                .fold(0.0, f64::max)
                / scale;
            assert!(err < 1e-12, "{name}: τ − bias − M u̇ {err:e}");
            forward_dynamics_in(&model, &mut ws, &u, &tau, &mut back).unwrap();
            let e_fd = (0..n)
                .map(|i| (back[i] - udot[i]).abs())
                .fold(0.0, f64::max)
                / 5.0;
            assert!(e_fd < 1e-7, "{name}: forward dynamics {e_fd:e}");
            worst = worst.max(err);
        }
    }
    println!("RNEA vs CRBA: worst relative error {worst:.2e}");
}

/// A spatial double pendulum hinged about −y (so that the world's `x, z` are the planar `x, y`
/// and a positive angle turns counter-clockwise as the planar ones do), its joints relative:
/// `q = (θ₁, θ₂ − θ₁)`.
fn spatial_double_pendulum(m: [f64; 2], l: [f64; 2]) -> Model {
    let rod = |name: &str, m: f64, l: f64| {
        let i = m * l * l / 12.0;
        Body::new(
            name,
            m,
            Vec3::new(0.0, 0.0, -l / 2.0),
            Mat3::from_diagonal(&Vec3::new(i, i, 0.0)),
        )
    };
    let axis = -Vec3::y();
    Model::new(
        vec![rod("rod 1", m[0], l[0]), rod("rod 2", m[1], l[1])],
        vec![
            Joint::revolute("shoulder", axis, None, 0, Placement::identity()),
            Joint::revolute(
                "elbow",
                axis,
                Some(0),
                1,
                Placement::from_translation(Vec3::new(0.0, 0.0, -l[0])),
            ),
        ],
        vec![ContactPoint::new(
            "tip of rod 2",
            1,
            Vec3::new(0.0, 0.0, -l[1]),
            0.0,
        )],
    )
    .unwrap()
}

#[test]
fn multibody_double_pendulum_equals_the_planar_built_in() {
    let (m, l) = ([1.3, 0.7], [0.9, 1.2]);
    let planar = DoublePendulum::new(m[0], m[1], l[0], l[1], 9.81, -5.0).unwrap();
    let spatial = spatial_double_pendulum(m, l);
    let mut rng = SplitMix64(12);
    let mut ws = Workspace::new(&spatial);
    let (mut worst_m, mut worst_w): (f64, f64) = (0.0, 0.0);
    for _ in 0..200 {
        let theta = [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)];
        let rate = [rng.range(-2.0, 2.0), rng.range(-2.0, 2.0)];
        let q = [theta[0], theta[1] - theta[0]];
        let u = [rate[0], rate[1] - rate[0]];
        ws.update(&spatial, &q).unwrap();
        let ms = crba(&spatial, &mut ws).clone();
        // θ = T q with T = [[1, 0], [1, 1]]: M_q = Tᵀ M_θ T.
        let t = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 1.0, 1.0]);
        let mp = t.transpose() * dynamics::mass_matrix(&planar, &theta) * &t;
        let e_m = relative_error(&ms, &mp);
        let space = contact_space(&spatial, &mut ws, 0, &u).unwrap();
        let imp = MechanismImpact::new(&planar, &theta, &rate, 0).unwrap();
        let (wp, vp) = (imp.inverse_inertia(), imp.contact_velocity());
        let ws3 = space.w;
        let e_w = [
            ws3[(0, 0)] - wp[(0, 0)],
            ws3[(0, 2)] - wp[(0, 1)],
            ws3[(2, 2)] - wp[(1, 1)],
            ws3[(1, 1)],
            ws3[(0, 1)],
            ws3[(1, 2)],
        ]
        .iter()
        .fold(0.0f64, |a, x| a.max(x.abs()))
            / wp.amax();
        let e_v = (space.velocity.x - vp.x)
            .abs()
            .max((space.velocity.z - vp.y).abs())
            .max(space.velocity.y.abs());
        assert!(e_m < 1e-12, "M: {e_m:e} at θ = {theta:?}");
        assert!(e_w < 1e-12, "W: {e_w:e} at θ = {theta:?}");
        assert!(e_v < 1e-12 * vp.amax().max(1.0), "v: {e_v:e}");
        worst_m = worst_m.max(e_m);
        worst_w = worst_w.max(e_w);
    }
    println!("double pendulum: worst relative error M {worst_m:.2e}, W {worst_w:.2e}");
}
