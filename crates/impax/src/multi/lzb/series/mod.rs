//! The path's Taylor series in one set of regimes: the step where every contact that carries
//! a force is loaded (`s_j > 0`), so that `F_j = κ_j s_j^η` is analytic there, or starts
//! loading from a double zero of `s_j` — a contact joining at `v_nj = 0` (`s_j ∝ t²`), and
//! the impact's start in `u = √τ` (`s_j = −v_nj⁻ u² + …`; the start is taken in `z`,
//! `onset.rs`, and in `u` only where that does not apply) — where, with `s_j = t² q_j`,
//! `q_j(0) > 0`, the force `κ_j |t|^(2η) q_j^η` is analytic for an integer `2η` (`η = 3/2`:
//! `|t|³`), its coefficients those of `q_j^η` shifted by `2η` orders.
//!
//! In a fixed set of regimes ([`Field`]) the right-hand side in `τ` is
//!
//! ```text
//! ds_j/dτ = −v_nj / div_j,   dp_nj/dτ = F_j = κ_j s_j^η,   dp_t/dτ = T F,
//! dw_tj/dτ = v_tj dp_tj/dτ,  v = v⁻ + W p,
//! ```
//!
//! and in a regularising variable `x` (`variable.rs`) every rate is multiplied by
//! `g = dτ/dx`: `m u^(m−1)` in `u = τ^(1/m)`, `−m σ^(m−1) e_j²/v_nj` in a separation's
//! `σ = s_j^(1/m)` (where `s_j = σ^m` exactly). Its Taylor coefficients in `t = x − x₀`
//! follow order by order from the recurrences of automatic differentiation (Griewank &
//! Walther, *Evaluating Derivatives*, 2nd ed., SIAM 2008, §13.2; Jorba & Zou, *A software
//! package for the numerical integration of ODEs by means of high-order Taylor methods*,
//! Experimental Mathematics 14 (2005) 99–117): with `a = s^α`, `s₀ > 0`,
//!
//! ```text
//! a₀ = s₀^α,   a_k = (1/(k s₀)) Σ_{i<k} (α (k − i) − i) s_{k−i} a_i,
//! (g f)_k = Σ_i g_i f_{k−i},      y_{k+1} = (dy/dx)_k / (k + 1),
//! (1/v)·: q_k = (n_k − Σ_{i≥1} v_i q_{k−i}) / v₀      (the quotient q = n/v),
//! ```
//!
//! and the velocities' coefficients `W p_k` (linear). The series is taken to order
//! [`ORDER`]; its step is where its last two terms reach the tolerance of each component
//! (`atol + RTOL |y|`, as the Runge–Kutta steps' error test), the step-size rule of Jorba &
//! Zou (their §3.2) with a safety factor: the first neglected term is then about `h/ρ` of
//! the tolerance, `ρ` the series' radius of convergence. The series is its own dense output,
//! of the same order, so an event inside the step is located on it and the path goes on from
//! it exactly there.

use super::field::{Eval, Field};
use super::state::{Setup, MAXK, PER, PN, PT, S, WT};
use super::variable::Var;
use super::RTOL;

/// The order of the series. The work per series grows as the order's square and the step
/// as `RTOL^(1/16)` of the radius of convergence (0.18; the step is set by the term of order
/// 16, the last one guarding it): near the least work per unit of path at `RTOL = 1e-12`
/// (Jorba & Zou's optimal order, `−½ ln RTOL + 1`, is 14.8).
pub(super) const ORDER: usize = 17;

/// The step's factor on the radius the last two terms suggest.
const SAFETY: f64 = 0.9;

/// The blocks of [`Series`]'s `aux` rows (`K` entries each, contact `j` at `K b + j`): the
/// forces, the normal and tangential velocities, `dp_t/dx`.
const F: usize = 0;
const VN: usize = 1;
const VT: usize = 2;
const DPT: usize = 3;

/// `1/k` for `k = 0 … ORDER + 1` (`0` for `k = 0`).
const RECIP: [f64; ORDER + 2] = {
    let mut r = [0.0; ORDER + 2];
    let mut k = 1;
    while k < ORDER + 2 {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

/// The state's Taylor series over one step, `y(x₀ + t) = Σ_k c_k t^k`, and the working
/// coefficients it is built from (kept between steps: every entry read is written first).
#[derive(Debug, Clone)]
pub(super) struct Series<const N: usize> {
    /// The coefficients, `c[k][i]` that of `t^k` in component `i` (the state's layout).
    c: [[f64; N]; ORDER + 1],
    /// By order, per contact: the force, `v_n`, `v_t`, `dp_t/dx` (blocks of `K`).
    aux: [[f64; N]; ORDER],
    /// The step (signed: negative in a separation's variable, which decreases).
    pub h: f64,
    /// In the start's variable `z` (`onset.rs`): where the step starts, `z₀`, and
    /// `1/(η+1)`; the rows of `s_j` then hold `q_j = s_j/τ`.
    onset: Option<(f64, f64)>,
}

impl<const N: usize> Series<N> {
    /// An empty series.
    pub(super) fn new() -> Self {
        Series {
            c: [[0.0; N]; ORDER + 1],
            aux: [[0.0; N]; ORDER],
            h: 0.0,
            onset: None,
        }
    }

    /// The state at `t = θ h` (Horner). A normal impulse never decreases (`dp_nj = F_j dτ`,
    /// `F_j ≥ 0`): one that the series puts below its start — a contact just joined, whose
    /// impulse is still below the tolerance, by round-off of the tolerance's size — is held
    /// there. In the start's variable `z` the rows of `s_j` hold `q_j`: `s_j = τ q_j`.
    #[inline]
    pub(super) fn at(&self, theta: f64) -> [f64; N] {
        let t = theta * self.h;
        let mut out = self.c[ORDER];
        for ck in self.c[..ORDER].iter().rev() {
            for (o, c) in out.iter_mut().zip(ck) {
                *o = *o * t + c;
            }
        }
        for j in 0..N / PER {
            let o = PER * j + PN;
            out[o] = out[o].max(self.c[0][o]);
        }
        if let Some((z0, inv_p)) = self.onset {
            // s_j = τ q_j, τ = z^(1/(η+1)).
            let tau = (z0 + t).max(0.0).powf(inv_p);
            for j in 0..N / PER {
                out[PER * j + S] *= tau;
            }
        }
        out
    }

    /// The step's end, `θ = 1`.
    #[inline]
    pub(super) fn end(&self) -> [f64; N] {
        self.at(1.0)
    }

    /// The Taylor series of the path from `(x0, y)` in the variable `var` and the regimes
    /// of `field`, and its step. `false` where it does not apply: a contact carrying a force
    /// is unloaded (`s_j ≤ 0`) other than from a double zero of `s_j` with `2η` an integer
    /// (module docs), a force from a double zero that does not grow, or no finite step; the
    /// Runge–Kutta step is taken there.
    #[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
    pub(super) fn build(
        &mut self,
        setup: &Setup,
        field: &Field,
        var: Var,
        x0: f64,
        y: &[f64; N],
    ) -> bool {
        self.onset = None;
        if var == Var::Onset {
            return self.build_onset(setup, field, x0, y);
        }
        let k = N / PER;
        let alpha = setup.law.eta;
        // Order 0: the point's velocities and forces, as the field gives them.
        let Eval { v: v0, f: f0, .. } = field.eval::<N>(setup, y);
        let Some(Loads {
            act,
            inv_s0,
            inv_div,
            from_zero,
        }) = Loads::of(setup, field, var, x0, y, &v0)
        else {
            return false;
        };
        // A force from zero: F_j = κ_j |t|^ζ q_j^η, in a separation's variable (which
        // decreases, t < 0) (−t)^ζ.
        let zeta = setup.law.double_zero.unwrap_or(0);
        let odd = zeta % 2 == 1 && var.separating().is_some();
        let amap = normal_map::<N>(setup, field);
        let Some(Rate {
            mut g,
            num,
            sep_s,
            glen,
            sep,
        }) = Rate::of(setup, var, x0)
        else {
            return false;
        };
        let in_time = var == Var::Time;
        let (c, aux) = (&mut self.c, &mut self.aux);
        c[0] = *y;
        for j in 0..k {
            aux[0][F * k + j] = f0[j];
        }
        for kk in 0..ORDER {
            // The velocities: v⁻ + W p at order 0, A p_n,k after.
            if kk == 0 {
                for j in 0..k {
                    aux[0][VT * k + j] = v0[2 * j];
                    aux[0][VN * k + j] = v0[2 * j + 1];
                }
            } else {
                for j in 0..k {
                    let (mut a, mut b) = (0.0, 0.0);
                    for cc in 0..k {
                        let pnk = c[kk][PER * cc + PN];
                        a += amap[2 * j][cc] * pnk;
                        b += amap[2 * j + 1][cc] * pnk;
                    }
                    aux[kk][VT * k + j] = a;
                    aux[kk][VN * k + j] = b;
                }
            }
            // g at this order, in a separation: g = num / v_nj.
            if let Some(js) = sep {
                // (Two partial sums: the additions of one chain wait on each other.)
                let (mut acc0, mut acc1) = (num[kk], 0.0);
                let mut i = 1;
                while i < kk {
                    acc0 -= aux[i][VN * k + js] * g[kk - i];
                    acc1 -= aux[i + 1][VN * k + js] * g[kk - i - 1];
                    i += 2;
                }
                if i == kk {
                    acc0 -= aux[i][VN * k + js] * g[0];
                }
                g[kk] = (acc0 + acc1) / aux[0][VN * k + js];
            }
            if kk > 0 {
                force_order(c, aux, kk, alpha, &inv_s0);
                for j in (0..k).filter(|&j| from_zero & (1 << j) != 0) {
                    let base = if odd { -setup.kappa[j] } else { setup.kappa[j] };
                    let Some(fk) = force_from_zero(c, aux, kk, j, zeta, alpha, base) else {
                        return false;
                    };
                    aux[kk][F * k + j] = fk;
                }
            }
            // The normal impulses and deflections at order kk + 1.
            let inv = RECIP[kk + 1];
            let (mut dphi, mut ds) = ([0.0; N], [0.0; N]);
            if in_time {
                // (g = 1.)
                for j in 0..k {
                    dphi[j] = aux[kk][F * k + j];
                    ds[j] = aux[kk][VN * k + j];
                }
            } else {
                // (Two partial sums each, as above.)
                let (mut dphi1, mut ds1) = ([0.0; N], [0.0; N]);
                let n = glen.min(kk + 1);
                let mut i = 0;
                while i + 1 < n {
                    let (g0, a0, g1, a1) = (g[i], &aux[kk - i], g[i + 1], &aux[kk - i - 1]);
                    for j in 0..k {
                        dphi[j] += g0 * a0[F * k + j];
                        ds[j] += g0 * a0[VN * k + j];
                        dphi1[j] += g1 * a1[F * k + j];
                        ds1[j] += g1 * a1[VN * k + j];
                    }
                    i += 2;
                }
                if i < n {
                    let (gi, a) = (g[i], &aux[kk - i]);
                    for j in 0..k {
                        dphi[j] += gi * a[F * k + j];
                        ds[j] += gi * a[VN * k + j];
                    }
                }
                for j in 0..k {
                    dphi[j] += dphi1[j];
                    ds[j] += ds1[j];
                }
            }
            for j in 0..k {
                c[kk + 1][PER * j + PN] = dphi[j] * inv;
                c[kk + 1][PER * j + S] = -ds[j] * inv * act[j] * inv_div[j];
            }
            if kk == 0 && from_zero != 0 {
                // A contact joining starts at v_nj = 0 (to round-off): s_j = O(t²) exactly.
                for j in (0..k).filter(|&j| from_zero & (1 << j) != 0) {
                    c[1][PER * j + S] = 0.0;
                }
            }
            if let Some(js) = sep {
                c[kk + 1][PER * js + S] = sep_s[kk + 1];
            }
        }
        tangential_rows(c, aux, field);
        let Some(h) = self.step(|i| setup.atol[i] + RTOL * y[i].abs()) else {
            return false;
        };
        self.h = if sep.is_some() { -h.min(x0) } else { h };
        true
    }

    /// The step of the series: where the term of order 16 reaches the tolerance `tol(i)` of
    /// every component (`atol + RTOL |y|` at the step's start; its root by four square roots),
    /// or the last, of order 17, if it is larger there (a vanishing term of order 16). `None`
    /// where the coefficients overflow or one is NaN (friction of `1e100` stops a slip within
    /// `τ ≈ 1/μ`: DOP853 then takes the step, and rejects its non-finite steps).
    fn step(&self, tol: impl Fn(usize) -> f64) -> Option<f64> {
        let c = &self.c;
        let (mut r1, mut r0) = (0.0f64, 0.0f64);
        for (i, (last, before)) in c[ORDER].iter().zip(&c[ORDER - 1]).enumerate() {
            let tol = tol(i);
            let (a1, a0) = (last.abs() / tol, before.abs() / tol);
            // (`max` would pass over a NaN: a coefficient of `∞ − ∞` or `0 · ∞`.)
            if a1.is_nan() || a0.is_nan() {
                return None;
            }
            r1 = r1.max(a1);
            r0 = r0.max(a0);
        }
        if !(r0.is_finite() && r1.is_finite()) {
            return None;
        }
        let mut h = (1.0 / r0).sqrt().sqrt().sqrt().sqrt();
        if r1 * h.powi(ORDER as i32) > 1.0 {
            h = h.min(r1.powf(-1.0 / ORDER as f64));
        }
        h *= SAFETY;
        (h.is_finite() && h > 0.0).then_some(h)
    }
}

/// Per contact: the mask of the contacts that carry a force, `1/s₀` (0 where `s₀ = 0`),
/// `1/div`, and the contacts whose force starts here from zero (bit `j`: `s_j = t² q_j`,
/// module docs).
struct Loads<const N: usize> {
    act: [f64; N],
    inv_s0: [f64; N],
    inv_div: [f64; N],
    from_zero: u32,
}

impl<const N: usize> Loads<N> {
    /// The loads at `x0` in `var`, state `y`, velocities `v0`; `None` where a contact that
    /// carries a force is unloaded and does not start from zero there (NaN included).
    fn of(
        setup: &Setup,
        field: &Field,
        var: Var,
        x0: f64,
        y: &[f64; N],
        v0: &[f64; 2 * MAXK],
    ) -> Option<Self> {
        let mut l = Loads {
            act: [0.0; N],
            inv_s0: [0.0; N],
            inv_div: [0.0; N],
            from_zero: 0,
        };
        let double_zero = setup.law.double_zero.is_some();
        for j in (0..N / PER).filter(|&j| field.active(j)) {
            let sj = y[PER * j + S];
            if sj > 0.0 {
                l.inv_s0[j] = 1.0 / sj;
            } else if sj == 0.0 && double_zero && starts_from_zero(setup, var, x0, v0[2 * j + 1]) {
                l.from_zero |= 1 << j;
            } else {
                return None;
            }
            l.act[j] = 1.0;
            l.inv_div[j] = 1.0 / field.div(j);
        }
        Some(l)
    }
}

/// `g = dτ/dx` in the variable `x`: its coefficients (`len` of them nonzero) or, in a
/// separation's variable, its numerator `−m σ^(m−1) e_j²` (divided order by order by
/// `v_nj`), and the separating contact's `s_j = σ^m`.
struct Rate {
    g: [f64; ORDER + 1],
    num: [f64; ORDER + 1],
    sep_s: [f64; ORDER + 1],
    glen: usize,
    sep: Option<usize>,
}

impl Rate {
    /// The rate at `x0` in `var`; `None` at `x0 = 0` in the start's or a separation's
    /// variable (a force from zero, or the separation itself).
    fn of(setup: &Setup, var: Var, x0: f64) -> Option<Rate> {
        let m = setup.law.m as usize;
        let mut r = Rate {
            g: [0.0; ORDER + 1],
            num: [0.0; ORDER + 1],
            sep_s: [0.0; ORDER + 1],
            glen: 1,
            sep: None,
        };
        match var {
            // (The start's variable has its own series, `onset.rs`.)
            Var::Onset => return None,
            Var::Time => r.g[0] = 1.0,
            Var::Root => {
                // (At u = 0 only for contacts starting from zero, `starts_from_zero`.)
                if x0 < 0.0 {
                    return None;
                }
                binomial_powers(m - 1, x0, &mut r.g);
                for gi in r.g.iter_mut().take(m) {
                    *gi *= m as f64;
                }
                r.glen = m;
            }
            Var::Separation { contact: j, .. } => {
                if x0 <= 0.0 {
                    return None;
                }
                binomial_powers(m - 1, x0, &mut r.num);
                let e2 = setup.e[j] * setup.e[j];
                for ni in r.num.iter_mut().take(m) {
                    *ni *= -(m as f64) * e2;
                }
                binomial_powers(m, x0, &mut r.sep_s);
                r.glen = ORDER + 1;
                r.sep = Some(j);
            }
        }
        Some(r)
    }
}

/// The map of the normal impulses' coefficients to the velocities' (orders `k ≥ 1`, where
/// `p_t,k = T p_n,k`): `v_k = A p_n,k`, `A = W_:t T + W_:n`, `2K × K`.
fn normal_map<const N: usize>(setup: &Setup, field: &Field) -> [[f64; N]; N] {
    let k = N / PER;
    let mut amap = [[0.0; N]; N];
    for (i, arow) in amap.iter_mut().enumerate().take(2 * k) {
        let wrow = &setup.w[i];
        for cc in 0..k {
            let mut a = wrow[2 * cc + 1];
            for b in 0..k {
                a += wrow[2 * b] * field.map_row(b)[cc];
            }
            arow[cc] = a;
        }
    }
    amap
}

/// The tangential impulses and the friction works of every order, from the normal
/// impulses': `p_t − p_t0 = T (p_n − p_n0)` in fixed regimes (`aux`'s `dp_t/dx` with them)
/// and `dw_tj/dx = v_tj dp_tj/dx` ([`work_rate`]). Neither feeds the other recurrences (the
/// velocities' map `A` has `T` in it), so they are formed after them, in one pass whose
/// orders do not wait on each other.
#[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
fn tangential_rows<const N: usize>(
    c: &mut [[f64; N]; ORDER + 1],
    aux: &mut [[f64; N]; ORDER],
    field: &Field,
) {
    let k = N / PER;
    for kk in 0..ORDER {
        for j in 0..k {
            let row = field.map_row(j);
            let mut a = 0.0;
            for cc in 0..k {
                a += row[cc] * c[kk + 1][PER * cc + PN];
            }
            c[kk + 1][PER * j + PT] = a;
            aux[kk][DPT * k + j] = a * (kk + 1) as f64;
        }
    }
    for kk in 0..ORDER {
        let w = work_rate(aux, kk);
        let inv = RECIP[kk + 1];
        for j in 0..k {
            c[kk + 1][PER * j + WT] = if field.rubs(j) { w[j] * inv } else { 0.0 };
        }
    }
}

/// The forces' coefficients of order `kk ≥ 1` (`aux`'s block `F`) by the power recurrence of
/// `a = s^α` (`F = κ a`, `inv_s0 = 1/s₀` per contact, 0 for one without force): two partial
/// sums per contact, the weights `α (kk − i) − i` falling by `α + 1` with `i`.
#[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
fn force_order<const N: usize>(
    c: &[[f64; N]; ORDER + 1],
    aux: &mut [[f64; N]; ORDER],
    kk: usize,
    alpha: f64,
    inv_s0: &[f64; N],
) {
    let k = N / PER;
    let (mut acc0, mut acc1) = ([0.0; N], [0.0; N]);
    let fall = alpha + 1.0;
    let mut c0 = alpha * kk as f64;
    let mut i = 0;
    while i + 1 < kk {
        let c1 = c0 - fall;
        for j in 0..k {
            acc0[j] += c0 * c[kk - i][PER * j + S] * aux[i][F * k + j];
            acc1[j] += c1 * c[kk - i - 1][PER * j + S] * aux[i + 1][F * k + j];
        }
        c0 = c1 - fall;
        i += 2;
    }
    if i < kk {
        for j in 0..k {
            acc0[j] += c0 * c[kk - i][PER * j + S] * aux[i][F * k + j];
        }
    }
    for j in 0..k {
        aux[kk][F * k + j] = (acc0[j] + acc1[j]) * (inv_s0[j] * RECIP[kk]);
    }
}

/// Whether a contact with `s_j = 0` and normal velocity `vn` starts its force here, at `x0`
/// in `var`, from a double zero of `s_j`: at the impact's start in `u` (`s_j = −v_nj⁻ u²`
/// to leading order), or joining at `v_nj = 0` (to [`Setup::approach`]) in `τ` or a
/// separation's variable.
fn starts_from_zero(setup: &Setup, var: Var, x0: f64, vn: f64) -> bool {
    match var {
        Var::Root => x0 == 0.0 && vn < 0.0,
        Var::Onset => false,
        Var::Time | Var::Separation { .. } => vn.abs() <= setup.approach,
    }
}

/// The force's coefficient of order `kk` of contact `j`, whose `s_j = t² q_j` starts from a
/// double zero (`q_i = s_{i+2}`, `q₀ > 0`): `F_j = κ_j |t|^ζ q_j^η = base t^ζ q_j^η`
/// (`base = ±κ_j`, the sign of `t^ζ` along the step), `ζ = 2η` an integer, by the power
/// recurrence of `q^η` (as [`force_order`]'s) shifted by `ζ` orders. `None` where `q₀ ≤ 0`
/// (the contact does not load: the Runge–Kutta step decides).
#[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
fn force_from_zero<const N: usize>(
    c: &[[f64; N]; ORDER + 1],
    aux: &[[f64; N]; ORDER],
    kk: usize,
    j: usize,
    zeta: usize,
    alpha: f64,
    base: f64,
) -> Option<f64> {
    let k = N / PER;
    if kk < zeta {
        return Some(0.0);
    }
    let n = kk - zeta;
    let q0 = c[2][PER * j + S];
    if q0.is_nan() || q0 <= 0.0 {
        return None;
    }
    if n == 0 {
        return Some(base * q0.powf(alpha));
    }
    let mut acc = 0.0;
    for i in 0..n {
        let weight = alpha * (n - i) as f64 - i as f64;
        acc += weight * c[n - i + 2][PER * j + S] * aux[i + zeta][F * k + j];
    }
    Some(acc * RECIP[n] / q0)
}

/// The coefficient of order `kk` of each contact's friction power `v_t dp_t/dx`: the product
/// of the series of `v_t` and of `dp_t/dx` (`aux`'s blocks `VT`, `DPT`), two partial sums.
#[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
fn work_rate<const N: usize>(aux: &[[f64; N]; ORDER], kk: usize) -> [f64; N] {
    let k = N / PER;
    let (mut w0, mut w1) = ([0.0; N], [0.0; N]);
    let mut i = 0;
    while i < kk {
        for j in 0..k {
            w0[j] += aux[i][VT * k + j] * aux[kk - i][DPT * k + j];
            w1[j] += aux[i + 1][VT * k + j] * aux[kk - i - 1][DPT * k + j];
        }
        i += 2;
    }
    if i == kk {
        for j in 0..k {
            w0[j] += aux[kk][VT * k + j] * aux[0][DPT * k + j];
        }
    }
    for j in 0..k {
        w0[j] += w1[j];
    }
    w0
}

/// `C(n, i) x^(n−i)` for `i = 0 … n`: the coefficients of `(x + t)^n` in `t`.
fn binomial_powers(n: usize, x: f64, out: &mut [f64; ORDER + 1]) {
    let mut c = 1.0;
    for (i, o) in out.iter_mut().enumerate().take(n.min(ORDER) + 1) {
        // x^(n−i) by repeated multiplication (n is small: the power m of the variables).
        let mut p = 1.0;
        for _ in 0..n - i {
            p *= x;
        }
        *o = c * p;
        c = c * (n - i) as f64 / (i + 1) as f64;
    }
}

mod onset;
#[cfg(test)]
mod tests;
mod watched;
