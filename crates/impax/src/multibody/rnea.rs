//! Inverse dynamics by the recursive Newton–Euler algorithm, the bias forces
//! `C(q, u) u + g(q)`, forward dynamics, and the rate of the configuration `q̇` from the
//! speeds `u`.
//!
//! Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §5.3 (table 5.1), in absolute
//! coordinates (world axes about one point `O`, see [`super::Workspace`]). Outwards, for the
//! joint of body `b` with parent `λ` (the world's "acceleration" `a₀ = (0, g e_z)` puts
//! gravity on every body):
//!
//! ```text
//! v_b = v_λ + S u_j,   a_b = a_λ + S u̇_j + c_j,   f_b = I_b a_b + v_b ×* I_b v_b,
//! ```
//!
//! with the velocity-product term `c_j = Ṡ u_j = v_b × S u_j` of a joint whose axis is fixed
//! in its parent, and `c_j = (0, v_o × ω)` for a free joint (its `S` turns about the moving
//! origin `o` of the floating base). Inwards, `τ_j = Sᵀ f_b` and `f_λ += f_b`. Then
//! `τ = M(q) u̇ + C(q, u) u + g(q)`, the bias forces are `τ` at `u̇ = 0`, and forward dynamics
//! solves `M u̇ = τ − C u − g` with the factor `M = Lᵀ L` ([`super::factor`]).

use super::crba::{crba, factor, solve};
use super::joint::JointKind;
use super::model::Model;
use super::workspace::{Force, Motion, Workspace};
use crate::error::Result;
use crate::math::Vec3;

/// `τ = M(q) u̇ + C(q, u) u + g(q)` at the workspace's configuration, into `tau` (`nv`).
///
/// `u`, `udot` and `tau` must have `nv` entries (unchecked: see [`Model::check_speeds`]).
pub fn inverse_dynamics(
    model: &Model,
    ws: &mut Workspace,
    u: &[f64],
    udot: &[f64],
    tau: &mut [f64],
) {
    let d = &model.data;
    let gravity = Motion {
        w: Vec3::zeros(),
        v: Vec3::new(0.0, 0.0, model.gravity),
    };
    for (j, joint) in model.joints.iter().enumerate() {
        let (mut v, mut a) = match joint.parent {
            Some(p) => (ws.velocity[p], ws.acceleration[p]),
            None => (Motion::default(), gravity),
        };
        let o = d.v_offset[j];
        let s = &ws.subspace[o..o + joint.kind.nv()];
        for (k, sk) in s.iter().enumerate() {
            v = v.add_scaled(sk, u[o + k]);
            a = a.add_scaled(sk, udot[o + k]);
        }
        match joint.kind {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => {
                let vj = Motion::default().add_scaled(&s[0], u[o]);
                let c = v.cross(&vj);
                a = a.add_scaled(&c, 1.0);
            }
            JointKind::Free => {
                let vo = s[0].v * u[o] + s[1].v * u[o + 1] + s[2].v * u[o + 2];
                let w = s[3].w * u[o + 3] + s[4].w * u[o + 4] + s[5].w * u[o + 5];
                a.v += vo.cross(&w);
            }
            JointKind::Fixed => {}
        }
        let b = joint.child;
        let inertia = &ws.inertia[b];
        let ia = inertia.apply(&a);
        let gyro = v.cross_force(&inertia.apply(&v));
        ws.velocity[b] = v;
        ws.acceleration[b] = a;
        ws.force[b] = Force {
            n: ia.n + gyro.n,
            f: ia.f + gyro.f,
        };
    }
    for (j, joint) in model.joints.iter().enumerate().rev() {
        let b = joint.child;
        let f = ws.force[b];
        let o = d.v_offset[j];
        for k in 0..joint.kind.nv() {
            tau[o + k] = ws.subspace[o + k].dot(&f);
        }
        if let Some(p) = joint.parent {
            ws.force[p].n += f.n;
            ws.force[p].f += f.f;
        }
    }
}

/// The bias forces `C(q, u) u + g(q)` (inverse dynamics at `u̇ = 0`) at the workspace's
/// configuration, into `out` (`nv`).
pub fn bias_forces(model: &Model, ws: &mut Workspace, u: &[f64], out: &mut [f64]) {
    let mut zero = std::mem::take(&mut ws.scratch);
    zero.iter_mut().for_each(|x| *x = 0.0);
    inverse_dynamics(model, ws, u, &zero, out);
    ws.scratch = zero;
}

/// Forward dynamics at the workspace's configuration: `u̇ = M⁻¹ (τ − C u − g)`, into `udot`.
///
/// # Errors
/// `u`, `tau` or `udot` of the wrong length; `u` or `tau` not finite; a singular mass
/// matrix.
pub fn forward_dynamics_in(
    model: &Model,
    ws: &mut Workspace,
    u: &[f64],
    tau: &[f64],
    udot: &mut [f64],
) -> Result<()> {
    model.check_speeds(u)?;
    crate::multibody::model::check_vector("tau", tau, model.speeds())?;
    if udot.len() != model.nv() {
        return Err(crate::Error::Invalid {
            field: "udot".into(),
            reason: format!(
                "needs room for {} accelerations, got {}",
                model.nv(),
                udot.len()
            ),
        });
    }
    bias_forces(model, ws, u, udot);
    for (x, t) in udot.iter_mut().zip(tau) {
        *x = t - *x;
    }
    crba(model, ws);
    factor(model, ws)?;
    solve(model, ws, udot);
    Ok(())
}

/// Forward dynamics: the accelerations `u̇` at `(q, u)` under the generalized forces `τ`.
///
/// # Errors
/// As [`Model::check_state`]; `tau` of the wrong length or not finite; a singular mass
/// matrix.
///
/// ```
/// use impax::multibody::{forward_dynamics, Body, Joint, Model, Placement};
/// use impax::math::{Mat3, Vec3};
/// // A point-mass pendulum held horizontal falls at θ̈ = g/l.
/// let bob = Body::new("bob", 1.0, Vec3::new(2.0, 0.0, 0.0), Mat3::zeros());
/// let pin = Joint::revolute("pin", Vec3::y(), None, 0, Placement::identity());
/// let model = Model::new(vec![bob], vec![pin], vec![])?;
/// let a = forward_dynamics(&model, &[0.0], &[0.0], &[0.0])?;
/// assert!((a[0] - 9.81 / 2.0).abs() < 1e-14);
/// # Ok::<(), impax::Error>(())
/// ```
pub fn forward_dynamics(model: &Model, q: &[f64], u: &[f64], tau: &[f64]) -> Result<Vec<f64>> {
    let mut ws = Workspace::new(model);
    ws.update(model, q)?;
    let mut udot = vec![0.0; model.nv()];
    forward_dynamics_in(model, &mut ws, u, tau, &mut udot)?;
    Ok(udot)
}

/// The rate of the configuration, `q̇`, from the speeds `u` (into `qdot`, `nq` entries):
/// `q̇ = u` for revolute and prismatic joints; for a free joint the position's rate is
/// `(vx, vy, vz)` and the quaternion's `½ (0, ω) ⊗ q = ½ (−ω·q_v, q_w ω + ω × q_v)` (ω in
/// the parent frame; e.g. Featherstone 2008, §4.6).
///
/// `q` and `u` must have `nq` and `nv` entries (unchecked).
pub fn configuration_rate(model: &Model, q: &[f64], u: &[f64], qdot: &mut [f64]) {
    let d = &model.data;
    for (j, joint) in model.joints.iter().enumerate() {
        let (oq, ov) = (d.q_offset[j], d.v_offset[j]);
        match joint.kind {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => qdot[oq] = u[ov],
            JointKind::Free => {
                qdot[oq..oq + 3].copy_from_slice(&u[ov..ov + 3]);
                let w = Vec3::new(u[ov + 3], u[ov + 4], u[ov + 5]);
                let qw = q[oq + 3];
                let qv = Vec3::new(q[oq + 4], q[oq + 5], q[oq + 6]);
                qdot[oq + 3] = -0.5 * w.dot(&qv);
                let r = (w * qw + w.cross(&qv)) * 0.5;
                qdot[oq + 4..oq + 7].copy_from_slice(r.as_slice());
            }
            JointKind::Fixed => {}
        }
    }
}

/// The second derivative of the configuration, `q̈`, from `(q, u, u̇)` (into `qddot`, `nq`
/// entries): `q̈ = u̇` for revolute and prismatic joints; for a free joint the position's
/// `(v̇x, v̇y, v̇z)` and the quaternion's `½ (0, ω̇) ⊗ q + ½ (0, ω) ⊗ q̇`, the derivative of
/// [`configuration_rate`] along the motion.
///
/// `q`, `u` and `udot` must have `nq`, `nv` and `nv` entries (unchecked).
pub fn configuration_acceleration(
    model: &Model,
    q: &[f64],
    u: &[f64],
    udot: &[f64],
    qddot: &mut [f64],
) {
    let mut qdot = vec![0.0; q.len()];
    configuration_rate(model, q, u, &mut qdot);
    configuration_rate(model, q, udot, qddot);
    let d = &model.data;
    for (j, joint) in model.joints.iter().enumerate() {
        if joint.kind == JointKind::Free {
            let (oq, ov) = (d.q_offset[j], d.v_offset[j]);
            let w = Vec3::new(u[ov + 3], u[ov + 4], u[ov + 5]);
            let rw = qdot[oq + 3];
            let rv = Vec3::new(qdot[oq + 4], qdot[oq + 5], qdot[oq + 6]);
            qddot[oq + 3] -= 0.5 * w.dot(&rv);
            let r = (w * rw + w.cross(&rv)) * 0.5;
            for k in 0..3 {
                qddot[oq + 4 + k] += r[k];
            }
        }
    }
}
