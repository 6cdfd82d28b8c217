//! JSON records of outcomes (the schema is documented in the book, docs/src/reference/json.md).

use impax::bodies::BodyOutcome;
use impax::law::WorkSplit;
use impax::math::Vec2;
use impax::multi::{ContactPhase, MultiDetail, MultiOutcome, MultiProblem, MultiResolution};
use impax::planar::{Breakdown, ContactProblem, LawDetail, Outcome, SmithReading};
use serde_json::{json, Map, Value};

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
    m.insert(
        "work".into(),
        json!({
            "compression": num(o.work.compression),
            "restitution": num(o.work.restitution),
            "friction": num(o.work.friction),
        }),
    );
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
    let state = |s: &impax::bodies::BodyState2| json!({ "vx": num(s.velocity.x), "vy": num(s.velocity.y), "omega": num(s.omega) });
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

fn multi_work(w: &WorkSplit) -> Value {
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
        Ok(o) => json!({
            "law": o.law.as_str(),
            "verdict": o.verdict.id(),
            "contacts": o.contacts.iter().map(|c| json!({
                "impulse": vec2(c.impulse),
                "velocity_after": vec2(c.velocity_after),
                "phases": multi_phases(&c.phases),
                "work": multi_work(&c.work),
            })).collect::<Vec<_>>(),
            "energy_change": num(o.energy_change),
            "inconsistency": o.inconsistency.map_or(Value::Null, |i| json!({ "id": i.id(), "message": i.to_string() })),
            "breakdown": Value::Null,
            "detail": multi_detail(o),
        }),
        Err(b) => json!({
            "law": b.law.as_str(),
            "verdict": "breakdown",
            "contacts": Value::Null,
            "energy_change": Value::Null,
            "inconsistency": Value::Null,
            "breakdown": { "id": b.reason.id(), "message": b.reason.to_string() },
            "detail": Value::Null,
        }),
    }
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
