//! A spatial mechanism of one's own at a state, struck at one contact: a robot from URDF or a
//! `space = "3d"` mechanism file, as every front end describes it — and the one builder.
//!
//! ```
//! use impax::scenario::{RobotSource, RobotSpec};
//! use impax::LawId;
//! // A brick (0.2 × 0.1 × 0.05 m, 1 kg) from URDF with a floating base, falling on a corner
//! // (the floor passes through it): q = (x, y, z, qw, qx, qy, qz), u = (v, ω) in the world.
//! let urdf = r#"<robot name="brick"><link name="brick"><inertial><mass value="1"/>
//!   <inertia ixx="0.00104" iyy="0.00354" izz="0.00417" ixy="0" ixz="0" iyz="0"/>
//!   </inertial></link></robot>"#;
//! let spec = RobotSpec {
//!     floating_base: true,
//!     contact: Some("brick:0.1,0.05,-0.025".into()),
//!     u: Some(vec![0.3, 0.0, -1.0, 0.0, 2.0, 0.0]),
//!     ..RobotSpec::new("", RobotSource::Urdf(urdf.into()))
//! };
//! let robot = spec.build()?;
//! assert_eq!(robot.coordinates()[..4], ["x", "y", "z", "qw"]);
//! let impact = robot.impact()?;
//! assert!(impact.gap().abs() < 1e-15);
//! let out = impact.resolve(LawId::Energetic, 0.5, 0.5)?;
//! assert!(out.energy_change_from_velocities.unwrap() < 0.0);
//! # Ok::<(), impax::Error>(())
//! ```

use super::MechanismFile;
use crate::error::{Error, Result};
use crate::multibody::urdf::link_contact;
use crate::multibody::{
    contact_position, forward_kinematics, read_urdf, BodyPose, ContactSpec, LinkFrame, Model,
    SpatialMechanismImpact, UrdfOptions,
};

/// Where a robot comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum RobotSource {
    /// The text of a URDF file.
    Urdf(String),
    /// A `space = "3d"` mechanism file, read.
    File(Box<MechanismFile>),
}

/// A spatial mechanism of one's own, as a front end gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotSpec {
    /// Its name (a URDF robot's own name is used when this is empty).
    pub name: String,
    /// The URDF text or the mechanism file.
    pub source: RobotSource,
    /// URDF: put a free joint first (`q = (x, y, z, qw, qx, qy, qz, …)`, `u = (v, ω, …)` in
    /// the world frame). Files say so with a `free` joint.
    pub floating_base: bool,
    /// The contact that strikes: URDF `LINK` or `LINK:x,y,z` (a point in the link's frame;
    /// required); a file's contact by name (default: the lowest at the state).
    pub contact: Option<String>,
    /// URDF: more contact points (`LINK` or `LINK:x,y,z` each), after `contact`: a
    /// simulation watches them all, and the lowest at the state strikes. A file's contacts
    /// are its own (this must be empty).
    pub more_contacts: Vec<String>,
    /// The floor's height (default: a file's `height`, else through the striking contact at
    /// the state).
    pub floor: Option<f64>,
    /// Gravitational acceleration `g ≥ 0` along `−z` (default: a file's `gravity`, else
    /// 9.81).
    pub gravity: Option<f64>,
    /// The generalized coordinates (default: the file's `q`, else the neutral state — zero
    /// joints, the base at the origin with the identity quaternion).
    pub q: Option<Vec<f64>>,
    /// The generalized velocities (default: the file's `u`, else zero).
    pub u: Option<Vec<f64>>,
}

impl RobotSpec {
    /// A spec with every option at its default.
    pub fn new(name: &str, source: RobotSource) -> Self {
        RobotSpec {
            name: name.into(),
            source,
            floating_base: false,
            contact: None,
            more_contacts: Vec::new(),
            floor: None,
            gravity: None,
            q: None,
            u: None,
        }
    }

    /// Read the description once — the URDF parsed (without contact points), or the file's
    /// model built — with the spec's `floating_base`, `floor` and `gravity`, but not its
    /// state nor its contact: a [`Robot`] to put at any state, struck at any contact
    /// ([`Robot::at`]).
    ///
    /// # Errors
    /// Every error of [`read_urdf`] and [`MechanismFile::spatial`]; `floating_base` for a
    /// file (it has its joints); a floor or a gravity that is not a finite number (≥ 0 for
    /// gravity) — each naming its field.
    pub fn load(&self) -> Result<Robot> {
        let floor = self
            .floor
            .map(|h| crate::error::finite("floor", h))
            .transpose()?;
        let mut robot = match &self.source {
            RobotSource::Urdf(text) => {
                let options = UrdfOptions::default().floating_base(self.floating_base);
                let urdf = read_urdf(text, &options)?;
                Robot {
                    name: if self.name.is_empty() {
                        urdf.name.clone()
                    } else {
                        self.name.clone()
                    },
                    model: urdf.model,
                    links: Some(urdf.links),
                    mimic_joints: urdf.mimic_joints.into_iter().map(|m| m.joint).collect(),
                    q: None,
                    u: None,
                    floor,
                }
            }
            RobotSource::File(file) => {
                if self.floating_base {
                    return Err(Error::Invalid {
                        field: "floating_base".into(),
                        reason: "a mechanism file gives its base a `free` joint itself".into(),
                    });
                }
                let model = file.spatial()?;
                Robot {
                    name: file.name.clone().unwrap_or_else(|| self.name.clone()),
                    floor: floor.or(file.floor_given().then(|| model.floor())),
                    model,
                    links: None,
                    mimic_joints: Vec::new(),
                    q: file.q.clone(),
                    u: file.u.clone(),
                }
            }
        };
        if let Some(g) = self.gravity {
            robot.model = robot.model.with_gravity(g)?;
        }
        Ok(robot)
    }

    /// Build the model at its state, its floor placed and its striking contact chosen: a
    /// file's named `contact`, else the lowest contact at the state (a URDF robot's contacts
    /// are `contact` and `more_contacts`, in that order; ties go to the first).
    ///
    /// # Errors
    /// Every error of [`RobotSpec::build_free`]; a URDF robot without `contact`; a mechanism
    /// without contacts; an unknown contact — each naming its field.
    pub fn build(&self) -> Result<BuiltRobot> {
        if matches!(self.source, RobotSource::Urdf(_)) && self.contact.is_none() {
            return Err(Error::Invalid {
                field: "contact".into(),
                reason: "which link strikes: LINK or LINK:x,y,z (a point in its frame)".into(),
            });
        }
        let free = self.build_free()?;
        let FreeRobot {
            name,
            mut model,
            q,
            u,
            mimic_joints,
        } = free;
        if model.contacts().is_empty() {
            return Err(Error::Invalid {
                field: "contact".into(),
                reason: format!("`{name}` has no contact point to strike"),
            });
        }
        let heights = contact_heights(&model, &q);
        let contact = match (&self.source, &self.contact) {
            (RobotSource::File(_), Some(c)) => {
                model.contact_index(c).ok_or_else(|| Error::Invalid {
                    field: "contact".into(),
                    reason: format!(
                        "`{c}` is not a contact of `{name}` (its contacts: {})",
                        model
                            .contacts()
                            .iter()
                            .map(|c| c.name.as_str())
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                })?
            }
            _ => (0..heights.len())
                .min_by(|&a, &b| heights[a].total_cmp(&heights[b]))
                .unwrap_or(0),
        };
        let floor = match (self.floor, &self.source) {
            (Some(h), _) => crate::error::finite("floor", h)?,
            (None, RobotSource::File(file)) if file.floor_given() => model.floor(),
            (None, _) => heights[contact],
        };
        model = model.with_floor(floor)?;
        Ok(BuiltRobot {
            name,
            model,
            q,
            u,
            contact,
            mimic_joints,
        })
    }

    /// Build the model at its state for its free motion (`impax conserved`): no contact needs
    /// to be given or chosen, and the floor is the file's or `floor` (else `z = 0`; it plays
    /// no part in a free motion).
    ///
    /// # Errors
    /// Every error of [`read_urdf`] and [`MechanismFile::spatial`]; `floating_base` or
    /// `more_contacts` for a file (it has its joints and contacts); `q` or `u` of the wrong
    /// length or not finite — each naming its field.
    pub fn build_free(&self) -> Result<FreeRobot> {
        let (mut model, name, mimic_joints, file_q, file_u) = match &self.source {
            RobotSource::Urdf(text) => {
                let mut options = UrdfOptions::default().floating_base(self.floating_base);
                for spec in self.contact.iter().chain(&self.more_contacts) {
                    options = options.contact(ContactSpec::parse(spec)?);
                }
                let robot = read_urdf(text, &options)?;
                let name = if self.name.is_empty() {
                    robot.name.clone()
                } else {
                    self.name.clone()
                };
                let mimic = robot.mimic_joints.iter().map(|m| m.joint.clone()).collect();
                (robot.model, name, mimic, None, None)
            }
            RobotSource::File(file) => {
                if self.floating_base {
                    return Err(Error::Invalid {
                        field: "floating_base".into(),
                        reason: "a mechanism file gives its base a `free` joint itself".into(),
                    });
                }
                if !self.more_contacts.is_empty() {
                    return Err(Error::Invalid {
                        field: "contact".into(),
                        reason: "a mechanism file's contacts are its [[contact]] tables (name \
                                 one to strike)"
                            .into(),
                    });
                }
                let model = file.spatial()?;
                let name = file.name.clone().unwrap_or_else(|| self.name.clone());
                (model, name, Vec::new(), file.q.clone(), file.u.clone())
            }
        };
        let q = self.q.clone().or(file_q).unwrap_or_else(|| model.neutral());
        let q = model.check_state(&q, None)?;
        let u = self
            .u
            .clone()
            .or(file_u)
            .unwrap_or_else(|| vec![0.0; model.nv()]);
        model.check_speeds(&u)?;
        if let Some(h) = self.floor {
            model = model.with_floor(crate::error::finite("floor", h)?)?;
        }
        if let Some(g) = self.gravity {
            model = model.with_gravity(g)?;
        }
        Ok(FreeRobot {
            name,
            model,
            q,
            u,
            mimic_joints,
        })
    }
}

/// A spatial mechanism of one's own read once ([`RobotSpec::load`]): a URDF robot or a
/// `space = "3d"` mechanism file, to put at many states and strike at any of its contacts
/// without reading its description again.
///
/// ```
/// use impax::scenario::{RobotSource, RobotSpec};
/// let urdf = r#"<robot name="brick"><link name="brick"><inertial><mass value="1"/>
///   <inertia ixx="0.00104" iyy="0.00354" izz="0.00417" ixy="0" ixz="0" iyz="0"/>
///   </inertial></link></robot>"#;
/// let spec = RobotSpec { floating_base: true, ..RobotSpec::new("", RobotSource::Urdf(urdf.into())) };
/// let robot = spec.load()?;
/// assert_eq!(robot.contact_names(), ["brick"]); // a URDF robot's contacts are its links
/// // Two corners of the brick, each at its own state, without reading the URDF again.
/// let q = [0.0, 0.0, 0.3, 1.0, 0.0, 0.0, 0.0];
/// let u = [0.0, 0.0, -1.0, 0.0, 0.0, 0.0];
/// let a = robot.at(Some(&q), Some(&u), Some("brick:0.1,0.05,-0.025"))?;
/// let b = robot.at(Some(&q), Some(&u), Some("brick:-0.1,0.05,-0.025"))?;
/// // The floor through each corner: 0.3 − 0.025 (to round-off).
/// assert!((a.model.floor() - 0.275).abs() < 1e-15 && a.model.floor() == b.model.floor());
/// // Falling flat, the corners' contact velocities are the same.
/// assert_eq!(a.impact()?.contact_velocity(), b.impact()?.contact_velocity());
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Robot {
    name: String,
    /// The bodies and joints (a file's contacts; none for a URDF robot), gravity applied.
    model: Model,
    /// A URDF robot's link frames (where its contacts are named).
    links: Option<Vec<LinkFrame>>,
    mimic_joints: Vec<String>,
    /// A file's state.
    q: Option<Vec<f64>>,
    u: Option<Vec<f64>>,
    /// The floor given (the spec's, else a file's `height`).
    floor: Option<f64>,
}

impl Robot {
    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The model: its bodies and joints, gravity applied; a file's contact points (a URDF
    /// robot has none until one is named: [`Robot::struck_by`]).
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Whether it was read from URDF.
    pub fn is_urdf(&self) -> bool {
        self.links.is_some()
    }

    /// URDF joints that mimic another, kept as independent coordinates (as Pinocchio's URDF
    /// reader does by default).
    pub fn mimic_joints(&self) -> &[String] {
        &self.mimic_joints
    }

    /// What `contact` may name: a file's contacts; a URDF robot's links (each as `LINK`, the
    /// origin of its frame, or `LINK:x,y,z`, a point in it), in alphabetical order.
    pub fn contact_names(&self) -> Vec<&str> {
        match &self.links {
            Some(links) => links.iter().map(|l| l.link.as_str()).collect(),
            None => self
                .model
                .contacts()
                .iter()
                .map(|c| c.name.as_str())
                .collect(),
        }
    }

    /// The state by default: a file's `q` and `u`, else the neutral configuration
    /// ([`Model::neutral`]) at rest.
    pub fn default_state(&self) -> (Vec<f64>, Vec<f64>) {
        let q = self.q.clone().unwrap_or_else(|| self.model.neutral());
        let u = self.u.clone().unwrap_or_else(|| vec![0.0; self.model.nv()]);
        (q, u)
    }

    /// The floor given (the spec's `floor`, else a file's `height`), or `None`: the floor
    /// passes through the striking contact at each state.
    pub fn floor(&self) -> Option<f64> {
        self.floor
    }

    /// The model with the contact points `contact` can strike at: a URDF robot's with the
    /// one contact `LINK` or `LINK:x,y,z` (required); a file's with its own.
    ///
    /// # Errors
    /// A URDF robot without `contact`, or with an unknown link or a malformed point; a
    /// mechanism without contact points.
    pub fn struck_by(&self, contact: Option<&str>) -> Result<Model> {
        let model = match &self.links {
            Some(links) => {
                let spec = contact.ok_or_else(|| Error::Invalid {
                    field: "contact".into(),
                    reason: "which link strikes: LINK or LINK:x,y,z (a point in its frame)".into(),
                })?;
                let point = link_contact(links, &ContactSpec::parse(spec)?)?;
                self.model.clone().with_contacts(vec![point])?
            }
            None => self.model.clone(),
        };
        if model.contacts().is_empty() {
            return Err(Error::Invalid {
                field: "contact".into(),
                reason: format!("`{}` has no contact point to strike", self.name),
            });
        }
        Ok(model)
    }

    /// The index in `model` (from [`Robot::struck_by`] with the same `contact`) of the
    /// contact that strikes at the configuration `q` (checked, [`Model::check_state`]): the
    /// one named, else the lowest at `q` (the first of equals).
    ///
    /// # Errors
    /// A name that is not one of `model`'s contacts (the error lists them).
    pub fn striking_contact(
        &self,
        model: &Model,
        contact: Option<&str>,
        q: &[f64],
    ) -> Result<usize> {
        match contact {
            Some(c) => model.contact_index(c).ok_or_else(|| Error::Invalid {
                field: "contact".into(),
                reason: format!(
                    "`{c}` is not a contact of `{}` (its contacts: {})",
                    self.name,
                    model
                        .contacts()
                        .iter()
                        .map(|c| c.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            }),
            None => {
                let heights = contact_heights(model, q);
                Ok((0..heights.len())
                    .min_by(|&a, &b| heights[a].total_cmp(&heights[b]))
                    .unwrap_or(0))
            }
        }
    }

    /// The robot at the state `(q, u)` (default: [`Robot::default_state`]), struck at
    /// `contact` ([`Robot::struck_by`], [`Robot::striking_contact`]), its floor the one
    /// given or through the striking contact.
    ///
    /// # Errors
    /// As [`Robot::struck_by`] and [`Robot::striking_contact`]; `q` or `u` of the wrong
    /// length or not finite ([`Model::check_state`]) — each naming its field.
    pub fn at(
        &self,
        q: Option<&[f64]>,
        u: Option<&[f64]>,
        contact: Option<&str>,
    ) -> Result<BuiltRobot> {
        let model = self.struck_by(contact)?;
        let (q0, u0) = self.default_state();
        let q = model.check_state(q.unwrap_or(&q0), None)?;
        let u = u.map_or(u0, <[f64]>::to_vec);
        model.check_speeds(&u)?;
        let index = self.striking_contact(&model, contact, &q)?;
        let floor = match self.floor {
            Some(h) => h,
            None => contact_heights(&model, &q)[index],
        };
        Ok(BuiltRobot {
            name: self.name.clone(),
            model: model.with_floor(floor)?,
            q,
            u,
            contact: index,
            mimic_joints: self.mimic_joints.clone(),
        })
    }
}

/// The height of every contact of `model` at `q`.
fn contact_heights(model: &Model, q: &[f64]) -> Vec<f64> {
    let mut poses = vec![BodyPose::identity(); model.bodies().len()];
    forward_kinematics(model, q, &mut poses);
    (0..model.contacts().len())
        .map(|k| contact_position(model, &poses, k)[2])
        .collect()
}

/// A spatial mechanism built from its [`RobotSpec`] for its free motion, at its state
/// ([`RobotSpec::build_free`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FreeRobot {
    /// Its name.
    pub name: String,
    /// The model (its contacts, if any; the floor the file's or the spec's).
    pub model: Model,
    /// The generalized coordinates (free joints' quaternions normalised).
    pub q: Vec<f64>,
    /// The generalized velocities.
    pub u: Vec<f64>,
    /// URDF joints that mimic another, kept as independent coordinates.
    pub mimic_joints: Vec<String>,
}

impl FreeRobot {
    /// The names of the entries of `q`.
    pub fn coordinates(&self) -> &[String] {
        self.model.coordinates()
    }

    /// One line describing the mechanism: its name, base, bodies, coordinates and gravity.
    pub fn description(&self) -> String {
        describe(&self.name, &self.model, &self.mimic_joints, None)
    }
}

/// `name (floating base, 13 bodies, 19 coordinates; g = 9.81)`, with the striking contact and
/// the floor when `contact` is given, and the mimic joints.
fn describe(name: &str, model: &Model, mimic_joints: &[String], contact: Option<usize>) -> String {
    let base = match model.joints().first() {
        Some(j) if j.kind == crate::multibody::JointKind::Free => "floating base",
        _ => "fixed base",
    };
    let mut s = format!(
        "{} ({}, {} bodies, {} coordinates; g = {})",
        name,
        base,
        model.bodies().len(),
        model.nq(),
        model.gravity(),
    );
    if let Some(k) = contact {
        s.push_str(&format!(
            ": contact `{}` strikes the floor z = {:.6}",
            model.contacts()[k].name,
            model.floor(),
        ));
    }
    if !mimic_joints.is_empty() {
        s.push_str(&format!(
            "; mimic joints kept independent: {}",
            mimic_joints.join(", ")
        ));
    }
    s
}

/// A spatial mechanism built from its [`RobotSpec`], at its state.
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltRobot {
    /// Its name.
    pub name: String,
    /// The model (its floor placed).
    pub model: Model,
    /// The generalized coordinates (free joints' quaternions normalised).
    pub q: Vec<f64>,
    /// The generalized velocities.
    pub u: Vec<f64>,
    /// The striking contact (index into the model's contacts).
    pub contact: usize,
    /// URDF joints that mimic another, kept as independent coordinates (as Pinocchio's URDF
    /// reader does by default).
    pub mimic_joints: Vec<String>,
}

impl BuiltRobot {
    /// The names of the entries of `q`.
    pub fn coordinates(&self) -> &[String] {
        self.model.coordinates()
    }

    /// The impact of the striking contact at the state.
    ///
    /// # Errors
    /// As [`SpatialMechanismImpact::new`].
    pub fn impact(&self) -> Result<SpatialMechanismImpact<'_>> {
        SpatialMechanismImpact::new(&self.model, &self.q, &self.u, self.contact)
    }

    /// One line describing the case.
    pub fn description(&self) -> String {
        describe(
            &self.name,
            &self.model,
            &self.mimic_joints,
            Some(self.contact),
        )
    }

    /// Every contact's gap `φ_k = z_k − h` above the floor at the state.
    pub fn gaps(&self) -> Vec<f64> {
        let floor = self.model.floor();
        contact_heights(&self.model, &self.q)
            .into_iter()
            .map(|z| z - floor)
            .collect()
    }

    /// One line describing the mechanism for a motion (`impax simulate`): its name, base,
    /// bodies, coordinates, gravity, contacts and floor.
    pub fn motion_description(&self) -> String {
        let mut s = describe(&self.name, &self.model, &self.mimic_joints, None);
        let names: Vec<String> = self
            .model
            .contacts()
            .iter()
            .map(|c| format!("`{}`", c.name))
            .collect();
        s.push_str(&format!(
            "; contacts {} above the floor z = {:.6}",
            names.join(", "),
            self.model.floor()
        ));
        s
    }
}
