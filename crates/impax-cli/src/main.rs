//! `impax`: rigid-body impact with friction, from the command line.
//!
//! Subcommands: `compare` (every law side by side on one body impact; default: the seed's
//! sphere), `resolve` (a contact-space problem directly), `paper` (reproduction reports).
//! Bad input of any kind prints one line on stderr and exits with code 2.

mod cli;
mod compare;
mod fmt;
mod input;
mod json;
mod paper;
mod resolve;
mod scenario;

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
