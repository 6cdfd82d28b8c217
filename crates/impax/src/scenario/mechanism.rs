//! A built-in mechanism as a file, the command line or a front end describes it: its name,
//! its parameters and its state, every one optional with the mechanism's default — and the one
//! builder of the built-ins from that description.
//!
//! ```toml
//! mechanism = "double-pendulum"   # double-pendulum | ring-pendulum | cart-pendulum | sphere | rod
//! friction = 0.5                  # compare only
//! restitution = 0.5               # compare only
//! laws = ["whittaker", "energetic"]
//! masses = [1.0, 1.0]             # per mechanism (see the table of MechanismSpec::build)
//! lengths = [1.0, 1.0]
//! radius = 1.0
//! gravity = 9.81
//! angles_deg = [30.0, 0.0]
//! rates = [-1.0, 2.0]
//! position = [0.0]
//! ```

use super::shape::AngleUnit;
use super::MechanismFile;
use crate::error::{Error, Num, Result};
use crate::mechanism::builtin::{
    BuiltIn, CartPendulum, DoublePendulum, RingPendulum, Rod, Sphere, STANDARD_GRAVITY,
};
use crate::mechanism::Mechanism;
use serde::Deserialize;

/// The largest angle coordinate a description may give, in degrees (one turn).
pub const MAX_ANGLE_DEG: f64 = 360.0;

/// Coulomb friction `μ` of a mechanism's impact when neither its description (a built-in's
/// `friction`, a mechanism file's) nor the front end gives one.
pub const DEFAULT_FRICTION: f64 = 0.5;

/// Restitution `e` of a mechanism's impact when neither its description nor the front end
/// gives one.
pub const DEFAULT_RESTITUTION: f64 = 0.5;

/// A built-in mechanism as written in a file (a top-level `mechanism` key) or filled in from
/// flags or a front end's arguments. Every field but the name is optional: each mechanism has
/// defaults ([`MechanismSpec::build`]).
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// The name, one of [`BuiltIn::NAMES`].
    pub mechanism: String,
    /// Coulomb friction `μ` of the impact (front ends that resolve one).
    pub friction: Option<f64>,
    /// Coefficient of restitution `e` of the impact.
    pub restitution: Option<f64>,
    /// The laws to show (ids).
    pub laws: Option<Vec<String>>,
    /// The masses (double-pendulum: m1, m2; ring-pendulum: ring, bob; cart-pendulum: cart,
    /// bob; sphere, rod: m).
    pub masses: Option<Vec<f64>>,
    /// The lengths (double-pendulum: l1, l2; ring- and cart-pendulum: the arm; rod: l).
    pub lengths: Option<Vec<f64>>,
    /// The radius (ring-pendulum: the ring; sphere).
    pub radius: Option<f64>,
    /// Gravitational acceleration `g` along `−y`.
    pub gravity: Option<f64>,
    /// The angle coordinates, in [`MechanismSpec::angle_unit`]: the key `angles_deg` of files.
    #[serde(rename = "angles_deg")]
    pub angles: Option<Vec<f64>>,
    /// The generalized velocities in coordinate order (rad/s for angles).
    pub rates: Option<Vec<f64>>,
    /// The position coordinates (ring- and cart-pendulum: x; sphere, rod: x, y).
    pub position: Option<Vec<f64>>,
    /// The generalized coordinates, all of them, in SI units (radians, metres): replace the
    /// state the other keys give (a mechanism file's state is given this way only).
    pub q: Option<Vec<f64>>,
    /// The generalized velocities, all of them (rad/s, m/s).
    pub u: Option<Vec<f64>>,
    /// A mechanism of one's own, from a mechanism file ([`MechanismFile`]): then `mechanism`
    /// is its name, and only `friction`, `restitution`, `laws`, `gravity`, `q` and `u` apply.
    /// Not a key.
    #[serde(skip)]
    pub file: Option<MechanismFile>,
    /// The unit of `angles`, and so their key in errors and how descriptions show them:
    /// degrees for files and flags (the default), radians for the Python bindings. Not a key.
    #[serde(skip)]
    pub angle_unit: AngleUnit,
}

/// A built-in mechanism built from its [`MechanismSpec`], at its state.
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltMechanism {
    /// The mechanism.
    pub mechanism: BuiltIn,
    /// Generalized coordinates (radians for angles).
    pub q: Vec<f64>,
    /// Generalized velocities (rad/s for angles).
    pub u: Vec<f64>,
    /// One line describing the case.
    pub description: String,
}

/// A state vector: one finite number per coordinate.
fn state_vector(field: &str, v: &[f64], coordinates: &[&str]) -> Result<Vec<f64>> {
    if v.len() != coordinates.len() {
        return Err(Error::Invalid {
            field: field.into(),
            reason: format!(
                "needs {} value(s) ({}), got {}",
                coordinates.len(),
                coordinates.join(", "),
                v.len()
            ),
        });
    }
    for (i, &x) in v.iter().enumerate() {
        crate::error::finite(&format!("{field}[{i}]"), x)?;
    }
    Ok(v.to_vec())
}

/// `n` things, singular or plural.
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// Numbers as a list, `1, 2.5`.
fn join(v: &[f64]) -> String {
    v.iter()
        .map(|x| Num(*x).to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

fn reject(name: &str, field: &str, present: bool) -> Result<()> {
    if present {
        Err(Error::Invalid {
            field: field.into(),
            reason: format!("not a parameter of {name}"),
        })
    } else {
        Ok(())
    }
}

impl MechanismSpec {
    /// The key of the angle coordinates as this spec spells them (`angles_deg` or `angles`).
    pub fn angles_key(&self) -> &'static str {
        match self.angle_unit {
            AngleUnit::Degrees => "angles_deg",
            AngleUnit::Radians => "angles",
        }
    }

    /// The numbers of `field` (or `default`): as many as the default, finite, angles at most
    /// one turn.
    fn list(&self, field: &str, v: &Option<Vec<f64>>, default: &[f64]) -> Result<Vec<f64>> {
        let v = v.clone().unwrap_or_else(|| default.to_vec());
        if v.len() != default.len() {
            return Err(Error::Invalid {
                field: field.into(),
                reason: format!("needs {} value(s), got {}", default.len(), v.len()),
            });
        }
        let turn = match self.angle_unit {
            AngleUnit::Degrees => (MAX_ANGLE_DEG, "-360 and 360 degrees"),
            AngleUnit::Radians => (MAX_ANGLE_DEG.to_radians(), "-2π and 2π radians"),
        };
        for (i, &x) in v.iter().enumerate() {
            if !x.is_finite() {
                return Err(Error::NotFinite {
                    field: format!("{field}[{i}]"),
                    value: x,
                });
            }
            if field == self.angles_key() && x.abs() > turn.0 {
                return Err(Error::Invalid {
                    field: format!("{field}[{i}]"),
                    reason: format!("must be between {}, got {}", turn.1, Num(x)),
                });
            }
        }
        Ok(v)
    }

    /// The angle coordinates (or their defaults, given in degrees), checked, in the spec's
    /// unit and in radians.
    fn angles(&self, default_deg: &[f64]) -> Result<(Vec<f64>, Vec<f64>)> {
        let unit = self.angle_unit;
        let default: Vec<f64> = match unit {
            AngleUnit::Degrees => default_deg.to_vec(),
            AngleUnit::Radians => default_deg.iter().map(|d| d.to_radians()).collect(),
        };
        let a = self.list(self.angles_key(), &self.angles, &default)?;
        let q = a.iter().map(|&x| unit.to_radians(x)).collect();
        Ok((a, q))
    }

    /// Build the mechanism and its state, with the defaults of each mechanism:
    ///
    /// | name | coordinates | `masses`; `lengths`; `radius` | defaults |
    /// |---|---|---|---|
    /// | `double-pendulum` | θ1, θ2 from the downward vertical | m1, m2; l1, l2 | 1, 1; 1, 1; 30°, 0°; rates −1, 2; the floor through the tip of rod 2 |
    /// | `ring-pendulum` | x, φ | ring, bob; the arm; the ring's | 1, 1; 1; 1; x = 0, φ = 30°; rates 0.5, 0 |
    /// | `cart-pendulum` | x, φ | cart, bob; the arm; — | 1, 1; 1; x = 0, φ = 30°; rates 0.5, 0 |
    /// | `sphere` | x, y, θ | m; —; r | 1; 1; on the floor, velocity (sin 30°, −cos 30°) |
    /// | `rod` | x, y, θ from the floor | m; l; — | 1; 1; 50°, its lower end on the floor, velocity (0.5, −1) |
    ///
    /// `gravity` defaults to [`STANDARD_GRAVITY`].
    ///
    /// ```
    /// use impax::scenario::MechanismSpec;
    /// let spec = MechanismSpec { mechanism: "double-pendulum".into(), ..MechanismSpec::default() };
    /// let built = spec.build()?;
    /// assert_eq!(built.q, vec![30f64.to_radians(), 0.0]);
    /// assert!(built.description.contains("θ1 = 30°, θ2 = 0°"));
    /// # Ok::<(), impax::Error>(())
    /// ```
    ///
    /// # Errors
    /// An unknown name, a parameter the mechanism does not take, a list of the wrong length, a
    /// number that is not finite, an angle beyond one turn, or parameters the mechanism
    /// refuses (a non-positive mass or length) — each naming the field.
    pub fn build(&self) -> Result<BuiltMechanism> {
        let mut built = match &self.file {
            Some(file) => self.linkage(file)?,
            None => self.built_in()?,
        };
        for (field, given, state) in [("q", &self.q, &mut built.q), ("u", &self.u, &mut built.u)] {
            if let Some(v) = given {
                *state = state_vector(field, v, built.mechanism.coordinates())?;
            }
        }
        if self.file.is_some() || self.q.is_some() {
            built.mechanism.place_floor(&built.q)?;
        }
        if self.file.is_some() || self.q.is_some() || self.u.is_some() {
            built.description = format!(
                "{}: q = ({}), u = ({})",
                built.description,
                join(&built.q),
                join(&built.u)
            );
        }
        Ok(built)
    }

    /// The planar mechanism of a mechanism file at the file's state (`q`, `u`, default zero).
    fn linkage(&self, file: &MechanismFile) -> Result<BuiltMechanism> {
        for (field, present) in [
            ("masses", self.masses.is_some()),
            ("lengths", self.lengths.is_some()),
            ("radius", self.radius.is_some()),
            (self.angles_key(), self.angles.is_some()),
            ("rates", self.rates.is_some()),
            ("position", self.position.is_some()),
        ] {
            if present {
                return Err(Error::Invalid {
                    field: field.into(),
                    reason: "not a parameter of a mechanism file (its state is `q` and `u`)".into(),
                });
            }
        }
        let mut file = file.clone();
        if let Some(g) = self.gravity {
            file.gravity = Some(g);
        }
        let linkage = file.planar()?;
        let n = linkage.dof();
        let zeros = vec![0.0; n];
        let q = state_vector(
            "q",
            file.q.as_ref().unwrap_or(&zeros),
            linkage.coordinates(),
        )?;
        let u = state_vector(
            "u",
            file.u.as_ref().unwrap_or(&zeros),
            linkage.coordinates(),
        )?;
        Ok(BuiltMechanism {
            description: format!(
                "{} (a mechanism file: {}, {}, {}; g = {})",
                self.mechanism,
                count(file.bodies.len(), "body", "bodies"),
                count(file.joints.len(), "joint", "joints"),
                count(file.contacts.len(), "contact", "contacts"),
                file.gravity.unwrap_or(STANDARD_GRAVITY)
            ),
            mechanism: BuiltIn::Linkage(linkage),
            q,
            u,
        })
    }

    /// A built-in mechanism at the state its keys give.
    fn built_in(&self) -> Result<BuiltMechanism> {
        let g = self.gravity.unwrap_or(STANDARD_GRAVITY);
        let name = self.mechanism.as_str();
        let show = |x: f64| self.angle_unit.show(x);
        match name {
            "double-pendulum" => {
                reject(name, "radius", self.radius.is_some())?;
                reject(name, "position", self.position.is_some())?;
                let m = self.list("masses", &self.masses, &[1.0, 1.0])?;
                let l = self.list("lengths", &self.lengths, &[1.0, 1.0])?;
                let (a, q) = self.angles(&[30.0, 0.0])?;
                let u = self.list("rates", &self.rates, &[-1.0, 2.0])?;
                let mut dp = DoublePendulum::new(m[0], m[1], l[0], l[1], g, 0.0)?;
                dp.put_floor_at_tip([q[0], q[1]]);
                Ok(BuiltMechanism {
                    description: format!(
                        "double pendulum (m = {}, {}; l = {}, {}; g = {}): θ1 = {}, θ2 = {}, rates ({}, {}) rad/s; the tip of rod 2 strikes the floor",
                        Num(m[0]), Num(m[1]), Num(l[0]), Num(l[1]), Num(g), show(a[0]), show(a[1]), Num(u[0]), Num(u[1])
                    ),
                    mechanism: BuiltIn::DoublePendulum(dp),
                    q,
                    u,
                })
            }
            "ring-pendulum" | "cart-pendulum" => self.pendulum_on_a_carrier(g),
            "sphere" => {
                reject(name, "lengths", self.lengths.is_some())?;
                let m = self.list("masses", &self.masses, &[1.0])?;
                let r = self.radius.unwrap_or(1.0);
                let p = self.list("position", &self.position, &[0.0, r])?;
                let (a, q) = self.angles(&[0.0])?;
                let (s, c) = 30f64.to_radians().sin_cos();
                let u = self.list("rates", &self.rates, &[s, -c, 0.0])?;
                Ok(BuiltMechanism {
                    description: format!(
                        "sphere (m = {}, r = {r}; g = {g}) at ({}, {}), θ = {}, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                        m[0], p[0], p[1], show(a[0]), u[0], u[1], u[2]
                    ),
                    mechanism: BuiltIn::Sphere(Sphere::new(m[0], r, g, 0.0)?),
                    q: vec![p[0], p[1], q[0]],
                    u,
                })
            }
            "rod" => {
                reject(name, "radius", self.radius.is_some())?;
                let m = self.list("masses", &self.masses, &[1.0])?;
                let l = self.list("lengths", &self.lengths, &[1.0])?;
                let (a, q) = self.angles(&[50.0])?;
                let lift = 0.5 * l[0] * q[0].sin().abs();
                let p = self.list("position", &self.position, &[0.0, lift])?;
                let u = self.list("rates", &self.rates, &[0.5, -1.0, 0.0])?;
                Ok(BuiltMechanism {
                    description: format!(
                        "rod (m = {}, l = {}; g = {g}) at ({}, {}), θ = {} from the floor, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                        m[0], l[0], p[0], p[1], show(a[0]), u[0], u[1], u[2]
                    ),
                    mechanism: BuiltIn::Rod(Rod::new(m[0], l[0], g, 0.0)?),
                    q: vec![p[0], p[1], q[0]],
                    u,
                })
            }
            other => Err(Error::Invalid {
                field: "mechanism".into(),
                reason: format!(
                    "unknown mechanism `{other}` (known: {})",
                    BuiltIn::NAMES.join(", ")
                ),
            }),
        }
    }

    /// `ring-pendulum` and `cart-pendulum`: a pendulum hung from a rolling ring or a cart.
    fn pendulum_on_a_carrier(&self, g: f64) -> Result<BuiltMechanism> {
        let name = self.mechanism.as_str();
        let ring = name == "ring-pendulum";
        if !ring {
            reject(name, "radius", self.radius.is_some())?;
        }
        let m = self.list("masses", &self.masses, &[1.0, 1.0])?;
        let l = self.list("lengths", &self.lengths, &[1.0])?;
        let x = self.list("position", &self.position, &[0.0])?;
        let (a, phi) = self.angles(&[30.0])?;
        let u = self.list("rates", &self.rates, &[0.5, 0.0])?;
        let (mechanism, what) = if ring {
            let r = self.radius.unwrap_or(1.0);
            (
                BuiltIn::RingPendulum(RingPendulum::new(m[0], r, m[1], l[0], g)?),
                format!(
                    "ring-pendulum (ring M = {}, R = {r}; bob m = {}, l = {}; g = {g})",
                    m[0], m[1], l[0]
                ),
            )
        } else {
            (
                BuiltIn::CartPendulum(CartPendulum::new(m[0], m[1], l[0], g)?),
                format!(
                    "cart-pendulum (cart M = {}; bob m = {}, l = {}; g = {g})",
                    m[0], m[1], l[0]
                ),
            )
        };
        Ok(BuiltMechanism {
            description: format!(
                "{what}: x = {}, φ = {}, ẋ = {}, φ̇ = {} rad/s",
                x[0],
                self.angle_unit.show(a[0]),
                u[0],
                u[1]
            ),
            mechanism,
            q: vec![x[0], phi[0]],
            u,
        })
    }
}
