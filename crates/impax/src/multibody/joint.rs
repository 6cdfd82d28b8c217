//! Joints of a kinematic tree: their kinds, their placements, and the joint transform
//! `X_J(q)` of each kind (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §4.4 and
//! table 4.1).

use crate::error::{Error, Num, Result};
use crate::math::{Mat3, Vec3};

/// A rigid transform: a frame's orientation `R` and origin `p` in another frame, so that a
/// point with coordinates `x` in the frame has coordinates `R x + p` outside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Rotation `R` (orthonormal, determinant +1).
    pub rotation: Mat3,
    /// Translation `p`, the frame's origin.
    pub translation: Vec3,
}

impl Default for Placement {
    fn default() -> Self {
        Self::identity()
    }
}

impl Placement {
    /// The identity: the frame coincides with the outer one.
    pub fn identity() -> Self {
        Placement {
            rotation: Mat3::identity(),
            translation: Vec3::zeros(),
        }
    }

    /// A pure translation.
    pub fn from_translation(p: Vec3) -> Self {
        Placement {
            rotation: Mat3::identity(),
            translation: p,
        }
    }

    /// From a rotation and a translation (the rotation is checked by [`Placement::check`]
    /// when the placement enters a model).
    pub fn new(rotation: Mat3, translation: Vec3) -> Self {
        Placement {
            rotation,
            translation,
        }
    }

    /// URDF's `<origin xyz rpy>`: fixed-axis roll, pitch, yaw,
    /// `R = Rz(yaw) Ry(pitch) Rx(roll)` (ROS REP 103; theory §7).
    ///
    /// ```
    /// use impax::multibody::Placement;
    /// use impax::math::Vec3;
    /// let x = Placement::from_xyz_rpy([1.0, 2.0, 3.0], [0.0, 0.0, std::f64::consts::FRAC_PI_2]);
    /// // A quarter turn about z takes the frame's x axis to the outer y axis.
    /// let p = x.transform_point(&Vec3::new(1.0, 0.0, 0.0));
    /// assert!((p - Vec3::new(1.0, 3.0, 3.0)).norm() < 1e-15);
    /// ```
    pub fn from_xyz_rpy(xyz: [f64; 3], rpy: [f64; 3]) -> Self {
        Placement {
            rotation: rpy_rotation(rpy),
            translation: Vec3::new(xyz[0], xyz[1], xyz[2]),
        }
    }

    /// `self ∘ other`: `other`'s frame placed in `self`'s frame, seen from outside `self`.
    pub fn compose(&self, other: &Placement) -> Placement {
        Placement {
            rotation: self.rotation * other.rotation,
            translation: self.rotation * other.translation + self.translation,
        }
    }

    /// The inverse transform `(Rᵀ, −Rᵀ p)`.
    pub fn inverse(&self) -> Placement {
        let rt = self.rotation.transpose();
        Placement {
            rotation: rt,
            translation: -(rt * self.translation),
        }
    }

    /// A point's outer coordinates, `R x + p`.
    pub fn transform_point(&self, x: &Vec3) -> Vec3 {
        self.rotation * x + self.translation
    }

    /// Whether this is the identity exactly.
    pub fn is_identity(&self) -> bool {
        *self == Placement::identity()
    }

    /// Check that every entry is finite and that the rotation is orthonormal with determinant
    /// +1 to `1e-9` (a placement read from six-digit text passes); `field` names it in the
    /// error. Returns the placement with its rotation re-orthonormalised (nearest rotation).
    pub fn check(&self, field: &str) -> Result<Placement> {
        for (i, x) in self
            .rotation
            .iter()
            .chain(self.translation.iter())
            .enumerate()
        {
            if !x.is_finite() {
                return Err(Error::NotFinite {
                    field: format!("{field}[{i}]"),
                    value: *x,
                });
            }
        }
        let r = self.rotation;
        let defect = (r.transpose() * r - Mat3::identity()).amax();
        let det = r.determinant();
        if defect > 1e-9 || det <= 0.0 {
            return Err(Error::Invalid {
                field: format!("{field}.rotation"),
                reason: format!(
                    "must be a rotation (orthonormal, determinant +1): |RᵀR − 1| = {}, det R = {}",
                    Num(defect),
                    Num(det)
                ),
            });
        }
        Ok(Placement {
            rotation: orthonormalise(&r),
            translation: self.translation,
        })
    }
}

/// The nearest rotation to an almost orthonormal `r` (two steps of the polar iteration
/// `R ← ½ (R + R⁻ᵀ)`, quadratic: 1e-9 → round-off).
fn orthonormalise(r: &Mat3) -> Mat3 {
    let mut r = *r;
    for _ in 0..2 {
        if let Some(inv) = r.try_inverse() {
            r = 0.5 * (r + inv.transpose());
        }
    }
    r
}

/// `R = Rz(y) Ry(p) Rx(r)` of URDF's roll–pitch–yaw (fixed axes x, then y, then z).
pub fn rpy_rotation(rpy: [f64; 3]) -> Mat3 {
    let (sr, cr) = rpy[0].sin_cos();
    let (sp, cp) = rpy[1].sin_cos();
    let (sy, cy) = rpy[2].sin_cos();
    Mat3::new(
        cy * cp,
        cy * sp * sr - sy * cr,
        cy * sp * cr + sy * sr,
        sy * cp,
        sy * sp * sr + cy * cr,
        sy * sp * cr - cy * sr,
        -sp,
        cp * sr,
        cp * cr,
    )
}

/// The kind of a joint and its motion subspace (Featherstone 2008, table 4.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointKind {
    /// Rotation by `q` about a unit axis through the joint frame's origin (axis in the joint
    /// frame): `X_J(q) = (exp(q [a]ₓ), 0)`; one coordinate, `u = q̇`.
    Revolute {
        /// Unit axis in the joint frame.
        axis: Vec3,
    },
    /// Translation by `q` along a unit axis: `X_J(q) = (1, q a)`; one coordinate, `u = q̇`.
    Prismatic {
        /// Unit axis in the joint frame.
        axis: Vec3,
    },
    /// No motion: the child is welded to the parent.
    Fixed,
    /// A floating base (the parent must be the world): seven coordinates
    /// `q = (x, y, z, qw, qx, qy, qz)`, the origin of the child frame and a unit quaternion
    /// (child → parent), and six speeds `u = (vx, vy, vz, wx, wy, wz)`: the velocity of the
    /// child frame's origin and the angular velocity, both in the parent frame. The child
    /// frame is the joint frame on the child (the child body's frame when
    /// `child_placement` is the identity) and the parent frame is `placement` (the world when
    /// it is the identity): with both identities, as the URDF reader makes them, `q` is the
    /// base's pose in the world and `u` its velocity in world axes (not Pinocchio's
    /// base-frame velocity). Then `(ẋ, ẏ, ż) = (vx, vy, vz)` and
    /// `q̇_quat = ½ (0, ω) ⊗ q_quat`.
    Free,
}

impl JointKind {
    /// Number of configuration coordinates `nq` (7 for a free joint, its quaternion
    /// included).
    pub fn nq(&self) -> usize {
        match self {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => 1,
            JointKind::Fixed => 0,
            JointKind::Free => 7,
        }
    }

    /// Number of speeds `nv` (degrees of freedom).
    pub fn nv(&self) -> usize {
        match self {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => 1,
            JointKind::Fixed => 0,
            JointKind::Free => 6,
        }
    }

    /// Its id: `revolute`, `prismatic`, `fixed`, `free`.
    pub fn id(&self) -> &'static str {
        match self {
            JointKind::Revolute { .. } => "revolute",
            JointKind::Prismatic { .. } => "prismatic",
            JointKind::Fixed => "fixed",
            JointKind::Free => "free",
        }
    }
}

/// A joint of a kinematic tree: it places its child body in its parent body (or the world).
///
/// The child's frame in the parent's: `X = placement ∘ X_J(q) ∘ child_placement⁻¹`, where
/// `placement` is the joint frame in the parent body's frame and `child_placement` the joint
/// frame in the child body's frame (the identity for URDF, whose child link frame is the joint
/// frame).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Its name, unique in the model (a revolute or prismatic joint's coordinate is named by
    /// it).
    pub name: String,
    /// Its kind and axis.
    pub kind: JointKind,
    /// The parent body's index, or `None` for the world. In tree order: the parent is the
    /// child of an earlier joint.
    pub parent: Option<usize>,
    /// The child body's index (each body is the child of exactly one joint).
    pub child: usize,
    /// The joint frame in the parent body's frame (or the world's).
    pub placement: Placement,
    /// The joint frame in the child body's frame.
    pub child_placement: Placement,
}

impl Joint {
    /// A joint with `child_placement` the identity (as in URDF).
    pub fn new(
        name: &str,
        kind: JointKind,
        parent: Option<usize>,
        child: usize,
        placement: Placement,
    ) -> Self {
        Joint {
            name: name.to_string(),
            kind,
            parent,
            child,
            placement,
            child_placement: Placement::identity(),
        }
    }

    /// A revolute joint about `axis` (in the joint frame).
    pub fn revolute(
        name: &str,
        axis: Vec3,
        parent: Option<usize>,
        child: usize,
        placement: Placement,
    ) -> Self {
        Self::new(name, JointKind::Revolute { axis }, parent, child, placement)
    }

    /// A floating base: the free joint of `child` to the world, with an identity placement.
    pub fn free(name: &str, child: usize) -> Self {
        Self::new(name, JointKind::Free, None, child, Placement::identity())
    }
}

/// Check an axis: finite and nonzero, and return it normalised.
pub(crate) fn unit_axis(field: &str, axis: &Vec3) -> Result<Vec3> {
    for (i, a) in axis.iter().enumerate() {
        if !a.is_finite() {
            return Err(Error::NotFinite {
                field: format!("{field}[{i}]"),
                value: *a,
            });
        }
    }
    let n = axis.norm();
    if n == 0.0 || !n.is_finite() {
        return Err(Error::Invalid {
            field: field.into(),
            reason: format!(
                "must be a nonzero direction, got ({}, {}, {})",
                axis.x, axis.y, axis.z
            ),
        });
    }
    Ok(axis / n)
}
