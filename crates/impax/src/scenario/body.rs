//! One planar body as a scenario describes it: its shape, its mass, and its motion either as
//! paper A's `v0, α, γ` (round bodies) or as its velocity and angular velocity — and the one
//! builder of planar bodies from that description, for every front end.

use super::shape::{AngleUnit, Need, Shape, ShapeParam, ShapeScalar};
use crate::error::{Error, Num, Result};
use crate::math::Vec2;
use crate::planar::bodies::{self, BodyState, RigidBody, Side};
use serde::Deserialize;

/// A body of a planar scenario, as written in a file (`[body]`, `[other]`) or filled in by a
/// front end. Fields are optional where the shape decides whether they apply
/// ([`Shape::parameters`]); [`BodySpec::build`] checks them.
///
/// ```
/// use impax::planar::bodies::Side;
/// use impax::scenario::BodySpec;
/// let rod = BodySpec {
///     shape: "rod".into(),
///     mass: 1.0,
///     length: Some(2.0),
///     angle: Some(90.0),
///     velocity: Some([0.0, -1.0]),
///     ..BodySpec::default()
/// };
/// let built = rod.build("body", Side::Below)?;
/// assert_eq!(built.description, "rod m = 1, L = 2, at 90° to the surface, v = (0, -1), ω = 0");
/// assert!((built.body.contact().y + 1.0).abs() < 1e-15);
/// let e = BodySpec { radius: Some(1.0), ..rod }.build("body", Side::Below).unwrap_err();
/// assert_eq!(e.to_string(), "body.radius: not a parameter of shape `rod`");
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, Deserialize, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// One of [`Shape::NAMES`].
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
    /// Half-width and half-height `[a, b]` (box).
    pub half_extents: Option<[f64; 2]>,
    /// The signs `[s_a, s_b]` (each `±1`) of the corner that strikes, in the body's frame
    /// (box; default: the lowest corner).
    pub corner: Option<[f64; 2]>,
    /// Angle from the surface (rod; ellipse, its `a` axis; box, its `a` side) in
    /// [`BodySpec::angle_unit`]: the key `angle_deg` of files.
    #[serde(rename = "angle_deg")]
    pub angle: Option<f64>,
    /// Approach speed `v0 > 0` (round bodies).
    pub speed: Option<f64>,
    /// Approach angle `α` from the normal, in `(−90°, 90°)`, in [`BodySpec::angle_unit`]
    /// (round bodies): the key `alpha_deg` of files.
    #[serde(rename = "alpha_deg")]
    pub alpha: Option<f64>,
    /// Spin ratio `γ = ω0 r / v0` (round bodies).
    pub spin_ratio: Option<f64>,
    /// Velocity of the centre of mass `[vx, vy]`.
    pub velocity: Option<[f64; 2]>,
    /// Angular velocity.
    pub omega: Option<f64>,
    /// The unit of `angle` and `alpha`, and so their keys in errors and how descriptions show
    /// them: degrees for files (the default), radians for the Python bindings. Not a key.
    #[serde(skip)]
    pub angle_unit: AngleUnit,
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
    pub body: RigidBody,
    /// Its velocity and angular velocity before the impact.
    pub state: BodyState,
    /// How its results are normalised.
    pub scale: Scale,
    /// E.g. `sphere m = 1, r = 1, v0 = 1, α = 30°, γ = 0`.
    pub description: String,
}

/// `prefix.key`, or `key` alone for an empty prefix.
fn field(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

/// `x` if finite, else an error naming `prefix.key` (no allocation when it is).
fn finite_at(prefix: &str, key: &str, x: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::NotFinite {
            field: field(prefix, key),
            value: x,
        })
    }
}

/// Where a shape parameter's numbers live in a [`BodySpec`].
enum Slot<'a> {
    One(&'a mut Option<f64>),
    Two(&'a mut Option<[f64; 2]>),
}

impl BodySpec {
    /// The key of a shape parameter as this body spells it (`angle_deg` or `angle`).
    pub fn key(&self, p: ShapeParam) -> &'static str {
        p.key(self.angle_unit)
    }

    /// The shape named by [`BodySpec::shape`].
    ///
    /// # Errors
    /// An unknown shape, naming `prefix.shape` and listing the known ones.
    pub fn parse_shape(&self, prefix: &str) -> Result<Shape> {
        match Shape::from_name(&self.shape) {
            Some(s) => Ok(s),
            None => Shape::parse(&self.shape, &field(prefix, "shape")),
        }
    }

    /// The numbers of a shape parameter, if given (a single number padded with NaN).
    fn values(&self, p: ShapeParam) -> Option<[f64; 2]> {
        let one = |x: Option<f64>| x.map(|x| [x, f64::NAN]);
        match p {
            ShapeParam::Radius => one(self.radius),
            ShapeParam::Length => one(self.length),
            ShapeParam::SemiAxes => self.semi_axes,
            ShapeParam::Inertia => one(self.inertia),
            ShapeParam::Contact => self.contact,
            ShapeParam::Angle => one(self.angle),
            ShapeParam::HalfExtents => self.half_extents,
            ShapeParam::Corner => self.corner,
        }
    }

    fn slot(&mut self, p: ShapeParam) -> Slot<'_> {
        match p {
            ShapeParam::Radius => Slot::One(&mut self.radius),
            ShapeParam::Length => Slot::One(&mut self.length),
            ShapeParam::SemiAxes => Slot::Two(&mut self.semi_axes),
            ShapeParam::Inertia => Slot::One(&mut self.inertia),
            ShapeParam::Contact => Slot::Two(&mut self.contact),
            ShapeParam::Angle => Slot::One(&mut self.angle),
            ShapeParam::HalfExtents => Slot::Two(&mut self.half_extents),
            ShapeParam::Corner => Slot::Two(&mut self.corner),
        }
    }

    /// Whether the shape parameter is given.
    pub fn has(&self, p: ShapeParam) -> bool {
        self.values(p).is_some()
    }

    /// Set a shape parameter from its numbers: one, or two for a pair (`semi_axes`); angles
    /// in [`BodySpec::angle_unit`]. The front ends that take parameters by name use it.
    ///
    /// # Errors
    /// The wrong count of numbers, naming the key (`semi_axes: expected 2 numbers, got 3`).
    pub fn set_param(&mut self, p: ShapeParam, values: &[f64]) -> Result<()> {
        let key = self.key(p);
        match (self.slot(p), values) {
            (Slot::One(x), &[v]) => *x = Some(v),
            (Slot::Two(x), &[a, b]) => *x = Some([a, b]),
            _ => {
                return Err(Error::Invalid {
                    field: key.into(),
                    reason: format!(
                        "expected {} number{}, got {}",
                        p.count(),
                        if p.count() == 1 { "" } else { "s" },
                        values.len()
                    ),
                })
            }
        }
        Ok(())
    }

    /// One number of a shape parameter (angles in [`BodySpec::angle_unit`]), if given.
    pub fn scalar(&self, s: ShapeScalar) -> Option<f64> {
        let (p, i) = s.param();
        self.values(p).map(|v| v[i])
    }

    /// Set one number of a shape parameter (angles in [`BodySpec::angle_unit`]); the other
    /// number of a pair not given yet is NaN, which [`BodySpec::build`] refuses.
    pub fn set_scalar(&mut self, s: ShapeScalar, value: f64) {
        let (p, i) = s.param();
        match self.slot(p) {
            Slot::One(x) => *x = Some(value),
            Slot::Two(x) => x.get_or_insert([f64::NAN; 2])[i] = value,
        }
    }

    /// Every parameter the shape needs is given, and none it does not take.
    fn check_parameters(&self, prefix: &str, shape: Shape) -> Result<()> {
        for &(p, need) in shape.parameters() {
            if need == Need::Required && !self.has(p) {
                return Err(Error::Invalid {
                    field: field(prefix, self.key(p)),
                    reason: format!("required for shape `{shape}`"),
                });
            }
        }
        for p in ShapeParam::ALL {
            if shape.takes(p).is_none() && self.has(p) {
                return Err(Error::Invalid {
                    field: field(prefix, self.key(p)),
                    reason: format!("not a parameter of shape `{shape}`"),
                });
            }
        }
        Ok(())
    }

    /// The body's angle in radians (0 if not given), checked finite.
    fn angle_radians(&self, prefix: &str) -> Result<f64> {
        let key = self.key(ShapeParam::Angle);
        let a = finite_at(prefix, key, self.angle.unwrap_or(0.0))?;
        Ok(self.angle_unit.to_radians(a))
    }

    /// The rigid body of the shape alone, on `side` of the contact (`Below` for the striking
    /// body A, `Above` for a second body B); `prefix` (`body`, `other`, or empty) names its
    /// fields in errors. No allocation unless it fails: sweeps rebuild bodies with it.
    ///
    /// # Errors
    /// An unknown shape, a parameter missing for the shape or not one of its parameters, a
    /// non-finite or out-of-range number — each naming `prefix.field`.
    pub fn rigid_body(&self, prefix: &str, side: Side) -> Result<RigidBody> {
        let m = finite_at(prefix, "mass", self.mass)?;
        let shape = self.parse_shape(prefix)?;
        self.check_parameters(prefix, shape)?;
        let nan = f64::NAN;
        let body = match shape {
            Shape::Sphere => bodies::sphere(m, self.radius.unwrap_or(nan), side),
            Shape::Disc => bodies::disc(m, self.radius.unwrap_or(nan), side),
            Shape::Rod => {
                let angle = self.angle_radians(prefix)?;
                bodies::rod(m, self.length.unwrap_or(nan), angle, side)
            }
            Shape::Ellipse => {
                let [a, b] = self.semi_axes.unwrap_or([nan; 2]);
                let angle = self.angle_radians(prefix)?;
                bodies::ellipse(m, a, b, angle, side)
            }
            Shape::Rigid => {
                let [rt, rn] = self.contact.unwrap_or([nan; 2]);
                RigidBody::new(m, self.inertia.unwrap_or(nan), Vec2::new(rt, rn))
            }
            Shape::Box => {
                let angle = self.angle_radians(prefix)?;
                let half_extents = self.half_extents.unwrap_or([nan; 2]);
                bodies::rectangle(m, half_extents, angle, self.corner, side)
            }
        };
        body.map_err(|e| e.prefixed(prefix))
    }

    /// The shape in words, e.g. `rod m = 1, L = 2, at 50° to the surface` (angles in
    /// [`BodySpec::angle_unit`]).
    pub fn shape_description(&self) -> String {
        let (m, nan) = (self.mass, f64::NAN);
        let angle = self.angle_unit.show(self.angle.unwrap_or(0.0));
        match Shape::from_name(&self.shape) {
            Some(s @ (Shape::Sphere | Shape::Disc)) => {
                format!("{s} m = {m}, r = {}", self.radius.unwrap_or(nan))
            }
            Some(Shape::Rod) => format!(
                "rod m = {m}, L = {}, at {angle} to the surface",
                self.length.unwrap_or(nan)
            ),
            Some(Shape::Ellipse) => {
                let [a, b] = self.semi_axes.unwrap_or([nan; 2]);
                format!("ellipse m = {m}, a = {a}, b = {b}, at {angle}")
            }
            Some(Shape::Rigid) => {
                let [rt, rn] = self.contact.unwrap_or([nan; 2]);
                format!(
                    "rigid body m = {m}, I = {}, contact at ({rt}, {rn})",
                    self.inertia.unwrap_or(nan)
                )
            }
            Some(Shape::Box) => {
                let [a, b] = self.half_extents.unwrap_or([nan; 2]);
                match self.corner {
                    None => format!("box m = {m}, a = {a}, b = {b}, at {angle}"),
                    Some([sa, sb]) => {
                        format!("box m = {m}, a = {a}, b = {b}, at {angle}, corner ({sa}, {sb})")
                    }
                }
            }
            None => format!("{} m = {m}", self.shape),
        }
    }

    /// Build the body on `side` of the contact (`Below` for the striking body A, `Above` for
    /// a second body B) with its state; `prefix` (`body`, `other`, or empty) names its fields
    /// in errors.
    ///
    /// # Errors
    /// As [`BodySpec::rigid_body`]; both kinds of motion given, `v0, α, γ` for a body that is
    /// not round, a speed not `> 0` or an approach angle outside `(−90°, 90°)`, or a kinetic
    /// energy (of the speed or of the spin) not representable with room to spare (below
    /// 1e300) — each naming `prefix.field`.
    pub fn build(&self, prefix: &str, side: Side) -> Result<BuiltBody> {
        let body = self.rigid_body(prefix, side)?;
        let shape = self.parse_shape(prefix)?;
        let desc = self.shape_description();
        let unit = self.angle_unit;
        let alpha_key = unit.alpha_key();
        let seed_motion = self.speed.is_some() || self.alpha.is_some() || self.spin_ratio.is_some();
        let direct_motion = self.velocity.is_some() || self.omega.is_some();
        if seed_motion && direct_motion {
            return Err(Error::Invalid {
                field: if prefix.is_empty() { "speed" } else { prefix }.into(),
                reason: format!(
                    "give either speed/{alpha_key}/spin_ratio or velocity/omega, not both"
                ),
            });
        }
        let built = if seed_motion {
            if !shape.is_round() {
                return Err(Error::Invalid {
                    field: field(prefix, "speed"),
                    reason: format!(
                        "speed/{alpha_key}/spin_ratio describe round bodies; give velocity and omega for shape `{shape}`"
                    ),
                });
            }
            let r = self.radius.unwrap_or(f64::NAN);
            let v0 = finite_at(prefix, "speed", self.speed.unwrap_or(1.0))?;
            let alpha = finite_at(prefix, alpha_key, self.alpha.unwrap_or(0.0))?;
            let gamma = finite_at(prefix, "spin_ratio", self.spin_ratio.unwrap_or(0.0))?;
            if v0 <= 0.0 {
                return Err(Error::Invalid {
                    field: field(prefix, "speed"),
                    reason: format!("must be > 0, got {}", Num(v0)),
                });
            }
            let right = unit.right_angle();
            if !(alpha > -right && alpha < right) {
                return Err(Error::Invalid {
                    field: field(prefix, alpha_key),
                    reason: format!(
                        "must be in {} for the body to approach the surface, got {}",
                        unit.approach_interval(),
                        Num(alpha)
                    ),
                });
            }
            let state = bodies::spin_state(v0, unit.to_radians(alpha), gamma, r)
                .map_err(|e| e.prefixed(prefix))?;
            BuiltBody {
                body,
                state,
                scale: Scale {
                    speed: v0,
                    length: r,
                    normalised: true,
                },
                description: format!(
                    "{desc}, v0 = {}, α = {}, γ = {}",
                    Num(v0),
                    unit.show(alpha),
                    Num(gamma)
                ),
            }
        } else {
            let [vx, vy] = self.velocity.unwrap_or([0.0, 0.0]);
            let vx = finite_at(prefix, "velocity", vx)?;
            let vy = finite_at(prefix, "velocity", vy)?;
            let omega = finite_at(prefix, "omega", self.omega.unwrap_or(0.0))?;
            BuiltBody {
                body,
                state: BodyState::new(vx, vy, omega),
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
                    field: field(prefix, key),
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
