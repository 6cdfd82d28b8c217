//! `impax`: rigid-body impact with friction, from the command line (see the `impax_cli`
//! library for the subcommands). Bad input of any kind prints one line on stderr and exits
//! with code 2.

use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let run = impax_cli::invoke(std::env::args_os());
    eprint!("{}", run.stderr);
    let mut stdout = std::io::stdout().lock();
    if stdout
        .write_all(&run.stdout)
        .and_then(|_| stdout.flush())
        .is_err()
    {
        return ExitCode::from(impax_cli::EXIT_FAILURE);
    }
    ExitCode::from(run.code)
}
