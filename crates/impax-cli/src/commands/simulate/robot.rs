//! `impax simulate ROBOT.urdf --contact FOOT …` (or a `space = "3d"` mechanism file): free
//! flight of a spatial mechanism with impacts at its contacts
//! ([`impax::multibody::simulate()`]) — the table, JSON ([`super::robot_json`]) and the
//! trajectory as CSV, with the keys and columns of the planar run where they mean the same.

use super::{csv, robot_json, scenario::run_options};
use crate::cli::{MechanismFlags, SimulateArgs};
use crate::input::{CliError, CliResult};
use crate::output::fmt::{magnitude, signed, Table};
use crate::sources::robot;
use crate::sources::File;
use impax::multibody::simulate::{simulate, Persistence, Run, StopReason};
use impax::scenario::BuiltRobot;
use impax::simulation::{EventKind, SimulationOptions};
use impax::LawId;

/// A spatial run ready to write: the mechanism at its start, the options and the run.
pub(super) struct RobotRun {
    pub built: BuiltRobot,
    pub options: SimulationOptions,
    pub run: Run,
}

/// The flags of the planar scenarios, refused for a robot.
fn refuse_planar_flags(args: &SimulateArgs) -> CliResult<()> {
    for (flag, given) in [
        ("mass", args.mass.is_some()),
        ("radius", args.radius.is_some()),
        ("height", args.height.is_some()),
        ("speed", args.speed.is_some()),
        ("alpha-deg", args.alpha_deg.is_some()),
        ("spin-ratio", args.spin_ratio.is_some()),
        ("disc", args.disc),
        ("length", args.length.is_some()),
        ("angle-deg", args.angle_deg.is_some()),
        ("half-width", args.half_width.is_some()),
        ("half-height", args.half_height.is_some()),
        ("omega", args.omega.is_some()),
        ("balls", args.balls.is_some()),
        ("v0", args.v0.is_some()),
        ("gap", args.gap.is_some()),
        ("masses", args.masses.is_some()),
        ("lengths", args.lengths.is_some()),
        ("angles-deg", args.angles_deg.is_some()),
        ("rates", args.rates.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: a parameter of the planar scenarios; a robot's state is --q and --u"
            )));
        }
    }
    for (flag, given) in [
        ("plot", args.plot.is_some()),
        ("animate", args.animate.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: pictures of a spatial motion are not drawn (its trajectory is in --csv)"
            )));
        }
    }
    Ok(())
}

/// Build the robot from its file and the flags, and run it.
pub(super) fn simulate_robot(args: &SimulateArgs, file: &File) -> CliResult<RobotRun> {
    refuse_planar_flags(args)?;
    let flags = MechanismFlags {
        gravity: args.gravity,
        q: args.q.clone(),
        u: args.u.clone(),
        contact: args.contact.clone(),
        floating_base: args.floating_base,
        floor: args.floor,
        ..MechanismFlags::default()
    };
    let law_flags: Vec<String> = args.law.iter().cloned().collect();
    let case = robot::load(file, &flags, args.friction, args.restitution, &law_flags)?;
    // A file naming exactly one law runs it; otherwise `energetic`.
    let law = match case.laws.as_slice() {
        [one] => *one,
        _ => LawId::Energetic,
    };
    let built = case.spec.build()?;
    let until = args.until.unwrap_or(3.0);
    let options = run_options(law, case.friction, case.restitution, until, args.samples)?;
    let run = simulate(&built.model, &built.q, &built.u, &options)?;
    Ok(RobotRun {
        built,
        options,
        run,
    })
}

/// `impax simulate` for a robot or a `space = "3d"` mechanism file.
pub fn run(args: &SimulateArgs, file: &File, out: &mut Vec<u8>) -> CliResult<()> {
    let r = simulate_robot(args, file)?;
    if let Some(path) = &args.csv {
        let coordinates = r.built.coordinates();
        let speeds = csv::speed_columns(coordinates, r.built.model.speeds());
        csv::write(path, coordinates, &speeds, &r.run.samples)?;
    }
    let text = if args.json {
        serde_json::to_string_pretty(&robot_json::document(&r)).map_err(CliError::failure)? + "\n"
    } else {
        table(&r)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

/// The stop in words.
pub(super) fn stop_text(r: &RobotRun) -> String {
    let name = |k: usize| r.built.model.contacts()[k].name.as_str();
    match &r.run.stop {
        StopReason::TimeLimit => "the end time was reached".into(),
        StopReason::ImpactLimit => format!("{} impacts (the limit)", r.options.max_impacts),
        StopReason::Breakdown { reason } => format!("the law does not apply: {reason}"),
        StopReason::UnsupportedContact { contact, touching } => format!(
            "`{}` struck while {} touched: more contacts at once than the law resolves",
            name(*contact),
            touching
                .iter()
                .map(|&j| format!("`{}`", name(j)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        StopReason::PersistentContact { contact, cause } => format!(
            "`{}` stays on the floor ({}), which the spatial simulation does not integrate",
            name(*contact),
            match cause {
                Persistence::Closed => "an impact left it at rest on the floor".to_string(),
                Persistence::LowBounce { height } =>
                    format!("its bounce of {height:.3e} m is below the touching tolerance"),
                Persistence::Accumulation { limit_time, ratio } => format!(
                    "its impacts accumulate, interval ratio {ratio:.6}, limit t∞ = {limit_time:.9}"
                ),
                Persistence::Pressed => "it touches pressed into the floor".to_string(),
            }
        ),
    }
}

/// The table: a line per impact (the first 40), the events, the energy ledger and the stop.
fn table(r: &RobotRun) -> String {
    let (run, model) = (&r.run, &r.built.model);
    let mut t = Table::new(&[
        ("#", true),
        ("time", true),
        ("contact", false),
        ("vt1-", true),
        ("vt2-", true),
        ("vn-", true),
        ("vt1+", true),
        ("vt2+", true),
        ("vn+", true),
        ("ΔT", true),
        ("T+V after", true),
        ("phases", false),
    ]);
    const SHOWN: usize = 40;
    for (k, i) in run.impacts.iter().enumerate().take(SHOWN) {
        let (vb, o) = (i.contact_velocity_before(), i.struck());
        let mut delta = signed(i.energy_change, 6);
        if i.energy_change > 0.0 {
            delta.push_str(" GAIN");
        }
        let contact = if i.contacts.len() == 1 {
            model.contacts()[i.contact].name.clone()
        } else {
            format!(
                "{} (+{})",
                model.contacts()[i.contact].name,
                i.contacts.len() - 1
            )
        };
        let phases = if i.contacts.len() == 1 {
            o.phase_summary()
        } else {
            format!("{} ({})", o.phase_summary(), i.law)
        };
        t.row(vec![
            (k + 1).to_string(),
            format!("{:.6}", i.time),
            contact,
            signed(vb.x, 5),
            signed(vb.y, 5),
            signed(vb.z, 5),
            signed(o.velocity_after.x, 5),
            signed(o.velocity_after.y, 5),
            signed(o.velocity_after.z, 5),
            delta,
            signed(i.total_energy_before + i.energy_change, 6),
            phases,
        ]);
    }
    let o = &r.options;
    let mut text = format!(
        "impax simulate — {}\nlaw {}, μ = {}, e = {}, until {} s; {} impacts, {} samples, {} integrator steps\n\n",
        r.built.motion_description(),
        o.law,
        o.friction,
        o.restitution,
        o.until,
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
        text.push_str(
            "contact: the one that struck (+ the others touching, resolved with it); vt1, vt2, vn: its velocity before (-) and after (+)\n",
        );
    }
    for (time, e) in &run.events {
        if let EventKind::Zeno {
            limit_time, ratio, ..
        } = e
        {
            text.push_str(&format!(
                "t = {time:.6}: impacts accumulate (interval ratio {ratio:.6}); their limit time t∞ = {limit_time:.12}\n"
            ));
        }
    }
    let gains = run.impacts.iter().filter(|i| i.energy_change > 0.0).count();
    if gains > 0 {
        text.push_str(&format!(
            "energy rises at {gains} impact(s) under {} (marked GAIN)\n",
            o.law
        ));
    }
    let l = &run.ledger;
    text.push_str(&format!(
        "energy T + V: {} at the start, {} at the end; ledger: the impacts' ΔT {}, the integration's drift {:+.1e}, residual {:.1e}\nstop at t = {:.6}: {} ({})\n",
        magnitude(l.initial, l.initial.abs().max(l.end.abs()), 6),
        magnitude(l.end, l.initial.abs().max(l.end.abs()), 6),
        signed(l.impacts, 6),
        l.drift,
        l.residual(),
        run.end_time,
        run.stop.id(),
        stop_text(r)
    ));
    text
}
