//! The event-driven loop: a step of the flight with its dense output, the gaps watched on it,
//! the first crossing located on the discrete solution, an impact and what follows it.

use super::impact::{strike, At, Struck};
use super::motion::{renormalise, Equations, Geometry};
use super::record::{ImpactRecord, Ledger, Persistence, Run, StopReason};
use crate::error::Result;
use crate::multibody::{forward_dynamics_in, gap_rates, Model, Workspace};
use crate::numerics::budget::StepBudget;
use crate::ode::Dopri5;
use crate::simulation::events::{accumulation, locate};
use crate::simulation::watch::{watch_times, Watch};
use crate::simulation::{EventKind, Mode, Sample, SimulationOptions};

/// Relative round-off of velocities: a normal velocity within this fraction of the run's
/// speed scale is zero (as in the planar run).
pub(super) const VELOCITY_ROUND_OFF: f64 = 1e-9;

/// Points of each step's dense output at which the gaps are watched (with the sample times
/// inside the step).
const PARTS: usize = 8;

/// Where the run is.
pub(super) struct Sim<'a> {
    pub model: &'a Model,
    pub opt: SimulationOptions,
    pub eq: Equations<'a>,
    pub geo: Geometry<'a>,
    pub ode: Dopri5,
    pub t: f64,
    /// `(q, u)`.
    pub y: Vec<f64>,
    pub samples: Vec<Sample>,
    /// The index of the next regular sample (at `next · dt`).
    pub next: u64,
    pub impacts: Vec<ImpactRecord>,
    pub events: Vec<(f64, EventKind)>,
    pub ledger: Ledger,
    /// `T + V` at the start of the current flight.
    pub flight_energy: f64,
    /// Impact times (accumulation).
    pub series: Vec<f64>,
    /// The largest contact speed of the run (and `√(g ℓ)`).
    pub vscale: f64,
    pub quaternion_drift: f64,
}

/// One step and its dense output at the watch times.
struct Dense {
    t0: f64,
    t1: f64,
    ystart: Vec<f64>,
    y1: Vec<f64>,
    /// The regular samples inside the step.
    inside: Vec<(f64, Vec<f64>)>,
    /// The times at which the gaps are watched and every contact's gap there: [`PARTS`]
    /// equal parts of the step and the samples inside it, ascending, then `t1`; and more
    /// where a contact could touch the floor unseen between two of them
    /// ([`crate::simulation::watch`]).
    gap_watch: Watch,
}

impl<'a> Sim<'a> {
    fn nq(&self) -> usize {
        self.model.nq()
    }

    fn tol_v(&self) -> f64 {
        VELOCITY_ROUND_OFF * self.vscale
    }

    /// Record the state `y` at `t` (its quaternions renormalised), unless it repeats the last
    /// sample.
    fn push(&mut self, t: f64, y: &[f64]) -> Result<()> {
        let nq = self.nq();
        let mut y = y.to_vec();
        renormalise(self.model, &mut y[..nq]);
        if let Some(last) = self.samples.last() {
            if last.t == t && last.q == y[..nq] && last.u == y[nq..] {
                return Ok(());
            }
        }
        let (kinetic, potential) = self.geo.energies(&y)?;
        self.samples.push(Sample {
            t,
            q: y[..nq].to_vec(),
            u: y[nq..].to_vec(),
            kinetic,
            potential,
            mode: Mode::Flight,
        });
        Ok(())
    }

    pub(super) fn run(mut self) -> Result<Run> {
        self.push(0.0, &self.y.clone())?;
        // A contact touching at the start: struck at t = 0 if it approaches; else it may be
        // persistent.
        let y = self.y.clone();
        let touching = self.geo.touching(&y);
        let mut pending = None;
        for &k in &touching {
            if self.rates(k)?[1] < -self.tol_v() {
                pending = Some(k);
                break;
            }
        }
        if pending.is_none() {
            if let Some(stop) = self.persistent(&touching, false)? {
                return self.finish(stop);
            }
        }
        self.start(self.opt.until)?;
        loop {
            if let Some(k) = pending.take() {
                if let Some(stop) = self.arrive(k)? {
                    return self.finish(stop);
                }
            }
            if self.t >= self.opt.until {
                return self.finish(StopReason::TimeLimit);
            }
            pending = self.advance()?;
        }
    }

    /// `[φ, φ̇, φ̈]` of contact `k` at the current state.
    fn rates(&mut self, k: usize) -> Result<[f64; 3]> {
        let (model, nq) = (self.model, self.nq());
        let mut ws = Workspace::new(model);
        let (q, u) = self.y.split_at(nq);
        ws.update(model, q)?;
        let mut udot = vec![0.0; model.nv()];
        forward_dynamics_in(model, &mut ws, u, &vec![0.0; model.nv()], &mut udot)?;
        Ok(gap_rates(model, ws.configuration(), u, &udot, k))
    }

    /// (Re)start the integrator at the current state, the first step within `span`.
    fn start(&mut self, span: f64) -> Result<()> {
        let span = span.min(self.opt.until - self.t).max(f64::MIN_POSITIVE);
        let eq = &mut self.eq;
        let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| eq.derivative(y, dy);
        self.ode.start(&mut f, self.t, &self.y, span)
    }

    /// Whether one of `contacts` (touching the floor at the current state) is persistent: it
    /// neither approaches nor leaves and is pressed into the floor, or its bounce is lower
    /// than the touching tolerance. `after_impact` names the first kind `closed` (else
    /// `pressed`).
    fn persistent(&mut self, contacts: &[usize], after_impact: bool) -> Result<Option<StopReason>> {
        let tol_v = self.tol_v();
        for &k in contacts {
            let [_, rate, accel] = self.rates(k)?;
            let cause = if rate <= tol_v {
                (accel <= 0.0).then_some(if after_impact {
                    Persistence::Closed
                } else {
                    Persistence::Pressed
                })
            } else {
                let height = rate * rate / (2.0 * -accel);
                let y = self.y.clone();
                (accel < 0.0 && height <= self.geo.touching_tolerance(&y, k))
                    .then_some(Persistence::LowBounce { height })
            };
            if let Some(cause) = cause {
                return Ok(Some(StopReason::PersistentContact { contact: k, cause }));
            }
        }
        Ok(None)
    }

    /// Contact `k` reaches the floor at the current state: an impact if it approaches, else
    /// it may be persistent. Then the integrator restarts, its first step within a quarter
    /// of the shortest coming flight (`2 φ̇ / |φ̈|`) of the contacts that just left.
    fn arrive(&mut self, k: usize) -> Result<Option<StopReason>> {
        let struck = self.rates(k)?[1] < -self.tol_v();
        let leaving = if struck {
            match self.impact(k)? {
                Ok(contacts) => contacts,
                Err(stop) => return Ok(Some(stop)),
            }
        } else {
            vec![k]
        };
        if let Some(stop) = self.persistent(&leaving, struck)? {
            return Ok(Some(stop));
        }
        let mut flight = f64::INFINITY;
        for &j in &leaving {
            let [_, rate, accel] = self.rates(j)?;
            if accel < 0.0 && rate > 0.0 {
                flight = flight.min(2.0 * rate / -accel);
            }
        }
        self.start(0.25 * flight)?;
        Ok(None)
    }

    /// The impact of contact `k` at the current state, with every contact touching: the
    /// contacts of the impact, or the stop.
    fn impact(&mut self, k: usize) -> Result<std::result::Result<Vec<usize>, StopReason>> {
        if self.impacts.len() >= self.opt.max_impacts {
            return Ok(Err(StopReason::ImpactLimit));
        }
        let (model, nq) = (self.model, self.nq());
        renormalise(model, &mut self.y[..nq]);
        let y = self.y.clone();
        let others: Vec<usize> = self
            .geo
            .touching(&y)
            .into_iter()
            .filter(|&j| j != k)
            .collect();
        let (_, potential) = self.geo.energies(&y)?;
        let at = At {
            t: self.t,
            q: &y[..nq],
            u: &y[nq..],
            potential,
        };
        let record = match strike(model, at, k, &others, &self.opt)? {
            Struck::Stop(stop) => return Ok(Err(stop)),
            Struck::Record(r) => *r,
        };
        let speed = record
            .contact_velocities_before
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        self.vscale = self.vscale.max(speed);
        let before = self.geo.energy(&y)?;
        self.ledger.drift += before - self.flight_energy;
        self.push(self.t, &y)?;
        self.ledger.impacts += record.law_energy_change;
        self.y[nq..].copy_from_slice(&record.u_after);
        let y = self.y.clone();
        self.flight_energy = self.geo.energy(&y)?;
        let contacts = record.contacts.clone();
        self.impacts.push(record);
        self.events.push((
            self.t,
            EventKind::Impact {
                index: self.impacts.len() - 1,
            },
        ));
        self.push(self.t, &y)?;
        self.series.push(self.t);
        if let Some((limit_time, ratio)) = accumulation(&self.series, self.opt.sample_interval) {
            self.events.push((
                self.t,
                EventKind::Zeno {
                    contact: k,
                    limit_time,
                    ratio,
                },
            ));
            return Ok(Err(StopReason::PersistentContact {
                contact: k,
                cause: Persistence::Accumulation { limit_time, ratio },
            }));
        }
        Ok(Ok(contacts))
    }

    /// The end of a run at the current state, recorded as its last sample.
    fn finish(mut self, stop: StopReason) -> Result<Run> {
        let y = self.y.clone();
        self.push(self.t, &y)?;
        let end = self.geo.energy(&y)?;
        self.ledger.drift += end - self.flight_energy;
        self.ledger.end = end;
        Ok(Run {
            samples: self.samples,
            impacts: self.impacts,
            events: self.events,
            stop,
            end_time: self.t,
            steps: (self.ode.accepted, self.ode.rejected),
            ledger: self.ledger,
            quaternion_drift: self.quaternion_drift,
        })
    }

    /// One step of the flight: the step, its samples, and the first contact to reach the
    /// floor in it (the state moved there), if any.
    fn advance(&mut self) -> Result<Option<usize>> {
        let dense = self.step()?;
        let event = self.first_crossing(&dense);
        let nq = self.nq();
        let Some((k, te)) = event else {
            for (ts, ys) in &dense.inside {
                self.push(*ts, ys)?;
            }
            self.y.copy_from_slice(&dense.y1);
            self.t = dense.t1;
            if let Some(drift) = renormalise(self.model, &mut self.y[..nq]) {
                self.quaternion_drift = self.quaternion_drift.max(drift);
                let eq = &mut self.eq;
                let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| eq.derivative(y, dy);
                self.ode.restart(&mut f, self.t, &self.y)?;
            }
            return Ok(None);
        };
        for (ts, ys) in &dense.inside {
            if *ts < te {
                self.push(*ts, ys)?;
            } else {
                let dt = self.opt.sample_interval;
                self.next = self.next.min((ts / dt).round() as u64);
            }
        }
        if te > dense.t0 {
            let mut trial = vec![0.0; self.y.len()];
            let eq = &mut self.eq;
            let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| eq.derivative(y, dy);
            self.ode
                .trial_step(&mut f, dense.t0, &dense.ystart, te - dense.t0, &mut trial);
            self.y.copy_from_slice(&trial);
        } else {
            self.y.copy_from_slice(&dense.ystart);
        }
        self.t = te;
        Ok(Some(k))
    }

    /// Take a step and interpolate its dense output at the regular samples inside it and at
    /// [`PARTS`] equal parts of it.
    fn step(&mut self) -> Result<Dense> {
        let until = self.opt.until;
        // One budget for the whole run, judged before every step.
        let budget = StepBudget {
            max: super::SIMULATION_MAX_STEPS,
            duration: until,
            field: "until",
        };
        let eq = &mut self.eq;
        let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| eq.derivative(y, dy);
        let step = self.ode.advance_within(&budget, self.t, &mut f, until)?;
        let (t0, t1) = (step.t0, step.t1);
        let mut buf = vec![0.0; step.y0.len()];
        let mut inside: Vec<(f64, Vec<f64>)> = Vec::new();
        loop {
            let ts = self.next as f64 * self.opt.sample_interval;
            if ts > t1 || ts > until {
                break;
            }
            step.interpolate(ts, &mut buf);
            inside.push((ts, buf.clone()));
            self.next += 1;
        }
        let mut times: Vec<f64> = (1..PARTS)
            .map(|j| t0 + (t1 - t0) * j as f64 / PARTS as f64)
            .chain(inside.iter().map(|s| s.0))
            .filter(|&tj| tj > t0 && tj < t1)
            .collect();
        times.sort_by(f64::total_cmp);
        times.push(t1);
        let states: Vec<Vec<f64>> = times
            .iter()
            .map(|&tj| {
                if tj == t1 {
                    step.y1.to_vec()
                } else {
                    step.interpolate(tj, &mut buf);
                    buf.clone()
                }
            })
            .collect();
        let ystart = step.y0.to_vec();
        let geo = &mut self.geo;
        let gap_watch = watch_times(
            |t, y| step.interpolate(t, y),
            |t, y| geo.probe(t, y),
            t0,
            &ystart,
            &times,
            &states,
        );
        Ok(Dense {
            t0,
            t1,
            ystart,
            y1: step.y1.to_vec(),
            inside,
            gap_watch,
        })
    }

    /// The first contact to reach the floor in the step: one at or below it at the step's
    /// start that goes further below its tolerance (an arrival at the start), else the
    /// earliest fall of a gap from positive to ≤ 0 on the dense output, located on the
    /// discrete solution (a bracket the discrete solution does not cross is a graze, no
    /// event).
    fn first_crossing(&mut self, dense: &Dense) -> Option<(usize, f64)> {
        let nc = self.model.contacts().len();
        let mut g0 = vec![0.0; nc];
        self.geo.gaps(&dense.ystart, &mut g0);
        let mut brackets = Vec::new();
        for k in 0..nc {
            let tol = self.geo.touching_tolerance(&dense.ystart, k);
            let mut prev = (dense.t0, g0[k]);
            for (tj, g) in &dense.gap_watch {
                let tj = *tj;
                if prev.1 > 0.0 && g[k] <= 0.0 {
                    brackets.push((k, prev.0, tj));
                    break;
                }
                if g0[k] <= 0.0 && g[k] < -tol && g[k] < g0[k] {
                    return Some((k, dense.t0));
                }
                prev = (tj, g[k]);
            }
        }
        let mut event: Option<(usize, f64)> = None;
        let mut trial = vec![0.0; dense.ystart.len()];
        for (k, a, b) in brackets {
            if event.is_some_and(|(_, te)| te <= a) {
                continue;
            }
            let eq = &mut self.eq;
            let geo = &mut self.geo;
            let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| eq.derivative(y, dy);
            let mut g = |y: &[f64]| geo.gap(y, k);
            let located = locate(
                &mut self.ode,
                &mut f,
                dense.t0,
                &dense.ystart,
                dense.t1,
                &dense.y1,
                a,
                b,
                &mut trial,
                &mut g,
            );
            if let Some(te) = located {
                if event.is_none_or(|(_, first)| te < first) {
                    event = Some((k, te));
                }
            }
        }
        event
    }
}
