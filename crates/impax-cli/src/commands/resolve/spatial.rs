//! `impax resolve` with a 3 × 3 `W` (six numbers) and `(v_t1, v_t2, v_n)`.

use super::single;
use crate::cli::ResolveArgs;
use crate::input::{finite_flag, parse_numbers, CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json;
use crate::sources::scenario::parse_laws;
use impax::spatial::{
    invariant_rays, sticking_ratio, ContactProblem, InvariantRays, LawDetail, PhaseKind,
};
use impax::LawId;
use serde_json::{json, Value};

/// The JSON entry of a spatial outcome (the planar entry's keys, plus `hodograph` for the
/// Darboux–Keller laws and the problem's `invariant_rays`).
fn spatial_entry(
    problem: &ContactProblem,
    law: LawId,
    r: &impax::spatial::Resolution,
    rays: &Value,
) -> Value {
    let mut m = match r {
        Ok(o) => {
            let mut m = json::spatial_outcome_fields(o);
            let hodograph = if law.is_darboux_keller() {
                impax::spatial::laws::hodograph(problem, law, &impax::law::Options::default())
                    .map(|pts| json!(pts))
                    .unwrap_or(Value::Null)
            } else {
                Value::Null
            };
            m.insert("hodograph".into(), hodograph);
            if law == LawId::Lcp {
                m.insert("all_solutions".into(), lcp_solutions(problem));
            }
            m
        }
        Err(b) => {
            let mut m = json::spatial_breakdown_fields(b);
            m.insert("hodograph".into(), Value::Null);
            m
        }
    };
    m.insert("invariant_rays".into(), rays.clone());
    Value::Object(m)
}

/// Every solution of the spatial LCP (least kinetic energy after first): `kind` (`stick`
/// or `slip`), `slip_angle_deg` (slip only), `impulse`, `velocity_after`, `energy_change`.
pub(crate) fn lcp_solutions(problem: &ContactProblem) -> Value {
    Value::Array(
        impax::spatial::laws::lcp::solutions(problem)
            .iter()
            .map(|s| {
                let mut e = json!({
                    "kind": s.kind.label(),
                    "impulse": json::vec3(s.impulse),
                    "velocity_after": json::vec3(s.velocity_after),
                    "energy_change": json::num(s.energy_change),
                });
                if let PhaseKind::Slip { to, .. } = s.kind {
                    e["slip_angle_deg"] = json!(to.to_degrees());
                }
                e
            })
            .collect(),
    )
}

/// `impax resolve` with a 3×3 `W` (upper triangle) and `(v_t1, v_t2, v_n)`.
pub fn run(args: &ResolveArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let w = parse_numbers("w", &args.w, 6, "W11,W12,W13,W22,W23,W33")?;
    let v = parse_numbers("v", &args.v, 3, "V1,V2,VN (spatial W has 6 numbers)")?;
    let mu = finite_flag("friction", single("friction", &args.friction)?)?;
    let e = finite_flag("restitution", single("restitution", &args.restitution)?)?;
    let problem = ContactProblem::from_upper(
        [w[0], w[1], w[2], w[3], w[4], w[5]],
        [v[0], v[1], v[2]],
        mu,
        e,
    )?;
    let laws = if args.law.is_empty() {
        LawId::SPATIAL.to_vec()
    } else {
        parse_laws(&args.law)?
    };
    if let Some(l) = laws.iter().find(|l| !l.is_spatial()) {
        return Err(CliError::input(format!(
            "law: `{l}` is defined for planar impacts only (spatial laws: {})",
            LawId::SPATIAL.map(|l| l.as_str()).join(", ")
        )));
    }
    let rays = invariant_rays(&problem);
    let rays_json = match rays {
        InvariantRays::All => json!("all"),
        InvariantRays::Rays { .. } => Value::Array(
            rays.as_slice()
                .iter()
                .map(|r| json!({ "angle_deg": r.angle.to_degrees(), "kind": r.kind.id(), "rate": r.rate }))
                .collect(),
        ),
    };
    let results: Vec<_> = laws.iter().map(|&l| (l, l.resolve(&problem))).collect();
    let text = if args.json {
        let doc = if args.law.len() == 1 {
            spatial_entry(&problem, results[0].0, &results[0].1, &rays_json)
        } else {
            json!({
                "problem": {
                    "w": [[w[0], w[1], w[2]], [w[1], w[3], w[4]], [w[2], w[4], w[5]]],
                    "v": { "t1": v[0], "t2": v[1], "n": v[2] },
                    "friction": mu,
                    "restitution": e,
                },
                "invariant_rays": rays_json,
                "results": results
                    .iter()
                    .map(|(l, r)| spatial_entry(&problem, *l, r, &rays_json))
                    .collect::<Vec<_>>(),
            })
        };
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        let mut t = Table::new(&[
            ("law", false),
            ("p_t1", true),
            ("p_t2", true),
            ("p_n", true),
            ("v_t1+", true),
            ("v_t2+", true),
            ("v_n+", true),
            ("ΔT", true),
            ("phases", false),
            ("verdict", false),
        ]);
        let mut notes = Vec::new();
        for (law, r) in &results {
            match r {
                Ok(o) => {
                    if let Some(i) = o.inconsistency {
                        notes.push(format!("{law}: {i}"));
                    }
                    if let LawDetail::DarbouxKeller {
                        second_compression: Some(p),
                        ..
                    } = o.detail
                    {
                        notes.push(format!(
                            "{law}: second compression (jamb) from p_n = {p:.6}"
                        ));
                    }
                    t.row(vec![
                        law.to_string(),
                        signed(o.impulse.x, 6),
                        signed(o.impulse.y, 6),
                        signed(o.impulse.z, 6),
                        signed(o.velocity_after.x, 6),
                        signed(o.velocity_after.y, 6),
                        signed(o.velocity_after.z, 6),
                        signed(o.energy_change, 6),
                        o.phases.summary(),
                        o.verdict.id().to_string(),
                    ]);
                }
                Err(b) => {
                    notes.push(format!("{law}: breakdown: {}", b.reason));
                    t.breakdown_row(law, "breakdown");
                }
            }
        }
        let mut s = format!(
            "impax resolve (3D) — W = [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]], v⁻ = ({}, {}, {}), μ = {}, e = {}\n",
            Plain(w[0]),
            Plain(w[1]),
            Plain(w[2]),
            Plain(w[1]),
            Plain(w[3]),
            Plain(w[4]),
            Plain(w[2]),
            Plain(w[4]),
            Plain(w[5]),
            Plain(v[0]),
            Plain(v[1]),
            Plain(v[2]),
            Plain(mu),
            Plain(e)
        );
        let lambda = sticking_ratio(&problem);
        s.push_str(&format!(
            "stick {} (|W_tt⁻¹ w_tn| = {:.6} vs μ = {}); invariant rays: {}\n\n",
            if lambda.norm() <= mu {
                "possible"
            } else {
                "impossible"
            },
            lambda.norm(),
            Plain(mu),
            match rays {
                InvariantRays::All => "every direction (no swirl)".to_string(),
                _ => rays
                    .as_slice()
                    .iter()
                    .map(|r| format!("{:.3}° {}", r.angle.to_degrees(), r.kind.id()))
                    .collect::<Vec<_>>()
                    .join(", "),
            }
        ));
        s.push_str(&t.render());
        s.push_str(&crate::output::fmt::notes(&notes));
        s
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}
