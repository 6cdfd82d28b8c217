//! `impax paper`: reproduction reports of the source papers.

use crate::cli::PaperArgs;
use crate::input::{CliError, CliResult};

pub fn run(args: &PaperArgs, _out: &mut Vec<u8>) -> CliResult<()> {
    Err(CliError::input(format!(
        "paper: unknown paper `{}` (known: liu2012)",
        args.paper
    )))
}
