//! The documents of a mechanism: every law on the impact of a planar mechanism (a built-in or
//! a mechanism file) or of a spatial one (a robot from URDF, a `space = "3d"` file), and the
//! quantities tracked along a planar mechanism's free motion. `impax compare MECHANISM --json`,
//! `impax compare ROBOT --json`, `impax conserved --json` and the explorer write these.
//!
//! ```
//! use impax::mechanism::impact::MechanismImpact;
//! use impax::scenario::MechanismSpec;
//! use impax::LawId;
//! let spec = MechanismSpec { mechanism: "double-pendulum".into(), ..MechanismSpec::default() };
//! let case = spec.build()?;
//! let impact = MechanismImpact::striking(&case.mechanism, &case.q, &case.u)?;
//! let problem = impact.problem(0.5, 0.5)?;
//! let results = vec![(LawId::Whittaker, impact.resolve(LawId::Whittaker, 0.5, 0.5)?)];
//! let doc = impax::json::mechanism_document(
//!     "double-pendulum", &case.description, &impact, &case.u, &problem, &results,
//! );
//! assert_eq!(doc["contact"], "tip of rod 2");
//! let ratio = doc["results"][0]["energy_ratio"].as_f64().unwrap();
//! assert!((ratio - 1.26087).abs() < 5e-6); // Kane's paradox: Whittaker's rule gains energy
//! # Ok::<(), impax::Error>(())
//! ```

use super::{
    breakdown_fields, num, outcome_fields, problem, spatial_breakdown_fields,
    spatial_outcome_fields, spatial_problem,
};
use crate::mechanism::conserved::{QuantityKind, Track, Tracking};
use crate::mechanism::impact::{MechanismImpact, MechanismOutcome};
use crate::mechanism::Mechanism;
use crate::multibody::{SpatialMechanismImpact, SpatialMechanismOutcome};
use crate::planar::ContactProblem;
use crate::scenario::{BuiltMechanism, BuiltRobot};
use crate::spatial;
use crate::LawId;
use serde_json::{json, Map, Value};

/// The keys a mechanism's impact adds to a law's entry (`fields`: the outcome's or the
/// breakdown's): `velocities_after` (`u⁺`), `energy_after` and `energy_ratio` (of the energy
/// before `t0`), `energy_change_from_velocities` — all null when the law broke down
/// (`applied` is `None`).
pub fn mechanism_entry(
    mut fields: Map<String, Value>,
    t0: f64,
    applied: Option<(f64, &[f64], Option<f64>)>,
) -> Value {
    match applied {
        Some((energy_change, after, from_velocities)) => {
            fields.insert(
                "velocities_after".into(),
                json!(after.iter().map(|&x| num(x)).collect::<Vec<_>>()),
            );
            fields.insert("energy_after".into(), num(t0 + energy_change));
            fields.insert("energy_ratio".into(), num((t0 + energy_change) / t0));
            fields.insert(
                "energy_change_from_velocities".into(),
                from_velocities.map_or(Value::Null, num),
            );
        }
        None => {
            for k in [
                "velocities_after",
                "energy_after",
                "energy_ratio",
                "energy_change_from_velocities",
            ] {
                fields.insert(k.into(), Value::Null);
            }
        }
    }
    Value::Object(fields)
}

/// One law's entry on a planar mechanism: the contact-space record
/// ([`outcome_fields`], the velocity after as `contact_velocity_after`) with
/// `velocities_after`, `energy_after`, `energy_ratio` and `energy_change_from_velocities`
/// (each null when the law broke down). `t0` is the kinetic energy before.
pub fn mechanism_result(r: &MechanismOutcome, t0: f64) -> Value {
    match &r.resolution {
        Ok(o) => mechanism_entry(
            outcome_fields(o, "contact_velocity_after"),
            t0,
            Some((
                o.energy_change,
                r.velocities_after.as_deref().unwrap_or_default(),
                r.energy_change_from_velocities,
            )),
        ),
        Err(b) => mechanism_entry(
            breakdown_fields(b, "contact_velocity_after", false),
            t0,
            None,
        ),
    }
}

/// The document of `impax compare MECHANISM --json` for a planar mechanism (a built-in or a
/// mechanism file) struck at one contact: `mechanism` (its name), `scenario` (the built
/// mechanism's description), `coordinates`, `q`, `u_before`, `contact`, `gap`, `problem`,
/// `energy_before` and `results` (one [`mechanism_result`] per law, in the order given).
pub fn mechanism_document<M: Mechanism + ?Sized>(
    name: &str,
    description: &str,
    impact: &MechanismImpact<'_, M>,
    u: &[f64],
    contact_problem: &ContactProblem,
    results: &[(LawId, MechanismOutcome)],
) -> Value {
    let m = impact.mechanism();
    let t0 = impact.energy_before();
    let entries: Vec<Value> = results
        .iter()
        .map(|(_, r)| mechanism_result(r, t0))
        .collect();
    json!({
        "mechanism": name,
        "scenario": description,
        "coordinates": m.coordinates(),
        "q": impact.configuration(),
        "u_before": u,
        "contact": m.contacts()[impact.contact()].name,
        "gap": num(impact.gap()),
        "problem": problem(contact_problem),
        "energy_before": t0,
        "results": entries,
    })
}

/// One law's entry on a spatial mechanism: the spatial record
/// ([`spatial_outcome_fields`]) with `velocities_after`, `energy_after`, `energy_ratio` and
/// `energy_change_from_velocities` (null when the law broke down).
pub fn robot_result(r: &SpatialMechanismOutcome, t0: f64) -> Value {
    match &r.resolution {
        Ok(o) => mechanism_entry(
            spatial_outcome_fields(o),
            t0,
            Some((
                o.energy_change,
                r.velocities_after.as_deref().unwrap_or_default(),
                r.energy_change_from_velocities,
            )),
        ),
        Err(b) => mechanism_entry(spatial_breakdown_fields(b), t0, None),
    }
}

/// The document of `impax compare ROBOT --json` for a spatial mechanism (a URDF robot or a
/// `space = "3d"` mechanism file) at its state: `mechanism`, `scenario` (its description),
/// `coordinates`, `speeds`, `mimic_joints`, `q`, `u_before`, `contact`, `gap`, `problem`,
/// `energy_before` and `results` (one [`robot_result`] per law, in the order given).
pub fn robot_document(
    built: &BuiltRobot,
    impact: &SpatialMechanismImpact<'_>,
    problem_: &spatial::ContactProblem,
    results: &[(LawId, SpatialMechanismOutcome)],
) -> Value {
    let t0 = impact.energy_before();
    let entries: Vec<Value> = results.iter().map(|(_, r)| robot_result(r, t0)).collect();
    json!({
        "mechanism": built.name,
        "scenario": built.description(),
        "coordinates": built.coordinates(),
        "speeds": built.model.speeds(),
        "mimic_joints": built.mimic_joints,
        "q": built.q,
        "u_before": built.u,
        "contact": built.model.contacts()[built.contact].name,
        "gap": num(impact.gap()),
        "problem": spatial_problem(problem_),
        "energy_before": num(t0),
        "results": entries,
    })
}

/// One tracked quantity: `name`, `kind` ([`Track::kind_id`]), `description`, `initial`,
/// `final`, `largest_deviation`, `relative_deviation`, `magnitude`, `conserved` (at
/// `tolerance`), and by kind `coordinate` and `cyclic`, `about`, `axis` or `symmetry_check`
/// (`holds`, `variation`, `gauge_rate`).
pub fn quantity(t: &Track, coordinates: &[&str], tolerance: f64) -> Value {
    let mut q = json!({
        "name": t.name,
        "kind": t.kind_id(),
        "description": t.description(coordinates),
        "initial": num(t.initial()),
        "final": num(*t.values.last().expect("samples")),
        "largest_deviation": num(t.largest_deviation()),
        "relative_deviation": num(t.relative_deviation()),
        "magnitude": num(t.magnitude),
        "conserved": t.conserved(tolerance),
    });
    match &t.kind {
        QuantityKind::GeneralizedMomentum { coordinate, cyclic } => {
            q["coordinate"] = json!(coordinates[*coordinate]);
            q["cyclic"] = json!(cyclic);
        }
        QuantityKind::AngularMomentum { about } => q["about"] = json!([about.x, about.y]),
        QuantityKind::LinearMomentum { axis } => {
            q["axis"] = json!(if *axis == 0 { "x" } else { "y" })
        }
        QuantityKind::Noether { check } => {
            q["symmetry_check"] = json!({
                "holds": check.holds(),
                "variation": num(check.variation),
                "gauge_rate": num(check.gauge_rate),
            })
        }
        QuantityKind::Energy => {}
    }
    q
}

/// The quantities along a planar mechanism's free motion (`impax conserved --json`):
/// `mechanism` (`name`), `scenario`, `coordinates`, `q`, `u`, `duration`, `samples`,
/// `tolerance`, `steps` (`accepted`, `rejected`), `cyclic` (the cyclic coordinates' names)
/// and `quantities` ([`quantity`] each).
pub fn conserved(
    name: &str,
    case: &BuiltMechanism,
    tracking: &Tracking,
    tolerance: f64,
    duration: f64,
) -> Value {
    let coords = case.mechanism.coordinates();
    let quantities: Vec<Value> = tracking
        .tracks
        .iter()
        .map(|t| quantity(t, coords, tolerance))
        .collect();
    json!({
        "mechanism": name,
        "scenario": case.description,
        "coordinates": coords,
        "q": case.q,
        "u": case.u,
        "duration": duration,
        "samples": tracking.times.len(),
        "tolerance": tolerance,
        "steps": { "accepted": tracking.steps.0, "rejected": tracking.steps.1 },
        "cyclic": tracking.cyclic.iter().map(|&i| coords[i]).collect::<Vec<_>>(),
        "quantities": quantities,
    })
}
