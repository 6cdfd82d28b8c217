//! The batch API: many planar problems resolved by one law, without allocation.
//!
//! Input is structure-of-arrays ([`ProblemColumns`]: one slice per entry of `(W, v⁻, μ, e)`)
//! or a slice of already validated [`ContactProblem`]s; output is a caller-owned slice of
//! compact [`ImpactSummary`] records, one per problem, in order. The law is chosen once per
//! batch, so the inner loop calls one law's closed form directly (no dispatch per impact).
//!
//! ```
//! use impax::analysis::{resolve_columns, ImpactSummary, ProblemColumns, Sequence, Status};
//! use impax::planar::Verdict;
//! use impax::LawId;
//! let a = 30f64.to_radians();
//! // The seed's sphere at γ = 0 and γ = 0.5 (paper A eq. 6: v_t⁻ = sin α + γ).
//! let (wtt, wtn, wnn) = ([3.5; 2], [0.0; 2], [1.0; 2]);
//! let (vt, vn) = ([a.sin(), a.sin() + 0.5], [-a.cos(); 2]);
//! let (mu, e) = ([0.4; 2], [0.7; 2]);
//! let cols = ProblemColumns::new(&wtt, &wtn, &wnn, &vt, &vn, &mu, &e).unwrap();
//! let mut out = [ImpactSummary::INVALID; 2];
//! resolve_columns(LawId::Whittaker, &cols, &mut out).unwrap();
//! assert_eq!(out[0].status, Status::Resolved(Verdict::EnergyGained)); // Kane's paradox
//! // Past γ* ≈ 0.206 no energy is gained, but the slip still reverses (eq. 11).
//! assert_eq!(out[1].status, Status::Resolved(Verdict::InconsistentAssumption));
//! resolve_columns(LawId::Energetic, &cols, &mut out).unwrap();
//! assert_eq!(out[0].sequence, Sequence::SlipStick);
//! ```

use crate::error::{Error, Result};
use crate::law::{ImpactLaw, LawId};
use crate::math::Vec2;
use crate::planar::laws::{Brach, Energetic, Lcp, Newton, Poisson, Smith, TwoPhase, Whittaker};
use crate::planar::{
    BriefResolution, ContactProblem, Outcome, PhaseKind, Phases, Resolution, Verdict, WorkSplit,
};

/// What became of one problem of a batch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Status {
    /// The law produced an outcome with this verdict.
    Resolved(Verdict),
    /// The law broke down (e.g. Whittaker's negative normal impulse): no numbers.
    Breakdown,
    /// The problem itself is invalid (e.g. `W` not positive definite, `v_n ≥ 0`).
    Invalid,
}

impl Status {
    /// Stable id: the verdict's id (`consistent`, `energy-gained`,
    /// `inconsistent-assumption`), `breakdown` or `invalid`.
    pub fn id(self) -> &'static str {
        match self {
            Status::Resolved(v) => v.id(),
            Status::Breakdown => "breakdown",
            Status::Invalid => "invalid",
        }
    }

    /// Whether the record carries numbers.
    pub fn is_resolved(self) -> bool {
        matches!(self, Status::Resolved(_))
    }
}

/// The phase sequence of an impact, classified.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sequence {
    /// Slip in one direction throughout.
    Slip,
    /// Slip that halts, then stick (the contact leaves rolling).
    SlipStick,
    /// Slip that halts and resumes in the opposite direction.
    SlipReverse,
    /// Stick throughout (no initial slip and the cone holds it; or Brach's sticking impulse).
    Stick,
    /// No slip and no friction (an algebraic law without an initial slip direction).
    NoSlip,
    /// No phases: a breakdown or an invalid problem.
    None,
}

impl Sequence {
    /// Every class, in presentation order.
    pub const ALL: [Sequence; 6] = [
        Sequence::Slip,
        Sequence::SlipStick,
        Sequence::SlipReverse,
        Sequence::Stick,
        Sequence::NoSlip,
        Sequence::None,
    ];

    /// Stable id: `slip`, `slip-stick`, `slip-reverse`, `stick`, `no-slip`, `none`.
    pub fn id(self) -> &'static str {
        match self {
            Sequence::Slip => "slip",
            Sequence::SlipStick => "slip-stick",
            Sequence::SlipReverse => "slip-reverse",
            Sequence::Stick => "stick",
            Sequence::NoSlip => "no-slip",
            Sequence::None => "none",
        }
    }

    /// Classify a phase sequence. Two slip phases are a reversal (the planar laws never
    /// produce two slips in one direction: [`Phases::push`] merges them).
    pub fn of(phases: &Phases) -> Self {
        match phases.as_slice() {
            [] => Sequence::None,
            [p] => match p.kind {
                PhaseKind::Stick => Sequence::Stick,
                PhaseKind::Slip(crate::planar::SlipDirection::None) => Sequence::NoSlip,
                PhaseKind::Slip(_) => Sequence::Slip,
            },
            [_, second, ..] => match second.kind {
                PhaseKind::Stick => Sequence::SlipStick,
                PhaseKind::Slip(_) => Sequence::SlipReverse,
            },
        }
    }
}

/// The compact record of one impact in a batch (88 bytes; the full [`Outcome`] is 168).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSummary {
    /// Verdict, breakdown or invalid problem.
    pub status: Status,
    /// Phase sequence.
    pub sequence: Sequence,
    /// Impulse on body A `(p_t, p_n)` (NaN unless resolved).
    pub impulse: Vec2,
    /// Contact velocity after `(v_t⁺, v_n⁺)` (NaN unless resolved).
    pub velocity_after: Vec2,
    /// `ΔT` (NaN unless resolved).
    pub energy_change: f64,
    /// Normal work in compression and restitution, friction work (NaN unless resolved).
    pub work: WorkSplit,
    /// Normal impulse at the end of compression; NaN if not reached (or not resolved).
    pub compression_impulse: f64,
}

impl ImpactSummary {
    /// The record of an invalid problem: every number NaN.
    pub const INVALID: ImpactSummary = ImpactSummary {
        status: Status::Invalid,
        sequence: Sequence::None,
        impulse: Vec2::new(f64::NAN, f64::NAN),
        velocity_after: Vec2::new(f64::NAN, f64::NAN),
        energy_change: f64::NAN,
        work: WorkSplit {
            compression: f64::NAN,
            restitution: f64::NAN,
            friction: f64::NAN,
        },
        compression_impulse: f64::NAN,
    };

    /// The record of a breakdown: every number NaN.
    pub const BREAKDOWN: ImpactSummary = ImpactSummary {
        status: Status::Breakdown,
        ..Self::INVALID
    };

    /// Summarise an outcome.
    #[inline]
    pub fn of(o: &Outcome) -> Self {
        Self {
            status: Status::Resolved(o.verdict),
            sequence: Sequence::of(&o.phases),
            impulse: o.impulse,
            velocity_after: o.velocity_after,
            energy_change: o.energy_change,
            work: o.work,
            compression_impulse: o.compression_impulse.unwrap_or(f64::NAN),
        }
    }

    /// Summarise a resolution (an outcome or a breakdown).
    #[inline]
    pub fn of_resolution(r: &Resolution) -> Self {
        match r {
            Ok(o) => Self::of(o),
            Err(_) => Self::BREAKDOWN,
        }
    }
}

/// A batch of planar problems as structure-of-arrays: entry `i` is
/// `W = [[wtt[i], wtn[i]], [wtn[i], wnn[i]]]`, `v⁻ = (vt[i], vn[i])`, `μ = friction[i]`,
/// `e = restitution[i]`.
#[derive(Debug, Clone, Copy)]
pub struct ProblemColumns<'a> {
    /// `W_tt`.
    pub wtt: &'a [f64],
    /// `W_tn`.
    pub wtn: &'a [f64],
    /// `W_nn`.
    pub wnn: &'a [f64],
    /// `v_t⁻`.
    pub vt: &'a [f64],
    /// `v_n⁻`.
    pub vn: &'a [f64],
    /// `μ`.
    pub friction: &'a [f64],
    /// `e`.
    pub restitution: &'a [f64],
}

impl<'a> ProblemColumns<'a> {
    /// Columns of equal length (an error names the first column that differs).
    pub fn new(
        wtt: &'a [f64],
        wtn: &'a [f64],
        wnn: &'a [f64],
        vt: &'a [f64],
        vn: &'a [f64],
        friction: &'a [f64],
        restitution: &'a [f64],
    ) -> Result<Self> {
        let n = wtt.len();
        for (name, c) in [
            ("wtn", wtn),
            ("wnn", wnn),
            ("vt", vt),
            ("vn", vn),
            ("friction", friction),
            ("restitution", restitution),
        ] {
            if c.len() != n {
                return Err(Error::Invalid {
                    field: name.into(),
                    reason: format!("column has {} entries, wtt has {n}", c.len()),
                });
            }
        }
        Ok(Self {
            wtt,
            wtn,
            wnn,
            vt,
            vn,
            friction,
            restitution,
        })
    }

    /// Number of problems.
    pub fn len(&self) -> usize {
        self.wtt.len()
    }

    /// Whether the batch is empty.
    pub fn is_empty(&self) -> bool {
        self.wtt.is_empty()
    }

    /// Problem `i`, validated ([`ContactProblem::from_entries`]).
    #[inline]
    pub fn problem(&self, i: usize) -> Result<ContactProblem> {
        ContactProblem::from_entries(
            self.wtt[i],
            self.wtn[i],
            self.wnn[i],
            self.vt[i],
            self.vn[i],
            self.friction[i],
            self.restitution[i],
        )
    }
}

fn check_len(n: usize, out: usize) -> Result<()> {
    if n == out {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: "out".into(),
            reason: format!("output has {out} records for {n} problems"),
        })
    }
}

/// Run `f(law)` with the law as a concrete type, so that the loop inside is monomorphised.
macro_rules! with_law {
    ($law:expr, |$l:ident| $body:expr) => {
        match $law {
            LawId::Whittaker => {
                let $l = Whittaker;
                $body
            }
            LawId::TwoPhase => {
                let $l = TwoPhase;
                $body
            }
            LawId::Smith => {
                let $l = Smith::SLIP;
                $body
            }
            LawId::Brach => {
                let $l = Brach;
                $body
            }
            LawId::Newton => {
                let $l = Newton;
                $body
            }
            LawId::Poisson => {
                let $l = Poisson;
                $body
            }
            LawId::Energetic => {
                let $l = Energetic;
                $body
            }
            LawId::Lcp => {
                let $l = Lcp;
                $body
            }
            LawId::SmithCentre => {
                let $l = NeedsBody;
                $body
            }
            LawId::Sequential => {
                let $l = crate::multi::sequential::OneContact;
                $body
            }
            LawId::Lzb => {
                let $l = crate::multi::lzb::OneContact;
                $body
            }
        }
    };
}

/// `smith-centre` in contact space: always a breakdown (it needs a body).
struct NeedsBody;
impl ImpactLaw for NeedsBody {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::SmithCentre
    }
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        LawId::SmithCentre.resolve(problem)
    }
}

/// Resolve validated problems with one law: `out[i]` summarises `law` on `problems[i]`.
///
/// No allocation. Errors only if the lengths differ. `smith-centre` needs a body and gives
/// [`Status::Breakdown`] here (use [`crate::planar::bodies::BodyImpact::resolve`]).
pub fn resolve_problems(
    law: LawId,
    problems: &[ContactProblem],
    out: &mut [ImpactSummary],
) -> Result<()> {
    check_len(problems.len(), out.len())?;
    with_law!(law, |l| {
        for (p, o) in problems.iter().zip(out.iter_mut()) {
            *o = summarize(&l, p);
        }
    });
    Ok(())
}

/// Resolve validated problems with one law and hand each resolution to `f(i, &resolution)`
/// in order: the batch without the compact record, for reductions that read the full
/// [`Outcome`] (e.g. [`Tally::add_resolution`](super::Tally::add_resolution)). No allocation;
/// the law is dispatched once.
///
/// ```
/// use impax::analysis::{for_each_resolution, Tally};
/// use impax::planar::ContactProblem;
/// use impax::LawId;
/// let a = 30f64.to_radians();
/// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
/// let mut t = Tally::new();
/// for_each_resolution(LawId::Whittaker, &[p, p], |_, r| t.add_resolution(r, 0.5));
/// assert_eq!(t.energy_gained, 2);
/// ```
pub fn for_each_resolution(
    law: LawId,
    problems: &[ContactProblem],
    mut f: impl FnMut(usize, &Resolution),
) {
    with_law!(law, |l| {
        for (i, p) in problems.iter().enumerate() {
            f(i, &l.resolve(p));
        }
    });
}

/// As [`for_each_resolution`] with the brief of each resolution
/// ([`ImpactLaw::resolve_brief`]: verdict, phases and `ΔT`), for reductions that read no
/// more, e.g. [`Tally::add_brief`](super::Tally::add_brief). The Darboux–Keller laws skip the
/// rest of the record; the counts are those of the full resolutions.
///
/// ```
/// use impax::analysis::{for_each_brief, for_each_resolution, Tally};
/// use impax::planar::ContactProblem;
/// use impax::LawId;
/// let a = 30f64.to_radians();
/// let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
/// let (mut brief, mut full) = (Tally::new(), Tally::new());
/// for_each_brief(LawId::Energetic, &[p, p], |_, r| brief.add_brief(r, 0.5));
/// for_each_resolution(LawId::Energetic, &[p, p], |_, r| full.add_resolution(r, 0.5));
/// assert_eq!(brief, full);
/// ```
pub fn for_each_brief(
    law: LawId,
    problems: &[ContactProblem],
    mut f: impl FnMut(usize, &BriefResolution),
) {
    with_law!(law, |l| {
        for (i, p) in problems.iter().enumerate() {
            f(i, &l.resolve_brief(p));
        }
    });
}

/// Resolve columns with one law: problem `i` is validated, then resolved; an invalid
/// problem gives [`ImpactSummary::INVALID`].
///
/// No allocation. Errors only if the output length differs from the batch.
pub fn resolve_columns(
    law: LawId,
    problems: &ProblemColumns<'_>,
    out: &mut [ImpactSummary],
) -> Result<()> {
    check_len(problems.len(), out.len())?;
    with_law!(law, |l| {
        for (i, o) in out.iter_mut().enumerate() {
            *o = match problems.problem(i) {
                Ok(p) => summarize(&l, &p),
                Err(_) => ImpactSummary::INVALID,
            };
        }
    });
    Ok(())
}

#[inline(always)]
fn summarize<L: ImpactLaw<Problem = ContactProblem, Outcome = crate::planar::Outcome>>(
    law: &L,
    p: &ContactProblem,
) -> ImpactSummary {
    match law.resolve(p) {
        Ok(o) => ImpactSummary::of(&o),
        Err(_) => ImpactSummary::BREAKDOWN,
    }
}
