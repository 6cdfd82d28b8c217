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
//!
//! The command by stages: the parameters from the flags and the file (`spec`), the scenario
//! built from them (`scenario`), the run, then the outputs — the table (`table`), JSON
//! (`json`), the trajectory as CSV (`csv`), the plot and the animation.

mod csv;
mod json;
pub mod robot;
mod robot_json;
mod scenario;
mod spec;
mod table;

pub use scenario::build;
pub use spec::SimSpec;

use crate::cli::SimulateArgs;
use crate::input::{CliError, CliResult};
use crate::output::plot;
use impax::mechanism::Mechanism;
use impax::simulation::scenarios::Initial;
use impax::simulation::{simulate, SimulationOptions};

/// The built-in scenarios.
pub const NAMES: [&str; 5] = [
    "bouncing-ball",
    "rod-drop",
    "double-pendulum-drop",
    "rocking-block",
    "cradle",
];

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

/// `impax simulate`: build the scenario, run it, write the outputs asked for (a robot or a
/// `space = "3d"` mechanism file in [`robot`]).
pub fn run(args: &SimulateArgs, out: &mut Vec<u8>) -> CliResult<()> {
    if !NAMES.contains(&args.scenario.as_str()) {
        if let Ok(text) = std::fs::read_to_string(&args.scenario) {
            if crate::sources::robot::is_robot(&args.scenario, &text) {
                let file = crate::sources::File {
                    name: args.scenario.clone(),
                    text,
                };
                return robot::run(args, &file, out);
            }
        }
    }
    for (flag, given) in [
        ("contact", !args.contact.is_empty()),
        ("floating-base", args.floating_base),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: for a robot (URDF) or a 3D mechanism file"
            )));
        }
    }
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
    let spec = spec::load(&args.scenario, &spec::flags(args))?;
    let case = build(&spec)?;
    let m = &case.initial.mechanism;
    let run = simulate(m, &case.initial.q, &case.initial.u, &case.options)?;
    if let Some(path) = &args.csv {
        let coordinates: Vec<String> = m.coordinates().iter().map(|c| c.to_string()).collect();
        csv::write(
            path,
            &coordinates,
            &csv::speed_columns(&coordinates, &coordinates),
            &run.samples,
        )?;
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
        serde_json::to_string_pretty(&json::document(&case, &run)).map_err(CliError::failure)?
            + "\n"
    } else {
        table::table(&case, &run)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}
