//! `lzb` in 3D: the multiple-impact law of Liu, Zhao & Brogliato at `K` spatial contacts —
//! every contact a compliant element that stores energy, the impulses distributed by the
//! contacts' force law, energetic restitution and Coulomb friction with the circular cone at
//! each contact, the slip directions turning (swirl) as the impact proceeds.
//!
//! C. Liu, Z. Zhao & B. Brogliato, *Frictionless multiple impacts in multibody systems. I.
//! Theoretical framework*, Proc. R. Soc. A 464 (2008) 3193–3211, doi 10.1098/rspa.2008.0078;
//! *II. Numerical algorithm and simulation results*, Proc. R. Soc. A 465 (2009) 1–23, doi
//! 10.1098/rspa.2008.0079; friction (in the plane): Z. Zhao, C. Liu & B. Brogliato, *Planar
//! dynamics of a rigid body system with frictional impacts*, Proc. R. Soc. A 465 (2009).
//! The spatial slip at one contact is Keller's (*Impact with friction*, J. Appl. Mech. 53
//! (1986) 1), as in [`crate::spatial::darboux_keller`].
//!
//! ## The model
//!
//! The planar law's ([`crate::multi::lzb`]: the normal model, the energetic restitution, the
//! events, the ends, the primary contact, all as there) with each contact's tangential
//! velocity and impulse 2-vectors. Integrated in the contact-force time `τ`
//! (`dp_nj = F_j dτ`), each contact's deflection `s_j` in the state
//! (`F_j = κ_j s_j^η`, `Ê_j = κ_j s_j^(η+1)/(η+1)`):
//!
//! ```text
//! ds_j/dτ = −v_nj (compression),  −v_nj / e_j² (expansion),  0 (off),
//! dp_nj/dτ = κ_j s_j^η,
//! dp_tj/dτ = −μ_j F_j ŝ_j,  ŝ_j = v_tj/|v_tj|          (slip)
//!          = x_j,  W_SS^tt x_S = −r_S, least norm          (stick: v_tj held),
//! v = v⁻ + W p      (W: 3K × 3K, rows t1, t2, n of each contact).
//! ```
//!
//! **Friction** (`friction.rs`): a sliding contact's friction opposes its slip, whose
//! direction turns as the impact proceeds (the other contacts' impulses and its own
//! friction change `v_tj`); the sticking contacts `S` take the tangential impulse rates
//! (two each) that keep their `v_t` fixed, least-norm when `W_SS^tt` is singular (redundant
//! contacts), accepted while `|x_j| ≤ μ_j F_j` (the circular cone); a stick that breaks
//! slips the way its tangential velocity then goes: along the centrifugal invariant ray of
//! its slip field `a_j(d) = c_j − μ_j F_j M_j d` (every other contact as it is; `M_j` the
//! Schur complement of the stick set in `W`'s tangential block), `(λ I + μ_j F_j M_j) d =
//! c_j`, `λ > 0` — the one-contact law's resumed slip
//! ([`crate::spatial::resumption_direction`]). Where several contacts are at rest at once,
//! every assignment of stick and slip is tried, most sticks first (the slips along their
//! coupled rays), the first consistent one taken.
//!
//! ## A slip that halts
//!
//! As `σ_j = |v_tj| → 0` the direction field of contact `j`'s slip is singular
//! (`dŝ_j/dτ = (I − ŝ_j ŝ_jᵀ) a_j / σ_j`, `a_j = dv_tj/dτ`) and the direction converges to
//! a centripetal invariant ray of the slip field as a power of the slip (`φ − φ* ∝ σ^λ`,
//! `λ` the ray's attraction: the one-contact law's `ray_series.rs`): in `τ` the path has a
//! branch point at the halt, and an explicit integrator's steps must shrink with the
//! distance to it. impax takes the halt in three pieces (`variable.rs`, `record.rs`,
//! `friction.rs`):
//!
//! 1. **the approach**: in `τ`; while the direction turns (`|ŝ_j × a_j| > 10⁻⁶ |a_j|`),
//!    the slip shrinks steadily (`ŝ_j·a_j < −½|a_j|`) and its halt is predicted within four
//!    steps, in `x = ln σ_j`, decreasing (`dτ/dx = σ_j/(ŝ_j·a_j)`), in which the path is
//!    smooth (the one-contact law's `log_sigma.rs`, the other contacts integrated
//!    alongside): its steps are e-folds of the slip;
//! 2. **the ray**: at the end of every step, a slip whose halt is predicted within four
//!    steps (or below [`NEAR`]` · max_i |v⁻_i|`) is compared with the centripetal ray its
//!    direction turns towards — of its slip field with every other contact as it is,
//!    `a_j(d) = c_j − μ_j F_j M_j d`, the one-contact field with `w_tn → c_j/F_j`,
//!    `W_tt → M_j` (its rays by the one-contact law's quartic, polished by Newton's method,
//!    or by Newton's method from the ray found at the last comparison). It goes on along
//!    the ray once
//!    ```text
//!    σ_j (δ + |Δφ*| σ_j/(σ' − σ_j)) ≤ σ_f = FREEZE · max_i |v⁻_i|,
//!    ```
//!    `δ` the angle between its direction and the ray, `Δφ*` the turn of the ray since the
//!    last comparison (at the slip `σ'`), extrapolated over the rest of the slip; at the
//!    latest at `σ_j = 2 σ_f` (an event), along its own direction if it is not within
//!    `σ_f/σ_j` of the ray (the halt then reported on the ray);
//! 3. **the last bit**: along that fixed direction `d`, friction `−μ_j F_j d`: the
//!    right-hand side is smooth and the halt, `d·v_tj = 0`, an ordinary event located on the
//!    dense output to round-off. There the contact sticks if the cone holds its stick
//!    friction, else leaves rest along its centrifugal ray, as above; the other slips
//!    halting along fixed directions within `σ_f` of their own halts decide with it (a
//!    symmetric body's corners halt together).
//!
//! A slip that halts on a ray along a straight line (a symmetric body's: `δ` and `Δφ*` at
//! round-off) goes on along it at the first comparison, a few steps from its halt.
//!
//! **Error bound.** Only the friction of the last bit is approximate: it acts over
//! `Δτ ≈ σ_j/|ŝ·a_j|`, along `d` where the true slip's direction is within `δ` of the ray
//! and follows the ray's drift, so the velocities are off by about
//! `|a_j| Δτ (δ + drift) ≈ σ_j (δ + drift) ≤ σ_f`: `1e-11` of the largest `|v⁻_i|`,
//! whatever the ray's attraction (the drift extrapolated linearly from the last comparison:
//! an estimate, not a bound). A slip that passes within `2 σ_f` of zero without halting
//! (a near miss, which the one-contact law turns through) is halted there, off by at most
//! `2π σ_f`. Measured against the one-contact law on decoupled contacts (tests, 974
//! halts): the halts located to `5e-11` of the normal impulse, on the same ray to
//! `1e-15` rad where that law reports one (along a weakly attracting ray its direction is
//! still turning where its integration stops); impulses to `1e-10`, the integration's own
//! tolerance.
//!
//! A slip that **leaves rest** goes along its ray, fixed, until `σ_j` reaches
//! [`NEAR`]` · max_i |v⁻_i|`, then follows its own direction (at zero slip the direction is
//! not defined; the ray drifts by `O(σ/|v⁻|)` over the piece, which is off by
//! `O(NEAR²)` relative).
//!
//! **Phases in closed form** (`closed.rs`): where the contacts that carry a force load in
//! fixed proportions and every slip keeps its direction — one contact alone in stick or
//! without friction, a symmetric body's contacts moving as one, its corners slipping round
//! the vertical on straight lines — the path has one degree of freedom, the velocities
//! linear and the energies quadratic in the normal impulse, and each event the root of a
//! linear or quadratic function: such a phase is taken exactly, without integration steps,
//! at the start and after every event (the planar law's phases in closed form, with a slip
//! on a straight line taken to its halt).
//!
//! **The end, breakdowns, energy, the primary**: as in the planar law. Settled, jammed
//! ([`BreakdownReason::Jammed`]), [`BreakdownReason::TooManySteps`] beyond [`MAX_STEPS`]
//! integration steps; `T + Σ_j Ê_j` never increases along the path, a gain is flagged only
//! beyond the disagreement of `½ (v⁻ + v⁺)·p` and the contacts' works summed.
//!
//! **With one contact** the law is the spatial `energetic` (the Darboux–Keller path in
//! `p_n`, Stronge's restitution), whose closed form and series [`resolve`] takes, with
//! `steps = 0`.
//!
//! ```
//! use impax::multi::spatial::{lzb, MultiDetail, MultiProblem};
//! // A box (m = 1, half-sizes 0.5, 0.3, 0.2) landing flat on four corners at v_z = −1
//! // without spin: lzb lifts it level at e |v_z|, each corner taking a quarter of the
//! // impulse, although W (12 × 12) has rank 6. The corners move as one: the whole impact
//! // in closed form, without an integration step.
//! let bx = impax::multi::scenarios::BoxFlat { spin: 0.0, ..Default::default() };
//! let sc = bx.build().unwrap();
//! let p = sc.impact.spatial_problem(&[0.3], &[0.5]).unwrap();
//! let out = lzb::resolve(&p).unwrap();
//! for c in &out.contacts {
//!     assert!((c.velocity_after.z - 0.5).abs() < 1e-10);
//!     assert!((c.impulse.z - 1.5 / 4.0).abs() < 1e-10);
//! }
//! assert!(matches!(out.detail, MultiDetail::Lzb { steps: 0, .. }));
//! ```

mod closed;
mod events;
mod field;
mod friction;
mod path;
mod record;
mod state;
mod variable;

use super::outcome::{assemble_ending, MultiDetail};
use super::{MultiOutcome, MultiProblem, MultiResolution};
use crate::law::{Breakdown, BreakdownReason, LawId};
use crate::multi::outcome::Ending;
use crate::multi::LzbPrimary;
use state::Setup;

pub use crate::multi::lzb::{MAX_CONTACTS, MAX_STEPS};

/// A halting slip goes on along the ray it halts on once its slip times its direction's
/// angle from that ray (with the ray's drift over the rest of the slip) is below `FREEZE`
/// times the largest `|v⁻_i|`, or its slip is below twice that (module docs: the error
/// bound of the halt).
pub const FREEZE: f64 = 1e-11;

/// A slip is near rest below `NEAR` times the largest `|v⁻_i|`: a shrinking one is compared
/// with the ray it halts on at every step from there, a slip leaving rest along a fixed
/// direction follows its own direction above it.
pub const NEAR: f64 = 1e-6;

/// A stick holds while the friction it needs exceeds the cone by at most this fraction of
/// the impact's force scale (the largest force of a contact alone stopping the largest
/// `|v⁻_i|`): the round-off of the stick solve, and of a symmetric body's contacts that
/// separate a hair apart, their forces then a hair from zero and unequal.
pub const STICK_ROUND_OFF: f64 = 1e-12;

/// The relative tolerance of the integration (each component of the state, against
/// `atol + RTOL |y|`, `atol` from the scale of the contact's impulse, deflection and
/// energy).
const RTOL: f64 = 1e-12;

/// `lzb` on `K` spatial contacts (module docs). Breakdowns:
/// [`BreakdownReason::TooManyContacts`] beyond [`MAX_CONTACTS`],
/// [`BreakdownReason::TooManySteps`] beyond [`MAX_STEPS`], [`BreakdownReason::Jammed`],
/// [`BreakdownReason::Overflow`] if a number is not representable; with one contact, the
/// spatial `energetic`'s.
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lzb;
    let k = problem.contacts();
    crate::multi::within(law, k, MAX_CONTACTS)?;
    if k == 1 {
        return one_contact(problem);
    }
    let setup = Setup::new(problem);
    let end = match k {
        2 => path::run::<10>(&setup),
        3 => path::run::<15>(&setup),
        4 => path::run::<20>(&setup),
        5 => path::run::<25>(&setup),
        6 => path::run::<30>(&setup),
        7 => path::run::<35>(&setup),
        _ => path::run::<40>(&setup),
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

/// One contact: the spatial `energetic` law on the contact's block (module docs).
fn one_contact(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lzb;
    let alone = problem.contact(0).map_err(|_| Breakdown {
        law,
        reason: BreakdownReason::Overflow,
    })?;
    let o = LawId::Energetic
        .resolve(&alone)
        .map_err(|b| Breakdown { law, ..b })?;
    let mut out = MultiOutcome::from_outcome(&o);
    out.law = law;
    out.detail = MultiDetail::Lzb {
        primaries: vec![LzbPrimary {
            contact: 0,
            impulse: 0.0,
        }],
        steps: 0,
    };
    Ok(out)
}
