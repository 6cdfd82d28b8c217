//! The smooth motion and the geometry the run watches: the equations of motion
//! `q̇ = Q(q) u`, `M u̇ = −(C u + g)`, each contact's gap, which contacts touch the floor, and
//! the renormalisation of the free joints' quaternions.

use crate::error::Result;
use crate::multibody::energy::{kinetic_energy, potential_energy};
use crate::multibody::kinematics::{forward_kinematics_with_joints, gap, BodyPose};
use crate::multibody::{configuration_rate, contact_position, forward_dynamics_in};
use crate::multibody::{forward_kinematics, JointKind, Model, Workspace};
use crate::simulation::watch::Probe;
use num_dual::Dual64;

/// The relative size of the touching tolerance (as the planar run's).
const TOUCHING: f64 = 1e-12;

/// The touching tolerance of a contact at `c` on a body whose frame is at `b`
/// ([`Geometry::touching_tolerance`]).
fn tolerance(m: &Model, c: [f64; 3], b: [f64; 3]) -> f64 {
    let lever = ((c[0] - b[0]).powi(2) + (c[1] - b[1]).powi(2) + (c[2] - b[2]).powi(2))
        .sqrt()
        .max(m.data.size);
    let far = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt() + m.floor().abs();
    TOUCHING * lever + 64.0 * f64::EPSILON * far
}

/// The equations of motion of free flight with their workspace.
pub(super) struct Equations<'a> {
    model: &'a Model,
    ws: Workspace,
    tau: Vec<f64>,
}

impl<'a> Equations<'a> {
    pub(super) fn new(model: &'a Model) -> Self {
        Equations {
            model,
            ws: Workspace::new(model),
            tau: vec![0.0; model.nv()],
        }
    }

    /// `ẏ = (q̇, u̇)` at `y = (q, u)`, or the error (an invalid configuration, a singular mass
    /// matrix).
    pub(super) fn try_derivative(&mut self, y: &[f64], dy: &mut [f64]) -> Result<()> {
        let m = self.model;
        let nq = m.nq();
        let (q, u) = y.split_at(nq);
        let (dq, du) = dy.split_at_mut(nq);
        self.ws.update(m, q)?;
        forward_dynamics_in(m, &mut self.ws, u, &self.tau, du)?;
        configuration_rate(m, q, u, dq);
        Ok(())
    }

    /// `ẏ` at `y`, NaN where the equations cannot be evaluated (the integrator then shrinks
    /// its step, or fails naming the equations of motion).
    pub(super) fn derivative(&mut self, y: &[f64], dy: &mut [f64]) {
        if self.try_derivative(y, dy).is_err() {
            dy.iter_mut().for_each(|x| *x = f64::NAN);
        }
    }
}

/// Forward kinematics into reusable buffers, for the gaps and energies at many states.
pub(super) struct Geometry<'a> {
    model: &'a Model,
    poses: Vec<BodyPose<f64>>,
    frames: Vec<BodyPose<f64>>,
    /// A workspace for the energies of samples and of the ledger.
    ws: Workspace,
}

impl<'a> Geometry<'a> {
    pub(super) fn new(model: &'a Model) -> Self {
        Geometry {
            model,
            poses: vec![BodyPose::identity(); model.bodies().len()],
            frames: vec![BodyPose::identity(); model.joints().len()],
            ws: Workspace::new(model),
        }
    }

    fn place(&mut self, q: &[f64]) {
        forward_kinematics_with_joints(self.model, q, &mut self.poses, &mut self.frames);
    }

    /// The gap of contact `k` at the state `y = (q, u)` (or at `q`).
    pub(super) fn gap(&mut self, y: &[f64], k: usize) -> f64 {
        self.place(&y[..self.model.nq()]);
        gap(self.model, &self.poses, k)
    }

    /// Every contact's gap at `y`, into `out`.
    pub(super) fn gaps(&mut self, y: &[f64], out: &mut [f64]) {
        self.place(&y[..self.model.nq()]);
        for (k, o) in out.iter_mut().enumerate() {
            *o = gap(self.model, &self.poses, k);
        }
    }

    /// The touching tolerance of contact `k` at `y`: `10⁻¹² ℓ + 64 ε (|x_c| + |h|)`, `ℓ` the
    /// larger of the contact's lever (its distance from its body's frame origin, the radius
    /// included) and the model's size, `x_c` the contact point and `h` the floor's height —
    /// the planar run's tolerance, with a lever that a foot at its link's origin does not
    /// shrink to nothing.
    pub(super) fn touching_tolerance(&mut self, y: &[f64], k: usize) -> f64 {
        self.place(&y[..self.model.nq()]);
        let m = self.model;
        let c = contact_position(m, &self.poses, k);
        tolerance(m, c, self.poses[m.contacts()[k].body].position)
    }

    /// Every contact's gap, its rate, the speed of its point and the spin of its body at
    /// `(t, y)`, for the watch of the gaps ([`crate::simulation::watch`]): one dual-number
    /// pass of the forward kinematics seeded `q + ε q̇`.
    pub(super) fn probe(&mut self, t: f64, y: &[f64]) -> Probe {
        let m = self.model;
        let (nq, nc) = (m.nq(), m.contacts().len());
        let mut qdot = vec![0.0; nq];
        configuration_rate(m, &y[..nq], &y[nq..nq + m.nv()], &mut qdot);
        let qd: Vec<Dual64> = (0..nq).map(|i| Dual64::new(y[i], qdot[i])).collect();
        let mut poses = vec![BodyPose::<Dual64>::identity(); m.bodies().len()];
        forward_kinematics(m, &qd, &mut poses);
        let mut p = Probe::at(t, nc);
        for k in 0..nc {
            let c = contact_position(m, &poses, k);
            p.gap.push(c[2].re - m.floor());
            p.rate.push(c[2].eps);
            p.speed
                .push((c[0].eps.powi(2) + c[1].eps.powi(2) + c[2].eps.powi(2)).sqrt());
            // |ω| from Ṙ Rᵀ = [ω]×.
            let r = &poses[m.contacts()[k].body].rotation;
            let w = |i: usize, j: usize| (0..3).map(|l| r[i][l].eps * r[j][l].re).sum::<f64>();
            p.spin
                .push((w(2, 1).powi(2) + w(0, 2).powi(2) + w(1, 0).powi(2)).sqrt());
            let b = poses[m.contacts()[k].body].position;
            p.tol.push(tolerance(
                m,
                [c[0].re, c[1].re, c[2].re],
                [b[0].re, b[1].re, b[2].re],
            ));
        }
        p
    }

    /// The contacts that touch the floor at `y` (gap within the touching tolerance).
    pub(super) fn touching(&mut self, y: &[f64]) -> Vec<usize> {
        (0..self.model.contacts().len())
            .filter(|&k| self.gap(y, k) <= self.touching_tolerance(y, k))
            .collect()
    }

    /// `(T, V)` at `y`.
    pub(super) fn energies(&mut self, y: &[f64]) -> Result<(f64, f64)> {
        let m = self.model;
        let (q, u) = y.split_at(m.nq());
        self.ws.update(m, q)?;
        Ok((
            kinetic_energy(m, &mut self.ws, u),
            potential_energy(m, &self.ws).0,
        ))
    }

    /// `T + V` at `y`.
    pub(super) fn energy(&mut self, y: &[f64]) -> Result<f64> {
        self.energies(y).map(|(t, v)| t + v)
    }
}

/// Renormalise every free joint's quaternion in `q` (the first `nq` entries of a state);
/// returns the largest departure `|‖q_quat‖ − 1|` it corrected, `None` when every norm was
/// exactly 1.
pub(crate) fn renormalise(model: &Model, q: &mut [f64]) -> Option<f64> {
    let mut worst: Option<f64> = None;
    for (j, joint) in model.joints().iter().enumerate() {
        if joint.kind != JointKind::Free {
            continue;
        }
        let o = model.joint_offsets(j).0 + 3;
        let quat = &mut q[o..o + 4];
        let norm = quat.iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm != 1.0 && norm > 0.0 {
            worst = Some(worst.unwrap_or(0.0).max((norm - 1.0).abs()));
            quat.iter_mut().for_each(|x| *x /= norm);
        }
    }
    worst
}
