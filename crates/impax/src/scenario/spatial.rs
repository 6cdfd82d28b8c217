//! The spatial body scenario (`space = "3d"`): one body striking a fixed surface, or two free
//! bodies — the shapes of [`crate::spatial::bodies`] by name, and the one builder of a spatial body
//! from its description, for every front end.
//!
//! ```toml
//! space = "3d"
//! friction = 0.4
//! restitution = 0.7
//! laws = ["whittaker", "energetic"]      # optional; default: every spatial law
//!
//! [body]                                 # body A, contact at its lowest point (−z)
//! shape = "ellipsoid"                    # sphere | ellipsoid | box | cylinder | rigid
//! mass = 1.0
//! semi_axes = [2.0, 1.0, 0.5]            # ellipsoid
//! # radius = 1.0                         # sphere, cylinder
//! # half_height = 1.0                    # cylinder
//! # half_extents = [1.0, 0.5, 0.3]       # box; corner = [1, -1, -1] optional
//! # inertia = [[1, 0, 0], [0, 2, 0], [0, 0, 2.5]]; contact = [0.3, -0.2, -0.8]   # rigid (body frame)
//! orientation_deg = [10.0, 20.0, 30.0]   # roll, pitch, yaw (or orientation = [w, x, y, z])
//! velocity = [0.5, 0.2, -1.0]
//! omega = [0.0, 3.0, 0.0]
//!
//! [other]                                # optional free body B, struck at its highest point
//! ```

use crate::error::{Error, Result};
use crate::math::{Mat3, Quat, UnitQuat, Vec3};
use crate::planar::bodies::Side;
use crate::spatial::bodies::{self, BodyImpact, BodyState, RigidBody};
use serde::Deserialize;

/// A spatial body's shape, by the name files give it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape3 {
    /// A solid sphere (`radius`).
    Sphere,
    /// A uniform solid ellipsoid (`semi_axes`).
    Ellipsoid,
    /// A uniform box (`half_extents`, optional `corner`).
    Box,
    /// A uniform solid cylinder (`radius`, `half_height`).
    Cylinder,
    /// Any rigid body (`inertia` in the body frame, `contact` from the centre of mass).
    Rigid,
}

impl Shape3 {
    /// Every shape, in the order files and errors list them.
    pub const ALL: [Shape3; 5] = [
        Shape3::Sphere,
        Shape3::Ellipsoid,
        Shape3::Box,
        Shape3::Cylinder,
        Shape3::Rigid,
    ];

    /// The name files give the shape.
    pub fn name(self) -> &'static str {
        match self {
            Shape3::Sphere => "sphere",
            Shape3::Ellipsoid => "ellipsoid",
            Shape3::Box => "box",
            Shape3::Cylinder => "cylinder",
            Shape3::Rigid => "rigid",
        }
    }

    /// The shape named `name`, if any.
    pub fn from_name(name: &str) -> Option<Self> {
        Shape3::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// A body of a spatial scenario, as written in a file (`[body]`, `[other]`) or filled in by a
/// front end; [`BodySpec3::build`] checks it.
///
/// ```
/// use impax::planar::bodies::Side;
/// use impax::scenario::BodySpec3;
/// let ball = BodySpec3 {
///     shape: "sphere".into(),
///     mass: 1.0,
///     radius: Some(1.0),
///     velocity: Some([0.5, 0.0, -1.0]),
///     ..BodySpec3::default()
/// };
/// let built = ball.build("body", Side::Below)?;
/// assert!((built.body.inverse_inertia()[(0, 0)] - 3.5).abs() < 1e-15);
/// let e = BodySpec3 { radius: None, ..ball }.build("body", Side::Below).unwrap_err();
/// assert_eq!(e.to_string(), "body.radius: required for shape `sphere`");
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, Deserialize, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[serde(deny_unknown_fields)]
pub struct BodySpec3 {
    /// One of the names of [`Shape3`].
    pub shape: String,
    /// Mass `m > 0`.
    pub mass: f64,
    /// Radius (sphere, cylinder).
    pub radius: Option<f64>,
    /// Half-height along the body's `z` axis (cylinder).
    pub half_height: Option<f64>,
    /// Semi-axes `[a, b, c]` along the body's axes (ellipsoid).
    pub semi_axes: Option<[f64; 3]>,
    /// Half-extents along the body's axes (box).
    pub half_extents: Option<[f64; 3]>,
    /// The signs (each `±1`) of the corner that strikes, in the body's frame (box; default:
    /// the lowest corner).
    pub corner: Option<[f64; 3]>,
    /// The inertia tensor about the centre of mass in the body frame (rigid).
    pub inertia: Option<[[f64; 3]; 3]>,
    /// The contact point from the centre of mass in the body frame (rigid).
    pub contact: Option<[f64; 3]>,
    /// The orientation as a quaternion `[w, x, y, z]` (normalised here).
    pub orientation: Option<[f64; 4]>,
    /// The orientation as roll, pitch, yaw in degrees (instead of `orientation`).
    pub orientation_deg: Option<[f64; 3]>,
    /// Velocity of the centre of mass (default zero).
    pub velocity: Option<[f64; 3]>,
    /// Angular velocity (default zero).
    pub omega: Option<[f64; 3]>,
}

/// A spatial body built from its description.
#[derive(Debug, Clone)]
pub struct BuiltBody3 {
    /// The body.
    pub body: RigidBody,
    /// Its motion before the impact.
    pub state: BodyState,
    /// A one-line description for tables (`sphere m = 1, r = 1, v = …, ω = …`).
    pub description: String,
}

impl BodySpec3 {
    /// The orientation of the body: `orientation` or `orientation_deg`, else the identity.
    fn orientation(&self, prefix: &str) -> Result<UnitQuat> {
        let invalid = |key: &str, reason: &str| Error::Invalid {
            field: format!("{prefix}.{key}"),
            reason: reason.into(),
        };
        match (self.orientation, self.orientation_deg) {
            (Some(_), Some(_)) => Err(invalid(
                "orientation",
                "give either orientation (quaternion) or orientation_deg, not both",
            )),
            (Some([w, x, y, z]), None) => {
                let q = Quat::new(w, x, y, z);
                let n = q.norm();
                if !n.is_finite() || n <= 0.0 {
                    return Err(invalid(
                        "orientation",
                        "must be a non-zero finite quaternion [w, x, y, z]",
                    ));
                }
                Ok(UnitQuat::from_quaternion(q))
            }
            (None, Some([r, p, y])) => {
                if ![r, p, y].iter().all(|a| a.is_finite()) {
                    return Err(invalid("orientation_deg", "must be finite angles"));
                }
                Ok(UnitQuat::from_euler_angles(
                    r.to_radians(),
                    p.to_radians(),
                    y.to_radians(),
                ))
            }
            (None, None) => Ok(UnitQuat::identity()),
        }
    }

    /// Build the body on `side` of the contact plane (body A below it, struck at its lowest
    /// point; body B above, at its highest).
    ///
    /// # Errors
    /// A field named inside `prefix` (`body.radius`): an unknown shape, a parameter the shape
    /// needs and lacks, a value the shape's builder in [`crate::spatial::bodies`] refuses, a
    /// non-finite velocity or angular velocity.
    pub fn build(&self, prefix: &str, side: Side) -> Result<BuiltBody3> {
        let q = self.orientation(prefix)?;
        let shape = Shape3::from_name(&self.shape).ok_or_else(|| Error::Invalid {
            field: format!("{prefix}.shape"),
            reason: format!(
                "unknown shape `{}` (3D shapes: {})",
                self.shape,
                Shape3::ALL.map(Shape3::name).join(", ")
            ),
        })?;
        fn need<T>(x: Option<T>, prefix: &str, key: &str, shape: Shape3) -> Result<T> {
            x.ok_or_else(|| Error::Invalid {
                field: format!("{prefix}.{key}"),
                reason: format!("required for shape `{}`", shape.name()),
            })
        }
        let m = self.mass;
        let (body, desc) = match shape {
            Shape3::Sphere => {
                let r = need(self.radius, prefix, "radius", shape)?;
                (
                    bodies::sphere(m, r, side),
                    format!("sphere m = {m}, r = {r}"),
                )
            }
            Shape3::Ellipsoid => {
                let a = need(self.semi_axes, prefix, "semi_axes", shape)?;
                (
                    bodies::ellipsoid(m, a, q, side),
                    format!("ellipsoid m = {m}, semi-axes {a:?}"),
                )
            }
            Shape3::Box => {
                let h = need(self.half_extents, prefix, "half_extents", shape)?;
                (
                    bodies::cuboid(m, h, q, self.corner, side),
                    format!("box m = {m}, half-extents {h:?}"),
                )
            }
            Shape3::Cylinder => {
                let r = need(self.radius, prefix, "radius", shape)?;
                let h = need(self.half_height, prefix, "half_height", shape)?;
                (
                    bodies::cylinder(m, r, h, q, side),
                    format!("cylinder m = {m}, r = {r}, half-height {h}"),
                )
            }
            Shape3::Rigid => {
                let i = need(self.inertia, prefix, "inertia", shape)?;
                let c = need(self.contact, prefix, "contact", shape)?;
                let im = Mat3::from_fn(|r, col| i[r][col]);
                (
                    RigidBody::new(m, im, q, Vec3::from(c)),
                    format!("rigid body m = {m}, contact {c:?}"),
                )
            }
        };
        let body = body.map_err(|e| e.prefixed(prefix))?;
        let v = self.velocity.unwrap_or([0.0; 3]);
        let w = self.omega.unwrap_or([0.0; 3]);
        if !v.iter().chain(w.iter()).all(|x| x.is_finite()) {
            return Err(Error::Invalid {
                field: prefix.into(),
                reason: "velocity and omega must be finite".into(),
            });
        }
        Ok(BuiltBody3 {
            body,
            state: BodyState::new(Vec3::from(v), Vec3::from(w)),
            description: format!("{desc}, v = {v:?}, ω = {w:?}"),
        })
    }
}

/// A spatial scenario file: `space = "3d"`, the coefficients, optionally the laws, body A and
/// optionally a free body B.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[serde(deny_unknown_fields)]
pub struct SpatialScenario {
    /// Must be `"3d"`.
    pub space: String,
    /// Coulomb friction `μ`.
    pub friction: f64,
    /// Coefficient of restitution `e`.
    pub restitution: f64,
    /// The laws to resolve (ids); `None`: every spatial law.
    pub laws: Option<Vec<String>>,
    /// Body A, striking at its lowest point.
    pub body: BodySpec3,
    /// Body B (free), struck at its highest point; `None`: a fixed surface.
    pub other: Option<BodySpec3>,
}

/// A spatial scenario built: the impact and its one-line description.
#[derive(Debug, Clone)]
pub struct BuiltSpatial {
    /// The bodies before the impact.
    pub impact: BodyImpact,
    /// `body A` or `body A striking body B`.
    pub description: String,
}

impl SpatialScenario {
    /// Whether a TOML text asks for the spatial bodies (`space = "3d"`).
    pub fn is_spatial(text: &str) -> bool {
        text.parse::<toml::Table>()
            .ok()
            .and_then(|t| t.get("space").and_then(|v| v.as_str().map(|s| s == "3d")))
            .unwrap_or(false)
    }

    /// Read a scenario from TOML text.
    ///
    /// # Errors
    /// [`Error::Syntax`]: malformed TOML, a missing or unknown key, a value of the wrong type.
    pub fn from_toml(text: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| Error::syntax(text, &e))
    }

    /// Build the bodies and the impact.
    ///
    /// # Errors
    /// `space` other than `3d`; as [`BodySpec3::build`], naming `body.…` or `other.…`.
    pub fn build(&self) -> Result<BuiltSpatial> {
        if self.space != "3d" {
            return Err(Error::Invalid {
                field: "space".into(),
                reason: format!("`{}` is not `3d`", self.space),
            });
        }
        let a = self.body.build("body", Side::Below)?;
        Ok(match &self.other {
            None => BuiltSpatial {
                impact: BodyImpact::on_fixed_surface(a.body, a.state),
                description: a.description,
            },
            Some(o) => {
                let b = o.build("other", Side::Above)?;
                BuiltSpatial {
                    impact: BodyImpact::between(a.body, a.state, b.body, b.state),
                    description: format!("{} striking {}", a.description, b.description),
                }
            }
        })
    }
}
