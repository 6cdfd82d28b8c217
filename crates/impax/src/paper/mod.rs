//! Reproductions of the source papers: every numbered result beside the value impax computes.
//!
//! Each report is a pure function returning rows (no I/O); front ends render them.
//!
//! * [`liu2012`] — paper A, Liu Yanzhu, *On Kane's paradox of frictional impact*,
//!   Mechanics in Engineering 2012(1): the seed's sphere under Whittaker's rule, the two-phase
//!   scheme and Smith's correction, and the exact Darboux–Keller answer.

pub mod liu2012;
