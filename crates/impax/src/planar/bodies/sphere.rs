//! Sphere and disc on a plane (paper A, Fig. 2).

use super::rigid::{BodyState, RigidBody, Side};
use crate::error::{finite, Error, Result};

fn positive(field: &str, x: f64) -> Result<f64> {
    finite(field, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value: x,
            reason: "must be > 0".into(),
        })
    }
}

/// A solid sphere in planar motion: `I = 2/5 m r²`, contact at distance `r` along `∓n`.
///
/// On a fixed plane `W = (1/m) diag(7/2, 1)`.
///
/// ```
/// use impax::planar::bodies::{sphere, Side};
/// let w = sphere(1.0, 1.0, Side::Below).unwrap().inverse_inertia();
/// assert!((w[(0, 0)] - 3.5).abs() < 1e-15 && w[(0, 1)] == 0.0 && w[(1, 1)] == 1.0);
/// ```
pub fn sphere(mass: f64, radius: f64, side: Side) -> Result<RigidBody> {
    let r = positive("radius", radius)?;
    let m = positive("mass", mass)?;
    RigidBody::new(m, 0.4 * m * r * r, side.direction() * r)
}

/// A uniform disc (cylinder rolling on its side): `I = ½ m r²`.
pub fn disc(mass: f64, radius: f64, side: Side) -> Result<RigidBody> {
    let r = positive("radius", radius)?;
    let m = positive("mass", mass)?;
    RigidBody::new(m, 0.5 * m * r * r, side.direction() * r)
}

/// The seed's state of a round body (paper A eq. 1): speed `v0` at angle `α` (radians) from
/// the normal, spin ratio `γ = ω0 r / v0`:
///
/// ```text
/// v_x⁻ = v0 sin α,   v_y⁻ = −v0 cos α,   ω⁻ = γ v0 / r.
/// ```
///
/// With counter-clockwise `ω` and the contact below the centre, the slip is
/// `v_x + ω r = v0 (sin α + γ)` (eq. 6).
pub fn spin_state(speed: f64, alpha: f64, spin_ratio: f64, radius: f64) -> Result<BodyState> {
    finite("speed", speed)?;
    finite("alpha", alpha)?;
    finite("spin-ratio", spin_ratio)?;
    let r = positive("radius", radius)?;
    Ok(BodyState::new(
        speed * alpha.sin(),
        -speed * alpha.cos(),
        spin_ratio * speed / r,
    ))
}
