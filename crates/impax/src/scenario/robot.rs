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
use crate::multibody::{
    contact_position, forward_kinematics, read_urdf, BodyPose, ContactSpec, Model,
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
