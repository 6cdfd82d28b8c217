//! `impax conserved MECHANISM`: integrate a mechanism's free motion and report, per quantity
//! (generalized momenta, energy, linear and angular momentum, Noether charges), its initial
//! value, its largest deviation and whether it is conserved (paper B).

use crate::cli::ConservedArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::{Plain, Table};
use crate::output::json::num;
use crate::output::plot;
use crate::sources::mechanism::{self, MechanismSpec};
use impax::math::Vec2;
use impax::mechanism::conserved::{self, QuantityKind, Track, TrackOptions, Tracking};
use impax::mechanism::Mechanism;
use impax::ode::Tolerances;
use serde_json::{json, Value};

pub fn run(args: &ConservedArgs, out: &mut Vec<u8>) -> CliResult<()> {
    if let Some(path) = &args.plot {
        plot::Format::of("plot", path)?;
    }
    let flags = MechanismSpec {
        masses: args.params.masses.clone(),
        lengths: args.params.lengths.clone(),
        radius: args.radius,
        gravity: args.params.gravity,
        angles: args.params.angles_deg.clone(),
        rates: args.params.rates.clone(),
        position: args.params.position.clone(),
        q: args.params.q.clone(),
        u: args.params.u.clone(),
        ..MechanismSpec::default()
    };
    for (flag, given) in [
        ("contact", args.params.contact.is_some()),
        ("floating-base", args.params.floating_base),
        ("floor", args.params.floor.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not used by `conserved` (the motion is free; no impact)"
            )));
        }
    }
    let mut spec = mechanism::load(&args.mechanism, &flags)?;
    if spec.file.is_some() {
        // A mechanism file's coefficients and laws are for its impacts.
        (spec.friction, spec.restitution, spec.laws) = (None, None, None);
    }
    for (field, given) in [
        ("friction", spec.friction.is_some()),
        ("restitution", spec.restitution.is_some()),
        ("laws", spec.laws.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "{field}: not used by `conserved` (the motion is free; no impact)"
            )));
        }
    }
    let case = mechanism::build(&spec)?;
    let duration = args.duration;
    if !(duration.is_finite() && duration > 0.0 && duration <= 1e6) {
        return Err(CliError::input(format!(
            "--duration: must be positive and at most 1e6 s, got {}",
            Plain(duration)
        )));
    }
    if args.samples == 0 || args.samples > 1_000_000 {
        return Err(CliError::input(format!(
            "--samples: must be between 1 and 10⁶, got {}",
            args.samples
        )));
    }
    if !(args.tolerance.is_finite() && args.tolerance > 0.0 && args.tolerance < 1.0) {
        return Err(CliError::input(format!(
            "--tolerance: must be in (0, 1), got {}",
            Plain(args.tolerance)
        )));
    }
    let mut about = Vec::new();
    for a in &args.about {
        let v = parse_numbers("about", a, 2, "X,Y")?;
        about.push(Vec2::new(v[0], v[1]));
    }
    if about.is_empty() {
        about.push(Vec2::zeros());
    }
    let options = TrackOptions {
        duration,
        intervals: args.samples,
        tolerances: Tolerances::TIGHT,
    };
    let symmetries = case.mechanism.symmetries();
    let tracking = conserved::track(
        &case.mechanism,
        &case.q,
        &case.u,
        &symmetries,
        &about,
        options,
    )?;
    if let Some(path) = &args.plot {
        plot::render(
            "plot",
            path,
            (1000, 640),
            &plot::conserved::ConservedFigure {
                title: format!("{} — relative change of each quantity", spec.mechanism),
                tracking: &tracking,
                tolerance: args.tolerance,
            },
        )?;
    }
    let text = if args.json {
        serde_json::to_string_pretty(&document(
            &spec.mechanism,
            &case,
            &tracking,
            args.tolerance,
            duration,
        ))
        .map_err(CliError::failure)?
            + "\n"
    } else {
        table(&case, &tracking, args.tolerance, duration)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn kind(t: &Track, coords: &[&str]) -> String {
    match &t.kind {
        QuantityKind::GeneralizedMomentum { coordinate, cyclic } => format!(
            "generalized momentum of {}{}",
            coords[*coordinate],
            if *cyclic { " (cyclic)" } else { "" }
        ),
        QuantityKind::Energy => "total energy T + V".into(),
        QuantityKind::LinearMomentum { axis } => {
            format!(
                "Newtonian momentum Σ m v_{}",
                if *axis == 0 { "x" } else { "y" }
            )
        }
        QuantityKind::AngularMomentum { about } => {
            format!("angular momentum about ({}, {})", about.x, about.y)
        }
        QuantityKind::Noether { .. } => "Noether charge Σ p ξ − F".into(),
    }
}

fn kind_id(t: &Track) -> &'static str {
    match t.kind {
        QuantityKind::GeneralizedMomentum { .. } => "generalized-momentum",
        QuantityKind::Energy => "energy",
        QuantityKind::LinearMomentum { .. } => "linear-momentum",
        QuantityKind::AngularMomentum { .. } => "angular-momentum",
        QuantityKind::Noether { .. } => "noether-charge",
    }
}

fn verdict(t: &Track, tolerance: f64) -> &'static str {
    match &t.kind {
        QuantityKind::Noether { check } if !check.holds() => "not a symmetry (δL ≠ dF/dt)",
        _ if t.conserved(tolerance) => "conserved",
        _ => "NOT conserved",
    }
}

fn table(case: &mechanism::MechanismCase, tr: &Tracking, tolerance: f64, duration: f64) -> String {
    let coords = case.mechanism.coordinates();
    let mut t = Table::new(&[
        ("quantity", false),
        ("what", false),
        ("initial", true),
        ("largest deviation", true),
        ("relative", true),
        ("verdict", false),
    ]);
    for track in &tr.tracks {
        t.row(vec![
            track.name.clone(),
            kind(track, coords),
            format!("{:+.10e}", track.initial()),
            format!("{:.3e}", track.largest_deviation()),
            format!("{:.1e}", track.relative_deviation()),
            verdict(track, tolerance).into(),
        ]);
    }
    let cyclic: Vec<&str> = tr.cyclic.iter().map(|&i| coords[i]).collect();
    let mut text = format!(
        "impax conserved — {}\nfree motion over {duration} s, {} samples; Dormand–Prince 5(4), relative tolerance {:e} ({} steps, {} rejected)\ncyclic coordinates (∂L/∂q ≡ 0): {}\n\n",
        case.description,
        tr.times.len(),
        Tolerances::TIGHT.relative,
        tr.steps.0,
        tr.steps.1,
        if cyclic.is_empty() { "none".to_string() } else { cyclic.join(", ") },
    );
    text.push_str(&t.render());
    text.push_str(&format!(
        "\nrelative: largest deviation / largest magnitude of the quantity's terms; conserved when ≤ {tolerance:e}\n"
    ));
    for track in &tr.tracks {
        if let QuantityKind::Noether { check } = &track.kind {
            text.push_str(&format!(
                "symmetry {}: δL = dF/dt {} (worst of 16 states: δL = {:.6e}, dF/dt = {:.6e})\n",
                track.name,
                if check.holds() { "holds" } else { "FAILS" },
                check.variation,
                check.gauge_rate
            ));
        }
    }
    text
}

fn document(
    name: &str,
    case: &mechanism::MechanismCase,
    tr: &Tracking,
    tolerance: f64,
    duration: f64,
) -> Value {
    let coords = case.mechanism.coordinates();
    let quantities: Vec<Value> = tr
        .tracks
        .iter()
        .map(|t| {
            let mut q = json!({
                "name": t.name,
                "kind": kind_id(t),
                "description": kind(t, coords),
                "initial": num(t.initial()),
                "final": num(*t.values.last().expect("samples")),
                "largest_deviation": num(t.largest_deviation()),
                "relative_deviation": num(t.relative_deviation()),
                "magnitude": num(t.magnitude),
                "conserved": t.conserved(tolerance),
            });
            match &t.kind {
                QuantityKind::GeneralizedMomentum { coordinate, cyclic } => {
                    q["coordinate"] = json!(coords[*coordinate]);
                    q["cyclic"] = json!(cyclic);
                }
                QuantityKind::AngularMomentum { about } => q["about"] = json!([about.x, about.y]),
                QuantityKind::LinearMomentum { axis } => {
                    q["axis"] = json!(if *axis == 0 { "x" } else { "y" })
                }
                QuantityKind::Noether { check } => {
                    q["symmetry_check"] = json!({
                        "holds": check.holds(),
                        "variation": num(check.variation),
                        "gauge_rate": num(check.gauge_rate),
                    })
                }
                QuantityKind::Energy => {}
            }
            q
        })
        .collect();
    json!({
        "mechanism": name,
        "scenario": case.description,
        "coordinates": coords,
        "q": case.q,
        "u": case.u,
        "duration": duration,
        "samples": tr.times.len(),
        "tolerance": tolerance,
        "steps": { "accepted": tr.steps.0, "rejected": tr.steps.1 },
        "cyclic": tr.cyclic.iter().map(|&i| coords[i]).collect::<Vec<_>>(),
        "quantities": quantities,
    })
}
