//! Spatial impacts at several contacts at once: the problem, the laws `lcp` and `sequential`,
//! the outcome — the planar [`crate::multi`] with two tangents per contact (theory §6).
//!
//! `K` contacts, contact-major: `v = (v_t1,1, v_t2,1, v_n,1, …)`, `p` likewise;
//! `v⁺ = v⁻ + W p` with `W = J M⁻¹ Jᵀ` (`3K × 3K`, symmetric positive semidefinite; a box
//! lying flat on four corners has rank 6) and `ΔT = ½ (v⁻ + v⁺)·p`.
//!
//! | law | module | rule |
//! |---|---|---|
//! | `lcp` | [`lcp`] | the complementarity impact at every contact at once with the exact circular cone: the contacts' modes enumerated, each slip direction a root of `ŝ × v_t⁺ = 0` |
//! | `sequential` | [`sequential`] | binary impacts with the spatial `energetic` law, the most approaching contact first |
//! | `lzb` | [`lzb`] | Liu, Zhao & Brogliato's multiple impacts with Coulomb friction at each contact, the slip directions turning (swirl), integrated to the end |
//!
//! With `K = 1` every spatial contact-space law applies (its one-contact outcome carried
//! over, [`MultiOutcome::from_outcome`]; `lzb` and `sequential` are `energetic`).
//!
//! ```
//! use impax::multi::spatial::{resolve, MultiProblem};
//! use impax::LawId;
//! // Two decoupled contacts (a block-diagonal W): each is its own one-contact problem.
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[3.5, 0.0, 0.0, 0.0, 0.0, 0.0, /**/ 3.5, 0.0, 0.0, 0.0, 0.0, /**/ 1.0, 0.0, 0.0, 0.0,
//!       /**/ 2.0, 0.0, 0.0, /**/ 2.0, 0.0, /**/ 1.0],
//!     &[0.5, 0.0, -1.0, 0.0, 0.2, -0.5],
//!     &[0.3],
//!     &[0.6],
//! )
//! .unwrap();
//! let out = resolve(LawId::Lcp, &p).unwrap().unwrap();
//! for c in &out.contacts {
//!     assert!(c.velocity_after.z > 0.0);
//! }
//! ```

pub mod lcp;
pub mod lzb;
mod outcome;
mod problem;
pub mod sequential;

pub use outcome::{
    BinaryImpact, ContactPhase, ContactPhaseKind, ContactResult, LcpSolution, MultiDetail,
    MultiOutcome, MultiResolution,
};
pub use problem::MultiProblem;

use crate::error::{Error, Result};
use crate::law::{Breakdown, LawId, Options};

/// Resolve a spatial `problem` with `law`: `lcp` (up to [`lcp::MAX_CONTACTS`] contacts),
/// `sequential` and `lzb` (up to [`lzb::MAX_CONTACTS`]) for several contacts; with `K = 1`
/// every spatial contact-space law (`lzb` is then `energetic`). Errors name the field `law`.
pub fn resolve(law: LawId, problem: &MultiProblem) -> Result<MultiResolution> {
    resolve_by(law, problem, &Options::default())
}

impl crate::law::Problem for MultiProblem {
    type Resolution = Result<MultiResolution>;

    /// [`resolve`] with the options `options` (the tolerance of a one-contact spatial law).
    #[inline]
    fn resolve_by(&self, law: LawId, options: &Options) -> Result<MultiResolution> {
        resolve_by(law, self, options)
    }
}

/// [`resolve`] with the options `options`.
fn resolve_by(law: LawId, problem: &MultiProblem, options: &Options) -> Result<MultiResolution> {
    let k = problem.contacts();
    match law {
        LawId::Lcp if k > lcp::MAX_CONTACTS => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`lcp` in 3D enumerates the 3^K combinations of the contacts' modes and takes at most {} contacts, got {k} (`sequential` takes any number)",
                lcp::MAX_CONTACTS
            ),
        }),
        LawId::Lcp if k > 1 => Ok(lcp::resolve(problem)),
        LawId::Sequential if k > 1 => Ok(sequential::resolve(problem)),
        LawId::Lzb if k > lzb::MAX_CONTACTS => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`lzb` integrates on fixed-size arrays and takes at most {} contacts, got {k} (`sequential` takes any number)",
                lzb::MAX_CONTACTS
            ),
        }),
        LawId::Lzb if k > 1 => Ok(lzb::resolve(problem)),
        _ if k == 1 => {
            let one = problem.contact(0)?;
            let run = match law {
                LawId::Sequential | LawId::Lzb => LawId::Energetic,
                l => l,
            };
            if !LawId::SPATIAL.contains(&run) {
                return Err(Error::Invalid {
                    field: "law".into(),
                    reason: format!("`{law}` has no spatial form"),
                });
            }
            Ok(crate::spatial::laws::resolve(run, &one, options)
                .map(|o| {
                    let mut m = MultiOutcome::from_outcome(&o);
                    m.law = law;
                    m
                })
                .map_err(|b| Breakdown { law, ..b }))
        }
        _ => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`{law}` is a one-contact law; with {k} contacts in 3D use lcp, sequential or lzb"
            ),
        }),
    }
}
