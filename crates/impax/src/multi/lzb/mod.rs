//! `lzb`: the multiple-impact law of Liu, Zhao & Brogliato — every contact a compliant
//! element that stores energy, the impulses distributed by the contacts' force law,
//! energetic restitution and Coulomb friction at each contact.
//!
//! (Module documentation: see the end of this file's header, written with the results.)

mod events;
mod field;
mod friction;
mod path;
mod state;
mod variable;

use super::outcome::{assemble, assemble_ending, ContactResult, Ending, LzbPrimary, MultiDetail};
use super::{MultiProblem, MultiResolution};
use crate::law::{Breakdown, BreakdownReason, ImpactLaw, LawId};
use crate::math::Vec2;
use crate::planar::laws::Energetic;
use crate::planar::{BriefResolution, ContactProblem, Outcome, Resolution};
use state::Setup;

/// The most contacts `lzb` takes (its state lives in fixed-size arrays).
pub const MAX_CONTACTS: usize = 8;

/// The most integration steps (accepted or rejected) of one impact; beyond,
/// [`BreakdownReason::TooManySteps`].
pub const MAX_STEPS: usize = 20_000;

/// An off contact joins the impact when its normal velocity falls below
/// `−APPROACH_ROUND_OFF · max_i |v⁻_i|`, and the impact ends when every contact is off (none
/// approaching beyond that round-off). A contact at rest to that round-off starts or joins
/// with zero slip.
pub const APPROACH_ROUND_OFF: f64 = 1e-12;

/// The impact has settled, and ends, when every contact that carries a force moves by at
/// most `SETTLED · max_i |v⁻_i|` and stores at most the energy that would move it by that much,
/// and no other contact approaches by more: the tail of ever smaller exchanges of an
/// inelastic collapse (three nearly plastic contacts pressing on each other) is cut there.
pub const SETTLED: f64 = 1e-9;

/// A contact becomes the primary when its stored energy exceeds the primary's by more than
/// this fraction (in `Ê^(1/(η+1))`): ties (a symmetric body) keep the primary.
pub const PRIMARY_MARGIN: f64 = 1e-9;

/// The relative tolerance of the integration (each component of the state, against
/// `atol + RTOL |y|`, `atol` from the scale of the contact's impulse, deflection and
/// energy).
const RTOL: f64 = 1e-12;

/// `lzb` on `K` contacts (module docs). Breakdowns: [`BreakdownReason::TooManyContacts`]
/// beyond [`MAX_CONTACTS`], [`BreakdownReason::TooManySteps`] beyond [`MAX_STEPS`],
/// [`BreakdownReason::Overflow`] if a number is not representable; with one contact,
/// `energetic`'s.
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lzb;
    let k = problem.contacts();
    if k > MAX_CONTACTS {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::TooManyContacts {
                contacts: k,
                limit: MAX_CONTACTS,
            },
        });
    }
    if k == 1 {
        return one_contact(problem);
    }
    let setup = Setup::new(problem);
    let end = match k {
        2 => path::run::<8>(&setup),
        3 => path::run::<12>(&setup),
        4 => path::run::<16>(&setup),
        5 => path::run::<20>(&setup),
        6 => path::run::<24>(&setup),
        7 => path::run::<28>(&setup),
        _ => path::run::<32>(&setup),
    }
    .map_err(|reason| Breakdown { law, reason })?;
    let out = assemble_ending(
        problem,
        law,
        end.contacts,
        MultiDetail::Lzb {
            primaries: end.primaries,
            steps: end.steps,
        },
        None,
        Ending::Integrated,
    );
    if out.is_finite() {
        Ok(out)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
    }
}

/// One contact: the closed-form `energetic` path on the contact's block (module docs).
fn one_contact(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lzb;
    let (_, _, v0, blocks) = problem.canonical();
    let overflow = Breakdown {
        law,
        reason: BreakdownReason::Overflow,
    };
    let alone = ContactProblem::with_inertia(
        &blocks[0],
        Vec2::new(v0[0], v0[1]),
        problem.friction(0),
        problem.restitution(0),
    )
    .map_err(|_| overflow)?;
    let o = Energetic
        .resolve(&alone)
        .map_err(|b| Breakdown { law, ..b })?;
    let mut contact = ContactResult {
        impulse: o.impulse,
        velocity_after: o.velocity_after,
        phases: Vec::new(),
        work: o.work,
    };
    for ph in o.phases.as_slice() {
        contact.push_phase(ph.kind.into(), ph.ends_at);
    }
    let out = assemble(
        problem,
        law,
        vec![contact],
        MultiDetail::Lzb {
            primaries: vec![LzbPrimary {
                contact: 0,
                impulse: 0.0,
            }],
            steps: 0,
        },
        o.inconsistency,
    );
    if out.is_finite() {
        Ok(out)
    } else {
        Err(overflow)
    }
}

/// `lzb` with one contact, as a one-contact law: [`Energetic`], its outcome and breakdowns
/// labelled `lzb` (what [`LawId::resolve`] runs for [`LawId::Lzb`]).
///
/// ```
/// use impax::planar::{laws::{Energetic, ImpactLaw}, ContactProblem};
/// use impax::multi::lzb::OneContact;
/// let p = ContactProblem::from_entries(2.0, 0.5, 1.5, 0.3, -1.0, 0.3, 0.5).unwrap();
/// let (l, e) = (OneContact.resolve(&p).unwrap(), Energetic.resolve(&p).unwrap());
/// assert_eq!(l.impulse, e.impulse);
/// assert_eq!(l.law, impax::LawId::Lzb);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct OneContact;

impl ImpactLaw for OneContact {
    fn id(&self) -> LawId {
        LawId::Lzb
    }

    #[inline]
    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        let law = LawId::Lzb;
        Energetic
            .resolve(problem)
            .map(|o| Outcome { law, ..o })
            .map_err(|b| Breakdown { law, ..b })
    }

    #[inline]
    fn resolve_brief(&self, problem: &ContactProblem) -> BriefResolution {
        Energetic.resolve_brief(problem).map_err(|b| Breakdown {
            law: LawId::Lzb,
            ..b
        })
    }
}
