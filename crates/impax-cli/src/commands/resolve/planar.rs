//! `impax resolve` with a 2 × 2 `W` (three numbers) and `(v_t, v_n)`.

use super::single;
use crate::cli::ResolveArgs;
use crate::input::{finite_flag, parse_numbers, CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json;
use crate::sources::scenario::parse_laws;
use impax::planar::ContactProblem;
use impax::LawId;
use serde_json::{json, Value};

pub fn run(args: &ResolveArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let w = parse_numbers("w", &args.w, 3, "WTT,WTN,WNN")?;
    let v = parse_numbers("v", &args.v, 2, "VT,VN (planar W has 3 numbers)")?;
    let mu = finite_flag("friction", single("friction", &args.friction)?)?;
    let e = finite_flag("restitution", single("restitution", &args.restitution)?)?;
    let problem = ContactProblem::from_entries(w[0], w[1], w[2], v[0], v[1], mu, e)?;
    let laws = if args.law.is_empty() {
        LawId::CONTACT_SPACE.to_vec()
    } else {
        parse_laws(&args.law)?
    };
    if let Some(l) = laws.iter().find(|l| l.needs_body()) {
        return Err(CliError::input(format!(
            "law: `{l}` needs a body (it reads the centre velocity); use `impax compare` with a scenario"
        )));
    }
    let results: Vec<_> = laws.iter().map(|&l| (l, l.resolve(&problem))).collect();
    let text = if args.json {
        let entry = |r: &Result<impax::planar::Outcome, impax::planar::Breakdown>| match r {
            Ok(o) => Value::Object(json::outcome_fields(o, "velocity_after")),
            Err(b) => Value::Object(json::breakdown_fields(b, "velocity_after", false)),
        };
        let doc = if args.law.len() == 1 {
            entry(&results[0].1)
        } else {
            json!({
                "problem": json::problem(&problem),
                "results": results.iter().map(|(_, r)| entry(r)).collect::<Vec<_>>(),
            })
        };
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        let mut t = Table::new(&[
            ("law", false),
            ("p_t", true),
            ("p_n", true),
            ("v_t+", true),
            ("v_n+", true),
            ("p_c", true),
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
                    t.row(vec![
                        law.to_string(),
                        signed(o.impulse.x, 6),
                        signed(o.impulse.y, 6),
                        signed(o.velocity_after.x, 6),
                        signed(o.velocity_after.y, 6),
                        o.compression_impulse.map_or("—".into(), |x| signed(x, 6)),
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
            "impax resolve — W = [[{}, {}], [{}, {}]], v⁻ = ({}, {}), μ = {}, e = {}\n\n",
            Plain(w[0]),
            Plain(w[1]),
            Plain(w[1]),
            Plain(w[2]),
            Plain(v[0]),
            Plain(v[1]),
            Plain(mu),
            Plain(e)
        );
        s.push_str(&t.render());
        s.push_str(&crate::output::fmt::notes(&notes));
        s
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}
