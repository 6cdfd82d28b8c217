//! The view with several contacts: a built-in system struck at several contacts at once
//! (the rod landing flat, the rocking block, Newton's cradle, ball–ball–wall) under every
//! multi-contact law, as `impax compare NAME` shows it, and each law's motion after the
//! impact for the animations.
//!
//! The request is [`system::MultiRequest`]; the answer:
//!
//! ```text
//! {
//!   "system", "scenario": one line, "friction", "restitution",
//!   "coordinates": ["x1", "y1", "theta1", …], "contact_names": ["balls 1–2", …],
//!   "u_before": [generalized velocities before], "energy_before": T⁻,
//!   "problem": {"contacts": K, "rank", "w": [[2K × 2K]], "v": [{"t", "n"}], "friction": [K],
//!               "restitution": [K], "stiffness": [K], "exponent"} (the command line's record),
//!   "columns": [{"key", "label", "kind": "velocity" | "impulse" | "energy"}],
//!   "results": [{
//!     "law", "verdict" (consistent | energy-gained | inconsistent-assumption | breakdown),
//!     "inconsistency": null | {"id", "message"}, "breakdown": null | {"id", "message"},
//!     "values": [one number per column] | null,
//!     "velocities_after": [n] | null, "normal_impulses": [K] | null,
//!     "contacts": [{"name", "impulse": {"t", "n"}, "velocity_after": {"t", "n"},
//!                   "phases": [{"kind", "ends_at"}], "work", "phase_summary": one line}] | null,
//!     "energy_change", "energy_after", "energy_ratio", "energy_change_from_velocities"
//!   }],
//!   "omitted": [{"law", "reason"}],     // a law that does not take this many contacts
//!   "scene": {"layout": "floor" | "row" | "wall", "gravity", "bodies": [{"shape", …,
//!             "position", "angle", "velocity"}]},
//!   "animation": {"window": seconds, "frames": 120, "motion": {law: {"poses": [[[x, y, θ]]],
//!                 "end": {"id", "time", "text"}}}}
//! }
//! ```
//!
//! The columns are the generalized velocities after that move (before, or after under some
//! law: a cradle's vertical velocities and spins stay zero, as in `impax compare`'s table),
//! each contact's normal impulse, `ΔT` and `T⁺/T⁻`. The numbers are the core's
//! ([`impax::multi::MultiImpact::resolve`]); [`motion`] says how the motion after is made.

pub mod motion;
pub mod system;

use crate::report::num;
use impax::law::Breakdown;
use impax::multi::{MultiOutcome, SystemOutcome};
use impax::LawId;
use motion::Motion;
use serde_json::{json, Map, Value};
use system::{named, MultiRequest, System};

/// Answer a request of the view with several contacts.
///
/// # Errors
/// One line naming the field: the request's (see [`system`]), no contact approaching,
/// friction or restitution out of range.
pub fn answer(request: &MultiRequest) -> Result<Value, String> {
    let system = request.system()?;
    let impact = &system.scenario.impact;
    let problem = impact
        .problem(&[system.friction], &[system.restitution])
        .map_err(|e| match e {
            impax::Error::NotApproaching { .. } => not_approaching(&system),
            other => named(other),
        })?;
    let mut resolved: Vec<(LawId, SystemOutcome)> = Vec::new();
    let mut omitted = Vec::new();
    for law in LawId::MULTI_CONTACT {
        match impact.resolve(law, &problem) {
            Ok(r) => resolved.push((law, r)),
            // A law that does not take this many contacts (lcp: 4^K modes).
            Err(e) if e.field() == "law" => {
                omitted.push(json!({ "law": law.as_str(), "reason": e.to_string() }))
            }
            Err(e) => return Err(named(e)),
        }
    }
    let shown = shown(&system, &resolved);
    let columns = columns(&system, &shown);
    let t0 = impact.energy_before();
    let names = impact.contacts();
    let results: Vec<Value> = resolved
        .iter()
        .map(|(law, r)| match (&r.resolution, &r.velocities_after) {
            (Ok(o), Some(u)) => outcome(o, u, r, &shown, t0, names),
            (Err(b), _) => broken(b),
            (Ok(_), None) => broken_without_velocities(*law),
        })
        .collect();
    let motions: Vec<(LawId, Motion, &[f64])> = resolved
        .iter()
        .filter_map(|(law, r)| {
            let u = r.velocities_after.as_deref()?;
            r.resolution.as_ref().ok()?;
            Some((*law, motion::after(&system, *law, u), u))
        })
        .collect();
    let plain: Vec<Motion> = motions.iter().map(|(_, m, _)| m.clone()).collect();
    let afters: Vec<&[f64]> = motions.iter().map(|(_, _, u)| *u).collect();
    let window = motion::window(&system, &plain, &afters);
    let motion: Map<String, Value> = motions
        .iter()
        .map(|(law, m, _)| (law.as_str().to_string(), m.to_json(window)))
        .collect();
    Ok(json!({
        "system": system.scenario.name,
        "scenario": system.scenario.description,
        "friction": system.friction,
        "restitution": system.restitution,
        "coordinates": impact.coordinates(),
        "contact_names": names,
        "u_before": impact.velocities_before().iter().map(|&x| num(x)).collect::<Vec<_>>(),
        "energy_before": t0,
        "problem": impax::json::multi_problem(&problem),
        "columns": columns,
        "results": results,
        "omitted": omitted,
        "scene": system.scene_json(),
        "animation": { "window": window, "frames": motion::FRAMES, "motion": motion },
    }))
}

/// The rod's message when no end comes down (as `impax compare rod-flat` says it).
fn not_approaching(system: &System) -> String {
    let v = system.scenario.impact.contact_velocities();
    match system.scenario.name {
        "rod-flat" => format!(
            "vy, omega: no end of the rod comes down (normal velocities {} and {}): `rod-flat` strikes only while an end approaches the floor",
            short(v[1]),
            short(v[3])
        ),
        name => format!("{name}: no contact approaches"),
    }
}

/// Six significant digits.
fn short(x: f64) -> String {
    let v: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    format!("{v}")
}

/// The coordinates worth a column (`impax compare`'s rule): those moving before, or after
/// under some law beyond `1e-12` of the fastest velocity before.
fn shown(system: &System, resolved: &[(LawId, SystemOutcome)]) -> Vec<usize> {
    let before = system.scenario.impact.velocities_before();
    let scale = before.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    (0..before.len())
        .filter(|&i| {
            before[i] != 0.0
                || resolved.iter().any(|(_, r)| {
                    r.velocities_after
                        .as_ref()
                        .is_some_and(|u| u[i].abs() > 1e-12 * scale)
                })
        })
        .collect()
}

/// A coordinate's velocity as the table labels it: `x1` → `ẋ₁⁺`, `theta` → `θ̇⁺`.
pub fn velocity_label(coordinate: &str) -> String {
    let digits = coordinate.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    let name = &coordinate[..coordinate.len() - digits.len()];
    let dotted = match name {
        "x" => "ẋ".to_string(),
        "y" => "ẏ".to_string(),
        "theta" => "θ̇".to_string(),
        other => format!("{other}\u{307}"),
    };
    let sub: String = digits
        .chars()
        .map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c))
        .collect();
    format!("{dotted}{sub}⁺")
}

fn columns(system: &System, shown: &[usize]) -> Vec<Value> {
    let impact = &system.scenario.impact;
    let coords = impact.coordinates();
    let mut out: Vec<Value> = shown
        .iter()
        .map(|&i| json!({ "key": coords[i], "label": velocity_label(&coords[i]), "kind": "velocity" }))
        .collect();
    for (j, name) in impact.contacts().iter().enumerate() {
        out.push(json!({ "key": format!("pn{}", j + 1), "label": format!("pₙ {name}"), "kind": "impulse" }));
    }
    out.push(json!({ "key": "dT", "label": "ΔT", "kind": "energy" }));
    out.push(json!({ "key": "ratio", "label": "T⁺/T⁻", "kind": "energy" }));
    out
}

fn outcome(
    o: &MultiOutcome,
    u: &[f64],
    r: &SystemOutcome,
    shown: &[usize],
    t0: f64,
    names: &[String],
) -> Value {
    let normal: Vec<f64> = o.contacts.iter().map(|c| c.impulse.y).collect();
    let ratio = (t0 + o.energy_change) / t0;
    let mut values: Vec<Value> = shown.iter().map(|&i| num(u[i])).collect();
    values.extend(normal.iter().map(|&p| num(p)));
    values.extend([num(o.energy_change), num(ratio)]);
    // Each contact as the command line writes it ([`impax::json::multi_outcome`]), with its
    // name and its phases in one line for the table.
    let mut contacts = impax::json::multi_outcome(o)["contacts"].take();
    for ((c, name), out) in o.contacts.iter().zip(names).zip(
        contacts
            .as_array_mut()
            .expect("the record's contacts")
            .iter_mut(),
    ) {
        out["name"] = json!(name);
        out["phase_summary"] = json!(c.phase_summary());
    }
    json!({
        "law": o.law.as_str(),
        "verdict": o.verdict.id(),
        "inconsistency": o.inconsistency.map_or(Value::Null, |i| json!({ "id": i.id(), "message": i.to_string() })),
        "breakdown": null,
        "values": values,
        "velocities_after": u.iter().map(|&x| num(x)).collect::<Vec<_>>(),
        "normal_impulses": normal.iter().map(|&x| num(x)).collect::<Vec<_>>(),
        "contacts": contacts,
        "energy_change": num(o.energy_change),
        "energy_after": num(t0 + o.energy_change),
        "energy_ratio": num(ratio),
        "energy_change_from_velocities": r.energy_change_from_velocities.map_or(Value::Null, num),
    })
}

fn broken(b: &Breakdown) -> Value {
    let mut v = broken_without_velocities(b.law);
    v["breakdown"] = json!({ "id": b.reason.id(), "message": b.reason.to_string() });
    v
}

fn broken_without_velocities(law: LawId) -> Value {
    json!({
        "law": law.as_str(),
        "verdict": "breakdown",
        "inconsistency": null,
        "breakdown": { "id": "no-velocities", "message": "no velocities after" },
        "values": null,
        "velocities_after": null,
        "normal_impulses": null,
        "contacts": null,
        "energy_change": null,
        "energy_after": null,
        "energy_ratio": null,
        "energy_change_from_velocities": null,
    })
}
