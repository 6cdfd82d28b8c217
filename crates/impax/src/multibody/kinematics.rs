//! Forward kinematics, generic over the scalar ([`Real`]: `f64` and the dual numbers of
//! automatic differentiation): each body's world orientation and position, a body point's
//! world position, a contact's floor gap.
//!
//! A joint places its child by `X_child = X_parent ∘ placement ∘ X_J(q) ∘ child_placement⁻¹`
//! (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §4.1–4.4), with the joint
//! transforms
//!
//! ```text
//! revolute   X_J = (1 + sin q [a]ₓ + (1 − cos q) [a]ₓ², 0)        (Rodrigues)
//! prismatic  X_J = (1, q a)
//! free       X_J = (R(qw, qx, qy, qz), (x, y, z)),  R of the normalised quaternion
//! fixed      X_J = identity
//! ```

use super::joint::{JointKind, Placement};
use super::model::Model;
use crate::math::Vec3;
use crate::mechanism::Real;

/// A body's (or a joint frame's) pose in the world: a point with body coordinates `x` is at
/// `R x + p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyPose<D> {
    /// Orientation `R`, body → world, by rows.
    pub rotation: [[D; 3]; 3],
    /// Position `p` of the body frame's origin.
    pub position: [D; 3],
}

impl<D: Real> BodyPose<D> {
    /// The world frame itself.
    pub fn identity() -> Self {
        let (o, z) = (D::one(), D::zero());
        BodyPose {
            rotation: [[o, z, z], [z, o, z], [z, z, o]],
            position: [z; 3],
        }
    }

    /// A constant placement as a pose.
    pub fn from_placement(x: &Placement) -> Self {
        BodyPose {
            rotation: std::array::from_fn(|i| std::array::from_fn(|j| D::from(x.rotation[(i, j)]))),
            position: std::array::from_fn(|i| D::from(x.translation[i])),
        }
    }

    /// World position `R x + p` of the body point `x`.
    pub fn point(&self, x: &Vec3) -> [D; 3] {
        let r = &self.rotation;
        std::array::from_fn(|i| r[i][0] * x[0] + r[i][1] * x[1] + r[i][2] * x[2] + self.position[i])
    }

    /// `self ∘ other`.
    pub fn compose(&self, other: &BodyPose<D>) -> BodyPose<D> {
        let (a, b) = (&self.rotation, &other.rotation);
        BodyPose {
            rotation: std::array::from_fn(|i| {
                std::array::from_fn(|j| a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j])
            }),
            position: std::array::from_fn(|i| {
                a[i][0] * other.position[0]
                    + a[i][1] * other.position[1]
                    + a[i][2] * other.position[2]
                    + self.position[i]
            }),
        }
    }

    /// `self ∘ x` with a constant placement `x`.
    pub fn compose_placement(&self, x: &Placement) -> BodyPose<D> {
        let (a, b, t) = (&self.rotation, &x.rotation, &x.translation);
        BodyPose {
            rotation: std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    a[i][0] * b[(0, j)] + a[i][1] * b[(1, j)] + a[i][2] * b[(2, j)]
                })
            }),
            position: std::array::from_fn(|i| {
                a[i][0] * t[0] + a[i][1] * t[1] + a[i][2] * t[2] + self.position[i]
            }),
        }
    }
}

impl BodyPose<f64> {
    /// The rotation as a matrix.
    pub fn rotation_matrix(&self) -> crate::math::Mat3 {
        crate::math::Mat3::from_fn(|i, j| self.rotation[i][j])
    }

    /// The position as a vector.
    pub fn position_vector(&self) -> Vec3 {
        Vec3::new(self.position[0], self.position[1], self.position[2])
    }
}

/// The joint transform `X_J(q)` of one joint, from its own coordinates `q` (`nq` of them).
pub fn joint_transform<D: Real>(kind: &JointKind, q: &[D]) -> BodyPose<D> {
    let mut x = BodyPose::identity();
    match *kind {
        JointKind::Revolute { axis: a } => {
            let (s, c) = q[0].sin_cos();
            let k = D::one() - c;
            let a = [a.x, a.y, a.z];
            // R = c 1 + s [a]ₓ + (1 − c) a aᵀ (Rodrigues, |a| = 1).
            for i in 0..3 {
                for j in 0..3 {
                    x.rotation[i][j] = k * (a[i] * a[j]);
                }
                x.rotation[i][i] += c;
            }
            x.rotation[0][1] -= s * a[2];
            x.rotation[0][2] += s * a[1];
            x.rotation[1][0] += s * a[2];
            x.rotation[1][2] -= s * a[0];
            x.rotation[2][0] -= s * a[1];
            x.rotation[2][1] += s * a[0];
        }
        JointKind::Prismatic { axis } => {
            x.position = [q[0] * axis.x, q[0] * axis.y, q[0] * axis.z];
        }
        JointKind::Free => {
            x.rotation = quaternion_rotation(q[3], q[4], q[5], q[6]);
            x.position = [q[0], q[1], q[2]];
        }
        JointKind::Fixed => {}
    }
    x
}

/// The rotation of the quaternion `w + x i + y j + z k` divided by its norm (homogeneous
/// form: every entry over `w² + x² + y² + z²`).
pub fn quaternion_rotation<D: Real>(w: D, x: D, y: D, z: D) -> [[D; 3]; 3] {
    let (ww, xx, yy, zz) = (w * w, x * x, y * y, z * z);
    let s = (ww + xx + yy + zz).recip();
    let two = s + s;
    let (xy, xz, yz, wx, wy, wz) = (x * y, x * z, y * z, w * x, w * y, w * z);
    [
        [(ww + xx - yy - zz) * s, (xy - wz) * two, (xz + wy) * two],
        [(xy + wz) * two, (ww - xx + yy - zz) * s, (yz - wx) * two],
        [(xz - wy) * two, (yz + wx) * two, (ww - xx - yy + zz) * s],
    ]
}

/// Every body's world pose at `q` (`poses.len()` = number of bodies), and every joint
/// frame's world pose after its motion, `X_parent ∘ placement ∘ X_J(q)` (`joints.len()` =
/// number of joints).
pub fn forward_kinematics_with_joints<D: Real>(
    model: &Model,
    q: &[D],
    poses: &mut [BodyPose<D>],
    joint_frames: &mut [BodyPose<D>],
) {
    let d = &model.data;
    for (j, joint) in model.joints.iter().enumerate() {
        let before = match joint.parent {
            Some(p) => poses[p].compose_placement(&joint.placement),
            None => BodyPose::from_placement(&joint.placement),
        };
        let frame = match joint.kind {
            JointKind::Fixed => before,
            kind => before.compose(&joint_transform(&kind, &q[d.q_offset[j]..])),
        };
        poses[joint.child] = if joint.child_placement.is_identity() {
            frame
        } else {
            frame.compose_placement(&d.child_inverse[j])
        };
        joint_frames[j] = frame;
    }
}

/// Every body's world pose at `q` (`poses.len()` = number of bodies).
///
/// ```
/// use impax::multibody::{forward_kinematics, Body, BodyPose, Joint, Model, Placement};
/// use impax::math::{Mat3, Vec3};
/// let bob = Body::new("bob", 1.0, Vec3::new(0.0, 0.0, -1.0), Mat3::zeros());
/// let pin = Joint::revolute("pin", Vec3::y(), None, 0, Placement::identity());
/// let model = Model::new(vec![bob], vec![pin], vec![])?;
/// let mut poses = [BodyPose::identity()];
/// forward_kinematics(&model, &[std::f64::consts::FRAC_PI_2], &mut poses);
/// // A quarter turn about y takes the bob from below the pin to −x.
/// let p = poses[0].point(&Vec3::new(0.0, 0.0, -1.0));
/// assert!((p[0] + 1.0).abs() < 1e-15 && p[2].abs() < 1e-15);
/// # Ok::<(), impax::Error>(())
/// ```
pub fn forward_kinematics<D: Real>(model: &Model, q: &[D], poses: &mut [BodyPose<D>]) {
    let mut frames = vec![BodyPose::identity(); model.joints.len()];
    forward_kinematics_with_joints(model, q, poses, &mut frames);
}

/// The world position where contact `k` touches: `p_b + R_b point − r e_z` (the body's
/// material point at the bottom of a round foot).
pub fn contact_position<D: Real>(model: &Model, poses: &[BodyPose<D>], k: usize) -> [D; 3] {
    let c = &model.contacts[k];
    let mut x = poses[c.body].point(&c.point);
    x[2] -= D::from(c.radius);
    x
}

/// The floor gap of contact `k`: `φ = z_c − h` (negative: below the floor).
pub fn gap<D: Real>(model: &Model, poses: &[BodyPose<D>], k: usize) -> D {
    contact_position(model, poses, k)[2] - D::from(model.floor)
}

/// The gap of contact `k` and its first two time derivatives along the motion `(q, u, u̇)`:
/// `[φ, φ̇, φ̈]` with `φ̇ = ∇φ·q̇` and `φ̈ = ∇φ·q̈ + q̇ᵀ ∇²φ q̇` (`q̇`, `q̈` from
/// [`super::configuration_rate`] and [`super::configuration_acceleration`]), by one
/// hyper-dual pass of the forward kinematics seeded `q + ε₁ q̇ + ε₂ q̇ + ε₁ε₂ q̈`.
///
/// `q`, `u` and `udot` must have `nq`, `nv` and `nv` entries (unchecked; `q` with unit
/// quaternions).
///
/// ```
/// use impax::multibody::{gap_rates, Body, ContactPoint, Joint, Model};
/// use impax::math::{Mat3, Vec3};
/// // A ball of radius 0.1 at height 1, falling at 2 m/s and spinning: φ = 0.9, φ̇ = −2,
/// // φ̈ = −g.
/// let ball = Body::new("ball", 1.0, Vec3::zeros(), Mat3::identity() * 0.004);
/// let foot = ContactPoint::new("bottom", 0, Vec3::zeros(), 0.1);
/// let model = Model::new(vec![ball], vec![Joint::free("root", 0)], vec![foot])?;
/// let q = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0];
/// let u = [0.0, 0.0, -2.0, 3.0, 0.0, 1.0];
/// let udot = [0.0, 0.0, -9.81, 0.0, 0.0, 0.0];
/// let [phi, rate, accel] = gap_rates(&model, &q, &u, &udot, 0);
/// assert!((phi - 0.9).abs() < 1e-15 && (rate + 2.0).abs() < 1e-15);
/// assert!((accel + 9.81).abs() < 1e-14);
/// # Ok::<(), impax::Error>(())
/// ```
pub fn gap_rates(model: &Model, q: &[f64], u: &[f64], udot: &[f64], k: usize) -> [f64; 3] {
    use num_dual::HyperDual64;
    let mut qdot = vec![0.0; q.len()];
    let mut qddot = vec![0.0; q.len()];
    super::configuration_rate(model, q, u, &mut qdot);
    super::configuration_acceleration(model, q, u, udot, &mut qddot);
    let qh: Vec<HyperDual64> = (0..q.len())
        .map(|i| HyperDual64::new(q[i], qdot[i], qdot[i], qddot[i]))
        .collect();
    let mut poses = vec![BodyPose::identity(); model.bodies.len()];
    forward_kinematics(model, &qh, &mut poses);
    let g = gap(model, &poses, k);
    [g.re, g.eps1, g.eps1eps2]
}
