//! Spatial (3D) impacts in contact space: the problem, the laws, the outcome, and the
//! structure of the slip field (invariant rays, resumption).
//!
//! ```
//! use impax::{LawId, spatial::ContactProblem};
//! // A planar problem embedded in 3D agrees with the planar closed form.
//! let p = ContactProblem::from_upper([3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [0.5, 0.0, -0.866], 0.4, 0.7)
//!     .unwrap();
//! let out = LawId::Energetic.resolve(&p).unwrap();
//! assert!((out.impulse.x + 0.5 / 3.5).abs() < 1e-12);
//! ```

pub mod bodies;
pub mod darboux_keller;
pub mod invariant;
pub mod laws;
mod outcome;
pub(crate) mod problem;

pub use invariant::{
    invariant_rays, resumption_direction, sticking_ratio, InvariantRay, InvariantRays, RayKind,
};
pub use outcome::{LawDetail, Outcome, Phase, PhaseKind, Phases, Resolution};
pub use problem::{ContactProblem, NEGLIGIBLE_SLIP, PIVOT_TOL};
