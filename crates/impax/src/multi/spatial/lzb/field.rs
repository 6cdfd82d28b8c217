//! The right-hand side in the contact-force time `τ` (`dp_nj = F_j dτ`):
//!
//! ```text
//! dp_nj/dτ = F_j = κ_j s_j^η                              (0 while the contact is off)
//! ds_j/dτ  = −v_nj (compression),  −v_nj / e_j² (expansion),  0 (off)
//! dp_tj/dτ = −μ_j F_j ŝ_j (slip: ŝ_j = v_tj/|v_tj|, or a fixed direction),
//!            x_j (stick: W_SS^tt x_S = −r_S, least norm),  0 (off)
//! dw_tj/dτ = v_tj · dp_tj/dτ
//! v = v⁻ + W p.
//! ```
//!
//! `r_S` is the rate of change of the sticking contacts' tangential velocities (two per
//! contact) due to every other impulse rate: `r_a = Σ_c W_{t_a n_c} F_c +
//! Σ_{c ∉ S} W_{t_a t_c} dp_tc/dτ`.

use super::state::{Modes, Normal, Setup, Tangent, MAXK, PER, PN, PT1, PT2, ROWS, S, WT};
use crate::math::Vec2;

/// The quantities of one point of the path: the contact velocities, the normal forces and the
/// tangential impulse rates.
#[derive(Debug, Clone, Copy)]
pub(super) struct Eval {
    /// `v = v⁻ + W p`.
    pub v: [f64; ROWS],
    /// `F_j = dp_nj/dτ`.
    pub f: [f64; MAXK],
    /// `dp_tj/dτ`.
    pub pt: [Vec2; MAXK],
}

/// Contact `j`'s tangential velocity in `v`.
#[inline(always)]
pub(super) fn slip(v: &[f64; ROWS], j: usize) -> Vec2 {
    Vec2::new(v[3 * j], v[3 * j + 1])
}

/// The tangential impulse rates given the normal forces `f` and the velocities `v`: slip
/// `−μ F ŝ`, stick by the stick set's least-norm solve.
#[inline(always)]
pub(super) fn tangential_rates(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
) -> [Vec2; MAXK] {
    rates_of_k(setup, modes, f, v, setup.k)
}

/// [`tangential_rates`] with the number of contacts `k` given (a constant where the
/// state's size is: the loops then unrolled).
#[inline(always)]
fn rates_of_k(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    k: usize,
) -> [Vec2; MAXK] {
    let mut pt = [Vec2::zeros(); MAXK];
    for j in (0..k).filter(|&j| modes.active(j) && setup.mu[j] > 0.0) {
        match modes.tangent[j] {
            Tangent::Slip => {
                let vt = slip(v, j);
                let sigma = (vt.x * vt.x + vt.y * vt.y).sqrt();
                if sigma > 0.0 {
                    pt[j] = vt * (-setup.mu[j] * f[j] / sigma);
                }
            }
            Tangent::Fixed { dir, .. } => pt[j] = dir * (-setup.mu[j] * f[j]),
            Tangent::Stick => {}
        }
    }
    let st = &modes.stick;
    let n = st.n;
    if n > 0 {
        // (Stick contacts have no rate yet: pt is zero there.)
        let mut q = [0.0; ROWS];
        for c in 0..k {
            q[3 * c] = pt[c].x;
            q[3 * c + 1] = pt[c].y;
            q[3 * c + 2] = f[c];
        }
        let mut r = [0.0; 2 * MAXK];
        for (i, &a) in st.idx[..n].iter().enumerate() {
            r[2 * i] = dot(&setup.w[3 * a][..3 * k], &q[..3 * k]);
            r[2 * i + 1] = dot(&setup.w[3 * a + 1][..3 * k], &q[..3 * k]);
        }
        for (i, &a) in st.idx[..n].iter().enumerate() {
            pt[a] = Vec2::new(
                -dot(&st.pinv[2 * i][..2 * n], &r[..2 * n]),
                -dot(&st.pinv[2 * i + 1][..2 * n], &r[..2 * n]),
            );
        }
    }
    pt
}

/// `Σ a_i b_i`.
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The velocities, forces and tangential rates at the state `y`.
#[inline(always)]
pub(super) fn eval(setup: &Setup, modes: &Modes, y: &[f64]) -> Eval {
    eval_k(setup, modes, y, setup.k)
}

/// [`eval`] with the number of contacts `k` given (as [`rates_of_k`]).
#[inline(always)]
fn eval_k(setup: &Setup, modes: &Modes, y: &[f64], k: usize) -> Eval {
    let n = 3 * k;
    let mut p = [0.0; ROWS];
    for c in 0..k {
        p[3 * c] = y[PER * c + PT1];
        p[3 * c + 1] = y[PER * c + PT2];
        p[3 * c + 2] = y[PER * c + PN];
    }
    let mut v = [0.0; ROWS];
    for ((vi, row), v0) in v.iter_mut().zip(&setup.w[..n]).zip(&setup.v0[..n]) {
        *vi = v0 + dot(&row[..n], &p[..n]);
    }
    let mut f = [0.0; MAXK];
    for (j, fj) in f.iter_mut().enumerate().take(k) {
        if modes.active(j) {
            *fj = setup.force(j, y[PER * j + S]);
        }
    }
    let pt = rates_of_k(setup, modes, &f, &v, k);
    Eval { v, f, pt }
}

/// `dy/dτ` (module docs) and the quantities of the point.
#[inline(always)]
pub(super) fn rates<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    y: &[f64; N],
) -> ([f64; N], Eval) {
    // (N = 5K: the contacts' loops unrolled for each K.)
    let ev = eval_k(setup, modes, y, N / PER);
    let mut dy = [0.0; N];
    for j in 0..N / PER {
        let vn = ev.v[3 * j + 2];
        let o = PER * j;
        dy[o + PT1] = ev.pt[j].x;
        dy[o + PT2] = ev.pt[j].y;
        dy[o + PN] = ev.f[j];
        dy[o + S] = match modes.normal[j] {
            Normal::Off => 0.0,
            Normal::Compression => -vn,
            Normal::Expansion => -vn / (setup.e[j] * setup.e[j]),
        };
        dy[o + WT] = ev.v[3 * j] * ev.pt[j].x + ev.v[3 * j + 1] * ev.pt[j].y;
    }
    (dy, ev)
}

/// How far contact `j`'s tangential impulse rate `pt[j]` is outside its friction cone
/// (`> 0`: outside): `|pt_j| − μ_j F_j` less the round-off of the stick solve,
/// [`super::STICK_ROUND_OFF`] of the impact's force scale ([`Setup::fscale`]).
#[inline]
pub(super) fn cone_excess(setup: &Setup, j: usize, pt: &[Vec2; MAXK], f: &[f64; MAXK]) -> f64 {
    pt[j].norm() - setup.mu[j] * f[j] - super::STICK_ROUND_OFF * setup.fscale
}

/// The rate of change of contact `j`'s tangential velocity, `dv_tj/dτ = (W dp/dτ)_tj`,
/// given the normal forces `f` and the tangential rates `pt`.
#[inline]
pub(super) fn slip_rate(setup: &Setup, j: usize, f: &[f64; MAXK], pt: &[Vec2; MAXK]) -> Vec2 {
    let mut a = [0.0; 2];
    for (ax, out) in a.iter_mut().enumerate() {
        let row = &setup.w[3 * j + ax];
        for c in 0..setup.k {
            *out += row[3 * c] * pt[c].x + row[3 * c + 1] * pt[c].y + row[3 * c + 2] * f[c];
        }
    }
    Vec2::new(a[0], a[1])
}

/// The round-off scale of contact `j`'s accelerations: `Σ_c |W_{t j, c}| |dp_c/dτ|`.
#[inline]
pub(super) fn rate_scale(setup: &Setup, j: usize, f: &[f64; MAXK], pt: &[Vec2; MAXK]) -> f64 {
    let mut x = 0.0;
    for ax in 0..2 {
        let row = &setup.w[3 * j + ax];
        for c in 0..setup.k {
            x += (row[3 * c] * pt[c].x).abs()
                + (row[3 * c + 1] * pt[c].y).abs()
                + (row[3 * c + 2] * f[c]).abs();
        }
    }
    x
}
