//! `impax compare scenario.toml` for spatial (3D) bodies: a scenario file with
//! `space = "3d"` (see the book, docs/src/scenarios.md, "Spatial bodies").
//!
//! The file's format and the bodies are the core's ([`impax::scenario::SpatialScenario`]);
//! this module resolves the laws and writes the table and the JSON.

use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Table};
use crate::output::json::num;
use crate::sources::scenario::parse_laws;
use impax::math::Vec3;
use impax::planar::Breakdown;
use impax::scenario::{BuiltSpatial, SpatialScenario};
use impax::spatial::bodies::{BodyImpact, BodyOutcome, BodyState};
use impax::LawId;
use serde_json::{json, Value};

/// Whether a TOML text asks for the spatial bodies (`space = "3d"`).
pub fn is_spatial(text: &str) -> bool {
    SpatialScenario::is_spatial(text)
}

fn vec3(v: Vec3) -> Value {
    json!({ "t1": num(v.x), "t2": num(v.y), "n": num(v.z) })
}

fn state(s: &BodyState) -> Value {
    json!({
        "vx": num(s.velocity.x), "vy": num(s.velocity.y), "vz": num(s.velocity.z),
        "omega_x": num(s.omega.x), "omega_y": num(s.omega.y), "omega_z": num(s.omega.z),
    })
}

pub(crate) fn entry(
    problem: &impax::spatial::ContactProblem,
    law: LawId,
    r: &Result<BodyOutcome, Breakdown>,
    t0: f64,
    two: bool,
) -> Value {
    match r {
        Ok(b) => {
            let o = &b.outcome;
            let mut e = json!({
                "law": law.as_str(),
                "verdict": o.verdict.id(),
                "impulse": vec3(o.impulse),
                "contact_velocity_after": vec3(o.velocity_after),
                "body_velocity_after": state(&b.body_after),
                "energy_change": num(o.energy_change),
                "energy_change_ratio": num(o.energy_change / t0),
                "energy_split": {
                    "translational": num(b.body_energy_change.translational + b.other_energy_change.translational),
                    "rotational": num(b.body_energy_change.rotational + b.other_energy_change.rotational),
                },
                "work": {
                    "compression": num(o.work.compression),
                    "restitution": num(o.work.restitution),
                    "friction": num(o.work.friction),
                },
                "phases": o.phases.as_slice().iter().map(|p| json!({"kind": p.kind.label(), "ends_at": num(p.ends_at), "label": p.kind.to_string()})).collect::<Vec<_>>(),
                "compression_impulse": o.compression_impulse.map_or(Value::Null, num),
                "inconsistency": o.inconsistency.map_or(Value::Null, |i| json!({"id": i.id(), "message": i.to_string()})),
            });
            if two {
                e["other_body_velocity_after"] = b.other_after.as_ref().map_or(Value::Null, state);
            }
            if law == LawId::Lcp {
                e["all_solutions"] = crate::commands::resolve::lcp_solutions(problem);
            }
            e
        }
        Err(b) => json!({
            "law": law.as_str(),
            "verdict": "breakdown",
            "breakdown": { "id": b.reason.id(), "message": b.reason.to_string() },
            "impulse": null, "contact_velocity_after": null, "body_velocity_after": null,
            "energy_change": null, "energy_change_ratio": null, "energy_split": null,
            "work": null, "phases": [], "compression_impulse": null, "inconsistency": null,
        }),
    }
}

/// A 3D scenario text: the impact, its description and the file's coefficients and laws.
pub(crate) fn load(source: &str, text: &str) -> CliResult<(BodyImpact, String, Spec3)> {
    let spec: SpatialScenario = toml::from_str(text)
        .map_err(|e| CliError::input(format!("{source}: {}", e.message().replace('\n', " "))))?;
    let BuiltSpatial {
        impact,
        description: desc,
    } = spec.build()?;
    Ok((
        impact,
        desc,
        Spec3 {
            friction: spec.friction,
            restitution: spec.restitution,
            laws: spec.laws,
        },
    ))
}

/// The coefficients and laws of a 3D scenario file.
pub(crate) struct Spec3 {
    pub(crate) friction: f64,
    pub(crate) restitution: f64,
    pub(crate) laws: Option<Vec<String>>,
}

/// Run `impax compare` on a 3D scenario text; `law_flags` override the file's `laws`.
pub fn run(
    source: &str,
    text: &str,
    law_flags: &[String],
    as_json: bool,
    out: &mut Vec<u8>,
) -> CliResult<()> {
    let (impact, desc, spec) = load(source, text)?;
    let laws = if !law_flags.is_empty() {
        parse_laws(law_flags)?
    } else if let Some(ids) = &spec.laws {
        parse_laws(ids)?
    } else {
        LawId::SPATIAL.to_vec()
    };
    if let Some(l) = laws.iter().find(|l| !l.is_spatial()) {
        return Err(CliError::input(format!(
            "law: `{l}` is defined for planar impacts only (spatial laws: {})",
            LawId::SPATIAL.map(|l| l.as_str()).join(", ")
        )));
    }
    let (ea, eb) = impact.energy_before();
    // Every energy is a number with room to spare (an `omega` of 1e200 gave a null
    // `energy_before`).
    for (prefix, e) in [("body", ea), ("other", eb)] {
        for (key, part) in [("velocity", e.translational), ("omega", e.rotational)] {
            if !(part.is_finite() && part <= 1e300) {
                return Err(CliError::input(format!(
                    "{prefix}.{key}: the kinetic energy it gives, {}, is not representable with room to spare (it must be below 1e300)",
                    impax::error::Num(part)
                )));
            }
        }
    }
    let t0 = crate::sources::scenario::reference_energy(
        &impax::planar::bodies::EnergyParts {
            translational: ea.translational + eb.translational,
            rotational: ea.rotational + eb.rotational,
        },
        "body.velocity",
    )?;
    let problem = impact.problem(spec.friction, spec.restitution)?;
    let results: Vec<_> = laws
        .iter()
        .map(|&l| (l, impact.resolve(l, &problem)))
        .collect();
    let two = impact.other.is_some();
    let text = if as_json {
        let w = problem.w();
        let doc = json!({
            "scenario": desc,
            "problem": {
                "w": [[w[(0,0)], w[(0,1)], w[(0,2)]], [w[(1,0)], w[(1,1)], w[(1,2)]], [w[(2,0)], w[(2,1)], w[(2,2)]]],
                "v": vec3(problem.velocity()),
                "friction": problem.friction(),
                "restitution": problem.restitution(),
            },
            "energy_before": ea.total() + eb.total(),
            "t0": t0,
            "results": results.iter().map(|(l, r)| entry(&problem, *l, r, t0, two)).collect::<Vec<_>>(),
        });
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        let mut t = Table::new(&[
            ("law", false),
            ("vx+", true),
            ("vy+", true),
            ("vz+", true),
            ("ωx+", true),
            ("ωy+", true),
            ("ωz+", true),
            ("ΔT/T0", true),
            ("phases", false),
            ("verdict", false),
        ]);
        let mut notes = Vec::new();
        for (law, r) in &results {
            match r {
                Ok(b) => {
                    let (v, w) = (b.body_after.velocity, b.body_after.omega);
                    if let Some(i) = b.outcome.inconsistency {
                        notes.push(format!("{law}: {i}"));
                    }
                    t.row(vec![
                        law.to_string(),
                        signed(v.x, 5),
                        signed(v.y, 5),
                        signed(v.z, 5),
                        signed(w.x, 5),
                        signed(w.y, 5),
                        signed(w.z, 5),
                        signed(b.outcome.energy_change / t0, 5),
                        b.outcome.phases.summary(),
                        b.outcome.verdict.id().to_string(),
                    ]);
                }
                Err(b) => {
                    notes.push(format!("{law}: breakdown: {}", b.reason));
                    t.breakdown_row(law, "breakdown");
                }
            }
        }
        let v = problem.velocity();
        let mut s = format!(
            "impax compare (3D) — {desc}, μ = {}, e = {}\ncontact velocity v⁻ = ({}, {}, {}); T0 = {t0}\n\n",
            spec.friction, spec.restitution, v.x, v.y, v.z
        );
        s.push_str(&t.render());
        s.push_str(&crate::output::fmt::notes(&notes));
        s
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}
