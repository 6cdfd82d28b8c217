//! # impax — rigid-body impact with friction
//!
//! Every classical frictional impact law side by side, the energy-consistent ones exact:
//! `whittaker`, `two-phase`, `smith`, `brach`, the Darboux–Keller integration in normal
//! impulse terminated by `newton`, `poisson` or `energetic` restitution, and `lcp`, the
//! velocity-level complementarity impact that physics engines converge to.
//!
//! ## Conventions
//! Contact frame: tangent first, normal last; the normal points out of the struck surface;
//! approach means `v_n < 0`; `p` is the impulse on the moving body (body A) and `p_n ≥ 0`.
//! Angles are radians in the library.
//!
//! ## Example: the seed's sphere (Liu 2012, paper A)
//!
//! ```
//! use impax::{LawId, planar::ContactProblem};
//! let alpha = 30f64.to_radians();
//! // Sphere, m = 1: W = diag(7/2, 1); v0 = 1, γ = 0 (no spin): v⁻ = (sin α, −cos α).
//! let p = ContactProblem::from_entries(3.5, 0.0, 1.0, alpha.sin(), -alpha.cos(), 0.4, 0.7)
//!     .unwrap();
//! let whittaker = LawId::Whittaker.resolve(&p).unwrap();
//! let energetic = LawId::Energetic.resolve(&p).unwrap();
//! assert!(whittaker.energy_change > 0.0); // Kane's paradox
//! assert!(energetic.energy_change < 0.0); // the slip halts; the sphere leaves rolling
//! assert_eq!(energetic.velocity_after.x, 0.0);
//! ```

#![warn(missing_docs)]

pub mod analysis;
pub mod bodies;
pub mod bodies3;
pub mod error;
pub mod law;
pub mod math;
pub mod mechanism;
pub mod multi;
mod numerics;
pub mod ode;
pub mod paper;
pub mod planar;
pub mod scenario;
pub mod simulation;
pub mod spatial;

pub use error::{Error, Result};
pub use law::{ImpactLaw, LawId};
