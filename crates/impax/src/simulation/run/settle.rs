//! Which contacts stay closed, and how: the acceleration-level contact problem at the current
//! state, the projections onto the closed contacts, rest and Painlevé's paradox.

use super::{energy, touching, Cause, Sim, VELOCITY_ROUND_OFF};
use crate::error::Result;
use crate::mechanism::dynamics;
use crate::mechanism::Mechanism;
use crate::planar::SlipDirection;
use crate::simulation::closed::{self, Closed, ContactDynamics, Hint, Regime, FORCE_ROUND_OFF};
use crate::simulation::record::{EventKind, StopReason};

impl<M: Mechanism + ?Sized> Sim<'_, M> {
    /// Contacts touching at the current state that neither approach nor leave, with the
    /// closed ones: they may stay closed. A round body goes to its closed form.
    pub(super) fn settle_touching(&mut self) -> Result<Option<StopReason>> {
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
    /// Close `contacts` at the current state: project their gaps and normal velocities to
    /// zero, and the tangential velocities of those that roll (`|v_t|` within round-off of the
    /// run's speeds), so that a sticking contact keeps sticking (a correction of the size of
    /// a bounce below the touching tolerance).
    pub(super) fn project_normals(&mut self, contacts: &[usize]) -> Result<()> {
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
    pub(super) fn project(&mut self) -> Result<()> {
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
    pub(super) fn settle(
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
    /// A state of the dense output put on the closed contacts (for the samples).
    pub(super) fn on_contacts(&self, mut y: Vec<f64>) -> Result<Vec<f64>> {
        if !self.closed.is_empty() {
            let n = self.n;
            let (q, rest) = y.split_at_mut(n);
            closed::project(self.m, q, &mut rest[..n], &self.closed)?;
        }
        Ok(y)
    }
}
