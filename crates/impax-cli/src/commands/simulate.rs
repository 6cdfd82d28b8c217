//! `impax simulate SCENARIO`: trajectories with impacts — a table of impacts, JSON, the
//! sampled trajectory as CSV, a plot of the motion and its energy, an animated SVG.
//!
//! Scenario files (TOML) name a built-in and override its parameters:
//!
//! ```toml
//! simulation = "bouncing-ball"   # bouncing-ball | rod-drop | double-pendulum-drop | rocking-block | cradle
//! law = "energetic"
//! friction = 0.3
//! restitution = 0.8
//! until = 5.0
//! height = 1.0                    # the flags' names, with underscores
//! alpha_deg = 30.0
//! spin_ratio = 0.0
//! ```

use crate::cli::SimulateArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json::num;
use crate::output::plot;
use impax::mechanism::builtin::STANDARD_GRAVITY;
use impax::mechanism::Mechanism;
use impax::simulation::scenarios::{self, Initial};
use impax::simulation::{simulate, EventKind, ImpactRecord, Run, SimulationOptions, StopReason};
use impax::LawId;
use serde::Deserialize;
use serde_json::{json, Value};
use std::io::Write;
use std::path::Path;

/// The built-in scenarios.
pub const NAMES: [&str; 5] = [
    "bouncing-ball",
    "rod-drop",
    "double-pendulum-drop",
    "rocking-block",
    "cradle",
];

/// Every parameter of every scenario (flags or TOML); each scenario accepts some.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimSpec {
    pub simulation: String,
    pub law: Option<String>,
    pub friction: Option<f64>,
    pub restitution: Option<f64>,
    pub until: Option<f64>,
    pub samples: Option<usize>,
    pub gravity: Option<f64>,
    pub mass: Option<f64>,
    pub radius: Option<f64>,
    pub height: Option<f64>,
    pub speed: Option<f64>,
    pub alpha_deg: Option<f64>,
    pub spin_ratio: Option<f64>,
    pub disc: Option<bool>,
    pub length: Option<f64>,
    pub angle_deg: Option<f64>,
    pub masses: Option<Vec<f64>>,
    pub lengths: Option<Vec<f64>>,
    pub angles_deg: Option<Vec<f64>>,
    pub rates: Option<Vec<f64>>,
    pub floor: Option<f64>,
    pub half_width: Option<f64>,
    pub half_height: Option<f64>,
    pub omega: Option<f64>,
    pub balls: Option<usize>,
    pub v0: Option<f64>,
    pub gap: Option<f64>,
}

/// What to draw for each body in pictures.
#[derive(Debug, Clone, Copy)]
pub enum Shape {
    /// A ball of this radius (with a spoke showing its rotation).
    Ball(f64),
    /// A rod of this length along its angle from the x axis.
    Rod(f64),
    /// A pendulum rod of this length, its angle from the downward vertical.
    Pendulum(f64),
    /// A rectangle of this half-width and half-height along its angle from the x axis.
    Block(f64, f64),
}

/// A scenario ready to run.
pub struct Case {
    pub name: String,
    pub description: String,
    pub initial: Initial,
    pub options: SimulationOptions,
    pub shapes: Vec<Shape>,
}

fn flags(args: &SimulateArgs) -> SimSpec {
    SimSpec {
        simulation: String::new(),
        law: args.law.clone(),
        friction: args.friction,
        restitution: args.restitution,
        until: args.until,
        samples: args.samples,
        gravity: args.gravity,
        mass: args.mass,
        radius: args.radius,
        height: args.height,
        speed: args.speed,
        alpha_deg: args.alpha_deg,
        spin_ratio: args.spin_ratio,
        disc: args.disc.then_some(true),
        length: args.length,
        angle_deg: args.angle_deg,
        masses: args.masses.clone(),
        lengths: args.lengths.clone(),
        angles_deg: args.angles_deg.clone(),
        rates: args.rates.clone(),
        floor: args.floor,
        half_width: args.half_width,
        half_height: args.half_height,
        omega: args.omega,
        balls: args.balls,
        v0: args.v0,
        gap: args.gap,
    }
}

fn merge(spec: &mut SimSpec, over: &SimSpec) {
    macro_rules! take {
        ($($f:ident),*) => { $( if over.$f.is_some() { spec.$f = over.$f.clone(); } )* };
    }
    take!(
        law,
        friction,
        restitution,
        until,
        samples,
        gravity,
        mass,
        radius,
        height,
        speed,
        alpha_deg,
        spin_ratio,
        disc,
        length,
        angle_deg,
        masses,
        lengths,
        angles_deg,
        rates,
        floor,
        half_width,
        half_height,
        omega,
        balls,
        v0,
        gap
    );
}

fn load(source: &str, over: &SimSpec) -> CliResult<SimSpec> {
    let mut spec = if NAMES.contains(&source) {
        SimSpec {
            simulation: source.into(),
            ..SimSpec::default()
        }
    } else {
        let text = std::fs::read_to_string(source).map_err(|e| {
            CliError::input(format!(
                "{source}: not a built-in scenario ({}) nor a readable file: {e}",
                NAMES.join(", ")
            ))
        })?;
        toml::from_str(&text)
            .map_err(|e| CliError::input(format!("{source}: {}", e.message().replace('\n', " "))))?
    };
    merge(&mut spec, over);
    Ok(spec)
}

/// The largest angle magnitude, in degrees, a scenario accepts: one full turn either way
/// (beyond it an angle only adds turns, and 1e308° is a typo, not a release angle).
pub const MAX_ANGLE_DEG: f64 = 360.0;

/// Check an angle in degrees: finite and at most [`MAX_ANGLE_DEG`] in magnitude.
fn angle(field: &str, deg: f64) -> CliResult<f64> {
    if deg.abs() <= MAX_ANGLE_DEG {
        Ok(deg)
    } else {
        Err(CliError::input(format!(
            "{field}: must be between -{MAX_ANGLE_DEG} and {MAX_ANGLE_DEG} degrees, got {}",
            Plain(deg)
        )))
    }
}

fn pair(field: &str, v: &Option<Vec<f64>>, default: [f64; 2]) -> CliResult<[f64; 2]> {
    match v {
        None => Ok(default),
        Some(v) if v.len() == 2 => Ok([v[0], v[1]]),
        Some(v) => Err(CliError::input(format!(
            "{field}: needs 2 values, got {}",
            v.len()
        ))),
    }
}

/// Build the scenario, refusing parameters it does not have.
pub fn build(spec: &SimSpec) -> CliResult<Case> {
    let name = spec.simulation.as_str();
    let allowed: &[&str] = match name {
        "bouncing-ball" => &[
            "mass",
            "radius",
            "height",
            "speed",
            "alpha_deg",
            "spin_ratio",
            "disc",
        ],
        "rod-drop" => &["mass", "length", "angle_deg", "height"],
        "double-pendulum-drop" => &["masses", "lengths", "angles_deg", "rates", "floor"],
        "rocking-block" => &["mass", "half_width", "half_height", "angle_deg", "omega"],
        "cradle" => &["balls", "mass", "radius", "v0", "gap"],
        other => {
            return Err(CliError::input(format!(
                "simulation: unknown scenario `{other}` (known: {})",
                NAMES.join(", ")
            )))
        }
    };
    let given = [
        ("mass", spec.mass.is_some()),
        ("radius", spec.radius.is_some()),
        ("height", spec.height.is_some()),
        ("speed", spec.speed.is_some()),
        ("alpha_deg", spec.alpha_deg.is_some()),
        ("spin_ratio", spec.spin_ratio.is_some()),
        ("disc", spec.disc.is_some()),
        ("length", spec.length.is_some()),
        ("angle_deg", spec.angle_deg.is_some()),
        ("masses", spec.masses.is_some()),
        ("lengths", spec.lengths.is_some()),
        ("angles_deg", spec.angles_deg.is_some()),
        ("rates", spec.rates.is_some()),
        ("floor", spec.floor.is_some()),
        ("half_width", spec.half_width.is_some()),
        ("half_height", spec.half_height.is_some()),
        ("omega", spec.omega.is_some()),
        ("balls", spec.balls.is_some()),
        ("v0", spec.v0.is_some()),
        ("gap", spec.gap.is_some()),
        // The cradle's balls move on a horizontal table: gravity acts across it.
        ("gravity", name == "cradle" && spec.gravity.is_some()),
    ];
    for (field, present) in given {
        if present && (!allowed.contains(&field) || field == "gravity") {
            return Err(CliError::input(format!(
                "{}: not a parameter of {name} (its parameters: {})",
                field.replace('_', "-"),
                allowed.join(", ").replace('_', "-")
            )));
        }
    }
    let g = spec.gravity.unwrap_or(STANDARD_GRAVITY);
    let (law_default, mu_default, e_default, until_default) = match name {
        "bouncing-ball" => ("energetic", 0.3, 0.8, 5.0),
        "rocking-block" => ("energetic", 1.0, 0.0, 6.0),
        "cradle" => ("energetic", 0.0, 1.0, 2.0),
        _ => ("energetic", 0.5, 0.5, 3.0),
    };
    let law: LawId = spec.law.as_deref().unwrap_or(law_default).trim().parse()?;
    let friction = spec.friction.unwrap_or(mu_default);
    let restitution = spec.restitution.unwrap_or(e_default);
    let until = spec.until.unwrap_or(until_default);
    let (initial, shapes, description) = match name {
        "bouncing-ball" => {
            let (m, r) = (spec.mass.unwrap_or(1.0), spec.radius.unwrap_or(0.1));
            let (h, v0) = (spec.height.unwrap_or(1.0), spec.speed.unwrap_or(2.0));
            let (a, gamma) = (
                angle("alpha-deg", spec.alpha_deg.unwrap_or(30.0))?,
                spec.spin_ratio.unwrap_or(0.0),
            );
            let disc = spec.disc.unwrap_or(false);
            let init = scenarios::bouncing_ball(m, r, h, v0, a.to_radians(), gamma, g, disc)?;
            (
                init,
                vec![Shape::Ball(r)],
                format!(
                    "bouncing {} (m = {m}, r = {r}) from {h} above the floor, v0 = {v0} at α = {a}° from the vertical, spin ratio γ = {gamma}",
                    if disc { "disc" } else { "ball" }
                ),
            )
        }
        "rod-drop" => {
            let (m, l) = (spec.mass.unwrap_or(1.0), spec.length.unwrap_or(1.0));
            let a = angle("angle-deg", spec.angle_deg.unwrap_or(30.0))?;
            let h = spec.height.unwrap_or(0.5);
            let init = scenarios::rod_drop(m, l, a.to_radians(), h, g)?;
            (
                init,
                vec![Shape::Rod(l)],
                format!("rod (m = {m}, l = {l}) dropped from rest at {a}° to the floor, lower end {h} above it"),
            )
        }
        "rocking-block" => {
            let m = spec.mass.unwrap_or(1.0);
            let (b, h) = (
                spec.half_width.unwrap_or(0.2),
                spec.half_height.unwrap_or(0.6),
            );
            let a = angle("angle-deg", spec.angle_deg.unwrap_or(10.0))?;
            let w = spec.omega.unwrap_or(0.0);
            let init = scenarios::rocking_block(m, b, h, a.to_radians(), w, g)?;
            (
                init,
                vec![Shape::Block(b, h)],
                format!(
                    "block (m = {m}, half-width {b}, half-height {h}) tilted {a}° onto a corner, turning at {w} rad/s about it"
                ),
            )
        }
        "cradle" => {
            let n = spec.balls.unwrap_or(3);
            let (m, r) = (spec.mass.unwrap_or(1.0), spec.radius.unwrap_or(0.5));
            let (v0, gap) = (spec.v0.unwrap_or(1.0), spec.gap.unwrap_or(0.0));
            let init = scenarios::cradle(n, m, r, v0, gap)?;
            (
                init,
                vec![Shape::Ball(r); n],
                format!(
                    "Newton's cradle: {n} balls (m = {m}, r = {r}) {} on a frictionless table, the first at v0 = {v0}",
                    if gap == 0.0 { "touching in a row".to_string() } else { format!("in a row {gap} apart") }
                ),
            )
        }
        _ => {
            let m = pair("masses", &spec.masses, [1.0, 1.0])?;
            let l = pair("lengths", &spec.lengths, [1.0, 1.0])?;
            let a = pair("angles_deg", &spec.angles_deg, [90.0, 90.0])?;
            for x in a {
                angle("angles-deg", x)?;
            }
            let u = pair("rates", &spec.rates, [0.0, 0.0])?;
            let floor = spec.floor.unwrap_or(-1.5);
            let init = scenarios::double_pendulum_drop(
                m[0],
                m[1],
                l[0],
                l[1],
                g,
                floor,
                [a[0].to_radians(), a[1].to_radians()],
                u,
            )?;
            (
                init,
                vec![Shape::Pendulum(l[0]), Shape::Pendulum(l[1])],
                format!(
                    "double pendulum (m = {}, {}; l = {}, {}) released at θ = ({}°, {}°), rates ({}, {}) rad/s, floor y = {floor}",
                    m[0], m[1], l[0], l[1], a[0], a[1], u[0], u[1]
                ),
            )
        }
    };
    let samples = spec.samples.unwrap_or(1000);
    if samples == 0 || samples > 1_000_000 {
        return Err(CliError::input(format!(
            "samples: must be between 1 and 10⁶, got {samples}"
        )));
    }
    let mut options = SimulationOptions::new(law, friction, restitution, until);
    options.sample_interval = until / samples as f64;
    if !(until.is_finite() && until > 0.0 && until <= 1e5) {
        return Err(CliError::input(format!(
            "until: must be positive and at most 1e5 s, got {}",
            Plain(until)
        )));
    }
    Ok(Case {
        name: name.into(),
        description,
        initial,
        options,
        shapes,
    })
}

pub fn run(args: &SimulateArgs, out: &mut Vec<u8>) -> CliResult<()> {
    for (flag, path) in [("plot", &args.plot), ("animate", &args.animate)] {
        if let Some(p) = path {
            plot::Format::of(flag, p)?;
        }
    }
    if let Some(p) = &args.animate {
        if plot::Format::of("animate", p)? != plot::Format::Svg {
            return Err(CliError::input(format!(
                "--animate {}: the animation is an animated SVG; the file name must end in .svg",
                p.display()
            )));
        }
    }
    let spec = load(&args.scenario, &flags(args))?;
    let case = build(&spec)?;
    let m = &case.initial.mechanism;
    let run = simulate(m, &case.initial.q, &case.initial.u, &case.options)?;
    if let Some(path) = &args.csv {
        write_csv(path, m, &run)?;
    }
    if let Some(path) = &args.plot {
        plot::render(
            "plot",
            path,
            (1100, 800),
            &plot::trajectory::TrajectoryFigure {
                title: format!(
                    "{} — {} (μ = {}, e = {})",
                    case.name, case.options.law, case.options.friction, case.options.restitution
                ),
                mechanism: m,
                run: &run,
                shapes: &case.shapes,
            },
        )?;
    }
    if let Some(path) = &args.animate {
        let svg = crate::output::animation::svg(&case, &run);
        std::fs::write(path, svg).map_err(|e| {
            CliError::input(format!("--animate {}: cannot write: {e}", path.display()))
        })?;
    }
    let text = if args.json {
        serde_json::to_string_pretty(&document(&case, &run)).map_err(CliError::failure)? + "\n"
    } else {
        table(&case, &run)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn stop_json(stop: &StopReason, time: f64) -> Value {
    let mut v = json!({ "id": stop.id(), "time": time });
    match stop {
        StopReason::Breakdown { reason } => v["reason"] = json!(reason),
        StopReason::UnsupportedContact { contact, touching } => {
            v["contact"] = json!(contact);
            v["touching"] = json!(touching);
        }
        StopReason::Painleve { contact, solutions } => {
            v["contact"] = json!(contact);
            v["solutions"] = json!(solutions);
        }
        _ => {}
    }
    v
}

fn stop_text(stop: &StopReason, case: &Case) -> String {
    let m = &case.initial.mechanism;
    match stop {
        StopReason::UnsupportedContact { contact, touching } => format!(
            "the {} met its surface while the {} touched: more contacts at once than the simulator resolves",
            m.contacts()[*contact].name,
            touching
                .iter()
                .map(|&j| m.contacts()[j].name)
                .collect::<Vec<_>>()
                .join(" and the ")
        ),
        StopReason::TimeLimit => "the end time was reached".into(),
        StopReason::Rest => "at rest".into(),
        StopReason::ImpactLimit => format!("{} impacts (the limit)", case.options.max_impacts),
        StopReason::Breakdown { reason } => format!("the law does not apply: {reason}"),
        StopReason::Painleve { contact, solutions } => format!(
            "Painlevé's paradox at the {}: the contact forces have {} — a tangential impact would be needed, which is not modelled",
            m.contacts()[*contact].name,
            if *solutions == 0 {
                "no solution".to_string()
            } else {
                format!("{solutions} solutions")
            }
        ),
    }
}

/// One entry per contact of an impact.
fn impact_contacts(m: &impax::mechanism::builtin::BuiltIn, i: &ImpactRecord) -> Vec<Value> {
    i.contacts
        .iter()
        .zip(&i.contact_velocities_before)
        .zip(&i.outcome.contacts)
        .map(|((&k, vb), c)| {
            json!({
                "contact": m.contacts()[k].name,
                "velocity_before": { "t": num(vb.x), "n": num(vb.y) },
                "velocity_after": { "t": num(c.velocity_after.x), "n": num(c.velocity_after.y) },
                "impulse": { "t": num(c.impulse.x), "n": num(c.impulse.y) },
                "work": { "compression": num(c.work.compression), "restitution": num(c.work.restitution), "friction": num(c.work.friction) },
                "phases": c.phases.iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) })).collect::<Vec<_>>(),
            })
        })
        .collect()
}

fn document(case: &Case, run: &Run) -> Value {
    let m = &case.initial.mechanism;
    let impacts: Vec<Value> = run
        .impacts
        .iter()
        .map(|i| {
            let o = i.struck();
            let vb = i.contact_velocity_before();
            json!({
                "time": i.time,
                "contact": m.contacts()[i.contact].name,
                "law": i.law.as_str(),
                "contacts": impact_contacts(m, i),
                "q": i.q,
                "u_before": i.u_before,
                "u_after": i.u_after,
                "contact_velocity_before": { "t": num(vb.x), "n": num(vb.y) },
                "contact_velocity_after": { "t": num(o.velocity_after.x), "n": num(o.velocity_after.y) },
                "impulse": { "t": num(o.impulse.x), "n": num(o.impulse.y) },
                "energy_before": i.kinetic_before,
                "energy_change": num(i.energy_change),
                "energy_split": { "translational": num(i.translational_change), "rotational": num(i.rotational_change) },
                "work": { "compression": num(o.work.compression), "restitution": num(o.work.restitution), "friction": num(o.work.friction) },
                "total_energy_before": i.total_energy_before,
                "total_energy_after": i.total_energy_before + i.energy_change,
                "phases": o.phases.iter().map(|p| json!({ "kind": p.kind.label(), "ends_at": num(p.ends_at) })).collect::<Vec<_>>(),
                "verdict": i.outcome.verdict.id(),
            })
        })
        .collect();
    let name = |k: &usize| m.contacts()[*k].name;
    let events: Vec<Value> = run
        .events
        .iter()
        .filter(|(_, e)| !matches!(e, EventKind::Impact { .. }))
        .map(|(t, e)| match e {
            EventKind::Zeno {
                contact,
                limit_time,
                ratio,
            } => json!({
                "time": t, "kind": "zeno", "contact": name(contact),
                "limit_time": limit_time, "ratio": ratio,
            }),
            EventKind::Sliding => json!({ "time": t, "kind": "sliding" }),
            EventKind::Rolling => json!({ "time": t, "kind": "rolling" }),
            EventKind::Rest => json!({ "time": t, "kind": "rest" }),
            EventKind::Closes { contact, regime } => json!({
                "time": t, "kind": "closes", "contact": name(contact), "regime": regime.label(),
            }),
            EventKind::Opens { contact } => {
                json!({ "time": t, "kind": "opens", "contact": name(contact) })
            }
            EventKind::Regime { contact, regime } => json!({
                "time": t, "kind": "regime", "contact": name(contact), "regime": regime.label(),
            }),
            EventKind::Impact { .. } => unreachable!("filtered"),
        })
        .collect();
    let e0 = run.samples.first().map_or(0.0, |s| s.kinetic + s.potential);
    let e1 = run.samples.last().map_or(0.0, |s| s.kinetic + s.potential);
    let l = &run.ledger;
    json!({
        "scenario": case.name,
        "description": case.description,
        "law": case.options.law.as_str(),
        "friction": case.options.friction,
        "restitution": case.options.restitution,
        "until": case.options.until,
        "coordinates": m.coordinates(),
        "q0": case.initial.q,
        "u0": case.initial.u,
        "stop": stop_json(&run.stop, run.end_time),
        "end_time": run.end_time,
        "energy_initial": e0,
        "energy_final": e1,
        "energy_rises_at_impacts": run.impacts.iter().filter(|i| i.energy_change > 0.0).count(),
        "ledger": {
            "initial": l.initial,
            "impacts": num(l.impacts),
            "contact_work": num(l.contact_work),
            "corrections": num(l.corrections),
            "end": l.end,
            "residual": num(l.residual()),
        },
        "impacts": impacts,
        "events": events,
        "samples": run.samples.len(),
        "steps": { "accepted": run.steps.0, "rejected": run.steps.1 },
    })
}

/// The phases column of an impact: the struck contact's phases; at several contacts each
/// contact's, named, and the law.
fn phases_cell(m: &impax::mechanism::builtin::BuiltIn, i: &ImpactRecord) -> String {
    if i.contacts.len() == 1 {
        return i.struck().phase_summary();
    }
    let each: Vec<String> = i
        .contacts
        .iter()
        .zip(&i.outcome.contacts)
        .map(|(&k, c)| format!("{}: {}", m.contacts()[k].name, c.phase_summary()))
        .collect();
    format!("{} ({})", each.join("; "), i.law)
}

fn table(case: &Case, run: &Run) -> String {
    let m = &case.initial.mechanism;
    let mut t = Table::new(&[
        ("#", true),
        ("time", true),
        ("x contact", true),
        ("vt-", true),
        ("vn-", true),
        ("vt+", true),
        ("vn+", true),
        ("ΔT", true),
        ("T+V after", true),
        ("phases", false),
    ]);
    const SHOWN: usize = 40;
    for (k, i) in run.impacts.iter().enumerate().take(SHOWN) {
        let o = i.struck();
        let vb = i.contact_velocity_before();
        let c = m.contact_point(i.contact, &i.q);
        let mut delta = signed(i.energy_change, 6);
        if i.energy_change > 0.0 {
            delta.push_str(" GAIN");
        }
        t.row(vec![
            (k + 1).to_string(),
            format!("{:.6}", i.time),
            signed(c[0], 5),
            signed(vb.x, 5),
            signed(vb.y, 5),
            signed(o.velocity_after.x, 5),
            signed(o.velocity_after.y, 5),
            delta,
            signed(i.total_energy_before + i.energy_change, 6),
            phases_cell(m, i),
        ]);
    }
    let mut text = format!(
        "impax simulate — {}\nlaw {}, μ = {}, e = {}, until {} s; {} impacts, {} samples, {} integrator steps\n\n",
        case.description,
        case.options.law,
        case.options.friction,
        case.options.restitution,
        case.options.until,
        run.impacts.len(),
        run.samples.len(),
        run.steps.0
    );
    if run.impacts.is_empty() {
        text.push_str("no impact\n");
    } else {
        text.push_str(&t.render());
        if run.impacts.len() > SHOWN {
            text.push_str(&format!(
                "… {} more impacts (all in --json)\n",
                run.impacts.len() - SHOWN
            ));
        }
    }
    let name = |k: &usize| m.contacts()[*k].name;
    let lines: Vec<String> = run
        .events
        .iter()
        .filter_map(|(time, e)| match e {
            EventKind::Zeno { limit_time, ratio, .. } => Some(format!(
                "t = {time:.6}: impacts accumulate (interval ratio {ratio:.6}); their limit time t∞ = {limit_time:.12}"
            )),
            EventKind::Sliding => Some(format!("t = {time:.6}: sliding contact begins")),
            EventKind::Rolling => Some(format!("t = {time:.6}: rolling begins")),
            EventKind::Rest => Some(format!("t = {time:.6}: at rest")),
            EventKind::Closes { contact, regime } => Some(format!(
                "t = {time:.6}: the {} stays in contact ({})",
                name(contact),
                regime.label()
            )),
            EventKind::Opens { contact } => Some(format!(
                "t = {time:.6}: the {} leaves its surface (its normal force vanished)",
                name(contact)
            )),
            EventKind::Regime { contact, regime } => Some(format!(
                "t = {time:.6}: the {} changes to {}",
                name(contact),
                regime.label()
            )),
            EventKind::Impact { .. } => None,
        })
        .collect();
    for line in lines.iter().take(SHOWN) {
        text.push_str(line);
        text.push('\n');
    }
    if lines.len() > SHOWN {
        text.push_str(&format!(
            "… {} more events (all in --json)\n",
            lines.len() - SHOWN
        ));
    }
    let gains = run.impacts.iter().filter(|i| i.energy_change > 0.0).count();
    if gains > 0 {
        text.push_str(&format!(
            "energy rises at {gains} impact(s) under {} (marked GAIN)\n",
            case.options.law
        ));
    }
    let e0 = run.samples.first().map_or(0.0, |s| s.kinetic + s.potential);
    let e1 = run.samples.last().map_or(0.0, |s| s.kinetic + s.potential);
    text.push_str(&format!(
        "energy T + V: {e0:.6} at the start, {e1:.6} at the end\nstop at t = {:.6}: {} ({})\n",
        run.end_time,
        run.stop.id(),
        stop_text(&run.stop, case)
    ));
    text
}

fn write_csv<M: Mechanism>(path: &Path, m: &M, run: &Run) -> CliResult<()> {
    let file = std::fs::File::create(path)
        .map_err(|e| CliError::input(format!("--csv {}: cannot create: {e}", path.display())))?;
    let mut w = std::io::BufWriter::new(file);
    let coords = m.coordinates();
    let mut header = vec!["t".to_string(), "mode".to_string()];
    header.extend(coords.iter().map(|c| c.to_string()));
    header.extend(coords.iter().map(|c| format!("{c}_rate")));
    header.extend(["kinetic".into(), "potential".into(), "energy".into()]);
    let fail = |e: std::io::Error| CliError::failure(format!("writing {}: {e}", path.display()));
    writeln!(w, "{}", header.join(",")).map_err(fail)?;
    for s in &run.samples {
        let mut row = vec![format!("{}", s.t), s.mode.id().to_string()];
        row.extend(s.q.iter().chain(&s.u).map(|x| format!("{x}")));
        row.extend([s.kinetic, s.potential, s.kinetic + s.potential].map(|x| format!("{x}")));
        writeln!(w, "{}", row.join(",")).map_err(fail)?;
    }
    w.flush().map_err(fail)
}
