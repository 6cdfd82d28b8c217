//! `impax resolve --contacts K`: a planar problem with several contacts (`impax::multi`).

use crate::cli::ResolveArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json;
use crate::sources::scenario::parse_laws;
use impax::multi::{lcp, MultiDetail, MultiProblem, MultiResolution};
use impax::LawId;
use serde_json::json;

/// The most binary impacts of `sequential` listed in a table's note.
const LISTED_IMPACTS: usize = 12;

pub fn run(args: &ResolveArgs, k: usize, out: &mut Vec<u8>) -> CliResult<()> {
    if k == 0 {
        return Err(CliError::input("--contacts: must be at least 1"));
    }
    let n = k.checked_mul(2).ok_or_else(|| too_many(k))?;
    let count = n.checked_mul(n + 1).ok_or_else(|| too_many(k))? / 2;
    let n3 = k.checked_mul(3).ok_or_else(|| too_many(k))?;
    let count3 = n3.checked_mul(n3 + 1).ok_or_else(|| too_many(k))? / 2;
    let given = args.w.split(',').count();
    if given == count3 {
        return super::multi_spatial::run(args, k, out);
    }
    if given != count {
        return Err(CliError::input(format!(
            "--w: expected {count} comma-separated numbers for {k} planar contact{s} (the upper triangle of the {n} × {n} W, row by row: t1, n1, t2, n2, …) or {count3} in 3D (the {n3} × {n3} W: t1_1, t2_1, n_1, t1_2, …), got {given}",
            s = if k == 1 { "" } else { "s" }
        )));
    }
    let w = parse_numbers("w", &args.w, count, "the upper triangle of W")?;
    let v = parse_numbers(
        "v",
        &args.v,
        n,
        "VT1,VN1,…: tangent and normal of each contact",
    )?;
    check_coefficients(args, k)?;
    let mut problem = MultiProblem::from_upper(k, &w, &v, &args.friction, &args.restitution)?;
    if !args.stiffness.is_empty() {
        problem = problem.with_stiffness(&args.stiffness)?;
    }
    if let Some(eta) = args.exponent {
        problem = problem.with_exponent(eta)?;
    }
    let laws = laws(args, k, lcp::MAX_CONTACTS, &LawId::MULTI_CONTACT)?;
    let mut results: Vec<(LawId, MultiResolution)> = Vec::new();
    for &law in &laws {
        results.push((law, law.resolve(&problem)?));
    }
    let text = if args.json {
        let doc = if args.law.len() == 1 {
            json::multi_entry(&results[0].1)
        } else {
            json!({
                "problem": json::multi_problem(&problem),
                "results": results.iter().map(|(_, r)| json::multi_entry(r)).collect::<Vec<_>>(),
            })
        };
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        table(&problem, &results)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

/// `--friction` and `--restitution`: one number for every contact or `K`, finite.
pub(super) fn check_coefficients(args: &ResolveArgs, k: usize) -> CliResult<()> {
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
    Ok(())
}

/// `--law`, or every law of `all` that takes `k` contacts (`lcp` up to `lcp_max`).
pub(super) fn laws(
    args: &ResolveArgs,
    k: usize,
    lcp_max: usize,
    all: &[LawId],
) -> CliResult<Vec<LawId>> {
    Ok(if args.law.is_empty() {
        all.iter()
            .copied()
            .filter(|l| *l != LawId::Lcp || k <= lcp_max)
            .collect()
    } else {
        parse_laws(&args.law)?
    })
}

pub(super) fn too_many(k: usize) -> CliError {
    CliError::input(format!("--contacts: {k} contacts are too many"))
}

/// `a | b | c`, or `a` when every contact has the same value.
pub(super) fn per_contact(values: impl Iterator<Item = f64>) -> String {
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

/// `, κ = …, η = …` when `lzb`'s force law is not the default (equal stiffnesses, Hertz).
pub(crate) fn force_law(p: &MultiProblem) -> String {
    let k = p.contacts();
    let equal = (1..k).all(|j| p.stiffness(j) == p.stiffness(0));
    let mut s = String::new();
    if !equal {
        s.push_str(&format!(
            ", κ = {}",
            per_contact((0..k).map(|j| p.stiffness(j)))
        ));
    }
    if p.exponent() != impax::multi::HERTZ_EXPONENT {
        s.push_str(&format!(", η = {}", Plain(p.exponent())));
    }
    s
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
                t.breakdown_row(law, "breakdown");
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
        "impax resolve — {k} contact{}, W {n} × {n} of rank {}, v⁻ = ({}), μ = {}, e = {}{}\n\n",
        if k == 1 { "" } else { "s" },
        p.rank(),
        v.join(" | "),
        per_contact((0..k).map(|j| p.friction(j))),
        per_contact((0..k).map(|j| p.restitution(j))),
        force_law(p),
        n = 2 * k,
    );
    s.push_str(&t.render());
    s.push_str(&crate::output::fmt::notes(&notes));
    s
}
