//! The pipeline of `impax sweep` and `impax map`: the sweep space (grid or random samples,
//! threads), the scenario as named numeric fields ([`template`]), the evaluation of each
//! point with every law, and the outputs (CSV rows, Parquet, columns, progress).

pub mod columns;
pub mod csv_rows;
pub mod evaluate;
#[cfg(feature = "parquet")]
pub mod parquet_out;
pub mod progress;
pub mod space;
pub mod template;
