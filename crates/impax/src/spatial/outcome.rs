//! What every spatial law returns.

use crate::law::LawId;
use crate::law::{Inconsistency, Verdict, WorkSplit};
use crate::math::Units;
use crate::math::Vec3;
use std::fmt;

/// A regime of the contact during a spatial impact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum PhaseKind {
    /// Slip whose direction turns from angle `from` to angle `to` (radians in the tangent
    /// plane, `atan2(v_t2, v_t1)`); equal angles when it does not swirl.
    Slip {
        /// Slip direction at the start of the phase.
        from: f64,
        /// Slip direction at the end of the phase.
        to: f64,
    },
    /// Stick: `v_t = 0`, friction ratio `|λ| ≤ μ`.
    Stick,
    /// Slip resumed at once after the halt along the centrifugal invariant ray at `angle`.
    Resumed {
        /// Angle of the ray.
        angle: f64,
    },
    /// No slip at the start and no friction (algebraic laws with `v_t⁻ = 0`).
    NoSlip,
}

impl PhaseKind {
    /// Short label: `slip`, `stick`, `resumed-slip`, `no-slip`.
    pub fn label(&self) -> &'static str {
        match self {
            PhaseKind::Slip { .. } => "slip",
            PhaseKind::Stick => "stick",
            PhaseKind::Resumed { .. } => "resumed-slip",
            PhaseKind::NoSlip => "no-slip",
        }
    }
}

impl fmt::Display for PhaseKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PhaseKind::Slip { from, to } => {
                write!(f, "slip({:.1}°→{:.1}°)", from.to_degrees(), to.to_degrees())
            }
            PhaseKind::Resumed { angle } => write!(f, "resumed-slip({:.1}°)", angle.to_degrees()),
            other => f.write_str(other.label()),
        }
    }
}

/// One phase and the normal impulse at which it ends.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Phase {
    /// The regime.
    pub kind: PhaseKind,
    /// Normal impulse at the end of the phase.
    pub ends_at: f64,
}

/// The phases of a spatial impact (at most two: slip, then stick or resumed slip).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phases {
    items: [Phase; 2],
    len: usize,
}

impl Phases {
    /// Multiply every phase's end impulse by `k` (a change of units).
    pub(crate) fn scale_impulse(&mut self, k: f64) {
        for p in &mut self.items[..self.len] {
            p.ends_at *= k;
        }
    }

    /// No phases.
    pub const fn new() -> Self {
        Self {
            items: [Phase {
                kind: PhaseKind::Stick,
                ends_at: 0.0,
            }; 2],
            len: 0,
        }
    }
    /// Append a phase (silently ignored beyond two, which no law produces).
    pub fn push(&mut self, kind: PhaseKind, ends_at: f64) {
        if self.len < 2 {
            self.items[self.len] = Phase { kind, ends_at };
            self.len += 1;
        }
    }
    /// The phases.
    pub fn as_slice(&self) -> &[Phase] {
        &self.items[..self.len]
    }
    /// Labels joined by ` → `.
    pub fn summary(&self) -> String {
        let v: Vec<String> = self.as_slice().iter().map(|p| p.kind.to_string()).collect();
        v.join(" → ")
    }
}

impl Default for Phases {
    fn default() -> Self {
        Self::new()
    }
}

/// Law-specific numbers of a spatial outcome.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum LawDetail {
    /// Nothing more.
    None,
    /// Brach: the sticking ratio's magnitude and whether it was capped.
    Brach {
        /// `|μ0| = |p*_t| / p*_n`; `None` when the impulse that stops the slip is not
        /// compressive (`p*_n ≤ 0`).
        ratio: Option<f64>,
        /// Whether `|μ0| > μ`.
        capped: bool,
    },
    /// The engine rule `lcp`: how many solutions the complementarity conditions have.
    Lcp {
        /// Number of distinct solutions (1, or 2–3 for some anisotropic coupled `W`).
        solutions: usize,
    },
    /// Darboux–Keller integration.
    DarbouxKeller {
        /// Normal impulse at which the initial slip halted, if it did before the end.
        slip_halt: Option<f64>,
        /// Normal impulse at which a second compression began (`v_n` fell back to zero
        /// after the end of the first compression: jamb), if it did.
        second_compression: Option<f64>,
        /// Accepted integration steps.
        steps: u32,
    },
}

/// The result of one law on one [`ContactProblem`](super::ContactProblem).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Outcome {
    /// Which law.
    pub law: LawId,
    /// Impulse on body A, `(p_t1, p_t2, p_n)`.
    pub impulse: Vec3,
    /// Contact velocity after.
    pub velocity_after: Vec3,
    /// Normal impulse at the end of (the first) compression, if reached.
    pub compression_impulse: Option<f64>,
    /// Work split (compression, restitution, friction).
    pub work: WorkSplit,
    /// `ΔT`.
    pub energy_change: f64,
    /// Phases.
    pub phases: Phases,
    /// Headline verdict.
    pub verdict: Verdict,
    /// A contradicted assumption, if any.
    pub inconsistency: Option<Inconsistency>,
    /// Law-specific detail.
    pub detail: LawDetail,
}

impl Outcome {
    /// The outcome of the problem in `u` ([`super::ContactProblem`]'s canonical units)
    /// in the problem's own units (every factor a power of two: exact).
    pub(crate) fn in_problem_units(mut self, u: Units) -> Self {
        self.impulse = self.impulse.map(|x| u.impulse(x));
        self.velocity_after = self.velocity_after.map(|x| u.velocity(x));
        self.compression_impulse = self.compression_impulse.map(|x| u.impulse(x));
        self.work = WorkSplit {
            compression: u.work(self.work.compression),
            restitution: u.work(self.work.restitution),
            friction: u.work(self.work.friction),
        };
        self.energy_change = u.work(self.energy_change);
        self.phases.scale_impulse(u.impulse(1.0));
        self.inconsistency = self.inconsistency.map(|i| match i {
            Inconsistency::SlipReversed { slip_after } => Inconsistency::SlipReversed {
                slip_after: u.velocity(slip_after),
            },
            Inconsistency::StillApproaching { normal_velocity } => {
                Inconsistency::StillApproaching {
                    normal_velocity: u.velocity(normal_velocity),
                }
            }
            other => other,
        });
        if let LawDetail::DarbouxKeller {
            slip_halt,
            second_compression,
            ..
        } = &mut self.detail
        {
            *slip_halt = slip_halt.map(|x| u.impulse(x));
            *second_compression = second_compression.map(|x| u.impulse(x));
        }
        self
    }

    /// Whether every number of the outcome is finite.
    pub fn is_finite(&self) -> bool {
        crate::law::record_is_finite(
            self.impulse.iter().chain(self.velocity_after.iter()),
            &self.work,
            self.energy_change,
            self.compression_impulse,
        )
    }
}

/// What a spatial law returns.
pub type Resolution = Result<Outcome, crate::law::Breakdown>;

/// The brief of a spatial outcome is the outcome itself (it is `Copy`): what
/// [`crate::law::ImpactLaw::resolve_brief`] gives for a spatial law.
impl From<&Outcome> for Outcome {
    #[inline]
    fn from(o: &Outcome) -> Self {
        *o
    }
}
