//! Why a law produced no result, as data.

use super::LawId;
use crate::math::Units;
use std::fmt;

/// Why a law produced no admissible result.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum BreakdownReason {
    /// The law's normal impulse would be negative (or unbounded): the denominator of
    /// `p_n = −(1+e) v_n⁻ / denominator` is not positive.
    NegativeNormalImpulse {
        /// The denominator, e.g. `W_nn − μ s0 W_tn` for Whittaker.
        denominator: f64,
    },
    /// The two-phase scheme finds no split: the switch would come after the impact ends.
    NoConsistentSplit {
        /// The switch impulse `p'`.
        switch_impulse: f64,
        /// The total normal impulse the second phase would need.
        total_impulse: f64,
    },
    /// Smith's equation for `η` has no admissible root.
    NoEtaRoot,
    /// The normal velocity cannot reach the termination: the bodies would not separate
    /// (a numerically degenerate problem).
    NoSeparation,
    /// The law is defined for planar problems only (`two-phase`, `smith`, `smith-centre`).
    PlanarOnly,
    /// The law reads a body's centre velocity (`smith-centre`) and was given only a
    /// contact-space problem.
    NeedsBody,
    /// The complementarity conditions of `lcp` have no solution (not observed for a
    /// positive definite `W`; reported rather than guessed). With several contacts: no mode
    /// of the enumeration satisfies the conditions to round-off.
    NoSolution,
    /// The law's impulse, velocity or energy is not representable in double precision
    /// (e.g. `whittaker` with `μ = 1e200`: `|p_t| = μ p_n` and `ΔT ≈ ½ W_tt p_t²` overflow).
    /// Reported rather than returning infinities as numbers.
    Overflow,
    /// `sequential` (several contacts) reached its bound on binary impacts with a contact still
    /// approaching ([`crate::multi::sequential::MAX_IMPACTS`]): the sequence does not settle
    /// (or settles too slowly, e.g. an inelastic collapse with `e` near 1).
    TooManyImpacts {
        /// The bound that was reached.
        limit: usize,
    },
    /// `lcp` enumerates `4^K` combinations of the contacts' modes and is limited to
    /// [`crate::multi::lcp::MAX_CONTACTS`] contacts; `lzb` integrates on fixed-size arrays
    /// and is limited to [`crate::multi::lzb::MAX_CONTACTS`].
    TooManyContacts {
        /// The problem's number of contacts.
        contacts: usize,
        /// The limit.
        limit: usize,
    },
    /// `lzb` (several contacts) reached its bound on integration steps
    /// ([`crate::multi::lzb::MAX_STEPS`]) before every contact separated: the impact does not
    /// settle (e.g. plastic contacts re-engaging without end) or needs steps too small.
    TooManySteps {
        /// The bound that was reached.
        limit: usize,
    },
    /// `lzb` (several contacts) came to rest with energy still stored in its contacts: every
    /// contact that carries a force is at rest and the forces balance (redundant contacts
    /// wedged by friction, `W` singular). The compliant contacts never release that energy:
    /// the impact does not end.
    Jammed {
        /// The energy held in the contacts.
        stored: f64,
    },
}

impl BreakdownReason {
    /// Stable id.
    pub fn id(&self) -> &'static str {
        match self {
            BreakdownReason::NegativeNormalImpulse { .. } => "negative-normal-impulse",
            BreakdownReason::NoConsistentSplit { .. } => "no-consistent-split",
            BreakdownReason::NoEtaRoot => "no-eta-root",
            BreakdownReason::NeedsBody => "needs-body",
            BreakdownReason::NoSeparation => "no-separation",
            BreakdownReason::PlanarOnly => "planar-only",
            BreakdownReason::NoSolution => "no-solution",
            BreakdownReason::Overflow => "overflow",
            BreakdownReason::TooManyImpacts { .. } => "too-many-impacts",
            BreakdownReason::TooManyContacts { .. } => "too-many-contacts",
            BreakdownReason::TooManySteps { .. } => "too-many-steps",
            BreakdownReason::Jammed { .. } => "jammed",
        }
    }
}

impl fmt::Display for BreakdownReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BreakdownReason::NegativeNormalImpulse { denominator } => write!(
                f,
                "the rule needs a negative normal impulse (denominator {denominator:.6} ≤ 0)"
            ),
            BreakdownReason::NoConsistentSplit {
                switch_impulse,
                total_impulse,
            } => write!(
                f,
                "no consistent two-phase split (switch at p_n = {switch_impulse:.6}, total {total_impulse:.6})"
            ),
            BreakdownReason::NoEtaRoot => f.write_str("Smith's η equation has no admissible root"),
            BreakdownReason::NoSeparation => {
                f.write_str("the normal velocity cannot reach the termination: no separation")
            }
            BreakdownReason::PlanarOnly => f.write_str("the law is defined for planar impacts only"),
            BreakdownReason::NeedsBody => {
                f.write_str("the law reads a body's centre velocity; contact space has none")
            }
            BreakdownReason::NoSolution => {
                f.write_str("the complementarity conditions have no solution")
            }
            BreakdownReason::Overflow => f.write_str(
                "the result is not representable in double precision (overflow)",
            ),
            BreakdownReason::TooManyImpacts { limit } => write!(
                f,
                "{limit} binary impacts and a contact still approaches: the sequence does not settle"
            ),
            BreakdownReason::TooManyContacts { contacts, limit } => write!(
                f,
                "{contacts} contacts: the law is limited to {limit}"
            ),
            BreakdownReason::TooManySteps { limit } => write!(
                f,
                "{limit} integration steps and a contact still carries an impulse: the impact does not settle"
            ),
            BreakdownReason::Jammed { stored } => write!(
                f,
                "the contacts came to rest holding energy {stored:.6} (wedged): the impact does not end"
            ),
        }
    }
}

/// A law that cannot produce a physical result for this problem. Reported as such, never
/// as numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Breakdown {
    /// Which law broke down.
    pub law: LawId,
    /// Why.
    pub reason: BreakdownReason,
}

impl fmt::Display for Breakdown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.law, self.reason)
    }
}

impl Breakdown {
    /// The breakdown with its numbers in the problem's own units.
    pub(crate) fn in_problem_units(mut self, u: Units) -> Self {
        self.reason = match self.reason {
            BreakdownReason::NegativeNormalImpulse { denominator } => {
                BreakdownReason::NegativeNormalImpulse {
                    denominator: u.inverse_inertia(denominator),
                }
            }
            BreakdownReason::NoConsistentSplit {
                switch_impulse,
                total_impulse,
            } => BreakdownReason::NoConsistentSplit {
                switch_impulse: u.impulse(switch_impulse),
                total_impulse: u.impulse(total_impulse),
            },
            other => other,
        };
        self
    }
}
