//! The Darboux–Keller / Routh impulse path in closed form (planar).
//!
//! With the normal impulse as independent variable (Keller 1986; Routh 1905; Stronge 2000;
//! theory §2), the contact velocity obeys `dv/dp_n = W (k, 1)` with friction ratio
//!
//! * slip, `ŝ = sign(v_t)`: `k = −μ ŝ`;
//! * stick (`v_t = 0`): `k = λ = −W_tn / W_tt`, admissible iff `|W_tn| ≤ μ W_tt`.
//!
//! Planar, `v(p_n)` is piecewise linear:
//!
//! 1. slip in `s0 = sign(v_t⁻)` with slopes `(b − μ s0 a, c − μ s0 b)`; it halts at
//!    `p_s = −v_t⁻ / (b − μ s0 a)` when that is positive;
//! 2. then stick (slopes `(0, (ac − b²)/a)`) if `|b| ≤ μ a`, otherwise slip resumes at once in
//!    `s1 = sign(b)` (reversal) with slopes `(b − μ s1 a, c − μ s1 b)` and never halts again.
//!
//! (`a = W_tt, b = W_tn, c = W_nn`.) The last segment always has `dv_n/dp_n > 0`, so the
//! compression ends; the termination rules [`newton`](super::newton),
//! [`poisson`](super::poisson) and [`energetic`](super::energetic) pick the end on this path.

use crate::planar::path::ImpulsePath;
use crate::planar::{ContactProblem, PhaseKind, SlipDirection};

/// The unbounded Darboux–Keller path of a problem and the impulse at which the initial
/// slip halts (if it does).
#[inline]
pub fn darboux_keller_path(problem: &ContactProblem) -> (ImpulsePath, Option<f64>) {
    let (a, b) = (problem.wtt(), problem.wtn());
    let mu = problem.friction();
    let vt = problem.velocity().x;
    let mut path = ImpulsePath::new(problem);
    let mut halt = None;
    let dir = SlipDirection::of(vt);
    if dir != SlipDirection::None {
        let s0 = dir.sign();
        let ratio = -mu * s0;
        let dvt = b - mu * s0 * a;
        if s0 * dvt < 0.0 {
            let ps = -vt / dvt;
            path.push(PhaseKind::Slip(dir), ratio, ps);
            halt = Some(ps);
        } else {
            path.push(PhaseKind::Slip(dir), ratio, f64::INFINITY);
            return (path, None);
        }
    }
    // v_t = 0 here: stick if the cone holds it, else slip resumes along sign(b).
    if b.abs() <= mu * a {
        path.push_from_rest(PhaseKind::Stick, -b / a, f64::INFINITY);
    } else {
        let s1 = SlipDirection::of(b);
        path.push_from_rest(PhaseKind::Slip(s1), -mu * s1.sign(), f64::INFINITY);
    }
    (path, halt)
}

/// End of compression on the path: the first `p_c` with `v_n(p_c) = 0`.
#[inline]
pub(crate) fn compression_end(path: &ImpulsePath) -> f64 {
    path.first_normal_velocity(0.0)
        .expect("the last Darboux–Keller segment has dv_n/dp_n > 0")
}
