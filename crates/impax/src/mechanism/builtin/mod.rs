//! Built-in mechanisms, each with its parameters checked at construction.
//!
//! | mechanism | coordinates | contact |
//! |---|---|---|
//! | [`DoublePendulum`] | θ₁, θ₂ (absolute, from the downward vertical) | tip of rod 2 on a floor |
//! | [`RingPendulum`] | x (ring centre), φ (pendulum from the downward vertical) | — (rolls) |
//! | [`CartPendulum`] | x (cart), φ | — |
//! | [`Sphere`] | x, y, θ | lowest point on a floor |
//! | [`Rod`] | x, y, θ (from the floor) | lower end on a floor |

mod double_pendulum;
mod free;
mod pendulums;

pub use double_pendulum::DoublePendulum;
pub use free::{Rod, Sphere};
pub use pendulums::{CartPendulum, RingPendulum};

use crate::error::{Error, Result};

/// Standard gravity, m/s² (the default of every built-in).
pub const STANDARD_GRAVITY: f64 = 9.81;

/// A parameter that must be finite and positive.
pub(crate) fn positive(field: &str, x: f64) -> Result<f64> {
    crate::error::finite(field, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value: x,
            reason: "must be positive".into(),
        })
    }
}

/// Gravity: finite and ≥ 0.
pub(crate) fn gravity(x: f64) -> Result<f64> {
    crate::error::finite("gravity", x)?;
    if x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: "gravity".into(),
            value: x,
            reason: "must be ≥ 0 (it acts along −y)".into(),
        })
    }
}
