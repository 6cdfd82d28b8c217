//! `impax conserved MECHANISM`: integrate a mechanism's free motion and report, per quantity
//! (generalized momenta, energy, linear and angular momentum, Noether charges), its initial
//! value, its largest deviation and whether it is conserved (paper B); a robot or a
//! `space = "3d"` mechanism file in [`robot`].

pub mod robot;

use crate::cli::ConservedArgs;
use crate::input::{parse_numbers, CliError, CliResult};
use crate::output::fmt::{Plain, Table};
use crate::output::plot;
use crate::sources::mechanism::{self, MechanismSpec};
use impax::math::Vec2;
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::conserved::{self, QuantityKind, TrackOptions, Tracking};
use impax::mechanism::Mechanism;
use impax::ode::Tolerances;

pub fn run(args: &ConservedArgs, out: &mut Vec<u8>) -> CliResult<()> {
    if !BuiltIn::NAMES.contains(&args.mechanism.as_str()) {
        if let Ok(text) = std::fs::read_to_string(&args.mechanism) {
            if crate::sources::robot::is_robot(&args.mechanism, &text) {
                let file = crate::sources::File {
                    name: args.mechanism.clone(),
                    text,
                };
                return robot::run(args, &file, out);
            }
        }
    }
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
        ("contact", !args.params.contact.is_empty()),
        ("floating-base", args.params.floating_base),
        ("floor", args.params.floor.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not used by `conserved` for a planar mechanism (the motion is free; no impact)"
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
    let options = track_options(args)?;
    let duration = options.duration;
    let mut about = Vec::new();
    for a in &args.about {
        let v = parse_numbers("about", a, 2, "X,Y")?;
        about.push(Vec2::new(v[0], v[1]));
    }
    if about.is_empty() {
        about.push(Vec2::zeros());
    }
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
        serde_json::to_string_pretty(&impax::json::conserved(
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

/// The options of the tracking from `--duration` (in (0, 1e6] s), `--samples` (1 to 10⁶)
/// and `--tolerance` (checked in (0, 1)); the integrator's tolerances are tight.
pub(crate) fn track_options(args: &ConservedArgs) -> CliResult<TrackOptions> {
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
    Ok(TrackOptions {
        duration,
        intervals: args.samples,
        tolerances: Tolerances::TIGHT,
    })
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
            track.description(coords),
            format!("{:+.10e}", track.initial()),
            format!("{:.3e}", track.largest_deviation()),
            format!("{:.1e}", track.relative_deviation()),
            track.verdict(tolerance).into(),
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
