//! What the subcommands write: aligned tables and numbers ([`fmt`]), JSON records
//! ([`json`]), plots ([`plot`]) and animations ([`animation`]).

pub mod animation;
pub mod fmt;
pub use impax::json;
pub mod plot;
