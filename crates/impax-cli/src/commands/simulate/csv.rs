//! `impax simulate --csv FILE`: the sampled trajectory, a row per sample (time, mode,
//! coordinates, their rates, the energies).

use crate::input::{CliError, CliResult};
use impax::mechanism::Mechanism;
use impax::simulation::Run;
use std::io::Write;
use std::path::Path;

/// Write the samples of `run` to `path`.
pub(super) fn write<M: Mechanism>(path: &Path, m: &M, run: &Run) -> CliResult<()> {
    let file = std::fs::File::create(path)
        .map_err(|e| CliError::input(format!("--csv {}: cannot create: {e}", path.display())))?;
    let mut w = std::io::BufWriter::new(file);
    let coords = m.coordinates();
    let mut header = vec!["t".to_string(), "mode".to_string()];
    header.extend(coords.iter().map(|c| c.to_string()));
    header.extend(coords.iter().map(|c| format!("{c}_rate")));
    header.extend(["kinetic".into(), "potential".into(), "energy".into()]);
    let fail = |e: std::io::Error| CliError::failure(format!("writing {}: {e}", path.display()));
    writeln!(w, "{}", header.join(",")).map_err(fail)?;
    for s in &run.samples {
        let mut row = vec![format!("{}", s.t), s.mode.id().to_string()];
        row.extend(s.q.iter().chain(&s.u).map(|x| format!("{x}")));
        row.extend([s.kinetic, s.potential, s.kinetic + s.potential].map(|x| format!("{x}")));
        writeln!(w, "{}", row.join(",")).map_err(fail)?;
    }
    w.flush().map_err(fail)
}
