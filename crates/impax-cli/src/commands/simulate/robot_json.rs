//! `impax simulate ROBOT --json`: the planar run's keys where they mean the same (`scenario`,
//! `description`, `law`, `friction`, `restitution`, `until`, `coordinates`, `q0`, `u0`,
//! `stop`, `end_time`, `energy_initial`, `energy_final`, `energy_rises_at_impacts`, `ledger`,
//! `impacts`, `events`, `samples`, `steps`), vectors as `{t1, t2, n}`, and the spatial
//! mechanism's own (`speeds`, `mimic_joints`, `floor`, `gravity`, `contacts` with their gaps
//! at the start, the ledger's measured `drift`, `quaternion_drift`).

use super::robot::RobotRun;
use crate::output::json::{self, num};
use impax::multibody::simulate::{ImpactRecord, Persistence, StopReason};
use impax::simulation::EventKind;
use serde_json::{json, Value};

/// The stop: `id`, `time`, and its contact by name, the persistence's `cause`, the
/// breakdown's `reason`, the contacts `touching`.
fn stop_json(r: &RobotRun) -> Value {
    let name = |k: usize| r.built.model.contacts()[k].name.clone();
    let mut v = json!({ "id": r.run.stop.id(), "time": r.run.end_time });
    match &r.run.stop {
        StopReason::Breakdown { reason } => v["reason"] = json!(reason),
        StopReason::UnsupportedContact { contact, touching } => {
            v["contact"] = json!(name(*contact));
            v["touching"] = json!(touching.iter().map(|&k| name(k)).collect::<Vec<_>>());
        }
        StopReason::PersistentContact { contact, cause } => {
            v["contact"] = json!(name(*contact));
            let mut c = json!({ "id": cause.id() });
            match cause {
                Persistence::LowBounce { height } => c["height"] = num(*height),
                Persistence::Accumulation { limit_time, ratio } => {
                    c["limit_time"] = num(*limit_time);
                    c["ratio"] = num(*ratio);
                }
                Persistence::Closed | Persistence::Pressed => {}
            }
            v["cause"] = c;
        }
        StopReason::TimeLimit | StopReason::ImpactLimit => {}
    }
    v
}

/// One impact: the struck contact's keys at the top (as in the plane), every contact of the
/// impact in `contacts`.
fn impact_json(r: &RobotRun, i: &ImpactRecord) -> Value {
    let name = |k: usize| r.built.model.contacts()[k].name.clone();
    let contacts: Vec<Value> = i
        .contacts
        .iter()
        .zip(&i.contact_velocities_before)
        .zip(&i.outcome.contacts)
        .map(|((&k, vb), c)| {
            let mut e = json::multi3_contact(c);
            e["contact"] = json!(name(k));
            e["velocity_before"] = json::vec3(*vb);
            e
        })
        .collect();
    let o = i.struck();
    let struck = json::multi3_contact(o);
    json!({
        "time": i.time,
        "contact": name(i.contact),
        "law": i.law.as_str(),
        "contacts": contacts,
        "q": i.q,
        "u_before": i.u_before,
        "u_after": i.u_after,
        "contact_velocity_before": json::vec3(i.contact_velocity_before()),
        "contact_velocity_after": json::vec3(o.velocity_after),
        "impulse": json::vec3(o.impulse),
        "energy_before": i.kinetic_before,
        "energy_change": num(i.energy_change),
        "law_energy_change": num(i.law_energy_change),
        "work": struck["work"],
        "total_energy_before": i.total_energy_before,
        "total_energy_after": i.total_energy_before + i.energy_change,
        "phases": struck["phases"],
        "verdict": i.outcome.verdict.id(),
    })
}

/// The document.
pub(super) fn document(r: &RobotRun) -> Value {
    let (run, built, o) = (&r.run, &r.built, &r.options);
    let model = &built.model;
    let events: Vec<Value> = run
        .events
        .iter()
        .filter_map(|(t, e)| match e {
            EventKind::Zeno {
                contact,
                limit_time,
                ratio,
            } => Some(json!({
                "time": t, "kind": "zeno", "contact": model.contacts()[*contact].name,
                "limit_time": limit_time, "ratio": ratio,
            })),
            _ => None,
        })
        .collect();
    let gaps: Vec<Value> = model
        .contacts()
        .iter()
        .zip(built.gaps())
        .map(|(c, g)| json!({ "name": c.name, "gap": num(g) }))
        .collect();
    let l = &run.ledger;
    json!({
        "scenario": built.name,
        "description": built.motion_description(),
        "law": o.law.as_str(),
        "friction": o.friction,
        "restitution": o.restitution,
        "until": o.until,
        "coordinates": built.coordinates(),
        "speeds": model.speeds(),
        "mimic_joints": built.mimic_joints,
        "q0": built.q,
        "u0": built.u,
        "floor": model.floor(),
        "gravity": model.gravity(),
        "contacts": gaps,
        "stop": stop_json(r),
        "end_time": run.end_time,
        "energy_initial": l.initial,
        "energy_final": l.end,
        "energy_rises_at_impacts": run.impacts.iter().filter(|i| i.energy_change > 0.0).count(),
        "ledger": {
            "initial": l.initial,
            "impacts": num(l.impacts),
            "drift": num(l.drift),
            "end": l.end,
            "residual": num(l.residual()),
        },
        "impacts": run.impacts.iter().map(|i| impact_json(r, i)).collect::<Vec<_>>(),
        "events": events,
        "samples": run.samples.len(),
        "steps": { "accepted": run.steps.0, "rejected": run.steps.1 },
        "quaternion_drift": num(run.quaternion_drift),
    })
}
