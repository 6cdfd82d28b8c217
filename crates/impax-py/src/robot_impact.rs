//! A state of a [`Mechanism`] struck at one contact, two ways:
//!
//! * [`record`] — `Mechanism.impact`: the command line's path and writer, step for step
//!   (`impax compare FILE --q .. --u .. --json`): a planar file built at the state by
//!   `impax::scenario::MechanismSpec`, a spatial one or a URDF robot put at it by
//!   `impax::scenario::Robot::at`; every law resolved; the document written by
//!   `impax::json::mechanism_document` / `impax::json::robot_document`;
//! * [`strike`] — `contact_problem` and every row of `impact_batch`: the description read
//!   once, the spatial model struck at the contact built once and a `Workspace` reused, so a
//!   row allocates only what one impact does. Both reduce the same model at the same state
//!   with the same functions, so a batch row equals the record's numbers bit for bit
//!   (tested).

use crate::robots::{Kind, Mechanism, Planar};
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::impact::{MechanismImpact as LibMechanismImpact, MechanismOutcome};
use impax::multibody::{
    forward_kinematics, BodyPose, Model, SpatialMechanismImpact, SpatialMechanismOutcome, Workspace,
};
use impax::scenario::{MechanismSpec, Robot};
use impax::LawId;
use std::borrow::Cow;

/// A state struck at a contact, reduced to contact space.
// One lives at a time on a worker's stack; boxing the larger variant would allocate per row.
#[allow(clippy::large_enum_variant)]
pub enum Struck<'a> {
    /// A planar mechanism file.
    Planar(LibMechanismImpact<'a, BuiltIn>),
    /// A spatial mechanism file or a URDF robot.
    Spatial(SpatialMechanismImpact<'a>),
}

/// One law's result on a struck state (the core's outcome).
pub enum Resolved {
    Planar(MechanismOutcome),
    Spatial(SpatialMechanismOutcome),
}

/// `W` (row-major, `d × d`) and `v⁻` (`d`).
pub type Reduced = (Vec<f64>, Vec<f64>);

impl Struck<'_> {
    /// `W` and `v⁻`.
    pub fn reduced(&self) -> Reduced {
        match self {
            Struck::Planar(i) => {
                let (w, v) = (i.inverse_inertia(), i.contact_velocity());
                (
                    vec![w[(0, 0)], w[(0, 1)], w[(1, 0)], w[(1, 1)]],
                    vec![v.x, v.y],
                )
            }
            Struck::Spatial(i) => {
                let (w, v) = (i.inverse_inertia(), i.contact_velocity());
                let rows = (0..3).flat_map(|r| (0..3).map(move |c| w[(r, c)]));
                (rows.collect(), vec![v.x, v.y, v.z])
            }
        }
    }

    /// Check the contact-space problem with these coefficients (as `resolve` does).
    pub fn check_problem(&self, friction: f64, restitution: f64) -> impax::Result<()> {
        match self {
            Struck::Planar(i) => i.problem(friction, restitution).map(|_| ()),
            Struck::Spatial(i) => i.problem(friction, restitution).map(|_| ()),
        }
    }

    /// `T⁻ = ½ u⁻ᵀ M u⁻`.
    pub fn energy_before(&self) -> f64 {
        match self {
            Struck::Planar(i) => i.energy_before(),
            Struck::Spatial(i) => i.energy_before(),
        }
    }

    /// Resolve with one law (the problem checked first, as the record does).
    pub fn resolve(&self, law: LawId, friction: f64, restitution: f64) -> impax::Result<Resolved> {
        Ok(match self {
            Struck::Planar(i) => {
                i.problem(friction, restitution)?;
                Resolved::Planar(i.resolve(law, friction, restitution)?)
            }
            Struck::Spatial(i) => {
                i.problem(friction, restitution)?;
                Resolved::Spatial(i.resolve(law, friction, restitution)?)
            }
        })
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
        (Kind::Spatial(s), None) => Err(impax::Error::Invalid {
            field: "contact".into(),
            reason: format!("`{}` has no contact point to strike", s.robot.name()),
        }),
    }
}

/// The record of `Mechanism.impact`: the document `impax compare ... --q Q --u U --json`
/// writes for this mechanism, contact, coefficients and laws.
///
/// # Errors
/// Every error of the state, the contact, the coefficients and the problem (not
/// approaching), each naming its field.
pub fn record(
    m: &Mechanism,
    q: &[f64],
    u: &[f64],
    contact: Option<&str>,
    friction: f64,
    restitution: f64,
    laws: &[LawId],
) -> impax::Result<serde_json::Value> {
    match &m.kind {
        Kind::Planar(p) => {
            let built = MechanismSpec {
                mechanism: m.name.clone(),
                gravity: p.gravity,
                file: Some(p.file.clone()),
                q: Some(q.to_vec()),
                u: Some(u.to_vec()),
                ..MechanismSpec::default()
            }
            .build()?;
            let impact = LibMechanismImpact::named(&built.mechanism, &built.q, &built.u, contact)?;
            let problem = impact.problem(friction, restitution)?;
            let results = laws
                .iter()
                .map(|&l| Ok((l, impact.resolve(l, friction, restitution)?)))
                .collect::<impax::Result<Vec<_>>>()?;
            Ok(impax::json::mechanism_document(
                &m.name,
                &built.description,
                &impact,
                &built.u,
                &problem,
                &results,
            ))
        }
        Kind::Spatial(s) => {
            let built = s.robot.at(Some(q), Some(u), contact)?;
            let impact = built.impact()?;
            let problem = impact.problem(friction, restitution)?;
            let results = laws
                .iter()
                .map(|&l| Ok((l, impact.resolve(l, friction, restitution)?)))
                .collect::<impax::Result<Vec<_>>>()?;
            Ok(impax::json::robot_document(
                &built, &impact, &problem, &results,
            ))
        }
    }
}

/// The gap at `q` of a spatial mechanism's contact above its floor.
pub fn spatial_gap(robot: &Robot, q: &[f64], contact: Option<&str>) -> impax::Result<f64> {
    let built = robot.at(Some(q), None, contact)?;
    let mut poses = vec![BodyPose::identity(); built.model.bodies().len()];
    forward_kinematics(&built.model, &built.q, &mut poses);
    Ok(impax::multibody::gap(&built.model, &poses, built.contact))
}
