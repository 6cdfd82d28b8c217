//! One planar body as a scenario file describes it: shape, mass, and its motion either as
//! paper A's `v0, α, γ` (round bodies) or as its velocity and angular velocity.

use crate::bodies::{self, BodyState2, RigidBody2, Side};
use crate::error::{Error, Num, Result};
use crate::math::Vec2;
use serde::Deserialize;

/// A body of a planar scenario, as written in a file (`[body]`, `[other]`). Fields are
/// optional where the shape decides whether they apply; [`BodySpec::build`] checks them.
#[derive(Debug, Clone, Deserialize, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// `sphere`, `disc`, `rod`, `ellipse` or `rigid`.
    pub shape: String,
    /// Mass `m > 0`.
    pub mass: f64,
    /// Radius (sphere, disc).
    pub radius: Option<f64>,
    /// Length (rod).
    pub length: Option<f64>,
    /// Semi-axes `[a, b]` (ellipse).
    pub semi_axes: Option<[f64; 2]>,
    /// Central moment of inertia (rigid).
    pub inertia: Option<f64>,
    /// Contact point from the centre of mass, `[t, n]` (rigid).
    pub contact: Option<[f64; 2]>,
    /// Angle from the surface in degrees (rod; ellipse, its `a` axis).
    pub angle_deg: Option<f64>,
    /// Approach speed `v0 > 0` (round bodies).
    pub speed: Option<f64>,
    /// Approach angle `α` from the normal, degrees in `(−90, 90)` (round bodies).
    pub alpha_deg: Option<f64>,
    /// Spin ratio `γ = ω0 r / v0` (round bodies).
    pub spin_ratio: Option<f64>,
    /// Velocity of the centre of mass `[vx, vy]`.
    pub velocity: Option<[f64; 2]>,
    /// Angular velocity.
    pub omega: Option<f64>,
}

/// How results are normalised in tables: by the approach speed and radius of a round body
/// given by `v0, α, γ`, else not at all.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Scale {
    /// Velocity scale `v0` (the approach speed of a round body; else 1).
    pub speed: f64,
    /// Length scale `r` (the radius of a round body; else 1).
    pub length: f64,
    /// Whether tables show normalised columns (`v/v0`, `ω r/v0`).
    pub normalised: bool,
}

/// A body built from its [`BodySpec`]: the rigid body, its state before the impact, the
/// normalisation of its tables and a one-line description.
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltBody {
    /// The body.
    pub body: RigidBody2,
    /// Its velocity and angular velocity before the impact.
    pub state: BodyState2,
    /// How its results are normalised.
    pub scale: Scale,
    /// E.g. `sphere m = 1, r = 1, v0 = 1, α = 30°, γ = 0`.
    pub description: String,
}

fn need(field: &str, shape: &str, x: Option<f64>) -> Result<f64> {
    x.ok_or_else(|| Error::Invalid {
        field: field.into(),
        reason: format!("required for shape `{shape}`"),
    })
}

fn reject(field: &str, shape: &str, present: bool) -> Result<()> {
    if present {
        Err(Error::Invalid {
            field: field.into(),
            reason: format!("not a parameter of shape `{shape}`"),
        })
    } else {
        Ok(())
    }
}

impl BodySpec {
    /// Build the body on `side` of the contact (`Below` for the striking body A, `Above` for
    /// a second body B); `prefix` (`body`, `other`) names its fields in errors.
    ///
    /// # Errors
    /// A field missing for the shape or not one of its parameters, a non-finite or
    /// out-of-range number, both kinds of motion given, `v0, α, γ` for a body that is not
    /// round, or a kinetic energy (of the speed or of the spin) not representable with room
    /// to spare (below 1e300) — each naming `prefix.field`.
    pub fn build(&self, prefix: &str, side: Side) -> Result<BuiltBody> {
        let f = |name: &str| format!("{prefix}.{name}");
        let shape = self.shape.as_str();
        let m = crate::error::finite(&f("mass"), self.mass)?;
        let named = |e: Error| e.prefixed(prefix);
        let (body, round_radius, desc) = match shape {
            "sphere" | "disc" => {
                let r = need(&f("radius"), shape, self.radius)?;
                reject(&f("length"), shape, self.length.is_some())?;
                reject(&f("semi_axes"), shape, self.semi_axes.is_some())?;
                reject(&f("inertia"), shape, self.inertia.is_some())?;
                reject(&f("contact"), shape, self.contact.is_some())?;
                reject(&f("angle_deg"), shape, self.angle_deg.is_some())?;
                let b = if shape == "sphere" {
                    bodies::sphere(m, r, side)
                } else {
                    bodies::disc(m, r, side)
                }
                .map_err(named)?;
                (b, Some(r), format!("{shape} m = {m}, r = {r}"))
            }
            "rod" => {
                let l = need(&f("length"), shape, self.length)?;
                let a = need(&f("angle_deg"), shape, self.angle_deg)?;
                reject(&f("radius"), shape, self.radius.is_some())?;
                reject(&f("semi_axes"), shape, self.semi_axes.is_some())?;
                reject(&f("inertia"), shape, self.inertia.is_some())?;
                reject(&f("contact"), shape, self.contact.is_some())?;
                let a = crate::error::finite(&f("angle_deg"), a)?;
                let b = bodies::rod(m, l, a.to_radians(), side).map_err(named)?;
                (
                    b,
                    None,
                    format!("rod m = {m}, L = {l}, at {a}° to the surface"),
                )
            }
            "ellipse" => {
                let [sa, sb] = self.semi_axes.ok_or_else(|| Error::Invalid {
                    field: f("semi_axes"),
                    reason: "required for shape `ellipse`".into(),
                })?;
                let a = self.angle_deg.unwrap_or(0.0);
                reject(&f("radius"), shape, self.radius.is_some())?;
                reject(&f("length"), shape, self.length.is_some())?;
                reject(&f("inertia"), shape, self.inertia.is_some())?;
                reject(&f("contact"), shape, self.contact.is_some())?;
                let a = crate::error::finite(&f("angle_deg"), a)?;
                let b = bodies::ellipse(m, sa, sb, a.to_radians(), side).map_err(named)?;
                (
                    b,
                    None,
                    format!("ellipse m = {m}, a = {sa}, b = {sb}, at {a}°"),
                )
            }
            "rigid" => {
                let i = need(&f("inertia"), shape, self.inertia)?;
                let [rt, rn] = self.contact.ok_or_else(|| Error::Invalid {
                    field: f("contact"),
                    reason: "required for shape `rigid`".into(),
                })?;
                reject(&f("radius"), shape, self.radius.is_some())?;
                reject(&f("length"), shape, self.length.is_some())?;
                reject(&f("semi_axes"), shape, self.semi_axes.is_some())?;
                reject(&f("angle_deg"), shape, self.angle_deg.is_some())?;
                let b = RigidBody2::new(m, i, Vec2::new(rt, rn)).map_err(named)?;
                (
                    b,
                    None,
                    format!("rigid body m = {m}, I = {i}, contact at ({rt}, {rn})"),
                )
            }
            other => {
                return Err(Error::Invalid {
                    field: f("shape"),
                    reason: format!(
                        "unknown shape `{other}` (known: sphere, disc, rod, ellipse, rigid)"
                    ),
                })
            }
        };
        let seed_motion =
            self.speed.is_some() || self.alpha_deg.is_some() || self.spin_ratio.is_some();
        let direct_motion = self.velocity.is_some() || self.omega.is_some();
        if seed_motion && direct_motion {
            return Err(Error::Invalid {
                field: prefix.into(),
                reason: "give either speed/alpha_deg/spin_ratio or velocity/omega, not both".into(),
            });
        }
        let built = if seed_motion {
            let r = round_radius.ok_or_else(|| Error::Invalid {
                field: f("speed"),
                reason: format!(
                    "speed/alpha_deg/spin_ratio describe round bodies; give velocity and omega for shape `{shape}`"
                ),
            })?;
            let v0 = crate::error::finite(&f("speed"), self.speed.unwrap_or(1.0))?;
            let alpha = crate::error::finite(&f("alpha_deg"), self.alpha_deg.unwrap_or(0.0))?;
            let gamma = crate::error::finite(&f("spin_ratio"), self.spin_ratio.unwrap_or(0.0))?;
            if v0 <= 0.0 {
                return Err(Error::Invalid {
                    field: f("speed"),
                    reason: format!("must be > 0, got {}", Num(v0)),
                });
            }
            if !(alpha > -90.0 && alpha < 90.0) {
                return Err(Error::Invalid {
                    field: f("alpha_deg"),
                    reason: format!(
                        "must be in (-90, 90) for the body to approach the surface, got {}",
                        Num(alpha)
                    ),
                });
            }
            let state = bodies::spin_state(v0, alpha.to_radians(), gamma, r).map_err(named)?;
            BuiltBody {
                body,
                state,
                scale: Scale {
                    speed: v0,
                    length: r,
                    normalised: true,
                },
                description: format!("{desc}, v0 = {v0}, α = {alpha}°, γ = {gamma}"),
            }
        } else {
            let [vx, vy] = self.velocity.unwrap_or([0.0, 0.0]);
            let vx = crate::error::finite(&f("velocity"), vx)?;
            let vy = crate::error::finite(&f("velocity"), vy)?;
            let omega = crate::error::finite(&f("omega"), self.omega.unwrap_or(0.0))?;
            BuiltBody {
                body,
                state: BodyState2::new(vx, vy, omega),
                scale: Scale {
                    speed: 1.0,
                    length: 1.0,
                    normalised: false,
                },
                description: format!("{desc}, v = ({vx}, {vy}), ω = {omega}"),
            }
        };
        self.energies_representable(prefix, &built)?;
        Ok(built)
    }

    /// Each part of the body's kinetic energy is a number with room to spare (a `spin_ratio`
    /// or an `omega` of 1e308 gave a null energy): an error names the key that sets it.
    fn energies_representable(&self, prefix: &str, b: &BuiltBody) -> Result<()> {
        let direct = self.velocity.is_some() || self.omega.is_some();
        let parts = [
            (
                if direct { "velocity" } else { "speed" },
                b.body.translational_energy(&b.state),
            ),
            (
                if direct { "omega" } else { "spin_ratio" },
                b.body.rotational_energy(&b.state),
            ),
        ];
        for (key, energy) in parts {
            if !(energy.is_finite() && energy <= 1e300) {
                return Err(Error::Invalid {
                    field: format!("{prefix}.{key}"),
                    reason: format!(
                        "the kinetic energy it gives, {}, is not representable with room to spare (it must be below 1e300)",
                        Num(energy)
                    ),
                });
            }
        }
        Ok(())
    }
}
