//! What every planar law returns: the impulse, velocities, work split, phases and a verdict.

use super::problem::Units;
use crate::law::LawId;
use crate::math::Vec2;
use std::fmt;

/// Direction of tangential slip, `sign(v_t)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
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

/// The energy audit of an impact: `ΔT = W_c + W_r + W_t` (theory §1).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WorkSplit {
    /// Normal work during compression `W_c = ∫₀^{p_c} v_n dp_n ≤ 0`.
    pub compression: f64,
    /// Normal work during restitution `W_r = ∫_{p_c}^{p_f} v_n dp_n`.
    pub restitution: f64,
    /// Friction work `W_t = ∫ v_t dp_t`.
    pub friction: f64,
}

impl WorkSplit {
    /// Total normal work `W_n = W_c + W_r`.
    pub fn normal(&self) -> f64 {
        self.compression + self.restitution
    }
    /// `W_n + W_t`, which equals `ΔT`.
    pub fn total(&self) -> f64 {
        self.normal() + self.friction
    }
}

/// The overall judgement of a law's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
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
    /// The velocity-level LCP (`lcp`, spatial) has several solutions: the rule alone does not
    /// say which one an engine returns (it depends on the engine's iteration). The one of
    /// least kinetic energy after is reported.
    MultipleSolutions {
        /// Number of distinct solutions (2 or 3).
        count: usize,
    },
    /// The impact ended with the bodies still approaching (`v_n⁺ < 0` beyond round-off): no
    /// impact law may end there. The Darboux–Keller laws are built never to (Poisson's
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

/// Which velocity Smith's correction factor `η` is built from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SmithReading {
    /// The sliding (contact-point tangential) velocity, as Smith 1991 and paper A's text.
    SlipVelocity,
    /// The centre-of-mass tangential velocity, the literal reading of paper A eq. 24.
    CentreVelocity,
}

/// Law-specific numbers worth reporting.
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// Whether the numbers of an outcome record (impulse and velocity components, the work
/// split, `ΔT`, the compression impulse) are all finite; shared by the planar and spatial
/// records.
pub(crate) fn record_is_finite<'a>(
    components: impl IntoIterator<Item = &'a f64>,
    work: &WorkSplit,
    energy_change: f64,
    compression_impulse: Option<f64>,
) -> bool {
    components.into_iter().all(|x| x.is_finite())
        && [
            work.compression,
            work.restitution,
            work.friction,
            energy_change,
        ]
        .iter()
        .all(|x| x.is_finite())
        && compression_impulse.is_none_or(f64::is_finite)
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

/// Why a law produced no admissible result.
#[derive(Debug, Clone, Copy, PartialEq)]
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
    /// positive definite `W`; reported rather than guessed).
    NoSolution,
    /// The law's impulse, velocity or energy is not representable in double precision
    /// (e.g. `whittaker` with `μ = 1e200`: `|p_t| = μ p_n` and `ΔT ≈ ½ W_tt p_t²` overflow).
    /// Reported rather than returning infinities as numbers.
    Overflow,
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
        }
    }
}

/// A law that cannot produce a physical result for this problem. Reported as such, never
/// as numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// What a law returns: an outcome or a breakdown.
pub type Resolution = Result<Outcome, Breakdown>;

/// What [`ImpactLaw::resolve_brief`](crate::law::ImpactLaw::resolve_brief) returns: the
/// brief of an outcome, or the breakdown.
pub type BriefResolution = Result<OutcomeBrief, Breakdown>;
