//! The view of conserved quantities (paper B): a built-in mechanism moving freely — the
//! ring-pendulum, or the cart-pendulum as the contrast — and what the core's tracker
//! ([`impax::mechanism::conserved::track`]) reports along the motion, as
//! `impax conserved NAME --json` does, with every quantity's values over time and the poses
//! of the bodies for the animation.
//!
//! A request: the built-in's description as a file's `mechanism` table spells it
//! ([`MechanismSpec`]: `mechanism`, `masses`, `lengths`, `radius`, `gravity`, `angles_deg`,
//! `rates`, `position`, or `q` and `u`) and the run's options `duration` (s, default 10),
//! `samples` (intervals, default 1000, at most 20,000), `tolerance` (default 1e-8) and `about`
//! (the points of the angular momenta, default the origin) — the command line's defaults:
//!
//! ```json
//! {"mechanism": "ring-pendulum", "masses": [1, 1], "lengths": [1], "radius": 1,
//!  "angles_deg": [30], "position": [0], "rates": [0.5, 0], "duration": 10}
//! ```
//!
//! The answer is the document of `impax conserved NAME --json` ([`impax::json::conserved`])
//! with the page's keys:
//!
//! ```text
//! "tolerances": {"relative", "absolute"},     // the integrator's (Dormand–Prince 5(4))
//! "times": [t0, t1, …],                       // the sample times
//! "quantities": [{ …, "values": [Q(t0), Q(t1), …], "verdict": one phrase }],
//! "scene": null | {"bodies": [{"name", "shape": "ring" | "cart" | "bob", "radius"}],
//!                  "arm": [from, to] (body indices), "floor": height},
//! "poses": [[[x, y, θ] per body] per sample]
//! ```

use impax::math::Vec2;
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::conserved::{track, TrackOptions, Tracking};
use impax::mechanism::{Mechanism, Pose};
use impax::ode::Tolerances;
use impax::scenario::MechanismSpec;
use serde_json::{json, Map, Value};

use crate::report::num;

/// The systems the view offers: the ring-pendulum of paper B and the cart-pendulum.
pub const SYSTEMS: [&str; 2] = ["ring-pendulum", "cart-pendulum"];

/// The systems the view offers with their parameters at the core's defaults, read off the
/// mechanism the core builds from the name alone (`masses`, `lengths`, `radius` for the
/// ring, `position`, `angles_deg`, `rates`): the page's sliders start there.
pub fn systems_json() -> Value {
    let mut out = Map::new();
    for name in SYSTEMS {
        let spec = MechanismSpec {
            mechanism: name.into(),
            ..MechanismSpec::default()
        };
        let Ok(case) = spec.build() else { continue };
        let m = &case.mechanism;
        let (radius, length) = match m {
            BuiltIn::RingPendulum(r) => (Some(r.radius()), r.length()),
            BuiltIn::CartPendulum(c) => (None, c.length()),
            _ => continue,
        };
        let masses: Vec<f64> = m.bodies().iter().map(|b| b.mass).collect();
        // The angle in degrees as a slider shows it: 30° is 0.5235987755982988 rad, which
        // converts back to 30.000000000000004 (a host test checks the round trip builds the
        // same state).
        let degrees = (case.q[1].to_degrees() * 1e9).round() / 1e9;
        let mut d = json!({
            "masses": masses, "lengths": [length], "position": [case.q[0]],
            "angles_deg": [degrees], "rates": case.u,
        });
        if let Some(r) = radius {
            d["radius"] = json!(r);
        }
        out.insert(name.into(), d);
    }
    Value::Object(out)
}

/// The largest number of sample intervals a request may ask for.
pub const MAX_SAMPLES: usize = 20_000;

/// The run's options, taken out of the request.
struct Run {
    duration: f64,
    samples: usize,
    tolerance: f64,
    about: Vec<Vec2>,
}

/// Split a request into the mechanism's description and the run's options.
fn split(request: &str) -> Result<(MechanismSpec, Run), String> {
    let mut v: Map<String, Value> =
        serde_json::from_str(request).map_err(|e| format!("request: {e}"))?;
    let mut number = |key: &str, default: f64| -> Result<f64, String> {
        match v.remove(key) {
            None | Some(Value::Null) => Ok(default),
            Some(x) => x
                .as_f64()
                .ok_or_else(|| format!("{key}: must be a number, got {x}")),
        }
    };
    let duration = number("duration", 10.0)?;
    let samples = number("samples", 1000.0)?;
    let tolerance = number("tolerance", 1e-8)?;
    if !(duration.is_finite() && duration > 0.0 && duration <= 1e4) {
        return Err(format!(
            "duration: must be positive and at most 10⁴ s, got {duration}"
        ));
    }
    if !(samples >= 1.0 && samples <= MAX_SAMPLES as f64 && samples.fract() == 0.0) {
        return Err(format!(
            "samples: must be a whole number from 1 to {MAX_SAMPLES}, got {samples}"
        ));
    }
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
        return Err(format!("tolerance: must be in (0, 1), got {tolerance}"));
    }
    let about: Vec<[f64; 2]> = match v.remove("about") {
        None | Some(Value::Null) => vec![[0.0, 0.0]],
        Some(a) => serde_json::from_value(a).map_err(|e| format!("about: {e}"))?,
    };
    let spec: MechanismSpec =
        serde_json::from_value(Value::Object(v)).map_err(|e| format!("request: {e}"))?;
    for (field, given) in [
        ("friction", spec.friction.is_some()),
        ("restitution", spec.restitution.is_some()),
        ("laws", spec.laws.is_some()),
    ] {
        if given {
            return Err(format!(
                "{field}: not used here (the motion is free; no impact)"
            ));
        }
    }
    let run = Run {
        duration,
        samples: samples as usize,
        tolerance,
        about: about.into_iter().map(|[x, y]| Vec2::new(x, y)).collect(),
    };
    Ok((spec, run))
}

/// Answer a request of the view of conserved quantities.
///
/// # Errors
/// One line naming the field: the request's, the mechanism's parameters or state, or a failed
/// integration.
pub fn answer(request: &str) -> Result<Value, String> {
    let (spec, run) = split(request)?;
    let case = spec.build().map_err(|e| e.to_string())?;
    let options = TrackOptions {
        duration: run.duration,
        intervals: run.samples,
        tolerances: Tolerances::TIGHT,
    };
    let symmetries = case.mechanism.symmetries();
    let tracking = track(
        &case.mechanism,
        &case.q,
        &case.u,
        &symmetries,
        &run.about,
        options,
    )
    .map_err(|e| e.to_string())?;
    let mut doc = impax::json::conserved(
        &spec.mechanism,
        &case,
        &tracking,
        run.tolerance,
        run.duration,
    );
    for (q, t) in doc["quantities"]
        .as_array_mut()
        .expect("quantities")
        .iter_mut()
        .zip(&tracking.tracks)
    {
        q["values"] = t.values.iter().map(|&x| num(x)).collect();
        q["verdict"] = json!(t.verdict(run.tolerance));
    }
    doc["tolerances"] = json!({
        "relative": options.tolerances.relative,
        "absolute": options.tolerances.absolute,
    });
    doc["times"] = json!(tracking.times);
    doc["scene"] = scene(&case.mechanism);
    doc["poses"] = poses(&case.mechanism, &tracking);
    Ok(doc)
}

/// What the page draws: the ring (its radius) or the cart, and the bob on its arm.
fn scene(m: &BuiltIn) -> Value {
    match m {
        BuiltIn::RingPendulum(r) => json!({
            "bodies": [{ "name": "ring", "shape": "ring", "radius": r.radius() },
                       { "name": "bob", "shape": "bob" }],
            "arm": [0, 1], "length": r.length(), "floor": 0.0,
        }),
        BuiltIn::CartPendulum(c) => json!({
            "bodies": [{ "name": "cart", "shape": "cart" }, { "name": "bob", "shape": "bob" }],
            "arm": [0, 1], "length": c.length(), "floor": 0.0,
        }),
        _ => Value::Null,
    }
}

/// The bodies' poses at the sample times: the mechanism's kinematics at the coordinates the
/// tracker recorded along its motion.
fn poses(m: &BuiltIn, tracking: &Tracking) -> Value {
    let mut pose = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
    tracking
        .positions
        .iter()
        .map(|q| {
            m.poses(q, &mut pose);
            pose.iter()
                .map(|p| json!([num(p.x), num(p.y), num(p.angle)]))
                .collect::<Vec<_>>()
        })
        .collect()
}
