//! Persistent contact of a round body with a horizontal floor, in closed form: Coulomb
//! sliding until the slip vanishes, then rolling at constant speed.
//!
//! With `q = (x, y, θ)`, the slip `s = ẋ + r θ̇` and normal force `N = m g`, sliding gives
//! `ẍ = −μ g σ`, `θ̈ = −μ m g r σ / I` (σ = sign s), so `ṡ = −μ g σ (1 + m r²/I)` and rolling
//! starts at `t* = |s| / (μ g (1 + m r²/I))`; rolling keeps `ẋ` and `θ̇ = −ẋ / r`.

use super::record::{EventKind, Mode, Recorder, StopReason};
use super::SimulationOptions;
use crate::mechanism::{dynamics, Mechanism, RoundOnFloor};

/// The state of a round body in contact at time `t0`: `(x, ẋ, θ, θ̇)` (y = floor + r, ẏ = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rolling {
    pub t0: f64,
    pub x: f64,
    pub vx: f64,
    pub theta: f64,
    pub omega: f64,
}

/// The constant deceleration of the slip while sliding, `μ g (1 + m r²/I)` (0 when μ = 0).
fn slip_rate(body: &RoundOnFloor, mu: f64, g: f64) -> f64 {
    mu * g * (1.0 + body.mass * body.radius * body.radius / body.inertia)
}

impl Rolling {
    /// The slip `s = ẋ + r θ̇`.
    pub fn slip(&self, body: &RoundOnFloor) -> f64 {
        self.vx + body.radius * self.omega
    }

    /// How long sliding lasts (`+∞` without friction or gravity; 0 when already rolling).
    pub fn sliding_time(&self, body: &RoundOnFloor, mu: f64, g: f64) -> f64 {
        let s = self.slip(body);
        if s == 0.0 {
            return 0.0;
        }
        let rate = slip_rate(body, mu, g);
        if rate > 0.0 {
            s.abs() / rate
        } else {
            f64::INFINITY
        }
    }

    /// The state at `t ≥ t0` while sliding (valid up to the end of sliding).
    pub fn sliding_at(&self, body: &RoundOnFloor, mu: f64, g: f64, t: f64) -> Rolling {
        let tau = t - self.t0;
        let sigma = crate::math::sign(self.slip(body));
        let ax = -mu * g * sigma;
        let alpha = -mu * body.mass * g * body.radius * sigma / body.inertia;
        Rolling {
            t0: t,
            x: self.x + self.vx * tau + 0.5 * ax * tau * tau,
            vx: self.vx + ax * tau,
            theta: self.theta + self.omega * tau + 0.5 * alpha * tau * tau,
            omega: self.omega + alpha * tau,
        }
    }

    /// The state at `t ≥ t0` while rolling (no slip: `θ̇ = −ẋ/r` kept exactly).
    pub fn rolling_at(&self, t: f64) -> Rolling {
        let tau = t - self.t0;
        Rolling {
            t0: t,
            x: self.x + self.vx * tau,
            vx: self.vx,
            theta: self.theta + self.omega * tau,
            omega: self.omega,
        }
    }

    /// The generalized state `(x, y, θ, ẋ, ẏ, θ̇)`.
    pub fn state(&self, body: &RoundOnFloor) -> [f64; 6] {
        [
            self.x,
            body.floor + body.radius,
            self.theta,
            self.vx,
            0.0,
            self.omega,
        ]
    }
}

/// Persistent contact of a round body: sliding (closed form) until rolling, then rolling to
/// the end time, or rest. Returns the stop reason, its time and the energy `T + V` there.
pub(crate) fn roll<M: Mechanism + ?Sized>(
    m: &M,
    body: &RoundOnFloor,
    mut state: Rolling,
    options: &SimulationOptions,
    rec: &mut Recorder<'_, M>,
    events: &mut Vec<(f64, EventKind)>,
) -> (StopReason, f64, f64) {
    let (mu, g, until) = (options.friction, m.gravity(), options.until);
    let speed_scale = state.vx.abs() + (body.radius * state.omega).abs();
    let mut t = state.t0;
    let n = m.dof();
    let energy_of = |s: &Rolling| {
        let y = s.state(body);
        dynamics::kinetic_energy(m, &y[..n], &y[n..]) + dynamics::potential_energy(m, &y[..n])
    };
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
            return (StopReason::TimeLimit, until, energy_of(&s));
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
        return (StopReason::Rest, t, energy_of(&state));
    }
    events.push((t, EventKind::Rolling));
    push(rec, &state, Mode::Rolling);
    while rec.next_time() < until {
        let s = state.rolling_at(rec.next_time());
        push(rec, &s, Mode::Rolling);
        rec.next += 1;
    }
    let last = state.rolling_at(until);
    push(rec, &last, Mode::Rolling);
    (StopReason::TimeLimit, until, energy_of(&last))
}
