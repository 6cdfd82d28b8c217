//! What the multibody tests share: the models (a hand-written tree with every joint kind,
//! solo12 with a fixed and a floating base, ur5), random states, and the independent
//! reference computations by forward-mode automatic differentiation of the generic
//! kinematics (theory §4): body velocity Jacobians from duals seeded along `q̇ = G(q) e_k`,
//! angular velocities from `Ṙ Rᵀ`, and accelerations from hyper-duals.

use impax::math::{Mat3, SplitMix64, Vec3};
use impax::mechanism::{Dual64, HyperDual64};
use impax::multibody::{
    configuration_rate, forward_kinematics, read_urdf, Body, BodyPose, ContactPoint, ContactSpec,
    Joint, JointKind, Model, Placement, UrdfOptions,
};
use nalgebra::{DMatrix, Matrix3xX};

pub const SOLO12: &str = include_str!("../data/urdf/solo12.urdf");
pub const UR5: &str = include_str!("../data/urdf/ur5_robot.urdf");
pub const FEET: [&str; 4] = ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"];

/// solo12 with its four feet as contacts, with a fixed or a floating base.
pub fn solo12(floating: bool) -> Model {
    let mut options = UrdfOptions::default().floating_base(floating);
    for f in FEET {
        options = options.contact(ContactSpec::new(f));
    }
    read_urdf(SOLO12, &options).expect("solo12 reads").model
}

/// ur5 with a contact at its tool flange.
pub fn ur5() -> Model {
    let options = UrdfOptions::default().contact(ContactSpec::new("tool0"));
    read_urdf(UR5, &options).expect("ur5 reads").model
}

/// A random rotation (from a random unit quaternion).
pub fn rotation(rng: &mut SplitMix64) -> Mat3 {
    let q = random_quaternion(rng);
    nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]))
        .to_rotation_matrix()
        .into_inner()
}

/// A random unit quaternion `(w, x, y, z)`.
pub fn random_quaternion(rng: &mut SplitMix64) -> [f64; 4] {
    loop {
        let q = [0; 4].map(|_| rng.range(-1.0, 1.0));
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        if (0.1..=1.0).contains(&n) {
            return q.map(|x| x / n);
        }
    }
}

fn random_vec(rng: &mut SplitMix64, s: f64) -> Vec3 {
    Vec3::new(rng.range(-s, s), rng.range(-s, s), rng.range(-s, s))
}

fn random_inertia(rng: &mut SplitMix64) -> Mat3 {
    let r = rotation(rng);
    let d = Mat3::from_diagonal(&Vec3::new(
        rng.range(0.1, 1.0),
        rng.range(0.1, 1.0),
        rng.range(0.1, 1.0),
    ));
    r * d * r.transpose()
}

fn random_placement(rng: &mut SplitMix64) -> Placement {
    Placement::new(rotation(rng), random_vec(rng, 0.5))
}

/// A hand-written tree with every joint kind: a base (free, or revolute from the world),
/// a revolute arm, a prismatic slider, a tool welded on by a fixed joint, a revolute joint
/// with a child placement, and a revolute leg on a second branch; random masses, inertias,
/// placements and axes, two contact points (one round).
pub fn hand_tree(floating: bool, seed: u64) -> Model {
    let mut rng = SplitMix64(seed);
    let names = ["base", "arm", "slider", "tool", "forearm", "leg"];
    let bodies: Vec<Body> = names
        .iter()
        .map(|n| {
            Body::new(
                n,
                rng.range(0.5, 3.0),
                random_vec(&mut rng, 0.3),
                random_inertia(&mut rng),
            )
        })
        .collect();
    let base = if floating {
        // (A free joint with a turned, offset frame on both sides: u in that frame's axes.)
        let mut j = Joint::free("root", 0);
        j.placement = random_placement(&mut rng);
        j.child_placement = random_placement(&mut rng);
        j
    } else {
        Joint::revolute(
            "root",
            random_vec(&mut rng, 1.0),
            None,
            0,
            random_placement(&mut rng),
        )
    };
    let mut forearm = Joint::revolute(
        "elbow",
        random_vec(&mut rng, 1.0),
        Some(3),
        4,
        random_placement(&mut rng),
    );
    forearm.child_placement = random_placement(&mut rng);
    let joints = vec![
        base,
        Joint::revolute(
            "shoulder",
            random_vec(&mut rng, 1.0),
            Some(0),
            1,
            random_placement(&mut rng),
        ),
        Joint::new(
            "slide",
            JointKind::Prismatic {
                axis: random_vec(&mut rng, 1.0),
            },
            Some(1),
            2,
            random_placement(&mut rng),
        ),
        Joint::new(
            "weld",
            JointKind::Fixed,
            Some(2),
            3,
            random_placement(&mut rng),
        ),
        forearm,
        Joint::revolute(
            "hip",
            random_vec(&mut rng, 1.0),
            Some(0),
            5,
            random_placement(&mut rng),
        ),
    ];
    let contacts = vec![
        ContactPoint::new("hand", 4, random_vec(&mut rng, 0.4), 0.0),
        ContactPoint::new("foot", 5, random_vec(&mut rng, 0.4), 0.05),
    ];
    Model::new(bodies, joints, contacts).expect("valid tree")
}

/// A random state: angles in `[−π, π]`, slides in `[−0.5, 0.5]`, a free joint anywhere in a
/// unit box with a random orientation; speeds in `[−2, 2]`.
pub fn random_state(model: &Model, rng: &mut SplitMix64) -> (Vec<f64>, Vec<f64>) {
    let mut q = vec![0.0; model.nq()];
    for (j, joint) in model.joints().iter().enumerate() {
        let (o, _) = model.joint_offsets(j);
        match joint.kind {
            JointKind::Revolute { .. } => {
                q[o] = rng.range(-std::f64::consts::PI, std::f64::consts::PI)
            }
            JointKind::Prismatic { .. } => q[o] = rng.range(-0.5, 0.5),
            JointKind::Free => {
                for k in 0..3 {
                    q[o + k] = rng.range(-1.0, 1.0);
                }
                q[o + 3..o + 7].copy_from_slice(&random_quaternion(rng));
            }
            JointKind::Fixed => {}
        }
    }
    let u = (0..model.nv()).map(|_| rng.range(-2.0, 2.0)).collect();
    (q, u)
}

/// `vee` of the skew part of `a` (by rows): `(a₂₁ − a₁₂, a₀₂ − a₂₀, a₁₀ − a₀₁)/2`.
fn vee(a: &Mat3) -> Vec3 {
    0.5 * Vec3::new(
        a[(2, 1)] - a[(1, 2)],
        a[(0, 2)] - a[(2, 0)],
        a[(1, 0)] - a[(0, 1)],
    )
}

/// The velocity Jacobians of every body by duals, seeded along `q̇ = G(q) e_k` for each speed
/// `k`: `(J_c, J_ω)`, the centre of mass's linear velocity and the angular velocity
/// `vee(Ṙ Rᵀ)`, both 3 × nv, in world axes.
pub fn body_jacobians_ad(model: &Model, q: &[f64]) -> Vec<(Matrix3xX<f64>, Matrix3xX<f64>)> {
    let (nv, nb) = (model.nv(), model.bodies().len());
    let mut out = vec![(Matrix3xX::zeros(nv), Matrix3xX::zeros(nv)); nb];
    let mut poses = vec![BodyPose::<Dual64>::identity(); nb];
    let mut e = vec![0.0; nv];
    let mut qdot = vec![0.0; model.nq()];
    for k in 0..nv {
        e.iter_mut()
            .enumerate()
            .for_each(|(i, x)| *x = f64::from(i == k));
        configuration_rate(model, q, &e, &mut qdot);
        let qd: Vec<Dual64> = q
            .iter()
            .zip(&qdot)
            .map(|(&x, &d)| Dual64::new(x, d))
            .collect();
        forward_kinematics(model, &qd, &mut poses);
        for (b, body) in model.bodies().iter().enumerate() {
            let c = poses[b].point(&body.com);
            let r = Mat3::from_fn(|i, j| poses[b].rotation[i][j].re);
            let rdot = Mat3::from_fn(|i, j| poses[b].rotation[i][j].eps);
            out[b]
                .0
                .set_column(k, &Vec3::new(c[0].eps, c[1].eps, c[2].eps));
            out[b].1.set_column(k, &vee(&(rdot * r.transpose())));
        }
    }
    out
}

/// The poses at `q` in `f64`.
pub fn poses_f64(model: &Model, q: &[f64]) -> Vec<BodyPose<f64>> {
    let mut poses = vec![BodyPose::identity(); model.bodies().len()];
    forward_kinematics(model, q, &mut poses);
    poses
}

/// `M = Σ_b J_cᵀ m J_c + J_ωᵀ I_world J_ω` from the dual-number Jacobians.
pub fn mass_matrix_ad(model: &Model, q: &[f64]) -> DMatrix<f64> {
    let nv = model.nv();
    let poses = poses_f64(model, q);
    let mut m = DMatrix::zeros(nv, nv);
    for ((jc, jw), (body, pose)) in body_jacobians_ad(model, q)
        .iter()
        .zip(model.bodies().iter().zip(&poses))
    {
        let r = pose.rotation_matrix();
        let iw = r * body.inertia * r.transpose();
        m += jc.transpose() * jc * body.mass + jw.transpose() * iw * jw;
    }
    m
}

/// The world-frame Jacobian of the material point `x` (body frame) of body `b` by duals.
pub fn point_jacobian_ad(model: &Model, q: &[f64], b: usize, x: &Vec3) -> Matrix3xX<f64> {
    let nv = model.nv();
    let mut out = Matrix3xX::zeros(nv);
    let mut poses = vec![BodyPose::<Dual64>::identity(); model.bodies().len()];
    let mut e = vec![0.0; nv];
    let mut qdot = vec![0.0; model.nq()];
    for k in 0..nv {
        e.iter_mut()
            .enumerate()
            .for_each(|(i, v)| *v = f64::from(i == k));
        configuration_rate(model, q, &e, &mut qdot);
        let qd: Vec<Dual64> = q
            .iter()
            .zip(&qdot)
            .map(|(&x, &d)| Dual64::new(x, d))
            .collect();
        forward_kinematics(model, &qd, &mut poses);
        let p = poses[b].point(x);
        out.set_column(k, &Vec3::new(p[0].eps, p[1].eps, p[2].eps));
    }
    out
}

/// `q̈` along `q̇ = G(q) u` at constant `u`: zero but for a free joint's quaternion,
/// `d/dt (½ ω ⊗ q) = ¼ ω ⊗ ω ⊗ q = −¼ |ω|² q`.
fn configuration_acceleration(model: &Model, q: &[f64], u: &[f64]) -> Vec<f64> {
    let mut qdd = vec![0.0; model.nq()];
    for (j, joint) in model.joints().iter().enumerate() {
        if joint.kind == JointKind::Free {
            let (oq, ov) = model.joint_offsets(j);
            let w2: f64 = u[ov + 3..ov + 6].iter().map(|x| x * x).sum();
            for k in 3..7 {
                qdd[oq + k] = -0.25 * w2 * q[oq + k];
            }
        }
    }
    qdd
}

/// The bias forces `C(q, u) u + g(q)` by Newton–Euler on each body with the accelerations
/// of hyper-duals (seed `q + ε₁q̇ + ε₂q̇ + ε₁ε₂q̈`, so the `ε₁ε₂` part of a pose is its second
/// time derivative at `u̇ = 0`):
/// `Σ_b J_cᵀ m (a_c + g e_z) + J_ωᵀ (I α + ω × I ω)`.
pub fn bias_ad(model: &Model, q: &[f64], u: &[f64]) -> Vec<f64> {
    let nb = model.bodies().len();
    let mut qdot = vec![0.0; model.nq()];
    configuration_rate(model, q, u, &mut qdot);
    let qdd = configuration_acceleration(model, q, u);
    let qh: Vec<HyperDual64> = (0..q.len())
        .map(|i| HyperDual64::new(q[i], qdot[i], qdot[i], qdd[i]))
        .collect();
    let mut poses = vec![BodyPose::<HyperDual64>::identity(); nb];
    forward_kinematics(model, &qh, &mut poses);
    let jac = body_jacobians_ad(model, q);
    let mut out = vec![0.0; model.nv()];
    for (b, body) in model.bodies().iter().enumerate() {
        let c = poses[b].point(&body.com);
        let a = Vec3::new(
            c[0].eps1eps2,
            c[1].eps1eps2,
            c[2].eps1eps2 + model.gravity(),
        );
        let part = |f: fn(&HyperDual64) -> f64| Mat3::from_fn(|i, j| f(&poses[b].rotation[i][j]));
        let (r, rd, rdd) = (part(|x| x.re), part(|x| x.eps1), part(|x| x.eps1eps2));
        let w = vee(&(rd * r.transpose()));
        let alpha = vee(&(rdd * r.transpose()));
        let iw = r * body.inertia * r.transpose();
        let f = a * body.mass;
        let n = iw * alpha + w.cross(&(iw * w));
        let g = jac[b].0.transpose() * f + jac[b].1.transpose() * n;
        out.iter_mut().zip(g.iter()).for_each(|(o, x)| *o += x);
    }
    out
}

/// The largest entry of `a − b` over the largest of `b`.
pub fn relative_error(a: &DMatrix<f64>, b: &DMatrix<f64>) -> f64 {
    (a - b).amax() / b.amax()
}
