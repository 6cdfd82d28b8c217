//! Event-driven free flight of a spatial multibody under gravity, with impacts at its
//! contacts — the spatial counterpart of [`crate::simulation`], with its design and, where
//! they fit, its records.
//!
//! * **Flight.** The state `y = (q, u)` follows `q̇ = Q(q) u` ([`super::configuration_rate`]:
//!   `q̇ = u` for hinges and sliders, `ẋ = v` and `q̇_quat = ½ (0, ω) ⊗ q_quat` for a free
//!   joint, `ω` in the world frame) and `M(q) u̇ = −(C(q, u) u + g(q))`
//!   ([`super::forward_dynamics_in`]), integrated by Dormand–Prince 5(4)
//!   ([`crate::ode::Dopri5`], tolerances of the options). After every accepted step each free
//!   joint's quaternion is renormalised (the rotation `R(q)` is homogeneous in the quaternion,
//!   so this changes no pose and no energy; the integrator restarts from the renormalised
//!   state with its step size) and the largest correction is reported
//!   ([`Run::quaternion_drift`]).
//! * **Events.** Every contact's gap `φ_k(q) = z_k − h` is watched on each step's dense output
//!   (eight equal parts and the sample times); a fall through zero is located *on the discrete
//!   solution* (re-stepping from the start of the step) by bracketing root finding, to within
//!   `2ε` of the time.
//! * **Impacts.** A contact that reaches the floor approaching (`φ̇ < 0` beyond round-off of
//!   the run's speeds) strikes. Alone, the run's law resolves it
//!   ([`super::SpatialMechanismImpact`]); when other contacts touch the floor at that instant
//!   (gap within the touching tolerance, `10⁻¹² ℓ` plus round-off of the positions, `ℓ` the
//!   contact's lever or the model's size), the impact is at all of them at once
//!   ([`super::SpatialMechanismMultiImpact`]) under the run's law if it is a multi-contact law
//!   (`lcp`, `sequential`, `lzb`), else under `lcp` — as the planar run does. The speeds
//!   jump to `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
//! * **Persistent contact.** Contacts that stay closed in 3D (the acceleration-level contact
//!   problem with the circular friction cone) are not modelled. When a contact would stay on
//!   the floor — an impact leaves it with zero normal velocity and pressed
//!   ([`Persistence::Closed`]), its bounce `φ̇²/(2|φ̈|)` is below the touching tolerance
//!   ([`Persistence::LowBounce`]), its impacts accumulate with a steady interval ratio
//!   ([`Persistence::Accumulation`], the planar run's test: `t∞ = t_k + Δt_k r/(1 − r)`), or it
//!   touches at rest pressed into the floor ([`Persistence::Pressed`]) — the run stops with
//!   [`StopReason::PersistentContact`], naming the contact, at that instant: no state is
//!   integrated through the floor.
//! * **The energy ledger** ([`Ledger`]): `T + V` at the start, the laws' `ΔT` summed over the
//!   impacts, the integration's drift of `T + V` over the flights (measured), and `T + V` at
//!   the end; `end = initial + impacts + drift` to round-off.
//!
//! ```
//! use impax::multibody::simulate::{simulate, Persistence, StopReason};
//! use impax::multibody::{Body, ContactPoint, Joint, Model};
//! use impax::math::{Mat3, Vec3};
//! use impax::simulation::SimulationOptions;
//! use impax::LawId;
//! // A ball (m = 1, r = 0.1) dropped from 1 m onto the floor z = 0 with e = 0.8: its
//! // bounces shrink by e, and their accumulation ends the run.
//! let ball = Body::new("ball", 1.0, Vec3::zeros(), Mat3::identity() * 0.004);
//! let bottom = ContactPoint::new("bottom", 0, Vec3::zeros(), 0.1);
//! let model = Model::new(vec![ball], vec![Joint::free("root", 0)], vec![bottom])?;
//! let q = [0.0, 0.0, 1.1, 1.0, 0.0, 0.0, 0.0];
//! let run = simulate(&model, &q, &[0.0; 6], &SimulationOptions::new(LawId::Energetic, 0.3, 0.8, 5.0))?;
//! let v: Vec<f64> = run.impacts.iter().map(|i| i.u_after[2]).collect();
//! assert!((v[1] / v[0] - 0.8).abs() < 1e-12);
//! assert!(matches!(
//!     run.stop,
//!     StopReason::PersistentContact { contact: 0, cause: Persistence::Accumulation { .. } }
//! ));
//! assert!(run.ledger.residual().abs() < 1e-12 * run.ledger.initial);
//! # Ok::<(), impax::Error>(())
//! ```

mod impact;
mod motion;
mod record;
mod run;

pub use crate::simulation::{EventKind, Mode, Sample, SimulationOptions};
pub use record::{ImpactRecord, Ledger, Persistence, Run, StopReason};

use crate::error::{Error, Num, Result};
use crate::ode::Dopri5;
pub(crate) use motion::renormalise;
use motion::{Equations, Geometry};
use run::Sim;

use super::{contact_jacobian, Model, Workspace};

/// Largest number of integrator steps (accepted and rejected) [`simulate`] takes over the
/// whole run. It gives up earlier, after a thousand steps, when the pace so far projects more
/// than twice as many (a state spinning at 10⁷ rad/s fails at once, not after minutes). The
/// error names `until`.
pub const SIMULATION_MAX_STEPS: usize = 200_000;

/// Simulate `model` from `(q0, u0)` at `t = 0` until `options.until`, or a stop (see the
/// [module docs](self)).
///
/// Every contact of the model is watched. The run's law must have a spatial form
/// ([`crate::LawId::is_spatial`]). The first sample is the initial state, the last the state
/// at the stop; no sampled state has a contact below the floor by more than its touching
/// tolerance (up to the dense output's error, of the integrator's tolerance).
///
/// # Errors
/// Invalid state or options (each naming its field); a law without a spatial form; a contact
/// starting below the floor; a singular mass matrix or a failed integration along the way; a
/// run that needs more than [`SIMULATION_MAX_STEPS`] steps (or whose pace projects more than
/// twice as many), naming `until`.
pub fn simulate(model: &Model, q0: &[f64], u0: &[f64], options: &SimulationOptions) -> Result<Run> {
    let q0 = model.check_state(q0, Some(u0))?;
    options.validate()?;
    if !options.law.is_spatial() {
        return Err(Error::Invalid {
            field: "law".into(),
            reason: format!(
                "`{}` is defined for planar impacts only (spatial laws: {}, sequential, lzb)",
                options.law,
                crate::LawId::SPATIAL.map(|l| l.as_str()).join(", ")
            ),
        });
    }
    let (nq, nv) = (model.nq(), model.nv());
    let mut y: Vec<f64> = q0.iter().chain(u0).copied().collect();
    let mut eq = Equations::new(model);
    eq.try_derivative(&y, &mut vec![0.0; nq + nv])?;
    let mut geo = Geometry::new(model);
    let e0 = geo.energy(&y)?;
    if !(e0.is_finite() && e0.abs() < 1e300) {
        return Err(Error::OutOfRange {
            field: "q".into(),
            value: e0,
            reason: "the energy T + V of the initial state is not representable with room for the motion (it must be below 1e300)".into(),
        });
    }
    for k in 0..model.contacts().len() {
        let g = geo.gap(&y, k);
        if g < -geo.touching_tolerance(&y, k) {
            return Err(Error::Invalid {
                field: "q".into(),
                reason: format!(
                    "the contact {} starts below the floor z = {} (gap {})",
                    model.contacts()[k].name,
                    Num(model.floor()),
                    Num(g)
                ),
            });
        }
    }
    let vscale = speed_scale(model, &q0, u0)?;
    motion::renormalise(model, &mut y[..nq]);
    let sim = Sim {
        model,
        opt: *options,
        eq,
        geo,
        ode: Dopri5::new(nq + nv, options.tolerances)?,
        t: 0.0,
        y,
        samples: Vec::new(),
        next: 1,
        impacts: Vec::new(),
        events: Vec::new(),
        ledger: Ledger {
            initial: e0,
            ..Ledger::default()
        },
        flight_energy: e0,
        series: Vec::new(),
        vscale,
        quaternion_drift: 0.0,
    };
    sim.run()
}

/// The run's speed scale: the contacts' speeds `|J u|` at the start and the speed `√(g ℓ)` of
/// a fall through each contact's lever `ℓ` (its distance from its body's frame origin, or the
/// model's size).
fn speed_scale(model: &Model, q: &[f64], u: &[f64]) -> Result<f64> {
    let mut ws = Workspace::new(model);
    ws.update(model, q)?;
    let mut scale = f64::MIN_POSITIVE;
    for k in 0..model.contacts().len() {
        let j = contact_jacobian(model, &ws, k)?;
        let v = &j * nalgebra::DVector::from_column_slice(u);
        let lever = model.contacts()[k].point.norm() + model.contacts()[k].radius;
        let lever = lever.max(model.data.size);
        scale = scale.max(v.norm()).max((model.gravity() * lever).sqrt());
    }
    Ok(scale)
}
