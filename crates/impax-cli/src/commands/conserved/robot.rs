//! `impax conserved ROBOT.urdf [--floating-base]` (or a `space = "3d"` mechanism file): the
//! conserved quantities of a spatial mechanism along its free motion
//! ([`impax::multibody::conserved`]) — the planar output's columns and keys, each quantity
//! with whether a symmetry of the mechanism conserves it (`expected`).

use super::track_options;
use crate::cli::ConservedArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::Table;
use crate::output::json::num;
use crate::sources::robot;
use crate::sources::File;
use impax::math::Vec3;
use impax::multibody::conserved::{rate_coordinate, track, QuantityKind, Track, Tracking};
use impax::ode::Tolerances;
use impax::scenario::FreeRobot;
use serde_json::{json, Value};

/// `impax conserved` for a robot or a `space = "3d"` mechanism file.
pub fn run(args: &ConservedArgs, file: &File, out: &mut Vec<u8>) -> CliResult<()> {
    for (flag, given) in [
        ("radius", args.radius.is_some()),
        ("plot", args.plot.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not available for a robot (its state is --q and --u)"
            )));
        }
    }
    // The file's coefficients and laws are for its impacts; the contacts play no part.
    let case = robot::load(file, &args.params, None, None, &[])?;
    let free = case.spec.build_free()?;
    let options = track_options(args)?;
    let mut about = Vec::new();
    for a in &args.about {
        let v = parse_numbers("about", a, 3, "X,Y,Z")?;
        about.push(Vec3::new(v[0], v[1], v[2]));
    }
    if about.is_empty() {
        about.push(Vec3::zeros());
    }
    let tracking = track(&free.model, &free.q, &free.u, &about, options)?;
    let text = if args.json {
        serde_json::to_string_pretty(&document(
            &free,
            &tracking,
            args.tolerance,
            options.duration,
        ))
        .map_err(CliError::failure)?
            + "\n"
    } else {
        table(&free, &tracking, args.tolerance, options.duration)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// What the quantity is, in words.
fn kind(t: &Track, free: &FreeRobot) -> String {
    match &t.kind {
        QuantityKind::GeneralizedMomentum { speed, cyclic } => format!(
            "generalized momentum of {}{}",
            free.model.speeds()[*speed],
            if *cyclic == Some(true) {
                " (cyclic)"
            } else {
                ""
            }
        ),
        QuantityKind::Energy => "total energy T + V".into(),
        QuantityKind::LinearMomentum { axis } => {
            format!("Newtonian momentum Σ m v_{}", AXES[*axis])
        }
        QuantityKind::AngularMomentum { about, axis } => format!(
            "angular momentum about ({}, {}, {}), {} component",
            about.x, about.y, about.z, AXES[*axis]
        ),
    }
}

fn kind_id(t: &Track) -> &'static str {
    match t.kind {
        QuantityKind::GeneralizedMomentum { .. } => "generalized-momentum",
        QuantityKind::Energy => "energy",
        QuantityKind::LinearMomentum { .. } => "linear-momentum",
        QuantityKind::AngularMomentum { .. } => "angular-momentum",
    }
}

/// The quantities a symmetry conserves that the integration did not keep within the
/// tolerance (its error, not the physics).
fn drifted(tr: &Tracking, tolerance: f64) -> Vec<&str> {
    tr.tracks
        .iter()
        .filter(|t| t.expected && !t.conserved(tolerance))
        .map(|t| t.name.as_str())
        .collect()
}

fn table(free: &FreeRobot, tr: &Tracking, tolerance: f64, duration: f64) -> String {
    let coords = free.coordinates();
    let mut t = Table::new(&[
        ("quantity", false),
        ("what", false),
        ("initial", true),
        ("largest deviation", true),
        ("relative", true),
        ("verdict", false),
        ("expected", false),
    ]);
    for track in &tr.tracks {
        t.row(vec![
            track.name.clone(),
            kind(track, free),
            format!("{:+.10e}", track.initial()),
            format!("{:.3e}", track.largest_deviation()),
            format!("{:.1e}", track.relative_deviation()),
            if track.conserved(tolerance) {
                "conserved"
            } else {
                "NOT conserved"
            }
            .into(),
            if track.expected { "yes" } else { "no" }.into(),
        ]);
    }
    let cyclic: Vec<&str> = tr.cyclic.iter().map(|&i| coords[i].as_str()).collect();
    let mut text = format!(
        "impax conserved — {}\nfree motion over {duration} s, {} samples; Dormand–Prince 5(4), relative tolerance {:e} ({} steps, {} rejected)\ncyclic coordinates (∂L/∂q ≡ 0): {}\n\n",
        free.description(),
        tr.times.len(),
        Tolerances::TIGHT.relative,
        tr.steps.0,
        tr.steps.1,
        if cyclic.is_empty() { "none".to_string() } else { cyclic.join(", ") },
    );
    text.push_str(&t.render());
    text.push_str(&format!(
        "\nrelative: largest deviation / largest magnitude of the quantity's terms; conserved when ≤ {tolerance:e}\nexpected: a symmetry conserves it (the energy; the momentum of a cyclic coordinate; a floating base's P_x, P_y and L_z about any point, all of P and L without gravity)\n"
    ));
    let drifted = drifted(tr, tolerance);
    if !drifted.is_empty() {
        text.push_str(&format!(
            "expected but beyond the tolerance (the integration's error): {}\n",
            drifted.join(", ")
        ));
    }
    text
}

fn document(free: &FreeRobot, tr: &Tracking, tolerance: f64, duration: f64) -> Value {
    let coords = free.coordinates();
    let quantities: Vec<Value> = tr
        .tracks
        .iter()
        .map(|t| {
            let mut q = json!({
                "name": t.name,
                "kind": kind_id(t),
                "description": kind(t, free),
                "initial": num(t.initial()),
                "final": num(*t.values.last().expect("samples")),
                "largest_deviation": num(t.largest_deviation()),
                "relative_deviation": num(t.relative_deviation()),
                "magnitude": num(t.magnitude),
                "conserved": t.conserved(tolerance),
                "expected": t.expected,
            });
            match &t.kind {
                QuantityKind::GeneralizedMomentum { speed, cyclic } => {
                    q["speed"] = json!(free.model.speeds()[*speed]);
                    if let Some(i) = rate_coordinate(&free.model, *speed) {
                        q["coordinate"] = json!(coords[i]);
                    }
                    if let Some(c) = cyclic {
                        q["cyclic"] = json!(c);
                    }
                }
                QuantityKind::AngularMomentum { about, axis } => {
                    q["about"] = json!([about.x, about.y, about.z]);
                    q["axis"] = json!(AXES[*axis]);
                }
                QuantityKind::LinearMomentum { axis } => q["axis"] = json!(AXES[*axis]),
                QuantityKind::Energy => {}
            }
            q
        })
        .collect();
    json!({
        "mechanism": free.name,
        "scenario": free.description(),
        "coordinates": coords,
        "speeds": free.model.speeds(),
        "mimic_joints": free.mimic_joints,
        "gravity": free.model.gravity(),
        "q": free.q,
        "u": free.u,
        "duration": duration,
        "samples": tr.times.len(),
        "tolerance": tolerance,
        "steps": { "accepted": tr.steps.0, "rejected": tr.steps.1 },
        "cyclic": tr.cyclic.iter().map(|&i| coords[i].clone()).collect::<Vec<_>>(),
        "expected_but_drifted": drifted(tr, tolerance),
        "quantities": quantities,
    })
}
