//! What a law returns for `K` contacts: per contact the impulse, the velocity after, the
//! phases and the work; `ΔT`, the verdict and the law's detail.

use super::MultiProblem;
use crate::law::energy::ENERGY_GAIN_ROUND_OFF;
use crate::law::{Breakdown, Inconsistency, LawId, Verdict, WorkSplit};
use crate::math::{Units, Vec2};
use crate::planar::{LawDetail, Outcome, PhaseKind, SlipDirection};
use nalgebra::{DMatrix, DVector};
use std::fmt;

/// The regime of one contact during (a part of) the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "kebab-case")
)]
pub enum ContactPhaseKind {
    /// No impulse at this contact (`p_j = 0`).
    Off,
    /// Stick: `v_t = 0` held by a friction ratio `|p_t| ≤ μ p_n`.
    Stick,
    /// Slip with Coulomb friction `p_t = −μ p_n ŝ` (`ŝ` the direction of the slip), or,
    /// without friction, `p_t = 0` labelled by the direction of the slip
    /// ([`SlipDirection::None`] when there is none).
    Slip(SlipDirection),
}

impl ContactPhaseKind {
    /// Stable label: `off`, `stick`, `slip+`, `slip-` or `no-slip`.
    pub fn label(self) -> &'static str {
        match self {
            ContactPhaseKind::Off => "off",
            ContactPhaseKind::Stick => "stick",
            ContactPhaseKind::Slip(d) => PhaseKind::Slip(d).label(),
        }
    }
}

impl From<PhaseKind> for ContactPhaseKind {
    fn from(kind: PhaseKind) -> Self {
        match kind {
            PhaseKind::Stick => ContactPhaseKind::Stick,
            PhaseKind::Slip(d) => ContactPhaseKind::Slip(d),
        }
    }
}

impl fmt::Display for ContactPhaseKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.label())
    }
}

/// One phase of one contact and the contact's own normal impulse at its end.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ContactPhase {
    /// The regime.
    pub kind: ContactPhaseKind,
    /// The contact's normal impulse `p_nj` at the end of the phase (counted from the start
    /// of the whole impact).
    pub ends_at: f64,
}

/// What happened at one contact.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ContactResult {
    /// The impulse on body A at this contact, `(p_t, p_n)`.
    pub impulse: Vec2,
    /// The contact velocity after, `(v_t⁺, v_n⁺)`.
    pub velocity_after: Vec2,
    /// The regimes in order (`lcp`: one; `sequential`: those of every binary impact at this
    /// contact, one `off` if it had none; `lzb`: the tangential regimes while the contact
    /// carries a force, `off` between two engagements, one `off` if it never engaged).
    pub phases: Phases,
    /// The work done at this contact, `∫ v_n dp_n` split at the end of its compression, and
    /// `∫ v_t dp_t`, along the law's path (`lcp`: the straight path `s p`, `0 ≤ s ≤ 1`, of all
    /// the impulses together; `sequential`: the binary impacts'; `lzb`: its integrated path,
    /// the normal work split by the sign of `v_n`). The contacts' works sum to `ΔT` (`lzb`: to
    /// the integration's tolerance).
    pub work: WorkSplit,
}

/// The phases of one contact ([`ContactResult::phases`]), in order: a slice, by
/// dereference; the first two held in place (no allocation), more on the heap.
///
/// ```
/// use impax::multi::{lcp, MultiProblem};
/// let p = MultiProblem::from_upper(1, &[3.5, 0.0, 1.0], &[0.5, -0.866], &[0.4], &[0.7]).unwrap();
/// let out = lcp::resolve(&p).unwrap();
/// let phases = &out.contacts[0].phases;
/// assert_eq!(phases.len(), 1);
/// for ph in phases {
///     assert!(ph.ends_at > 0.0);
/// }
/// ```
#[derive(Clone)]
pub struct Phases {
    /// How many are in `first` (while `more` is empty).
    len: usize,
    first: [ContactPhase; 2],
    /// Every phase, once there are more than two.
    more: Vec<ContactPhase>,
}

impl Phases {
    /// No phase.
    pub fn new() -> Self {
        let none = ContactPhase {
            kind: ContactPhaseKind::Off,
            ends_at: 0.0,
        };
        Phases {
            len: 0,
            first: [none; 2],
            more: Vec::new(),
        }
    }

    /// One phase.
    pub fn one(phase: ContactPhase) -> Self {
        let mut out = Phases::new();
        out.push(phase);
        out
    }

    /// Append a phase.
    pub fn push(&mut self, phase: ContactPhase) {
        if self.more.is_empty() {
            if self.len < self.first.len() {
                self.first[self.len] = phase;
                self.len += 1;
                return;
            }
            self.more.extend_from_slice(&self.first[..self.len]);
        }
        self.more.push(phase);
    }
}

impl Default for Phases {
    fn default() -> Self {
        Phases::new()
    }
}

impl std::ops::Deref for Phases {
    type Target = [ContactPhase];
    fn deref(&self) -> &[ContactPhase] {
        if self.more.is_empty() {
            &self.first[..self.len]
        } else {
            &self.more
        }
    }
}

impl std::ops::DerefMut for Phases {
    fn deref_mut(&mut self) -> &mut [ContactPhase] {
        if self.more.is_empty() {
            &mut self.first[..self.len]
        } else {
            &mut self.more
        }
    }
}

impl<'a> IntoIterator for &'a Phases {
    type Item = &'a ContactPhase;
    type IntoIter = std::slice::Iter<'a, ContactPhase>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a> IntoIterator for &'a mut Phases {
    type Item = &'a mut ContactPhase;
    type IntoIter = std::slice::IterMut<'a, ContactPhase>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter_mut()
    }
}

impl fmt::Debug for Phases {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl PartialEq for Phases {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl ContactResult {
    /// Labels joined by ` → `, e.g. `slip+ → stick`.
    pub fn phase_summary(&self) -> String {
        let labels: Vec<&str> = self.phases.iter().map(|p| p.kind.label()).collect();
        labels.join(" → ")
    }

    /// Append a phase ending at `ends_at`; extend the last one if it has the same kind. A
    /// loaded phase (stick or slip) that ends where the last one ended carries no impulse and
    /// is not recorded (a regime chosen at the very point where the contact's impulse stops
    /// growing); an `off` phase is recorded all the same (the impulse never grows while off).
    pub(crate) fn push_phase(&mut self, kind: ContactPhaseKind, ends_at: f64) {
        match self.phases.last_mut() {
            Some(last) if last.kind == kind => last.ends_at = ends_at,
            Some(last) if last.ends_at == ends_at && kind != ContactPhaseKind::Off => {}
            _ => self.phases.push(ContactPhase { kind, ends_at }),
        }
    }
}

/// One solution of the complementarity conditions of [`super::lcp`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LcpSolution {
    /// Each contact's regime: `off`, `stick`, `slip+` or `slip-` (`slip±`/`no-slip` by the
    /// slip after at a frictionless contact).
    pub regimes: PerContact<ContactPhaseKind>,
    /// The impulses, one per contact (module docs of [`super::lcp`] for the choice when `W` is
    /// singular).
    pub impulses: PerContact<Vec2>,
    /// The contact velocities after, one per contact.
    pub velocities_after: PerContact<Vec2>,
    /// `ΔT = ½ Σ_j (v_j⁻ + v_j⁺)·p_j`.
    pub energy_change: f64,
}

/// One value per contact of an [`LcpSolution`], held in place (no allocation; at most
/// [`super::lcp::MAX_CONTACTS`] contacts): a slice, by dereference.
///
/// ```
/// use impax::multi::{lcp, MultiProblem};
/// let p = MultiProblem::from_upper(1, &[3.5, 0.0, 1.0], &[0.5, -0.866], &[0.4], &[0.7]).unwrap();
/// let s = &lcp::solutions(&p)[0];
/// assert_eq!(s.impulses.len(), 1);
/// let all: &[impax::math::Vec2] = &s.impulses;
/// assert_eq!(all[0], s.impulses[0]);
/// ```
#[derive(Clone, Copy)]
pub struct PerContact<T: Copy> {
    len: usize,
    items: [T; super::lcp::MAX_CONTACTS],
}

impl<T: Copy> PerContact<T> {
    /// `len` copies of `value` (`len ≤` [`super::lcp::MAX_CONTACTS`]).
    pub(crate) fn filled(len: usize, value: T) -> Self {
        assert!(len <= super::lcp::MAX_CONTACTS);
        Self {
            len,
            items: [value; super::lcp::MAX_CONTACTS],
        }
    }
}

impl<T: Copy> std::ops::Deref for PerContact<T> {
    type Target = [T];
    fn deref(&self) -> &[T] {
        &self.items[..self.len]
    }
}

impl<T: Copy> std::ops::DerefMut for PerContact<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        &mut self.items[..self.len]
    }
}

impl<'a, T: Copy> IntoIterator for &'a PerContact<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a, T: Copy> IntoIterator for &'a mut PerContact<T> {
    type Item = &'a mut T;
    type IntoIter = std::slice::IterMut<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter_mut()
    }
}

impl<T: Copy + fmt::Debug> fmt::Debug for PerContact<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<T: Copy + PartialEq> PartialEq for PerContact<T> {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

// serde: both as the sequence they dereference to (the forms they had as `Vec`s).

#[cfg(feature = "serde")]
impl serde::Serialize for Phases {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.iter())
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Phases {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let list = Vec::<ContactPhase>::deserialize(deserializer)?;
        let mut out = Phases::new();
        for phase in list {
            out.push(phase);
        }
        Ok(out)
    }
}

#[cfg(feature = "serde")]
impl<T: Copy + serde::Serialize> serde::Serialize for PerContact<T> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.iter())
    }
}

#[cfg(feature = "serde")]
impl<'de, T: Copy + serde::Deserialize<'de>> serde::Deserialize<'de> for PerContact<T> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let list = Vec::<T>::deserialize(deserializer)?;
        let (Some(&first), true) = (list.first(), list.len() <= super::lcp::MAX_CONTACTS) else {
            return Err(D::Error::custom(format!(
                "{} contacts: a solution has 1 to {}",
                list.len(),
                super::lcp::MAX_CONTACTS
            )));
        };
        let mut out = PerContact::filled(list.len(), first);
        out.copy_from_slice(&list);
        Ok(out)
    }
}

/// One binary impact of [`super::sequential`]: a contact resolved alone by `energetic`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BinaryImpact {
    /// The contact (from 0).
    pub contact: usize,
    /// Its velocity before this impact.
    pub velocity_before: Vec2,
    /// The one-contact outcome on the contact's own block (impulse, velocity after, phases,
    /// work, `ΔT`: the whole system's `ΔT` of this impact, since only this contact pushes).
    pub outcome: Outcome,
}

/// A primary contact of [`super::lzb`]: the contact with the most stored energy, whose
/// normal impulse is the independent variable of Liu, Zhao & Brogliato's formulation, from
/// the moment it took over.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LzbPrimary {
    /// The contact (from 0).
    pub contact: usize,
    /// Its own normal impulse `p_nj` when it took over (0 for the first primary).
    pub impulse: f64,
}

/// Law-specific detail.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(tag = "id", rename_all = "kebab-case")
)]
pub enum MultiDetail {
    /// `lcp`: every solution of the conditions, least kinetic energy after first (the first
    /// is the result).
    Lcp {
        /// The solutions.
        solutions: Vec<LcpSolution>,
    },
    /// `sequential`: the binary impacts in order.
    Sequential {
        /// The impacts.
        impacts: Vec<BinaryImpact>,
    },
    /// `lzb`: the primary contacts in turn and the number of integration steps.
    Lzb {
        /// The primary contacts in turn ([`LzbPrimary`]): the first at the start of the impact
        /// (the contact whose stored energy grows fastest), then each contact whose stored
        /// energy overtook the primary's, or the one with the most energy when the primary
        /// separated. The primary does not change the result (module docs of
        /// [`super::lzb`]); it is reported as the papers' independent variable.
        primaries: Vec<LzbPrimary>,
        /// The accepted integration steps (each ending at the end of a step or at an event);
        /// phases taken in closed form count none: 0 with one contact (the closed-form
        /// `energetic` path) and for contacts that load in fixed proportions throughout (a
        /// rod landing flat).
        steps: usize,
    },
    /// A one-contact law on a problem with one contact: its own detail and compression
    /// impulse.
    OneContact {
        /// The law's detail.
        detail: LawDetail,
        /// The normal impulse at the end of compression, if reached on the law's path.
        compression_impulse: Option<f64>,
    },
}

/// The result of a law on a [`MultiProblem`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MultiOutcome {
    /// Which law.
    pub law: LawId,
    /// One entry per contact, in order.
    pub contacts: Vec<ContactResult>,
    /// `ΔT = v⁻·p + ½ pᵀ W p = ½ (v⁻ + v⁺)·p` (exact for any impulse).
    pub energy_change: f64,
    /// Headline verdict: energy gained takes precedence over an inconsistency.
    pub verdict: Verdict,
    /// A contradicted assumption, if any: [`Inconsistency::MultipleSolutions`] (`lcp`),
    /// [`Inconsistency::StillApproaching`] (a contact approaching after the impact beyond
    /// round-off: a guard that the laws are built never to trip).
    pub inconsistency: Option<Inconsistency>,
    /// Law-specific detail.
    pub detail: MultiDetail,
}

/// What a law returns for `K` contacts: an outcome or a breakdown.
pub type MultiResolution = Result<MultiOutcome, Breakdown>;

impl MultiOutcome {
    /// The impulses, one per contact.
    pub fn impulses(&self) -> Vec<Vec2> {
        self.contacts.iter().map(|c| c.impulse).collect()
    }

    /// The contact velocities after, one per contact.
    pub fn velocities_after(&self) -> Vec<Vec2> {
        self.contacts.iter().map(|c| c.velocity_after).collect()
    }

    /// Whether every number of the outcome, its detail included, is finite.
    pub fn is_finite(&self) -> bool {
        // `x · 0` is ±0 for a finite `x` and NaN otherwise: one sum of them tells whether every
        // number is finite, without a branch per number.
        let mut zero = 0.0 * self.energy_change;
        let mut add = |x: f64| zero += x * 0.0;
        for c in &self.contacts {
            add(c.impulse.x);
            add(c.impulse.y);
            add(c.velocity_after.x);
            add(c.velocity_after.y);
            add(c.work.compression);
            add(c.work.restitution);
            add(c.work.friction);
            for p in &c.phases {
                add(p.ends_at);
            }
        }
        match &self.detail {
            MultiDetail::Lcp { solutions } => {
                for s in solutions {
                    add(s.energy_change);
                    for x in s.impulses.iter().chain(&s.velocities_after) {
                        add(x.x);
                        add(x.y);
                    }
                }
            }
            MultiDetail::Sequential { impacts } => {
                for b in impacts {
                    add(b.velocity_before.x);
                    add(b.velocity_before.y);
                    if !b.outcome.is_finite() {
                        return false;
                    }
                }
            }
            MultiDetail::Lzb { primaries, .. } => {
                for p in primaries {
                    add(p.impulse);
                }
            }
            MultiDetail::OneContact { .. } => {}
        }
        zero == 0.0
    }

    /// A one-contact outcome as the outcome of a problem with one contact.
    pub fn from_outcome(o: &Outcome) -> Self {
        let mut contact = ContactResult {
            impulse: o.impulse,
            velocity_after: o.velocity_after,
            phases: Phases::new(),
            work: o.work,
        };
        for p in o.phases.as_slice() {
            contact.push_phase(p.kind.into(), p.ends_at);
        }
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

/// Whether `energy_change = ΔT` of the impulses `p` (taking `v⁻` to `v⁺`) is a real gain: it
/// exceeds the round-off of its own evaluation, the one-contact test
/// ([`crate::law::energy`]) over the `2K` components,
///
/// ```text
/// ΔT > 16 ε Σ_i (|v⁻_i| + |v⁺_i| + (|W| |p|)_i) |p_i|.
/// ```
pub fn is_energy_gain(
    problem: &MultiProblem,
    energy_change: f64,
    p: &[Vec2],
    v_after: &[Vec2],
) -> bool {
    let (u, w, v, _) = problem.canonical();
    energy_gain(
        w,
        v,
        energy_change * u.a * u.a / u.b,
        |j| p[j].map(|x| x * u.a / u.b),
        |j| v_after[j].map(|x| x * u.a),
    )
}

/// [`is_energy_gain`] in the canonical units, with contact `j`'s impulse `p(j)` and velocity
/// after `v_after(j)`.
fn energy_gain(
    w: &DMatrix<f64>,
    v: &DVector<f64>,
    energy_change: f64,
    p: impl Fn(usize) -> Vec2,
    v_after: impl Fn(usize) -> Vec2,
) -> bool {
    if energy_change <= 0.0 {
        return false;
    }
    let n = v.len();
    let mut scale = 0.0;
    for i in 0..n {
        let wp: f64 = (0..n).map(|k| w[(i, k)].abs() * flat(k, &p).abs()).sum();
        scale += (v[i].abs() + flat(i, &v_after).abs() + wp) * flat(i, &p).abs();
    }
    energy_change > ENERGY_GAIN_ROUND_OFF * scale
}

/// Component `i` of the contact-major vector whose contact `j` is `x(j)`.
#[inline(always)]
fn flat(i: usize, x: &impl Fn(usize) -> Vec2) -> f64 {
    if i.is_multiple_of(2) {
        x(i / 2).x
    } else {
        x(i / 2).y
    }
}

/// The relative round-off below which a negative normal velocity after is not "approaching"
/// (relative to the velocity scale `max_i (|v⁻_i| + (|W| |p|)_i)`), and the tolerance of the
/// conditions of [`super::lcp`].
pub const VELOCITY_ROUND_OFF: f64 = 1e-9;

/// `max_i (|v⁻_i| + (|W| |p|)_i)`: the scale of the velocities of an impact (`p(j)` contact
/// `j`'s impulse, `k` contacts).
pub(crate) fn velocity_scale(
    w: &DMatrix<f64>,
    v: &DVector<f64>,
    k: usize,
    p: impl Fn(usize) -> Vec2,
) -> f64 {
    let n = v.len();
    (0..n)
        .map(|i| {
            v[i].abs()
                + (0..k)
                    .map(|j| {
                        let pj = p(j);
                        w[(i, 2 * j)].abs() * pj.x.abs() + w[(i, 2 * j + 1)].abs() * pj.y.abs()
                    })
                    .sum::<f64>()
        })
        .fold(0.0, f64::max)
}

/// How a law reaches its end, for the energy-gain test of [`assemble`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Ending {
    /// Exactly (closed forms, linear algebra): a gain beyond round-off is a gain.
    Exact,
    /// To an integration's tolerance (`lzb`): a gain must also exceed the disagreement of
    /// the two evaluations of `ΔT`, `½ (v⁻ + v⁺)·p` and the contacts' works summed (as the
    /// spatial Darboux–Keller laws do), so that what is flagged is a gain, not the
    /// integration's error.
    Integrated,
}

/// Assemble the outcome of a law from its per-contact results in the problem's canonical
/// units: `ΔT = ½ Σ_j (v_j⁻ + v_j⁺)·p_j`, the verdict (energy gained, else the law's
/// inconsistency, else a contact still approaching beyond [`VELOCITY_ROUND_OFF`]), then every
/// number in the problem's own units.
pub(crate) fn assemble(
    problem: &MultiProblem,
    law: LawId,
    contacts: Vec<ContactResult>,
    detail: MultiDetail,
    inconsistency: Option<Inconsistency>,
) -> MultiOutcome {
    assemble_ending(problem, law, contacts, detail, inconsistency, Ending::Exact)
}

/// [`assemble`] for a law that reaches its end as `ending` says.
pub(crate) fn assemble_ending(
    problem: &MultiProblem,
    law: LawId,
    mut contacts: Vec<ContactResult>,
    mut detail: MultiDetail,
    inconsistency: Option<Inconsistency>,
    ending: Ending,
) -> MultiOutcome {
    let (u, w, v, _) = problem.canonical();
    let energy_change: f64 = contacts
        .iter()
        .enumerate()
        .map(|(j, c)| {
            0.5 * ((v[2 * j] + c.velocity_after.x) * c.impulse.x
                + (v[2 * j + 1] + c.velocity_after.y) * c.impulse.y)
        })
        .sum();
    let p = |j: usize| contacts[j].impulse;
    let va = |j: usize| contacts[j].velocity_after;
    let inconsistency = inconsistency.or_else(|| {
        let least = contacts
            .iter()
            .map(|c| c.velocity_after.y)
            .fold(f64::INFINITY, f64::min);
        // (The scale only when a contact approaches at all: a tolerance is never negative.)
        (least < 0.0 && least < -VELOCITY_ROUND_OFF * velocity_scale(w, v, contacts.len(), p))
            .then_some(Inconsistency::StillApproaching {
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
    let verdict = if energy_gain(w, v, established, p, va) {
        Verdict::EnergyGained
    } else if inconsistency.is_some() {
        Verdict::InconsistentAssumption
    } else {
        Verdict::Consistent
    };
    // Back to the problem's units (powers of two: exact).
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
        Inconsistency::SlipReversed { slip_after } => Inconsistency::SlipReversed {
            slip_after: u.velocity(slip_after),
        },
        Inconsistency::ReversalDidNotHappen { slip_after } => Inconsistency::ReversalDidNotHappen {
            slip_after: u.velocity(slip_after),
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
