//! Planar impacts at several contacts at once: the problem, the laws `lcp`, `sequential` and
//! `lzb`, the outcome (theory §6).
//!
//! `K` contacts, contact-major: `v = (v_t1, v_n1, …, v_tK, v_nK)`, `p` likewise (the impulse on
//! body A at each contact; `p_nj ≥ 0`). With the configuration frozen,
//!
//! ```text
//! v⁺ = v⁻ + W p,    W = J M⁻¹ Jᵀ  (2K × 2K, symmetric positive semidefinite),
//! ΔT = v⁻·p + ½ pᵀ W p = ½ (v⁻ + v⁺)·p      (exact for any impulse).
//! ```
//!
//! `W` is singular when the contact rows `J` are dependent (a rod lying flat: four rows, three
//! degrees of freedom); `v⁻ = J u` is then in the range of `W` and the velocities after are
//! determined while the impulses are not (`p + z`, `W z = 0`).
//!
//! | law | module | rule |
//! |---|---|---|
//! | `lcp` | [`lcp`] | `0 ≤ p_nj ⊥ v_nj⁺ − max(−e_j v_nj⁻, 0) ≥ 0` and Coulomb with maximal dissipation at every contact at once (Anitescu & Potra 1997; Stewart & Trinkle 1996); every solution, by exact enumeration of the contacts' modes |
//! | `sequential` | [`sequential`] | binary impacts: the most approaching contact alone with `energetic`, all velocities updated, until none approaches |
//! | `lzb` | [`lzb`] | Liu, Zhao & Brogliato's multiple impacts (2008, 2009): every contact a compliant element `F_j = κ_j δ_j^η` storing energy, the impulses distributed by the force law, energetic restitution and Coulomb friction at each contact, integrated to the end |
//!
//! Data flows one way: [`MultiProblem`] → [`lcp::resolve`] / [`sequential::resolve`] /
//! [`lzb::resolve`] (or [`LawId::resolve`]) → [`MultiOutcome`] or
//! [`Breakdown`]. With one contact they reduce to the one-contact laws
//! (`lcp` to [`crate::planar::laws::Lcp`], `sequential` and `lzb` to
//! [`crate::planar::laws::Energetic`]).
//!
//! ```
//! use impax::{LawId, multi::MultiProblem};
//! // A uniform rod (m = 1, l = 1) lying flat lands on both ends at v_y = −1, e = 0.8:
//! // W (rank 3) from J M⁻¹ Jᵀ with the ends at x = ∓1/2 (theory §6).
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[1.0, 0.0, 1.0, 0.0, /**/ 4.0, 0.0, -2.0, /**/ 1.0, 0.0, /**/ 4.0],
//!     &[0.0, -1.0, 0.0, -1.0],
//!     &[0.5],
//!     &[0.8],
//! )
//! .unwrap();
//! let out = LawId::Lcp.resolve(&p).unwrap().unwrap();
//! for c in &out.contacts {
//!     assert!((c.velocity_after.y - 0.8).abs() < 1e-12); // both ends leave at e |v_y|
//!     assert!((c.impulse.y - 0.9).abs() < 1e-12);        // (1 + e) m |v_y| / 2 each
//! }
//! ```

pub mod lcp;
pub mod lzb;
mod outcome;
pub(crate) mod problem;
pub mod scenarios;
pub mod sequential;
pub mod spatial;
mod system;
pub(crate) mod validate;

pub use outcome::{
    is_energy_gain, BinaryImpact, ContactPhase, ContactPhaseKind, ContactResult, LcpSolution,
    LzbPrimary, MultiDetail, MultiOutcome, MultiResolution, PerContact, Phases, VELOCITY_ROUND_OFF,
};
pub use problem::{MultiProblem, HERTZ_EXPONENT, RANGE_TOL, RANK_TOL};
pub use scenarios::MultiScenario;
pub use system::{MultiImpact, SystemOutcome, SystemProblem};

use crate::error::{Error, Result};
use crate::law::LawId;
use crate::law::{Breakdown, BreakdownReason};

/// Resolve `problem` with `law` (as [`LawId::resolve`] does): `lcp`, `sequential` and `lzb`
/// for several contacts (`lcp` up to [`lcp::MAX_CONTACTS`], `lzb` up to
/// [`lzb::MAX_CONTACTS`]); with `K = 1` every contact-space law, its one-contact outcome
/// carried over ([`MultiOutcome::from_outcome`]). Errors name the field `law`: a one-contact
/// law with `K ≥ 2`, `smith-centre`, `lcp` with `K >` [`lcp::MAX_CONTACTS`], `lzb` with
/// `K >` [`lzb::MAX_CONTACTS`].
pub fn resolve(law: LawId, problem: &MultiProblem) -> Result<MultiResolution> {
    let k = problem.contacts();
    if law.needs_body() {
        return Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`{law}` needs a body (it reads the centre velocity); contact space has none"
            ),
        });
    }
    match law {
        LawId::Lcp if k > lcp::MAX_CONTACTS => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`lcp` enumerates the 4^K combinations of the contacts' modes and takes at most {} contacts, got {k} (`sequential` takes any number)",
                lcp::MAX_CONTACTS
            ),
        }),
        LawId::Lcp => Ok(lcp::resolve(problem)),
        LawId::Sequential => Ok(sequential::resolve(problem)),
        LawId::Lzb if k > lzb::MAX_CONTACTS => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`lzb` integrates on fixed-size arrays and takes at most {} contacts, got {k} (`sequential` takes any number)",
                lzb::MAX_CONTACTS
            ),
        }),
        LawId::Lzb => Ok(lzb::resolve(problem)),
        _ if k == 1 => {
            let one = problem.contact(0)?;
            Ok(law.resolve(&one).map(|o| MultiOutcome::from_outcome(&o)))
        }
        _ => Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`{law}` is a one-contact law; with {k} contacts use {}",
                LawId::MULTI_CONTACT.map(|l| l.as_str()).join(" or ")
            ),
        }),
    }
}

impl crate::law::Problem for MultiProblem {
    type Resolution = Result<MultiResolution>;

    /// Resolve a planar problem with several contacts ([`crate::multi`]).
    ///
    /// `lcp`, `sequential` and `lzb` take several contacts (`lcp` at most
    /// [`crate::multi::lcp::MAX_CONTACTS`], `lzb` at most [`crate::multi::lzb::MAX_CONTACTS`],
    /// `sequential` any number); with one contact every contact-space law does,
    /// its one-contact outcome carried over ([`MultiOutcome::from_outcome`]).
    ///
    /// Errors ([`Error::Invalid`] naming the field `law`): a one-contact law with two contacts
    /// or more, `smith-centre` (it needs a body), `lcp` with more than
    /// [`crate::multi::lcp::MAX_CONTACTS`] contacts, `lzb` with more than
    /// [`crate::multi::lzb::MAX_CONTACTS`]. A law that has no result for these
    /// numbers gives a [`Breakdown`], as with one contact.
    ///
    /// [`MultiOutcome::from_outcome`]: crate::multi::MultiOutcome::from_outcome
    ///
    /// ```
    /// use impax::{LawId, multi::MultiProblem};
    /// // Two contacts that do not interact: each is its own one-contact problem.
    /// let p = MultiProblem::from_upper(
    ///     2,
    ///     &[2.0, 0.5, 0.0, 0.0, /**/ 1.5, 0.0, 0.0, /**/ 3.0, 0.2, /**/ 1.0],
    ///     &[0.3, -1.0, -0.4, -0.5],
    ///     &[0.3],
    ///     &[0.5],
    /// )
    /// .unwrap();
    /// let out = LawId::Lcp.resolve(&p).unwrap().unwrap();
    /// assert!((out.contacts[0].velocity_after.y - 0.5).abs() < 1e-12); // −e v_n⁻
    /// assert!((out.contacts[1].velocity_after.y - 0.25).abs() < 1e-12);
    /// assert!(LawId::Whittaker.resolve(&p).is_err()); // a one-contact law
    /// ```
    ///
    /// The planar laws are exact: `options` changes nothing.
    fn resolve_by(&self, law: LawId, _options: &crate::law::Options) -> Result<MultiResolution> {
        resolve(law, self)
    }
}

/// `Err(too-many-contacts)` when a law that takes at most `limit` contacts is given `k`.
pub(crate) fn within(law: LawId, k: usize, limit: usize) -> std::result::Result<(), Breakdown> {
    if k > limit {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::TooManyContacts { contacts: k, limit },
        });
    }
    Ok(())
}

/// The outcome, or the breakdown `overflow` when one of its numbers is not finite.
pub(crate) fn finite_or_overflow<T>(
    law: LawId,
    out: T,
    finite: bool,
) -> std::result::Result<T, Breakdown> {
    if finite {
        Ok(out)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
    }
}
