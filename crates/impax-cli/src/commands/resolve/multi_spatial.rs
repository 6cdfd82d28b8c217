//! `impax resolve --contacts K` with a `3K × 3K` W: a spatial problem with several contacts
//! (`impax::multi::spatial`).

use super::multi::{check_coefficients, laws, per_contact};
use crate::cli::ResolveArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json;
use impax::multi::spatial::{self, MultiDetail, MultiProblem, MultiResolution};
use impax::LawId;
use serde_json::json;

/// The laws that take several spatial contacts.
const LAWS: [LawId; 3] = [LawId::Lcp, LawId::Sequential, LawId::Lzb];

pub fn run(args: &ResolveArgs, k: usize, out: &mut Vec<u8>) -> CliResult<()> {
    let n = 3 * k;
    let w = parse_numbers("w", &args.w, n * (n + 1) / 2, "the upper triangle of W")?;
    let v = parse_numbers(
        "v",
        &args.v,
        n,
        "V1_1,V2_1,VN_1,…: the two tangents and the normal of each contact",
    )?;
    check_coefficients(args, k)?;
    let mut problem = MultiProblem::from_upper(k, &w, &v, &args.friction, &args.restitution)?;
    if !args.stiffness.is_empty() {
        problem = problem.with_stiffness(&args.stiffness)?;
    }
    if let Some(eta) = args.exponent {
        problem = problem.with_exponent(eta)?;
    }
    let laws = laws(args, k, spatial::lcp::MAX_CONTACTS, &LAWS)?;
    let mut results: Vec<(LawId, MultiResolution)> = Vec::new();
    for &law in &laws {
        results.push((law, spatial::resolve(law, &problem)?));
    }
    let text = if args.json {
        let doc = if args.law.len() == 1 {
            json::multi3_entry(&results[0].1)
        } else {
            json!({
                "problem": json::multi3_problem(&problem),
                "results": results.iter().map(|(_, r)| json::multi3_entry(r)).collect::<Vec<_>>(),
            })
        };
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        table(&problem, &results)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

/// The table: one row per law and contact, `ΔT` and the verdict on each law's first row.
fn table(p: &MultiProblem, results: &[(LawId, MultiResolution)]) -> String {
    let k = p.contacts();
    let mut t = Table::new(&[
        ("law", false),
        ("contact", true),
        ("p_t1", true),
        ("p_t2", true),
        ("p_n", true),
        ("v_t1+", true),
        ("v_t2+", true),
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
                    notes.push(format!(
                        "{law}: {} binary impact{}",
                        impacts.len(),
                        if impacts.len() == 1 { "" } else { "s" }
                    ));
                }
                for (j, c) in o.contacts.iter().enumerate() {
                    let first = j == 0;
                    let on_first = |s: String| if first { s } else { String::new() };
                    t.row(vec![
                        on_first(law.to_string()),
                        (j + 1).to_string(),
                        signed(c.impulse.x, 6),
                        signed(c.impulse.y, 6),
                        signed(c.impulse.z, 6),
                        signed(c.velocity_after.x, 6),
                        signed(c.velocity_after.y, 6),
                        signed(c.velocity_after.z, 6),
                        c.phase_summary(),
                        on_first(signed(o.energy_change, 6)),
                        on_first(o.verdict.id().to_string()),
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
            format!("{}, {}, {}", Plain(c.x), Plain(c.y), Plain(c.z))
        })
        .collect();
    let mut s = format!(
        "impax resolve — {k} contact{} in 3D, W {n} × {n} of rank {}, v⁻ = ({}), μ = {}, e = {}\n\n",
        if k == 1 { "" } else { "s" },
        p.rank(),
        v.join(" | "),
        per_contact((0..k).map(|j| p.friction(j))),
        per_contact((0..k).map(|j| p.restitution(j))),
        n = 3 * k,
    );
    s.push_str(&t.render());
    s.push_str(&crate::output::fmt::notes(&notes));
    s
}
