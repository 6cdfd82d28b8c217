//! Chebyshev–Lobatto panels: the spectral building blocks of the spatial slip stage in the
//! angle variable (Trefethen, *Approximation Theory and Approximation Practice*, SIAM 2013,
//! ch. 2–3 and 19; Greengard, SIAM J. Numer. Anal. 28 (1991) 1071, for the spectral
//! integration matrix).
//!
//! On `[−1, 1]` the `N + 1` Lobatto points `t_j = −cos(π j / N)` (ascending) carry values
//! `v_j` of a function; the interpolant `p(t) = Σ_m c_m T_m(t)` has
//!
//! ```text
//! c_m = (2/N) Σ''_j v_j T_m(t_j)        (Σ'' halves the first and last terms,
//!                                        and c_0, c_N are halved once more),
//! ∫_{−1}^{t} T_0 = t + 1,   ∫_{−1}^{t} T_1 = (t² − 1)/2,
//! ∫_{−1}^{t} T_m = [T_{m+1}(t)/(m+1) − T_{m−1}(t)/(m−1)]/2 + (−1)^m/(1 − m²)   (m ≥ 2).
//! ```
//!
//! The cumulative integral at every node is one matrix product (exact for polynomials of
//! degree `N`); for an analytic integrand it converges geometrically, and the size of the last
//! two coefficients `|c_{N−1}| + |c_N|` estimates the error. The interpolant is evaluated
//! anywhere by the barycentric formula with weights `(−1)^j`, halved at the ends
//! (Berrut & Trefethen, SIAM Rev. 46 (2004) 501).

use std::sync::OnceLock;

/// Panel degree: `N + 1 = 17` nodes.
pub(crate) const N: usize = 16;
/// Number of nodes.
pub(crate) const M: usize = N + 1;

/// The node set with its integration matrix, tail rows and barycentric weights.
pub(crate) struct Lobatto {
    /// The nodes `t_j = −cos(π j/N)`, ascending from −1 to 1.
    pub t: [f64; M],
    /// `integ_t[k][j − 1] = ∫_{−1}^{t_j} ℓ_k(t) dt` (`ℓ_k` the Lagrange basis), by columns,
    /// for `j = 1 … N` (the integral to `t_0 = −1` is zero): sixteen entries, eight pairs.
    integ_t: [[f64; N]; M],
    /// Rows giving `c_{N−1}` and `c_N` from the values.
    tail: [[f64; M]; 2],
    /// Barycentric weights.
    bw: [f64; M],
}

static LOBATTO: OnceLock<Lobatto> = OnceLock::new();

/// The 17-point Lobatto panel (built once).
pub(crate) fn lobatto() -> &'static Lobatto {
    LOBATTO.get_or_init(Lobatto::build)
}

/// `∫_{−1}^{t} T_m(τ) dτ` with `T_k(t) = cos(k θ)`, `t = cos θ`.
fn integral_of_t(m: usize, theta: f64) -> f64 {
    let t = theta.cos();
    match m {
        0 => t + 1.0,
        1 => 0.5 * (t * t - 1.0),
        _ => {
            let mf = m as f64;
            let at_t = 0.5
                * (((mf + 1.0) * theta).cos() / (mf + 1.0)
                    - ((mf - 1.0) * theta).cos() / (mf - 1.0));
            let sign = if m.is_multiple_of(2) { 1.0 } else { -1.0 };
            at_t + sign / (1.0 - mf * mf)
        }
    }
}

impl Lobatto {
    fn build() -> Lobatto {
        let pi = std::f64::consts::PI;
        let nf = N as f64;
        // θ_j with t_j = cos θ_j = −cos(π j/N): θ_j = π (N − j)/N.
        let theta: [f64; M] = std::array::from_fn(|j| pi * (N - j) as f64 / nf);
        let t: [f64; M] = std::array::from_fn(|j| {
            if j == 0 {
                -1.0
            } else if j == N {
                1.0
            } else if 2 * j == N {
                0.0
            } else {
                -(pi * j as f64 / nf).cos()
            }
        });
        // coef[m][k]: c_m of the basis vector e_k.
        let mut coef = [[0.0; M]; M];
        for (m, row) in coef.iter_mut().enumerate() {
            for (k, c) in row.iter_mut().enumerate() {
                let end = if k == 0 || k == N { 0.5 } else { 1.0 };
                let halve = if m == 0 || m == N { 0.5 } else { 1.0 };
                *c = 2.0 / nf * end * halve * (m as f64 * theta[k]).cos();
            }
        }
        let mut integ = [[0.0; M]; M];
        // Row 0 (the integral from −1 to −1) stays exactly zero.
        for (j, row) in integ.iter_mut().enumerate().skip(1) {
            let im: [f64; M] = std::array::from_fn(|m| integral_of_t(m, theta[j]));
            for (k, x) in row.iter_mut().enumerate() {
                *x = (0..M).map(|m| coef[m][k] * im[m]).sum();
            }
        }
        let bw = std::array::from_fn(|j| {
            let s = if j % 2 == 0 { 1.0 } else { -1.0 };
            if j == 0 || j == N {
                0.5 * s
            } else {
                s
            }
        });
        let integ_t = std::array::from_fn(|k| std::array::from_fn(|j| integ[j + 1][k]));
        Lobatto {
            t,
            integ_t,
            tail: [coef[N - 1], coef[N]],
            bw,
        }
    }

    /// The cumulative integral `∫_{−1}^{t_j}` of the interpolant of `v`, at every node.
    #[inline]
    pub(crate) fn cumulative(&self, v: &[f64; M]) -> [f64; M] {
        // Column by column (`integ_t[k][j − 1] = integ[j][k]`): independent lanes that
        // vectorise; the first node's integral is zero.
        let mut acc = [0.0; N];
        for (col, &vk) in self.integ_t.iter().zip(v.iter()) {
            for (o, &c) in acc.iter_mut().zip(col.iter()) {
                *o += c * vk;
            }
        }
        let mut out = [0.0; M];
        out[1..].copy_from_slice(&acc);
        out
    }

    /// The integral over the whole panel `∫_{−1}^{1}` of the interpolant of `v`
    /// (Clenshaw–Curtis).
    #[inline]
    pub(crate) fn integral(&self, v: &[f64; M]) -> f64 {
        self.integ_t
            .iter()
            .zip(v.iter())
            .map(|(col, x)| col[N - 1] * x)
            .sum()
    }

    /// `|c_{N−1}| + |c_N|`: the size of the last two Chebyshev coefficients of `v`.
    #[inline]
    pub(crate) fn tail(&self, v: &[f64; M]) -> f64 {
        let dot = |r: &[f64; M]| -> f64 { r.iter().zip(v.iter()).map(|(a, b)| a * b).sum() };
        dot(&self.tail[0]).abs() + dot(&self.tail[1]).abs()
    }

    /// [`Lobatto::tail`] and the largest `|v_j|` of `K` integrands in one pass.
    #[inline]
    pub(crate) fn tails_and_sizes<const K: usize>(
        &self,
        vs: [&[f64; M]; K],
    ) -> ([f64; K], [f64; K]) {
        let (mut a, mut b, mut size) = ([0.0; K], [0.0; K], [0.0f64; K]);
        #[allow(clippy::needless_range_loop)] // j indexes the two rows and every integrand
        for j in 0..M {
            let (ra, rb) = (self.tail[0][j], self.tail[1][j]);
            for k in 0..K {
                let x = vs[k][j];
                a[k] += ra * x;
                b[k] += rb * x;
                size[k] = size[k].max(x.abs());
            }
        }
        (std::array::from_fn(|k| a[k].abs() + b[k].abs()), size)
    }

    /// The Lagrange basis at `t`: `ℓ_k(t)`, so that the interpolant of `v` at `t` is
    /// `Σ ℓ_k(t) v_k` (barycentric formula; exact at the nodes).
    #[inline]
    pub(crate) fn basis(&self, t: f64) -> [f64; M] {
        let mut out = [0.0; M];
        if let Some(j) = self.t.iter().position(|&tj| tj == t) {
            out[j] = 1.0;
            return out;
        }
        let mut sum = 0.0;
        for ((o, &tj), &w) in out.iter_mut().zip(self.t.iter()).zip(self.bw.iter()) {
            *o = w / (t - tj);
            sum += *o;
        }
        let inv = 1.0 / sum;
        for o in out.iter_mut() {
            *o *= inv;
        }
        out
    }
}

/// `Σ ℓ_k v_k`.
#[inline]
pub(crate) fn dot(l: &[f64; M], v: &[f64; M]) -> f64 {
    l.iter().zip(v.iter()).map(|(a, b)| a * b).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_of_degree_n_exactly() {
        let l = lobatto();
        for deg in 0..=N {
            let v: [f64; M] = std::array::from_fn(|j| l.t[j].powi(deg as i32));
            let c = l.cumulative(&v);
            for (j, (&cj, &tj)) in c.iter().zip(l.t.iter()).enumerate() {
                let exact =
                    (tj.powi(deg as i32 + 1) - (-1f64).powi(deg as i32 + 1)) / (deg as f64 + 1.0);
                assert!(
                    (cj - exact).abs() < 1e-15,
                    "deg {deg} node {j}: {}",
                    cj - exact
                );
            }
            if deg + 1 < N {
                assert!(l.tail(&v) < 1e-14, "deg {deg}: tail {}", l.tail(&v));
            }
        }
    }

    #[test]
    fn exponential_to_machine_precision_with_a_vanishing_tail() {
        let l = lobatto();
        let v: [f64; M] = std::array::from_fn(|j| (1.5 * l.t[j]).exp());
        let c = l.cumulative(&v);
        for (&cj, &tj) in c.iter().zip(l.t.iter()) {
            let exact = ((1.5 * tj).exp() - (-1.5f64).exp()) / 1.5;
            assert!(
                (cj - exact).abs() < 2e-15 * exact.abs().max(1.0),
                "{}",
                cj - exact
            );
        }
        assert!(l.tail(&v) < 1e-13);
        // A function with a nearby singularity has a visible tail.
        let w: [f64; M] = std::array::from_fn(|j| 1.0 / (1.05 - l.t[j]));
        assert!(l.tail(&w) > 1e-3);
    }

    #[test]
    fn tails_in_one_pass_are_the_tails_one_by_one() {
        let l = lobatto();
        let a: [f64; M] = std::array::from_fn(|j| 1.0 / (1.05 - l.t[j]));
        let b: [f64; M] = std::array::from_fn(|j| -(3.0 * l.t[j]).cos());
        let (tails, sizes) = l.tails_and_sizes([&a, &b]);
        for (k, v) in [a, b].iter().enumerate() {
            assert_eq!(tails[k], l.tail(v));
            assert_eq!(sizes[k], v.iter().fold(0.0f64, |m, x| m.max(x.abs())));
        }
    }

    #[test]
    fn barycentric_interpolation_is_spectral() {
        let l = lobatto();
        let v: [f64; M] = std::array::from_fn(|j| (2.0 * l.t[j]).sin());
        for &t in &[-0.999, -0.3, 0.0, 0.123, 0.77, 1.0] {
            let got = dot(&l.basis(t), &v);
            assert!((got - (2.0 * t).sin()).abs() < 1e-14, "t {t}");
        }
    }
}
