//! Event-driven simulation of bodies and mechanisms with impacts.
//!
//! The smooth motion between impacts is integrated to tolerance ([`crate::ode::Dopri5`] on
//! the equations of motion of [`crate::mechanism::dynamics`]); each contact's gap `φ_k(q)` is
//! watched on the step's dense output, and a crossing with approach is located *on the
//! discrete solution* (re-stepping from the start of the step that contains it) to round-off
//! by bracketing root finding; the chosen impact law is applied to the mechanism's contact
//! problem ([`crate::mechanism::impact`]), and the motion resumes. Then:
//!
//! * **accumulation (Zeno):** when the intervals between impacts at one contact shrink
//!   geometrically (three equal ratios `r < 1` in a row) and the rest of the series is below
//!   the output resolution, the sequence is summed, `t∞ = t_k + Δt_k r/(1 − r)`, and the body
//!   is put in persistent contact at `t∞` with zero normal velocity (the standard completion
//!   of a Zeno sequence; e.g. Goebel, Sanfelice & Teel, *Hybrid Dynamical Systems*, 2012, and
//!   the bouncing ball's `t∞ = t₁ + 2 e v₁ / (g (1 − e))`);
//! * **persistent contact:** a round body on a horizontal floor (see
//!   [`crate::mechanism::Mechanism::round_on_floor`]) slides with Coulomb friction,
//!   `ṡ = −μ g sign(s) (1 + m r²/I)` for the slip `s = ẋ + r θ̇`, until it rolls, then rolls
//!   at constant speed (closed form); any other body stops with
//!   [`StopReason::PersistentContact`], a regime this simulator does not model;
//! * **rest:** a round body with neither slip nor speed left stops with [`StopReason::Rest`].
//!
//! Every impact is recorded with its energy ledger: `ΔT`, its split into normal and friction
//! work (the law's) and into translational and rotational parts (from the bodies'
//! velocities), and the total mechanical energy `T + V` before and after.

mod contact;
mod run;
pub mod scenarios;

pub use run::{
    simulate, EventKind, ImpactRecord, Mode, Run, Sample, SimulationOptions, StopReason,
};
