//! What every planar law returns: the impulse, velocities, work split, phases and a verdict.

use crate::law::{record_is_finite, Breakdown, Inconsistency, LawId, Verdict, WorkSplit};
use crate::math::{Units, Vec2};
use std::fmt;

/// Direction of tangential slip, `sign(v_t)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum SlipDirection {
    /// `v_t > 0`: friction acts along `−t`.
    Positive,
    /// `v_t < 0`: friction acts along `+t`.
    Negative,
    /// `v_t = 0` at the start of an algebraic law: no friction direction is defined, the law
    /// applies no friction.
    None,
}

impl SlipDirection {
    /// Direction of `v_t`.
    #[inline]
    pub fn of(vt: f64) -> Self {
        if vt > 0.0 {
            Self::Positive
        } else if vt < 0.0 {
            Self::Negative
        } else {
            Self::None
        }
    }
    /// `+1`, `−1` or `0`.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            Self::Positive => 1.0,
            Self::Negative => -1.0,
            Self::None => 0.0,
        }
    }
}

/// A regime of the contact during the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum PhaseKind {
    /// Slip with Coulomb friction `dp_t = −μ ŝ dp_n`.
    Slip(SlipDirection),
    /// Stick: `v_t = 0` held by a friction ratio `|dp_t/dp_n| ≤ μ`.
    Stick,
}

impl PhaseKind {
    /// Short label: `slip+`, `slip-`, `no-slip` or `stick`.
    pub fn label(self) -> &'static str {
        match self {
            PhaseKind::Slip(SlipDirection::Positive) => "slip+",
            PhaseKind::Slip(SlipDirection::Negative) => "slip-",
            PhaseKind::Slip(SlipDirection::None) => "no-slip",
            PhaseKind::Stick => "stick",
        }
    }
}

impl fmt::Display for PhaseKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.label())
    }
}

/// One phase of the impact and the normal impulse `p_n` at which it ends.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Phase {
    /// The regime.
    pub kind: PhaseKind,
    /// Normal impulse at the end of the phase.
    pub ends_at: f64,
}

/// The phase sequence of one impact (at most [`Phases::CAPACITY`] phases; no allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phases {
    items: [Phase; Phases::CAPACITY],
    len: usize,
}

impl Phases {
    /// The most phases a planar law produces (slip, then stick or reversed slip).
    pub const CAPACITY: usize = 2;

    /// No phases.
    pub const fn new() -> Self {
        Self {
            items: [Phase {
                kind: PhaseKind::Stick,
                ends_at: 0.0,
            }; Self::CAPACITY],
            len: 0,
        }
    }

    /// Append a phase; if it has the same kind as the last one, extend that one instead.
    ///
    /// # Panics
    /// Never for the planar laws, which produce at most [`Phases::CAPACITY`] phases; a
    /// programming error otherwise.
    pub fn push(&mut self, kind: PhaseKind, ends_at: f64) {
        if self.len > 0 && self.items[self.len - 1].kind == kind {
            self.items[self.len - 1].ends_at = ends_at;
            return;
        }
        assert!(self.len < Self::CAPACITY, "too many phases");
        self.items[self.len] = Phase { kind, ends_at };
        self.len += 1;
    }

    /// The phases as a slice.
    pub fn as_slice(&self) -> &[Phase] {
        &self.items[..self.len]
    }

    /// Number of phases.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no phases.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Labels joined by ` → `, e.g. `slip+ → stick`.
    pub fn summary(&self) -> String {
        let labels: Vec<&str> = self.as_slice().iter().map(|p| p.kind.label()).collect();
        labels.join(" → ")
    }
}

impl Default for Phases {
    fn default() -> Self {
        Self::new()
    }
}

/// Which velocity Smith's correction factor `η` is built from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum SmithReading {
    /// The sliding (contact-point tangential) velocity, as Smith 1991 and paper A's text.
    SlipVelocity,
    /// The centre-of-mass tangential velocity, the literal reading of paper A eq. 24.
    CentreVelocity,
}

/// Law-specific numbers worth reporting.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum LawDetail {
    /// Nothing beyond the common record.
    None,
    /// Two-phase: the normal impulse at which the friction direction was switched
    /// (`None` when the slip does not halt and the scheme reduces to Whittaker's).
    TwoPhase {
        /// `I'_y` of paper A eq. 21.
        switch_impulse: Option<f64>,
    },
    /// Smith: the correction factor and how it was chosen.
    Smith {
        /// `η` in `[−1, 1]` (signed: it carries the friction direction).
        eta: f64,
        /// Number of admissible roots of the η equation in `[−1, 1]`.
        roots: usize,
        /// The reading of eq. 24 used.
        reading: SmithReading,
    },
    /// Brach: the sticking ratio and whether it was capped to the cone.
    Brach {
        /// `μ0 = p_t/p_n` of the impulse that leaves no tangential velocity; `None` when
        /// that impulse is not compressive (`p*_n ≤ 0`: no impulse within any cone stops the
        /// slip, and the friction is capped along `p*_t`).
        ratio: Option<f64>,
        /// Whether `|μ0| > μ` (or no `μ0`) so that `μ sign(μ0)` was used.
        capped: bool,
    },
    /// The engine rule `lcp`: the friction ratio of the solution and how many of the three
    /// enumerated candidates (stick, slip+, slip−) satisfy the complementarity conditions.
    Lcp {
        /// `p_t / p_n`.
        ratio: f64,
        /// `1`, or `2` on the stick/slip boundary (the same impulse); `0` only when
        /// round-off leaves every candidate a hair outside its test (the nearest is used).
        consistent_candidates: usize,
    },
    /// Darboux–Keller integration: the normal impulse at which slip halted, if it did.
    DarbouxKeller {
        /// `p_s`, the end of the initial slip.
        slip_halt: Option<f64>,
    },
}

/// The result of one impact law on one [`ContactProblem`](super::ContactProblem).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Outcome {
    /// Which law produced it.
    pub law: LawId,
    /// Impulse on body A, `(p_t, p_n)`.
    pub impulse: Vec2,
    /// Contact velocity after, `v⁺ = v⁻ + W p`.
    pub velocity_after: Vec2,
    /// Normal impulse at the end of compression (`v_n = 0`), if reached on the law's path.
    pub compression_impulse: Option<f64>,
    /// Work split along the law's impulse path.
    pub work: WorkSplit,
    /// `ΔT = v⁻·p + ½ pᵀ W p` (exact for any impulse; equals `work.total()`).
    pub energy_change: f64,
    /// Phase sequence.
    pub phases: Phases,
    /// Headline verdict: energy gained takes precedence over an inconsistency.
    pub verdict: Verdict,
    /// The law's contradicted assumption, if any (reported even when energy is gained).
    pub inconsistency: Option<Inconsistency>,
    /// Law-specific detail.
    pub detail: LawDetail,
}

impl Outcome {
    /// Whether every number of the outcome is finite.
    pub fn is_finite(&self) -> bool {
        record_is_finite(
            self.impulse.iter().chain(self.velocity_after.iter()),
            &self.work,
            self.energy_change,
            self.compression_impulse,
        )
    }
}

impl Outcome {
    /// The outcome of the problem in [`Units`] expressed in the problem's own units.
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
        self.phases = self.phases.in_problem_units(u);
        self.inconsistency = self.inconsistency.map(|i| match i {
            Inconsistency::SlipReversed { slip_after } => Inconsistency::SlipReversed {
                slip_after: u.velocity(slip_after),
            },
            Inconsistency::ReversalDidNotHappen { slip_after } => {
                Inconsistency::ReversalDidNotHappen {
                    slip_after: u.velocity(slip_after),
                }
            }
            Inconsistency::StillApproaching { normal_velocity } => {
                Inconsistency::StillApproaching {
                    normal_velocity: u.velocity(normal_velocity),
                }
            }
            other => other,
        });
        self.detail = match self.detail {
            LawDetail::TwoPhase { switch_impulse } => LawDetail::TwoPhase {
                switch_impulse: switch_impulse.map(|x| u.impulse(x)),
            },
            LawDetail::DarbouxKeller { slip_halt } => LawDetail::DarbouxKeller {
                slip_halt: slip_halt.map(|x| u.impulse(x)),
            },
            other => other,
        };
        self
    }
}

impl OutcomeBrief {
    /// The brief in the problem's own units (as [`Outcome::in_problem_units`]).
    pub(crate) fn in_problem_units(mut self, u: Units) -> Self {
        self.energy_change = u.work(self.energy_change);
        self.phases = self.phases.in_problem_units(u);
        self
    }
}

impl Phases {
    /// The phases with their end impulses in the problem's own units.
    pub(crate) fn in_problem_units(mut self, u: Units) -> Self {
        for p in &mut self.items[..self.len] {
            p.ends_at = u.impulse(p.ends_at);
        }
        self
    }
}

/// The part of an [`Outcome`] a reduction over many impacts reads (e.g.
/// [`Tally`](crate::analysis::Tally)): the verdict, the phase sequence and `ΔT`.
///
/// [`ImpactLaw::resolve_brief`](crate::law::ImpactLaw::resolve_brief) returns it; it always
/// equals [`OutcomeBrief::of`] the full outcome, field for field.
///
/// ```
/// use impax::planar::{laws::{Energetic, ImpactLaw}, ContactProblem, OutcomeBrief};
/// let a = 30f64.to_radians();
/// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
/// let brief = Energetic.resolve_brief(&p).unwrap();
/// assert_eq!(brief, OutcomeBrief::of(&Energetic.resolve(&p).unwrap()));
/// assert_eq!(brief.phases.len(), 2); // slip, then stick
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OutcomeBrief {
    /// Headline verdict (as [`Outcome::verdict`]).
    pub verdict: Verdict,
    /// Phase sequence (as [`Outcome::phases`]).
    pub phases: Phases,
    /// `ΔT` (as [`Outcome::energy_change`]).
    pub energy_change: f64,
}

impl OutcomeBrief {
    /// The brief of a full outcome.
    #[inline]
    pub fn of(o: &Outcome) -> Self {
        Self {
            verdict: o.verdict,
            phases: o.phases,
            energy_change: o.energy_change,
        }
    }
}

impl Outcome {
    /// The vertices of the law's impulse path in Routh's `(p_t, p_n)` plane, from the origin
    /// to [`Outcome::impulse`] (Routh 1905; Stronge 2000, ch. 5).
    ///
    /// Every planar law moves the impulse along straight pieces, one per phase: each phase
    /// but the last is followed along its friction ratio `dp_t/dp_n` (`−μ ŝ` in slip,
    /// `−W_tn/W_tt` in stick, `0` without slip) up to its end; the last piece runs straight to
    /// the final impulse (which also covers the algebraic laws' single line, whatever its
    /// ratio, e.g. Smith's `−μ η`). `problem` must be the problem the outcome was resolved
    /// from.
    ///
    /// ```
    /// use impax::{LawId, planar::ContactProblem};
    /// let a = 30f64.to_radians();
    /// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
    /// let o = LawId::Energetic.resolve(&p).unwrap();
    /// let path = o.impulse_path(&p);
    /// let path_halt = |v: &[impax::math::Vec2]| v[1].y;
    /// // Slip halts at p_n = v_t⁻/(μ W_tt) = 0.3571, then stick to the end: three vertices.
    /// assert!((path_halt(&path) - 0.5 / 1.4).abs() < 1e-12);
    /// assert_eq!(path.len(), 3);
    /// assert_eq!(path[0].x, 0.0);
    /// assert!((path[1].x + 0.4 * path[1].y).abs() < 1e-15); // slip: p_t = −μ p_n
    /// assert_eq!(path[2], o.impulse);
    /// ```
    pub fn impulse_path(&self, problem: &super::ContactProblem) -> Vec<Vec2> {
        let mut points = Vec::with_capacity(Phases::CAPACITY + 1);
        points.push(Vec2::new(0.0, 0.0));
        let phases = self.phases.as_slice();
        let mut at = Vec2::new(0.0, 0.0);
        for phase in phases.iter().take(phases.len().saturating_sub(1)) {
            let ratio = match phase.kind {
                PhaseKind::Slip(dir) => -problem.friction() * dir.sign(),
                PhaseKind::Stick => -problem.wtn() / problem.wtt(),
            };
            let dp = phase.ends_at - at.y;
            at = Vec2::new(at.x + ratio * dp, phase.ends_at);
            points.push(at);
        }
        points.push(self.impulse);
        points
    }
}

/// What a law returns: an outcome or a breakdown.
pub type Resolution = Result<Outcome, Breakdown>;

impl From<&Outcome> for OutcomeBrief {
    /// [`OutcomeBrief::of`].
    fn from(o: &Outcome) -> Self {
        OutcomeBrief::of(o)
    }
}

/// What [`ImpactLaw::resolve_brief`](crate::law::ImpactLaw::resolve_brief) returns: the
/// brief of an outcome, or the breakdown.
pub type BriefResolution = Result<OutcomeBrief, Breakdown>;
