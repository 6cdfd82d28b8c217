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
//!
//! ## Feature `serde`
//! `Serialize` and `Deserialize` (as num-dual's `serde` feature does) on the law ids
//! ([`LawId`], written as its id: `"two-phase"`), the verdicts, inconsistencies and breakdowns
//! ([`law::Verdict`], [`law::Inconsistency`], [`law::Breakdown`], [`law::BreakdownReason`]),
//! the work split, the outcomes with their phases and details ([`planar::Outcome`],
//! [`spatial::Outcome`], [`multi::MultiOutcome`], [`planar::bodies::BodyOutcome`],
//! [`spatial::bodies::BodyOutcome`]), the problems ([`planar::ContactProblem`],
//! [`spatial::ContactProblem`], [`multi::MultiProblem`]) and the scenario
//! ([`scenario::PlanarScenario`]); nalgebra's vectors with it. Ids are written as the ids the
//! command line prints: a verdict as `"energy-gained"`, an enum with numbers as an object
//! tagged by its `"id"` (`{"id": "slip-reversed", "slip_after": -0.1}`). A problem is written
//! as plain data (`W` by rows, `v⁻`, the coefficients) and read back through its validating
//! constructor: what is read is as checked as what is built, and an invalid problem is an
//! error naming its field. Every value reads back equal to what was written.
//!
//! ```toml
//! impax = { version = "0.1", features = ["serde"] }
//! ```
//!
//! ```
//! # #[cfg(feature = "serde")]
//! # {
//! use impax::{LawId, planar::{ContactProblem, Outcome}};
//! let p = ContactProblem::from_entries(3.5, 0.0, 1.0, 0.5, -0.75f64.sqrt(), 0.4, 0.7)?;
//! let o = LawId::TwoPhase.resolve(&p).expect("a result");
//! let json = serde_json::to_value(&o)?;
//! assert_eq!(json["law"], "two-phase");
//! assert_eq!(json["verdict"], "energy-gained");
//! assert_eq!(json["inconsistency"]["id"], "reversal-did-not-happen");
//! assert_eq!(serde_json::from_value::<Outcome>(json)?, o);
//! // A problem is read through its validation: here v_n ≥ 0 (no approach).
//! let bad = r#"{"w": [[3.5, 0.0], [0.0, 1.0]], "v": [0.5, 0.1], "friction": 0.4, "restitution": 0.7}"#;
//! let e = serde_json::from_str::<ContactProblem>(bad).unwrap_err();
//! assert!(e.to_string().starts_with("v: "));
//! # }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod analysis;
pub mod error;
#[cfg(feature = "serde")]
mod forms;
pub mod impact;
#[cfg(feature = "json")]
pub mod json;
pub mod law;
pub mod math;
pub mod mechanism;
pub mod multi;
pub mod multibody;
mod numerics;
pub mod ode;
pub mod paper;
pub mod planar;
pub mod scenario;
pub mod simulation;
pub mod spatial;

pub use error::{Error, Result};
pub use law::{ImpactLaw, LawId};
