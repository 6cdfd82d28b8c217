//! `lzb`: the multiple-impact law of Liu, Zhao & Brogliato — every contact a compliant
//! element that stores energy, the impulses distributed by the contacts' force law,
//! energetic restitution and Coulomb friction at each contact.
//!
//! C. Liu, Z. Zhao & B. Brogliato, *Frictionless multiple impacts in multibody systems. I.
//! Theoretical framework*, Proc. R. Soc. A 464 (2008) 3193–3211, doi 10.1098/rspa.2008.0078
//! (open copy HAL hal-00755941); *II. Numerical algorithm and simulation results*, Proc. R.
//! Soc. A 465 (2009) 1–23, doi 10.1098/rspa.2008.0079; friction in the plane: Z. Zhao,
//! C. Liu & B. Brogliato, *Planar dynamics of a rigid body system with frictional impacts*,
//! Proc. R. Soc. A 465 (2009). The numerical algorithm as published is implemented in
//! Siconos (`kernel/src/simulation/MultipleImpact.cpp`), which was read for the points below.
//!
//! ## The model
//!
//! The configuration is frozen (theory §6): `v = v⁻ + W p`. Each contact `j` is a compliant
//! element with the force law `F_j = κ_j δ_j^η` ([`MultiProblem::with_stiffness`],
//! [`MultiProblem::with_exponent`]; `η = 3/2` is Hertz's), whose potential energy is
//! `E_j = κ_j δ_j^(η+1)/(η+1)`, so that `F_j = κ_j^(1/(η+1)) ((η+1) E_j)^(η/(η+1))`. The
//! impulses grow as `dp_nj = F_j dt`, hence the **distributing law** of part I: with `m` the
//! primary contact (the one with the most stored energy) and its normal impulse `P_m` the
//! independent variable,
//!
//! ```text
//! dp_nj/dP_m = F_j/F_m = (κ_j/κ_m)^(1/(η+1)) (E_j/E_m)^(η/(η+1)),
//! dE_j = −v_nj dp_nj            in compression (v_nj < 0),
//! dE_j = −v_nj dp_nj / e_j²     in expansion   (v_nj ≥ 0),
//! ```
//!
//! The second rate is the **bi-stiffness** energetic restitution of part I: the contact
//! unloads `1/e_j^(2η)` times stiffer, so that the normal work done in expansion is `e_j²`
//! times the energy released (the stored energy variable kept continuous, as Siconos does).
//! When `E_j` is back to zero in expansion the contact **separates**; it stays off while
//! `v_nj ≥ 0` and joins again, from zero energy, if it approaches again. With `e_j = 0` the
//! energy stored is lost where compression ends. Only the stiffness *ratios* matter (every
//! `κ_j` times one factor changes the duration of the impact, not its outcome).
//!
//! **Friction** (Coulomb, per contact): a slipping contact has `dp_tj = −μ_j σ_j dp_nj`,
//! `σ_j = sign(v_tj)`; the sticking contacts `S` have tangential impulse rates that keep their
//! `v_t` at zero, `W_SS^tt ẋ_S = −(the rest of W ṗ)_S` (least norm when `W_SS^tt` is
//! singular: redundant contacts share one tangential velocity), accepted while
//! `|ẋ_j| ≤ μ_j F_j`; else that contact slips, the way its tangential velocity then goes. A
//! slip that halts sticks or reverses, as with one contact ([`crate::planar::laws::energetic`]).
//! Where several contacts have zero slip at once, every assignment of stick and slip is tried,
//! most sticks first, and the first consistent one taken (`friction.rs`).
//!
//! ## How the papers integrate it, and how impax does
//!
//! Part II integrates in `P_m` with a fixed step `ΔP`, and the rates above are `0/0` where
//! energies vanish:
//!
//! * **at the start** every `E_j = 0`. The algorithm takes the most approaching contact as
//!   primary and, over the first step, the self-consistent ratios of approaching contacts,
//!   `dp_nj/dP_m = (κ_j/κ_m) (v_nj/v_nm)^η` (the limit of the law as `E → 0`: `δ_j ≈ −v_nj t`);
//! * **a contact without energy that approaches** later is given, over one step, the energy
//!   `|v_nj| ΔP` (`ΔP` the primary's step) to set its ratio. The equations in `E` have the
//!   trivial branch `E_j ≡ 0` there (`dE_j/dP_m ∝ E_j^(η/(η+1))` is not Lipschitz at 0): a
//!   contact that starts approaching with no energy must be pushed onto the other one;
//! * **the primary** is re-chosen at every step (the most energy), so that `E_m` is never
//!   small while others are not.
//!
//! impax integrates the same equations in the **contact-force time** `τ`, `dp_nj = F_j dτ`
//! (the time of the compliant model, up to the stiffness scale: `dP_m = F_m dτ` turns one into
//! the other, so the path is the same), with each contact's **deflection**
//! `s_j ∝ E_j^(1/(η+1))` in the state (`Ê_j = κ_j s_j^(η+1)/(η+1)`, `F_j = κ_j s_j^η`, the
//! largest `κ_j` scaled to 1):
//!
//! ```text
//! ds_j/dτ = −v_nj (compression),  −v_nj / e_j² (expansion),  0 (off),
//! dp_nj/dτ = κ_j s_j^η,   dp_tj/dτ = −μ_j σ_j dp_nj/dτ (slip) or the stick solve,   v = v⁻ + W p.
//! ```
//!
//! This is the suggested regular form `ds_j/dP_m = −v_nj (κ_j/κ_m)^(1/(η+1)) /
//! ((η+1) E_m^(η/(η+1)))` multiplied through by `F_m`: no contact is singled out, so
//!
//! * there is **no `0/0` at the start**: all `s_j = 0` and `ds_j/dτ = −v_nj⁻ > 0` for the
//!   approaching contacts, whose forces then grow in the ratios above by themselves;
//! * **a contact joins** as soon as its `v_nj` falls below zero (below `−`[`APPROACH_ROUND_OFF`]
//!   of the largest `|v⁻_i|`): `ds_j/dτ = −v_nj > 0` is regular at `s_j = 0`, there is no
//!   trivial branch. A contact at rest at the start, `v_nj⁻` at or above that round-off
//!   (the middle contacts of a cradle, the resting corner of a rocking block), is off until
//!   then;
//! * **the primary** plays no part in the integration; it is still followed — the contact
//!   with the most stored energy, changing when another's exceeds it by [`PRIMARY_MARGIN`],
//!   or when it separates — and reported ([`MultiDetail::Lzb`]), with the normal impulse of
//!   each primary where it took over. At the start it is the contact whose energy grows
//!   fastest, the largest `κ_j |v_nj⁻|^(η+1)` (the most approaching one for equal stiffness).
//!
//! The right-hand side is smooth except where a contact's force law is not, at `s_j = 0`
//! (`F ∝ s^η`): from the start of the impact to its first event the path is integrated in
//! `z = τ^(η+1)`, in which it is analytic for every `η` (`s_j = τ q_j(z)`), and at each
//! separation in `σ = s_j^(1/m)` (module `variable.rs`), in which it is analytic for Hertz's
//! exponent. Where every contact that carries a force is loaded (`s_j > 0`), or starts
//! loading from a double zero of `s_j` (a contact joining at `v_nj = 0`: `s_j = t² q_j`, the
//! force `κ_j |t|^(2η) q_j^η`, analytic for an integer `2η`), and from the start in `z`, the
//! path is a **Taylor series** in the variable, to order 17, its
//! coefficients by the recurrences of automatic differentiation (`s^η`, products, the
//! quotient of a separation's variable) and its step where the terms reach the tolerance
//! (`series/`); elsewhere — a force starting from zero for another exponent (a contact
//! joining; the start, where the approaches differ a thousandfold or more and it is taken in
//! `u`), and where a series' coefficients overflow (friction of `1e100`) — the explicit
//! Runge–Kutta pair of
//! order 8 of Dormand & Prince (DOP853, as in Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, §II.5; the crate's `numerics::dop853`) takes the step. The tolerance is
//! `1e-12` relative on every component. The events — a compression ending (`v_nj = 0`), a
//! separation (`Ê_j = 0`), a recompression while loaded, a contact joining, a slip halting,
//! a stick breaking — are located on the step's dense output (on a series step, each
//! function is a polynomial of the step, `series/watched.rs`; on a DOP853 step, its
//! seventh-order extension) and the path goes on from the solution there (`events.rs`,
//! `path.rs`); a series step in which an event's function rises above zero and falls back
//! (a slip that halts and would resume the same way) is shortened to where it is above zero,
//! so the event is seen. A primary switch is located on the dense output too.
//!
//! **Phases in closed form.** Where the contacts that carry a force load in fixed
//! proportions — one contact alone (the striking corner of a rocking block, the first ball
//! of a cradle, the last contact still loaded), or several moving as one (a rod or a block
//! landing flat) — the path has one degree of freedom: the velocities are linear and the
//! energies quadratic in the normal impulse, as with one contact, and every event is the
//! root of a linear or quadratic function. Such a phase is taken in closed form from its start
//! to its first event, and the integration takes over where the proportions stop holding
//! (`closed.rs`: the conditions, checked to round-off, and the formulas). At the impact's
//! start this is done only for a phase that reaches a quarter of its compression's deflection
//! (one ending earlier, at a contact joining, would leave the integration next to the start's
//! singular point).
//!
//! **The end.** The impact ends when every contact is off (separated, or never engaged) and
//! none approaches. Two more ends are recognised: the impact has **settled** when every
//! contact still loaded is at rest to [`SETTLED`] of the largest `|v⁻_i|` and holds less
//! energy than would move it by that much (a geometric tail of ever smaller exchanges, three
//! nearly plastic contacts pressing on one another, is cut there, the energy left lost); it is
//! **jammed** when the loaded contacts are at rest with their forces balanced and energy held
//! (only possible with redundant contacts, `W` singular, wedged by friction): no finite
//! impulse ends it, and it is reported as [`BreakdownReason::Jammed`]. Past [`MAX_STEPS`]
//! integration steps, [`BreakdownReason::TooManySteps`] (a contact chattering on another
//! that keeps loading it, thousands of micro-impacts: about 0.4% of the random problems of the
//! tests, most with `W` singular).
//!
//! **Energy.** `T + Σ_j Ê_j` never increases along the path: in compression the stored energy
//! is the normal work done, in expansion the work is `e_j²` times the energy released, and
//! Coulomb friction does negative work. So `ΔT ≤ 0` up to the integration's error; a gain is
//! flagged only beyond the disagreement of `½ (v⁻ + v⁺)·p` and the contacts' works summed (as
//! for the spatial Darboux–Keller laws). Each contact's work is split by the sign of `v_nj`
//! (compression, restitution) and friction.
//!
//! **Accuracy.** Velocities after to about `1e-12` relative (Newton's cradles against an
//! independent integration of the chain in the balls' own coordinates, to `2e-12`); up to
//! `1e-8` where two contacts separate within a hair of each other (the regularising variable
//! serves one). The rod landing flat and Housner's block, taken in closed form, to
//! round-off.
//!
//! **With one contact** the law is `energetic` exactly (the path in `p_n` is the
//! Darboux–Keller one and the bi-stiffness restitution is Stronge's): [`resolve`] takes its
//! closed form, whatever `κ` and `η`, and reports `steps = 0`.
//!
//! ```
//! use impax::multi::{lzb, MultiDetail, MultiProblem};
//! // Newton's cradle, three equal balls (m = 1) touching, e = 1, frictionless: the second
//! // contact starts at v_n = 0 and joins; Hertz contacts let a little of the impulse back.
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[2.0, 0.0, 0.0, 0.0, /**/ 2.0, 0.0, -1.0, /**/ 2.0, 0.0, /**/ 2.0],
//!     &[0.0, -1.0, 0.0, 0.0],
//!     &[0.0],
//!     &[1.0],
//! )
//! .unwrap();
//! let out = lzb::resolve(&p).unwrap();
//! let (p1, p2) = (out.contacts[0].impulse.y, out.contacts[1].impulse.y);
//! let balls = [1.0 - p1, p1 - p2, p2]; // velocities after, ball 1 at 1 before
//! assert!((balls[0] + 0.0709523537).abs() < 1e-9);
//! assert!((balls[1] - 0.0764030391).abs() < 1e-9);
//! assert!((balls[2] - 0.9945493146).abs() < 1e-9);
//! assert!(out.energy_change.abs() < 1e-10); // elastic: energy kept
//! let MultiDetail::Lzb { primaries, .. } = &out.detail else { unreachable!() };
//! assert_eq!(primaries[0].contact, 0); // the first contact struck starts as the primary
//! ```

mod closed;
pub(in crate::multi) mod common;
mod events;
mod field;
mod friction;
mod path;
mod series;
mod state;
mod stepper;
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
    crate::multi::within(law, k, MAX_CONTACTS)?;
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
    let finite = out.is_finite();
    crate::multi::finite_or_overflow(law, out, finite)
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
        phases: crate::multi::Phases::new(),
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
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

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
