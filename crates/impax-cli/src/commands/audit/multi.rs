//! `impax audit NAME` for the systems struck at several contacts at once (`rod-flat`,
//! `rocking-block`, `cradle`, `ball-ball-wall`; `impax::multi::scenarios`): the engine-style
//! rules `lcp` and `sequential` against `lzb`.
//!
//! `lzb` (Liu, Zhao & Brogliato 2008, 2009; with friction Zhao, Liu & Brogliato 2009) follows
//! the contacts' stored energies through the impact and never creates energy; `lcp` is the
//! velocity-level complementarity impact at every contact at once that projected Gauss–Seidel
//! and sequential-impulse engines converge to (checked against pymunk); `sequential` resolves
//! one contact at a time with the one-contact `energetic` law, as event-driven codes do with
//! binary collisions. Newton's cradle is the classic: `lcp` sends the first ball back and moves
//! the others together, `sequential` and `lzb` pass the momentum down the row.

use super::{Audit, Row, RowData};
use crate::cli::AuditArgs;
use crate::commands::compare::multi::{built_in, problem};
use crate::input::{finite_flag, CliError, CliResult};
use crate::output::fmt::Plain;
use crate::output::json;
use impax::LawId;

/// The built-ins' names.
pub const BUILT_INS: [&str; 4] = crate::commands::compare::multi::BUILT_INS;

/// The laws of a multi-contact audit, in presentation order.
const LAWS: [LawId; 3] = [LawId::Lzb, LawId::Lcp, LawId::Sequential];

/// The engine-style rules, audited against [`REFERENCE`].
const ENGINE_RULES: [LawId; 2] = [LawId::Lcp, LawId::Sequential];

/// The energetically consistent multiple-impact law.
const REFERENCE: LawId = LawId::Lzb;

const LEGEND: &str = "exact: lzb = the energetically consistent multiple-impact law (Liu, Zhao & Brogliato); engine: lcp = what sequential-impulse / PGS engines converge to (checked against pymunk), sequential = one contact at a time (binary collisions)";

/// The audit of the built-in `name`.
pub fn build(name: &str, args: &AuditArgs) -> CliResult<Audit> {
    if let Some(flag) = args.mechanism.first_given() {
        return Err(CliError::input(format!(
            "--{flag}: not a parameter of `{name}` (see impax compare {name} --help)"
        )));
    }
    if let Some(x) = args.friction {
        finite_flag("friction", x)?;
    }
    if let Some(x) = args.restitution {
        finite_flag("restitution", x)?;
    }
    let sc = built_in(name, args.mass, args.radius, &args.multi)?;
    let problem = problem(name, &sc, args.friction, args.restitution, &args.multi)?;
    let k = problem.contacts();
    let rows = LAWS
        .iter()
        .map(|&law| {
            let r = sc.impact.resolve(law, &problem)?;
            let entry = match json::multi_entry(&r.resolution) {
                serde_json::Value::Object(m) => m,
                _ => serde_json::Map::new(),
            };
            let result = match (r.resolution, r.velocities_after) {
                (Ok(o), Some(velocities)) => Ok(RowData {
                    verdict: o.verdict,
                    energy_change: o.energy_change,
                    phases: o
                        .contacts
                        .iter()
                        .map(|c| c.phase_summary())
                        .collect::<Vec<_>>()
                        .join(" | "),
                    velocities,
                    entry,
                }),
                (Err(b), _) => Err(b),
                (Ok(_), None) => unreachable!("a resolved impact is applied to the system"),
            };
            Ok(Row { law, result })
        })
        .collect::<CliResult<Vec<_>>>()?;
    // The coordinates worth reporting: those moving before, or after under some law (a
    // cradle's vertical velocities and spins stay zero).
    let before = sc.impact.velocities_before();
    let scale = before.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let moving: Vec<usize> = (0..before.len())
        .filter(|&i| {
            before[i] != 0.0
                || rows.iter().any(|r| {
                    r.result
                        .as_ref()
                        .is_ok_and(|d| d.velocities[i].abs() > 1e-12 * scale)
                })
        })
        .collect();
    let pick = |u: &[f64]| moving.iter().map(|&i| u[i]).collect::<Vec<f64>>();
    let rows: Vec<Row> = rows
        .into_iter()
        .map(|r| Row {
            law: r.law,
            result: r.result.map(|d| RowData {
                velocities: pick(&d.velocities),
                ..d
            }),
        })
        .collect();
    let t0 = sc.impact.energy_before();
    let v: Vec<String> = (0..k)
        .map(|j| {
            let c = problem.contact_velocity(j);
            format!("{} ({:.6}, {:.6})", sc.impact.contacts()[j], c.x, c.y)
        })
        .collect();
    Ok(Audit {
        description: format!(
            "{}; μ = {}, e = {}{}",
            sc.description,
            Plain(problem.friction(0)),
            Plain(problem.restitution(0)),
            crate::commands::resolve::force_law(&problem)
        ),
        reference: REFERENCE,
        reference_label: "the multiple-impact answer (`lzb`)",
        engine_rules: &ENGINE_RULES,
        legend: LEGEND,
        names: moving
            .iter()
            .map(|&i| format!("{}'", sc.impact.coordinates()[i]))
            .collect(),
        before: pick(before),
        energy_before: t0,
        problem: json::multi_problem(&problem),
        problem_line: format!(
            "contact space: {k} contacts, W {n} × {n} of rank {}; v⁻ = (v_t, v_n): {}; T⁻ = {t0:.6}",
            problem.rank(),
            v.join(", "),
            n = 2 * k
        ),
        rows,
    })
}
