//! Planar (2D) impacts in contact space: the problem, the laws, the outcome.
//!
//! Data flows one way: [`ContactProblem`] → a law ([`laws`]) → [`Outcome`] or [`Breakdown`].

pub mod laws;
mod outcome;
pub mod path;
mod problem;

pub(crate) use outcome::record_is_finite;
pub use outcome::{
    Breakdown, BreakdownReason, BriefResolution, Inconsistency, LawDetail, Outcome, OutcomeBrief,
    Phase, PhaseKind, Phases, Resolution, SlipDirection, SmithReading, Verdict, WorkSplit,
};
pub(crate) use problem::Units;
pub use problem::{ContactProblem, InverseInertia};
