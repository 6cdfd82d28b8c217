//! The initial slip (theory §2, "Spatial"): with `ŝ = v_t/|v_t|` and `g = w_tn − μ W_tt ŝ`,
//!
//! ```text
//! dv_t/dp_n = g,  dv_n/dp_n = w_nn − μ w_tn·ŝ,  dp_t/dp_n = −μ ŝ,
//! dW_n/dp_n = v_n,  dW_t/dp_n = −μ |v_t|,
//! ```
//!
//! singular at `σ = |v_t| → 0`, where steps in `p_n` must shrink with `σ`. The stage runs in
//! whichever variable keeps the system smooth and hands over between them here:
//!
//! * the angle variable (module `angle`) first, wherever the slip turns or shrinks appreciably
//!   before the next normal event ([`Slip::turns_before_event`]), tried again a few steps
//!   after it handed back;
//! * the normal impulse itself (module `p_n`) otherwise;
//! * `u = ln σ` (module `log_sigma`) as soon as the slip shrinks steadily (`ŝ·g < −0.9 |g|`), until
//!   it no longer does (`ŝ·g ≥ −0.7 |g|`);
//! * the pseudo-time `τ`, `dp_n = σ dτ` (module `tau`), once the slip is small (below `σ⁻/20`) and
//!   not shrinking steadily, back to `p_n` once it has grown past `σ⁻/10`.
//!
//! Wherever the slip is on an invariant ray or near a centripetal one, its rest is in
//! closed form (module `tail`). No small epsilon decides the halt.

use super::events::Events;
use super::field::Field;
use super::state::{Centrifugal, Point, Scales, SlipEnd};
use super::{log_sigma, p_n, tau};
use crate::law::BreakdownReason;
use crate::math::{norm_of, Mat2, Vec2, Vec3};
use crate::spatial::invariant::resumption_direction;
use crate::spatial::ContactProblem;

/// The variable the slip is integrated in, outside the angle variable.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Mode {
    /// The normal impulse `p_n`.
    NormalImpulse,
    /// `u = ln σ`, decreasing (a steady approach to a halt).
    LogSlip,
    /// The pseudo-time `τ`, `dp_n = σ dτ` (small slip that need not shrink steadily).
    PseudoTime,
}

/// How a variable's run ended.
pub(super) enum Next {
    /// The slip stage ended.
    End(SlipEnd),
    /// Go on in the variable given, with the first step given (in that variable).
    Switch(Mode, f64),
}

/// What every variable of the slip stage reads: the problem's data, its direction field,
/// the centrifugal ray, the error scales and the stage's start.
pub(super) struct Slip {
    /// `W_tt`.
    pub wtt: Mat2,
    /// `w_tn`.
    pub wtn: Vec2,
    /// `w_nn`.
    pub wnn: f64,
    /// The friction coefficient `μ`.
    pub mu: f64,
    /// The coefficient of restitution.
    pub e: f64,
    /// The direction field of the slip.
    pub field: Field,
    /// The centrifugal invariant ray, if any.
    pub centrifugal: Option<Centrifugal>,
    /// The scales of the error control.
    pub sc: Scales,
    /// The slip speed at the start of the stage, `σ⁻`.
    pub sigma0: f64,
    /// The normal velocity at the start of the stage, `v_n⁻`.
    pub vn0: f64,
    /// The budget of steps.
    pub max_steps: u32,
    /// Whether the observer does anything (else `p_n` inside a panel of the angle variable
    /// only where an event reads it).
    pub observing: bool,
}

impl Slip {
    fn new(problem: &ContactProblem, sc: Scales, pt: &Point, observing: bool) -> Slip {
        let (wtt, wtn, mu) = (problem.wtt(), problem.wtn(), problem.friction());
        // The centrifugal invariant ray, if any: the direction of resumption (theory §2).
        let centrifugal = resumption_direction(problem).map(|(dir, rate)| Centrifugal {
            dir,
            rate,
            slope: problem.resumed_slope(rate),
        });
        Slip {
            wtt,
            wtn,
            wnn: problem.wnn(),
            mu,
            e: problem.restitution(),
            field: Field::new(&wtt, wtn, mu),
            centrifugal,
            sc,
            sigma0: norm_of(pt.vt),
            vn0: pt.vn,
            max_steps: 200_000,
            observing,
        }
    }

    /// The rate of change of the slip at `vt`: `ŝ·g` and `|g|`, for the switches between
    /// variables.
    pub(super) fn rates(&self, vt: Vec2) -> (f64, f64) {
        let s = vt / norm_of(vt);
        let g = self.wtn - self.mu * (self.wtt * s);
        (s.dot(&g), norm_of(g))
    }

    /// Whether the slip turns or shrinks appreciably before the next normal event (the angle
    /// variable pays off), judged from the rates at `pt`: `(|ŝ × g| + max(0, −ŝ·g))/σ` times
    /// the normal impulse to the event, `|v_n|` (or `e |v_n⁻|` after compression) over
    /// `k_n = w_nn − μ w_tn·ŝ`, at least a quarter (always when `k_n ≤ 0`).
    pub(super) fn turns_before_event(&self, pt: &Point, ev: &Events) -> bool {
        let (field, wnn, wtn, mu) = (&self.field, self.wnn, self.wtn, self.mu);
        let sigma = norm_of(pt.vt);
        let s = pt.vt / sigma;
        let kn = wnn - mu * wtn.dot(&s);
        if kn.is_nan() || kn <= 0.0 {
            return true;
        }
        let to_event = if ev.pc.is_none() {
            -pt.vn
        } else {
            ev.e * self.vn0.abs()
        }
        .abs()
            / kn;
        let rate = field.f_at(s.x, s.y).abs() + (-field.q_at(s.x, s.y)).max(0.0);
        // (A NaN says nothing: try the angle variable.)
        (rate * to_event).partial_cmp(&(0.25 * sigma)) != Some(std::cmp::Ordering::Less)
    }
}

/// Integrate the slip of `problem` from `pt` (`v_t ≠ 0`) to its end: the termination of the
/// law during the slip, or the halt. `pt`, `ev` and `steps` advance; `observe` sees every
/// accepted point.
pub(super) fn run(
    problem: &ContactProblem,
    sc: Scales,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<SlipEnd, BreakdownReason> {
    let slip = Slip::new(problem, sc, pt, observing);
    // The angle variable is tried first, and again a few steps after a start on a ray.
    let mut angle_retry = Some(0u32);
    let (mut mode, mut h) = (Mode::NormalImpulse, 0.05 * sc.p);
    while *steps < slip.max_steps {
        let next = match mode {
            Mode::NormalImpulse => p_n::run(&slip, pt, ev, steps, h, &mut angle_retry, observe)?,
            Mode::LogSlip => log_sigma::run(&slip, pt, ev, steps, h, observe)?,
            Mode::PseudoTime => tau::run(&slip, pt, ev, steps, h, observe)?,
        };
        match next {
            Next::End(end) => return Ok(end),
            Next::Switch(to, first_step) => (mode, h) = (to, first_step),
        }
    }
    Err(BreakdownReason::NoSeparation)
}
