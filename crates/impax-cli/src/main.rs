//! `impax`: rigid-body impact with friction, from the command line.
//!
//! Subcommands: `compare` (every law side by side on one body impact; default: the seed's
//! sphere; `--plot` draws Routh's diagram and energy bars), `resolve` (a contact-space problem
//! directly), `paper` (reproduction reports), `sweep` (parameter sweeps streamed as CSV),
//! `map` (maps of a 2-parameter sweep as PNG/SVG), `conserved` (conserved quantities of a
//! mechanism's motion), `simulate` (trajectories with impacts), `audit` (an impact as a
//! physics engine computes it, against the rigid-body answer), `explore` (the interactive
//! page in the browser).
//! Bad input of any kind prints one line on stderr and exits with code 2.

mod animation;
mod audit;
mod cli;
mod columns;
mod compare;
mod compare3;
mod compare_mech;
mod conserved;
mod csv_rows;
mod evaluate;
mod explore;
mod fmt;
mod input;
mod json;
mod map;
mod mechanism;
mod paper;
#[cfg(feature = "parquet")]
mod parquet_out;
mod plot;
mod progress;
mod resolve;
mod scenario;
mod simulate;
mod space;
mod sweep;
mod template;

use clap::Parser;
use std::io::Write;
use std::process::ExitCode;

/// Exit code for bad input (usage, values, files).
const EXIT_BAD_INPUT: u8 = 2;
/// Exit code for any other failure (e.g. a closed stdout).
const EXIT_FAILURE: u8 = 1;

fn main() -> ExitCode {
    let cli = match cli::Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => {
            use clap::error::ErrorKind;
            if matches!(
                err.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = err.print();
                return if err.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                    ExitCode::from(EXIT_BAD_INPUT)
                } else {
                    ExitCode::SUCCESS
                };
            }
            eprintln!("{}", input::one_line_clap_error(&err));
            return ExitCode::from(EXIT_BAD_INPUT);
        }
    };
    let mut out = Vec::new();
    let result = match &cli.command {
        cli::Command::Compare(args) => compare::run(args, &mut out),
        cli::Command::Resolve(args) => resolve::run(args, &mut out),
        cli::Command::Paper(args) => paper::run(args, &mut out),
        cli::Command::Sweep(args) => sweep::run(args),
        cli::Command::Map(args) => map::run(args, &mut out),
        cli::Command::Explore(args) => explore::run(args, &mut out),
        cli::Command::Conserved(args) => conserved::run(args, &mut out),
        cli::Command::Simulate(args) => simulate::run(args, &mut out),
        cli::Command::Audit(args) => audit::run(args, &mut out),
    };
    match result {
        Ok(()) => {
            let mut stdout = std::io::stdout().lock();
            if stdout.write_all(&out).and_then(|_| stdout.flush()).is_err() {
                return ExitCode::from(EXIT_FAILURE);
            }
            ExitCode::SUCCESS
        }
        Err(err) => {
            eprintln!("error: {}", err.message.replace('\n', " "));
            ExitCode::from(match err.kind {
                input::ErrorKind::BadInput => EXIT_BAD_INPUT,
                input::ErrorKind::Failure => EXIT_FAILURE,
            })
        }
    }
}
