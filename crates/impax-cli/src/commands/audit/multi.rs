//! `impax audit NAME` for the systems struck at several contacts at once (`rod-flat`,
//! `rocking-block`, `cradle`, `ball-ball-wall`, in 3D `box-flat`; `impax::multi::scenarios`): the engine-style
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
use crate::commands::compare::multi::{built_in, resolve_all};
use crate::input::{finite_flag, CliError, CliResult};
use crate::output::fmt::Plain;
use impax::LawId;

/// The built-ins' names.
pub const BUILT_INS: [&str; 5] = crate::commands::compare::multi::BUILT_INS;

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
    let ids: Vec<String> = LAWS.iter().map(|l| l.as_str().to_string()).collect();
    let (view, rows) = resolve_all(
        name,
        &sc,
        args.friction,
        args.restitution,
        &args.multi,
        &ids,
    )?;
    let rows: Vec<Row> = rows
        .into_iter()
        .map(|r| Row {
            law: r.law,
            result: r.result.map(|o| RowData {
                verdict: o.verdict,
                energy_change: o.energy_change,
                phases: o.phases.join(" | "),
                velocities: o.velocities_after,
                entry: match r.entry {
                    serde_json::Value::Object(m) => m,
                    _ => serde_json::Map::new(),
                },
            }),
        })
        .collect();
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
    Ok(Audit {
        description: format!(
            "{}; μ = {}, e = {}{}",
            sc.description,
            Plain(view.friction),
            Plain(view.restitution),
            view.force_law
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
        problem_line: format!(
            "contact space: {} contacts, W {n} × {n} of rank {}; v⁻ = {}: {}; T⁻ = {t0:.6}",
            sc.impact.contacts().len(),
            view.rank,
            view.frame,
            view.contacts,
            n = view.size
        ),
        problem: view.json,
        rows,
    })
}
