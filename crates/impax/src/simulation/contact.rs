//! Persistent contact of a round body with a horizontal floor, in closed form: Coulomb
//! sliding until the slip vanishes, then rolling at constant speed.
//!
//! With `q = (x, y, θ)`, the slip `s = ẋ + r θ̇` and normal force `N = m g`, sliding gives
//! `ẍ = −μ g σ`, `θ̈ = −μ m g r σ / I` (σ = sign s), so `ṡ = −μ g σ (1 + m r²/I)` and rolling
//! starts at `t* = |s| / (μ g (1 + m r²/I))`; rolling keeps `ẋ` and `θ̇ = −ẋ / r`.

use crate::mechanism::RoundOnFloor;

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
