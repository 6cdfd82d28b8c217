//! Uniform rod striking with one end.

use super::rigid::{RigidBody, Side};
use crate::error::{finite, Error, Result};
use crate::math::Vec2;

/// A uniform thin rod of length `L` at angle `θ` (radians) from the tangent, `0 < θ < π`,
/// striking with its lowest end (or, as body B, struck at its highest end).
///
/// `I = m L²/12`; the contact point is `r = ∓(L/2)(cos θ, sin θ)`.
///
/// ```
/// use impax::planar::bodies::{rod, Side};
/// let b = rod(1.0, 2.0, 50f64.to_radians(), Side::Below).unwrap();
/// assert!(b.contact().y < 0.0);
/// ```
pub fn rod(mass: f64, length: f64, angle: f64, side: Side) -> Result<RigidBody> {
    finite("length", length)?;
    finite("angle", angle)?;
    if length <= 0.0 {
        return Err(Error::OutOfRange {
            field: "length".into(),
            value: length,
            reason: "must be > 0".into(),
        });
    }
    if !(angle > 0.0 && angle < std::f64::consts::PI) {
        return Err(Error::OutOfRange {
            field: "angle".into(),
            value: angle,
            reason: "a rod touches with one end only for 0 < angle < 180°".into(),
        });
    }
    let half = 0.5 * length * Vec2::new(angle.cos(), angle.sin());
    let r = match side {
        Side::Below => -half,
        Side::Above => half,
    };
    RigidBody::new(mass, mass * length * length / 12.0, r)
}
