//! `impax resolve --contacts K`: a planar problem with several contacts (`impax::multi`).

use crate::cli::ResolveArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json;
use crate::sources::scenario::parse_laws;
use impax::law::WorkSplit;
use impax::math::Vec2;
use impax::multi::{lcp, ContactPhase, MultiDetail, MultiOutcome, MultiProblem, MultiResolution};
use impax::LawId;
use serde_json::{json, Value};

/// The most binary impacts of `sequential` listed in a table's note.
const LISTED_IMPACTS: usize = 12;

pub fn run(args: &ResolveArgs, k: usize, out: &mut Vec<u8>) -> CliResult<()> {
    if k == 0 {
        return Err(CliError::input("--contacts: must be at least 1"));
    }
    let n = k.checked_mul(2).ok_or_else(|| too_many(k))?;
    let count = n.checked_mul(n + 1).ok_or_else(|| too_many(k))? / 2;
    let given = args.w.split(',').count();
    if given != count {
        return Err(CliError::input(format!(
            "--w: expected {count} comma-separated numbers for {k} contact{} (the upper triangle of the {n} × {n} W, row by row: t1, n1, t2, n2, …), got {given}",
            if k == 1 { "" } else { "s" }
        )));
    }
    let w = parse_numbers("w", &args.w, count, "the upper triangle of W")?;
    let v = parse_numbers(
        "v",
        &args.v,
        n,
        "VT1,VN1,…: tangent and normal of each contact",
    )?;
    for (flag, values) in [
        ("friction", &args.friction),
        ("restitution", &args.restitution),
    ] {
        if values.len() != 1 && values.len() != k {
            return Err(CliError::input(format!(
                "--{flag}: expected 1 number (every contact) or {k} (one per contact), got {}",
                values.len()
            )));
        }
        if let Some(x) = values.iter().find(|x| !x.is_finite()) {
            return Err(CliError::input(format!(
                "--{flag}: must be finite numbers, got {}",
                Plain(*x)
            )));
        }
    }
    let problem = MultiProblem::from_upper(k, &w, &v, &args.friction, &args.restitution)?;
    let laws = if args.law.is_empty() {
        // Every law that takes K contacts (`lcp` enumerates 4^K modes: up to 6).
        LawId::MULTI_CONTACT
            .into_iter()
            .filter(|l| *l != LawId::Lcp || k <= lcp::MAX_CONTACTS)
            .collect()
    } else {
        parse_laws(&args.law)?
    };
    let mut results: Vec<(LawId, MultiResolution)> = Vec::new();
    for &law in &laws {
        results.push((law, law.resolve_multi(&problem)?));
    }
    let text = if args.json {
        let doc = if args.law.len() == 1 {
            entry(&results[0].1)
        } else {
            json!({
                "problem": problem_json(&problem),
                "results": results.iter().map(|(_, r)| entry(r)).collect::<Vec<_>>(),
            })
        };
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        table(&problem, &results)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn too_many(k: usize) -> CliError {
    CliError::input(format!("--contacts: {k} contacts are too many"))
}

/// `{t, n}`.
fn vec2(v: Vec2) -> Value {
    json!({ "t": json::num(v.x), "n": json::num(v.y) })
}

fn phases(list: &[ContactPhase]) -> Value {
    Value::Array(
        list.iter()
            .map(|p| json!({ "kind": p.kind.label(), "ends_at": json::num(p.ends_at) }))
            .collect(),
    )
}

fn work(w: &WorkSplit) -> Value {
    json!({
        "compression": json::num(w.compression),
        "restitution": json::num(w.restitution),
        "friction": json::num(w.friction),
    })
}

/// The problem as JSON: `contacts`, `w` (2K × 2K), `v` (one `{t, n}` per contact),
/// `friction`, `restitution` (K each), `rank`.
fn problem_json(p: &MultiProblem) -> Value {
    let k = p.contacts();
    let w = p.w();
    json!({
        "contacts": k,
        "w": (0..2 * k).map(|i| (0..2 * k).map(|j| json::num(w[(i, j)])).collect::<Vec<_>>()).collect::<Vec<_>>(),
        "v": (0..k).map(|j| vec2(p.contact_velocity(j))).collect::<Vec<_>>(),
        "friction": (0..k).map(|j| p.friction(j)).collect::<Vec<_>>(),
        "restitution": (0..k).map(|j| p.restitution(j)).collect::<Vec<_>>(),
        "rank": p.rank(),
    })
}

/// One law's entry: `law`, `verdict`, `contacts`, `energy_change`, `inconsistency`,
/// `breakdown`, `detail` (every number null when the law broke down).
fn entry(r: &MultiResolution) -> Value {
    match r {
        Ok(o) => json!({
            "law": o.law.as_str(),
            "verdict": o.verdict.id(),
            "contacts": o.contacts.iter().map(|c| json!({
                "impulse": vec2(c.impulse),
                "velocity_after": vec2(c.velocity_after),
                "phases": phases(&c.phases),
                "work": work(&c.work),
            })).collect::<Vec<_>>(),
            "energy_change": json::num(o.energy_change),
            "inconsistency": o.inconsistency.map_or(Value::Null, |i| json!({ "id": i.id(), "message": i.to_string() })),
            "breakdown": Value::Null,
            "detail": detail(o),
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
fn detail(o: &MultiOutcome) -> Value {
    match &o.detail {
        MultiDetail::Lcp { solutions } => json!({
            "solutions": solutions.iter().map(|s| json!({
                "energy_change": json::num(s.energy_change),
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
                "phases": Value::Array(b.outcome.phases.as_slice().iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": json::num(p.ends_at) })).collect()),
                "energy_change": json::num(b.outcome.energy_change),
            })).collect::<Vec<_>>(),
        }),
        MultiDetail::OneContact { detail, .. } => json::detail(detail),
    }
}

/// `a | b | c`, or `a` when every contact has the same value.
fn per_contact(values: impl Iterator<Item = f64>) -> String {
    let v: Vec<f64> = values.collect();
    if v.windows(2).all(|w| w[0] == w[1]) {
        Plain(v[0]).to_string()
    } else {
        v.iter()
            .map(|x| Plain(*x).to_string())
            .collect::<Vec<_>>()
            .join(" | ")
    }
}

/// The table: one row per law and contact, `ΔT` and the verdict on each law's first row.
fn table(p: &MultiProblem, results: &[(LawId, MultiResolution)]) -> String {
    let k = p.contacts();
    let mut t = Table::new(&[
        ("law", false),
        ("contact", true),
        ("p_t", true),
        ("p_n", true),
        ("v_t+", true),
        ("v_n+", true),
        ("phases", false),
        ("ΔT", true),
        ("verdict", false),
    ]);
    let mut notes = Vec::new();
    for (law, r) in results {
        match r {
            Ok(o) => {
                if let Some(i) = o.inconsistency {
                    notes.push(format!("{law}: {i}"));
                }
                if let MultiDetail::Sequential { impacts } = &o.detail {
                    let order: Vec<String> = impacts
                        .iter()
                        .take(LISTED_IMPACTS)
                        .map(|b| (b.contact + 1).to_string())
                        .collect();
                    notes.push(format!(
                        "{law}: {} binary impact{} (contact {}{})",
                        impacts.len(),
                        if impacts.len() == 1 { "" } else { "s" },
                        order.join(", "),
                        if impacts.len() > LISTED_IMPACTS {
                            ", …"
                        } else {
                            ""
                        }
                    ));
                }
                for (j, c) in o.contacts.iter().enumerate() {
                    let first = j == 0;
                    t.row(vec![
                        if first {
                            law.to_string()
                        } else {
                            String::new()
                        },
                        (j + 1).to_string(),
                        signed(c.impulse.x, 6),
                        signed(c.impulse.y, 6),
                        signed(c.velocity_after.x, 6),
                        signed(c.velocity_after.y, 6),
                        c.phase_summary(),
                        if first {
                            signed(o.energy_change, 6)
                        } else {
                            String::new()
                        },
                        if first {
                            o.verdict.id().to_string()
                        } else {
                            String::new()
                        },
                    ]);
                }
            }
            Err(b) => {
                notes.push(format!("{law}: breakdown: {}", b.reason));
                let mut row = vec![law.to_string()];
                row.extend(std::iter::repeat_n("—".to_string(), 7));
                row.push("breakdown".into());
                t.row(row);
            }
        }
    }
    let v: Vec<String> = (0..k)
        .map(|j| {
            let c = p.contact_velocity(j);
            format!("{}, {}", Plain(c.x), Plain(c.y))
        })
        .collect();
    let mut s = format!(
        "impax resolve — {k} contact{}, W {n} × {n} of rank {}, v⁻ = ({}), μ = {}, e = {}\n\n",
        if k == 1 { "" } else { "s" },
        p.rank(),
        v.join(" | "),
        per_contact((0..k).map(|j| p.friction(j))),
        per_contact((0..k).map(|j| p.restitution(j))),
        n = 2 * k,
    );
    s.push_str(&t.render());
    for n in notes {
        s.push_str(&format!("note — {n}\n"));
    }
    s
}
