//! The `impax` command line as a library: the binary (`src/main.rs`) is [`invoke`] on the
//! process's arguments, and the fuzz targets (`fuzz/`) call the same entry points.
//!
//! Subcommands: `compare` (every law side by side on one body impact; default: the seed's
//! sphere; `--plot` draws Routh's diagram and energy bars), `resolve` (a contact-space problem
//! directly), `paper` (reproduction reports), `sweep` (parameter sweeps streamed as CSV),
//! `map` (maps of a 2-parameter sweep as PNG/SVG), `conserved` (conserved quantities of a
//! mechanism's motion), `simulate` (trajectories with impacts), `audit` (an impact as a
//! physics engine computes it, against the rigid-body answer), `explore` (the interactive
//! page in the browser).
//! Bad input of any kind prints one line on stderr and exits with code 2.

mod cli;
mod commands;
pub mod contract;
pub mod input;
mod output;
mod pipeline;
mod sources;

use clap::Parser;
use std::ffi::OsString;

/// Exit code for bad input (usage, values, files).
pub const EXIT_BAD_INPUT: u8 = 2;
/// Exit code for any other failure (e.g. a closed stdout).
pub const EXIT_FAILURE: u8 = 1;

/// What one invocation of the command line produced.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Invocation {
    /// The exit code: 0, [`EXIT_BAD_INPUT`] or [`EXIT_FAILURE`].
    pub code: u8,
    /// What goes to standard output (subcommands that stream — `sweep`'s CSV, `explore` —
    /// write there themselves).
    pub stdout: Vec<u8>,
    /// What goes to standard error: one line on an error.
    pub stderr: String,
}

/// Run the command line on `args` (the first is the program's name), as the binary does.
pub fn invoke<I, T>(args: I) -> Invocation
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match cli::Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(err) => {
            use clap::error::ErrorKind;
            let (code, stdout, stderr) = match err.kind() {
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
                    (0, err.render().to_string().into_bytes(), String::new())
                }
                ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                    (EXIT_BAD_INPUT, Vec::new(), err.render().to_string())
                }
                _ => (
                    EXIT_BAD_INPUT,
                    Vec::new(),
                    format!("{}\n", input::one_line_clap_error(&err)),
                ),
            };
            return Invocation {
                code,
                stdout,
                stderr,
            };
        }
    };
    let mut out = Vec::new();
    let result = match &cli.command {
        cli::Command::Compare(args) => commands::compare::run(args, &mut out),
        cli::Command::Resolve(args) => commands::resolve::run(args, &mut out),
        cli::Command::Paper(args) => commands::paper::run(args, &mut out),
        cli::Command::Sweep(args) => commands::sweep::run(args),
        cli::Command::Map(args) => commands::map::run(args, &mut out),
        cli::Command::Explore(args) => commands::explore::run(args, &mut out),
        cli::Command::Conserved(args) => commands::conserved::run(args, &mut out),
        cli::Command::Simulate(args) => commands::simulate::run(args, &mut out),
        cli::Command::Audit(args) => commands::audit::run(args, &mut out),
    };
    match result {
        Ok(()) => Invocation {
            code: 0,
            stdout: out,
            stderr: String::new(),
        },
        Err(err) => Invocation {
            code: match err.kind {
                input::ErrorKind::BadInput => EXIT_BAD_INPUT,
                input::ErrorKind::Failure => EXIT_FAILURE,
            },
            stdout: Vec::new(),
            stderr: format!("error: {}\n", err.message.replace('\n', " ")),
        },
    }
}

/// The Rust examples of the book's chapter "The Rust library" (`docs/src/library.md`),
/// compiled and run as doctests so that the book cannot drift from the library.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/src/library.md")]
pub struct BookLibraryChapter;
