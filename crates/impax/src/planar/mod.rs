//! Planar (2D) impacts in contact space: the problem, the laws, the outcome.
//!
//! Data flows one way: [`ContactProblem`] → a law ([`laws`]) → [`Outcome`] or [`Breakdown`].

pub mod bodies;
pub mod laws;
mod outcome;
pub(crate) mod path;
mod problem;

// The shared vocabulary, also at `impax::law` (re-exported here, where it always was).
pub use crate::law::{Breakdown, BreakdownReason, Inconsistency, Verdict, WorkSplit};
pub use outcome::{
    BriefResolution, LawDetail, Outcome, OutcomeBrief, Phase, PhaseKind, Phases, Resolution,
    SlipDirection, SmithReading,
};
pub use problem::{ContactProblem, InverseInertia};
