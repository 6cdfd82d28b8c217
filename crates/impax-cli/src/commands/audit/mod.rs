//! `impax audit SCENARIO`: what an engine computes at one impact, and how far it is from the
//! rigid-body answer.
//!
//! The exact Darboux–Keller laws (`newton`, `poisson`, `energetic`) are shown beside the two
//! engine-style rules: `lcp` (the velocity-level complementarity impact that sequential-impulse
//! and projected Gauss–Seidel engines converge to, validated against pymunk) and `whittaker`
//! (Newton's restitution with Coulomb friction on the total impulse, the closed-form rule of
//! simple engines). Each engine-style rule is compared with `energetic` (Stronge's energetic
//! restitution, which never creates energy): the differences of the velocities after, of `ΔT`
//! and of `T⁺/T⁻`, and a verdict in words. Scenarios: the built-in `sphere`, `rod` and
//! `double-pendulum` (through the mechanism code), mechanism files, and planar or 3D body
//! files as `impax compare` reads them.
//!
//! The systems struck at several contacts at once ([`multi`]: `rod-flat`, `rocking-block`,
//! `cradle`, `ball-ball-wall`) are audited the same way with their own laws: `lcp` (what
//! sequential-impulse / projected Gauss–Seidel engines converge to) and `sequential` (one
//! contact at a time, the binary collisions of event-driven codes) against `lzb`, the
//! energetically consistent multiple-impact law.

mod multi;
mod robot;

use crate::cli::{AuditArgs, CompareArgs};
use crate::input::{finite_flag, CliError, CliResult};
use crate::output::fmt::{signed, Table};
use crate::output::json::{self, num};
use crate::sources::mechanism::{self, MechanismSpec};
use crate::sources::{File, Source};
use impax::mechanism::impact::MechanismImpact;
use impax::mechanism::Mechanism;
use impax::planar::{Breakdown, Verdict};
use impax::LawId;
use serde_json::{json, Value};

/// The laws of a one-contact audit, in presentation order: the exact ones, then the
/// engine-style ones.
pub const LAWS: [LawId; 5] = [
    LawId::Newton,
    LawId::Poisson,
    LawId::Energetic,
    LawId::Lcp,
    LawId::Whittaker,
];
/// The engine-style rules audited against [`REFERENCE`].
pub const ENGINE_RULES: [LawId; 2] = [LawId::Lcp, LawId::Whittaker];
/// The rigid-body answer the engine-style rules are measured against.
pub const REFERENCE: LawId = LawId::Energetic;

/// The built-in scenarios and their default coefficients `(μ, e)`: the seed's sphere
/// (30° from the normal, no spin), the rod of docs/src/engine-audit.md (50° to the floor, translating at
/// (0.5, −1)) and Kane & Levinson's double pendulum.
const BUILT_INS: [(&str, f64, f64); 3] = [
    ("sphere", 0.4, 0.7),
    ("rod", 0.8, 1.0),
    ("double-pendulum", 0.5, 0.5),
];

/// One law's result at the level of the bodies.
struct Row {
    law: LawId,
    result: Result<RowData, Breakdown>,
}

/// What the audit needs of an outcome, planar or spatial.
struct RowData {
    verdict: Verdict,
    energy_change: f64,
    phases: String,
    /// The velocities after, in the order of [`Audit::names`].
    velocities: Vec<f64>,
    /// The outcome's JSON entry (the keys of `impax compare --json`).
    entry: serde_json::Map<String, Value>,
}

impl RowData {
    fn planar(o: &impax::planar::Outcome, velocities: Vec<f64>) -> Self {
        Self {
            verdict: o.verdict,
            energy_change: o.energy_change,
            phases: o.phases.summary(),
            velocities,
            entry: json::outcome_fields(o, "contact_velocity_after"),
        }
    }
}

/// Everything an audit reports, whatever the scenario's kind.
struct Audit {
    description: String,
    /// The law the engine-style rules are measured against.
    reference: LawId,
    /// How the verdicts name the reference, e.g. "the rigid-body answer (`energetic`)".
    reference_label: &'static str,
    /// The engine-style rules, in presentation order.
    engine_rules: &'static [LawId],
    /// The table's legend of the roles.
    legend: &'static str,
    /// Names of the velocity components (generalized velocities or body velocities).
    names: Vec<String>,
    before: Vec<f64>,
    energy_before: f64,
    /// The contact-space problem as JSON and as a line of text.
    problem: Value,
    problem_line: String,
    rows: Vec<Row>,
}

impl Audit {
    /// The role of a law in the audit.
    fn role(&self, law: LawId) -> &'static str {
        if self.engine_rules.contains(&law) {
            "engine"
        } else {
            "exact"
        }
    }
}

/// How a one-contact audit names its reference.
const RIGID_BODY_ANSWER: &str = "the rigid-body answer (`energetic`)";

/// The legend of a one-contact audit's table.
const LEGEND: &str = "exact: the Darboux–Keller integration (energetic: the rigid-body answer); engine: lcp = what sequential-impulse / PGS engines converge to (checked against pymunk), whittaker = restitution + Coulomb on the total impulse";

/// The header line of a planar contact-space problem.
fn planar_line(p: &impax::planar::ContactProblem, t0: f64) -> String {
    let v = p.velocity();
    format!(
        "contact space: W = [[{:.6}, {:.6}], [{:.6}, {:.6}]], v⁻ = ({:.6}, {:.6}); T⁻ = {:.6}",
        p.wtt(),
        p.wtn(),
        p.wtn(),
        p.wnn(),
        v.x,
        v.y,
        t0
    )
}

pub fn run(args: &AuditArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let audit = build(args)?;
    let text = if args.json {
        serde_json::to_string_pretty(&document(&audit)).map_err(CliError::failure)? + "\n"
    } else {
        table(&audit)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn build(args: &AuditArgs) -> CliResult<Audit> {
    let source = args.scenario.as_str();
    if let Some(x) = args.friction {
        finite_flag("friction", x)?;
    }
    if let Some(x) = args.restitution {
        finite_flag("restitution", x)?;
    }
    if multi::BUILT_INS.contains(&source) {
        return multi::build(source, args);
    }
    let multi_flag = args.mass.is_some().then_some("mass");
    if let Some(flag) = args.multi.given().first().copied().or(multi_flag) {
        return Err(CliError::input(format!(
            "--{flag}: only for the systems struck at several contacts ({})",
            multi::BUILT_INS.join(", ")
        )));
    }
    if let Some(&(name, mu, e)) = BUILT_INS.iter().find(|b| b.0 == source) {
        let mut flags = mechanism_flags(args);
        flags.friction = Some(args.friction.unwrap_or(mu));
        flags.restitution = Some(args.restitution.unwrap_or(e));
        return mechanism_audit(&Source::BuiltInMechanism(name.into()), &flags);
    }
    if impax::mechanism::builtin::BuiltIn::NAMES.contains(&source) {
        return Err(CliError::input(format!(
            "scenario: `{source}` has no impact to audit (built-in scenarios: {}; or a TOML file)",
            names()
        )));
    }
    let unreadable = |e| {
        CliError::input(format!(
            "scenario: `{source}` is neither a built-in scenario ({}) nor a readable file: {e}",
            names()
        ))
    };
    let file = match Source::classify(source, &[], unreadable)? {
        Source::Mechanism(file) => {
            return mechanism_audit(&Source::Mechanism(file), &mechanism_flags(args))
        }
        Source::Spatial(file) | Source::Planar(file) => file,
        Source::BuiltInMechanism(_) => unreachable!("no built-in names were given"),
        Source::Robot(file) => return robot::audit(&file, args),
    };
    let radius = args.radius.is_some().then_some("radius");
    if let Some(flag) = args.mechanism.first_given().or(radius) {
        return Err(CliError::input(format!(
            "--{flag}: only for a built-in scenario or a mechanism file; edit the body scenario file instead"
        )));
    }
    if crate::commands::compare::spatial::is_spatial(&file.text) {
        return spatial_audit(&file.name, &file.text, args);
    }
    body_audit(&file, args)
}

fn names() -> String {
    BUILT_INS
        .map(|b| b.0)
        .iter()
        .chain(multi::BUILT_INS.iter())
        .copied()
        .collect::<Vec<_>>()
        .join(", ")
}

fn mechanism_flags(args: &AuditArgs) -> MechanismSpec {
    MechanismSpec {
        mechanism: String::new(),
        friction: args.friction,
        restitution: args.restitution,
        laws: None,
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

/// A built-in scenario or a mechanism TOML file, through the mechanism's contact problem.
fn mechanism_audit(source: &Source, flags: &MechanismSpec) -> CliResult<Audit> {
    let spec = mechanism::load_source(source, flags)?;
    // A file's `laws` are for `compare`; an audit always shows its own laws.
    let case = mechanism::build(&spec)?;
    if case.mechanism.contacts().is_empty() {
        return Err(CliError::input(format!(
            "{}: has no contact point to strike",
            spec.mechanism
        )));
    }
    let friction = spec.friction.unwrap_or(0.5);
    let restitution = spec.restitution.unwrap_or(0.5);
    let impact = MechanismImpact::striking(&case.mechanism, &case.q, &case.u)?;
    let problem = impact.problem(friction, restitution)?;
    let mut rows = Vec::new();
    for law in LAWS {
        let r = impact.resolve(law, friction, restitution)?;
        rows.push(Row {
            law,
            result: r.resolution.map(|o| {
                RowData::planar(&o, r.velocities_after.expect("applied to the mechanism"))
            }),
        });
    }
    let t0 = impact.energy_before();
    Ok(Audit {
        description: format!("{}; μ = {friction}, e = {restitution}", case.description),
        reference: REFERENCE,
        reference_label: RIGID_BODY_ANSWER,
        engine_rules: &ENGINE_RULES,
        legend: LEGEND,
        names: case
            .mechanism
            .coordinates()
            .iter()
            .map(|c| format!("{c}'"))
            .collect(),
        before: case.u.clone(),
        energy_before: t0,
        problem: json::problem(&problem),
        problem_line: planar_line(&problem, t0),
        rows,
    })
}

/// A body scenario file (`impax compare`'s format, planar).
fn body_audit(file: &File, args: &AuditArgs) -> CliResult<Audit> {
    let compare = CompareArgs {
        scenario: Some(file.name.clone().into()),
        alpha_deg: None,
        restitution: args.restitution,
        friction: args.friction,
        spin_ratio: None,
        mass: None,
        radius: None,
        speed: None,
        law: Vec::new(),
        mechanism: Default::default(),
        multi: Default::default(),
        json: args.json,
        plot: None,
    };
    let sc = crate::sources::scenario::load(&compare, Some(file))?;
    let problem = sc.impact.problem(sc.friction, sc.restitution)?;
    let state = |s: &impax::planar::bodies::BodyState| vec![s.velocity.x, s.velocity.y, s.omega];
    let mut names: Vec<String> = ["vx", "vy", "omega"].map(String::from).to_vec();
    let mut before = state(&sc.impact.body.1);
    if let Some(o) = &sc.impact.other {
        names.extend(["other.vx", "other.vy", "other.omega"].map(String::from));
        before.extend(state(&o.1));
    }
    let rows = LAWS
        .iter()
        .map(|&law| Row {
            law,
            result: sc.impact.resolve(law, &problem).map(|b| {
                let mut v = state(&b.body_after);
                if let Some(o) = &b.other_after {
                    v.extend(state(o));
                }
                RowData::planar(&b.outcome, v)
            }),
        })
        .collect();
    let t0 = sc.impact.energy_before().total();
    Ok(Audit {
        description: format!(
            "{}; μ = {}, e = {}",
            sc.description, sc.friction, sc.restitution
        ),
        reference: REFERENCE,
        reference_label: RIGID_BODY_ANSWER,
        engine_rules: &ENGINE_RULES,
        legend: LEGEND,
        names,
        before,
        energy_before: t0,
        problem: json::problem(&problem),
        problem_line: planar_line(&problem, t0),
        rows,
    })
}

/// A `space = "3d"` scenario file (`impax compare`'s format): the spatial laws.
fn spatial_audit(source: &str, text: &str, args: &AuditArgs) -> CliResult<Audit> {
    let (impact, desc, spec) = crate::commands::compare::spatial::load(source, text)?;
    let friction = args.friction.unwrap_or(spec.friction);
    let restitution = args.restitution.unwrap_or(spec.restitution);
    let problem = impact.problem(friction, restitution)?;
    let (ea, eb) = impact.energy_before();
    let t0 = ea.total() + eb.total();
    let two = impact.other.is_some();
    let state = |s: &impax::spatial::bodies::BodyState| {
        vec![
            s.velocity.x,
            s.velocity.y,
            s.velocity.z,
            s.omega.x,
            s.omega.y,
            s.omega.z,
        ]
    };
    let mut names: Vec<String> = ["vx", "vy", "vz", "omega_x", "omega_y", "omega_z"]
        .map(String::from)
        .to_vec();
    let mut before = state(&impact.body.1);
    if let Some(o) = &impact.other {
        names.extend(
            names
                .clone()
                .iter()
                .map(|n| format!("other.{n}"))
                .collect::<Vec<_>>(),
        );
        before.extend(state(&o.1));
    }
    let rows = LAWS
        .iter()
        .map(|&law| {
            let r = impact.resolve(law, &problem);
            let entry = crate::commands::compare::spatial::entry(&problem, law, &r, t0, two);
            Row {
                law,
                result: r.map(|b| {
                    let mut v = state(&b.body_after);
                    if let Some(o) = &b.other_after {
                        v.extend(state(o));
                    }
                    RowData {
                        verdict: b.outcome.verdict,
                        energy_change: b.outcome.energy_change,
                        phases: b.outcome.phases.summary(),
                        velocities: v,
                        entry: match entry {
                            Value::Object(m) => m,
                            _ => serde_json::Map::new(),
                        },
                    }
                }),
            }
        })
        .collect();
    let w = problem.w();
    let v = problem.velocity();
    Ok(Audit {
        description: format!("{desc}; μ = {friction}, e = {restitution}"),
        reference: REFERENCE,
        reference_label: RIGID_BODY_ANSWER,
        engine_rules: &ENGINE_RULES,
        legend: LEGEND,
        names,
        before,
        energy_before: t0,
        problem: json!({
            "w": [[w[(0, 0)], w[(0, 1)], w[(0, 2)]], [w[(1, 0)], w[(1, 1)], w[(1, 2)]], [w[(2, 0)], w[(2, 1)], w[(2, 2)]]],
            "v": { "t1": num(v.x), "t2": num(v.y), "n": num(v.z) },
            "friction": friction,
            "restitution": restitution,
        }),
        problem_line: format!(
            "contact space (3D): W = [[{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}]], v⁻ = ({:.6}, {:.6}, {:.6}); T⁻ = {:.6}",
            w[(0, 0)], w[(0, 1)], w[(0, 2)], w[(1, 0)], w[(1, 1)], w[(1, 2)], w[(2, 0)], w[(2, 1)], w[(2, 2)], v.x, v.y, v.z, t0
        ),
        rows,
    })
}

/// Every verdict id of an engine-style rule (`engine_rules[].verdict.id` of `--json`), each
/// documented in the book (`docs/src/reference/ids.md`, "Audit verdicts").
pub const VERDICT_IDS: [&str; 7] = [
    "gains-energy",
    "matches",
    "redistributes",
    "dissipates-more",
    "dissipates-less",
    "breakdown",
    "no-reference",
];

/// The comparison of one engine-style rule with the reference.
struct Judgement {
    law: LawId,
    /// `u_rule − u_reference`, per velocity component (None on a breakdown).
    velocity_differences: Option<Vec<f64>>,
    energy_change_difference: Option<f64>,
    ratio: Option<f64>,
    reference_ratio: Option<f64>,
    id: &'static str,
    text: String,
}

fn percent(x: f64) -> String {
    format!("{:.1} %", 100.0 * x)
}

/// The verdict of one engine-style rule against the reference, in words.
fn judge(audit: &Audit, law: LawId) -> Judgement {
    let find = |l: LawId| audit.rows.iter().find(|r| r.law == l).expect("audited law");
    let rule = find(law);
    let reference = find(audit.reference);
    let t0 = audit.energy_before;
    let name = match law {
        LawId::Lcp => "an engine of this kind (sequential impulses / projected Gauss–Seidel: Box2D, Chipmunk, Bullet)",
        LawId::Sequential => "an engine of this kind (one contact at a time: the binary collisions of event-driven codes)",
        _ => "an engine of this kind (restitution and Coulomb friction on the total impulse)",
    };
    let label = audit.reference_label;
    let (o, u) = match &rule.result {
        Ok(d) => (d, &d.velocities),
        Err(b) => {
            return Judgement {
                law,
                velocity_differences: None,
                energy_change_difference: None,
                ratio: None,
                reference_ratio: None,
                id: "breakdown",
                text: format!("{name} has no answer here: {}", b.reason),
            }
        }
    };
    let ratio = (t0 + o.energy_change) / t0;
    let Ok(r) = &reference.result else {
        return Judgement {
            law,
            velocity_differences: None,
            energy_change_difference: None,
            ratio: Some(ratio),
            reference_ratio: None,
            id: "no-reference",
            text: format!(
                "{name}: the reference law `{}` has no answer here",
                audit.reference
            ),
        };
    };
    let ref_ratio = (t0 + r.energy_change) / t0;
    let ur = &r.velocities;
    let diffs: Vec<f64> = u.iter().zip(ur).map(|(a, b)| a - b).collect();
    let scale = audit
        .before
        .iter()
        .chain(ur.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    let largest = diffs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let reference_words = if ref_ratio <= 1.0 {
        format!("{label} dissipates {}", percent(1.0 - ref_ratio))
    } else {
        format!("{label} returns {}", percent(ref_ratio - 1.0))
    };
    let (id, text) = if o.verdict == Verdict::EnergyGained {
        (
            "gains-energy",
            format!(
                "{name} returns {} more energy than the bodies brought into this impact (T⁺/T⁻ = {ratio:.4}): energy from nowhere, where {reference_words} (T⁺/T⁻ = {ref_ratio:.4})",
                percent(ratio - 1.0)
            ),
        )
    } else if largest > 1e-9 * scale && (ratio - ref_ratio).abs() <= 1e-9 {
        (
            "redistributes",
            format!(
                "{name} ends with the same kinetic energy as {label} (T⁺/T⁻ = {ratio:.4}) but shares it differently between the bodies"
            ),
        )
    } else if largest <= 1e-9 * scale {
        (
            "matches",
            format!(
                "{name} gets this impact right: it matches {label} to {:.1e} (T⁺/T⁻ = {ratio:.4})",
                largest / scale
            ),
        )
    } else if ratio < ref_ratio {
        (
            "dissipates-more",
            format!(
                "{name} dissipates {} of the kinetic energy here, {} of T⁻ more than it should: {reference_words}",
                percent(1.0 - ratio),
                percent(ref_ratio - ratio)
            ),
        )
    } else {
        (
            "dissipates-less",
            format!(
                "{name} dissipates {} of the kinetic energy here, {} of T⁻ less than it should: {reference_words}",
                percent(1.0 - ratio),
                percent(ratio - ref_ratio)
            ),
        )
    };
    let text = if id == "matches" {
        text
    } else {
        format!(
            "{text}; its velocities after differ from {} by up to {:.4}",
            label.split(" (").next().unwrap_or(label),
            largest
        )
    };
    Judgement {
        law,
        velocity_differences: Some(diffs),
        energy_change_difference: Some(o.energy_change - r.energy_change),
        ratio: Some(ratio),
        reference_ratio: Some(ref_ratio),
        id,
        text,
    }
}

fn document(audit: &Audit) -> Value {
    let t0 = audit.energy_before;
    let results: Vec<Value> = audit
        .rows
        .iter()
        .map(|row| {
            let mut m = match &row.result {
                Ok(d) => {
                    let mut m = d.entry.clone();
                    m.insert(
                        "velocities_after".into(),
                        json!(d.velocities.iter().map(|&x| num(x)).collect::<Vec<_>>()),
                    );
                    m.insert("energy_after".into(), num(t0 + d.energy_change));
                    m.insert("energy_ratio".into(), num((t0 + d.energy_change) / t0));
                    m
                }
                Err(b) => {
                    let mut m = json::breakdown_fields(b, "contact_velocity_after", false);
                    for k in ["velocities_after", "energy_after", "energy_ratio"] {
                        m.insert(k.into(), Value::Null);
                    }
                    m
                }
            };
            m.insert("role".into(), json!(audit.role(row.law)));
            Value::Object(m)
        })
        .collect();
    let engine: Vec<Value> = audit
        .engine_rules
        .iter()
        .map(|&law| {
            let j = judge(audit, law);
            debug_assert!(VERDICT_IDS.contains(&j.id), "undocumented verdict {}", j.id);
            json!({
                "law": j.law.as_str(),
                "reference": audit.reference.as_str(),
                "velocities_after_difference": j.velocity_differences.as_ref().map(|d| d.iter().map(|&x| num(x)).collect::<Vec<_>>()),
                "largest_velocity_difference": j.velocity_differences.as_ref().map(|d| num(d.iter().fold(0.0f64, |m, x| m.max(x.abs())))),
                "energy_change_difference": j.energy_change_difference.map(num),
                "energy_ratio": j.ratio.map(num),
                "reference_energy_ratio": j.reference_ratio.map(num),
                "verdict": { "id": j.id, "text": j.text },
            })
        })
        .collect();
    json!({
        "scenario": audit.description,
        "velocity_names": audit.names,
        "velocities_before": audit.before,
        "problem": audit.problem,
        "energy_before": num(t0),
        "reference": audit.reference.as_str(),
        "results": results,
        "engine_rules": engine,
    })
}

fn table(audit: &Audit) -> String {
    let t0 = audit.energy_before;
    let mut columns: Vec<(String, bool)> = vec![("law".into(), false), ("role".into(), false)];
    for n in &audit.names {
        columns.push((format!("{n}+"), true));
    }
    columns.extend([
        ("ΔT".into(), true),
        ("T+/T-".into(), true),
        ("phases".into(), false),
        ("verdict".into(), false),
    ]);
    let cols: Vec<(&str, bool)> = columns.iter().map(|(s, r)| (s.as_str(), *r)).collect();
    let mut t = Table::new(&cols);
    for row in &audit.rows {
        let mut cells = vec![row.law.to_string(), audit.role(row.law).to_string()];
        match &row.result {
            Ok(d) => {
                cells.extend(d.velocities.iter().map(|&x| signed(x, 5)));
                cells.push(signed(d.energy_change, 5));
                cells.push(format!("{:.4}", (t0 + d.energy_change) / t0));
                cells.push(d.phases.clone());
                cells.push(d.verdict.id().to_string());
            }
            Err(_) => {
                cells.extend(std::iter::repeat_n("—".to_string(), audit.names.len() + 3));
                cells.push("breakdown".into());
            }
        }
        t.row(cells);
    }
    let mut s = format!(
        "impax audit — {}\n{}\n\n",
        audit.description, audit.problem_line
    );
    s.push_str(&t.render());
    s.push('\n');
    s.push_str(audit.legend);
    s.push_str("\n\n");
    let difference = format!("engine rule − {}", audit.reference);
    let mut d = Table::new(&[
        (difference.as_str(), false),
        ("largest |Δu|", true),
        ("Δ(ΔT)", true),
        ("Δ(T+/T-)", true),
    ]);
    let judgements: Vec<Judgement> = audit
        .engine_rules
        .iter()
        .map(|&l| judge(audit, l))
        .collect();
    debug_assert!(judgements.iter().all(|j| VERDICT_IDS.contains(&j.id)));
    for j in &judgements {
        match (
            &j.velocity_differences,
            j.energy_change_difference,
            j.ratio,
            j.reference_ratio,
        ) {
            (Some(dv), Some(de), Some(r), Some(rr)) => d.row(vec![
                j.law.to_string(),
                format!("{:.5}", dv.iter().fold(0.0f64, |m, x| m.max(x.abs()))),
                signed(de, 5),
                signed(r - rr, 5),
            ]),
            _ => d.row(vec![j.law.to_string(), "—".into(), "—".into(), "—".into()]),
        }
    }
    s.push_str(&d.render());
    s.push('\n');
    for j in &judgements {
        s.push_str(&format!("verdict — {}: {}\n", j.law, j.text));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::VERDICT_IDS;

    /// `no-reference` was printed by `--json` but missing from the documented list of ids.
    #[test]
    fn every_verdict_id_is_documented() {
        let ids = include_str!("../../../../../docs/src/reference/ids.md");
        let start = ids.find("## Audit verdicts").expect("the audit verdicts");
        let end = start + ids[start..].find("\n## ").expect("the next section");
        let section = &ids[start..end];
        for id in VERDICT_IDS {
            assert!(
                section.contains(&format!("`{id}`")),
                "`{id}` is not documented"
            );
        }
    }
}
