//! One step of the motion with its events: the step and its dense output, the watched
//! quantities on it (the gaps of the open contacts, the forces and slips of the closed ones),
//! the first event located on the discrete solution, and the state moved to the step's end or
//! to the event.

use super::{rhs, touching, Advance, Cause, Sim, PARTS, STALL};
use crate::error::{Error, Result};
use crate::mechanism::dynamics;
use crate::mechanism::Mechanism;
use crate::numerics::budget::StepBudget;
use crate::simulation::closed::{self, Closed, Hint, Regime, FORCE_ROUND_OFF};
use crate::simulation::events::{gap_of, locate, watched, watched_value, Watched};
use crate::simulation::record::Mode;
use crate::simulation::watch::{watch_times, Probe, Watch};
use crate::simulation::{StopReason, SIMULATION_MAX_STEPS};

/// A sliding contact whose force coefficient is within this fraction of its terms when the
/// integration cannot go on is jammed at the Painlevé bound ([`Sim::jam`]).
const JAM: f64 = 1e-6;

/// One step of the integrator and its dense output at the watch times.
struct Dense {
    /// The step's start.
    t0: f64,
    /// The step's end.
    t1: f64,
    /// The state at `t0`.
    ystart: Vec<f64>,
    /// The state at `t1`.
    y1: Vec<f64>,
    /// The regular samples inside the step (kept only before the event, if any).
    inside: Vec<(f64, Vec<f64>)>,
    /// The watch times inside the step, ascending, then `t1`.
    times: Vec<f64>,
    /// The states at `times`.
    states: Vec<Vec<f64>>,
    /// The times at which the open contacts' gaps are watched and the gaps there (in the
    /// contacts' order): `times` and more where a contact could touch its surface unseen
    /// between two of them (`watch.rs`).
    gap_watch: Watch,
}

/// The watched quantities' falls through zero in a step.
#[derive(Default)]
struct Crossings {
    /// A fall from positive to ≤ 0 between two watch times: `(what, a, b)`.
    brackets: Vec<(Watched, f64, f64)>,
    /// The first quantity at or below zero at the step's start that goes further below its
    /// round-off: an event at the start.
    at_start: Option<Watched>,
    /// The sliding regime's determinant at the step's start.
    det0: f64,
}

impl<M: Mechanism + ?Sized> Sim<'_, M> {
    /// One step of the motion, with its events.
    pub(super) fn advance(&mut self) -> Result<Advance> {
        let closed = self.closed.clone();
        let mut f = rhs(self.m, closed.clone(), self.opt.friction, self.wscale);
        let dense = match self.step(&mut f) {
            Ok(dense) => dense,
            Err(error @ Error::Integration { .. }) => {
                return match self.jam(&closed)? {
                    Some(stop) => Ok(Advance::Stop(stop)),
                    None => Err(error),
                };
            }
            Err(error) => return Err(error),
        };
        let mut crossings = Crossings::default();
        self.watch_gaps(&closed, &dense, &mut crossings);
        self.watch_closed(&closed, &dense, &mut crossings)?;
        let event = self.first_event(&mut f, &closed, &dense, crossings);
        let mode = self.mode();
        let Some((what, te)) = event else {
            self.reach_step_end(&mut f, dense, mode)?;
            return Ok(Advance::Free);
        };
        self.reach_event(&mut f, dense, te, mode)?;
        if let Watched::Gap(k) = what {
            return Ok(Advance::Arrival(k));
        }
        self.regime_change(what, mode)
    }

    /// The sliding motion cannot be integrated on (the step size underflowed) at the current
    /// state: if a sliding contact's force coefficient has reached zero there ([`JAM`] of its
    /// terms), the contact is jammed at the Painlevé bound — its force grows without bound as
    /// the coefficient and the free normal acceleration vanish together (Génot & Brogliato
    /// 1999; the "dynamic jam") and no bounded force continues the slip: Painlevé's paradox,
    /// with no solution. Else `None` (the failure stands).
    fn jam(&self, closed: &[Closed]) -> Result<Option<StopReason>> {
        let Some(sliding) = closed.iter().find(|c| matches!(c.regime, Regime::Slip(_))) else {
            return Ok(None);
        };
        let w = closed::watch(self.m, closed, self.opt.friction, &self.y)?;
        Ok(
            (w.coefficient.abs() <= JAM).then_some(StopReason::Painleve {
                contact: sliding.contact,
                solutions: 0,
            }),
        )
    }

    /// Take a step and interpolate its dense output at the regular samples inside it and at
    /// [`PARTS`] equal parts of it.
    fn step(&mut self, f: &mut impl FnMut(f64, &[f64], &mut [f64])) -> Result<Dense> {
        let n = self.n;
        let until = self.opt.until;
        // One budget for the whole run, judged before every step (as in 3D).
        let budget = StepBudget {
            max: SIMULATION_MAX_STEPS,
            duration: until,
            field: "until",
        };
        let step = self.ode.advance_within(&budget, self.t, f, until)?;
        let (t0, t1) = (step.t0, step.t1);
        let ystart = step.y0.to_vec();
        let y1 = step.y1.to_vec();
        let mut buf = vec![0.0; 2 * n + 1];
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
        // The gaps' watch: more times where an open contact could dip through unseen.
        let m = self.m;
        let open: Vec<usize> = (0..m.contacts().len())
            .filter(|&k| !self.closed.iter().any(|c| c.contact == k))
            .collect();
        let gap_watch = if open.is_empty() {
            Vec::new()
        } else {
            watch_times(
                |t, y| step.interpolate(t, y),
                |t, y| Probe::planar(m, &open, n, t, y),
                t0,
                &ystart,
                &times,
                &states,
            )
        };
        Ok(Dense {
            t0,
            t1,
            ystart,
            y1,
            inside,
            times,
            states,
            gap_watch,
        })
    }

    /// The gaps of the open contacts on the dense output: the first fall from positive to
    /// ≤ 0 brackets an arrival; a gap at or below zero at the step's start that goes further
    /// below its round-off arrives at the start.
    fn watch_gaps(&self, closed: &[Closed], dense: &Dense, crossings: &mut Crossings) {
        let (m, n) = (self.m, self.n);
        let Dense {
            t0,
            ystart,
            gap_watch,
            ..
        } = dense;
        let open = (0..m.contacts().len()).filter(|&k| !closed.iter().any(|c| c.contact == k));
        for (i, k) in open.enumerate() {
            let g0 = gap_of(m, k, ystart);
            let tol = dynamics::touching_tolerance(m, k, &ystart[..n]);
            let mut prev = (*t0, g0);
            for (tj, gaps) in gap_watch {
                let (tj, g) = (*tj, gaps[i]);
                if prev.1 > 0.0 && g <= 0.0 {
                    crossings.brackets.push((Watched::Gap(k), prev.0, tj));
                    break;
                }
                if g0 <= 0.0 && g < -tol && g < g0 {
                    crossings.at_start = crossings.at_start.or(Some(Watched::Gap(k)));
                    break;
                }
                prev = (tj, g);
            }
        }
    }

    /// The forces, slips and friction margins of the closed contacts on the dense output
    /// (and the sliding regime's determinant), bracketed as the gaps are.
    fn watch_closed(
        &self,
        closed: &[Closed],
        dense: &Dense,
        crossings: &mut Crossings,
    ) -> Result<()> {
        if closed.is_empty() {
            return Ok(());
        }
        let (m, mu) = (self.m, self.opt.friction);
        let Dense {
            t0,
            ystart,
            times,
            states,
            ..
        } = dense;
        let watch0 = closed::watch(m, closed, mu, ystart)?;
        crossings.det0 = watch0.det;
        let values: Vec<Vec<(Watched, f64)>> = std::iter::once(ystart)
            .chain(states.iter())
            .map(|y| {
                closed::watch(m, closed, mu, y)
                    .map(|w| watched(closed, &w, mu, watch0.det))
                    .unwrap_or_default()
            })
            .collect();
        let scale = values
            .iter()
            .flatten()
            .filter(|(w, _)| matches!(w, Watched::Force(_) | Watched::Margin(_)))
            .fold(0.0f64, |s, (_, g)| s.max(g.abs()));
        let mut all_times = vec![*t0];
        all_times.extend(times);
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
                    crossings
                        .brackets
                        .push((what, all_times[s - 1], all_times[s]));
                    break;
                }
                if g0 <= 0.0 && g < -tol && g < g0 {
                    crossings.at_start = crossings.at_start.or(Some(what));
                    break;
                }
            }
        }
        Ok(())
    }

    /// The first event of the step: one at its start, else the earliest crossing located on
    /// the discrete solution (a bracket the discrete solution does not cross is no event).
    fn first_event(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        closed: &[Closed],
        dense: &Dense,
        crossings: Crossings,
    ) -> Option<(Watched, f64)> {
        let (m, n, mu) = (self.m, self.n, self.opt.friction);
        let Crossings {
            brackets,
            at_start,
            det0,
        } = crossings;
        let mut event: Option<(Watched, f64)> = at_start.map(|w| (w, dense.t0));
        if event.is_none() {
            let mut trial = vec![0.0; 2 * n + 1];
            for (what, a, b) in brackets {
                if event.is_some_and(|(_, te)| te <= a) {
                    continue;
                }
                let located = {
                    let mut g = |y: &[f64]| watched_value(m, mu, closed, what, y, det0);
                    locate(
                        &mut self.ode,
                        f,
                        dense.t0,
                        &dense.ystart,
                        dense.t1,
                        &dense.y1,
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
        event
    }

    /// No event in the step: record its samples and go to its end, projected onto the closed
    /// contacts (the integrator restarted if the projection moved the state).
    fn reach_step_end(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        dense: Dense,
        mode: Mode,
    ) -> Result<()> {
        for (ts, ys) in dense.inside {
            let ys = self.on_contacts(ys)?;
            self.rec.push(ts, &ys, mode);
        }
        self.y.copy_from_slice(&dense.y1);
        self.t = dense.t1;
        if !self.closed.is_empty() {
            let before = self.y.clone();
            self.project()?;
            if self.y != before {
                self.ode.restart(f, self.t, &self.y)?;
            }
        }
        Ok(())
    }

    /// An event at `te`: record the samples before it and go to the state at `te` on the
    /// discrete solution. Errors when the events at one instant do not end.
    fn reach_event(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        dense: Dense,
        te: f64,
        mode: Mode,
    ) -> Result<()> {
        let n = self.n;
        for (ts, ys) in dense.inside {
            if ts < te {
                let ys = self.on_contacts(ys)?;
                self.rec.push(ts, &ys, mode);
            } else {
                self.rec.next = self.rec.next.min((ts / self.rec.dt).round() as u64);
            }
        }
        if te > dense.t0 {
            let mut trial = vec![0.0; 2 * n + 1];
            self.ode
                .trial_step(f, dense.t0, &dense.ystart, te - dense.t0, &mut trial);
            self.y.copy_from_slice(&trial);
        } else {
            self.y.copy_from_slice(&dense.ystart);
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
        Ok(())
    }

    /// A change of the closed contacts' regimes (`what` fell through zero) at the current
    /// state: settle the contacts touching anew and restart the integrator.
    fn regime_change(&mut self, what: Watched, mode: Mode) -> Result<Advance> {
        let m = self.m;
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
}
