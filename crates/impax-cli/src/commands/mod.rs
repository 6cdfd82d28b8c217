//! One module per subcommand, each with one entry point `run`.

pub mod audit;
pub mod compare;
pub mod conserved;
pub mod explore;
pub mod map;
pub mod paper;
pub mod resolve;
pub mod simulate;
pub mod sweep;
