//! Built-in simulation scenarios: a bouncing ball with spin, a rod dropped on its end, and
//! Kane's double pendulum falling onto the floor. Each returns the mechanism and its initial
//! state; the floor is `y = 0` for the free bodies.

use crate::error::{Error, Result};
use crate::mechanism::builtin::{BuiltIn, DoublePendulum, Rod, Sphere};

/// A mechanism with its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct Initial {
    /// The mechanism.
    pub mechanism: BuiltIn,
    /// Initial coordinates.
    pub q: Vec<f64>,
    /// Initial velocities.
    pub u: Vec<f64>,
}

fn non_negative(field: &str, x: f64) -> Result<f64> {
    crate::error::finite(field, x)?;
    if x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value: x,
            reason: "must be ≥ 0".into(),
        })
    }
}

/// A ball (sphere, or disc with `disc = true`) of mass `m` and radius `r` whose lowest point
/// is `height` above the floor, thrown at `speed` at `angle` (radians) from the downward
/// vertical (towards +x), with spin ratio `γ = ω r / v0` (paper A's: the slip at first
/// contact is `v0 (sin α + γ)`; γ < −sin α is backspin strong enough to reverse the slip).
#[allow(clippy::too_many_arguments)]
pub fn bouncing_ball(
    mass: f64,
    radius: f64,
    height: f64,
    speed: f64,
    angle: f64,
    spin_ratio: f64,
    gravity: f64,
    disc: bool,
) -> Result<Initial> {
    let height = non_negative("height", height)?;
    let speed = non_negative("speed", speed)?;
    crate::error::finite("angle", angle)?;
    crate::error::finite("spin ratio", spin_ratio)?;
    let ball = if disc {
        Sphere::disc(mass, radius, gravity, 0.0)?
    } else {
        Sphere::new(mass, radius, gravity, 0.0)?
    };
    let init = Initial {
        mechanism: BuiltIn::Sphere(ball),
        q: vec![0.0, radius + height, 0.0],
        u: vec![
            speed * angle.sin(),
            -speed * angle.cos(),
            spin_ratio * speed / radius,
        ],
    };
    init.energies_representable(("height", height), ("speed", speed))?;
    Ok(init)
}

impl Initial {
    /// The initial potential and kinetic energies are representable with room for the motion
    /// (`|V|`, `T` below 1e300): each named by the parameter that sets it.
    fn energies_representable(&self, potential: (&str, f64), kinetic: (&str, f64)) -> Result<()> {
        use crate::mechanism::dynamics;
        let check = |(field, value): (&str, f64), energy: f64, what: &str| {
            if energy.is_finite() && energy.abs() < 1e300 {
                Ok(())
            } else {
                Err(Error::OutOfRange {
                    field: field.into(),
                    value,
                    reason: format!("the {what} energy at the start, {}, is not representable with room for the motion (it must be below 1e300)", crate::error::Num(energy)),
                })
            }
        };
        check(
            potential,
            dynamics::potential_energy(&self.mechanism, &self.q),
            "potential",
        )?;
        check(
            kinetic,
            dynamics::kinetic_energy(&self.mechanism, &self.q, &self.u),
            "kinetic",
        )
    }
}

/// A uniform rod of mass `m` and length `l` at `angle` (radians, from the floor) whose lower
/// end is `height` above the floor, dropped from rest.
pub fn rod_drop(mass: f64, length: f64, angle: f64, height: f64, gravity: f64) -> Result<Initial> {
    let height = non_negative("height", height)?;
    crate::error::finite("angle", angle)?;
    let rod = Rod::new(mass, length, gravity, 0.0)?;
    let lift = 0.5 * length * angle.sin().abs();
    let init = Initial {
        mechanism: BuiltIn::Rod(rod),
        q: vec![0.0, height + lift, angle],
        u: vec![0.0, 0.0, 0.0],
    };
    init.energies_representable(("height", height), ("height", height))?;
    Ok(init)
}

/// Kane's double pendulum (rods `m1, m2, l1, l2`, pinned at the origin) released at angles
/// `q` (radians from the downward vertical) with rates `u`, above the floor `y = floor`.
#[allow(clippy::too_many_arguments)]
pub fn double_pendulum_drop(
    m1: f64,
    m2: f64,
    l1: f64,
    l2: f64,
    gravity: f64,
    floor: f64,
    q: [f64; 2],
    u: [f64; 2],
) -> Result<Initial> {
    let p = DoublePendulum::new(m1, m2, l1, l2, gravity, floor)?;
    Ok(Initial {
        mechanism: BuiltIn::DoublePendulum(p),
        q: q.to_vec(),
        u: u.to_vec(),
    })
}
