//! The event-driven simulation loop.

use super::contact::Rolling;
use crate::error::{Error, Result};
use crate::law::LawId;
use crate::math::Vec2;
use crate::mechanism::dynamics::{self, check_state};
use crate::mechanism::impact::MechanismImpact;
use crate::mechanism::Mechanism;
use crate::numerics::roots::illinois_with_bisection;
use crate::ode::{Dopri5, Tolerances};
use crate::planar::Outcome;

/// Options of a simulation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulationOptions {
    /// The impact law applied at every impact.
    pub law: LawId,
    /// Coulomb friction `μ ≥ 0` (impacts and sliding).
    pub friction: f64,
    /// Coefficient of restitution `e ∈ [0, 1]`.
    pub restitution: f64,
    /// End time (> 0).
    pub until: f64,
    /// Spacing of the output samples (> 0, at most 10⁶ samples in all).
    pub sample_interval: f64,
    /// Largest number of impacts before stopping with [`StopReason::ImpactLimit`].
    pub max_impacts: usize,
    /// Integrator tolerances of the free motion.
    pub tolerances: Tolerances,
}

impl SimulationOptions {
    /// `law`, `μ`, `e` until `until`, with 1000 sample intervals, at most 10,000 impacts and
    /// tight tolerances (1e-12 relative).
    pub fn new(law: LawId, friction: f64, restitution: f64, until: f64) -> Self {
        SimulationOptions {
            law,
            friction,
            restitution,
            until,
            sample_interval: until / 1000.0,
            max_impacts: 10_000,
            tolerances: Tolerances::TIGHT,
        }
    }

    fn validate(&self) -> Result<()> {
        crate::error::finite("friction", self.friction)?;
        crate::error::finite("restitution", self.restitution)?;
        crate::error::coefficients(self.friction, self.restitution)?;
        if !(self.until.is_finite() && self.until > 0.0) {
            return Err(Error::OutOfRange {
                field: "until".into(),
                value: self.until,
                reason: "the end time must be finite and positive".into(),
            });
        }
        let count = self.until / self.sample_interval;
        if !(self.sample_interval > 0.0 && count.is_finite() && count <= 1e6) {
            return Err(Error::OutOfRange {
                field: "sample interval".into(),
                value: self.sample_interval,
                reason: "must be positive and give at most 10⁶ samples".into(),
            });
        }
        if self.law.needs_body() {
            return Err(Error::Invalid {
                field: "law".into(),
                reason: format!(
                    "`{}` needs a single body's centre velocity; choose a contact-space law",
                    self.law
                ),
            });
        }
        Ok(())
    }
}

/// Why a simulation ended.
#[derive(Debug, Clone, PartialEq)]
pub enum StopReason {
    /// The end time was reached.
    TimeLimit,
    /// A round body came to rest on the floor.
    Rest,
    /// A body reached persistent contact that the simulator does not model (any body but a
    /// round one on a horizontal floor): a plastic impact, or an accumulation of impacts.
    PersistentContact {
        /// The contact.
        contact: usize,
    },
    /// [`SimulationOptions::max_impacts`] impacts happened.
    ImpactLimit,
    /// The law does not apply at an impact (its breakdown reason).
    Breakdown {
        /// Why.
        reason: String,
    },
    /// A contact struck, or was pressed into its surface, while other contacts touched theirs
    /// (a rod landing on both ends, rocking onto its second end, a pendulum's elbow meeting
    /// the floor where its tip rests): an impact or a resting contact at several points at
    /// once, which this simulator does not model. The run ends at that instant, before the
    /// impact.
    UnsupportedContact {
        /// The contact that struck or was pressed.
        contact: usize,
        /// The contacts touching their surfaces at that time.
        touching: Vec<usize>,
    },
}

impl StopReason {
    /// Stable id: `time-limit`, `rest`, `persistent-contact`, `impact-limit`, `breakdown`,
    /// `unsupported-contact`.
    pub fn id(&self) -> &'static str {
        match self {
            StopReason::UnsupportedContact { .. } => "unsupported-contact",
            StopReason::TimeLimit => "time-limit",
            StopReason::Rest => "rest",
            StopReason::PersistentContact { .. } => "persistent-contact",
            StopReason::ImpactLimit => "impact-limit",
            StopReason::Breakdown { .. } => "breakdown",
        }
    }
}

/// The regime of the motion at a sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Free motion (no contact).
    Flight,
    /// A round body sliding on the floor.
    Sliding,
    /// A round body rolling on the floor.
    Rolling,
    /// At rest.
    Rest,
}

impl Mode {
    /// `flight`, `sliding`, `rolling`, `rest`.
    pub fn id(self) -> &'static str {
        match self {
            Mode::Flight => "flight",
            Mode::Sliding => "sliding",
            Mode::Rolling => "rolling",
            Mode::Rest => "rest",
        }
    }
}

/// Something that happened during the run.
#[derive(Debug, Clone, PartialEq)]
pub enum EventKind {
    /// Impact number `index` (into [`Run::impacts`]).
    Impact {
        /// Index into the impacts.
        index: usize,
    },
    /// An accumulation of impacts at `contact`, completed at its limit time.
    Zeno {
        /// The contact.
        contact: usize,
        /// `t∞`, the sum of the geometric series of impact intervals.
        limit_time: f64,
        /// The common ratio of the intervals.
        ratio: f64,
    },
    /// Persistent sliding contact begins.
    Sliding,
    /// Rolling begins (the slip vanished).
    Rolling,
    /// The body comes to rest.
    Rest,
}

/// One output sample of the trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Time.
    pub t: f64,
    /// Generalized coordinates.
    pub q: Vec<f64>,
    /// Generalized velocities.
    pub u: Vec<f64>,
    /// Kinetic energy `T`.
    pub kinetic: f64,
    /// Potential energy `V`.
    pub potential: f64,
    /// The regime.
    pub mode: Mode,
}

/// One impact and its energy ledger.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactRecord {
    /// Time of the impact.
    pub time: f64,
    /// The contact that struck.
    pub contact: usize,
    /// Configuration at the impact.
    pub q: Vec<f64>,
    /// Generalized velocities before.
    pub u_before: Vec<f64>,
    /// Generalized velocities after.
    pub u_after: Vec<f64>,
    /// Contact velocity before, `(v_t, v_n)`.
    pub contact_velocity_before: Vec2,
    /// The law's result in contact space (impulse, work split, phases, verdict …).
    pub outcome: Outcome,
    /// Kinetic energy before.
    pub kinetic_before: f64,
    /// `ΔT` from the generalized velocities.
    pub energy_change: f64,
    /// Translational part of `ΔT`, `Σ_b ½ m_b Δ|v_b|²`.
    pub translational_change: f64,
    /// Rotational part of `ΔT`, `Σ_b ½ I_b Δω_b²`.
    pub rotational_change: f64,
    /// Total mechanical energy `T + V` before (`V` is continuous across the impact).
    pub total_energy_before: f64,
}

/// The result of a simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Output samples (at the sample interval, plus before and after every impact).
    pub samples: Vec<Sample>,
    /// Every impact.
    pub impacts: Vec<ImpactRecord>,
    /// Every event, with its time.
    pub events: Vec<(f64, EventKind)>,
    /// Why the run ended.
    pub stop: StopReason,
    /// When it ended.
    pub end_time: f64,
    /// Accepted and rejected integrator steps.
    pub steps: (usize, usize),
}

struct Recorder<'a, M: Mechanism + ?Sized> {
    m: &'a M,
    dt: f64,
    next: u64,
    samples: Vec<Sample>,
}

impl<M: Mechanism + ?Sized> Recorder<'_, M> {
    fn push(&mut self, t: f64, y: &[f64], mode: Mode) {
        let n = self.m.dof();
        let (q, u) = y.split_at(n);
        self.samples.push(Sample {
            t,
            q: q.to_vec(),
            u: u.to_vec(),
            kinetic: dynamics::kinetic_energy(self.m, q, u),
            potential: dynamics::potential_energy(self.m, q),
            mode,
        });
    }
    /// The next regular sample time.
    fn next_time(&self) -> f64 {
        self.next as f64 * self.dt
    }
}

/// Gap of contact `k` at the state `y = (q, u)`.
fn gap_of<M: Mechanism + ?Sized>(m: &M, k: usize, y: &[f64]) -> f64 {
    dynamics::gap(m, k, &y[..m.dof()])
}

/// The contacts other than `except` that touch their surfaces at `q` (gap within
/// [`dynamics::touching_tolerance`]).
fn touching<M: Mechanism + ?Sized>(m: &M, q: &[f64], except: usize) -> Vec<usize> {
    (0..m.contacts().len())
        .filter(|&j| j != except && dynamics::gap(m, j, q) <= dynamics::touching_tolerance(m, j, q))
        .collect()
}

/// Contact `k` at `(q, u)` touches its surface without approaching it and is accelerated into
/// it (`φ̇ = 0`, `φ̈ < 0`): it would stay closed, pressed against the surface.
fn pressed<M: Mechanism + ?Sized>(m: &M, k: usize, q: &[f64], u: &[f64]) -> Result<bool> {
    if dynamics::gap(m, k, q) > dynamics::touching_tolerance(m, k, q) {
        return Ok(false);
    }
    let acc = dynamics::accelerations(m, q, u)?;
    let [_, rate, accel] = dynamics::gap_rates(m, k, q, u, acc.as_slice());
    Ok(rate <= 0.0 && accel < 0.0)
}

/// What happens at `(t, y)` when contact `k` reaches its surface.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Arrival {
    /// Its gap crossed zero: an impact if it approaches (a graze otherwise).
    Crossing(usize),
    /// It touched its surface at the start of a step and the motion moved it into the
    /// surface: an impact if it approaches, else it is pressed into persistent contact.
    Pressing(usize),
}

/// Simulate `m` from `(q0, u0)` at `t = 0` until `options.until` (or a stop).
///
/// Every contact of the mechanism is watched (both ends of a rod, a double pendulum's tip and
/// elbow). The run stops with [`StopReason::UnsupportedContact`] when a contact strikes, or is
/// pressed into its surface, while another one touches its own (an impact or a resting
/// contact at several points at once), and with [`StopReason::PersistentContact`] when a
/// single contact stays closed on any body but a round one on a floor; the last sample is the
/// state at the stop, with its true energy. No sampled state has a contact below its surface
/// by more than [`dynamics::touching_tolerance`].
///
/// # Errors
/// Invalid state or options; a start below a surface; a singular mass matrix or a failed
/// integration along the way.
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
    let energy = dynamics::kinetic_energy(m, q0, u0) + dynamics::potential_energy(m, q0);
    if !(energy.is_finite() && energy.abs() < 1e300) {
        return Err(Error::OutOfRange {
            field: "q".into(),
            value: energy,
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
    let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| dynamics::state_derivative(m, y, dy);
    let mut ode = Dopri5::new(2 * n, options.tolerances)?;
    let mut rec = Recorder {
        m,
        dt: options.sample_interval,
        next: 1,
        samples: Vec::new(),
    };
    let mut y: Vec<f64> = q0.iter().chain(u0).copied().collect();
    let mut t = 0.0;
    rec.push(0.0, &y, Mode::Flight);
    let mut impacts: Vec<ImpactRecord> = Vec::new();
    let mut events: Vec<(f64, EventKind)> = Vec::new();
    // Impact times of the current run of impacts at one contact (for accumulation).
    let mut series: (usize, Vec<f64>) = (usize::MAX, Vec::new());
    let until = options.until;

    // A contact touching at the start: struck at t = 0 if it approaches, pressed if the
    // motion pushes it into its surface.
    let mut pending: Option<Arrival> = None;
    for k in 0..contacts {
        if dynamics::gap(m, k, q0) > dynamics::touching_tolerance(m, k, q0) {
            continue;
        }
        if dynamics::gap_rate(m, k, q0, u0) < 0.0 {
            pending = Some(Arrival::Crossing(k));
            break;
        }
        if pending.is_none() && pressed(m, k, q0, u0)? {
            pending = Some(Arrival::Pressing(k));
        }
    }
    ode.start(&mut f, t, &y, until)?;
    let mut ystart = vec![0.0; 2 * n];
    let mut trial = vec![0.0; 2 * n];
    let mut buf = vec![0.0; 2 * n];
    loop {
        if let Some(arrival) = pending.take() {
            let (Arrival::Crossing(k) | Arrival::Pressing(k)) = arrival;
            let (q, u) = y.split_at(n);
            let others = touching(m, q, k);
            let v_k = dynamics::gap_rate(m, k, q, u);
            if v_k >= 0.0 {
                if let Arrival::Pressing(_) = arrival {
                    // Pressed into the surface: persistent contact.
                    if !others.is_empty() {
                        let stop = StopReason::UnsupportedContact {
                            contact: k,
                            touching: others,
                        };
                        return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                    }
                    if let Some((body, state)) = rolling_from(m, k, t, &y) {
                        let (stop, end) = roll(m, &body, state, options, &mut rec, &mut events);
                        return Ok(finish(rec, impacts, events, stop, end, &ode));
                    }
                    let stop = StopReason::PersistentContact { contact: k };
                    return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                }
            } else {
                // ---- the impact at (t, y) on contact k ----
                if impacts.len() >= options.max_impacts {
                    return Ok(stop_at(
                        rec,
                        impacts,
                        events,
                        StopReason::ImpactLimit,
                        t,
                        &y,
                        &ode,
                    ));
                }
                // Another contact touching and approaching: an impact at several points.
                if others.iter().any(|&j| dynamics::gap_rate(m, j, q, u) < 0.0) {
                    let stop = StopReason::UnsupportedContact {
                        contact: k,
                        touching: others,
                    };
                    return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                }
                let imp = MechanismImpact::new(m, q, u, k)?;
                let v = imp.contact_velocity();
                // A contact that one coordinate alone moves (a double pendulum's elbow) has a
                // singular W: no one-contact law applies there.
                let problem = match imp.problem(options.friction, options.restitution) {
                    Ok(p) => p,
                    Err(e) => {
                        let stop = StopReason::Breakdown {
                            reason: format!(
                                "the {} strikes, and its contact problem is not one a one-contact law takes: {e}",
                                m.contacts()[k].name
                            ),
                        };
                        return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                    }
                };
                let outcome = match options.law.resolve(&problem) {
                    Ok(o) => o,
                    Err(b) => {
                        let stop = StopReason::Breakdown {
                            reason: b.reason.to_string(),
                        };
                        return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                    }
                };
                let after = imp.velocities_after(outcome.impulse);
                // The impulse at k must not drive another touching contact into its surface.
                let speed = v.norm();
                let mut blocked = false;
                for &j in &others {
                    let vj = dynamics::gap_rate(m, j, q, &after);
                    if vj < 0.0 || (vj <= 1e-9 * speed && pressed(m, j, q, &after)?) {
                        blocked = true;
                    }
                }
                if blocked {
                    let stop = StopReason::UnsupportedContact {
                        contact: k,
                        touching: others,
                    };
                    return Ok(stop_at(rec, impacts, events, stop, t, &y, &ode));
                }
                let (tr0, rot0) = energy_parts(m, imp.kinematics(), u);
                let (tr1, rot1) = energy_parts(m, imp.kinematics(), &after);
                let kinetic_before = imp.energy_before();
                let potential = dynamics::potential_energy(m, q);
                rec.push(t, &y, Mode::Flight);
                impacts.push(ImpactRecord {
                    time: t,
                    contact: k,
                    q: q.to_vec(),
                    u_before: u.to_vec(),
                    u_after: after.clone(),
                    contact_velocity_before: v,
                    energy_change: imp.kinetic_energy(&after) - kinetic_before,
                    translational_change: tr1 - tr0,
                    rotational_change: rot1 - rot0,
                    total_energy_before: kinetic_before + potential,
                    kinetic_before,
                    outcome,
                });
                events.push((
                    t,
                    EventKind::Impact {
                        index: impacts.len() - 1,
                    },
                ));
                y[n..].copy_from_slice(&after);
                rec.push(t, &y, Mode::Flight);
                let vn_after = outcome.velocity_after.y;
                // The height of the coming bounce, `φ̇² / 2|φ̈|`: below the touching tolerance
                // the contact cannot be told apart from its surface.
                let apex = {
                    let (q, u) = y.split_at(n);
                    let acc = dynamics::accelerations(m, q, u)?;
                    let [_, rate, accel] = dynamics::gap_rates(m, k, q, u, acc.as_slice());
                    if accel < 0.0 {
                        rate.max(0.0).powi(2) / (2.0 * -accel)
                    } else {
                        f64::INFINITY
                    }
                };
                // Persistent contact: a plastic impact, a bounce too low to leave the surface,
                // or an accumulation of impacts.
                let mut persistent: Option<f64> = None; // the time it starts
                if vn_after <= 1e-9 * v.y.abs() {
                    persistent = Some(t);
                    series.1.clear();
                } else {
                    if series.0 != k {
                        series = (k, Vec::new());
                    }
                    series.1.push(t);
                    if let Some((limit, ratio)) = accumulation(&series.1, options.sample_interval) {
                        events.push((
                            t,
                            EventKind::Zeno {
                                contact: k,
                                limit_time: limit,
                                ratio,
                            },
                        ));
                        // Complete the tail: the tangential motion continues, the normal
                        // velocity vanishes at t∞.
                        let tail = limit - t;
                        for i in 0..n {
                            y[i] += y[n + i] * tail;
                        }
                        t = limit;
                        persistent = Some(t);
                        series.1.clear();
                    } else if apex <= dynamics::touching_tolerance(m, k, &y[..n]) {
                        persistent = Some(t);
                        series.1.clear();
                    }
                }
                if let Some(t_contact) = persistent {
                    if let Some((body, state)) = rolling_from(m, k, t_contact, &y) {
                        let (stop, end) = roll(m, &body, state, options, &mut rec, &mut events);
                        return Ok(finish(rec, impacts, events, stop, end, &ode));
                    }
                    let stop = StopReason::PersistentContact { contact: k };
                    // Leave the state with zero normal contact velocity (plastic, frictionless).
                    let (q, u) = y.split_at(n);
                    let imp = MechanismImpact::new(m, q, u, k)?;
                    let w = imp.inverse_inertia();
                    let vn = imp.contact_velocity().y;
                    if vn < 0.0 {
                        let after = imp.velocities_after(Vec2::new(0.0, -vn / w[(1, 1)]));
                        y[n..].copy_from_slice(&after);
                    }
                    return Ok(stop_at(rec, impacts, events, stop, t_contact, &y, &ode));
                }
            }
            // Bound the first step by a quarter of the coming flight of the contact just struck
            // (`2 φ̇ / |φ̈|`), so that a short bounce is resolved by the step sampling.
            let (q, u) = y.split_at(n);
            let acc = dynamics::accelerations(m, q, u)?;
            let [_, rate, accel] = dynamics::gap_rates(m, k, q, u, acc.as_slice());
            let flight = if accel < 0.0 && rate > 0.0 {
                2.0 * rate / -accel
            } else {
                f64::INFINITY
            };
            ode.start(&mut f, t, &y, (until - t).min(0.25 * flight))?;
        }
        if t >= until {
            return Ok(finish(rec, impacts, events, StopReason::TimeLimit, t, &ode));
        }
        // ---- one step of free motion ----
        let step = ode.advance(&mut f, until)?;
        let (t0, t1) = (step.t0, step.t1);
        ystart.copy_from_slice(step.y0);
        // Regular samples inside the step (kept only before the event, if any).
        let mut inside: Vec<(f64, Vec<f64>)> = Vec::new();
        while rec.next_time() <= t1 && rec.next_time() <= until {
            let ts = rec.next_time();
            step.interpolate(ts, &mut buf);
            inside.push((ts, buf.clone()));
            rec.next += 1;
        }
        // Each contact's gap on the dense output, at PARTS points of the step and at the
        // samples: the first crossing from positive to ≤ 0 brackets an arrival; a contact
        // touching at the step's start that goes further in arrives at the start.
        const PARTS: usize = 8;
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
                states.push(step.y1.to_vec());
            } else {
                step.interpolate(tj, &mut buf);
                states.push(buf.clone());
            }
        }
        let mut brackets: Vec<(usize, f64, f64)> = Vec::new();
        let mut pressing: Option<usize> = None;
        for k in 0..contacts {
            let g0 = gap_of(m, k, step.y0);
            let tol = dynamics::touching_tolerance(m, k, &step.y0[..n]);
            let mut prev = (t0, g0);
            for (&tj, yj) in times.iter().zip(&states) {
                let g = gap_of(m, k, yj);
                if prev.1 > 0.0 && g <= 0.0 {
                    brackets.push((k, prev.0, tj));
                    break;
                }
                if g0 <= 0.0 && g < -tol && g < g0 {
                    pressing = pressing.or(Some(k));
                    break;
                }
                prev = (tj, g);
            }
        }
        let y1 = step.y1.to_vec();
        let mut event: Option<(Arrival, f64)> = None;
        if let Some(k) = pressing {
            event = Some((Arrival::Pressing(k), t0));
        } else {
            for (k, a, b) in brackets {
                let located = locate(
                    &mut ode, &mut f, m, k, t0, &ystart, t1, &y1, a, b, &mut trial,
                );
                if let Some(te) = located {
                    if event.is_none_or(|(_, t_first)| te < t_first) {
                        event = Some((Arrival::Crossing(k), te));
                    }
                }
            }
        }
        match event {
            Some((arrival, te)) => {
                for (ts, ys) in inside {
                    if ts < te {
                        rec.push(ts, &ys, Mode::Flight);
                    } else {
                        rec.next = rec.next.min((ts / rec.dt).round() as u64);
                    }
                }
                if te > t0 {
                    ode.trial_step(&mut f, t0, &ystart, te - t0, &mut trial);
                    y.copy_from_slice(&trial);
                } else {
                    y.copy_from_slice(&ystart);
                }
                t = te;
                pending = Some(arrival);
            }
            None => {
                for (ts, ys) in inside {
                    rec.push(ts, &ys, Mode::Flight);
                }
                y.copy_from_slice(&y1);
                t = t1;
            }
        }
        // Keep the regular sampling clock consistent after a rewind.
        while rec.next_time() <= t && rec.next_time() <= until && event.is_none() {
            rec.next += 1;
        }
    }
}

/// Persistent contact of contact `k` at `(t, y)` that the closed form continues: a round body
/// on a horizontal floor, with its state `(x, ẋ, θ, θ̇)`.
fn rolling_from<M: Mechanism + ?Sized>(
    m: &M,
    k: usize,
    t: f64,
    y: &[f64],
) -> Option<(crate::mechanism::RoundOnFloor, Rolling)> {
    let n = m.dof();
    let body = m.round_on_floor()?;
    (m.contacts()[k].surface.normal == Vec2::new(0.0, 1.0)).then_some((
        body,
        Rolling {
            t0: t,
            x: y[0],
            vx: y[n],
            theta: y[2],
            omega: y[n + 2],
        },
    ))
}

/// The end of a run at `(t, y)`, recorded as its last sample (so that the run's final energy
/// is the state's at the stop).
fn stop_at<M: Mechanism + ?Sized>(
    mut rec: Recorder<'_, M>,
    impacts: Vec<ImpactRecord>,
    events: Vec<(f64, EventKind)>,
    stop: StopReason,
    t: f64,
    y: &[f64],
    ode: &Dopri5,
) -> Run {
    rec.push(t, y, Mode::Flight);
    finish(rec, impacts, events, stop, t, ode)
}

/// The end of a run.
fn finish<M: Mechanism + ?Sized>(
    rec: Recorder<'_, M>,
    impacts: Vec<ImpactRecord>,
    events: Vec<(f64, EventKind)>,
    stop: StopReason,
    end_time: f64,
    ode: &Dopri5,
) -> Run {
    Run {
        samples: rec.samples,
        impacts,
        events,
        stop,
        end_time,
        steps: (ode.accepted, ode.rejected),
    }
}

/// Translational and rotational kinetic energy at the velocities `u`.
fn energy_parts<M: Mechanism + ?Sized>(m: &M, kin: &dynamics::Kinematics, u: &[f64]) -> (f64, f64) {
    let vel = dynamics::body_velocities(kin, u);
    let (mut tr, mut rot) = (0.0, 0.0);
    for (b, v) in m.bodies().iter().zip(&vel) {
        tr += 0.5 * b.mass * (v[0] * v[0] + v[1] * v[1]);
        rot += 0.5 * b.inertia * v[2] * v[2];
    }
    (tr, rot)
}

/// An accumulation of impacts: the last intervals shrink geometrically (three ratios equal to
/// 1e-4) and the rest of the series is below a thousandth of the sample interval; or the last
/// interval is below round-off of the time. Returns `(t∞, ratio)`.
fn accumulation(times: &[f64], sample_interval: f64) -> Option<(f64, f64)> {
    let k = times.len();
    if k < 2 {
        return None;
    }
    let last = times[k - 1];
    let dt = last - times[k - 2];
    if dt <= 64.0 * f64::EPSILON * last.abs().max(1.0) {
        return Some((last, 0.0));
    }
    if k < 5 {
        return None;
    }
    let d: Vec<f64> = (k - 4..k).map(|i| times[i] - times[i - 1]).collect();
    let r: Vec<f64> = (1..4).map(|i| d[i] / d[i - 1]).collect();
    let ratio = r[2];
    let steady = r.iter().all(|&x| x > 0.0 && x < 1.0)
        && (r[2] - r[1]).abs() <= 1e-4 * ratio
        && (r[1] - r[0]).abs() <= 1e-4 * ratio;
    let tail = dt * ratio / (1.0 - ratio);
    (steady && tail <= 1e-3 * sample_interval).then_some((last + tail, ratio))
}

/// Locate the crossing of contact `k`'s gap on the discrete solution (re-stepping from
/// `(t0, y0)`), bracketed by `[a, b]` from the dense output; `None` when the discrete solution
/// does not cross (a dense-output graze).
#[allow(clippy::too_many_arguments)]
fn locate<M: Mechanism + ?Sized>(
    ode: &mut Dopri5,
    f: &mut impl FnMut(f64, &[f64], &mut [f64]),
    m: &M,
    k: usize,
    t0: f64,
    y0: &[f64],
    t1: f64,
    y1: &[f64],
    a: f64,
    b: f64,
    trial: &mut [f64],
) -> Option<f64> {
    let mut g = |t: f64| -> f64 {
        if t == t0 {
            return gap_of(m, k, y0);
        }
        if t == t1 {
            return gap_of(m, k, y1);
        }
        ode.trial_step(f, t0, y0, t - t0, trial);
        gap_of(m, k, trial)
    };
    let (mut lo, mut hi) = (a, b);
    let mut glo = g(lo);
    if glo <= 0.0 {
        lo = t0;
        glo = gap_of(m, k, y0);
    }
    let mut ghi = g(hi);
    if ghi > 0.0 {
        hi = t1;
        ghi = gap_of(m, k, y1);
    }
    if !(glo > 0.0 && ghi <= 0.0) {
        return None;
    }
    // The gap falls through zero: its negative rises through zero, to round-off of t.
    Some(illinois_with_bisection(|t| -g(t), lo, -glo, hi, -ghi))
}

/// Persistent contact of a round body: sliding (closed form) until rolling, then rolling to
/// the end time, or rest. Returns the stop reason and its time.
fn roll<M: Mechanism + ?Sized>(
    m: &M,
    body: &crate::mechanism::RoundOnFloor,
    mut state: Rolling,
    options: &SimulationOptions,
    rec: &mut Recorder<'_, M>,
    events: &mut Vec<(f64, EventKind)>,
) -> (StopReason, f64) {
    let (mu, g, until) = (options.friction, m.gravity(), options.until);
    let speed_scale = state.vx.abs() + (body.radius * state.omega).abs();
    let mut t = state.t0;
    let push = |rec: &mut Recorder<'_, M>, s: &Rolling, mode: Mode| {
        rec.push(s.t0, &s.state(body), mode);
    };
    rec.next = rec.next.max((t / rec.dt).floor() as u64 + 1);
    let sliding = state.sliding_time(body, mu, g);
    if sliding > 0.0 {
        events.push((t, EventKind::Sliding));
        push(rec, &state, Mode::Sliding);
        let end = (t + sliding).min(until);
        while rec.next_time() < end {
            let s = state.sliding_at(body, mu, g, rec.next_time());
            push(rec, &s, Mode::Sliding);
            rec.next += 1;
        }
        if t + sliding >= until {
            let s = state.sliding_at(body, mu, g, until);
            push(rec, &s, Mode::Sliding);
            return (StopReason::TimeLimit, until);
        }
        state = state.sliding_at(body, mu, g, t + sliding);
        state.omega = -state.vx / body.radius; // the slip is exactly zero from here on
        t = state.t0;
    }
    if state.vx.abs() <= 1e-12 * speed_scale.max(f64::MIN_POSITIVE) || state.vx == 0.0 {
        state.vx = 0.0;
        state.omega = 0.0;
        events.push((t, EventKind::Rest));
        push(rec, &state, Mode::Rest);
        return (StopReason::Rest, t);
    }
    events.push((t, EventKind::Rolling));
    push(rec, &state, Mode::Rolling);
    while rec.next_time() < until {
        let s = state.rolling_at(rec.next_time());
        push(rec, &s, Mode::Rolling);
        rec.next += 1;
    }
    push(rec, &state.rolling_at(until), Mode::Rolling);
    (StopReason::TimeLimit, until)
}
