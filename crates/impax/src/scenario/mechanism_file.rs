//! A mechanism of one's own as a file: bodies, joints and contact points, planar or spatial —
//! read once here for every front end.
//!
//! ```toml
//! name = "double pendulum"      # optional (default: the file's name)
//! space = "2d"                  # "2d" (default) or "3d"
//! gravity = 9.81                # along −y (2d) or −z (3d)
//! friction = 0.5                # of the impact
//! restitution = 0.5
//! laws = ["whittaker", "energetic"]
//! q = [0.5236, -0.5236]         # the state (SI: radians, metres), default all zero
//! u = [-1.0, 3.0]               #   (3d with a free joint: its quaternion defaults to 1)
//!
//! [[body]]
//! name = "rod 1"
//! mass = 1.0
//! inertia = 0.0833333333333333  # 2d: about the centre of mass; 3d: 3 × 3, body frame
//! com = [0.0, 0.0]              # in the body's frame (default: its origin)
//!
//! [[joint]]
//! name = "theta1"               # names the coordinate (default: the child's name)
//! type = "revolute"             # revolute | prismatic | fixed | free | rolling (2d only)
//! parent = "world"              # or a body placed by an earlier joint
//! child = "rod 1"
//! at = [0.0, 0.0]               # the joint's point in the parent's frame
//! child_at = [0.0, 0.5]         # the same point in the child's frame
//! # axis = [1.0, 0.0]           # prismatic, rolling (2d); revolute and prismatic (3d)
//! # radius = 0.5                # rolling
//!
//! [[contact]]
//! name = "tip"                  # default: the body's name
//! body = "rod 2"
//! point = [0.0, -0.5]           # in the body's frame
//! # radius = 0.02               # a round foot
//! surface = "floor"             # the only surface today
//! # height = 0.0                # default: through the lowest contact at the state
//! ```
//!
//! The generalized coordinates are the joints' in file order (module
//! [`crate::mechanism::linkage`] for the planar joints, [`crate::multibody`] for the spatial
//! ones); unknown keys are errors, and every error names its field
//! (`joint[theta2].parent`, `body[rod 1].inertia`).

use crate::error::{Error, Result};
use crate::math::{Mat3, Vec2, Vec3};
use crate::mechanism::linkage::{self, JointKind as Kind2, LinkBody, LinkContact, Linkage};
use crate::multibody::{self, Body, ContactPoint, JointKind as Kind3, Model, Placement};
use crate::LawId;
use serde::Deserialize;

/// The dimension of a mechanism file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
pub enum Space {
    /// In the plane (`x`, `y` up), the default.
    #[default]
    #[serde(rename = "2d")]
    Planar,
    /// In space (`z` up).
    #[serde(rename = "3d")]
    Spatial,
}

/// A body's moment of inertia: a number (planar) or a 3 × 3 matrix (spatial).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum InertiaEntry {
    /// About the centre of mass, in the plane.
    Scalar(f64),
    /// About the centre of mass, in the body's frame, rows of a symmetric 3 × 3 matrix.
    Matrix([[f64; 3]; 3]),
}

/// A `[[body]]` table.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyEntry {
    /// The body's name.
    pub name: String,
    /// Its mass.
    pub mass: f64,
    /// Its moment of inertia about its centre of mass.
    pub inertia: InertiaEntry,
    /// Its centre of mass in its own frame (default: the origin).
    pub com: Option<Vec<f64>>,
}

/// A `[[joint]]` table.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointEntry {
    /// The joint's name (default: the child's).
    pub name: Option<String>,
    /// `revolute`, `prismatic`, `fixed`, `free` or `rolling`.
    #[serde(rename = "type")]
    pub kind: String,
    /// `world` or a body.
    pub parent: String,
    /// The body it places.
    pub child: String,
    /// The joint's point in the parent's frame (default: the origin).
    pub at: Option<Vec<f64>>,
    /// The joint's point in the child's frame (default: the origin).
    pub child_at: Option<Vec<f64>>,
    /// The axis (prismatic and rolling in 2d; revolute and prismatic in 3d).
    pub axis: Option<Vec<f64>>,
    /// The radius of a rolling disc.
    pub radius: Option<f64>,
}

/// A `[[contact]]` table.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactEntry {
    /// The contact's name (default: the body's).
    pub name: Option<String>,
    /// The body that touches.
    pub body: String,
    /// The point in the body's frame (default: its origin).
    pub point: Option<Vec<f64>>,
    /// The radius of a round foot (default 0).
    pub radius: Option<f64>,
    /// The surface: `floor` (the default and, today, the only one).
    pub surface: Option<String>,
    /// The floor's height (default: through the lowest contact at the state).
    pub height: Option<f64>,
}

/// A mechanism file (module docs).
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismFile {
    /// The mechanism's name.
    pub name: Option<String>,
    /// `2d` or `3d`.
    #[serde(default)]
    pub space: Space,
    /// Gravitational acceleration `g ≥ 0` (default 9.81).
    pub gravity: Option<f64>,
    /// Coulomb friction of the impact.
    pub friction: Option<f64>,
    /// Restitution of the impact.
    pub restitution: Option<f64>,
    /// The laws to show.
    pub laws: Option<Vec<String>>,
    /// The generalized coordinates of the state.
    pub q: Option<Vec<f64>>,
    /// The generalized velocities of the state.
    pub u: Option<Vec<f64>>,
    /// The bodies.
    #[serde(rename = "body", default)]
    pub bodies: Vec<BodyEntry>,
    /// The joints, from the world outwards.
    #[serde(rename = "joint", default)]
    pub joints: Vec<JointEntry>,
    /// The contact points.
    #[serde(rename = "contact", default)]
    pub contacts: Vec<ContactEntry>,
}

/// Whether a TOML text is a mechanism file: it has `[[body]]` tables (an array; a body
/// scenario has one `[body]` table) or `[[joint]]` tables.
pub fn is_mechanism_file(text: &str) -> bool {
    text.parse::<toml::Table>()
        .map(|t| t.get("body").is_some_and(|b| b.is_array()) || t.contains_key("joint"))
        .unwrap_or(false)
}

fn invalid(field: impl Into<String>, reason: impl Into<String>) -> Error {
    Error::Invalid {
        field: field.into(),
        reason: reason.into(),
    }
}

/// A vector of `n` numbers from a key (or zeros).
fn vector<const N: usize>(field: &str, v: &Option<Vec<f64>>) -> Result<[f64; N]> {
    let Some(v) = v else {
        return Ok([0.0; N]);
    };
    let out: [f64; N] = v.as_slice().try_into().map_err(|_| {
        invalid(
            field,
            format!(
                "needs {N} numbers ({} in this file's space), got {}",
                N,
                v.len()
            ),
        )
    })?;
    for (i, x) in out.iter().enumerate() {
        crate::error::finite(&format!("{field}[{i}]"), *x)?;
    }
    Ok(out)
}

impl MechanismFile {
    /// Read a mechanism file's text.
    ///
    /// # Errors
    /// [`Error::Syntax`] with the line and column for malformed TOML, an unknown key or a
    /// value of the wrong type.
    pub fn parse(text: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| Error::syntax(text, &e))
    }

    /// The laws the file asks for (`laws`, each once, in the file's order), else every law
    /// of its space ([`LawId::CONTACT_SPACE`] in the plane, [`LawId::SPATIAL`] in space).
    ///
    /// ```
    /// use impax::scenario::MechanismFile;
    /// use impax::LawId;
    /// let f = MechanismFile::parse("laws = [\"energetic\", \"whittaker\", \"energetic\"]")?;
    /// assert_eq!(f.law_ids()?, [LawId::Energetic, LawId::Whittaker]);
    /// let f = MechanismFile::parse("space = \"3d\"\nlaws = [\"smith\"]")?;
    /// assert_eq!(f.law_ids().unwrap_err().field(), "laws[0]");
    /// # Ok::<(), impax::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::Invalid`] on `laws[i]`: an unknown id, or in space a law defined for planar
    /// impacts only.
    pub fn law_ids(&self) -> Result<Vec<LawId>> {
        let Some(ids) = &self.laws else {
            return Ok(match self.space {
                Space::Planar => LawId::CONTACT_SPACE.to_vec(),
                Space::Spatial => LawId::SPATIAL.to_vec(),
            });
        };
        let mut laws = Vec::new();
        for (i, id) in ids.iter().enumerate() {
            let field = format!("laws[{i}]");
            let law: LawId = id.trim().parse().map_err(|e: Error| match e {
                Error::UnknownLaw { id, known } => invalid(
                    &field,
                    format!("unknown impact law `{id}` (known: {known})"),
                ),
                other => other,
            })?;
            if self.space == Space::Spatial && !law.is_spatial() {
                return Err(invalid(
                    field,
                    format!(
                        "`{law}` is defined for planar impacts only (spatial laws: {})",
                        LawId::SPATIAL.map(|l| l.as_str()).join(", ")
                    ),
                ));
            }
            if !laws.contains(&law) {
                laws.push(law);
            }
        }
        Ok(laws)
    }

    /// The index of the body named `name`, for the field `field`.
    fn body(&self, field: &str, name: &str) -> Result<usize> {
        self.bodies
            .iter()
            .position(|b| b.name == name)
            .ok_or_else(|| invalid(field, format!("`{name}` is not a body of the file")))
    }

    /// The parent of a joint: `None` for `world`.
    fn parent(&self, field: &str, name: &str) -> Result<Option<usize>> {
        if name == "world" {
            Ok(None)
        } else {
            self.body(field, name).map(Some)
        }
    }

    fn joint_name(j: &JointEntry) -> String {
        j.name.clone().unwrap_or_else(|| j.child.clone())
    }

    fn contact_name(&self, c: &ContactEntry, k: usize) -> String {
        c.name.clone().unwrap_or_else(|| {
            if self.contacts.iter().filter(|d| d.body == c.body).count() > 1 {
                format!("{}[{k}]", c.body)
            } else {
                c.body.clone()
            }
        })
    }

    fn check_surface(c: &ContactEntry, field: &str) -> Result<()> {
        match c.surface.as_deref() {
            None | Some("floor") => Ok(()),
            Some(other) => Err(invalid(
                format!("{field}.surface"),
                format!("`{other}`: the only surface is `floor`"),
            )),
        }
    }

    /// The planar mechanism of a `2d` file (its floors where the file puts them, or at
    /// `y = 0` until [`Linkage::place_floor`]).
    ///
    /// # Errors
    /// A `3d` file; an unknown body, joint type or surface; a vector of the wrong length;
    /// and every error of [`Linkage::new`], each naming its field.
    pub fn planar(&self) -> Result<Linkage> {
        if self.space != Space::Planar {
            return Err(invalid(
                "space",
                "a `3d` file is a spatial mechanism: `impax compare`, `audit` and `sweep` take it; \
                 `simulate` and `conserved` are planar only for now",
            ));
        }
        let mut bodies = Vec::with_capacity(self.bodies.len());
        for b in &self.bodies {
            let field = format!("body[{}]", b.name);
            let InertiaEntry::Scalar(inertia) = b.inertia else {
                return Err(invalid(
                    format!("{field}.inertia"),
                    "a planar body's inertia is one number (about its centre of mass)",
                ));
            };
            let com = vector::<2>(&format!("{field}.com"), &b.com)?;
            bodies.push(LinkBody::new(&b.name, b.mass, inertia, Vec2::from(com)));
        }
        let mut joints = Vec::with_capacity(self.joints.len());
        for j in &self.joints {
            let name = Self::joint_name(j);
            let field = format!("joint[{name}]");
            let axis = |default: Option<[f64; 2]>| -> Result<Vec2> {
                match (&j.axis, default) {
                    (None, Some(d)) => Ok(Vec2::from(d)),
                    (None, None) => Err(invalid(format!("{field}.axis"), "is needed")),
                    (a, _) => vector::<2>(&format!("{field}.axis"), a).map(Vec2::from),
                }
            };
            let kind = match j.kind.as_str() {
                "revolute" => Kind2::Revolute,
                "prismatic" => Kind2::Prismatic { axis: axis(None)? },
                "fixed" => Kind2::Fixed,
                "free" => Kind2::Free,
                "rolling" => Kind2::Rolling {
                    axis: axis(Some([1.0, 0.0]))?,
                    radius: j
                        .radius
                        .ok_or_else(|| invalid(format!("{field}.radius"), "is needed"))?,
                },
                other => return Err(unknown_type(&field, other, true)),
            };
            if j.axis.is_some() && matches!(kind, Kind2::Revolute | Kind2::Fixed | Kind2::Free) {
                return Err(invalid(
                    format!("{field}.axis"),
                    format!("a planar `{}` joint has no axis", j.kind),
                ));
            }
            joints.push(linkage::Joint {
                parent: self.parent(&format!("{field}.parent"), &j.parent)?,
                child: self.body(&format!("{field}.child"), &j.child)?,
                at: Vec2::from(vector::<2>(&format!("{field}.at"), &j.at)?),
                child_at: Vec2::from(vector::<2>(&format!("{field}.child_at"), &j.child_at)?),
                name,
                kind,
            });
        }
        let mut contacts = Vec::with_capacity(self.contacts.len());
        for (k, c) in self.contacts.iter().enumerate() {
            let name = self.contact_name(c, k);
            let field = format!("contact[{name}]");
            Self::check_surface(c, &field)?;
            contacts.push(LinkContact {
                body: self.body(&format!("{field}.body"), &c.body)?,
                point: Vec2::from(vector::<2>(&format!("{field}.point"), &c.point)?),
                radius: c.radius.unwrap_or(0.0),
                height: c.height,
                name,
            });
        }
        let name = self.name.as_deref().unwrap_or("mechanism");
        Linkage::new(name, bodies, joints, contacts, self.gravity.unwrap_or(9.81))
    }

    /// The spatial mechanism of a `3d` file, its floor at the file's `height` (one for every
    /// contact) or at `z = 0`.
    ///
    /// # Errors
    /// A `2d` file; an unknown body, joint type or surface; a vector of the wrong length;
    /// contacts with different heights; and every error of [`Model::new`], each naming its
    /// field.
    pub fn spatial(&self) -> Result<Model> {
        if self.space != Space::Spatial {
            return Err(invalid("space", "a `2d` file is a planar mechanism"));
        }
        let mut bodies = Vec::with_capacity(self.bodies.len());
        for b in &self.bodies {
            let field = format!("body[{}]", b.name);
            let InertiaEntry::Matrix(rows) = b.inertia else {
                return Err(invalid(
                    format!("{field}.inertia"),
                    "a spatial body's inertia is a 3 × 3 matrix about its centre of mass (rows)",
                ));
            };
            let inertia = Mat3::from_fn(|i, j| rows[i][j]);
            let com = Vec3::from(vector::<3>(&format!("{field}.com"), &b.com)?);
            bodies.push(Body::new(&b.name, b.mass, com, inertia));
        }
        let mut joints = Vec::with_capacity(self.joints.len());
        for j in &self.joints {
            let name = Self::joint_name(j);
            let field = format!("joint[{name}]");
            let axis = || -> Result<Vec3> {
                match &j.axis {
                    None => Err(invalid(format!("{field}.axis"), "is needed")),
                    a => vector::<3>(&format!("{field}.axis"), a).map(Vec3::from),
                }
            };
            let kind = match j.kind.as_str() {
                "revolute" => Kind3::Revolute { axis: axis()? },
                "prismatic" => Kind3::Prismatic { axis: axis()? },
                "fixed" => Kind3::Fixed,
                "free" => Kind3::Free,
                other => return Err(unknown_type(&field, other, false)),
            };
            if j.radius.is_some() {
                return Err(invalid(
                    format!("{field}.radius"),
                    "only a rolling joint has one",
                ));
            }
            let at = Vec3::from(vector::<3>(&format!("{field}.at"), &j.at)?);
            let child_at = Vec3::from(vector::<3>(&format!("{field}.child_at"), &j.child_at)?);
            let mut joint = multibody::Joint::new(
                &name,
                kind,
                self.parent(&format!("{field}.parent"), &j.parent)?,
                self.body(&format!("{field}.child"), &j.child)?,
                Placement::from_translation(at),
            );
            joint.child_placement = Placement::from_translation(child_at);
            joints.push(joint);
        }
        let mut contacts = Vec::with_capacity(self.contacts.len());
        let mut height: Option<f64> = None;
        for (k, c) in self.contacts.iter().enumerate() {
            let name = self.contact_name(c, k);
            let field = format!("contact[{name}]");
            Self::check_surface(c, &field)?;
            if let Some(h) = c.height {
                if height.is_some_and(|g| g != h) {
                    return Err(invalid(
                        format!("{field}.height"),
                        "every contact of a spatial mechanism strikes the same floor",
                    ));
                }
                height = Some(h);
            }
            let point = Vec3::from(vector::<3>(&format!("{field}.point"), &c.point)?);
            let body = self.body(&format!("{field}.body"), &c.body)?;
            contacts.push(ContactPoint::new(
                &name,
                body,
                point,
                c.radius.unwrap_or(0.0),
            ));
        }
        Model::new(bodies, joints, contacts)?
            .with_gravity(self.gravity.unwrap_or(multibody::STANDARD_GRAVITY))?
            .with_floor(height.unwrap_or(0.0))
    }

    /// Put every contact's floor at the height `h` (`y = h` in 2d, `z = h` in 3d), the
    /// file's own `height`s replaced.
    ///
    /// ```
    /// use impax::scenario::MechanismFile;
    /// let text = std::fs::read_to_string(concat!(
    ///     env!("CARGO_MANIFEST_DIR"), "/../../examples/mechanisms/double-pendulum.toml"))?;
    /// let mut file = MechanismFile::parse(&text)?;
    /// assert!(!file.floor_given());
    /// file.set_floor(-2.0);
    /// assert!(file.floor_given() && file.contacts.iter().all(|c| c.height == Some(-2.0)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn set_floor(&mut self, h: f64) {
        self.contacts.iter_mut().for_each(|c| c.height = Some(h));
    }

    /// Whether the file gives the floor's height (else it passes through the lowest contact
    /// at the state).
    pub fn floor_given(&self) -> bool {
        self.contacts.iter().any(|c| c.height.is_some())
    }
}

fn unknown_type(field: &str, other: &str, planar: bool) -> Error {
    invalid(
        format!("{field}.type"),
        format!(
            "unknown joint type `{other}` (known: revolute, prismatic, fixed, free{})",
            if planar {
                ", rolling"
            } else {
                "; rolling is planar only"
            }
        ),
    )
}
