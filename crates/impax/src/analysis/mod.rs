//! Analysis at scale: parameter spaces, the batch API, a deterministic parallel sweep driver,
//! reductions, and the analytic threshold of paper A's energy-gain map.
//!
//! * [`grid`]: [`Axis`], [`Grid`] and [`RandomSamples`]: point `i` ↦ parameter values, a
//!   pure function of `i`;
//! * [`batch`]: [`resolve_problems`] / [`resolve_columns`]: one law over many problems
//!   (structure-of-arrays in, compact [`ImpactSummary`] records out), no allocation;
//!   [`for_each_brief`]: each law's verdict, phases and `ΔT` only, for reductions;
//! * [`sweep`]: [`run_ordered`]: chunks computed in parallel, consumed in order, constant
//!   memory — output independent of the thread count;
//! * [`tally`]: [`Tally`]: counts by verdict and phase sequence, range of `ΔT/T0`;
//! * [`threshold`]: Whittaker's energy-gain thresholds for the sphere, paper A eq. 13.
//!
//! No I/O: front ends (the `impax` CLI) map points to problems, write rows and draw maps.

pub mod batch;
pub mod grid;
pub mod sweep;
pub mod tally;
pub mod threshold;

pub use batch::{
    for_each_brief, for_each_resolution, resolve_columns, resolve_problems, ImpactSummary,
    ProblemColumns, Sequence, Status,
};
pub use grid::{Axis, Grid, RandomSamples, SampleRange, Space};
pub use sweep::{run_ordered, run_ordered_waves};
pub use tally::Tally;
pub use threshold::{whittaker_sphere_energy_ratio, whittaker_sphere_thresholds, SphereThresholds};
