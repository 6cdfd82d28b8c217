//! `impax compare ROBOT.urdf --contact LINK[:x,y,z]` (or a `space = "3d"` mechanism file):
//! every spatial law side by side on one contact of a spatial mechanism, with the
//! generalized velocities after and the kinetic energy before and after.

use crate::cli::CompareArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Table};
use crate::output::json;
use crate::sources::robot::{self, RobotCase};
use crate::sources::File;
use impax::multibody::{SpatialMechanismImpact, SpatialMechanismOutcome};
use impax::scenario::BuiltRobot;
use impax::LawId;

pub fn run(args: &CompareArgs, file: &File, out: &mut Vec<u8>) -> CliResult<()> {
    for (flag, given) in [
        ("alpha-deg", args.alpha_deg.is_some()),
        ("spin-ratio", args.spin_ratio.is_some()),
        ("speed", args.speed.is_some()),
        ("mass", args.mass.is_some()),
        ("radius", args.radius.is_some()),
        ("plot", args.plot.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not a parameter of a robot (its state is --q and --u)"
            )));
        }
    }
    let case = robot::load(
        file,
        &args.mechanism,
        args.friction,
        args.restitution,
        &args.law,
    )?;
    let built = case.spec.build()?;
    let impact = built.impact()?;
    let problem = impact.problem(case.friction, case.restitution)?;
    let results = case
        .laws
        .iter()
        .map(|&law| Ok((law, impact.resolve(law, case.friction, case.restitution)?)))
        .collect::<CliResult<Vec<_>>>()?;
    let text = if args.json {
        serde_json::to_string_pretty(&json::robot_document(&built, &impact, &problem, &results))
            .map_err(CliError::failure)?
            + "\n"
    } else {
        table(&built, &case, &impact, &results)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

fn table(
    built: &BuiltRobot,
    case: &RobotCase,
    impact: &SpatialMechanismImpact<'_>,
    results: &[(LawId, SpatialMechanismOutcome)],
) -> String {
    let t0 = impact.energy_before();
    let v = impact.contact_velocity();
    let w = impact.inverse_inertia();
    let mut s = format!(
        "impax compare — {}; μ = {}, e = {}\ncontact ({}): v⁻ = ({:.6}, {:.6}, {:.6}), \
         W = [[{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}]]; T⁻ = {:.6}\n\n",
        built.description(),
        case.friction,
        case.restitution,
        built.model.contacts()[built.contact].name,
        v.x,
        v.y,
        v.z,
        w[(0, 0)],
        w[(0, 1)],
        w[(0, 2)],
        w[(1, 0)],
        w[(1, 1)],
        w[(1, 2)],
        w[(2, 0)],
        w[(2, 1)],
        w[(2, 2)],
        t0
    );
    let mut t = Table::new(&[
        ("law", false),
        ("vt1+", true),
        ("vt2+", true),
        ("vn+", true),
        ("pn", true),
        ("ΔT", true),
        ("T+/T-", true),
        ("phases", false),
        ("verdict", false),
    ]);
    let mut notes = Vec::new();
    for (law, r) in results {
        match &r.resolution {
            Ok(o) => {
                if let Some(i) = o.inconsistency {
                    notes.push(format!("{law}: {i}"));
                }
                t.row(vec![
                    law.to_string(),
                    signed(o.velocity_after.x, 5),
                    signed(o.velocity_after.y, 5),
                    signed(o.velocity_after.z, 5),
                    signed(o.impulse.z, 5),
                    signed(o.energy_change, 5),
                    format!("{:.5}", (t0 + o.energy_change) / t0),
                    o.phases.summary(),
                    o.verdict.id().to_string(),
                ]);
            }
            Err(b) => {
                notes.push(format!("{law}: breakdown: {}", b.reason));
                t.breakdown_row(law, "breakdown");
            }
        }
    }
    s.push_str(&t.render());
    s.push_str(
        "\nvt1+, vt2+, vn+: contact velocity after; pn: normal impulse; ΔT = T⁺ − T⁻; the \
         generalized velocities after are in --json (velocities_after)\n",
    );
    s.push_str(&crate::output::fmt::notes(&notes));
    s
}
