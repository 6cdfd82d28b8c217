//! The Dormand–Prince 5(4) integrator with dense output, on slices of any length (the
//! public path is [`crate::ode`], whose documentation gives the method and its source).

use super::budget::StepBudget;
use crate::error::{Error, Result};

// Butcher tableau: Dormand & Prince, J. Comp. Appl. Math. 6 (1980), table 2.
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// b − b̂, b̂ the embedded fourth-order weights (the seventh stage is the FSAL stage).
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Continuous extension (Hairer, Nørsett & Wanner, §II.6, eq. 6.12; the `contd5` of DOPRI5).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Error tolerances of an adaptive integration: a component's local error is measured
/// against `absolute + relative · |y_i|`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance (≥ 1e-15).
    pub relative: f64,
    /// Absolute tolerance (> 0).
    pub absolute: f64,
}

impl Tolerances {
    /// Tight tolerances for long conservative motions: 1e-12 relative, 1e-14 absolute.
    pub const TIGHT: Tolerances = Tolerances {
        relative: 1e-12,
        absolute: 1e-14,
    };
}

/// One accepted step, handed to the caller's observer: the interval `[t0, t1]`, the state at
/// both ends, and [`Step::interpolate`] for the dense output inside it.
pub struct Step<'a> {
    /// Start of the step.
    pub t0: f64,
    /// End of the step.
    pub t1: f64,
    /// The state at `t0`.
    pub y0: &'a [f64],
    /// The state at `t1`.
    pub y1: &'a [f64],
    cont: &'a [Vec<f64>; 5],
}

impl Step<'_> {
    /// The fourth-order continuous extension at `t ∈ [t0, t1]`, written into `out`:
    /// `y(θ) = r₁ + θ (r₂ + (1−θ) (r₃ + θ (r₄ + (1−θ) r₅)))`, θ = (t − t0)/(t1 − t0).
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        let h = self.t1 - self.t0;
        let theta = if h == 0.0 { 1.0 } else { (t - self.t0) / h };
        let theta1 = 1.0 - theta;
        let [r1, r2, r3, r4, r5] = self.cont;
        for i in 0..out.len() {
            out[i] = r1[i] + theta * (r2[i] + theta1 * (r3[i] + theta * (r4[i] + theta1 * r5[i])));
        }
    }
}

/// Dormand–Prince 5(4) with adaptive steps and dense output, for state vectors of a fixed
/// length chosen at construction (the workspace is allocated once).
///
/// Two ways to drive it: [`Dopri5::integrate`] over an interval with an observer, or
/// step by step with [`Dopri5::start`] and [`Dopri5::advance`] (for event-driven
/// simulation), with [`Dopri5::trial_step`] to re-step from a step's start to an event so
/// that the event lies on the discrete solution itself.
pub struct Dopri5 {
    tol: Tolerances,
    k: [Vec<f64>; 7],
    y: Vec<f64>,
    y1: Vec<f64>,
    stage: Vec<f64>,
    cont: [Vec<f64>; 5],
    trial_k: [Vec<f64>; 6],
    trial_stage: Vec<f64>,
    t: f64,
    /// The start of the last accepted step.
    t0: f64,
    h: f64,
    pending: bool,
    last_rejected: bool,
    steps: usize,
    /// Number of accepted steps so far.
    pub accepted: usize,
    /// Number of rejected steps so far.
    pub rejected: usize,
    /// Largest number of steps (accepted + rejected) between two calls to
    /// [`Dopri5::start`].
    pub max_steps: usize,
}

impl Dopri5 {
    /// An integrator for states of length `n` with the given tolerances.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] when a tolerance is not finite and positive, or the
    /// relative tolerance is below 1e-15 (below round-off, no step would be accepted).
    pub fn new(n: usize, tol: Tolerances) -> Result<Self> {
        if !(tol.relative.is_finite() && tol.relative >= 1e-15) {
            return Err(Error::OutOfRange {
                field: "relative tolerance".into(),
                value: tol.relative,
                reason: "must be finite and at least 1e-15".into(),
            });
        }
        if !(tol.absolute.is_finite() && tol.absolute > 0.0) {
            return Err(Error::OutOfRange {
                field: "absolute tolerance".into(),
                value: tol.absolute,
                reason: "must be finite and positive".into(),
            });
        }
        let v = || vec![0.0; n];
        Ok(Dopri5 {
            tol,
            k: std::array::from_fn(|_| v()),
            y: v(),
            y1: v(),
            stage: v(),
            cont: std::array::from_fn(|_| v()),
            trial_k: std::array::from_fn(|_| v()),
            trial_stage: v(),
            t: 0.0,
            t0: 0.0,
            h: 0.0,
            pending: false,
            last_rejected: false,
            steps: 0,
            accepted: 0,
            rejected: 0,
            max_steps: 1_000_000,
        })
    }

    /// Start (or restart, e.g. after an impact changed the velocities) at `(t0, y0)`;
    /// `span` bounds the first step.
    ///
    /// # Errors
    /// [`Error::Integration`] when the right-hand side is not finite at `(t0, y0)`.
    pub fn start(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t0: f64,
        y0: &[f64],
        span: f64,
    ) -> Result<()> {
        assert_eq!(
            y0.len(),
            self.y.len(),
            "state length differs from the integrator's"
        );
        self.y.copy_from_slice(y0);
        self.t = t0;
        f(t0, &self.y, &mut self.k[0]);
        if !self.k[0].iter().all(|x| x.is_finite()) {
            return Err(Error::Integration {
                reason: "the equations of motion are not finite at the initial state".into(),
            });
        }
        self.h = self.initial_step(f, t0, span.max(f64::MIN_POSITIVE));
        self.pending = false;
        self.last_rejected = false;
        self.steps = 0;
        Ok(())
    }

    /// Replace the current state by `(t, y)` — a small correction of it, such as a projection
    /// onto constraints — keeping the step size the integrator has adapted (one evaluation of
    /// `f`, where [`Dopri5::start`] estimates the first step anew).
    ///
    /// # Errors
    /// [`Error::Integration`] when the right-hand side is not finite at `(t, y)`.
    pub fn restart(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t: f64,
        y: &[f64],
    ) -> Result<()> {
        assert_eq!(
            y.len(),
            self.y.len(),
            "state length differs from the integrator's"
        );
        self.y.copy_from_slice(y);
        self.t = t;
        f(t, &self.y, &mut self.k[0]);
        if !self.k[0].iter().all(|x| x.is_finite()) {
            return Err(Error::Integration {
                reason: "the equations of motion are not finite at the corrected state".into(),
            });
        }
        self.pending = false;
        Ok(())
    }

    /// Steps (accepted and rejected) since the last [`Dopri5::start`], the count that
    /// [`Dopri5::max_steps`] bounds.
    pub(crate) fn steps_since_start(&self) -> usize {
        self.steps
    }

    /// The time of the current state (the end of the last accepted step).
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The current state (the end of the last accepted step).
    pub fn state(&self) -> &[f64] {
        if self.pending {
            &self.y1
        } else {
            &self.y
        }
    }

    /// Take one accepted step from the current state, not beyond `t_max`, and return it
    /// (with its dense output). The step's end becomes the current state.
    ///
    /// # Errors
    /// [`Error::Integration`] when the right-hand side becomes non-finite, the step size
    /// underflows, or more than [`Dopri5::max_steps`] steps are needed.
    pub fn advance(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t_max: f64,
    ) -> Result<Step<'_>> {
        self.take_step(f, t_max)?;
        Ok(self.last_step())
    }

    /// [`Dopri5::advance`] within the step budget of a whole motion now at `t`: the budget
    /// judged before the step ([`StepBudget::check`], its early verdict naming the motion's
    /// field), the step limited to what the budget leaves, and a step that fails judged by the
    /// budget again (the budget's verdict, when it applies, says more than "too many steps").
    ///
    /// # Errors
    /// The budget's verdict; the errors of [`Dopri5::advance`].
    pub(crate) fn advance_within(
        &mut self,
        budget: &StepBudget,
        t: f64,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t_max: f64,
    ) -> Result<Step<'_>> {
        let used = self.accepted + self.rejected;
        budget.check(used, t)?;
        self.max_steps = self.steps_since_start() + budget.remaining(used);
        if let Err(e) = self.take_step(f, t_max) {
            budget.check(self.accepted + self.rejected, self.t)?;
            return Err(e);
        }
        Ok(self.last_step())
    }

    /// The last accepted step (its end the current state).
    fn last_step(&self) -> Step<'_> {
        Step {
            t0: self.t0,
            t1: self.t,
            y0: &self.y,
            y1: &self.y1,
            cont: &self.cont,
        }
    }

    /// Take one accepted step ([`Dopri5::advance`]), kept for [`Dopri5::last_step`].
    fn take_step(&mut self, f: &mut impl FnMut(f64, &[f64], &mut [f64]), t_max: f64) -> Result<()> {
        if self.pending {
            std::mem::swap(&mut self.y, &mut self.y1);
            self.k.swap(0, 6);
            self.pending = false;
        }
        let t = self.t;
        let mut h = self.h;
        loop {
            self.steps += 1;
            if self.steps > self.max_steps {
                return Err(Error::Integration {
                    reason: "too many steps (the motion may be singular or stiff)".into(),
                });
            }
            let last = t + h >= t_max;
            if last {
                h = t_max - t;
            }
            let err = self.step(f, t, h);
            if !err.is_finite() {
                // A non-finite stage: shrink hard.
                h *= 0.1;
                self.rejected += 1;
                self.last_rejected = true;
                if h <= f64::EPSILON * t.abs().max(1.0) {
                    return Err(Error::Integration {
                        reason: "the equations of motion became non-finite".into(),
                    });
                }
                continue;
            }
            if err <= 1.0 {
                self.accepted += 1;
                let t1 = if last { t_max } else { t + h };
                self.dense(h);
                let fac =
                    (0.9 * err.powf(-0.2)).clamp(0.2, if self.last_rejected { 1.0 } else { 10.0 });
                // Keep the proposal of the untruncated step when the last one was shortened.
                self.h = if last { self.h.max(h) } else { h * fac };
                self.last_rejected = false;
                self.t0 = t;
                self.t = t1;
                self.pending = true;
                return Ok(());
            }
            self.rejected += 1;
            self.last_rejected = true;
            h *= (0.9 * err.powf(-0.2)).max(0.2);
            if h <= 4.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
                return Err(Error::Integration {
                    reason: "the step size underflowed (the motion may be singular)".into(),
                });
            }
        }
    }

    /// One Dormand–Prince step of size `h` from an arbitrary `(t0, y0)` without error
    /// control, the fifth-order solution written into `out` (used to place an event exactly
    /// on the discrete solution: re-step from the start of the step that contains it). Does
    /// not disturb the current step.
    pub fn trial_step(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t0: f64,
        y0: &[f64],
        h: f64,
        out: &mut [f64],
    ) {
        let n = y0.len();
        let s = &mut self.trial_stage;
        let [k1, k2, k3, k4, k5, k6] = &mut self.trial_k;
        f(t0, y0, k1);
        for i in 0..n {
            s[i] = y0[i] + h * A21 * k1[i];
        }
        f(t0 + C2 * h, s, k2);
        for i in 0..n {
            s[i] = y0[i] + h * (A31 * k1[i] + A32 * k2[i]);
        }
        f(t0 + C3 * h, s, k3);
        for i in 0..n {
            s[i] = y0[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        }
        f(t0 + C4 * h, s, k4);
        for i in 0..n {
            s[i] = y0[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        }
        f(t0 + C5 * h, s, k5);
        for i in 0..n {
            s[i] =
                y0[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        }
        f(t0 + h, s, k6);
        for i in 0..n {
            out[i] = y0[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        }
    }

    /// Integrate `y' = f(t, y)` from `(t0, y0)` to `t_end` (forward, `t_end > t0`), calling
    /// `observe` after every accepted step. The observer returns `Some(t)` to stop the
    /// integration at `t` inside the step just taken (an event it located with
    /// [`Step::interpolate`]); the state there is then the dense output. On return `y0` holds
    /// the state at the returned time.
    ///
    /// # Errors
    /// [`Error::Integration`] when the right-hand side is not finite, the step size underflows,
    /// or more than [`Dopri5::max_steps`] steps are needed.
    pub fn integrate(
        &mut self,
        mut f: impl FnMut(f64, &[f64], &mut [f64]),
        t0: f64,
        y0: &mut [f64],
        t_end: f64,
        mut observe: impl FnMut(&Step<'_>) -> Option<f64>,
    ) -> Result<f64> {
        if t_end.is_nan() || t_end <= t0 {
            return Ok(t0);
        }
        self.start(&mut f, t0, y0, t_end - t0)?;
        loop {
            let step = self.advance(&mut f, t_end)?;
            if let Some(ts) = observe(&step) {
                let ts = ts.clamp(step.t0, step.t1);
                step.interpolate(ts, y0);
                return Ok(ts);
            }
            if step.t1 >= t_end {
                y0.copy_from_slice(step.y1);
                return Ok(step.t1);
            }
        }
    }

    /// Hairer's starting step (HNW I, §II.4, "Starting step size").
    fn initial_step(
        &mut self,
        f: &mut impl FnMut(f64, &[f64], &mut [f64]),
        t: f64,
        span: f64,
    ) -> f64 {
        let n = self.y.len().max(1) as f64;
        let tol = self.tol;
        let sc = |y: f64| tol.absolute + tol.relative * y.abs();
        let d0 = (self.y.iter().map(|&y| (y / sc(y)).powi(2)).sum::<f64>() / n).sqrt();
        let d1 = (self
            .y
            .iter()
            .zip(&self.k[0])
            .map(|(&y, &k)| (k / sc(y)).powi(2))
            .sum::<f64>()
            / n)
            .sqrt();
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        let h0 = h0.min(span);
        for i in 0..self.y.len() {
            self.stage[i] = self.y[i] + h0 * self.k[0][i];
        }
        f(t + h0, &self.stage, &mut self.k[1]);
        let d2 = (self
            .y
            .iter()
            .zip(self.k[1].iter().zip(&self.k[0]))
            .map(|(&y, (&k1, &k0))| ((k1 - k0) / sc(y)).powi(2))
            .sum::<f64>()
            / n)
            .sqrt()
            / h0;
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(0.2)
        };
        let h = (100.0 * h0).min(h1).min(span);
        if h.is_finite() && h > 0.0 {
            h
        } else {
            span * 1e-6
        }
    }

    /// One trial step of size `h` from `(t, self.y)` with `k[0] = f(t, y)`: the fifth-order
    /// solution in `y1`, the stages in `k`; returns the scaled error norm (HNW eq. 4.11).
    fn step(&mut self, f: &mut impl FnMut(f64, &[f64], &mut [f64]), t: f64, h: f64) -> f64 {
        let n = self.y.len();
        let (y, s) = (&self.y, &mut self.stage);
        let [k1, k2, k3, k4, k5, k6, k7] = &mut self.k;
        for i in 0..n {
            s[i] = y[i] + h * A21 * k1[i];
        }
        f(t + C2 * h, s, k2);
        for i in 0..n {
            s[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
        }
        f(t + C3 * h, s, k3);
        for i in 0..n {
            s[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        }
        f(t + C4 * h, s, k4);
        for i in 0..n {
            s[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        }
        f(t + C5 * h, s, k5);
        for i in 0..n {
            s[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        }
        f(t + h, s, k6);
        let y1 = &mut self.y1;
        for i in 0..n {
            y1[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        }
        f(t + h, y1, k7);
        let mut sum = 0.0;
        for i in 0..n {
            let e =
                h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            let sc = self.tol.absolute + self.tol.relative * y[i].abs().max(y1[i].abs());
            sum += (e / sc).powi(2);
        }
        if !k7.iter().all(|x| x.is_finite()) || !y1.iter().all(|x| x.is_finite()) {
            return f64::NAN;
        }
        (sum / n.max(1) as f64).sqrt()
    }

    /// The coefficients of the continuous extension of the step just accepted.
    fn dense(&mut self, h: f64) {
        let [r1, r2, r3, r4, r5] = &mut self.cont;
        let [k1, _, k3, k4, k5, k6, k7] = &self.k;
        for i in 0..self.y.len() {
            let dy = self.y1[i] - self.y[i];
            let bspl = h * k1[i] - dy;
            r1[i] = self.y[i];
            r2[i] = dy;
            r3[i] = bspl;
            r4[i] = dy - h * k7[i] - bspl;
            r5[i] =
                h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn harmonic(_: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }

    #[test]
    fn harmonic_oscillator_to_tolerance() {
        let mut ode = Dopri5::new(2, Tolerances::TIGHT).unwrap();
        let mut y = [1.0, 0.0];
        let t = ode
            .integrate(harmonic, 0.0, &mut y, 20.0, |_| None)
            .unwrap();
        assert_eq!(t, 20.0);
        assert!((y[0] - 20f64.cos()).abs() < 2e-10, "{}", y[0] - 20f64.cos());
        assert!((y[1] + 20f64.sin()).abs() < 2e-10);
    }

    #[test]
    fn dense_output_is_fourth_order_accurate() {
        // Loose tolerance so that steps are long; the interpolant's error must stay of the
        // order of the tolerance everywhere inside the steps.
        let tol = Tolerances {
            relative: 1e-8,
            absolute: 1e-10,
        };
        let mut ode = Dopri5::new(2, tol).unwrap();
        let mut y = [1.0, 0.0];
        let mut worst: f64 = 0.0;
        let mut out = [0.0; 2];
        ode.integrate(harmonic, 0.0, &mut y, 10.0, |s| {
            for j in 1..10 {
                let t = s.t0 + (s.t1 - s.t0) * j as f64 / 10.0;
                s.interpolate(t, &mut out);
                worst = worst.max((out[0] - t.cos()).abs());
            }
            None
        })
        .unwrap();
        assert!(worst < 1e-7, "dense output error {worst}");
    }

    #[test]
    fn observer_stops_at_an_event() {
        // Stop at the first zero of cos t (t = π/2), located by bisection on the dense output.
        let mut ode = Dopri5::new(2, Tolerances::TIGHT).unwrap();
        let mut y = [1.0, 0.0];
        let mut buf = [0.0; 2];
        let t = ode
            .integrate(harmonic, 0.0, &mut y, 10.0, |s| {
                if s.y1[0] > 0.0 {
                    return None;
                }
                let (mut a, mut b) = (s.t0, s.t1);
                for _ in 0..200 {
                    let m = 0.5 * (a + b);
                    s.interpolate(m, &mut buf);
                    if buf[0] > 0.0 {
                        a = m
                    } else {
                        b = m
                    }
                }
                Some(0.5 * (a + b))
            })
            .unwrap();
        assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-9, "{t}");
        assert!(y[0].abs() < 1e-9);
    }

    #[test]
    fn bad_tolerances_are_errors() {
        assert!(Dopri5::new(
            2,
            Tolerances {
                relative: 0.0,
                absolute: 1e-9
            }
        )
        .is_err());
        assert!(Dopri5::new(
            2,
            Tolerances {
                relative: 1e-9,
                absolute: f64::NAN
            }
        )
        .is_err());
    }
}
