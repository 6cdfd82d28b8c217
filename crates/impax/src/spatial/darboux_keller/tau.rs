//! The slip in the pseudo-time `τ`, `dp_n = σ dτ` (theory §2, "Spatial"): the variable of
//! a small slip (below `σ⁻/20`) that does not shrink steadily — the direction swings while
//! the slip passes near zero. The state `z = (v_t, v_n, p_t, W_n, W_t, p_n)` obeys
//!
//! ```text
//! dv_t/dτ = σ w_tn − μ W_tt v_t,  dv_n/dτ = σ w_nn − μ w_tn·v_t,  dp_n/dτ = σ,
//! dp_t/dτ = −μ v_t,  dW_n/dτ = σ v_n,  dW_t/dτ = −μ σ²,
//! ```
//!
//! with no division, smooth everywhere but at `v_t = 0` itself, which is reached only as
//! `τ → ∞`; the step is bounded by the stability limit `3/(|w_tn| + μ |W_tt|)` (DOP853 is
//! stable on the real axis to about −6). Back to `u = ln σ` when the slip shrinks steadily
//! again, to `p_n` once it has grown past `σ⁻/10`; where `σ` has shrunk by `e^−LOG_SPAN`
//! the rest is a straight run in closed form.

use super::events::Events;
use super::log_sigma::LOG_SPAN;
use super::slip::{Mode, Next, Slip};
use super::state::Point;
use super::step::{grow, shrink, Advance, Stepper, Variable};
use crate::law::BreakdownReason;
use crate::math::{norm_of, Vec2, Vec3};

/// The slip in `τ`: `[v_t1, v_t2, v_n, p_t1, p_t2, W_n, W_t, p_n]`.
struct PseudoTime<'a> {
    slip: &'a Slip,
    atol: [f64; 8],
}

impl<'a> PseudoTime<'a> {
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
            sc.rtol * sc.p,
        ];
        PseudoTime { slip, atol }
    }
}

/// The state of `p` in this variable.
fn state(p: &Point) -> [f64; 8] {
    [p.vt.x, p.vt.y, p.vn, p.pt.x, p.pt.y, p.wn, p.wt, p.p]
}

impl Variable<8> for PseudoTime<'_> {
    const VN: usize = 2;

    #[inline]
    fn rhs(&self, _t: f64, z: &[f64; 8]) -> [f64; 8] {
        let (wtt, wtn, wnn, mu) = (&self.slip.wtt, self.slip.wtn, self.slip.wnn, self.slip.mu);
        let (v1, v2) = (z[0], z[1]);
        let sigma = norm_of(Vec2::new(v1, v2));
        let wv1 = wtt[(0, 0)] * v1 + wtt[(0, 1)] * v2;
        let wv2 = wtt[(1, 0)] * v1 + wtt[(1, 1)] * v2;
        [
            sigma * wtn.x - mu * wv1,
            sigma * wtn.y - mu * wv2,
            sigma * wnn - mu * (wtn.x * v1 + wtn.y * v2),
            -mu * v1,
            -mu * v2,
            sigma * z[2],
            -mu * sigma * sigma,
            sigma,
        ]
    }

    #[inline]
    fn point(&self, _t: f64, z: &[f64; 8]) -> Point {
        Point {
            p: z[7],
            vt: Vec2::new(z[0], z[1]),
            vn: z[2],
            pt: Vec2::new(z[3], z[4]),
            wn: z[5],
            wt: z[6],
        }
    }

    fn atol(&self) -> &[f64; 8] {
        &self.atol
    }

    fn rtol(&self) -> f64 {
        self.slip.sc.rtol
    }
}

/// Integrate the small slip in `τ` from `pt` with the first step `ht`, until it ends, grows
/// or shrinks steadily.
pub(super) fn run(
    slip: &Slip,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    mut ht: f64,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Next, BreakdownReason> {
    let var = PseudoTime::new(slip);
    let mut st = Stepper::new(&var, 0.0, state(pt));
    // Stability: the Lipschitz constant of the τ system in v_t is at most
    // |w_tn| + μ |W_tt|, and DOP853 is stable on the real axis to about −6.
    let h_stable = 3.0 / (slip.wtn.norm() + slip.mu * slip.wtt.norm()).max(f64::MIN_POSITIVE);
    let sigma_end = norm_of(pt.vt) * (-LOG_SPAN).exp();
    while *steps < slip.max_steps {
        ht = ht.min(h_stable);
        let en = match st.advance(&var, ht, pt, ev, steps, observe) {
            Advance::Rejected(en) => {
                ht *= shrink(en);
                continue;
            }
            Advance::Stalled(why) => return Err(why),
            Advance::Event(Some(end)) => return Ok(Next::End(end)),
            Advance::Event(None) => continue,
            Advance::Accepted(en) => en,
        };
        if let Some(end) = slip.end_on_ray(pt, ev)? {
            observe(pt.p, pt.velocity());
            return Ok(Next::End(end));
        }
        ht *= grow(en);
        let sigma = norm_of(pt.vt);
        let (q, gn) = slip.rates(pt.vt);
        if sigma <= sigma_end && q < 0.0 {
            // σ has shrunk by e^-40: the rest is a straight run at the last bit of the
            // result.
            let end = slip.run_tail(pt, ev, pt.vt / sigma, q)?;
            observe(pt.p, pt.velocity());
            return Ok(Next::End(end));
        }
        if q < -0.9 * gn && slip.turns_before_event(pt, ev) {
            return Ok(Next::Switch(Mode::LogSlip, -(q.abs() * ht).min(0.25)));
        }
        if sigma > 0.1 * slip.sigma0 {
            return Ok(Next::Switch(Mode::NormalImpulse, sigma * ht));
        }
    }
    Err(BreakdownReason::NoSeparation)
}
