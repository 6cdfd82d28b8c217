//! Uniform rectangle (a box in the plane) striking with one corner.

use super::rigid::{RigidBody, Side};
use crate::error::{finite, Error, Result};
use crate::math::Vec2;

/// A uniform rectangle of half-width `a` and half-height `b` (`half_extents = [a, b]`, along
/// its own x and y axes), its x axis at angle `θ` (radians) from the tangent, striking with one
/// corner (or, as body B, struck at one): `I = m (a² + b²)/3`.
///
/// The corner is `(s_a a, s_b b)` in the body's frame with the signs `corner = [s_a, s_b]`
/// (each `±1`), or, if `None`, the corner lowest along `∓n` (the highest for `Side::Above`).
/// The contact point is that corner turned by `θ`:
///
/// ```text
/// r = (s_a a cos θ − s_b b sin θ,  s_a a sin θ + s_b b cos θ).
/// ```
///
/// When two corners are lowest (an edge on the surface, e.g. at `θ = 0`) the contact is not a
/// single point and the corner must be given.
///
/// ```
/// use impax::planar::bodies::{rectangle, Side};
/// // Tilted by 30°: the lowest corner is (−a, −b) in the body frame.
/// let b = rectangle(1.0, [1.0, 0.5], 30f64.to_radians(), None, Side::Below).unwrap();
/// let (s, c) = 30f64.to_radians().sin_cos();
/// assert!((b.contact().y + (s + 0.5 * c)).abs() < 1e-15);
/// assert!((b.inertia() - 1.25 / 3.0).abs() < 1e-15);
/// // Flat on its long edge the corner must be chosen.
/// assert!(rectangle(1.0, [1.0, 0.5], 0.0, None, Side::Below).is_err());
/// let c = rectangle(1.0, [1.0, 0.5], 0.0, Some([1.0, -1.0]), Side::Below).unwrap();
/// assert_eq!((c.contact().x, c.contact().y), (1.0, -0.5));
/// ```
pub fn rectangle(
    mass: f64,
    half_extents: [f64; 2],
    angle: f64,
    corner: Option<[f64; 2]>,
    side: Side,
) -> Result<RigidBody> {
    let [a, b] = half_extents;
    for (field, x) in [("half_extents[0]", a), ("half_extents[1]", b)] {
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
    let turned = |sa: f64, sb: f64| Vec2::new(sa * a * c - sb * b * s, sa * a * s + sb * b * c);
    let contact = match corner {
        Some([sa, sb]) => {
            if sa.abs() != 1.0 || sb.abs() != 1.0 {
                return Err(Error::Invalid {
                    field: "corner".into(),
                    reason: "each entry must be +1 or -1".into(),
                });
            }
            turned(sa, sb)
        }
        None => {
            // The corner farthest along the direction of the contact, and the runner-up.
            let d = side.direction();
            let mut best = Vec2::zeros();
            let (mut best_h, mut second_h) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
            for (sa, sb) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
                let r = turned(sa, sb);
                let h = r.dot(&d);
                if h > best_h {
                    second_h = best_h;
                    best_h = h;
                    best = r;
                } else if h > second_h {
                    second_h = h;
                }
            }
            if best_h - second_h <= 1e-12 * (a + b) {
                return Err(Error::Invalid {
                    field: "corner".into(),
                    reason: "an edge touches, not one corner: tilt the box or give `corner`".into(),
                });
            }
            best
        }
    };
    RigidBody::new(mass, mass * (a * a + b * b) / 3.0, contact)
}
