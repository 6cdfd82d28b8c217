//! An impact in the run and what follows it: an accumulation of impacts completed, the
//! contacts that stay closed, or a round body's closed form.

use super::{energy, touching, Cause, Sim, VELOCITY_ROUND_OFF};
use crate::error::{Error, Result};
use crate::math::Vec2;
use crate::mechanism::dynamics;
use crate::mechanism::Mechanism;
use crate::simulation::closed::Hint;
use crate::simulation::contact::{roll, Rolling};
use crate::simulation::events::accumulation;
use crate::simulation::impacts::{strike, Struck};
use crate::simulation::record::{EventKind, StopReason};

impl<M: Mechanism + ?Sized> Sim<'_, M> {
    /// The impact of contact `k` at the current state, with every contact touching.
    pub(super) fn impact(&mut self, k: usize) -> Result<Option<StopReason>> {
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
    /// Persistent contact of contact `k` that the closed form continues: a round body on a
    /// horizontal floor, with its state `(x, ẋ, θ, θ̇)`.
    pub(super) fn rolling_from(
        &self,
        k: usize,
    ) -> Option<(crate::mechanism::RoundOnFloor, Rolling)> {
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
    pub(super) fn roll(&mut self, k: usize) -> Result<StopReason> {
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
}
