//! `impax simulate --json`: one JSON object with the scenario, the stop, the energy ledger,
//! every impact (at each of its contacts) and every event.

use super::Case;
use crate::output::json::num;
use impax::mechanism::Mechanism;
use impax::simulation::{EventKind, ImpactRecord, Run, StopReason};
use serde_json::{json, Value};

/// The stop reason and its time.
fn stop_json(stop: &StopReason, time: f64) -> Value {
    let mut v = json!({ "id": stop.id(), "time": time });
    match stop {
        StopReason::Breakdown { reason } => v["reason"] = json!(reason),
        StopReason::UnsupportedContact { contact, touching } => {
            v["contact"] = json!(contact);
            v["touching"] = json!(touching);
        }
        StopReason::Painleve { contact, solutions } => {
            v["contact"] = json!(contact);
            v["solutions"] = json!(solutions);
        }
        _ => {}
    }
    v
}

/// One entry per contact of an impact.
fn impact_contacts(m: &impax::mechanism::builtin::BuiltIn, i: &ImpactRecord) -> Vec<Value> {
    i.contacts
        .iter()
        .zip(&i.contact_velocities_before)
        .zip(&i.outcome.contacts)
        .map(|((&k, vb), c)| {
            json!({
                "contact": m.contacts()[k].name,
                "velocity_before": { "t": num(vb.x), "n": num(vb.y) },
                "velocity_after": { "t": num(c.velocity_after.x), "n": num(c.velocity_after.y) },
                "impulse": { "t": num(c.impulse.x), "n": num(c.impulse.y) },
                "work": { "compression": num(c.work.compression), "restitution": num(c.work.restitution), "friction": num(c.work.friction) },
                "phases": c.phases.iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) })).collect::<Vec<_>>(),
            })
        })
        .collect()
}

/// The document.
pub(super) fn document(case: &Case, run: &Run) -> Value {
    let m = &case.initial.mechanism;
    let impacts: Vec<Value> = run
        .impacts
        .iter()
        .map(|i| {
            let o = i.struck();
            let vb = i.contact_velocity_before();
            json!({
                "time": i.time,
                "contact": m.contacts()[i.contact].name,
                "law": i.law.as_str(),
                "contacts": impact_contacts(m, i),
                "q": i.q,
                "u_before": i.u_before,
                "u_after": i.u_after,
                "contact_velocity_before": { "t": num(vb.x), "n": num(vb.y) },
                "contact_velocity_after": { "t": num(o.velocity_after.x), "n": num(o.velocity_after.y) },
                "impulse": { "t": num(o.impulse.x), "n": num(o.impulse.y) },
                "energy_before": i.kinetic_before,
                "energy_change": num(i.energy_change),
                "energy_split": { "translational": num(i.translational_change), "rotational": num(i.rotational_change) },
                "work": { "compression": num(o.work.compression), "restitution": num(o.work.restitution), "friction": num(o.work.friction) },
                "total_energy_before": i.total_energy_before,
                "total_energy_after": i.total_energy_before + i.energy_change,
                "phases": o.phases.iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) })).collect::<Vec<_>>(),
                "verdict": i.outcome.verdict.id(),
            })
        })
        .collect();
    let name = |k: &usize| m.contacts()[*k].name;
    let events: Vec<Value> = run
        .events
        .iter()
        .filter(|(_, e)| !matches!(e, EventKind::Impact { .. }))
        .map(|(t, e)| match e {
            EventKind::Zeno {
                contact,
                limit_time,
                ratio,
            } => json!({
                "time": t, "kind": "zeno", "contact": name(contact),
                "limit_time": limit_time, "ratio": ratio,
            }),
            EventKind::Sliding => json!({ "time": t, "kind": "sliding" }),
            EventKind::Rolling => json!({ "time": t, "kind": "rolling" }),
            EventKind::Rest => json!({ "time": t, "kind": "rest" }),
            EventKind::Closes { contact, regime } => json!({
                "time": t, "kind": "closes", "contact": name(contact), "regime": regime.label(),
            }),
            EventKind::Opens { contact } => {
                json!({ "time": t, "kind": "opens", "contact": name(contact) })
            }
            EventKind::Regime { contact, regime } => json!({
                "time": t, "kind": "regime", "contact": name(contact), "regime": regime.label(),
            }),
            EventKind::Impact { .. } => unreachable!("filtered"),
        })
        .collect();
    let e0 = run.samples.first().map_or(0.0, |s| s.kinetic + s.potential);
    let e1 = run.samples.last().map_or(0.0, |s| s.kinetic + s.potential);
    let l = &run.ledger;
    json!({
        "scenario": case.name,
        "description": case.description,
        "law": case.options.law.as_str(),
        "friction": case.options.friction,
        "restitution": case.options.restitution,
        "until": case.options.until,
        "coordinates": m.coordinates(),
        "q0": case.initial.q,
        "u0": case.initial.u,
        "stop": stop_json(&run.stop, run.end_time),
        "end_time": run.end_time,
        "energy_initial": e0,
        "energy_final": e1,
        "energy_rises_at_impacts": run.impacts.iter().filter(|i| i.energy_change > 0.0).count(),
        "ledger": {
            "initial": l.initial,
            "impacts": num(l.impacts),
            "contact_work": num(l.contact_work),
            "corrections": num(l.corrections),
            "end": l.end,
            "residual": num(l.residual()),
        },
        "impacts": impacts,
        "events": events,
        "samples": run.samples.len(),
        "steps": { "accepted": run.steps.0, "rejected": run.steps.1 },
    })
}
