//! Uniform elliptical disc.

use super::rigid::{RigidBody, Side};
use crate::error::{finite, Error, Result};
use crate::math::{Mat2, Vec2};

/// A uniform elliptical disc with semi-axes `a` (along its own x axis) and `b`, its x axis
/// at angle `θ` (radians) from the tangent. `I = m (a² + b²)/4`.
///
/// The contact point is the support point in the direction `d = ∓n`, where the ellipse's
/// normal is the surface's: with `M = R diag(a², b²) Rᵀ`, `r = M d / √(dᵀ M d)`.
///
/// ```
/// use impax::planar::bodies::{ellipse, Side};
/// // A circle of radius 1 touches at distance 1 below the centre.
/// let b = ellipse(1.0, 1.0, 1.0, 0.3, Side::Below).unwrap();
/// assert!((b.contact().y + 1.0).abs() < 1e-15 && b.contact().x.abs() < 1e-15);
/// ```
pub fn ellipse(mass: f64, a: f64, b: f64, angle: f64, side: Side) -> Result<RigidBody> {
    for (field, x) in [("semi-axis-a", a), ("semi-axis-b", b)] {
        finite(field, x)?;
        if x <= 0.0 {
            return Err(Error::OutOfRange {
                field: field.into(),
                value: x,
                reason: "must be > 0".into(),
            });
        }
    }
    finite("angle", angle)?;
    let (s, c) = angle.sin_cos();
    let rot = Mat2::new(c, -s, s, c);
    let m = rot * Mat2::new(a * a, 0.0, 0.0, b * b) * rot.transpose();
    let d: Vec2 = side.direction();
    let md = m * d;
    let r = md / d.dot(&md).sqrt();
    RigidBody::new(mass, mass * (a * a + b * b) / 4.0, r)
}
