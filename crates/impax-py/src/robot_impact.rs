//! One state of a [`Mechanism`] struck at one contact — the one path that `impact`,
//! `contact_problem` and every row of `impact_batch` take, so that a batch row equals the
//! single call bit for bit.
//!
//! * planar: the linkage with its floor placed at the state (unless given), struck at the
//!   named contact or the one that strikes (`MechanismImpact::named`);
//! * spatial: `q` checked (quaternions normalised, [`Model::check_state`]), the contact
//!   chosen ([`impax::scenario::Robot::striking_contact`]) and the impact reduced to contact
//!   space by `SpatialMechanismImpact` on the model struck at that contact — exactly what
//!   `BuiltRobot::impact` (the command line) does, the floor aside (it moves no number but
//!   the gap).

use crate::outcome::{Context, Outcome, Raw};
use crate::robots::{Kind, Mechanism, Planar};
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::impact::MechanismImpact as LibMechanismImpact;
use impax::multibody::{forward_kinematics, BodyPose, Model, SpatialMechanismImpact, Workspace};
use impax::scenario::Robot;
use impax::{spatial, LawId};
use std::borrow::Cow;

/// A state struck at a contact, reduced to contact space.
pub enum Struck<'a> {
    /// A planar mechanism file.
    Planar(LibMechanismImpact<'a, BuiltIn>),
    /// A spatial mechanism file or a URDF robot.
    Spatial(SpatialMechanismImpact<'a>),
}

/// One law's result on a struck state: the record's numbers.
pub struct Row {
    pub law: LawId,
    pub raw: Raw,
    pub approach_energy: f64,
    pub velocities_after: Option<Vec<f64>>,
    pub energy_before: f64,
    pub energy_change_from_velocities: Option<f64>,
    pub problem3: Option<spatial::ContactProblem>,
}

impl Row {
    /// The record `impact` returns.
    pub fn into_outcome(self) -> Outcome {
        Outcome {
            law: self.law,
            context: Context::Mechanism {
                velocities_after: self.velocities_after,
                energy_before: self.energy_before,
                energy_change_from_velocities: self.energy_change_from_velocities,
                spatial: matches!(self.raw, Raw::Spatial(_)),
            },
            raw: self.raw,
            approach_energy: self.approach_energy,
            problem3: self.problem3,
        }
    }
}

impl Struck<'_> {
    /// `W` (row-major, `d × d`) and `v⁻` (`d`).
    pub fn reduced(&self) -> (Vec<f64>, Vec<f64>) {
        match self {
            Struck::Planar(i) => {
                let (w, v) = (i.inverse_inertia(), i.contact_velocity());
                (vec![w[(0, 0)], w[(0, 1)], w[(1, 0)], w[(1, 1)]], vec![v.x, v.y])
            }
            Struck::Spatial(i) => {
                let (w, v) = (i.inverse_inertia(), i.contact_velocity());
                let rows = (0..3).flat_map(|r| (0..3).map(move |c| w[(r, c)]));
                (rows.collect(), vec![v.x, v.y, v.z])
            }
        }
    }

    /// Check the contact-space problem with these coefficients (as `resolve` would).
    pub fn check_problem(&self, friction: f64, restitution: f64) -> impax::Result<()> {
        match self {
            Struck::Planar(i) => i.problem(friction, restitution).map(|_| ()),
            Struck::Spatial(i) => i.problem(friction, restitution).map(|_| ()),
        }
    }

    /// Resolve with one law: the contact-space outcome, `u⁺` and the energies.
    pub fn resolve(&self, law: LawId, friction: f64, restitution: f64) -> impax::Result<Row> {
        match self {
            Struck::Planar(i) => {
                let problem = i.problem(friction, restitution)?;
                let r = i.resolve(law, friction, restitution)?;
                Ok(Row {
                    law,
                    raw: Raw::Planar(r.resolution),
                    approach_energy: problem.approach_energy(),
                    velocities_after: r.velocities_after,
                    energy_before: i.energy_before(),
                    energy_change_from_velocities: r.energy_change_from_velocities,
                    problem3: None,
                })
            }
            Struck::Spatial(i) => {
                let problem = i.problem(friction, restitution)?;
                let r = i.resolve(law, friction, restitution)?;
                Ok(Row {
                    law,
                    raw: Raw::Spatial(r.resolution),
                    approach_energy: problem.approach_energy(),
                    velocities_after: r.velocities_after,
                    energy_before: i.energy_before(),
                    energy_change_from_velocities: r.energy_change_from_velocities,
                    problem3: Some(problem),
                })
            }
        }
    }
}

/// The planar linkage at `q`: its floor through its lowest contact there, unless given.
///
/// # Errors
/// `q` of the wrong length or not finite.
pub fn placed<'a>(p: &'a Planar, q: &[f64]) -> impax::Result<Cow<'a, BuiltIn>> {
    if p.floor_given {
        return Ok(Cow::Borrowed(&p.mechanism));
    }
    let mut m = p.mechanism.clone();
    m.place_floor(q)?;
    Ok(Cow::Owned(m))
}

/// `f(struck)` at `(q, u)` struck at `contact`: `model` is the spatial model struck at it
/// ([`crate::robots::Spatial::model`]), `workspace` a reusable one for it (taken and given
/// back).
pub fn strike<R>(
    m: &Mechanism,
    model: Option<&Model>,
    workspace: &mut Option<Workspace>,
    q: &[f64],
    u: &[f64],
    contact: Option<&str>,
    f: impl FnOnce(&Struck<'_>) -> impax::Result<R>,
) -> impax::Result<R> {
    match (&m.kind, model) {
        (Kind::Planar(p), _) => {
            let mechanism = placed(p, q)?;
            let impact = LibMechanismImpact::named(&*mechanism, q, u, contact)?;
            f(&Struck::Planar(impact))
        }
        (Kind::Spatial(s), Some(model)) => {
            let q = model.check_state(q, None)?;
            let k = s.robot.striking_contact(model, contact, &q)?;
            let ws = workspace.take().unwrap_or_else(|| Workspace::new(model));
            let struck = Struck::Spatial(SpatialMechanismImpact::new_in(model, &q, u, k, ws)?);
            let r = f(&struck);
            if let Struck::Spatial(i) = struck {
                *workspace = Some(i.into_workspace());
            }
            r
        }
        (Kind::Spatial(_), None) => unreachable!("a spatial mechanism is struck on its model"),
    }
}

/// The gap at `q` of a spatial mechanism's contact above its floor.
pub fn spatial_gap(robot: &Robot, q: &[f64], contact: Option<&str>) -> impax::Result<f64> {
    let built = robot.at(Some(q), None, contact)?;
    let mut poses = vec![BodyPose::identity(); built.model.bodies().len()];
    forward_kinematics(&built.model, &built.q, &mut poses);
    Ok(impax::multibody::gap(&built.model, &poses, built.contact))
}
