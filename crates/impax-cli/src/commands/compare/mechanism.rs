//! `impax compare MECHANISM`: every law side by side on an impact of a built-in mechanism
//! (e.g. Kane & Levinson's double pendulum), with the kinetic energy before and after.

use crate::cli::CompareArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Table};
use crate::output::json;
use crate::sources::mechanism::{self, MechanismCase, MechanismSpec};
use crate::sources::scenario::parse_laws;
use crate::sources::Source;
use impax::mechanism::impact::{MechanismImpact, MechanismOutcome};
use impax::mechanism::Mechanism;
use impax::planar::Verdict;
use impax::LawId;

/// The mechanism flags of `compare` as a spec (for merging over a file or a built-in).
pub fn flags(args: &CompareArgs) -> MechanismSpec {
    MechanismSpec {
        mechanism: String::new(),
        friction: args.friction,
        restitution: args.restitution,
        laws: (!args.law.is_empty()).then(|| args.law.clone()),
        masses: args.mechanism.masses.clone(),
        lengths: args.mechanism.lengths.clone(),
        radius: args.radius,
        gravity: args.mechanism.gravity,
        angles: args.mechanism.angles_deg.clone(),
        rates: args.mechanism.rates.clone(),
        position: args.mechanism.position.clone(),
        q: args.mechanism.q.clone(),
        u: args.mechanism.u.clone(),
        file: None,
        angle_unit: Default::default(),
    }
}

pub fn run(args: &CompareArgs, source: &Source, out: &mut Vec<u8>) -> CliResult<()> {
    for (flag, given) in [
        ("alpha-deg", args.alpha_deg.is_some()),
        ("spin-ratio", args.spin_ratio.is_some()),
        ("speed", args.speed.is_some()),
        ("mass", args.mass.is_some()),
        ("plot", args.plot.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not a parameter of a mechanism (use --angles-deg, --rates, --masses, --lengths)"
            )));
        }
    }
    let spec = mechanism::load_source(source, &flags(args))?;
    let case = mechanism::build(&spec)?;
    let friction = spec.friction.unwrap_or(impax::scenario::DEFAULT_FRICTION);
    let restitution = spec
        .restitution
        .unwrap_or(impax::scenario::DEFAULT_RESTITUTION);
    let laws = match &spec.laws {
        Some(ids) => parse_laws(ids)?,
        None => LawId::CONTACT_SPACE.to_vec(),
    };
    if case.mechanism.contacts().is_empty() {
        return Err(CliError::input(format!(
            "{}: has no contact point to strike (try `impax conserved {}`)",
            spec.mechanism, spec.mechanism
        )));
    }
    let impact = MechanismImpact::striking(&case.mechanism, &case.q, &case.u)?;
    let problem = impact.problem(friction, restitution)?;
    let results = laws
        .iter()
        .map(|&law| Ok((law, impact.resolve(law, friction, restitution)?)))
        .collect::<CliResult<Vec<_>>>()?;
    let text = if args.json {
        serde_json::to_string_pretty(&json::mechanism_document(
            &spec.mechanism,
            &case.description,
            &impact,
            &case.u,
            &problem,
            &results,
        ))
        .map_err(CliError::failure)?
            + "\n"
    } else {
        table(&case, &impact, &problem, &results)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn table(
    case: &MechanismCase,
    impact: &MechanismImpact<'_, impax::mechanism::builtin::BuiltIn>,
    problem: &impax::planar::ContactProblem,
    results: &[(LawId, MechanismOutcome)],
) -> String {
    let m = &case.mechanism;
    let coords = m.coordinates();
    let t0 = impact.energy_before();
    let mut columns: Vec<(String, bool)> = vec![("law".into(), false)];
    for c in coords {
        columns.push((format!("{c}+"), true));
    }
    columns.extend([
        ("vt+".into(), true),
        ("vn+".into(), true),
        ("ΔT".into(), true),
        ("T+/T-".into(), true),
        ("phases".into(), false),
        ("verdict".into(), false),
    ]);
    let cols: Vec<(&str, bool)> = columns.iter().map(|(s, r)| (s.as_str(), *r)).collect();
    let mut t = Table::new(&cols);
    let mut notes = Vec::new();
    for (law, r) in results {
        match &r.resolution {
            Ok(o) => {
                let after = r.velocities_after.as_ref().expect("applied");
                let mut row = vec![law.to_string()];
                row.extend(after.iter().map(|&x| signed(x, 5)));
                let verdict = match o.verdict {
                    Verdict::Consistent => "consistent".to_string(),
                    Verdict::EnergyGained => "ENERGY GAINED (Kane's paradox)".to_string(),
                    Verdict::InconsistentAssumption => "inconsistent assumption".to_string(),
                };
                if let Some(i) = o.inconsistency {
                    notes.push(format!("{law}: {i}"));
                }
                let phases: Vec<String> = o
                    .phases
                    .as_slice()
                    .iter()
                    .map(|p| format!("{}@{:.4}", p.kind.label(), p.ends_at))
                    .collect();
                row.extend([
                    signed(o.velocity_after.x, 5),
                    signed(o.velocity_after.y, 5),
                    signed(o.energy_change, 5),
                    format!("{:.5}", (t0 + o.energy_change) / t0),
                    phases.join(" → "),
                    verdict,
                ]);
                t.row(row);
            }
            Err(b) => {
                t.breakdown_row(law, "BREAKDOWN");
                notes.push(format!("{law}: breakdown: {}", b.reason));
            }
        }
    }
    let w = problem.w();
    let v = problem.velocity();
    let mut text = format!(
        "impax compare — {}; μ = {}, e = {}\ncontact ({}): W = J M⁻¹ Jᵀ = [[{:.6}, {:.6}], [{:.6}, {:.6}]], v⁻ = ({:.6}, {:.6}); T⁻ = {:.6}\n\n",
        case.description,
        problem.friction(),
        problem.restitution(),
        m.contacts()[impact.contact()].name,
        w[(0, 0)],
        w[(0, 1)],
        w[(1, 0)],
        w[(1, 1)],
        v.x,
        v.y,
        t0,
    );
    text.push_str(&t.render());
    text.push_str(&format!(
        "\n{}: generalized velocities after; vt+, vn+: contact velocity after; ΔT = T⁺ − T⁻\n",
        coords
            .iter()
            .map(|c| format!("{c}+"))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    text.push_str(&crate::output::fmt::notes(&notes));
    text
}
