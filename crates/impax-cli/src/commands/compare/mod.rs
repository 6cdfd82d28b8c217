//! `impax compare`: every law side by side on one body impact (planar here; a `space = "3d"`
//! file in [`spatial`], a mechanism in [`mechanism`]).

pub mod mechanism;
pub mod multi;
pub mod robot;
pub mod spatial;

use crate::cli::CompareArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Table};
use crate::output::json;
use crate::output::plot::{
    self,
    energy::EnergyRow,
    routh::{LawPath, RouthFigure},
};
use crate::sources::scenario::{self, Scenario};
use crate::sources::Source;

/// The mechanisms `impax compare` knows by name (a body scenario is a file or the seed).
const MECHANISMS: [&str; 3] = ["double-pendulum", "ring-pendulum", "cart-pendulum"];
use impax::planar::Verdict;
use serde_json::json;

pub fn run(args: &CompareArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let file = match &args.scenario {
        None => None,
        Some(path)
            if multi::BUILT_INS.contains(&path.to_string_lossy().as_ref()) && !path.is_file() =>
        {
            return multi::run(&path.to_string_lossy(), args, out);
        }
        Some(path) => {
            if let Some(flag) = args.multi.given().first() {
                return Err(CliError::input(format!(
                    "--{flag}: only for a built-in system struck at several contacts (`impax compare rod-flat`, `rocking-block`, `cradle`, `ball-ball-wall`)"
                )));
            }
            let unreadable = |e| {
                CliError::input(format!(
                    "{}: cannot read scenario file: {e}",
                    path.display()
                ))
            };
            match Source::classify(&path.to_string_lossy(), &MECHANISMS, unreadable)? {
                source @ (Source::BuiltInMechanism(_) | Source::Mechanism(_)) => {
                    return mechanism::run(args, &source, out)
                }
                Source::Spatial(file) => return run_spatial(args, &file.name, &file.text, out),
                Source::Robot(file) => return robot::run(args, &file, out),
                Source::Planar(file) => Some(file),
            }
        }
    };
    if let Some(path) = &args.plot {
        plot::Format::of("plot", path)?;
    }
    reject_mechanism_flags(args)?;
    let sc = scenario::load(args, file.as_ref())?;
    let problem = sc.impact.problem(sc.friction, sc.restitution)?;
    let results: Vec<_> = sc
        .laws
        .iter()
        .map(|&law| (law, sc.impact.resolve(law, &problem)))
        .collect();
    let text = if args.json {
        let two = sc.impact.other.is_some();
        let entries: Vec<_> = results
            .iter()
            .map(|(_, r)| match r {
                Ok(b) => json::body_entry(b, sc.t0, two),
                Err(b) => serde_json::Value::Object(json::breakdown_fields(
                    b,
                    "contact_velocity_after",
                    true,
                )),
            })
            .collect();
        let before = sc.impact.energy_before();
        let doc = json!({
            "scenario": sc.description,
            "problem": json::problem(&problem),
            "energy_before": before.total(),
            "t0": sc.t0,
            "results": entries,
        });
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        table(&sc, &problem, &results)
    };
    if let Some(path) = &args.plot {
        draw(&sc, &problem, &results, path)?;
    }
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

/// The mechanism flags are refused for body scenarios.
fn reject_mechanism_flags(args: &CompareArgs) -> CliResult<()> {
    if let Some(flag) = args.multi.given().first() {
        return Err(CliError::input(format!(
            "--{flag}: only for a built-in system struck at several contacts (`impax compare rod-flat`, `rocking-block`, `cradle`, `ball-ball-wall`)"
        )));
    }
    match args.mechanism.first_given() {
        Some(flag) => Err(CliError::input(format!(
            "--{flag}: only for a mechanism (e.g. `impax compare double-pendulum --{flag} …`)"
        ))),
        None => Ok(()),
    }
}

/// Routh's impulse-space diagram and the energy bars of every law, to `path`.
fn draw(
    sc: &Scenario,
    problem: &impax::planar::ContactProblem,
    results: &[(
        impax::LawId,
        Result<impax::planar::bodies::BodyOutcome, impax::planar::Breakdown>,
    )],
    path: &std::path::Path,
) -> CliResult<()> {
    let mut paths = Vec::new();
    let mut energy = Vec::new();
    for (law, r) in results {
        match r {
            Ok(b) => {
                let o = &b.outcome;
                paths.push(LawPath::of(problem, o));
                energy.push(EnergyRow {
                    law: *law,
                    values: Some([
                        o.work.normal() / sc.t0,
                        o.work.friction / sc.t0,
                        o.energy_change / sc.t0,
                        b.energy_change.translational / sc.t0,
                        b.energy_change.rotational / sc.t0,
                    ]),
                });
            }
            Err(_) => energy.push(EnergyRow {
                law: *law,
                values: None,
            }),
        }
    }
    let v = problem.velocity();
    let figure = RouthFigure {
        title: format!("impax compare — {}", sc.description),
        subtitle: format!(
            "μ = {}, e = {}; W = [[{}, {}], [{}, {}]], v⁻ = ({}, {}); T0 = {}",
            sc.friction,
            sc.restitution,
            g(problem.wtt()),
            g(problem.wtn()),
            g(problem.wtn()),
            g(problem.wnn()),
            g(v.x),
            g(v.y),
            g(sc.t0)
        ),
        problem: *problem,
        paths,
        energy,
    };
    plot::render("plot", path, RouthFigure::DEFAULT_SIZE, &figure)
}

fn table(
    sc: &Scenario,
    problem: &impax::planar::ContactProblem,
    results: &[(
        impax::LawId,
        Result<impax::planar::bodies::BodyOutcome, impax::planar::Breakdown>,
    )],
) -> String {
    let s = sc.scale;
    let (hx, hy, hw) = if s.normalised {
        ("vx+/v0", "vy+/v0", "ω+r/v0")
    } else {
        ("vx+", "vy+", "ω+")
    };
    let mut t = Table::new(&[
        ("law", false),
        (hx, true),
        (hy, true),
        (hw, true),
        ("vt+", true),
        ("ΔT/T0", true),
        ("phases", false),
        ("verdict", false),
    ]);
    let mut notes = Vec::new();
    for (law, r) in results {
        match r {
            Ok(b) => {
                let o = &b.outcome;
                let v = b.body_after.velocity / s.speed;
                let w = b.body_after.omega * s.length / s.speed;
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
                t.row(vec![
                    law.to_string(),
                    signed(v.x, 5),
                    signed(v.y, 5),
                    signed(w, 5),
                    signed(o.velocity_after.x / s.speed, 5),
                    signed(o.energy_change / sc.t0, 5),
                    phases.join(" → "),
                    if o.inconsistency.is_some() && o.verdict == Verdict::EnergyGained {
                        format!("{verdict}; inconsistent assumption")
                    } else {
                        verdict
                    },
                ]);
            }
            Err(b) => {
                let dash = "—".to_string();
                t.row(vec![
                    law.to_string(),
                    dash.clone(),
                    dash.clone(),
                    dash.clone(),
                    dash.clone(),
                    dash.clone(),
                    dash,
                    "BREAKDOWN".to_string(),
                ]);
                notes.push(format!("{law}: breakdown: {}", b.reason));
            }
        }
    }
    let v = problem.velocity();
    let mut text = format!(
        "impax compare — {}, μ = {}, e = {}\ncontact space: W = [[{}, {}], [{}, {}]], v⁻ = ({}, {}); T0 = {}\n\n",
        sc.description,
        sc.friction,
        sc.restitution,
        g(problem.wtt()),
        g(problem.wtn()),
        g(problem.wtn()),
        g(problem.wnn()),
        g(v.x),
        g(v.y),
        g(sc.t0),
    );
    text.push_str(&t.render());
    text.push_str("\nphases: regime@normal impulse at its end; vt+: slip velocity after");
    if s.normalised {
        text.push_str(" (/v0)");
    }
    text.push('\n');
    text.push_str(&crate::output::fmt::notes(&notes));
    text
}

/// Short general format for header numbers.
fn g(x: f64) -> String {
    let r = (x * 1e6).round() / 1e6;
    if r == 0.0 {
        "0".into()
    } else {
        format!("{r}")
    }
}

/// A `space = "3d"` scenario: the spatial bodies (the planar-only flags are refused).
fn run_spatial(args: &CompareArgs, source: &str, text: &str, out: &mut Vec<u8>) -> CliResult<()> {
    for (flag, given) in [
        ("alpha-deg", args.alpha_deg.is_some()),
        ("spin-ratio", args.spin_ratio.is_some()),
        ("radius", args.radius.is_some()),
        ("speed", args.speed.is_some()),
        ("mass", args.mass.is_some()),
        ("friction", args.friction.is_some()),
        ("restitution", args.restitution.is_some()),
        ("plot", args.plot.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not available for 3D scenarios yet; edit the scenario file"
            )));
        }
    }
    crate::commands::compare::spatial::run(source, text, &args.law, args.json, out)
}
