//! Any spatial rigid body.

use crate::error::{finite, Error, Num, Result};
use crate::math::{Mat3, Vec3};
use nalgebra::UnitQuaternion;

/// Velocity state: centre-of-mass velocity and angular velocity, both in the world frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BodyState {
    /// Centre-of-mass velocity.
    pub velocity: Vec3,
    /// Angular velocity (world frame).
    pub omega: Vec3,
}

impl BodyState {
    /// A state from its parts.
    pub fn new(velocity: Vec3, omega: Vec3) -> Self {
        Self { velocity, omega }
    }
}

/// Kinetic energy in translational `½ m |v|²` and rotational `½ ωᵀ I ω` parts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyParts {
    /// Translational part.
    pub translational: f64,
    /// Rotational part.
    pub rotational: f64,
}

impl EnergyParts {
    /// Both parts.
    pub fn total(&self) -> f64 {
        self.translational + self.rotational
    }
}

/// A rigid body with its contact point (theory §1):
///
/// ```text
/// W = (1/m) 1 − [r]× I⁻¹ [r]×,   v_contact = v + ω × r,   m Δv = p,   I Δω = r × p,
/// ```
///
/// with `r` the contact point from the centre of mass and `I` the inertia tensor, both in
/// the world frame (`I = R I_body Rᵀ`, `r = R r_body`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    mass: f64,
    inertia: Mat3,
    inertia_inv: Mat3,
    contact: Vec3,
}

impl RigidBody {
    /// Validate and build from the body-frame inertia tensor (symmetric positive definite),
    /// the orientation (body → world) and the body-frame contact point.
    pub fn new(
        mass: f64,
        inertia_body: Mat3,
        orientation: UnitQuaternion<f64>,
        contact_body: Vec3,
    ) -> Result<Self> {
        finite("mass", mass)?;
        if mass <= 0.0 {
            return Err(Error::OutOfRange {
                field: "mass".into(),
                value: mass,
                reason: "must be > 0".into(),
            });
        }
        for i in 0..3 {
            for j in 0..3 {
                finite("inertia", inertia_body[(i, j)])?;
            }
            finite("contact", contact_body[i])?;
        }
        for k in orientation.coords.iter() {
            finite("orientation", *k)?;
        }
        let asym = (inertia_body - inertia_body.transpose()).abs().max();
        if asym > 1e-12 * inertia_body.abs().max() {
            return Err(Error::Invalid {
                field: "inertia".into(),
                reason: "the inertia tensor must be symmetric".into(),
            });
        }
        let ib = 0.5 * (inertia_body + inertia_body.transpose());
        if ib.cholesky().is_none() {
            return Err(Error::Invalid {
                field: "inertia".into(),
                reason: "the inertia tensor must be positive definite".into(),
            });
        }
        let eig = ib.symmetric_eigenvalues();
        let (a, b, c) = (eig[0], eig[1], eig[2]);
        let tol = 1e-12 * (a + b + c);
        if a + b < c - tol || a + c < b - tol || b + c < a - tol {
            return Err(Error::Invalid {
                field: "inertia".into(),
                reason: format!(
                    "principal moments {}, {}, {} violate the triangle inequality of a rigid body",
                    Num(a),
                    Num(b),
                    Num(c)
                ),
            });
        }
        let r = orientation.to_rotation_matrix();
        let inertia = r.matrix() * ib * r.matrix().transpose();
        let inertia_inv = inertia.try_inverse().ok_or_else(|| Error::Invalid {
            field: "inertia".into(),
            reason: "singular".into(),
        })?;
        Ok(Self {
            mass,
            inertia,
            inertia_inv,
            contact: r * contact_body,
        })
    }

    /// Mass.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// World-frame inertia tensor.
    pub fn inertia(&self) -> &Mat3 {
        &self.inertia
    }
    /// World-frame contact point from the centre of mass.
    pub fn contact(&self) -> Vec3 {
        self.contact
    }

    /// `W = (1/m) 1 − [r]× I⁻¹ [r]×`.
    pub fn inverse_inertia(&self) -> Mat3 {
        let rx = self.contact.cross_matrix();
        Mat3::identity() / self.mass - rx * self.inertia_inv * rx
    }

    /// Velocity of the material point at the contact, `v + ω × r`.
    pub fn contact_velocity(&self, s: &BodyState) -> Vec3 {
        s.velocity + s.omega.cross(&self.contact)
    }

    /// State after the impulse `p` at the contact point.
    pub fn apply(&self, s: &BodyState, p: Vec3) -> BodyState {
        BodyState {
            velocity: s.velocity + p / self.mass,
            omega: s.omega + self.inertia_inv * self.contact.cross(&p),
        }
    }

    /// Kinetic energy split.
    pub fn energy(&self, s: &BodyState) -> EnergyParts {
        EnergyParts {
            translational: 0.5 * self.mass * s.velocity.norm_squared(),
            rotational: 0.5 * s.omega.dot(&(self.inertia * s.omega)),
        }
    }
}
