//! Any planar rigid body: mass, central moment of inertia, contact point.

use crate::error::{finite, Error, Result};
use crate::math::{cross2, Mat2, Vec2};

/// `a + b`, or exactly zero when the sum is below its rounding error `4 ε (|a| + |b|)`.
#[inline]
pub(crate) fn sum_or_zero(a: f64, b: f64) -> f64 {
    let s = a + b;
    if s.abs() <= 4.0 * f64::EPSILON * (a.abs() + b.abs()) {
        0.0
    } else {
        s
    }
}

/// Which side of the body touches: body A strikes a surface below it (`Below`, contact at
/// the support point along `−n`); the struck body B is met from above (`Above`, along `+n`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// The contact point is the lowest point of the body (body A).
    Below,
    /// The contact point is the highest point of the body (body B).
    Above,
}

impl Side {
    /// The unit direction from the centre toward the contact, in the contact frame.
    pub fn direction(self) -> Vec2 {
        match self {
            Side::Below => Vec2::new(0.0, -1.0),
            Side::Above => Vec2::new(0.0, 1.0),
        }
    }
}

/// Velocity state of a planar body: centre velocity `(v_x, v_y)` (tangent, normal) and the
/// counter-clockwise angular velocity `ω`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BodyState {
    /// Centre-of-mass velocity.
    pub velocity: Vec2,
    /// Angular velocity (counter-clockwise positive, `t × n = +1`).
    pub omega: f64,
}

impl BodyState {
    /// A state from its components.
    pub fn new(vx: f64, vy: f64, omega: f64) -> Self {
        Self {
            velocity: Vec2::new(vx, vy),
            omega,
        }
    }
}

/// A planar rigid body with its contact point.
///
/// With `r = (r_t, r_n)` from the centre of mass to the contact point and `I` the central
/// moment of inertia (theory §1):
///
/// ```text
/// W = [[1/m + r_n²/I, −r_t r_n/I], [−r_t r_n/I, 1/m + r_t²/I]],
/// v_contact = v + ω × r = (v_x − ω r_n, v_y + ω r_t),
/// m Δv = p,   I Δω = r × p = r_t p_n − r_n p_t.
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    mass: f64,
    inertia: f64,
    contact: Vec2,
}

impl RigidBody {
    /// Validate and build (`mass > 0`, `inertia > 0`, finite contact offset).
    pub fn new(mass: f64, inertia: f64, contact: Vec2) -> Result<Self> {
        finite("mass", mass)?;
        finite("inertia", inertia)?;
        finite("contact[t]", contact.x)?;
        finite("contact[n]", contact.y)?;
        if mass <= 0.0 {
            return Err(Error::OutOfRange {
                field: "mass".into(),
                value: mass,
                reason: "must be > 0".into(),
            });
        }
        if inertia <= 0.0 {
            return Err(Error::OutOfRange {
                field: "inertia".into(),
                value: inertia,
                reason: "must be > 0".into(),
            });
        }
        Ok(Self {
            mass,
            inertia,
            contact,
        })
    }

    /// Mass `m`.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Central moment of inertia `I`.
    pub fn inertia(&self) -> f64 {
        self.inertia
    }
    /// Contact point relative to the centre of mass, `r = (r_t, r_n)`.
    pub fn contact(&self) -> Vec2 {
        self.contact
    }

    /// Contact-space inverse inertia `W` of this body at its contact point.
    pub fn inverse_inertia(&self) -> Mat2 {
        let (rt, rn) = (self.contact.x, self.contact.y);
        let (im, ii) = (1.0 / self.mass, 1.0 / self.inertia);
        Mat2::new(
            im + rn * rn * ii,
            -rt * rn * ii,
            -rt * rn * ii,
            im + rt * rt * ii,
        )
    }

    /// Velocity of the material point at the contact: `v + ω × r`.
    ///
    /// Each component is a sum of two terms; a sum smaller than its own rounding error
    /// (`4 ε (|a| + |b|)`) is returned as exactly zero, so that a state meant to have no
    /// slip (e.g. `γ = −sin α` for the seed's sphere, where `sin 30°` is not exactly ½ in
    /// floating point) is not given a spurious slip direction by round-off.
    pub fn contact_velocity(&self, s: &BodyState) -> Vec2 {
        Vec2::new(
            sum_or_zero(s.velocity.x, -s.omega * self.contact.y),
            sum_or_zero(s.velocity.y, s.omega * self.contact.x),
        )
    }

    /// State after the impulse `p` acts at the contact point: `m Δv = p`, `I Δω = r × p`.
    pub fn apply(&self, s: &BodyState, p: Vec2) -> BodyState {
        BodyState {
            velocity: s.velocity + p / self.mass,
            omega: s.omega + cross2(self.contact, p) / self.inertia,
        }
    }

    /// Translational kinetic energy `½ m |v|²`.
    pub fn translational_energy(&self, s: &BodyState) -> f64 {
        0.5 * self.mass * s.velocity.norm_squared()
    }

    /// Rotational kinetic energy `½ I ω²`.
    pub fn rotational_energy(&self, s: &BodyState) -> f64 {
        0.5 * self.inertia * s.omega * s.omega
    }
}
