//! Event-driven simulation of bodies and mechanisms with impacts and contacts that stay
//! closed.
//!
//! The smooth motion is integrated to tolerance ([`crate::ode::Dopri5`] on the equations of
//! motion of [`crate::mechanism::dynamics`]); each open contact's gap `φ_k(q)` is watched on
//! the step's dense output (at eight equal parts of the step, and more where a contact could
//! touch unseen between two of them: `watch`), and a crossing with approach is located *on
//! the discrete solution* (re-stepping from the start of the step that contains it) to
//! round-off by bracketing root finding. Then:
//!
//! * **impacts** (`impacts`): a contact that strikes alone gets the run's law
//!   on its contact problem ([`crate::mechanism::impact`]); one that strikes while others touch
//!   their surfaces (closed contacts, or contacts arriving together: a rod landing flat, a
//!   rocking block's corner, a cradle's touching balls) gets the impact at all of them at once
//!   ([`crate::multi::MultiImpact`]), under the run's law if it is a multi-contact law and
//!   under `lcp` otherwise (each [`ImpactRecord`] says which);
//! * **contacts that stay closed**: a contact left touching with zero normal velocity (a
//!   plastic impact, a bounce lower than the touching tolerance, an accumulation of impacts, a
//!   contact pressed into its surface) is closed; the motion is integrated with the forces of
//!   the closed contacts from the acceleration-level contact problem ([`closed`]: normal
//!   complementarity, Coulomb sliding and sticking, solved exactly by enumerating the
//!   contacts' regimes), projected back onto the contacts after every step. Events: a normal
//!   force vanishes (the contact opens), a slip halts (stick or reversal), a stick's friction
//!   reaches `μ λ_n` (slip), another contact strikes;
//! * **accumulation (Zeno):** when the intervals between impacts shrink geometrically (three
//!   equal ratios `r < 1` in a row) and the rest of the series is below the output
//!   resolution, the sequence is summed, `t∞ = t_k + Δt_k r/(1 − r)`, and the contacts of the
//!   last impacts are closed at `t∞` with zero normal velocity (the standard completion of a
//!   Zeno sequence; e.g. Goebel, Sanfelice & Teel, *Hybrid Dynamical Systems*, 2012, and the
//!   bouncing ball's `t∞ = t₁ + 2 e v₁ / (g (1 − e))`);
//! * **a round body on a horizontal floor** (see
//!   [`crate::mechanism::Mechanism::round_on_floor`]) slides with Coulomb friction,
//!   `ṡ = −μ g sign(s) (1 + m r²/I)` for the slip `s = ẋ + r θ̇`, until it rolls, then rolls at
//!   constant speed (closed form);
//! * **rest** ([`StopReason::Rest`]): every body still, to round-off of the run's speeds, with
//!   closed contacts whose forces balance gravity;
//! * **Painlevé** ([`StopReason::Painleve`]): the force problem of the closed contacts has no
//!   solution or several, or a sliding contact reaches the bound where its force grows without
//!   bound — the run stops there rather than integrate through.
//!
//! Every impact is recorded with its energy ledger: `ΔT`, its split into normal and friction
//! work (the law's) and into translational and rotational parts (from the bodies'
//! velocities), and the total mechanical energy `T + V` before and after; the run's
//! [`Ledger`] closes `T + V` at the end against the impacts, the work of the contact forces
//! and the projections.
//!
//! ```
//! use impax::simulation::{scenarios::rod_drop, simulate, SimulationOptions, StopReason};
//! use impax::LawId;
//! // A unit rod dropped flat from 0.5 m (μ = e = 0.5): both ends strike at once (one impact,
//! // under lcp since energetic takes one contact), bounce, and the rod comes to rest lying flat.
//! let init = rod_drop(1.0, 1.0, 0.0, 0.5, 9.81)?;
//! let options = SimulationOptions::new(LawId::Energetic, 0.5, 0.5, 3.0);
//! let run = simulate(&init.mechanism, &init.q, &init.u, &options)?;
//! assert_eq!(run.impacts[0].contacts, vec![0, 1]);
//! assert_eq!(run.impacts[0].law, LawId::Lcp);
//! assert_eq!(run.stop, StopReason::Rest);
//! let last = run.samples.last().unwrap();
//! assert!(last.q[1].abs() < 1e-12 && last.q[2].abs() < 1e-12); // y = 0, θ = 0
//! assert!(run.ledger.residual().abs() < 1e-12 * run.ledger.initial);
//! # Ok::<(), impax::Error>(())
//! ```

pub mod closed;
mod contact;
pub(crate) mod events;
mod impacts;
mod options;
mod record;
mod run;
pub mod scenarios;
pub(crate) mod watch;

pub use closed::{Regime, FORCE_ROUND_OFF, MAX_CLOSED};

/// The integrator steps (accepted and rejected) a whole run may take. After its first
/// thousand steps a run whose pace projects more than twice as many (a mechanism spinning at
/// 10⁷ rad/s) is refused at once, naming `until` — not after the whole budget.
pub const SIMULATION_MAX_STEPS: usize = 1_000_000;
pub use options::SimulationOptions;
pub use record::{EventKind, ImpactRecord, Ledger, Mode, Run, Sample, StopReason};
pub use run::simulate;
