//! The series of the impact's start in `z = τ^(η+1)`, from `τ = 0` to the first event.
//!
//! Every contact that carries a force at the start approaches (`v_nj⁻ < 0`) and has
//! `s_j = −v_nj⁻ τ + …`; its force `κ_j s_j^η ∝ τ^η` is not analytic at `τ = 0`. By induction
//! on the terms, `ds/dτ = −v_n/div`, `dv/dτ = A F` give
//!
//! ```text
//! s_j = τ q_j(z),   F_j = τ^η κ_j q_j^η,   p_j, v_j, w_tj analytic in z = τ^(η+1),
//! ```
//!
//! for any `η > 0` (each term of `s_j` is `τ^(1 + n(η+1))`: a force `∝ τ^(η + n(η+1))`
//! integrates twice to `τ^(1 + (n+1)(η+1))`). With `dτ/dz = τ^(−η)/(η+1)`, in `z`
//!
//! ```text
//! dp_nj/dz = κ_j q_j^η / (η+1),        z dq_j/dz = (−v_nj/div_j − q_j) / (η+1),
//! ```
//!
//! so, with `t = z − z₀`: at `z₀ = 0`, `q_j,k = −v_nj,k / (div_j ((η+1) k + 1))` (the
//! velocities of order `k` come from the impulses of order `k`, which come from the forces
//! of order `k − 1`: the recurrence is explicit); at `z₀ > 0`,
//! `z₀ (k+1) q_j,k+1 = (−v_nj,k/div_j − q_j,k)/(η+1) − k q_j,k`. The force's coefficients
//! are those of `q_j^η` by the power recurrence (`q_j(0) > 0`), the tangential impulses and
//! the works as in `τ`.
//!
//! In `u = √τ` the same path is `s_j = u² G(u^(2η+2))`: of a series of order 17 only four
//! terms are nonzero, and its steps are short. In `z` every order counts: the radius of
//! convergence is that of the path's nearest complex singularity, `z` of the complex points
//! where a contact alone would separate elastically, and a first step reaches most of the way
//! to the first compression's end (the 256 random problems of the benchmark: see the
//! performance chapter).

use super::{force_order, normal_map, tangential_rows, Series, F, ORDER, RECIP, VN, VT};
use crate::multi::lzb::field::{Eval, Field};
use crate::multi::lzb::state::{Setup, PER, PN, S};
use crate::multi::lzb::RTOL;

impl<const N: usize> Series<N> {
    /// The series of the start from `(z0, y)` (module docs) in the regimes of `field`, and its
    /// step; `false` where it does not apply (a loaded contact with `q_j ≤ 0` or a force
    /// `κ_j q_j^η` below the normal numbers, or no finite step: the start is then taken in
    /// `u`).
    #[allow(clippy::needless_range_loop)] // the rows are indexed by order and contact alike
    pub(super) fn build_onset(
        &mut self,
        setup: &Setup,
        field: &Field,
        z0: f64,
        y: &[f64; N],
    ) -> bool {
        let k = N / PER;
        let eta = setup.law.eta;
        let inv_p = 1.0 / (eta + 1.0);
        let tau0 = setup.law.onset_time(z0);
        let Eval { v: v0, .. } = field.eval::<N>(setup, y);
        // q_j(z₀): −v_nj⁻/div_j at the start, s_j/τ after it.
        let (mut q0, mut inv_q0, mut inv_div) = ([0.0; N], [0.0; N], [0.0; N]);
        let mut qmax = 0.0f64;
        for j in (0..k).filter(|&j| field.active(j)) {
            inv_div[j] = 1.0 / field.div(j);
            let q = if z0 == 0.0 {
                -v0[2 * j + 1] * inv_div[j]
            } else {
                y[PER * j + S] / tau0
            };
            if !(q > 0.0 && q.is_finite()) {
                return false;
            }
            (q0[j], inv_q0[j]) = (q, 1.0 / q);
            qmax = qmax.max(q);
            // (A force that underflows would stay zero through the power recurrence.)
            if setup.kappa[j] * setup.law.power.of(q) < f64::MIN_POSITIVE {
                return false;
            }
        }
        let amap = normal_map::<N>(setup, field);
        let (c, aux) = (&mut self.c, &mut self.aux);
        c[0] = *y;
        for j in 0..k {
            c[0][PER * j + S] = q0[j];
            aux[0][F * k + j] = if field.active(j) {
                setup.kappa[j] * setup.law.power.of(q0[j])
            } else {
                0.0
            };
            aux[0][VT * k + j] = v0[2 * j];
            aux[0][VN * k + j] = v0[2 * j + 1];
        }
        for kk in 0..=ORDER {
            if kk > 0 {
                // The velocities of order kk (A p_n,kk) and, at z₀ = 0, q of order kk.
                let mut vn = [0.0; N];
                for j in 0..k {
                    let (mut a, mut b) = (0.0, 0.0);
                    for cc in 0..k {
                        let pnk = c[kk][PER * cc + PN];
                        a += amap[2 * j][cc] * pnk;
                        b += amap[2 * j + 1][cc] * pnk;
                    }
                    vn[j] = b;
                    if kk < ORDER {
                        aux[kk][VT * k + j] = a;
                        aux[kk][VN * k + j] = b;
                    }
                }
                if z0 == 0.0 {
                    let denom = 1.0 / ((eta + 1.0) * kk as f64 + 1.0);
                    for j in 0..k {
                        c[kk][PER * j + S] = -vn[j] * inv_div[j] * denom;
                    }
                }
                if kk == ORDER {
                    break;
                }
                force_order(c, aux, kk, eta, &inv_q0);
            }
            if z0 > 0.0 {
                let inv = 1.0 / (z0 * (kk + 1) as f64);
                for j in 0..k {
                    let q = c[kk][PER * j + S];
                    let rate = (-aux[kk][VN * k + j] * inv_div[j] - q) * inv_p;
                    // (Zero for a contact without force: q and inv_div are.)
                    c[kk + 1][PER * j + S] = (rate - kk as f64 * q) * inv;
                }
            }
            // The normal impulses of order kk + 1: dp_n/dz = κ q^η/(η+1) (p_t = T p_n and the
            // works after the loop).
            let inv = RECIP[kk + 1];
            for j in 0..k {
                c[kk + 1][PER * j + PN] = aux[kk][F * k + j] * inv_p * inv;
            }
        }
        tangential_rows(c, aux, field);
        // The tolerance of q_j: relative, as of the velocity it is (plus a tenth of it of the
        // largest, for the contacts without force, whose rows are zero).
        let c0 = c[0];
        let tol = |i: usize| {
            if i % PER == S {
                RTOL * (c0[i].abs() + 0.1 * qmax)
            } else {
                setup.atol[i] + RTOL * y[i].abs()
            }
        };
        let Some(h) = self.step(tol) else {
            return false;
        };
        self.h = h;
        self.onset = Some((z0, inv_p));
        true
    }
}
