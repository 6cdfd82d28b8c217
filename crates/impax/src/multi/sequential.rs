//! `sequential`: binary impacts, one contact at a time — the binary-collision model.
//!
//! The classical way to resolve simultaneous impacts as a sequence of single ones (e.g.
//! Stronge, *Impact Mechanics* 2000, ch. 8 on multiple collisions; the textbook Newton's
//! cradle): while a contact approaches, take **the most approaching contact** — the most
//! negative `v_nj` (ties: the lowest index) — and resolve it **alone** with the one-contact
//! [`energetic`](crate::planar::laws::energetic) law on its own block `W_jj`, as if the other
//! contacts were absent; its impulse `p_j` changes every contact's velocity,
//!
//! ```text
//! v_i ← v_i + W_ij p_j   (i ≠ j),      v_j ← v_j⁺ of the binary impact,
//! ```
//!
//! and the next most approaching contact is taken, until no contact approaches beyond
//! round-off (`v_nj ≥ −`[`APPROACH_ROUND_OFF`]` · max_i |v⁻_i|`). Each binary impact satisfies
//! its energetic restitution and Coulomb's law, so the sequence never gains energy (each
//! `ΔT_i ≤ 0`, and the whole `ΔT = Σ_i ΔT_i` since only one contact pushes at a time) and never
//! ends with a contact approaching.
//!
//! **Bound.** A sequence can be infinite (three balls in a row with `e < 1`, an inelastic
//! collapse: the impacts alternate with geometrically decreasing velocities); it then ends by
//! the round-off test above. It is cut at [`MAX_IMPACTS`] binary impacts with the breakdown
//! [`BreakdownReason::TooManyImpacts`] (`too-many-impacts`) if a contact still approaches.
//!
//! **What it gets wrong.** The result depends on the order: simultaneous contacts are not
//! simultaneous here. A rod landing flat on both ends (symmetric, `W` singular) ends with the
//! body at `(0, e |v_y|, 0)` only for `e = 0` or `e = 1`; for `0 < e < 1` the first end struck
//! (the lowest index on the tie) makes it rotate. Newton's cradle, which it gets right, is the
//! case the model was made for.
//!
//! With one contact: `energetic` exactly (the same impulse and velocities; the outcome
//! labelled `sequential`).
//!
//! ```
//! use impax::multi::{sequential, MultiProblem};
//! // Newton's cradle, three equal balls (m = 1) touching, e = 1, frictionless: ball 1 stops,
//! // ball 2 passes the impulse on, ball 3 leaves at v0 — two binary impacts.
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[2.0, 0.0, 0.0, 0.0, /**/ 2.0, 0.0, -1.0, /**/ 2.0, 0.0, /**/ 2.0],
//!     &[0.0, -1.0, 0.0, 0.0],
//!     &[0.0],
//!     &[1.0],
//! )
//! .unwrap();
//! let out = sequential::resolve(&p).unwrap();
//! assert!((out.contacts[0].impulse.y - 1.0).abs() < 1e-15);
//! assert!((out.contacts[1].impulse.y - 1.0).abs() < 1e-15);
//! assert!(out.energy_change.abs() < 1e-15);
//! assert!(out.contacts[0].velocity_after.y.abs() < 1e-15); // balls 1 and 2 at rest together
//! ```

use super::outcome::{assemble, BinaryImpact, ContactPhaseKind, ContactResult, MultiDetail};
use super::problem::coupling;
use super::{MultiProblem, MultiResolution};
use crate::law::{Breakdown, BreakdownReason, ImpactLaw, LawId, WorkSplit};
use crate::math::Vec2;
use crate::planar::laws::Energetic;
use crate::planar::{BriefResolution, ContactProblem, Outcome, Resolution};

/// The most binary impacts of one resolution.
pub const MAX_IMPACTS: usize = 10_000;

/// A contact approaches while `v_nj < −APPROACH_ROUND_OFF · max_i |v⁻_i|`.
pub const APPROACH_ROUND_OFF: f64 = 1e-12;

/// `sequential` on `K` contacts (module docs). Breakdowns: a binary impact's (`energetic`'s,
/// relabelled), [`BreakdownReason::TooManyImpacts`], [`BreakdownReason::Overflow`].
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Sequential;
    let k = problem.contacts();
    let (_, w, v0, blocks) = problem.canonical();
    let (mu, e) = (problem.frictions(), problem.restitutions());
    let mut v: Vec<Vec2> = (0..k)
        .map(|j| Vec2::new(v0[2 * j], v0[2 * j + 1]))
        .collect();
    let tol = APPROACH_ROUND_OFF * v0.amax();
    let mut contacts: Vec<ContactResult> = (0..k)
        .map(|_| ContactResult {
            impulse: Vec2::zeros(),
            velocity_after: Vec2::zeros(),
            phases: crate::multi::Phases::new(),
            work: WorkSplit::default(),
        })
        .collect();
    let mut impacts: Vec<BinaryImpact> = Vec::new();
    let mut inconsistency = None;
    loop {
        // The most approaching contact; ties: the lowest index.
        let mut j = 0;
        for i in 1..k {
            if v[i].y < v[j].y {
                j = i;
            }
        }
        if v[j].y >= -tol {
            break;
        }
        if impacts.len() >= MAX_IMPACTS {
            return Err(Breakdown {
                law,
                reason: BreakdownReason::TooManyImpacts { limit: MAX_IMPACTS },
            });
        }
        let alone =
            ContactProblem::with_inertia(&blocks[j], v[j], mu[j], e[j]).map_err(|_| Breakdown {
                law,
                reason: BreakdownReason::Overflow,
            })?;
        let out = Energetic
            .resolve(&alone)
            .map_err(|b| Breakdown { law, ..b })?;
        let p = out.impulse;
        for (i, vi) in v.iter_mut().enumerate() {
            if i != j {
                *vi += coupling(w, i, j) * p;
            }
        }
        let before = v[j];
        v[j] = out.velocity_after;
        let c = &mut contacts[j];
        let offset = c.impulse.y;
        for ph in out.phases.as_slice() {
            c.push_phase(ph.kind.into(), offset + ph.ends_at);
        }
        c.work = WorkSplit {
            compression: c.work.compression + out.work.compression,
            restitution: c.work.restitution + out.work.restitution,
            friction: c.work.friction + out.work.friction,
        };
        c.impulse += p;
        inconsistency = inconsistency.or(out.inconsistency);
        impacts.push(BinaryImpact {
            contact: j,
            velocity_before: before,
            outcome: Outcome { law, ..out },
        });
    }
    for (c, vj) in contacts.iter_mut().zip(&v) {
        c.velocity_after = *vj;
        if c.phases.is_empty() {
            c.push_phase(ContactPhaseKind::Off, 0.0);
        }
    }
    let out = assemble(
        problem,
        law,
        contacts,
        MultiDetail::Sequential { impacts },
        inconsistency,
    );
    let finite = out.is_finite();
    crate::multi::finite_or_overflow(law, out, finite)
}

/// `sequential` with one contact, as a one-contact law: [`Energetic`], its outcome and
/// breakdowns labelled `sequential` (what [`LawId::resolve`] runs for
/// [`LawId::Sequential`]).
///
/// ```
/// use impax::planar::{laws::{Energetic, ImpactLaw}, ContactProblem};
/// use impax::multi::sequential::OneContact;
/// let p = ContactProblem::from_entries(2.0, 0.5, 1.5, 0.3, -1.0, 0.3, 0.5).unwrap();
/// let (s, e) = (OneContact.resolve(&p).unwrap(), Energetic.resolve(&p).unwrap());
/// assert_eq!(s.impulse, e.impulse);
/// assert_eq!(s.law, impax::LawId::Sequential);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct OneContact;

impl ImpactLaw for OneContact {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Sequential
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        let law = LawId::Sequential;
        Energetic
            .resolve(problem)
            .map(|o| Outcome { law, ..o })
            .map_err(|b| Breakdown { law, ..b })
    }

    #[inline]
    fn resolve_brief(&self, problem: &ContactProblem) -> BriefResolution {
        Energetic.resolve_brief(problem).map_err(|b| Breakdown {
            law: LawId::Sequential,
            ..b
        })
    }
}
