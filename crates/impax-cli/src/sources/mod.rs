//! Where a system comes from: a body scenario file (or the seed's) and a built-in
//! mechanism or mechanism file.

pub mod mechanism;
pub mod scenario;
