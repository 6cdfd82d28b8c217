//! `impax resolve`: a contact-space problem directly — planar ([`planar`]), spatial
//! ([`spatial`]), or with several contacts, planar ([`multi`]) or spatial ([`multi_spatial`]).

mod multi;
mod multi_spatial;
mod planar;
mod spatial;

pub(crate) use multi::force_law;
pub(crate) use spatial::lcp_solutions;

use crate::cli::ResolveArgs;
use crate::input::{CliError, CliResult};

pub fn run(args: &ResolveArgs, out: &mut Vec<u8>) -> CliResult<()> {
    if let Some(k) = args.contacts {
        return multi::run(args, k, out);
    }
    if !args.stiffness.is_empty() || args.exponent.is_some() {
        let flag = if args.stiffness.is_empty() {
            "exponent"
        } else {
            "stiffness"
        };
        return Err(CliError::input(format!(
            "--{flag}: a parameter of `lzb` at several contacts; only with --contacts K"
        )));
    }
    let count = args.w.split(',').count();
    if count == 6 {
        return spatial::run(args, out);
    }
    if count != 3 {
        return Err(CliError::input(format!(
            "--w: expected 3 numbers (planar: WTT,WTN,WNN) or 6 (spatial: W11,W12,W13,W22,W23,W33), got {count} in `{}` (several contacts: --contacts K)",
            args.w
        )));
    }
    planar::run(args, out)
}

/// The one value of `--flag` (a list is for several contacts).
pub(super) fn single(flag: &str, values: &[f64]) -> CliResult<f64> {
    match values {
        [x] => Ok(*x),
        _ => Err(CliError::input(format!(
            "--{flag}: expected one number, got {} (one per contact needs --contacts K)",
            values.len()
        ))),
    }
}
