//! The view "Your mechanism": a mechanism file pasted into the page (planar, or
//! `space = "3d"`), at its own state or at the page's `q` and `u`, struck at the contact that
//! strikes, under every law — the numbers of `impax compare FILE --json`.
//!
//! A request:
//!
//! ```json
//! {"file": "…the TOML text…", "q": [0.5236, -0.5236], "u": [-1, 3],
//!  "friction": 0.5, "restitution": 0.5}
//! ```
//!
//! `q`, `u`, `friction` and `restitution` are optional (null or absent): the file's, else
//! zero (a free joint's quaternion 1) and 0.5. The answer is the document of
//! `impax compare FILE --json` ([`impax::json::mechanism_document`] in the plane,
//! [`impax::json::robot_document`] in space) with the page's keys:
//!
//! ```text
//! "space": "2d" | "3d", "friction", "restitution",
//! "speeds": [names of the entries of u],
//! "rows": [{"key", "label", "kind": "velocity" | "contact" | "impulse" | "energy",
//!           "before": number | null}],            // the table's rows, in order
//! "results": [{ …, "values": [one number per row] | null, "phase_summary": one line }]
//! ```
//!
//! A file that does not read or build, a state of the wrong length or a contact that cannot
//! strike is answered with one line saying where: `line 27: joint[theta2].parent: …`
//! ([`impax::scenario::file_error_message`]).

use impax::mechanism::impact::MechanismImpact;
use impax::mechanism::Mechanism;
use impax::multibody::SpatialMechanismOutcome;
use impax::scenario::{
    file_error_message, MechanismFile, MechanismSpec, RobotSource, RobotSpec, Space,
    DEFAULT_FRICTION, DEFAULT_RESTITUTION,
};
use impax::LawId;
use serde::Deserialize;
use serde_json::{json, Value};

use crate::report::num;

/// The files of `examples/mechanisms/`, embedded when the module is built: the page's menu.
pub const EXAMPLES: [(&str, &str); 7] = [
    (
        "double-pendulum.toml",
        include_str!("../../../examples/mechanisms/double-pendulum.toml"),
    ),
    (
        "ring-pendulum.toml",
        include_str!("../../../examples/mechanisms/ring-pendulum.toml"),
    ),
    (
        "cart-pendulum.toml",
        include_str!("../../../examples/mechanisms/cart-pendulum.toml"),
    ),
    (
        "sphere.toml",
        include_str!("../../../examples/mechanisms/sphere.toml"),
    ),
    (
        "rod.toml",
        include_str!("../../../examples/mechanisms/rod.toml"),
    ),
    (
        "arm-3d.toml",
        include_str!("../../../examples/mechanisms/arm-3d.toml"),
    ),
    (
        "hopper-3d.toml",
        include_str!("../../../examples/mechanisms/hopper-3d.toml"),
    ),
];

/// The examples as `[{"name", "text"}]`, the page's menu (in [`crate::info_json`]).
pub fn examples_json() -> Value {
    EXAMPLES
        .iter()
        .map(|(name, text)| json!({ "name": name, "text": text }))
        .collect()
}

/// A request of the view "Your mechanism".
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismRequest {
    /// The mechanism file's text (TOML).
    pub file: String,
    /// The generalized coordinates (default: the file's `q`).
    #[serde(default)]
    pub q: Option<Vec<f64>>,
    /// The generalized velocities (default: the file's `u`).
    #[serde(default)]
    pub u: Option<Vec<f64>>,
    /// Coulomb friction (default: the file's, else 0.5).
    #[serde(default)]
    pub friction: Option<f64>,
    /// Restitution (default: the file's, else 0.5).
    #[serde(default)]
    pub restitution: Option<f64>,
}

/// Answer a request of the view "Your mechanism".
///
/// # Errors
/// One line saying where: the file's syntax (line and column), a field of the file (its
/// line), the state, the coefficients, a contact that does not strike.
pub fn answer(request: &MechanismRequest) -> Result<Value, String> {
    let text = request.file.as_str();
    // Where the error is: in the file, unless it is about a value the page gave.
    let at = |e: impax::Error| {
        let field = e.field().split('[').next().unwrap_or_default();
        let given = match field {
            "q" => request.q.is_some(),
            "u" => request.u.is_some(),
            "friction" => request.friction.is_some(),
            "restitution" => request.restitution.is_some(),
            _ => false,
        };
        if given {
            e.to_string()
        } else {
            file_error_message(text, &e)
        }
    };
    let file = MechanismFile::parse(text).map_err(at)?;
    let name = file.name.clone().unwrap_or_else(|| "mechanism".into());
    let friction = request
        .friction
        .or(file.friction)
        .unwrap_or(DEFAULT_FRICTION);
    let restitution = request
        .restitution
        .or(file.restitution)
        .unwrap_or(DEFAULT_RESTITUTION);
    let laws = file.law_ids().map_err(at)?;
    // In space the core says so (`contact: … has no contact point to strike`); in the plane
    // the same words, where the command line suggests `impax conserved`.
    if file.contacts.is_empty() && file.space == Space::Planar {
        return Err(format!(
            "contact: `{name}` has no contact point to strike (its free motion: `impax conserved`)"
        ));
    }
    let mut doc = match file.space {
        Space::Planar => planar(request, file, &name, &laws, friction, restitution, &at)?,
        Space::Spatial => spatial(request, file, &name, &laws, friction, restitution, &at)?,
    };
    doc["friction"] = json!(friction);
    doc["restitution"] = json!(restitution);
    Ok(doc)
}

fn planar(
    request: &MechanismRequest,
    file: MechanismFile,
    name: &str,
    laws: &[LawId],
    friction: f64,
    restitution: f64,
    at: &dyn Fn(impax::Error) -> String,
) -> Result<Value, String> {
    let spec = MechanismSpec {
        mechanism: name.into(),
        q: request.q.clone(),
        u: request.u.clone(),
        file: Some(file),
        ..MechanismSpec::default()
    };
    let case = spec.build().map_err(at)?;
    let impact = MechanismImpact::striking(&case.mechanism, &case.q, &case.u).map_err(at)?;
    let problem = impact.problem(friction, restitution).map_err(at)?;
    let results = laws
        .iter()
        .map(|&law| Ok((law, impact.resolve(law, friction, restitution).map_err(at)?)))
        .collect::<Result<Vec<_>, String>>()?;
    let mut doc = impax::json::mechanism_document(
        name,
        &case.description,
        &impact,
        &case.u,
        &problem,
        &results,
    );
    let coords = case.mechanism.coordinates();
    let mut rows: Vec<Value> = coords
        .iter()
        .zip(&case.u)
        .map(|(c, &u)| row(c, &format!("{c}⁺"), "velocity", Some(u)))
        .collect();
    let v = impact.contact_velocity();
    rows.extend([
        row("vt", "v_t⁺", "contact", Some(v.x)),
        row("vn", "v_n⁺", "contact", Some(v.y)),
        row("pt", "p_t", "impulse", None),
        row("pn", "p_n", "impulse", None),
    ]);
    rows.extend(energy_rows());
    for (entry, (_, r)) in doc["results"]
        .as_array_mut()
        .expect("results")
        .iter_mut()
        .zip(&results)
    {
        let (values, summary) = match (&r.resolution, &r.velocities_after) {
            (Ok(o), Some(after)) => {
                let mut values: Vec<f64> = after.clone();
                values.extend([
                    o.velocity_after.x,
                    o.velocity_after.y,
                    o.impulse.x,
                    o.impulse.y,
                    o.energy_change,
                    entry["energy_ratio"].as_f64().unwrap_or(f64::NAN),
                ]);
                let phases: Vec<String> = o
                    .phases
                    .as_slice()
                    .iter()
                    .map(|p| format!("{}@{:.4}", p.kind.label(), p.ends_at))
                    .collect();
                (Some(values), phases.join(" → "))
            }
            _ => (None, String::new()),
        };
        finish_entry(entry, values, summary);
    }
    doc["space"] = json!("2d");
    doc["speeds"] = json!(coords);
    doc["rows"] = json!(rows);
    Ok(doc)
}

fn spatial(
    request: &MechanismRequest,
    file: MechanismFile,
    name: &str,
    laws: &[LawId],
    friction: f64,
    restitution: f64,
    at: &dyn Fn(impax::Error) -> String,
) -> Result<Value, String> {
    let spec = RobotSpec {
        q: request.q.clone(),
        u: request.u.clone(),
        ..RobotSpec::new(name, RobotSource::File(Box::new(file)))
    };
    let built = spec.build().map_err(at)?;
    let impact = built.impact().map_err(at)?;
    let problem = impact.problem(friction, restitution).map_err(at)?;
    let results: Vec<(LawId, SpatialMechanismOutcome)> = laws
        .iter()
        .map(|&law| Ok((law, impact.resolve(law, friction, restitution).map_err(at)?)))
        .collect::<Result<_, String>>()?;
    let mut doc = impax::json::robot_document(&built, &impact, &problem, &results);
    let speeds = built.model.speeds();
    let mut rows: Vec<Value> = speeds
        .iter()
        .zip(&built.u)
        .map(|(c, &u)| row(c, &format!("{c}⁺"), "velocity", Some(u)))
        .collect();
    let v = impact.contact_velocity();
    rows.extend([
        row("vt1", "v_t1⁺", "contact", Some(v.x)),
        row("vt2", "v_t2⁺", "contact", Some(v.y)),
        row("vn", "v_n⁺", "contact", Some(v.z)),
        row("pt1", "p_t1", "impulse", None),
        row("pt2", "p_t2", "impulse", None),
        row("pn", "p_n", "impulse", None),
    ]);
    rows.extend(energy_rows());
    for (entry, (_, r)) in doc["results"]
        .as_array_mut()
        .expect("results")
        .iter_mut()
        .zip(&results)
    {
        let (values, summary) = match (&r.resolution, &r.velocities_after) {
            (Ok(o), Some(after)) => {
                let mut values: Vec<f64> = after.clone();
                let (w, p) = (o.velocity_after, o.impulse);
                values.extend([w.x, w.y, w.z, p.x, p.y, p.z, o.energy_change]);
                values.push(entry["energy_ratio"].as_f64().unwrap_or(f64::NAN));
                (Some(values), o.phases.summary())
            }
            _ => (None, String::new()),
        };
        finish_entry(entry, values, summary);
    }
    doc["space"] = json!("3d");
    doc["speeds"] = json!(speeds);
    doc["rows"] = json!(rows);
    Ok(doc)
}

fn row(key: &str, label: &str, kind: &str, before: Option<f64>) -> Value {
    json!({ "key": key, "label": label, "kind": kind, "before": before.map(num) })
}

/// `ΔT = T⁺ − T⁻` and `T⁺/T⁻`.
fn energy_rows() -> [Value; 2] {
    [
        row("dT", "ΔT = T⁺ − T⁻", "energy", None),
        row("ratio", "T⁺/T⁻", "energy", None),
    ]
}

fn finish_entry(entry: &mut Value, values: Option<Vec<f64>>, summary: String) {
    entry["values"] = values.map_or(Value::Null, |v| v.into_iter().map(num).collect());
    entry["phase_summary"] = json!(summary);
}
