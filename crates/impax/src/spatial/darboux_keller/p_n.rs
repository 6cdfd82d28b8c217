//! The slip in the normal impulse `p_n` (theory §2, "Spatial"): the state
//! `y = (v_t, v_n, p_t, W_n, W_t)` with
//!
//! ```text
//! dv_t/dp_n = g,  dv_n/dp_n = w_nn − μ w_tn·ŝ,  dp_t/dp_n = −μ ŝ,
//! dW_n/dp_n = v_n,  dW_t/dp_n = −μ σ,      ŝ = v_t/σ,  σ = |v_t|,  g = w_tn − μ W_tt ŝ,
//! ```
//!
//! each component's error on its own scale (`rtol` times the velocity, impulse and work
//! scales). The variable of a slip that is neither small nor shrinking steadily, and that
//! the angle variable does not take (on a ray, or barely turning before the next event);
//! never a step past the predicted halt `σ/|ŝ·g|`.

use super::angle;
use super::events::Events;
use super::slip::{Mode, Next, Slip};
use super::state::Point;
use super::step::{grow, shrink, Advance, Stepper, Variable};
use crate::law::BreakdownReason;
use crate::math::{norm_of, Vec2, Vec3};

/// The slip in `p_n`: `[v_t1, v_t2, v_n, p_t1, p_t2, W_n, W_t]`.
struct NormalImpulse<'a> {
    slip: &'a Slip,
    atol: [f64; 7],
}

impl<'a> NormalImpulse<'a> {
    fn new(slip: &'a Slip) -> Self {
        let sc = slip.sc;
        let atol = [
            sc.rtol * sc.vt,
            sc.rtol * sc.vt,
            sc.rtol * sc.vn,
            sc.rtol * sc.p,
            sc.rtol * sc.p,
            sc.rtol * sc.wn,
            sc.rtol * sc.wt,
        ];
        NormalImpulse { slip, atol }
    }
}

/// The state of `p` in this variable.
fn state(p: &Point) -> [f64; 7] {
    [p.vt.x, p.vt.y, p.vn, p.pt.x, p.pt.y, p.wn, p.wt]
}

impl Variable<7> for NormalImpulse<'_> {
    const VN: usize = 2;

    #[inline]
    fn rhs(&self, _p: f64, y: &[f64; 7]) -> [f64; 7] {
        let (wtt, wtn, wnn, mu) = (&self.slip.wtt, self.slip.wtn, self.slip.wnn, self.slip.mu);
        let vt = Vec2::new(y[0], y[1]);
        let sigma = norm_of(vt);
        let s = vt / sigma;
        let g = wtn - mu * (wtt * s);
        [
            g.x,
            g.y,
            wnn - mu * wtn.dot(&s),
            -mu * s.x,
            -mu * s.y,
            y[2],
            -mu * sigma,
        ]
    }

    #[inline]
    fn point(&self, p: f64, y: &[f64; 7]) -> Point {
        Point {
            p,
            vt: Vec2::new(y[0], y[1]),
            vn: y[2],
            pt: Vec2::new(y[3], y[4]),
            wn: y[5],
            wt: y[6],
        }
    }

    fn atol(&self) -> &[f64; 7] {
        &self.atol
    }

    fn rtol(&self) -> f64 {
        self.slip.sc.rtol
    }
}

/// Integrate the slip in `p_n` from `pt` with the first step `h`, trying the angle variable
/// where it pays off (`angle_retry`: the step count from which it is tried again, `None`
/// for good), until the slip ends or another variable takes over.
pub(super) fn run(
    slip: &Slip,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    mut h: f64,
    angle_retry: &mut Option<u32>,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Next, BreakdownReason> {
    let var = NormalImpulse::new(slip);
    let mut st = Stepper::new(&var, pt.p, state(pt));
    while *steps < slip.max_steps {
        if let Some(end) = slip.end_on_ray(pt, ev)? {
            observe(pt.p, pt.velocity());
            return Ok(Next::End(end));
        }
        let try_angle =
            angle_retry.is_some_and(|at| *steps >= at && slip.turns_before_event(pt, ev));
        if try_angle {
            let before = *steps;
            match angle::run(slip, pt, ev, steps, observe)? {
                angle::Exit::End(end) => return Ok(Next::End(end)),
                angle::Exit::Unavailable => *angle_retry = None,
                angle::Exit::Handoff => {
                    *angle_retry = (*steps == before).then_some(*steps + 3);
                    st = Stepper::new(&var, pt.p, state(pt));
                    continue;
                }
            }
        }
        let sigma = norm_of(pt.vt);
        let (q, gn) = slip.rates(pt.vt);
        // Go logarithmic as soon as the slip shrinks steadily (hysteresis: enter only where
        // the shrink rate is nearly |g|): steps in p_n would have to shrink with σ. Once the
        // slip is small otherwise, go to the pseudo-time τ, in which a swing of the direction
        // near the origin takes steps independent of σ. (Only where the slip shrinks
        // appreciably before the next event: a slip far above the normal velocity changes
        // ln σ by less than its round-off over the impact.)
        if q < -0.9 * gn && slip.turns_before_event(pt, ev) {
            return Ok(Next::Switch(Mode::LogSlip, -(h * -q / sigma).min(0.25)));
        }
        if sigma < 0.05 * slip.sigma0 {
            let ht = (h / sigma).min(0.5 / gn.max(f64::MIN_POSITIVE));
            return Ok(Next::Switch(Mode::PseudoTime, ht));
        }
        // Never step past the predicted halt.
        if q < 0.0 {
            h = h.min(0.5 * sigma / -q);
        }
        st.x = pt.p;
        let en = match st.advance(&var, h, pt, ev, steps, observe) {
            Advance::Rejected(en) => {
                h *= shrink(en);
                continue;
            }
            Advance::Stalled(why) => return Err(why),
            Advance::Event(Some(end)) => return Ok(Next::End(end)),
            Advance::Event(None) => continue,
            Advance::Accepted(en) => en,
        };
        h *= grow(en);
    }
    Err(BreakdownReason::NoSeparation)
}
