//! The slip in `u = ln σ`, decreasing (theory §2, "Spatial"): the variable of a slip that
//! shrinks steadily (`ŝ·g < −0.9 |g|`: near a centripetal invariant ray, or on an inward
//! spiral), whatever its size, in which the system is smooth all the way to the halt. The
//! state is `z = (ŝ, σ, p_n, v_n, p_t, W_n, W_t)` — the direction carried as a vector
//! (normalised on use) and `σ` as a state, `dσ/du = σ`, so that no trigonometric function is
//! evaluated — with
//!
//! ```text
//! dŝ/du = ŝ' (ŝ × g)/(ŝ·g),  dσ/du = σ,  dp_n/du = σ/(ŝ·g),  d(·)/du = d(·)/dp_n · dp_n/du,
//! ```
//!
//! (`ŝ'` the direction turned by a right angle), each component's error on its own scale
//! (`rtol` absolute on the direction, relative on `σ`). It runs until the series about the
//! centripetal ray ahead (`tail`) gives the whole rest of the slip to the tolerance; where
//! that series does not converge (a weakly attracting ray), until `σ` has shrunk by
//! `e^−LOG_SPAN`, the remaining impulse `σ/|ŝ·g|` then added in closed form; or until the slip
//! no longer shrinks steadily (`ŝ·g ≥ −0.7 |g|`), where the pseudo-time `τ` takes over.

use super::events::Events;
use super::slip::{Mode, Next, Slip};
use super::state::Point;
use super::step::{grow, shrink, Advance, Stepper, Variable};
use super::tail::TailSeries;
use crate::law::BreakdownReason;
use crate::math::{norm_of, Vec2, Vec3};

/// How far the logarithmic stage integrates (`σ` shrinks by `e^-40`); the pseudo-time
/// stops at the same depth below its start.
pub(super) const LOG_SPAN: f64 = 40.0;

/// The slip in `u = ln σ`: `[ŝ1, ŝ2, σ, p_n, v_n, p_t1, p_t2, W_n, W_t]`.
struct LogSlip<'a> {
    slip: &'a Slip,
    atol: [f64; 9],
}

impl<'a> LogSlip<'a> {
    fn new(slip: &'a Slip) -> Self {
        let sc = slip.sc;
        let atol = [
            sc.rtol,
            sc.rtol,
            sc.rtol * sc.vt,
            sc.rtol * sc.p,
            sc.rtol * sc.vn,
            sc.rtol * sc.p,
            sc.rtol * sc.p,
            sc.rtol * sc.wn,
            sc.rtol * sc.wt,
        ];
        LogSlip { slip, atol }
    }
}

/// The state of `p` in this variable (`σ = |v_t|`).
fn state(p: &Point) -> [f64; 9] {
    let sigma = norm_of(p.vt);
    [
        p.vt.x / sigma,
        p.vt.y / sigma,
        sigma,
        p.p,
        p.vn,
        p.pt.x,
        p.pt.y,
        p.wn,
        p.wt,
    ]
}

/// The direction of slip in the state `z`.
#[inline]
fn direction(z: &[f64; 9]) -> Vec2 {
    let s = Vec2::new(z[0], z[1]);
    s / s.norm()
}

impl Variable<9> for LogSlip<'_> {
    const VN: usize = 4;

    #[inline]
    fn rhs(&self, _u: f64, z: &[f64; 9]) -> [f64; 9] {
        let (wtt, wtn, wnn, mu) = (&self.slip.wtt, self.slip.wtn, self.slip.wnn, self.slip.mu);
        let s = Vec2::new(z[0], z[1]);
        let s = s / s.norm();
        let g = wtn - mu * (wtt * s);
        let q = s.dot(&g);
        let f = s.x * g.y - s.y * g.x;
        let sigma = z[2];
        let dp = sigma / q;
        let dphi = f / q;
        [
            -s.y * dphi,
            s.x * dphi,
            sigma,
            dp,
            (wnn - mu * wtn.dot(&s)) * dp,
            -mu * s.x * dp,
            -mu * s.y * dp,
            z[4] * dp,
            -mu * sigma * dp,
        ]
    }

    #[inline]
    fn point(&self, _u: f64, z: &[f64; 9]) -> Point {
        Point {
            p: z[3],
            vt: z[2] * direction(z),
            vn: z[4],
            pt: Vec2::new(z[5], z[6]),
            wn: z[7],
            wt: z[8],
        }
    }

    fn atol(&self) -> &[f64; 9] {
        &self.atol
    }

    fn rtol(&self) -> f64 {
        self.slip.sc.rtol
    }
}

/// Integrate the shrinking slip in `u = ln σ` from `pt` with the first step `hu < 0`, until
/// it ends or no longer shrinks steadily.
pub(super) fn run(
    slip: &Slip,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    mut hu: f64,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Next, BreakdownReason> {
    let (wtt, wtn, wnn, mu) = (&slip.wtt, slip.wtn, slip.wnn, slip.mu);
    let var = LogSlip::new(slip);
    let u_start = norm_of(pt.vt).ln();
    let u_end = u_start - LOG_SPAN;
    let sigma = norm_of(pt.vt);
    let mut st = Stepper::new(&var, u_start, state(pt));
    let mut series = TailSeries::new();
    let g0 = wtn - mu * (wtt * (pt.vt / sigma));
    if let Some(ser) = series.get(&slip.field, wnn, g0, pt.vt) {
        if let Some(end) = slip.series_tail(ser, pt, ev, observe) {
            return Ok(Next::End(end));
        }
    }
    while st.x > u_end && *steps < slip.max_steps {
        let hstep = hu.max(u_end - st.x);
        let en = match st.advance(&var, hstep, pt, ev, steps, observe) {
            Advance::Rejected(en) => {
                hu *= shrink(en);
                continue;
            }
            Advance::Stalled(why) => return Err(why),
            Advance::Event(Some(end)) => return Ok(Next::End(end)),
            Advance::Event(None) => continue,
            Advance::Accepted(en) => en,
        };
        let s = direction(&st.y);
        let g = wtn - mu * (wtt * s);
        if let Some(ser) = series.get(&slip.field, wnn, g, pt.vt) {
            if let Some(end) = slip.series_tail(ser, pt, ev, observe) {
                return Ok(Next::End(end));
            }
        }
        if let Some((s, q)) = slip.straight_tail(pt.vt) {
            let end = slip.run_tail(pt, ev, s, q)?;
            observe(pt.p, pt.velocity());
            return Ok(Next::End(end));
        }
        // The slip must keep shrinking; otherwise go on in τ.
        let q = s.dot(&g);
        if q >= -0.7 * norm_of(g) {
            let gn = norm_of(g).max(f64::MIN_POSITIVE);
            let ht = (hu.abs() / q.abs().max(f64::MIN_POSITIVE)).min(0.5 / gn);
            return Ok(Next::Switch(Mode::PseudoTime, ht));
        }
        hu *= grow(en);
    }
    if *steps >= slip.max_steps {
        return Err(BreakdownReason::NoSeparation);
    }
    // σ has shrunk by e^-40: the rest is a straight run at the last bit of the result.
    let s = direction(&st.y);
    let q = s.dot(&(wtn - mu * (wtt * s)));
    if q.is_nan() || q >= 0.0 {
        return Err(BreakdownReason::NoSeparation);
    }
    let end = slip.run_tail(pt, ev, s, q)?;
    observe(pt.p, pt.velocity());
    Ok(Next::End(end))
}
