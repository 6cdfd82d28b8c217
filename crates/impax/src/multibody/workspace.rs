//! Spatial vectors in world axes and the reusable [`Workspace`] of the `f64` algorithms.
//!
//! Every spatial quantity is expressed in world axes about one reference point `O` fixed in
//! space for the instant (the origin of the first joint's frame: the floating base's, or a
//! fixed base's root), so that no transform is needed between bodies and lever arms stay
//! as short as the robot (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, ch. 2: motion
//! vectors `(ω, v_O)`, force vectors `(n_O, f)`, and the algorithms in absolute coordinates of
//! §5.3 and §6.2).

use super::joint::JointKind;
use super::kinematics::{forward_kinematics_with_joints, BodyPose};
use super::model::Model;
use crate::error::Result;
use crate::math::{Mat3, Vec3};
use nalgebra::DMatrix;

/// A motion vector `(ω, v_O)`: angular velocity and the velocity of the body point at `O`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Motion {
    pub(crate) w: Vec3,
    pub(crate) v: Vec3,
}

/// A force vector `(n_O, f)`: moment about `O` and force.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Force {
    pub(crate) n: Vec3,
    pub(crate) f: Vec3,
}

impl Motion {
    /// `self × m = (ω × m_ω, ω × m_v + v × m_ω)` (Featherstone eq. 2.31).
    #[inline]
    pub(crate) fn cross(&self, m: &Motion) -> Motion {
        Motion {
            w: self.w.cross(&m.w),
            v: self.w.cross(&m.v) + self.v.cross(&m.w),
        }
    }

    /// `self ×* f = (ω × n + v × f, ω × f)` (Featherstone eq. 2.32).
    #[inline]
    pub(crate) fn cross_force(&self, f: &Force) -> Force {
        Force {
            n: self.w.cross(&f.n) + self.v.cross(&f.f),
            f: self.w.cross(&f.f),
        }
    }

    /// The power `m · f = ω·n + v·f`.
    #[inline]
    pub(crate) fn dot(&self, f: &Force) -> f64 {
        self.w.dot(&f.n) + self.v.dot(&f.f)
    }

    /// `self + m s`.
    #[inline]
    pub(crate) fn add_scaled(&self, m: &Motion, s: f64) -> Motion {
        Motion {
            w: self.w + m.w * s,
            v: self.v + m.v * s,
        }
    }

    /// The velocity of the point at `r` (relative to `O`) of a body moving with `self`:
    /// `v_O + ω × r`.
    #[inline]
    pub(crate) fn point_velocity(&self, r: &Vec3) -> Vec3 {
        self.v + self.w.cross(r)
    }
}

/// A spatial inertia about `O` in world axes: mass `m`, first moment `h = m c` (`c` the
/// centre of mass relative to `O`) and rotational inertia about `O`,
/// `Ī = I_c + m (|c|² 1 − c cᵀ)` (Featherstone eq. 2.63).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Inertia {
    pub(crate) m: f64,
    pub(crate) h: Vec3,
    pub(crate) i: Mat3,
}

impl Default for Inertia {
    fn default() -> Self {
        Inertia {
            m: 0.0,
            h: Vec3::zeros(),
            i: Mat3::zeros(),
        }
    }
}

impl Inertia {
    /// `I m = (Ī ω + h × v, m v − h × ω)`.
    #[inline]
    pub(crate) fn apply(&self, m: &Motion) -> Force {
        Force {
            n: self.i * m.w + self.h.cross(&m.v),
            f: m.v * self.m - self.h.cross(&m.w),
        }
    }

    #[inline]
    pub(crate) fn add(&mut self, other: &Inertia) {
        self.m += other.m;
        self.h += other.h;
        self.i += other.i;
    }
}

/// Reusable storage of the `f64` algorithms for one model: the kinematics at the last
/// configuration given to [`Workspace::update`] and room for the mass matrix, its factor
/// and the recursions, so that repeated evaluations allocate nothing.
///
/// ```
/// use impax::multibody::{Body, Joint, Model, Placement, Workspace};
/// use impax::math::{Mat3, Vec3};
/// let bob = Body::new("bob", 2.0, Vec3::new(0.0, 0.0, -1.0), Mat3::zeros());
/// let pin = Joint::revolute("pin", Vec3::y(), None, 0, Placement::identity());
/// let model = Model::new(vec![bob], vec![pin], vec![])?;
/// let mut ws = Workspace::new(&model);
/// ws.update(&model, &[0.3])?;
/// // M = m l² for a point mass on a rod.
/// assert!((impax::multibody::crba(&model, &mut ws)[(0, 0)] - 2.0).abs() < 1e-15);
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Workspace {
    /// The configuration (quaternions normalised).
    pub(crate) q: Vec<f64>,
    pub(crate) poses: Vec<BodyPose<f64>>,
    pub(crate) frames: Vec<BodyPose<f64>>,
    /// The reference point `O` (world).
    pub(crate) origin: Vec3,
    /// The motion subspace: one motion vector per speed.
    pub(crate) subspace: Vec<Motion>,
    /// Each body's spatial inertia about `O`.
    pub(crate) inertia: Vec<Inertia>,
    pub(crate) composite: Vec<Inertia>,
    pub(crate) mass: DMatrix<f64>,
    /// The factor `L` of `M = Lᵀ L` ([`super::factor`], lower triangular, the sparsity of
    /// `M`) when factored.
    pub(crate) factor: DMatrix<f64>,
    pub(crate) velocity: Vec<Motion>,
    pub(crate) acceleration: Vec<Motion>,
    pub(crate) force: Vec<Force>,
    pub(crate) scratch: Vec<f64>,
}

impl Workspace {
    /// Storage for `model`, at its neutral configuration.
    pub fn new(model: &Model) -> Self {
        let (nb, nj, nv) = (model.bodies.len(), model.joints.len(), model.nv());
        let mut ws = Workspace {
            q: model.neutral(),
            poses: vec![BodyPose::identity(); nb],
            frames: vec![BodyPose::identity(); nj],
            origin: Vec3::zeros(),
            subspace: vec![Motion::default(); nv],
            inertia: vec![Inertia::default(); nb],
            composite: vec![Inertia::default(); nb],
            mass: DMatrix::zeros(nv, nv),
            factor: DMatrix::zeros(nv, nv),
            velocity: vec![Motion::default(); nb],
            acceleration: vec![Motion::default(); nb],
            force: vec![Force::default(); nb],
            scratch: vec![0.0; nv],
        };
        let q = ws.q.clone();
        ws.kinematics(model, &q);
        ws
    }

    /// Check `q` ([`Model::check_state`]) and compute the kinematics there: body poses,
    /// joint frames, the motion subspace and the bodies' spatial inertias.
    ///
    /// # Errors
    /// As [`Model::check_state`].
    pub fn update(&mut self, model: &Model, q: &[f64]) -> Result<()> {
        let mut checked = std::mem::take(&mut self.q);
        let result = model.check_configuration_into(q, &mut checked);
        if result.is_ok() {
            self.kinematics(model, &checked);
        }
        self.q = checked;
        result
    }

    /// The configuration of the last update (quaternions normalised).
    pub fn configuration(&self) -> &[f64] {
        &self.q
    }

    /// The bodies' world poses at the last update.
    pub fn poses(&self) -> &[BodyPose<f64>] {
        &self.poses
    }

    /// The kinematics at a checked `q`.
    fn kinematics(&mut self, model: &Model, q: &[f64]) {
        forward_kinematics_with_joints(model, q, &mut self.poses, &mut self.frames);
        self.origin = self.frames[0].position_vector();
        let d = &model.data;
        for (j, joint) in model.joints.iter().enumerate() {
            let f = &self.frames[j];
            let r = f.position_vector() - self.origin;
            let rot = f.rotation_matrix();
            let s = &mut self.subspace[d.v_offset[j]..];
            match joint.kind {
                JointKind::Revolute { axis } => {
                    let a = rot * axis;
                    s[0] = Motion {
                        w: a,
                        v: r.cross(&a),
                    };
                }
                JointKind::Prismatic { axis } => {
                    s[0] = Motion {
                        w: Vec3::zeros(),
                        v: rot * axis,
                    };
                }
                JointKind::Free => {
                    // u in the axes of the frame before the joint's motion (the placement's:
                    // the parent is the world).
                    let r0 = joint.placement.rotation;
                    for k in 0..3 {
                        let e = r0.column(k).into_owned();
                        s[k] = Motion {
                            w: Vec3::zeros(),
                            v: e,
                        };
                        s[3 + k] = Motion {
                            w: e,
                            v: r.cross(&e),
                        };
                    }
                }
                JointKind::Fixed => {}
            }
        }
        for (b, body) in model.bodies.iter().enumerate() {
            let pose = &self.poses[b];
            let rot = pose.rotation_matrix();
            let c = pose.position_vector() + rot * body.com - self.origin;
            let m = body.mass;
            let outer = Mat3::identity() * c.norm_squared() - c * c.transpose();
            self.inertia[b] = Inertia {
                m,
                h: c * m,
                i: rot * body.inertia * rot.transpose() + outer * m,
            };
        }
    }
}
