//! The event-driven simulation loop: flight, impacts, contacts that stay closed.
//!
//! This file holds the run's state and its loop; the stages are methods in their own files:
//! one step of the motion with its events (`step`), an impact and what follows it (`impact`),
//! and which contacts stay closed (`settle`).

mod impact;
mod settle;
mod step;

use super::closed::{self, Closed};
use super::record::{EventKind, ImpactRecord, Ledger, Mode, Recorder, Run, StopReason};
use super::SimulationOptions;
use crate::error::{Error, Result};
use crate::mechanism::dynamics::{self, check_state};
use crate::mechanism::{Mechanism, Pose};
use crate::ode::Dopri5;

/// Relative round-off of velocities: a normal velocity within this fraction of the run's
/// speed scale is zero (a contact that neither approaches nor leaves).
const VELOCITY_ROUND_OFF: f64 = 1e-9;

/// Points of each step's dense output at which the gaps and the closed contacts' forces are
/// watched (with the sample times inside the step).
const PARTS: usize = 8;

/// The most events in a row at one instant before the run is declared stalled.
const STALL: usize = 64;

/// The contacts that touch their surfaces at `q` (gap within
/// [`dynamics::touching_tolerance`]).
fn touching<M: Mechanism + ?Sized>(m: &M, q: &[f64]) -> Vec<usize> {
    (0..m.contacts().len())
        .filter(|&j| dynamics::gap(m, j, q) <= dynamics::touching_tolerance(m, j, q))
        .collect()
}

/// `T + V` at `y`.
fn energy<M: Mechanism + ?Sized>(m: &M, y: &[f64]) -> f64 {
    let n = m.dof();
    dynamics::kinetic_energy(m, &y[..n], &y[n..2 * n]) + dynamics::potential_energy(m, &y[..n])
}

/// `|T₀| + |V₀|` (the energies at the start) rounded to a power of two (1 if it is zero or
/// not finite).
fn energy_scale(kinetic: f64, potential: f64) -> f64 {
    let e = kinetic.abs() + potential.abs();
    if e.is_finite() && e > 0.0 {
        2f64.powi(e.log2().round() as i32)
    } else {
        1.0
    }
}

/// The right-hand side of the motion with the closed contacts `closed`, the contact forces'
/// work integrated in units of `wscale` (the run's energy scale, a power of two: the work is
/// then judged by the integrator's tolerances relative to the energy of the motion, whatever
/// the units of mass).
fn rhs<'a, M: Mechanism + ?Sized>(
    m: &'a M,
    closed: Vec<Closed>,
    mu: f64,
    wscale: f64,
) -> impl FnMut(f64, &[f64], &mut [f64]) + 'a {
    move |_t, y, dy| {
        closed::derivative(m, &closed, mu, y, dy);
        if let Some(w) = dy.last_mut() {
            *w /= wscale;
        }
    }
}

/// Where the run is.
struct Sim<'a, M: Mechanism + ?Sized> {
    m: &'a M,
    opt: SimulationOptions,
    n: usize,
    rec: Recorder<'a, M>,
    impacts: Vec<ImpactRecord>,
    events: Vec<(f64, EventKind)>,
    ledger: Ledger,
    /// Impact times and their contacts since the last change of regime (accumulation).
    series: Vec<(f64, Vec<usize>)>,
    closed: Vec<Closed>,
    t: f64,
    /// `(q, u, w)`: `w` the work of the contact forces.
    y: Vec<f64>,
    ode: Dopri5,
    /// The largest contact speed of the run (and `√(g L)`, `L` the largest lever).
    vscale: f64,
    /// The energy scale `|T₀| + |V₀|` as a power of two (1 if zero): the unit of the
    /// integrated work of the contact forces (`y[2n]`).
    wscale: f64,
    /// Events at the current instant (a guard against endless switching).
    stall: (f64, usize),
    /// The end time and energy of a round body's closed form that ended the run.
    rolled: Option<(f64, f64)>,
}

/// Simulate `m` from `(q0, u0)` at `t = 0` until `options.until` (or a stop).
///
/// Every contact of the mechanism is watched (both ends of a rod, a double pendulum's tip and
/// elbow, a block's corners). An impact at one contact applies the run's law; at several at
/// once (a contact striking while others touch) the multi-contact impact (`MultiImpact`; see
/// the [module docs](super)). Contacts left touching with zero normal velocity — a plastic
/// impact, a bounce below the touching tolerance, an accumulation of impacts completed, a contact
/// pressed into its surface — stay closed: the motion is integrated with their forces, which
/// the acceleration-level contact problem gives ([`super::closed`]), until a force vanishes (the
/// contact opens), a slip halts (stick or reversal), a stick fails (slip), or another contact
/// strikes. A round body on a horizontal floor slides and rolls in closed form instead. The
/// run stops at rest ([`StopReason::Rest`]), at Painlevé's paradox ([`StopReason::Painleve`]),
/// or where the laws do not apply. No sampled state has a contact below its surface by more
/// than [`dynamics::touching_tolerance`]; the last sample is the state at the stop.
///
/// # Errors
/// Invalid state or options; a start below a surface; a singular mass matrix or a failed
/// integration along the way; contact regimes that switch endlessly at one instant.
pub fn simulate<M: Mechanism + ?Sized>(
    m: &M,
    q0: &[f64],
    u0: &[f64],
    options: &SimulationOptions,
) -> Result<Run> {
    check_state(m, q0, Some(u0))?;
    dynamics::check_precision(m, q0)?;
    options.validate()?;
    dynamics::accelerations(m, q0, u0)?;
    let n = m.dof();
    let contacts = m.contacts().len();
    let (t0, v0) = (
        dynamics::kinetic_energy(m, q0, u0),
        dynamics::potential_energy(m, q0),
    );
    let e0 = t0 + v0;
    if !(e0.is_finite() && e0.abs() < 1e300) {
        return Err(Error::OutOfRange {
            field: "q".into(),
            value: e0,
            reason: "the energy T + V of the initial state is not representable with room for the motion (it must be below 1e300)".into(),
        });
    }
    for k in 0..contacts {
        let g = dynamics::gap(m, k, q0);
        if g < -dynamics::touching_tolerance(m, k, q0) {
            return Err(Error::Invalid {
                field: "q".into(),
                reason: format!(
                    "the {} starts below its surface (gap {})",
                    m.contacts()[k].name,
                    crate::error::Num(g)
                ),
            });
        }
    }
    // The speed scale: the contacts' speeds and the speed of a fall through a lever.
    let mut vscale = f64::MIN_POSITIVE;
    {
        let kin = dynamics::kinematics(m, q0);
        let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
        m.poses(q0, &mut poses);
        for k in 0..contacts {
            let j = dynamics::contact_jacobian_of(m, k, q0, &kin);
            let v = &j * nalgebra::DVector::from_column_slice(u0);
            let c = m.contact_point(k, q0);
            let b = poses[m.contacts()[k].body];
            let lever = (c[0] - b.x).hypot(c[1] - b.y);
            vscale = vscale.max(v.norm()).max((m.gravity() * lever).sqrt());
        }
    }
    let mut y: Vec<f64> = q0.iter().chain(u0).copied().collect();
    y.push(0.0);
    let mut sim = Sim {
        m,
        opt: *options,
        n,
        rec: Recorder {
            m,
            dt: options.sample_interval,
            next: 1,
            samples: Vec::new(),
        },
        impacts: Vec::new(),
        events: Vec::new(),
        ledger: Ledger {
            initial: e0,
            ..Ledger::default()
        },
        series: Vec::new(),
        closed: Vec::new(),
        t: 0.0,
        y,
        ode: Dopri5::new(2 * n + 1, options.tolerances)?,
        vscale,
        wscale: energy_scale(t0, v0),
        stall: (0.0, 0),
        rolled: None,
    };
    sim.rec.push(0.0, &sim.y, Mode::Flight);
    sim.run()
}

/// How a new set of closed contacts came about.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cause {
    /// The start, an impact or a contact pressed into its surface.
    Contact,
    /// A change of the closed contacts' forces or slips (the openings are recorded).
    Event,
}

impl<M: Mechanism + ?Sized> Sim<'_, M> {
    fn q(&self) -> &[f64] {
        &self.y[..self.n]
    }
    fn u(&self) -> &[f64] {
        &self.y[self.n..2 * self.n]
    }
    fn tol_v(&self) -> f64 {
        VELOCITY_ROUND_OFF * self.vscale
    }
    fn mode(&self) -> Mode {
        if self.closed.is_empty() {
            Mode::Flight
        } else {
            Mode::Contact
        }
    }

    fn run(mut self) -> Result<Run> {
        let m = self.m;
        let n = self.n;
        // A contact touching at the start: struck at t = 0 if it approaches; the others that
        // touch without leaving may stay closed.
        let mut pending: Option<usize> = None;
        for k in touching(m, self.q()) {
            if dynamics::gap_rate(m, k, self.q(), self.u()) < 0.0 {
                pending = Some(k);
                break;
            }
        }
        if pending.is_none() {
            if let Some(stop) = self.settle_touching()? {
                return Ok(self.finish_at(stop));
            }
        }
        self.start(self.opt.until)?;
        loop {
            if let Some(k) = pending.take() {
                if let Some(stop) = self.arrive(k)? {
                    return Ok(self.finish_at(stop));
                }
            }
            if self.t >= self.opt.until {
                let (t, e) = (self.t, energy(m, &self.y));
                return Ok(self.finish(StopReason::TimeLimit, t, e));
            }
            match self.advance()? {
                Advance::Free => {}
                Advance::Arrival(k) => pending = Some(k),
                Advance::Stop(stop) => return Ok(self.finish_at(stop)),
            }
            debug_assert_eq!(self.y.len(), 2 * n + 1);
        }
    }

    /// (Re)start the integrator at the current state, the first step within `span`.
    fn start(&mut self, span: f64) -> Result<()> {
        let mut f = rhs(self.m, self.closed.clone(), self.opt.friction, self.wscale);
        let span = span.min(self.opt.until - self.t).max(f64::MIN_POSITIVE);
        self.ode.start(&mut f, self.t, &self.y, span)
    }

    /// Contact `k` reaches its surface at the current state: an impact if it approaches,
    /// else its contact may close.
    fn arrive(&mut self, k: usize) -> Result<Option<StopReason>> {
        let m = self.m;
        let v_k = dynamics::gap_rate(m, k, self.q(), self.u());
        if v_k < -self.tol_v() && !(self.closed.iter().any(|c| c.contact == k)) {
            if let Some(stop) = self.impact(k)? {
                return Ok(Some(stop));
            }
        } else if let Some(stop) = self.settle_touching()? {
            return Ok(Some(stop));
        }
        // Bound the first step by a quarter of the coming flight of contact k (`2 φ̇ / |φ̈|`),
        // so that a short bounce is resolved by the step sampling.
        let (q, u) = (self.q(), self.u());
        let acc = dynamics::accelerations(m, q, u)?;
        let [_, rate, accel] = dynamics::gap_rates(m, k, q, u, acc.as_slice());
        let flight = if accel < 0.0 && rate > 0.0 && !self.closed.iter().any(|c| c.contact == k) {
            2.0 * rate / -accel
        } else {
            f64::INFINITY
        };
        self.start(0.25 * flight)?;
        Ok(None)
    }

    /// The end of a run at the current state, recorded as its last sample (so that the run's
    /// final energy is the state's at the stop).
    fn finish_at(mut self, stop: StopReason) -> Run {
        if let Some((end, e)) = self.rolled {
            return self.finish(stop, end, e);
        }
        let mode = if stop == StopReason::Rest {
            Mode::Rest
        } else {
            self.mode()
        };
        self.rec.push(self.t, &self.y, mode);
        let (t, e) = (self.t, energy(self.m, &self.y));
        self.finish(stop, t, e)
    }

    /// The end of a run.
    fn finish(mut self, stop: StopReason, end_time: f64, end_energy: f64) -> Run {
        self.ledger.end = end_energy;
        self.ledger.contact_work += self.y[2 * self.n] * self.wscale;
        Run {
            samples: self.rec.samples,
            impacts: self.impacts,
            events: self.events,
            stop,
            end_time,
            steps: (self.ode.accepted, self.ode.rejected),
            ledger: self.ledger,
        }
    }
}

/// What a step ended with.
enum Advance {
    /// Go on.
    Free,
    /// Contact `k` reached its surface at the current state.
    Arrival(usize),
    /// The run ends at the current state.
    Stop(StopReason),
}
