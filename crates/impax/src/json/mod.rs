//! JSON records of outcomes, the one writer of the command line and the explorer (feature
//! `json`): every key is a documented contract (the book's reference, "JSON output"), so the
//! front ends write outcomes only through these functions and add only their own keys.

use crate::law::WorkSplit;
use crate::math::{Vec2, Vec3};
use crate::multi::spatial as multi3;
use crate::multi::{ContactPhase, MultiDetail, MultiOutcome, MultiProblem, MultiResolution};
use crate::planar::bodies::BodyOutcome;
use crate::planar::{Breakdown, ContactProblem, LawDetail, Outcome, SmithReading};
use crate::spatial::{self, PhaseKind};
use serde_json::{json, Map, Value};

mod mechanism;
pub use mechanism::{
    conserved, mechanism_document, mechanism_entry, mechanism_result, quantity, robot_document,
    robot_result,
};

/// JSON numbers: `-0` printed as `0`.
pub fn num(x: f64) -> Value {
    json!(if x == 0.0 { 0.0 } else { x })
}

/// The JSON `detail` of a planar one-contact outcome (null for a law without one).
pub fn detail(d: &LawDetail) -> Value {
    match *d {
        LawDetail::None => Value::Null,
        LawDetail::TwoPhase { switch_impulse } => json!({ "switch_impulse": switch_impulse }),
        LawDetail::Smith {
            eta,
            roots,
            reading,
        } => json!({
            "eta": eta,
            "roots": roots,
            "reading": match reading {
                SmithReading::SlipVelocity => "slip-velocity",
                SmithReading::CentreVelocity => "centre-velocity",
            },
        }),
        LawDetail::Brach { ratio, capped } => json!({ "ratio": ratio, "capped": capped }),
        LawDetail::DarbouxKeller { slip_halt } => json!({ "slip_halt": slip_halt }),
        LawDetail::Lcp {
            ratio,
            consistent_candidates,
        } => json!({ "ratio": ratio, "consistent_candidates": consistent_candidates }),
    }
}

/// The contact-space fields of an outcome; `velocity_key` names the after-velocity field.
pub fn outcome_fields(o: &Outcome, velocity_key: &str) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("law".into(), json!(o.law.as_str()));
    m.insert("verdict".into(), json!(o.verdict.id()));
    m.insert(
        "impulse".into(),
        json!({ "t": num(o.impulse.x), "n": num(o.impulse.y) }),
    );
    m.insert(
        velocity_key.into(),
        json!({ "t": num(o.velocity_after.x), "n": num(o.velocity_after.y) }),
    );
    m.insert(
        "compression_impulse".into(),
        o.compression_impulse.map_or(Value::Null, num),
    );
    m.insert("work".into(), work_split(&o.work));
    m.insert("energy_change".into(), num(o.energy_change));
    m.insert(
        "phases".into(),
        Value::Array(
            o.phases
                .as_slice()
                .iter()
                .map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) }))
                .collect(),
        ),
    );
    m.insert(
        "inconsistency".into(),
        o.inconsistency.map_or(
            Value::Null,
            |i| json!({ "id": i.id(), "message": i.to_string() }),
        ),
    );
    m.insert("detail".into(), detail(&o.detail));
    m
}

/// A breakdown entry: the law, `verdict = "breakdown"`, the reason, and every number null.
pub fn breakdown_fields(b: &Breakdown, velocity_key: &str, body: bool) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("law".into(), json!(b.law.as_str()));
    m.insert("verdict".into(), json!("breakdown"));
    m.insert(
        "breakdown".into(),
        json!({ "id": b.reason.id(), "message": b.reason.to_string() }),
    );
    let mut keys = vec![
        "impulse",
        velocity_key,
        "compression_impulse",
        "work",
        "energy_change",
        "inconsistency",
        "detail",
    ];
    if body {
        keys.extend(["body_velocity_after", "energy_change_ratio", "energy_split"]);
    }
    for k in keys {
        m.insert(k.into(), Value::Null);
    }
    m.insert("phases".into(), json!([]));
    m
}

/// A `compare` entry for one law applied to a body scenario.
pub fn body_entry(r: &BodyOutcome, t0: f64, two_bodies: bool) -> Value {
    let mut m = outcome_fields(&r.outcome, "contact_velocity_after");
    let state = |s: &crate::planar::bodies::BodyState| json!({ "vx": num(s.velocity.x), "vy": num(s.velocity.y), "omega": num(s.omega) });
    m.insert("body_velocity_after".into(), state(&r.body_after));
    if two_bodies {
        m.insert(
            "other_body_velocity_after".into(),
            r.other_after.as_ref().map_or(Value::Null, state),
        );
    }
    m.insert(
        "energy_change_ratio".into(),
        num(r.outcome.energy_change / t0),
    );
    m.insert(
        "energy_split".into(),
        json!({
            "translational": num(r.energy_change.translational),
            "rotational": num(r.energy_change.rotational),
        }),
    );
    Value::Object(m)
}

/// The contact-space problem as JSON.
pub fn problem(p: &ContactProblem) -> Value {
    json!({
        "w": [[p.wtt(), p.wtn()], [p.wtn(), p.wnn()]],
        "v": { "t": num(p.velocity().x), "n": num(p.velocity().y) },
        "friction": p.friction(),
        "restitution": p.restitution(),
    })
}

// Several contacts at once (`impax resolve --contacts`, the multi-contact built-ins).

/// `{t, n}`.
pub fn vec2(v: Vec2) -> Value {
    json!({ "t": num(v.x), "n": num(v.y) })
}

fn multi_phases(list: &[ContactPhase]) -> Value {
    Value::Array(
        list.iter()
            .map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) }))
            .collect(),
    )
}

/// A work split as JSON: `{compression, restitution, friction}`.
fn work_split(w: &WorkSplit) -> Value {
    json!({
        "compression": num(w.compression),
        "restitution": num(w.restitution),
        "friction": num(w.friction),
    })
}

/// The problem as JSON: `contacts`, `w` (2K × 2K), `v` (one `{t, n}` per contact),
/// `friction`, `restitution` (K each), `rank`.
pub fn multi_problem(p: &MultiProblem) -> Value {
    let k = p.contacts();
    let w = p.w();
    json!({
        "contacts": k,
        "w": (0..2 * k).map(|i| (0..2 * k).map(|j| num(w[(i, j)])).collect::<Vec<_>>()).collect::<Vec<_>>(),
        "v": (0..k).map(|j| vec2(p.contact_velocity(j))).collect::<Vec<_>>(),
        "friction": (0..k).map(|j| p.friction(j)).collect::<Vec<_>>(),
        "restitution": (0..k).map(|j| p.restitution(j)).collect::<Vec<_>>(),
        "stiffness": (0..k).map(|j| p.stiffness(j)).collect::<Vec<_>>(),
        "exponent": p.exponent(),
        "rank": p.rank(),
    })
}

/// One law's entry: `law`, `verdict`, `contacts`, `energy_change`, `inconsistency`,
/// `breakdown`, `detail` (every number null when the law broke down).
pub fn multi_entry(r: &MultiResolution) -> Value {
    match r {
        Ok(o) => multi_outcome(o),
        Err(b) => broken_entry(b),
    }
}

/// The entry of a multi-contact law that resolved ([`multi_entry`]).
pub fn multi_outcome(o: &MultiOutcome) -> Value {
    entry_of(
        o.law,
        o.verdict,
        o.contacts
            .iter()
            .map(|c| {
                contact_of(
                    vec2(c.impulse),
                    vec2(c.velocity_after),
                    multi_phases(&c.phases),
                    &c.work,
                )
            })
            .collect(),
        o.energy_change,
        o.inconsistency,
        multi_detail(o),
    )
}

/// One contact's object: `impulse`, `velocity_after`, `phases`, `work`.
fn contact_of(impulse: Value, velocity_after: Value, phases: Value, work: &WorkSplit) -> Value {
    json!({
        "impulse": impulse,
        "velocity_after": velocity_after,
        "phases": phases,
        "work": work_split(work),
    })
}

/// A multi-contact law's entry, planar or spatial.
fn entry_of(
    law: crate::LawId,
    verdict: crate::law::Verdict,
    contacts: Vec<Value>,
    energy_change: f64,
    inconsistency: Option<crate::law::Inconsistency>,
    detail: Value,
) -> Value {
    json!({
        "law": law.as_str(),
        "verdict": verdict.id(),
        "contacts": contacts,
        "energy_change": num(energy_change),
        "inconsistency": inconsistency.map_or(Value::Null, |i| json!({ "id": i.id(), "message": i.to_string() })),
        "breakdown": Value::Null,
        "detail": detail,
    })
}

/// The entry of a multi-contact law that broke down: every number null.
fn broken_entry(b: &Breakdown) -> Value {
    json!({
        "law": b.law.as_str(),
        "verdict": "breakdown",
        "contacts": Value::Null,
        "energy_change": Value::Null,
        "inconsistency": Value::Null,
        "breakdown": { "id": b.reason.id(), "message": b.reason.to_string() },
        "detail": Value::Null,
    })
}

/// `lcp`: `solutions` (each `energy_change` and per contact `kind`, `impulse`,
/// `velocity_after`; least kinetic energy after first). `sequential`: `impacts` (each
/// `contact`, counted from 1, `velocity_before`, `impulse`, `velocity_after`, `phases`,
/// `energy_change`). A one-contact law (K = 1): its own detail.
fn multi_detail(o: &MultiOutcome) -> Value {
    match &o.detail {
        MultiDetail::Lcp { solutions } => json!({
            "solutions": solutions.iter().map(|s| json!({
                "energy_change": num(s.energy_change),
                "contacts": (0..s.regimes.len()).map(|j| json!({
                    "kind": s.regimes[j].label(),
                    "impulse": vec2(s.impulses[j]),
                    "velocity_after": vec2(s.velocities_after[j]),
                })).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
        }),
        MultiDetail::Sequential { impacts } => json!({
            "impacts": impacts.iter().map(|b| json!({
                "contact": b.contact + 1,
                "velocity_before": vec2(b.velocity_before),
                "impulse": vec2(b.outcome.impulse),
                "velocity_after": vec2(b.outcome.velocity_after),
                "phases": Value::Array(b.outcome.phases.as_slice().iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) })).collect()),
                "energy_change": num(b.outcome.energy_change),
            })).collect::<Vec<_>>(),
        }),
        MultiDetail::Lzb { primaries, steps } => json!({
            "primaries": primaries.iter().map(|p| json!({
                "contact": p.contact + 1,
                "impulse": num(p.impulse),
            })).collect::<Vec<_>>(),
            "steps": steps,
        }),
        MultiDetail::OneContact { detail, .. } => self::detail(detail),
    }
}

// In 3D (`impax resolve` with a 3 × 3 W, or `--contacts K` with a 3K × 3K W; `box-flat`).

/// `{t1, t2, n}`.
pub fn vec3(v: Vec3) -> Value {
    json!({ "t1": num(v.x), "t2": num(v.y), "n": num(v.z) })
}

/// The JSON fields of a spatial one-contact outcome: `law`, `verdict`, `impulse`,
/// `velocity_after` (`{t1, t2, n}`), `compression_impulse`, `work`, `energy_change`, `phases`,
/// `inconsistency`, `detail`.
pub fn spatial_outcome_fields(o: &spatial::Outcome) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("law".into(), json!(o.law.as_str()));
    m.insert("verdict".into(), json!(o.verdict.id()));
    m.insert("impulse".into(), vec3(o.impulse));
    m.insert("velocity_after".into(), vec3(o.velocity_after));
    m.insert(
        "compression_impulse".into(),
        o.compression_impulse.map_or(Value::Null, num),
    );
    m.insert("work".into(), work_split(&o.work));
    m.insert("energy_change".into(), num(o.energy_change));
    let phases: Vec<Value> = o
        .phases
        .as_slice()
        .iter()
        .map(|ph| phase3(ph.kind, ph.ends_at))
        .collect();
    m.insert("phases".into(), Value::Array(phases));
    m.insert(
        "inconsistency".into(),
        o.inconsistency.map_or(
            Value::Null,
            |i| json!({ "id": i.id(), "message": i.to_string() }),
        ),
    );
    m.insert("detail".into(), detail3(&o.detail));
    m
}

/// The JSON fields of a spatial one-contact breakdown: the outcome's keys null (`phases`
/// empty), `verdict` `breakdown` and `breakdown` `{id, message}`.
pub fn spatial_breakdown_fields(b: &Breakdown) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("law".into(), json!(b.law.as_str()));
    m.insert("verdict".into(), json!("breakdown"));
    m.insert(
        "breakdown".into(),
        json!({ "id": b.reason.id(), "message": b.reason.to_string() }),
    );
    for k in [
        "impulse",
        "velocity_after",
        "compression_impulse",
        "work",
        "energy_change",
        "inconsistency",
        "detail",
    ] {
        m.insert(k.into(), Value::Null);
    }
    m.insert("phases".into(), json!([]));
    m
}

/// The JSON of a spatial problem: `w` (3 × 3, rows), `v` (`{t1, t2, n}`), `friction`,
/// `restitution`.
pub fn spatial_problem(p: &spatial::ContactProblem) -> Value {
    let w = p.w();
    json!({
        "w": (0..3).map(|i| (0..3).map(|j| num(w[(i, j)])).collect::<Vec<_>>()).collect::<Vec<_>>(),
        "v": vec3(p.velocity()),
        "friction": p.friction(),
        "restitution": p.restitution(),
    })
}

/// A spatial phase: `kind`, `ends_at`, and `from_deg`, `to_deg` (slip) or `angle_deg`
/// (resumed slip).
pub fn phase3(kind: PhaseKind, ends_at: f64) -> Value {
    let mut e = json!({ "kind": kind.label(), "ends_at": num(ends_at) });
    match kind {
        PhaseKind::Slip { from, to } => {
            e["from_deg"] = json!(from.to_degrees());
            e["to_deg"] = json!(to.to_degrees());
        }
        PhaseKind::Resumed { angle } => e["angle_deg"] = json!(angle.to_degrees()),
        _ => {}
    }
    e
}

/// A spatial law's `detail`.
pub fn detail3(d: &spatial::LawDetail) -> Value {
    match *d {
        spatial::LawDetail::None => Value::Null,
        spatial::LawDetail::Brach { ratio, capped } => json!({ "ratio": ratio, "capped": capped }),
        spatial::LawDetail::Lcp { solutions } => json!({ "solutions": solutions }),
        spatial::LawDetail::DarbouxKeller {
            slip_halt,
            second_compression,
            steps,
        } => json!({
            "slip_halt": slip_halt,
            "second_compression": second_compression,
            "steps": steps,
        }),
    }
}

fn multi3_phases(list: &[multi3::ContactPhase]) -> Value {
    Value::Array(
        list.iter()
            .map(|p| match p.kind {
                multi3::ContactPhaseKind::Off => {
                    json!({ "kind": "off", "ends_at": num(p.ends_at) })
                }
                multi3::ContactPhaseKind::Impact(k) => phase3(k, p.ends_at),
            })
            .collect(),
    )
}

/// One contact of a spatial impact at several contacts: `impulse`, `velocity_after`
/// (`{t1, t2, n}`), `phases` (as [`phase3`], `off` where it had no impulse), `work`
/// (`compression`, `restitution`, `friction`) — the objects of [`multi3_entry`]'s `contacts`.
pub fn multi3_contact(c: &multi3::ContactResult) -> Value {
    contact_of(
        vec3(c.impulse),
        vec3(c.velocity_after),
        multi3_phases(&c.phases),
        &c.work,
    )
}

/// The spatial problem with `K` contacts: `contacts`, `w` (3K × 3K), `v` (one `{t1, t2, n}`
/// per contact), `friction`, `restitution`, `stiffness` (K each), `exponent`, `rank`.
pub fn multi3_problem(p: &multi3::MultiProblem) -> Value {
    let k = p.contacts();
    let w = p.w();
    json!({
        "contacts": k,
        "w": (0..3 * k).map(|i| (0..3 * k).map(|j| num(w[(i, j)])).collect::<Vec<_>>()).collect::<Vec<_>>(),
        "v": (0..k).map(|j| vec3(p.contact_velocity(j))).collect::<Vec<_>>(),
        "friction": (0..k).map(|j| p.friction(j)).collect::<Vec<_>>(),
        "restitution": (0..k).map(|j| p.restitution(j)).collect::<Vec<_>>(),
        "stiffness": (0..k).map(|j| p.stiffness(j)).collect::<Vec<_>>(),
        "exponent": p.exponent(),
        "rank": p.rank(),
    })
}

/// One spatial law's entry with `K` contacts: the keys of [`multi_entry`], vectors as
/// `{t1, t2, n}`.
pub fn multi3_entry(r: &multi3::MultiResolution) -> Value {
    match r {
        Ok(o) => entry_of(
            o.law,
            o.verdict,
            o.contacts.iter().map(multi3_contact).collect(),
            o.energy_change,
            o.inconsistency,
            multi3_detail(o),
        ),
        Err(b) => broken_entry(b),
    }
}

/// `lcp`: `solutions` (each `energy_change` and per contact `kind`, `slip_angle_deg` for a
/// slip, `impulse`, `velocity_after`); `sequential`: `impacts` (as in the plane, vectors
/// `{t1, t2, n}`); one contact: the law's own detail.
fn multi3_detail(o: &multi3::MultiOutcome) -> Value {
    match &o.detail {
        multi3::MultiDetail::Lcp { solutions } => json!({
            "solutions": solutions.iter().map(|s| json!({
                "energy_change": num(s.energy_change),
                "contacts": (0..s.regimes.len()).map(|j| {
                    let mut e = json!({
                        "kind": s.regimes[j].label(),
                        "impulse": vec3(s.impulses[j]),
                        "velocity_after": vec3(s.velocities_after[j]),
                    });
                    if let multi3::ContactPhaseKind::Impact(PhaseKind::Slip { to, .. }) = s.regimes[j] {
                        e["slip_angle_deg"] = json!(to.to_degrees());
                    }
                    e
                }).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
        }),
        multi3::MultiDetail::Sequential { impacts } => json!({
            "impacts": impacts.iter().map(|b| json!({
                "contact": b.contact + 1,
                "velocity_before": vec3(b.velocity_before),
                "impulse": vec3(b.outcome.impulse),
                "velocity_after": vec3(b.outcome.velocity_after),
                "phases": Value::Array(b.outcome.phases.as_slice().iter().map(|p| phase3(p.kind, p.ends_at)).collect()),
                "energy_change": num(b.outcome.energy_change),
            })).collect::<Vec<_>>(),
        }),
        multi3::MultiDetail::Lzb { primaries, steps } => json!({
            "primaries": primaries.iter().map(|p| json!({
                "contact": p.contact + 1,
                "impulse": num(p.impulse),
            })).collect::<Vec<_>>(),
            "steps": steps,
        }),
        multi3::MultiDetail::OneContact { detail, .. } => detail3(detail),
    }
}
