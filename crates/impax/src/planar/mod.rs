//! Planar (2D) impacts in contact space: the problem, the laws, the outcome.
//!
//! Data flows one way: [`ContactProblem`] → a law ([`laws`]) → [`Outcome`] or [`Breakdown`].

pub mod laws;
mod outcome;
pub mod path;
mod problem;

pub use outcome::{
    Breakdown, BreakdownReason, Inconsistency, LawDetail, Outcome, Phase, PhaseKind, Phases,
    Resolution, SlipDirection, SmithReading, Verdict, WorkSplit,
};
pub use problem::{ContactProblem, InverseInertia};
