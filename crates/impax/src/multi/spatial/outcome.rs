//! What a spatial law returns for `K` contacts: the planar outcome's fields with 3-vectors.

use super::problem::flatten;
use super::MultiProblem;
use crate::law::energy::ENERGY_GAIN_ROUND_OFF;
use crate::law::{Breakdown, Inconsistency, LawId, Verdict, WorkSplit};
use crate::math::{Units, Vec3};
use crate::multi::outcome::Ending;
use crate::multi::{LzbPrimary, VELOCITY_ROUND_OFF};
use crate::spatial::{LawDetail, Outcome, PhaseKind};
use nalgebra::{DMatrix, DVector};
use std::fmt;

/// The regime of one contact during (a part of) a spatial impact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum ContactPhaseKind {
    /// No impulse at this contact.
    Off,
    /// A regime of the one-contact vocabulary: stick, slip (with its direction, radians in
    /// the tangent plane, `atan2(v_t2, v_t1)`), resumed slip, no slip.
    Impact(PhaseKind),
}

impl ContactPhaseKind {
    /// Stable label: `off`, `stick`, `slip`, `resumed-slip` or `no-slip`.
    pub fn label(&self) -> &'static str {
        match self {
            ContactPhaseKind::Off => "off",
            ContactPhaseKind::Impact(k) => k.label(),
        }
    }
}

impl fmt::Display for ContactPhaseKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ContactPhaseKind::Off => f.write_str("off"),
            ContactPhaseKind::Impact(k) => k.fmt(f),
        }
    }
}

/// One phase of one contact and the contact's own normal impulse at its end.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ContactPhase {
    /// The regime.
    pub kind: ContactPhaseKind,
    /// The contact's normal impulse `p_nj` at the end of the phase.
    pub ends_at: f64,
}

/// What happened at one contact.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ContactResult {
    /// The impulse on body A at this contact, `(p_t1, p_t2, p_n)`.
    pub impulse: Vec3,
    /// The contact velocity after, `(v_t1⁺, v_t2⁺, v_n⁺)`.
    pub velocity_after: Vec3,
    /// The regimes in order (`lcp`: one; `sequential`: those of every binary impact at this
    /// contact, one `off` if it had none).
    pub phases: Vec<ContactPhase>,
    /// The work done at this contact along the law's path (as for the planar
    /// [`crate::multi::ContactResult::work`]).
    pub work: WorkSplit,
}

impl ContactResult {
    /// Labels joined by ` → `, e.g. `slip(30.0°→12.4°) → stick`.
    pub fn phase_summary(&self) -> String {
        let labels: Vec<String> = self.phases.iter().map(|p| p.kind.to_string()).collect();
        labels.join(" → ")
    }

    /// Append a phase ending at `ends_at`; extend the last one if it has the same kind. A
    /// loaded phase that ends where the last one ended carries no impulse and is not recorded;
    /// an `off` phase is recorded all the same (as in the plane,
    /// [`crate::multi::ContactResult`]).
    pub(crate) fn push_phase(&mut self, kind: ContactPhaseKind, ends_at: f64) {
        match self.phases.last_mut() {
            Some(last) if last.kind == kind => last.ends_at = ends_at,
            Some(last) if last.ends_at == ends_at && kind != ContactPhaseKind::Off => {}
            _ => self.phases.push(ContactPhase { kind, ends_at }),
        }
    }

    /// A contact with nothing yet.
    pub(crate) fn empty() -> Self {
        Self {
            impulse: Vec3::zeros(),
            velocity_after: Vec3::zeros(),
            phases: Vec::new(),
            work: WorkSplit::default(),
        }
    }
}

/// One solution of the complementarity conditions of [`super::lcp`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LcpSolution {
    /// Each contact's regime: `off`, `stick`, or `slip` along its final slip direction.
    pub regimes: Vec<ContactPhaseKind>,
    /// The impulses, one per contact.
    pub impulses: Vec<Vec3>,
    /// The contact velocities after, one per contact.
    pub velocities_after: Vec<Vec3>,
    /// `ΔT = ½ Σ_j (v_j⁻ + v_j⁺)·p_j`.
    pub energy_change: f64,
}

/// One binary impact of [`super::sequential`]: a contact resolved alone by the spatial
/// `energetic` law.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BinaryImpact {
    /// The contact (from 0).
    pub contact: usize,
    /// Its velocity before this impact.
    pub velocity_before: Vec3,
    /// The one-contact outcome on the contact's own block.
    pub outcome: Outcome,
}

/// Law-specific detail.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum MultiDetail {
    /// `lcp`: every solution found, least kinetic energy after first (the first is the
    /// result).
    Lcp {
        /// The solutions.
        solutions: Vec<LcpSolution>,
    },
    /// `sequential`: the binary impacts in order.
    Sequential {
        /// The impacts.
        impacts: Vec<BinaryImpact>,
    },
    /// `lzb`: the primary contacts in turn and the number of integration steps (as for the
    /// planar [`crate::multi::MultiDetail::Lzb`]).
    Lzb {
        /// The primary contacts in turn: the first at the start of the impact, then each
        /// contact whose stored energy overtook the primary's, or the one with the most
        /// energy when the primary separated.
        primaries: Vec<LzbPrimary>,
        /// The accepted integration steps (each ending at the end of a step or at an event);
        /// 0 with one contact (the spatial `energetic` law).
        steps: usize,
    },
    /// A one-contact law on a problem with one contact: its own detail.
    OneContact {
        /// The law's detail.
        detail: LawDetail,
        /// The normal impulse at the end of compression, if reached on the law's path.
        compression_impulse: Option<f64>,
    },
}

/// The result of a law on a spatial [`MultiProblem`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiOutcome {
    /// Which law.
    pub law: LawId,
    /// One entry per contact, in order.
    pub contacts: Vec<ContactResult>,
    /// `ΔT = ½ (v⁻ + v⁺)·p` (exact for any impulse).
    pub energy_change: f64,
    /// Headline verdict: energy gained takes precedence over an inconsistency.
    pub verdict: Verdict,
    /// A contradicted assumption, if any (as for the planar outcome).
    pub inconsistency: Option<Inconsistency>,
    /// Law-specific detail.
    pub detail: MultiDetail,
}

/// What a spatial law returns for `K` contacts: an outcome or a breakdown.
pub type MultiResolution = Result<MultiOutcome, Breakdown>;

impl MultiOutcome {
    /// The impulses, one per contact.
    pub fn impulses(&self) -> Vec<Vec3> {
        self.contacts.iter().map(|c| c.impulse).collect()
    }

    /// The contact velocities after, one per contact.
    pub fn velocities_after(&self) -> Vec<Vec3> {
        self.contacts.iter().map(|c| c.velocity_after).collect()
    }

    /// Whether every number of the outcome, its detail included, is finite.
    pub fn is_finite(&self) -> bool {
        let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
        let detail = match &self.detail {
            MultiDetail::Lcp { solutions } => solutions.iter().all(|s| {
                s.energy_change.is_finite()
                    && s.impulses.iter().chain(&s.velocities_after).all(finite)
            }),
            MultiDetail::Sequential { impacts } => impacts
                .iter()
                .all(|b| finite(&b.velocity_before) && b.outcome.is_finite()),
            MultiDetail::Lzb { primaries, .. } => primaries.iter().all(|x| x.impulse.is_finite()),
            MultiDetail::OneContact { .. } => true,
        };
        detail
            && self.energy_change.is_finite()
            && self.contacts.iter().all(|c| {
                finite(&c.impulse)
                    && finite(&c.velocity_after)
                    && c.work.total().is_finite()
                    && c.phases.iter().all(|p| p.ends_at.is_finite())
            })
    }

    /// A one-contact outcome as the outcome of a problem with one contact.
    pub fn from_outcome(o: &Outcome) -> Self {
        let contact = ContactResult {
            impulse: o.impulse,
            velocity_after: o.velocity_after,
            phases: o
                .phases
                .as_slice()
                .iter()
                .map(|p| ContactPhase {
                    kind: ContactPhaseKind::Impact(p.kind),
                    ends_at: p.ends_at,
                })
                .collect(),
            work: o.work,
        };
        Self {
            law: o.law,
            contacts: vec![contact],
            energy_change: o.energy_change,
            verdict: o.verdict,
            inconsistency: o.inconsistency,
            detail: MultiDetail::OneContact {
                detail: o.detail,
                compression_impulse: o.compression_impulse,
            },
        }
    }
}

/// Whether `energy_change` of the flat impulses `p` (taking `v⁻` to `v⁺`) is a real gain,
/// beyond the round-off of its evaluation over the `3K` components (the planar
/// [`crate::multi::is_energy_gain`]'s test), all in the canonical units.
fn energy_gain(
    w: &DMatrix<f64>,
    v: &DVector<f64>,
    energy_change: f64,
    p: &DVector<f64>,
    v_after: &DVector<f64>,
) -> bool {
    if energy_change <= 0.0 {
        return false;
    }
    let n = v.len();
    let mut scale = 0.0;
    for i in 0..n {
        let wp: f64 = (0..n).map(|k| w[(i, k)].abs() * p[k].abs()).sum();
        scale += (v[i].abs() + v_after[i].abs() + wp) * p[i].abs();
    }
    energy_change > ENERGY_GAIN_ROUND_OFF * scale
}

/// `max_i (|v⁻_i| + (|W| |p|)_i)`: the scale of the velocities of an impact.
pub(crate) fn velocity_scale(w: &DMatrix<f64>, v: &DVector<f64>, p: &DVector<f64>) -> f64 {
    (0..v.len())
        .map(|i| {
            v[i].abs()
                + (0..p.len())
                    .map(|k| w[(i, k)].abs() * p[k].abs())
                    .sum::<f64>()
        })
        .fold(0.0, f64::max)
}

/// Assemble the outcome from per-contact results in the canonical units: `ΔT`, the verdict
/// (energy gained, else the law's inconsistency, else a contact still approaching beyond
/// [`VELOCITY_ROUND_OFF`]), then every number in the problem's own units.
pub(crate) fn assemble(
    problem: &MultiProblem,
    law: LawId,
    contacts: Vec<ContactResult>,
    detail: MultiDetail,
    inconsistency: Option<Inconsistency>,
) -> MultiOutcome {
    assemble_ending(problem, law, contacts, detail, inconsistency, Ending::Exact)
}

/// [`assemble`] for a law that reaches its end as `ending` says (an integrated law: a gain
/// must also exceed the disagreement of `ΔT` and the contacts' works summed, as in the
/// plane).
pub(crate) fn assemble_ending(
    problem: &MultiProblem,
    law: LawId,
    mut contacts: Vec<ContactResult>,
    mut detail: MultiDetail,
    inconsistency: Option<Inconsistency>,
    ending: Ending,
) -> MultiOutcome {
    let (u, w, v) = problem.canonical();
    let p = flatten(&contacts.iter().map(|c| c.impulse).collect::<Vec<_>>());
    let va = flatten(
        &contacts
            .iter()
            .map(|c| c.velocity_after)
            .collect::<Vec<_>>(),
    );
    let energy_change = 0.5 * (v + &va).dot(&p);
    let inconsistency = inconsistency.or_else(|| {
        let tol = VELOCITY_ROUND_OFF * velocity_scale(w, v, &p);
        let least = contacts
            .iter()
            .map(|c| c.velocity_after.z)
            .fold(f64::INFINITY, f64::min);
        (least < -tol).then_some(Inconsistency::StillApproaching {
            normal_velocity: least,
        })
    });
    let established = match ending {
        Ending::Exact => energy_change,
        Ending::Integrated => {
            let works: f64 = contacts.iter().map(|c| c.work.total()).sum();
            energy_change - 2.0 * (energy_change - works).abs()
        }
    };
    let verdict = if energy_gain(w, v, established, &p, &va) {
        Verdict::EnergyGained
    } else if inconsistency.is_some() {
        Verdict::InconsistentAssumption
    } else {
        Verdict::Consistent
    };
    for c in &mut contacts {
        c.impulse = c.impulse.map(|x| u.impulse(x));
        c.velocity_after = c.velocity_after.map(|x| u.velocity(x));
        c.work = work_in(u, c.work);
        for ph in &mut c.phases {
            ph.ends_at = u.impulse(ph.ends_at);
        }
    }
    match &mut detail {
        MultiDetail::Lcp { solutions } => {
            for s in solutions {
                for x in &mut s.impulses {
                    *x = x.map(|y| u.impulse(y));
                }
                for x in &mut s.velocities_after {
                    *x = x.map(|y| u.velocity(y));
                }
                s.energy_change = u.work(s.energy_change);
            }
        }
        MultiDetail::Sequential { impacts } => {
            for b in impacts {
                b.velocity_before = b.velocity_before.map(|y| u.velocity(y));
                b.outcome = b.outcome.in_problem_units(u);
            }
        }
        MultiDetail::Lzb { primaries, .. } => {
            for x in primaries {
                x.impulse = u.impulse(x.impulse);
            }
        }
        MultiDetail::OneContact { .. } => {}
    }
    let inconsistency = inconsistency.map(|i| match i {
        Inconsistency::StillApproaching { normal_velocity } => Inconsistency::StillApproaching {
            normal_velocity: u.velocity(normal_velocity),
        },
        other => other,
    });
    MultiOutcome {
        law,
        contacts,
        energy_change: u.work(energy_change),
        verdict,
        inconsistency,
        detail,
    }
}

/// A work split in the problem's units.
fn work_in(u: Units, w: WorkSplit) -> WorkSplit {
    WorkSplit {
        compression: u.work(w.compression),
        restitution: u.work(w.restitution),
        friction: u.work(w.friction),
    }
}
