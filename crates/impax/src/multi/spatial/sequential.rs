//! `sequential` in 3D: binary impacts, one contact at a time, each with the spatial
//! `energetic` law — the planar [`crate::multi::sequential`] with swirl.
//!
//! While a contact approaches, the most approaching one (the most negative `v_nj`; ties: the
//! lowest index) is resolved alone on its own block `W_jj` by the one-contact spatial
//! [`energetic`](crate::spatial::laws) law (Stronge's energetic restitution, the Darboux–Keller
//! integration with the slip direction turning), every other contact's velocity updated by
//! `v_i ← v_i + W_ij p_j`, until none approaches beyond round-off
//! (`v_nj ≥ −`[`APPROACH_ROUND_OFF`]` · max_i |v⁻_i|`), at most [`MAX_IMPACTS`] binary impacts.
//! Each binary impact dissipates, so the sequence never gains energy.
//!
//! ```
//! use impax::multi::spatial::{sequential, MultiProblem};
//! // Newton's cradle of three unit point masses in 3D, frictionless, e = 1: the normals
//! // (last of each contact) coupled by −1, the tangents uncoupled.
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, -1.0,
//!       2.0, 0.0, 0.0, 2.0, 0.0, 2.0],
//!     &[0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
//!     &[0.0],
//!     &[1.0],
//! )
//! .unwrap();
//! let out = sequential::resolve(&p).unwrap();
//! assert!((out.contacts[1].velocity_after.z - 1.0).abs() < 1e-12); // the last ball leaves
//! assert!(out.energy_change.abs() < 1e-12);
//! ```

use super::outcome::{
    assemble, BinaryImpact, ContactPhase, ContactPhaseKind, ContactResult, MultiDetail,
};
use super::problem::coupling;
use super::{MultiProblem, MultiResolution};
use crate::law::{Breakdown, BreakdownReason, LawId, WorkSplit};
use crate::math::{Mat3, Vec3};
use crate::spatial::{ContactProblem, Outcome};

pub use crate::multi::sequential::{APPROACH_ROUND_OFF, MAX_IMPACTS};

/// `sequential` on `K` spatial contacts (module docs). Breakdowns: a binary impact's
/// (`energetic`'s, relabelled), [`BreakdownReason::TooManyImpacts`],
/// [`BreakdownReason::Overflow`].
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Sequential;
    let k = problem.contacts();
    let (_, w, v0) = problem.canonical();
    let mut v: Vec<Vec3> = (0..k)
        .map(|j| Vec3::new(v0[3 * j], v0[3 * j + 1], v0[3 * j + 2]))
        .collect();
    let blocks: Vec<Mat3> = (0..k).map(|j| coupling(w, j, j)).collect();
    let tol = APPROACH_ROUND_OFF * v0.amax();
    let mut contacts: Vec<ContactResult> = (0..k).map(|_| ContactResult::empty()).collect();
    let mut impacts: Vec<BinaryImpact> = Vec::new();
    let mut inconsistency = None;
    loop {
        let mut j = 0;
        for i in 1..k {
            if v[i].z < v[j].z {
                j = i;
            }
        }
        if v[j].z >= -tol {
            break;
        }
        if impacts.len() >= MAX_IMPACTS {
            return Err(Breakdown {
                law,
                reason: BreakdownReason::TooManyImpacts { limit: MAX_IMPACTS },
            });
        }
        let alone =
            ContactProblem::new(blocks[j], v[j], problem.friction(j), problem.restitution(j))
                .map_err(|_| Breakdown {
                    law,
                    reason: BreakdownReason::Overflow,
                })?;
        let out = LawId::Energetic
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
        let offset = c.impulse.z;
        for ph in out.phases.as_slice() {
            c.phases.push(ContactPhase {
                kind: ContactPhaseKind::Impact(ph.kind),
                ends_at: offset + ph.ends_at,
            });
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
            c.phases.push(ContactPhase {
                kind: ContactPhaseKind::Off,
                ends_at: 0.0,
            });
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
