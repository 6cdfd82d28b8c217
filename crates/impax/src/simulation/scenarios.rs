//! Built-in simulation scenarios: a bouncing ball with spin, a rod dropped on its end, Kane's
//! double pendulum falling onto the floor, a rocking block and Newton's cradle. Each returns
//! the mechanism and its initial state; the floor is `y = 0` for the free bodies.

use crate::error::{Error, Result};
use crate::mechanism::builtin::{Block, BuiltIn, Cradle, DoublePendulum, Rod, Sphere};

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

/// A uniform rectangular block (mass `m`, half-width `b`, half-height `h`, see [`Block`]) on
/// the floor `y = 0`, tilted by `angle` (radians, counter-clockwise; `|angle| < π/2`) onto one
/// bottom corner — corner A for a positive tilt, corner B for a negative one, or, upright,
/// the corner about which `omega` lifts the block (A for `ω ≥ 0`) — and turning about that
/// corner at `omega` (rad/s): the centre moves at `ω ẑ × (G − P)`, `P` the corner.
///
/// Released from rest at a tilt below `α = atan(b/h)` it rocks: it falls back onto its other
/// corner, strikes, rocks about that one, and so on, each impact (plastic, with enough
/// friction) scaling the angular velocity by Housner's `1 − (3/2) sin²α`
/// ([`Block::housner_ratio`]).
pub fn rocking_block(
    mass: f64,
    half_width: f64,
    half_height: f64,
    angle: f64,
    omega: f64,
    gravity: f64,
) -> Result<Initial> {
    crate::error::finite("angle", angle)?;
    crate::error::finite("omega", omega)?;
    if angle.abs() >= 0.5 * std::f64::consts::PI {
        return Err(Error::OutOfRange {
            field: "angle".into(),
            value: angle,
            reason: "the tilt must be below 90° either way (the block stands on a bottom corner)"
                .into(),
        });
    }
    let block = Block::new(mass, half_width, half_height, gravity, 0.0)?;
    let [b, h] = block.half_sizes();
    let (s, c) = angle.sin_cos();
    // The pivot corner's offset from the centre, rotated: A = (−b, −h), B = (b, −h).
    let on_a = angle > 0.0 || (angle == 0.0 && omega >= 0.0);
    let px = if on_a { -b } else { b };
    let r = [c * px + s * h, s * px - c * h];
    let y = -r[1];
    // G − P = −r; the centre's velocity ω ẑ × (G − P).
    let u = vec![omega * r[1], -omega * r[0], omega];
    let init = Initial {
        mechanism: BuiltIn::Block(block),
        q: vec![0.0, y, angle],
        u,
    };
    init.energies_representable(("half-height", half_height), ("omega", omega))?;
    Ok(init)
}

/// Newton's cradle: `balls` equal solid spheres (mass `m`, radius `r`, see [`Cradle`]) in a row
/// along `x` on a frictionless table, `gap` apart (0: touching), the first moving towards the
/// others at `v0 > 0`.
///
/// With gaps every impact is a binary one, ball against ball (`e = 1`: the velocity passes
/// down the row, `(0, …, 0, v0)`); touching, the first ball strikes the row at once, an impact
/// at all the contacts together (the LCP: not the textbook answer; `sequential`: the textbook
/// one).
pub fn cradle(balls: usize, mass: f64, radius: f64, v0: f64, gap: f64) -> Result<Initial> {
    let gap = non_negative("gap", gap)?;
    crate::error::finite("v0", v0)?;
    if v0 <= 0.0 {
        return Err(Error::OutOfRange {
            field: "v0".into(),
            value: v0,
            reason: "must be positive: the first ball moves towards the others".into(),
        });
    }
    let cradle = Cradle::new(balls, mass, radius)?;
    let r = cradle.radius();
    let mut q = vec![0.0; 3 * balls];
    for (i, x) in q.iter_mut().step_by(3).enumerate() {
        *x = i as f64 * (2.0 * r + gap);
    }
    let mut u = vec![0.0; 3 * balls];
    u[0] = v0;
    let init = Initial {
        mechanism: BuiltIn::Cradle(cradle),
        q,
        u,
    };
    init.energies_representable(("gap", gap), ("v0", v0))?;
    Ok(init)
}
