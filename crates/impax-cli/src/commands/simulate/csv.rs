//! `impax simulate --csv FILE`: the sampled trajectory, a row per sample (time, mode,
//! coordinates, their rates, the energies).

use crate::input::{CliError, CliResult};
use impax::simulation::Sample;
use std::io::Write;
use std::path::Path;

/// Write `samples` to `path`: columns `t`, `mode`, the coordinates `coordinates`, the speeds
/// `speeds`, `kinetic`, `potential`, `energy`.
pub(super) fn write(
    path: &Path,
    coordinates: &[String],
    speeds: &[String],
    samples: &[Sample],
) -> CliResult<()> {
    let file = std::fs::File::create(path)
        .map_err(|e| CliError::input(format!("--csv {}: cannot create: {e}", path.display())))?;
    let mut w = std::io::BufWriter::new(file);
    let mut header = vec!["t".to_string(), "mode".to_string()];
    header.extend(coordinates.iter().cloned());
    header.extend(speeds.iter().cloned());
    header.extend(["kinetic".into(), "potential".into(), "energy".into()]);
    let fail = |e: std::io::Error| CliError::failure(format!("writing {}: {e}", path.display()));
    writeln!(w, "{}", header.join(",")).map_err(fail)?;
    for s in samples {
        let mut row = vec![format!("{}", s.t), s.mode.id().to_string()];
        row.extend(s.q.iter().chain(&s.u).map(|x| format!("{x}")));
        row.extend([s.kinetic, s.potential, s.kinetic + s.potential].map(|x| format!("{x}")));
        writeln!(w, "{}", row.join(",")).map_err(fail)?;
    }
    w.flush().map_err(fail)
}

/// The speeds' column names: a speed that is a coordinate's rate is `NAME_rate` (every speed
/// of a planar mechanism, a robot's joints), the others keep their names (a floating base's
/// `vx`, …, `wz`).
pub(super) fn speed_columns(coordinates: &[String], speeds: &[String]) -> Vec<String> {
    speeds
        .iter()
        .map(|s| {
            if coordinates.contains(s) {
                format!("{s}_rate")
            } else {
                s.clone()
            }
        })
        .collect()
}
