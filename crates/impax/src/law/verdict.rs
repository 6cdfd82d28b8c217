//! The judgement of a law's result: its verdict and the assumption it contradicts.

use std::fmt;

/// The overall judgement of a law's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum Verdict {
    /// No energy gained and the law's assumptions hold.
    Consistent,
    /// The kinetic energy rose: Kane's paradox.
    EnergyGained,
    /// The law's own assumption is contradicted by its result (see [`Inconsistency`]).
    InconsistentAssumption,
}

impl Verdict {
    /// Stable id used in JSON: `consistent`, `energy-gained`, `inconsistent-assumption`.
    pub fn id(self) -> &'static str {
        match self {
            Verdict::Consistent => "consistent",
            Verdict::EnergyGained => "energy-gained",
            Verdict::InconsistentAssumption => "inconsistent-assumption",
        }
    }
}

/// An assumption of a law that its own result contradicts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum Inconsistency {
    /// Friction was held against the initial slip but the slip reversed during the impact
    /// (Whittaker, Smith at `η = ±1`): friction did positive work in the end part.
    SlipReversed {
        /// Tangential contact velocity after the impact.
        slip_after: f64,
    },
    /// The two-phase scheme assumed the slip reverses after it halts, but the final slip
    /// has the initial direction (paper A §3: `v_Px⁺ > 0`).
    ReversalDidNotHappen {
        /// Tangential contact velocity after the impact.
        slip_after: f64,
    },
    /// The velocity-level LCP (`lcp`, spatial, or planar with several contacts) has several
    /// solutions: the rule alone does not say which one an engine returns (it depends on the
    /// engine's iteration). The one of least kinetic energy after is reported.
    MultipleSolutions {
        /// Number of distinct solutions (2 or 3 for one spatial contact; any number ≥ 2 with
        /// several contacts).
        count: usize,
    },
    /// The impact ended with the bodies still approaching (`v_n⁺ < 0` beyond round-off): no
    /// impact law may end there. With several contacts: the most negative `v_n⁺`. The Darboux–Keller laws are built never to (Poisson's
    /// after a jamb ends only once the restitution impulse reaches `e` times the impulse of
    /// every compression phase, with `v_n ≥ 0`); the check stays as a guard.
    StillApproaching {
        /// Normal contact velocity after the impact.
        normal_velocity: f64,
    },
}

impl Inconsistency {
    /// Stable id: `slip-reversed`, `reversal-did-not-happen`, `multiple-solutions` or
    /// `still-approaching`.
    pub fn id(&self) -> &'static str {
        match self {
            Inconsistency::SlipReversed { .. } => "slip-reversed",
            Inconsistency::ReversalDidNotHappen { .. } => "reversal-did-not-happen",
            Inconsistency::MultipleSolutions { .. } => "multiple-solutions",
            Inconsistency::StillApproaching { .. } => "still-approaching",
        }
    }
}

impl fmt::Display for Inconsistency {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Inconsistency::SlipReversed { slip_after } => write!(
                f,
                "friction kept against the initial slip, but the slip reversed (v_t+ = {slip_after:.6})"
            ),
            Inconsistency::ReversalDidNotHappen { slip_after } => write!(
                f,
                "assumed the slip reverses after it halts, but v_t+ = {slip_after:.6} keeps the initial direction"
            ),
            Inconsistency::MultipleSolutions { count } => write!(
                f,
                "the complementarity conditions have {count} solutions; the one of least kinetic energy after is shown"
            ),
            Inconsistency::StillApproaching { normal_velocity } => write!(
                f,
                "the impact ended with the bodies still approaching (v_n+ = {normal_velocity:.6e} < 0)"
            ),
        }
    }
}
