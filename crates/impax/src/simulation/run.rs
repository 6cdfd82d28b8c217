//! The event-driven simulation loop: flight, impacts, contacts that stay closed.

use super::closed::{self, Closed, ContactDynamics, Hint, Regime, FORCE_ROUND_OFF};
use super::contact::{roll, Rolling};
use super::events::{accumulation, gap_of, locate, watched, watched_value, Watched};
use super::impacts::{strike, Struck};
use super::record::{EventKind, ImpactRecord, Ledger, Mode, Recorder, Run, StopReason};
use super::SimulationOptions;
use crate::error::{Error, Result};
use crate::math::Vec2;
use crate::mechanism::dynamics::{self, check_state};
use crate::mechanism::{Mechanism, Pose};
use crate::ode::Dopri5;
use crate::planar::SlipDirection;

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

/// The right-hand side of the motion with the closed contacts `closed`.
fn rhs<'a, M: Mechanism + ?Sized>(
    m: &'a M,
    closed: Vec<Closed>,
    mu: f64,
) -> impl FnMut(f64, &[f64], &mut [f64]) + 'a {
    move |_t, y, dy| closed::derivative(m, &closed, mu, y, dy)
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
    let e0 = dynamics::kinetic_energy(m, q0, u0) + dynamics::potential_energy(m, q0);
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
        let mut f = rhs(self.m, self.closed.clone(), self.opt.friction);
        let span = span.min(self.opt.until - self.t).max(f64::MIN_POSITIVE);
        self.ode.start(&mut f, self.t, &self.y, span)
    }

    /// Contacts touching at the current state that neither approach nor leave, with the
    /// closed ones: they may stay closed. A round body goes to its closed form.
    fn settle_touching(&mut self) -> Result<Option<StopReason>> {
        let (m, tol) = (self.m, self.tol_v());
        let mut candidates: Vec<usize> = self.closed.iter().map(|c| c.contact).collect();
        for j in touching(m, self.q()) {
            if !candidates.contains(&j) && dynamics::gap_rate(m, j, self.q(), self.u()) <= tol {
                candidates.push(j);
            }
        }
        candidates.sort_unstable();
        if m.round_on_floor().is_some() && self.closed.is_empty() {
            // The closed form continues a round body pressed into the floor.
            if let Some(&j) = candidates.first() {
                if self.pressed(j)? {
                    return Ok(Some(self.roll(j)?));
                }
            }
            return Ok(None);
        }
        self.settle(candidates, Hint::None, Cause::Contact)
    }

    /// Contact `k` at `(q, u)` touches its surface without approaching it and is accelerated
    /// into it (`φ̇ = 0`, `φ̈ < 0`).
    fn pressed(&self, k: usize) -> Result<bool> {
        let (m, q, u) = (self.m, self.q(), self.u());
        if dynamics::gap(m, k, q) > dynamics::touching_tolerance(m, k, q) {
            return Ok(false);
        }
        let acc = dynamics::accelerations(m, q, u)?;
        let [_, rate, accel] = dynamics::gap_rates(m, k, q, u, acc.as_slice());
        Ok(rate <= 0.0 && accel < 0.0)
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

    /// The impact of contact `k` at the current state, with every contact touching.
    fn impact(&mut self, k: usize) -> Result<Option<StopReason>> {
        let (m, n) = (self.m, self.n);
        if self.impacts.len() >= self.opt.max_impacts {
            return Ok(Some(StopReason::ImpactLimit));
        }
        let others: Vec<usize> = touching(m, self.q())
            .into_iter()
            .chain(self.closed.iter().map(|c| c.contact))
            .filter(|&j| j != k)
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        let record = match strike(m, self.t, self.q(), self.u(), k, &others, &self.opt)? {
            Struck::Stop(stop) => return Ok(Some(stop)),
            Struck::Record(r) => *r,
        };
        let speed = record
            .contact_velocities_before
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        self.vscale = self.vscale.max(speed);
        self.rec.push(self.t, &self.y, self.mode());
        self.ledger.impacts += record.energy_change;
        self.y[n..2 * n].copy_from_slice(&record.u_after);
        let contacts = record.contacts.clone();
        let normal_after: Vec<f64> = record
            .outcome
            .contacts
            .iter()
            .map(|c| c.velocity_after.y)
            .collect();
        self.impacts.push(record);
        self.events.push((
            self.t,
            EventKind::Impact {
                index: self.impacts.len() - 1,
            },
        ));
        self.rec.push(self.t, &self.y, self.mode());
        self.after_impact(k, &contacts, &normal_after, speed)
    }

    /// After an impact at `contacts` (`k` struck, the normal velocities after, the speed of the
    /// contacts before): an accumulation completed, or the contacts that stay closed.
    fn after_impact(
        &mut self,
        k: usize,
        contacts: &[usize],
        normal_after: &[f64],
        speed: f64,
    ) -> Result<Option<StopReason>> {
        let (m, n) = (self.m, self.n);
        self.series.push((self.t, contacts.to_vec()));
        let times: Vec<f64> = self.series.iter().map(|s| s.0).collect();
        if let Some((limit, ratio)) = accumulation(&times, self.opt.sample_interval) {
            self.events.push((
                self.t,
                EventKind::Zeno {
                    contact: k,
                    limit_time: limit,
                    ratio,
                },
            ));
            let mut candidates: Vec<usize> = self
                .series
                .iter()
                .rev()
                .take(4)
                .flat_map(|s| s.1.iter().copied())
                .chain(self.closed.iter().map(|c| c.contact))
                .collect();
            candidates.sort_unstable();
            candidates.dedup();
            self.series.clear();
            if candidates == [k] && self.closed.is_empty() && self.rolling_from(k).is_some() {
                // A round body: complete the tail — the tangential motion continues, the
                // normal velocity vanishes at t∞ — and go on in closed form.
                let tail = limit - self.t;
                for i in 0..n {
                    self.y[i] += self.y[n + i] * tail;
                }
                self.t = limit;
                return Ok(Some(self.roll(k)?));
            }
            // Any other body: the remaining bounces (all within a thousandth of a sample
            // interval) are neglected and the contacts close at the last impact, keeping the
            // energy (a drift over the tail would not: the motion of a rod turning about its
            // chattering end is no uniform translation).
            let before = energy(m, &self.y);
            self.project_normals(&candidates)?;
            self.ledger.corrections += energy(m, &self.y) - before;
            return self.settle(candidates, Hint::None, Cause::Contact);
        }
        // Contacts left touching without leaving: those with zero normal velocity after (to
        // round-off), and those whose bounce is too low to leave the surface (`φ̇²/2|φ̈|` below
        // the touching tolerance).
        let acc = dynamics::accelerations(m, self.q(), self.u())?;
        let mut candidates = Vec::new();
        for (&j, &vn) in contacts.iter().zip(normal_after) {
            let stays = vn <= VELOCITY_ROUND_OFF * speed || {
                let [_, rate, accel] =
                    dynamics::gap_rates(m, j, self.q(), self.u(), acc.as_slice());
                accel < 0.0
                    && rate.max(0.0).powi(2) / (2.0 * -accel)
                        <= dynamics::touching_tolerance(m, j, self.q())
            };
            if stays {
                candidates.push(j);
            }
        }
        candidates.sort_unstable();
        if let Some(stop) = self.round_body(k, &candidates)? {
            return Ok(Some(stop));
        }
        if !candidates.is_empty() {
            let before = energy(m, &self.y);
            self.project_normals(&candidates)?;
            self.ledger.corrections += energy(m, &self.y) - before;
        }
        self.settle(candidates, Hint::None, Cause::Contact)
    }

    /// A round body whose only staying contact is `k` on a horizontal floor: the closed form.
    fn round_body(&mut self, k: usize, candidates: &[usize]) -> Result<Option<StopReason>> {
        if candidates == [k] && self.closed.is_empty() && self.rolling_from(k).is_some() {
            return Ok(Some(self.roll(k)?));
        }
        Ok(None)
    }

    /// Close `contacts` at the current state: project their gaps and normal velocities to
    /// zero, and the tangential velocities of those that roll (`|v_t|` within round-off of the
    /// run's speeds), so that a sticking contact keeps sticking (a correction of the size of
    /// a bounce below the touching tolerance).
    fn project_normals(&mut self, contacts: &[usize]) -> Result<()> {
        let (m, n, tol) = (self.m, self.n, self.tol_v());
        let kin = dynamics::kinematics(m, self.q());
        let u = nalgebra::DVector::from_column_slice(self.u());
        let normal: Vec<Closed> = contacts
            .iter()
            .map(|&contact| {
                let j = dynamics::contact_jacobian_of(m, contact, self.q(), &kin);
                let vt = (j.row(0) * &u)[0];
                Closed {
                    contact,
                    regime: if vt.abs() <= tol {
                        Regime::Stick
                    } else {
                        Regime::Frictionless
                    },
                }
            })
            .collect();
        let (q, rest) = self.y.split_at_mut(n);
        closed::project(m, q, &mut rest[..n], &normal)
    }

    /// Project onto the closed contacts, the change of `T + V` recorded.
    fn project(&mut self) -> Result<()> {
        if self.closed.is_empty() {
            return Ok(());
        }
        let n = self.n;
        let before = energy(self.m, &self.y);
        let (q, rest) = self.y.split_at_mut(n);
        closed::project(self.m, q, &mut rest[..n], &self.closed)?;
        self.ledger.corrections += energy(self.m, &self.y) - before;
        Ok(())
    }

    /// Decide which of `candidates` stay closed, and how, by the acceleration-level contact
    /// problem; record the changes; stop at rest or at Painlevé's paradox.
    fn settle(
        &mut self,
        mut candidates: Vec<usize>,
        hint: Hint,
        cause: Cause,
    ) -> Result<Option<StopReason>> {
        let (m, n) = (self.m, self.n);
        candidates.sort_unstable();
        candidates.dedup();
        let previous = std::mem::take(&mut self.closed);
        if candidates.is_empty() {
            if cause == Cause::Event {
                for c in &previous {
                    self.events
                        .push((self.t, EventKind::Opens { contact: c.contact }));
                }
            }
            return Ok(None);
        }
        if candidates.len() > closed::MAX_CLOSED {
            return Ok(Some(StopReason::UnsupportedContact {
                contact: candidates[0],
                touching: candidates[1..].to_vec(),
            }));
        }
        let (q, u) = (self.q().to_vec(), self.u().to_vec());
        let cd = ContactDynamics::new(m, &q, &u, &candidates)?;
        let tol = self.tol_v();
        let sliding: Vec<Option<SlipDirection>> = (0..candidates.len())
            .map(|j| {
                let vt = cd.v[2 * j];
                (vt.abs() > tol).then(|| SlipDirection::of(vt))
            })
            .collect();
        let solutions = cd.solutions(self.opt.friction, &sliding, hint)?;
        if solutions.len() != 1 {
            let contact = (0..candidates.len())
                .find(|&j| sliding[j].is_some())
                .map_or(candidates[0], |j| candidates[j]);
            return Ok(Some(StopReason::Painleve {
                contact,
                solutions: solutions.len(),
            }));
        }
        let solution = solutions.into_iter().next().expect("one solution");
        for c in &solution.closed {
            match previous.iter().find(|p| p.contact == c.contact) {
                None => self.events.push((
                    self.t,
                    EventKind::Closes {
                        contact: c.contact,
                        regime: c.regime,
                    },
                )),
                Some(p) if p.regime != c.regime => self.events.push((
                    self.t,
                    EventKind::Regime {
                        contact: c.contact,
                        regime: c.regime,
                    },
                )),
                Some(_) => {}
            }
        }
        if cause == Cause::Event {
            for p in &previous {
                if !solution.closed.iter().any(|c| c.contact == p.contact) {
                    self.events
                        .push((self.t, EventKind::Opens { contact: p.contact }));
                }
            }
        }
        self.closed = solution.closed;
        self.project()?;
        // Rest: every body still (to round-off of the run's speeds) and no acceleration.
        if !self.closed.is_empty() {
            let u = self.u();
            let mass = dynamics::mass_matrix(m, self.q());
            let total: f64 = m.bodies().iter().map(|b| b.mass).sum();
            let uv = nalgebra::DVector::from_column_slice(u);
            let kinetic = 0.5 * uv.dot(&(&mass * &uv));
            let a = &solution.forces.accel;
            let a_free = &cd.a_free;
            let norm = |x: &nalgebra::DVector<f64>| x.dot(&(&mass * x)).max(0.0).sqrt();
            let still = kinetic <= 0.5 * total * (VELOCITY_ROUND_OFF * self.vscale).powi(2);
            let balanced = norm(a) <= FORCE_ROUND_OFF * norm(a_free);
            if still && balanced {
                let before = energy(m, &self.y);
                self.y[n..2 * n].fill(0.0);
                self.ledger.corrections += energy(m, &self.y) - before;
                self.events.push((self.t, EventKind::Rest));
                return Ok(Some(StopReason::Rest));
            }
        }
        Ok(None)
    }

    /// One step of the motion, with its events.
    fn advance(&mut self) -> Result<Advance> {
        let (m, n) = (self.m, self.n);
        let until = self.opt.until;
        let mu = self.opt.friction;
        let closed = self.closed.clone();
        let mut f = rhs(m, closed.clone(), mu);
        let step = self.ode.advance(&mut f, until)?;
        let (t0, t1) = (step.t0, step.t1);
        let ystart = step.y0.to_vec();
        let y1 = step.y1.to_vec();
        let mut buf = vec![0.0; 2 * n + 1];
        // Regular samples inside the step (kept only before the event, if any).
        let mut inside: Vec<(f64, Vec<f64>)> = Vec::new();
        while self.rec.next_time() <= t1 && self.rec.next_time() <= until {
            let ts = self.rec.next_time();
            step.interpolate(ts, &mut buf);
            inside.push((ts, buf.clone()));
            self.rec.next += 1;
        }
        let mut times: Vec<f64> = (1..PARTS)
            .map(|j| t0 + (t1 - t0) * j as f64 / PARTS as f64)
            .chain(inside.iter().map(|s| s.0))
            .filter(|&tj| tj > t0 && tj < t1)
            .collect();
        times.sort_by(f64::total_cmp);
        times.push(t1);
        let mut states: Vec<Vec<f64>> = Vec::with_capacity(times.len());
        for &tj in &times {
            if tj == t1 {
                states.push(y1.clone());
            } else {
                step.interpolate(tj, &mut buf);
                states.push(buf.clone());
            }
        }
        // Each watched quantity on the dense output: the first fall from positive to ≤ 0
        // brackets an event; one at or below zero at the step's start that goes further
        // below its round-off happens at the start.
        let mut brackets: Vec<(Watched, f64, f64)> = Vec::new();
        let mut at_start: Option<Watched> = None;
        for k in 0..m.contacts().len() {
            if closed.iter().any(|c| c.contact == k) {
                continue;
            }
            let g0 = gap_of(m, k, &ystart);
            let tol = dynamics::touching_tolerance(m, k, &ystart[..n]);
            let mut prev = (t0, g0);
            for (&tj, yj) in times.iter().zip(&states) {
                let g = gap_of(m, k, yj);
                if prev.1 > 0.0 && g <= 0.0 {
                    brackets.push((Watched::Gap(k), prev.0, tj));
                    break;
                }
                if g0 <= 0.0 && g < -tol && g < g0 {
                    at_start = at_start.or(Some(Watched::Gap(k)));
                    break;
                }
                prev = (tj, g);
            }
        }
        let mut det0 = 0.0;
        if !closed.is_empty() {
            let watch0 = closed::watch(m, &closed, mu, &ystart)?;
            det0 = watch0.det;
            let values: Vec<Vec<(Watched, f64)>> = std::iter::once(&ystart)
                .chain(states.iter())
                .map(|y| {
                    closed::watch(m, &closed, mu, y)
                        .map(|w| watched(&closed, &w, mu, watch0.det))
                        .unwrap_or_default()
                })
                .collect();
            let scale = values
                .iter()
                .flatten()
                .filter(|(w, _)| matches!(w, Watched::Force(_) | Watched::Margin(_)))
                .fold(0.0f64, |s, (_, g)| s.max(g.abs()));
            let mut all_times = vec![t0];
            all_times.extend(&times);
            for (i, &(what, g0)) in values[0].iter().enumerate() {
                let tol = match what {
                    Watched::Slip(_) => self.tol_v(),
                    Watched::Singular => 0.0,
                    _ => FORCE_ROUND_OFF * scale,
                };
                for s in 1..values.len() {
                    let Some(&(_, g)) = values[s].get(i) else {
                        break;
                    };
                    let prev = values[s - 1].get(i).map_or(g0, |x| x.1);
                    if prev > 0.0 && g <= 0.0 {
                        brackets.push((what, all_times[s - 1], all_times[s]));
                        break;
                    }
                    if g0 <= 0.0 && g < -tol && g < g0 {
                        at_start = at_start.or(Some(what));
                        break;
                    }
                }
            }
        }
        let mut event: Option<(Watched, f64)> = at_start.map(|w| (w, t0));
        if event.is_none() {
            let mut trial = vec![0.0; 2 * n + 1];
            for (what, a, b) in brackets {
                if event.is_some_and(|(_, te)| te <= a) {
                    continue;
                }
                let located = {
                    let closed = &closed;
                    let mut g = |y: &[f64]| watched_value(m, mu, closed, what, y, det0);
                    locate(
                        &mut self.ode,
                        &mut f,
                        t0,
                        &ystart,
                        t1,
                        &y1,
                        a,
                        b,
                        &mut trial,
                        &mut g,
                    )
                };
                if let Some(te) = located {
                    if event.is_none_or(|(_, t_first)| te < t_first) {
                        event = Some((what, te));
                    }
                }
            }
        }
        let mode = self.mode();
        let Some((what, te)) = event else {
            for (ts, ys) in inside {
                let ys = self.on_contacts(ys)?;
                self.rec.push(ts, &ys, mode);
            }
            self.y.copy_from_slice(&y1);
            self.t = t1;
            if !self.closed.is_empty() {
                let before = self.y.clone();
                self.project()?;
                if self.y != before {
                    self.ode.restart(&mut f, self.t, &self.y)?;
                }
            }
            return Ok(Advance::Free);
        };
        for (ts, ys) in inside {
            if ts < te {
                let ys = self.on_contacts(ys)?;
                self.rec.push(ts, &ys, mode);
            } else {
                self.rec.next = self.rec.next.min((ts / self.rec.dt).round() as u64);
            }
        }
        if te > t0 {
            let mut trial = vec![0.0; 2 * n + 1];
            self.ode
                .trial_step(&mut f, t0, &ystart, te - t0, &mut trial);
            self.y.copy_from_slice(&trial);
        } else {
            self.y.copy_from_slice(&ystart);
        }
        self.t = te;
        if self.stall.0 == te {
            self.stall.1 += 1;
            if self.stall.1 > STALL {
                return Err(Error::Integration {
                    reason: format!(
                        "the contacts' regimes switch endlessly at t = {}",
                        crate::error::Num(te)
                    ),
                });
            }
        } else {
            self.stall = (te, 0);
        }
        if let Watched::Gap(k) = what {
            return Ok(Advance::Arrival(k));
        }
        // A change of the closed contacts' regimes.
        self.project()?;
        self.rec.push(self.t, &self.y, mode);
        self.series.clear();
        let hint = match what {
            Watched::Force(k) => Hint::Open(k),
            Watched::Margin(k) => Hint::Slip(k),
            _ => Hint::None,
        };
        let mut candidates: Vec<usize> = self.closed.iter().map(|c| c.contact).collect();
        let tol = self.tol_v();
        for j in touching(m, self.q()) {
            if !candidates.contains(&j) && dynamics::gap_rate(m, j, self.q(), self.u()).abs() <= tol
            {
                candidates.push(j);
            }
        }
        if let Some(stop) = self.settle(candidates, hint, Cause::Event)? {
            return Ok(Advance::Stop(stop));
        }
        self.start(self.opt.until)?;
        Ok(Advance::Free)
    }

    /// A state of the dense output put on the closed contacts (for the samples).
    fn on_contacts(&self, mut y: Vec<f64>) -> Result<Vec<f64>> {
        if !self.closed.is_empty() {
            let n = self.n;
            let (q, rest) = y.split_at_mut(n);
            closed::project(self.m, q, &mut rest[..n], &self.closed)?;
        }
        Ok(y)
    }

    /// Persistent contact of contact `k` that the closed form continues: a round body on a
    /// horizontal floor, with its state `(x, ẋ, θ, θ̇)`.
    fn rolling_from(&self, k: usize) -> Option<(crate::mechanism::RoundOnFloor, Rolling)> {
        let (m, n, y) = (self.m, self.n, &self.y);
        let body = m.round_on_floor()?;
        (m.contacts()[k].surface.normal == Vec2::new(0.0, 1.0)).then_some((
            body,
            Rolling {
                t0: self.t,
                x: y[0],
                vx: y[n],
                theta: y[2],
                omega: y[n + 2],
            },
        ))
    }

    /// A round body in persistent contact at contact `k`: sliding (closed form) until rolling,
    /// then rolling to the end time, or rest. Returns the stop.
    fn roll(&mut self, k: usize) -> Result<StopReason> {
        let (body, state) = self.rolling_from(k).ok_or_else(|| Error::Invalid {
            field: "contact".into(),
            reason: "not a round body on a horizontal floor".into(),
        })?;
        let before = energy(self.m, &self.y);
        let (stop, end, e1) = roll(
            self.m,
            &body,
            state,
            &self.opt,
            &mut self.rec,
            &mut self.events,
        );
        // The closed form's sliding is the contact's work.
        self.ledger.contact_work += e1 - before;
        self.rolled = Some((end, e1));
        Ok(stop)
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
        self.ledger.contact_work += self.y[2 * self.n];
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
