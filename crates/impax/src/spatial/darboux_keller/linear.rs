//! The straight pieces of the path, every event on them in closed form: stick, the resumed
//! slip along the centrifugal invariant ray, the frictionless path, a slip too fast for the
//! impact to turn, and the closed-form ends of a slip on a ray (`tail`).
//!
//! On a straight piece the friction ratio `dp_t/dp_n` is constant, so `v_n` is linear and
//! `W_n` quadratic in `p_n` ([`Linear`]): the end of compression is `v_n = 0`, Newton's end
//! `v_n = −e v_n⁻`, the energetic end a root of the quadratic `W_n = (1 − e²) W_c`, Poisson's
//! `p_n = (1 + e) C` with `C` the compression impulse of every phase ([`poisson_end`]).
//! Stick holds if `|W_tt⁻¹ w_tn| ≤ μ`, `dv_n/dp_n = w_nn − w_tnᵀ W_tt⁻¹ w_tn` (theory §2);
//! otherwise the slip resumes at once along the unique centrifugal ray
//! `(λ' I + μ W_tt) ŝ = w_tn`, `λ' > 0` ([`resumption_direction`]).

use super::events::Events;
use super::state::{Point, Scales};
use super::Termination;
use crate::law::BreakdownReason;
use crate::math::{norm_of, Mat2, Vec2};
use crate::spatial::invariant::resumption_direction;
use crate::spatial::outcome::{PhaseKind, Phases};
use crate::spatial::ContactProblem;

/// The frictionless path (`μ = 0`): `p = p_n (0, 0, 1)`, `v_n` linear, and the three
/// terminations coincide at `p_f = (1 + e) p_c`, `p_c = −v_n⁻/w_nn`; `v_t = v_t⁻ + w_tn p_n`
/// runs straight, through zero if it points against `w_tn`. Records the end of compression
/// in `ev`; returns the end point, the phases and where the slip passed through zero.
pub(super) fn frictionless(
    problem: &ContactProblem,
    ev: &mut Events,
) -> (Point, Phases, Option<f64>) {
    let (wtn, wnn) = (problem.wtn(), problem.wnn());
    let (e, v0) = (problem.restitution(), problem.velocity());
    let mut phases = Phases::new();
    let pc = -v0.z / wnn;
    let pf = (1.0 + e) * pc;
    let vt = v0.xy() + wtn * pf;
    let vt0 = v0.xy();
    let through_zero = vt0.x * wtn.y - vt0.y * wtn.x == 0.0 && vt0.dot(&wtn) < 0.0;
    let halt = norm_of(vt0) / norm_of(wtn);
    if through_zero && halt < pf {
        // The slip runs straight through zero and continues along w_tn.
        let a = vt0.y.atan2(vt0.x);
        phases.push(PhaseKind::Slip { from: a, to: a }, halt);
    }
    let kind = if through_zero && halt < pf {
        PhaseKind::Resumed {
            angle: wtn.y.atan2(wtn.x),
        }
    } else if v0.x != 0.0 || v0.y != 0.0 {
        PhaseKind::Slip {
            from: v0.y.atan2(v0.x),
            to: vt.y.atan2(vt.x),
        }
    } else if wtn.norm() > 0.0 {
        PhaseKind::Resumed {
            angle: wtn.y.atan2(wtn.x),
        }
    } else {
        PhaseKind::Stick
    };
    phases.push(kind, pf);
    ev.pc = Some(pc);
    ev.wc = pc * (v0.z + 0.5 * wnn * pc);
    let end = Point {
        p: pf,
        vt,
        vn: v0.z + wnn * pf,
        pt: Vec2::zeros(),
        wn: pf * (v0.z + 0.5 * wnn * pf),
        wt: 0.0,
    };
    let slip_halt = (through_zero && halt < pf).then_some(halt);
    (end, phases, slip_halt)
}

/// The straight piece that follows a halt of the slip (or an impact without initial slip):
/// stick if `|W_tt⁻¹ w_tn| ≤ μ` (the ratio and the slope of stick from `W = L D Lᵀ`: the slope
/// is the last pivot, accurate where `w_nn + w_tn·λ` would cancel in an ill-conditioned `W`),
/// otherwise the resumed slip along the centrifugal invariant ray, to the termination.
pub(super) fn stick_or_resumed(problem: &ContactProblem) -> Result<Linear, BreakdownReason> {
    let mu = problem.friction();
    let (lambda, stick_slope) = problem.stick();
    Ok(if lambda.norm() <= mu {
        Linear {
            kind: PhaseKind::Stick,
            ratio: lambda,
            slope: stick_slope,
            dir: Vec2::zeros(),
            sigma: 0.0,
            dsigma: 0.0,
            length: f64::INFINITY,
        }
    } else {
        let (s, rate) = resumption_direction(problem).ok_or(BreakdownReason::NoSeparation)?;
        Linear {
            kind: PhaseKind::Resumed {
                angle: s.y.atan2(s.x),
            },
            ratio: -mu * s,
            slope: problem.resumed_slope(rate),
            dir: s,
            sigma: 0.0,
            dsigma: rate,
            length: f64::INFINITY,
        }
    })
}

/// A slip so fast beside the normal velocity that the impact cannot turn it: `|dv_t/dp_n| =
/// |g| ≤ G = |w_tn| + μ ‖W_tt‖`, so over the normal impulse `L = ε σ⁻/(4G)` the direction
/// turns by less than `ε/4` and the speed changes at the constant rate `ŝ·g` — the path is
/// straight to round-off. If the law ends within `L` on it (every event in closed form),
/// that is the end: the integration is not needed (and its squares of `σ` could overflow).
/// Tried only where `4 G` times the normal impulse scale is below `ε σ⁻`; `None` if the law
/// does not end within `L` (then the integration takes over).
pub(super) fn rigid_slip(
    wtt: &Mat2,
    wtn: Vec2,
    wnn: f64,
    mu: f64,
    sc: Scales,
    pt: &mut Point,
    ev: &mut Events,
) -> Result<Option<Point>, BreakdownReason> {
    let sigma = norm_of(pt.vt);
    let g_max = norm_of(wtn) + mu * wtt.norm();
    let rigid = 4.0 * g_max * sc.p <= f64::EPSILON * sigma;
    if !rigid {
        return Ok(None);
    }
    let dir = pt.vt / sigma;
    let piece = Linear {
        kind: PhaseKind::Slip { from: 0.0, to: 0.0 },
        ratio: -mu * dir,
        slope: wnn - mu * wtn.dot(&dir),
        dir,
        sigma,
        dsigma: dir.dot(&(wtn - mu * (wtt * dir))),
        length: f64::EPSILON * sigma / (4.0 * g_max),
    };
    let (mut end, mut events) = (*pt, *ev);
    if piece.run(&mut end, &mut events, mu)? {
        (*pt, *ev) = (end, events);
        Ok(Some(end))
    } else {
        Ok(None)
    }
}

/// A straight piece of the path: friction ratio `ratio`, slip `σ dir` with `σ` changing at
/// rate `dsigma` from `sigma`, of normal-impulse length `length`. Along it, from its start
/// (`x` the normal impulse into the piece),
///
/// ```text
/// p_t = p_t0 + ratio x,   v_n = v_n0 + slope x,   v_t = dir (σ + σ' x),
/// W_n = W_n0 + x (v_n0 + slope x/2),   W_t = W_t0 − μ x (σ + σ' x/2).
/// ```
pub(super) struct Linear {
    /// The phase the piece is (stick, resumed slip; a slip in closed form reports its own).
    pub kind: PhaseKind,
    /// `dp_t/dp_n`.
    pub ratio: Vec2,
    /// `dv_n/dp_n` on the piece, `w_nn + w_tn·ratio`.
    pub slope: f64,
    /// The direction of the slip (zero in stick).
    pub dir: Vec2,
    /// The slip speed at the start.
    pub sigma: f64,
    /// `dσ/dp_n`.
    pub dsigma: f64,
    /// The normal impulse along the piece (`∞`: to the termination).
    pub length: f64,
}

impl Linear {
    /// Advance along the piece in closed form, locating the end of compression, a second
    /// compression and the termination exactly. Returns `true` if the law terminated in
    /// the piece (`pt` is then the end point), `false` if the piece was run to its end.
    pub(super) fn run(
        &self,
        pt: &mut Point,
        ev: &mut Events,
        mu: f64,
    ) -> Result<bool, BreakdownReason> {
        let kn = self.slope;
        let start = *pt;
        let at = |x: f64| -> Point {
            Point {
                p: start.p + x,
                vt: self.dir * (self.sigma + self.dsigma * x),
                vn: start.vn + kn * x,
                pt: start.pt + self.ratio * x,
                wn: start.wn + x * (start.vn + 0.5 * kn * x),
                wt: start.wt - mu * x * (self.sigma + 0.5 * self.dsigma * x),
            }
        };
        // Smallest x ≥ 0 past the minimum of the work with v x + ½ kn x² = w.
        let work_root = |v: f64, w: f64| -> Option<f64> {
            let disc = v * v + 2.0 * kn * w;
            if disc < 0.0 || kn <= 0.0 && v <= 0.0 {
                return None;
            }
            let sq = disc.max(0.0).sqrt();
            let x = if v >= 0.0 {
                if v + sq > 0.0 {
                    2.0 * w / (v + sq)
                } else {
                    0.0
                }
            } else {
                (-v + sq) / kn
            };
            (x >= 0.0).then_some(x)
        };
        if ev.pc.is_none() {
            if kn > 0.0 {
                let x = -start.vn / kn;
                if x <= self.length {
                    let c = at(x);
                    ev.pc = Some(c.p);
                    ev.wc = c.wn;
                }
            }
            if ev.pc.is_none() {
                if !self.length.is_finite() {
                    return Err(BreakdownReason::NoSeparation);
                }
                *pt = at(self.length);
                return Ok(false);
            }
        } else if ev.second.is_none() && start.vn > 0.0 && kn < 0.0 {
            let x = -start.vn / kn;
            if x <= self.length {
                ev.second = Some(start.p + x);
            }
        }
        let pc = ev.pc.expect("set above");
        let x_end = match ev.term {
            Termination::Newton => {
                if kn > 0.0 {
                    Some(((ev.target - start.vn) / kn).max(0.0))
                } else if start.vn >= ev.target {
                    Some(0.0)
                } else {
                    None
                }
            }
            Termination::Poisson => poisson_end(ev, &start, kn, self.length),
            Termination::Energetic => {
                if pc >= start.p && kn > 0.0 {
                    // Compression ends inside this piece: from p_c (v_n = 0) the restitution
                    // work −e² W_c is reached at x = e √2 √(−W_c) / √k_n — no cancellation, and
                    // no overflow of the quotient −W_c / k_n where x itself is representable.
                    let root = (-ev.wc).max(0.0).sqrt() / kn.sqrt();
                    Some(pc - start.p + ev.e * std::f64::consts::SQRT_2 * root)
                } else {
                    let need = (1.0 - ev.e * ev.e) * ev.wc - start.wn;
                    if need <= 0.0 && start.p >= pc && start.vn >= 0.0 {
                        Some(0.0)
                    } else {
                        work_root(start.vn, need)
                    }
                }
            }
        };
        match x_end {
            Some(x) if x <= self.length => {
                *pt = at(x);
                if ev.term == Termination::Newton && kn > 0.0 && start.vn <= ev.target {
                    // Newton's rule holds exactly at its end (not only to the round-off of the
                    // path's normal velocity, which after a long compression can exceed it).
                    pt.vn = ev.target;
                }
                Ok(true)
            }
            _ if self.length.is_finite() => {
                *pt = at(self.length);
                Ok(false)
            }
            _ => Err(BreakdownReason::NoSeparation),
        }
    }
}

/// Where Poisson's law ends on a straight piece from `start` (`v_n` of slope `kn`, of
/// normal-impulse length `length`), after the end of the first compression: `None` if not
/// in the piece. The restitution impulse (where `v_n ≥ 0`) must reach `e` times the
/// compression impulse `C` (where `v_n < 0`, every phase); so a later compression inside the
/// piece is followed to its end, which adds to `C`, and the law never ends while `v_n < 0`.
fn poisson_end(ev: &mut Events, start: &Point, kn: f64, length: f64) -> Option<f64> {
    let pc = ev.pc.expect("after the first compression");
    let mut from = 0.0;
    if ev.again.is_none() && start.vn < 0.0 && start.p > pc {
        // (Already in a later compression phase: its start was not seen.)
        ev.again = Some(start.p);
    }
    if let Some(began) = ev.again {
        // In a later compression phase (v_n ≤ 0): it ends where v_n is back to zero.
        if kn <= 0.0 {
            return None;
        }
        from = (-start.vn / kn).max(0.0);
        if from > length {
            return None;
        }
        ev.recompressed += start.p + from - began;
        ev.again = None;
    }
    let c = pc + ev.recompressed;
    let x = ((1.0 + ev.e) * c - start.p).max(from);
    if kn < 0.0 && start.vn >= 0.0 {
        // v_n falls back to zero inside the piece before the end: a later compression,
        // v_n < 0 for the rest of the piece.
        let back = -start.vn / kn;
        if back < x && back <= length {
            ev.again = Some(start.p + back);
            return None;
        }
    }
    Some(x)
}
