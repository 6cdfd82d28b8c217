//! The answer to a compare request: every law's result, Routh's diagram, the energy bars and
//! the animation frames, as JSON for the page.
//!
//! ```text
//! {
//!   "kind": "body" | "mechanism",
//!   "scenario": one line,
//!   "problem": {"w": [[W_tt, W_tn], [W_tn, W_nn]], "v": {"t", "n"}, "friction", "restitution"},
//!   "energy_before", "t0",
//!   "columns": [{"key", "label"}],       // the table's numeric columns, in order
//!   "results": [{
//!     "law", "verdict" (consistent | energy-gained | inconsistent-assumption | breakdown),
//!     "inconsistency": null | {"id", "message"}, "breakdown": null | {"id", "message"},
//!     "values": [one number per column] | null,
//!     "impulse": {"t", "n"}, "contact_velocity_after": {"t", "n"},
//!     "body_velocity_after": {"vx", "vy", "omega"}      (body)
//!     "velocities_after": [θ̇₁, θ̇₂]                       (mechanism)
//!     "energy_change", "energy_change_ratio",
//!     "energy": {"normal", "friction", "translational", "rotational"}  // each / T0
//!     "phases": [{"kind", "ends_at"}], "path": [[p_t, p_n], …]
//!   }],
//!   "routh": {"friction", "restitution", "lines": [{"id", "label", "coef": [u, v, w]}]},
//!   "threshold": null | {"upper", "lower", "edge"},  // Whittaker's γ*₊, γ*₋ and −sin α for a
//!                                                     // sphere (paper A eq. 13)
//!   "animation": {"duration", "shapes", "pins", "before", "after": {law: frames}}
//! }
//! ```
//!
//! Numbers are those of the library (`-0` written as `0`); a law that breaks down has
//! `values = null` and no path. The body's velocities are normalised by `v0` and `ω` by
//! `v0/ρ` in `values`, as in `impax compare`'s table for round bodies.

use crate::animation::{self, Outline};
use crate::case::{BodyCase, Case, MechanismCase, Request};
use impax::mechanism::{Mechanism, Pose};
use impax::planar::{Breakdown, ContactProblem, Outcome};
use impax::scenario::Shape;
use impax::LawId;
use serde_json::{json, Map, Value};

pub use impax::json::num;

/// Answer a compare request.
///
/// # Errors
/// The request's case or problem is invalid (one line naming the field).
pub fn compare(request: &Request) -> Result<Value, String> {
    match request.case()? {
        Case::Body(b) => body(&b, request.friction, request.restitution),
        Case::Mechanism(m) => mechanism(&m, request.friction, request.restitution),
    }
}

/// The outcome's record as the command line writes it ([`impax::json::outcome_fields`]),
/// with `breakdown` (null) and the impulse `path` for the drawing.
fn common(o: &Outcome, problem: &ContactProblem) -> Map<String, Value> {
    let mut m = impax::json::outcome_fields(o, "contact_velocity_after");
    m.insert("breakdown".into(), Value::Null);
    m.insert(
        "path".into(),
        Value::Array(
            o.impulse_path(problem)
                .iter()
                .map(|p| json!([num(p.x), num(p.y)]))
                .collect(),
        ),
    );
    m
}

fn broken(b: &Breakdown) -> Value {
    json!({
        "law": b.law.as_str(),
        "verdict": "breakdown",
        "inconsistency": null,
        "breakdown": { "id": b.reason.id(), "message": b.reason.to_string() },
        "values": null,
        "energy_change": null,
        "energy_change_ratio": null,
        "energy": null,
        "phases": [],
        "path": [],
    })
}

/// The straight lines of Routh's diagram, `u p_t + v p_n = w`.
fn routh(p: &ContactProblem) -> Value {
    let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
    let v = p.velocity();
    let e = p.restitution();
    json!({
        "friction": p.friction(),
        "restitution": e,
        "lines": [
            { "id": "stick", "label": "sticking: v_t = 0", "coef": [a, b, -v.x] },
            { "id": "compression", "label": "maximum compression: v_n = 0", "coef": [b, c, -v.y] },
            { "id": "newton", "label": format!("Newton restitution: v_n = −e v_n⁻ (e = {e})"),
              "coef": [b, c, -(1.0 + e) * v.y] },
        ],
    })
}

fn body(case: &BodyCase, friction: f64, restitution: f64) -> Result<Value, String> {
    let problem = case.problem(friction, restitution)?;
    let t0 = case.t0();
    let (v0, rho) = (case.speed, case.length_scale);
    let results: Vec<Value> = LawId::ALL
        .iter()
        .map(|&law| match case.impact.resolve(law, &problem) {
            Ok(b) => {
                let o = &b.outcome;
                let mut m = common(o, &problem);
                let s = b.body_after;
                m.insert(
                    "body_velocity_after".into(),
                    json!({ "vx": num(s.velocity.x), "vy": num(s.velocity.y), "omega": num(s.omega) }),
                );
                m.insert(
                    "values".into(),
                    json!([
                        num(s.velocity.x / v0),
                        num(s.velocity.y / v0),
                        num(s.omega * rho / v0),
                        num(o.velocity_after.x / v0),
                        num(o.energy_change / t0),
                    ]),
                );
                m.insert("energy_change_ratio".into(), num(o.energy_change / t0));
                m.insert(
                    "energy".into(),
                    json!({
                        "normal": num(o.work.normal() / t0),
                        "friction": num(o.work.friction / t0),
                        "translational": num(b.energy_change.translational / t0),
                        "rotational": num(b.energy_change.rotational / t0),
                    }),
                );
                Value::Object(m)
            }
            Err(b) => broken(&b),
        })
        .collect();
    let threshold = if case.shape == Shape::Sphere {
        let t = impax::analysis::whittaker_sphere_thresholds(
            case.alpha_deg.to_radians(),
            restitution,
            friction,
        );
        let edge = -case.alpha_deg.to_radians().sin();
        json!({ "upper": t.upper.map(num), "lower": t.lower.map(num), "edge": num(edge) })
    } else {
        Value::Null
    };
    Ok(json!({
        "kind": "body",
        "scenario": case.description,
        "problem": impax::json::problem(&problem),
        "energy_before": case.impact.energy_before().total(),
        "t0": t0,
        "columns": [
            { "key": "vx", "label": "vx⁺/v0" },
            { "key": "vy", "label": "vy⁺/v0" },
            { "key": "omega", "label": "ω⁺ρ/v0" },
            { "key": "vt", "label": "vt⁺/v0" },
            { "key": "dT", "label": "ΔT/T0" },
        ],
        "results": results,
        "routh": routh(&problem),
        "threshold": threshold,
        "animation": body_animation(case, &problem),
    }))
}

/// The body's outline in its own frame at the instant of impact: the shapes the page draws
/// as they are, any other as a rigid body (its contact point and radius of gyration).
fn body_outline(case: &BodyCase) -> Outline {
    let spec = &case.spec;
    let body = case.impact.body.0;
    let direction = spec.angle_unit.to_radians(spec.angle.unwrap_or(0.0));
    match case.shape {
        Shape::Sphere | Shape::Disc => Outline::Circle {
            radius: spec.radius.unwrap_or(0.0),
        },
        Shape::Rod => Outline::Segment {
            half_length: 0.5 * spec.length.unwrap_or(0.0),
            direction,
        },
        Shape::Ellipse => {
            let [a, b] = spec.semi_axes.unwrap_or([0.0, 0.0]);
            Outline::Ellipse { a, b, direction }
        }
        _ => Outline::Rigid {
            contact: [body.contact().x, body.contact().y],
            gyration: (body.inertia() / body.mass()).sqrt(),
        },
    }
}

fn body_animation(case: &BodyCase, problem: &ContactProblem) -> Value {
    let rho = case.length_scale;
    let before = case.state();
    let outline = [body_outline(case)];
    let c0 = -case.impact.body.0.contact();
    let mut states = vec![(None, before)];
    for &law in LawId::ALL.iter() {
        if let Ok(b) = case.impact.resolve(law, problem) {
            states.push((Some(law), b.body_after));
        }
    }
    // The centre travels 2.5 ρ before the impact, and a body that is not round turns by at
    // most about half a radian in either half (the spin of a round one shows on its radius).
    let speed = before.velocity.norm().max(1e-300);
    let fastest = states
        .iter()
        .map(|(_, s)| s.omega.abs())
        .fold(0.0, f64::max);
    let mut duration = 2.5 * rho / speed;
    if !matches!(outline[0], Outline::Circle { .. }) {
        duration = duration.min(0.5 / fastest.max(1e-300));
    }
    let frames = |s: &impax::planar::bodies::BodyState, approach: bool| {
        animation::to_json(&animation::half(&outline, duration, approach, |t| {
            vec![[
                c0.x + s.velocity.x * t,
                c0.y + s.velocity.y * t,
                s.omega * t,
            ]]
        }))
    };
    let mut after = Map::new();
    for (law, s) in &states {
        if let Some(law) = law {
            after.insert(law.as_str().into(), frames(s, false));
        }
    }
    json!({
        "duration": duration,
        "shapes": [outline[0].to_json()],
        "pins": [],
        "before": frames(&before, true),
        "after": after,
    })
}

fn mechanism(case: &MechanismCase, friction: f64, restitution: f64) -> Result<Value, String> {
    let impact = case.impact()?;
    let problem = impact
        .problem(friction, restitution)
        .map_err(|e| e.to_string())?;
    let t0 = impact.energy_before();
    let laws = LawId::CONTACT_SPACE;
    let mut after = Map::new();
    let mut results = Vec::new();
    for &law in laws.iter() {
        let r = impact
            .resolve(law, friction, restitution)
            .map_err(|e| e.to_string())?;
        match (&r.resolution, &r.velocities_after) {
            (Ok(o), Some(u)) => {
                let mut m = common(o, &problem);
                m.insert(
                    "velocities_after".into(),
                    Value::Array(u.iter().map(|&x| num(x)).collect()),
                );
                let ratio = (t0 + o.energy_change) / t0;
                m.insert(
                    "values".into(),
                    json!([
                        num(u[0]),
                        num(u[1]),
                        num(o.velocity_after.x),
                        num(o.velocity_after.y),
                        num(o.energy_change / t0),
                        num(ratio),
                    ]),
                );
                m.insert("energy_change_ratio".into(), num(o.energy_change / t0));
                m.insert("energy_ratio".into(), num(ratio));
                m.insert(
                    "energy".into(),
                    json!({
                        "normal": num(o.work.normal() / t0),
                        "friction": num(o.work.friction / t0),
                        "translational": null,
                        "rotational": null,
                    }),
                );
                after.insert(law.as_str().into(), pendulum_frames(case, u, false));
                results.push(Value::Object(m));
            }
            (Err(b), _) => results.push(broken(b)),
            (Ok(_), None) => return Err(format!("{law}: no velocities after the impact")),
        }
    }
    Ok(json!({
        "kind": "mechanism",
        "scenario": case.description,
        "problem": impax::json::problem(&problem),
        "energy_before": t0,
        "t0": t0,
        "columns": [
            { "key": "u1", "label": "θ̇₁⁺ (rad/s)" },
            { "key": "u2", "label": "θ̇₂⁺ (rad/s)" },
            { "key": "vt", "label": "vt⁺" },
            { "key": "vn", "label": "vn⁺" },
            { "key": "dT", "label": "ΔT/T⁻" },
            { "key": "ratio", "label": "T⁺/T⁻" },
        ],
        "results": results,
        "routh": routh(&problem),
        "threshold": null,
        "animation": {
            "duration": pendulum_duration(case),
            "shapes": pendulum_outlines(case).map(Outline::to_json),
            "pins": [pin(case)],
            "before": pendulum_frames(case, &case.u, true),
            "after": after,
        },
    }))
}

fn pendulum_duration(case: &MechanismCase) -> f64 {
    let fastest = case.u[0].abs().max(case.u[1].abs()).max(1e-300);
    0.35 / fastest
}

/// The pin, in the frame whose origin is the tip at the impact (the floor is `y = 0`).
fn pin(case: &MechanismCase) -> Value {
    let tip = case.pendulum.contact_point(0, &case.q);
    json!([num(-tip[0]), num(-tip[1])])
}

fn pendulum_outlines(case: &MechanismCase) -> [Outline; 2] {
    // A rod's pose angle is θ from the downward vertical: its direction is θ − π/2.
    let down = -std::f64::consts::FRAC_PI_2;
    case.pendulum.lengths().map(|l| Outline::Segment {
        half_length: 0.5 * l,
        direction: down,
    })
}

/// Poses of both rods at `q + u t` (velocities held: the impact is instantaneous), over
/// the approach (t from −τ to 0) or the rebound (t from 0 to τ).
fn pendulum_frames(case: &MechanismCase, u: &[f64], approach: bool) -> Value {
    let tau = pendulum_duration(case);
    let tip = case.pendulum.contact_point(0, &case.q);
    let outlines = pendulum_outlines(case);
    animation::to_json(&animation::half(&outlines, tau, approach, |t| {
        let mut poses = [Pose::new(0.0, 0.0, 0.0); 2];
        let q = [case.q[0] + u[0] * t, case.q[1] + u[1] * t];
        case.pendulum.poses(&q, &mut poses);
        poses
            .iter()
            .map(|p| [p.x - tip[0], p.y - tip[1], p.angle])
            .collect()
    }))
}
