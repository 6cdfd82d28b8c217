//! The slip near an invariant ray in closed form: a convergent series about the ray
//! (theory §2, "Spatial"; the linearisation of the direction field at an invariant ray,
//! Poincaré's normal form of a one-dimensional flow).
//!
//! With `u = ln σ` the direction of slip obeys an autonomous scalar equation and everything
//! else is a quadrature weighted by `σ = e^u`:
//!
//! ```text
//! dφ/du = F(φ) = f(φ)/q(φ),   f = ŝ × g,  q = ŝ · g,  g = w_tn − μ W_tt ŝ,
//! dp_n/du = σ/q,  dp_t/du = −μ ŝ σ/q,  dv_n/du = (w_nn − μ w_tn·ŝ) σ/q,
//! dW_n/du = v_n σ/q,  dW_t/du = −μ σ²/q.
//! ```
//!
//! At an invariant ray `φ*` (`f(φ*) = 0`, `q(φ*) ≠ 0`) put `η = φ − φ*` and
//! `λ = F'(φ*) = f'(φ*)/q(φ*)`. The flow is conjugate to its linear part: there is an
//! analytic `h` with `h(ξ) = ξ + b₂ ξ² + …` and `λ ξ h'(ξ) = F(φ* + h(ξ))`, so that
//! `η(u) = h(ξ₀ e^{λ(u−u₀)})` exactly (`λ n b_n = [F∘(φ* + h)]_n = λ b_n + terms of lower
//! order`, so `b_n` follows order by order: no resonance in one dimension; the composition is
//! carried by `C = cos(φ* + h)`, `S = sin(φ* + h)` and their double angles, whose
//! coefficients follow from `C' = −S h'`, `S' = C h'`, so the whole construction is
//! O(terms²)). Along that solution every integrand is `σ` or `σ²`
//! times a power series in `ξ`, and each term integrates in closed form with
//! `E(a, s) = (e^{a s} − 1)/a`:
//!
//! ```text
//! Δp_n(s) = σ₀ Σ r_k ξ₀^k E(1 + kλ, s),          r = 1/q ∘ (φ* + h),
//! Δp_t(s) = −μ σ₀ Σ (c_k, s_k) ξ₀^k E(1 + kλ, s), (c, s) = (cos, sin)/q ∘ (φ* + h),
//! Δv_n(s) = σ₀ Σ κ_k ξ₀^k E(1 + kλ, s),          κ = w_nn r − μ (w₁ c + w₂ s),
//! ΔW_n(s) = v_n₀ Δp_n + σ₀² [Σ_n (κ/(1+jλ) ∗ r)_n ξ₀^n E(2 + nλ, s)
//!                           − Σ_k r_k ξ₀^k E(1 + kλ, s) · Σ_j κ_j ξ₀^j/(1 + jλ)],
//! ΔW_t(s) = −μ σ₀² Σ r_k ξ₀^k E(2 + kλ, s),
//! ```
//!
//! with `s = u − u₀`. Toward a centripetal ray (`q < 0`, `λ > 0`) the limit `s → −∞` is the
//! halt of slip, `E(a, −∞) = −1/a`: the tens of integration steps that resolve `σ` over
//! tens of e-folds are replaced by one evaluation of the series, and the direction at the
//! halt is the ray's angle `φ*` itself.

use super::field::Field;
use crate::math::Vec2;

/// Number of series terms (`ξ⁰ … ξ^(TERMS−1)`).
pub(super) const TERMS: usize = 20;

/// `E(a, s) = (e^{a s} − 1)/a` (`s` at `a = 0`), without cancellation.
#[inline]
pub(super) fn expm1_ratio(a: f64, s: f64) -> f64 {
    if a == 0.0 {
        s
    } else {
        (a * s).exp_m1() / a
    }
}

/// `Σ_{j=1}^{n−1} a_j b_{n−j}` (the coefficient of `ξⁿ` in a product of series, less the
/// two terms that involve `a₀` or `b₀`) for `K` series `b` at once, kept interleaved and in
/// reverse order (`rev[TERMS − 1 − m] = (b¹_m, …, b^K_m)`), so that the sums run forward
/// through both.
#[inline]
fn inner_many<const K: usize>(a: &[f64; TERMS], rev: &[[f64; K]; TERMS], n: usize) -> [f64; K] {
    let mut acc = [0.0; K];
    if !(2..=TERMS).contains(&n) {
        return acc;
    }
    let (a, rev) = (&a[1..n], &rev[TERMS - n..TERMS - 1]);
    for j in 0..a.len() {
        let x = a[j];
        let y = rev[j];
        for k in 0..K {
            acc[k] += x * y[k];
        }
    }
    acc
}

/// The closed-form slip about one invariant ray (see the module documentation).
#[derive(Debug, Clone)]
pub(super) struct RaySeries {
    /// The ray's angle `φ*`.
    pub phi: f64,
    /// `(cos φ*, sin φ*)`.
    pub dir: Vec2,
    /// `λ = F'(φ*)`: the rate at which the direction approaches the ray per unit of `ln σ`.
    pub lambda: f64,
    mu: f64,
    b: [f64; TERMS],
    r: [f64; TERMS],
    rc: [f64; TERMS],
    rs: [f64; TERMS],
    kappa: [f64; TERMS],
    kr: [f64; TERMS],
    /// `1/(1 + kλ)` and `1/(2 + kλ)`.
    inv1: [f64; TERMS],
    inv2: [f64; TERMS],
}

/// Increments along the series from its start (`s = 0`) to `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Increment {
    /// `Δp_n`.
    pub dp: f64,
    /// `Δp_t`.
    pub dpt: Vec2,
    /// `Δv_n`.
    pub dvn: f64,
    /// Normal work `ΔW_n`.
    pub dwn: f64,
    /// Friction work `ΔW_t`.
    pub dwt: f64,
}

impl RaySeries {
    /// The series about the ray `phi` of the field (`wnn`, `wtn` for the normal
    /// quantities). `None` if `q(φ*) = 0` or `λ` is not finite and nonzero.
    pub(super) fn new(field: &Field, wnn: f64, phi: f64) -> Option<RaySeries> {
        // Along the solution put C = cos(φ* + h), S = sin(φ* + h) and their double angles
        // C₂, S₂: C' = −S h', S' = C h', C₂' = −2 S₂ h', S₂' = 2 C₂ h', so the coefficient
        // of ξⁿ of each follows from those of lower order and b_n enters linearly
        // (C_n = known − b_n S₀, …). Then f∘ and q∘ are linear in them, F∘ = f∘/q∘, and
        // λ n b_n = [F∘]_n = known + λ b_n gives b_n. Everything is O(TERMS²).
        let (s0, c0) = phi.sin_cos();
        let (s20, c20) = (2.0 * s0 * c0, c0 * c0 - s0 * s0);
        let (fa, fb, fc, fd) = (field.a, field.b, field.c, field.d);
        let mu = field.mu;
        let f_of = |c: f64, s: f64, c2: f64, s2: f64| fa * c + fb * s + fc * c2 + fd * s2;
        let q_of = |c: f64, s: f64, c2: f64, s2: f64| {
            field.w1 * c + field.w2 * s - mu * (field.p * c2 + field.q * s2)
        };
        let q0 = q_of(c0, s0, c20, s20) - mu * field.m;
        if q0 == 0.0 || !q0.is_finite() {
            return None;
        }
        let (df0, dq0) = (
            f_of(-s0, c0, -2.0 * s20, 2.0 * c20),
            q_of(-s0, c0, -2.0 * s20, 2.0 * c20),
        );
        let lambda = df0 / q0;
        if lambda == 0.0 || !lambda.is_finite() {
            return None;
        }
        let mut b = [0.0; TERMS];
        // n b_n, for the derivative recurrences.
        let mut nb = [0.0; TERMS];
        // (C, S, C₂, S₂) in reverse order.
        let mut trig = [[0.0; 4]; TERMS];
        // q∘; and F∘ with the quotients (1, C, S)/q∘, which are all sums against q∘, in one
        // reverse-order array of four lanes.
        let inv_q0 = 1.0 / q0;
        let mut q = [0.0; TERMS];
        let mut fq = [[0.0; 4]; TERMS];
        let (mut r, mut rc, mut rs) = ([0.0; TERMS], [0.0; TERMS], [0.0; TERMS]);
        // The quotients' coefficient n from the sum `acc` of its middle terms:
        // (num_n − q_n quot_0 − acc)/q_0 (`first` = quot_0, zero for n = 0 itself).
        let quotient = |qn: f64, first: [f64; 3], num: [f64; 3], acc: [f64; 3]| -> [f64; 3] {
            std::array::from_fn(|k| (num[k] - qn * first[k] - acc[k]) * inv_q0)
        };
        trig[TERMS - 1] = [c0, s0, c20, s20];
        q[0] = q0;
        let first = quotient(q0, [0.0; 3], [1.0, c0, s0], [0.0; 3]);
        // φ* is a root of f: F∘₀ = 0 (its value there is round-off).
        fq[TERMS - 1] = [0.0, first[0], first[1], first[2]];
        (r[0], rc[0], rs[0]) = (first[0], first[1], first[2]);
        b[1] = 1.0;
        nb[1] = 1.0;
        trig[TERMS - 2] = [-s0, c0, -2.0 * s20, 2.0 * c20];
        q[1] = dq0;
        let v = quotient(dq0, first, [0.0, -s0, c0], [0.0; 3]);
        fq[TERMS - 2] = [lambda, v[0], v[1], v[2]];
        (r[1], rc[1], rs[1]) = (v[0], v[1], v[2]);
        for n in 2..TERMS {
            let inv_n = 1.0 / n as f64;
            let [ic, is, ic2, is2] = inner_many(&nb, &trig, n);
            // C' = −S h', S' = C h', C₂' = −2 S₂ h', S₂' = 2 C₂ h'.
            let (ck, sk, c2k, s2k) = (
                -is * inv_n,
                ic * inv_n,
                -2.0 * is2 * inv_n,
                2.0 * ic2 * inv_n,
            );
            let fk = f_of(ck, sk, c2k, s2k);
            let qk = q_of(ck, sk, c2k, s2k);
            let [qf, a1, a2, a3] = inner_many(&q, &fq, n);
            let big_fk = (fk - qf) * inv_q0;
            let bn = big_fk / (lambda * (n - 1) as f64);
            b[n] = bn;
            nb[n] = n as f64 * bn;
            let (cn, sn) = (ck - bn * s0, sk + bn * c0);
            trig[TERMS - 1 - n] = [cn, sn, c2k - 2.0 * bn * s20, s2k + 2.0 * bn * c20];
            q[n] = qk + bn * dq0;
            let v = quotient(q[n], first, [0.0, cn, sn], [a1, a2, a3]);
            fq[TERMS - 1 - n] = [big_fk + lambda * bn, v[0], v[1], v[2]];
            (r[n], rc[n], rs[n]) = (v[0], v[1], v[2]);
        }
        let mut kappa = [0.0; TERMS];
        let (mut inv1, mut inv2) = ([0.0; TERMS], [0.0; TERMS]);
        let mut ka = [0.0; TERMS];
        for k in 0..TERMS {
            kappa[k] = wnn * r[k] - mu * (field.w1 * rc[k] + field.w2 * rs[k]);
            let kl = k as f64 * lambda;
            inv1[k] = 1.0 / (1.0 + kl);
            inv2[k] = 1.0 / (2.0 + kl);
            ka[k] = kappa[k] * inv1[k];
        }
        // κ/(1 + jλ) ∗ r, row by row (contiguous multiply-adds that vectorise).
        let mut kr = [0.0; TERMS];
        for (j, &kj) in ka.iter().enumerate() {
            for (o, &rm) in kr[j..].iter_mut().zip(&r) {
                *o += kj * rm;
            }
        }
        // Every coefficient finite (a NaN or an infinity anywhere makes the sum one).
        let total: f64 = (0..TERMS)
            .map(|k| b[k] + r[k] + rc[k] + rs[k] + kr[k])
            .sum();
        if !total.is_finite() {
            return None;
        }
        Some(RaySeries {
            phi,
            dir: Vec2::new(c0, s0),
            lambda,
            mu,
            b,
            r,
            rc,
            rs,
            kappa,
            kr,
            inv1,
            inv2,
        })
    }

    /// Whether the ray is centripetal (`q(φ*) < 0`) and attracts the direction as the slip
    /// shrinks (`λ > 0`): the series then runs to the halt.
    pub(super) fn attracts_to_halt(&self) -> bool {
        self.r[0] < 0.0 && self.lambda > 0.0
    }

    /// `|1/q(φ*)|`: the impulse per unit of slip along the ray.
    pub(super) fn impulse_per_slip(&self) -> f64 {
        self.r[0].abs()
    }

    /// The offset `η` of the direction `s` (unit vector) from the ray.
    #[inline]
    pub(super) fn offset(&self, s: Vec2) -> f64 {
        (self.dir.x * s.y - self.dir.y * s.x).atan2(self.dir.dot(&s))
    }

    /// `η = h(ξ)`.
    pub(super) fn angle_offset(&self, xi: f64) -> f64 {
        self.b.iter().rev().fold(0.0, |acc, &c| acc * xi + c)
    }

    /// `ξ = h⁻¹(η)` by Newton's method, or `None` if it does not converge.
    pub(super) fn normal_coordinate(&self, eta: f64) -> Option<f64> {
        let mut xi = eta;
        for _ in 0..12 {
            let (mut h, mut dh) = (0.0, 0.0);
            for &c in self.b.iter().rev() {
                dh = dh * xi + h;
                h = h * xi + c;
            }
            if dh == 0.0 || !dh.is_finite() {
                return None;
            }
            let step = (h - eta) / dh;
            xi -= step;
            if step.abs() <= 8.0 * f64::EPSILON * xi.abs() || xi == 0.0 {
                return Some(xi);
            }
        }
        None
    }

    /// The size of the last two terms of the series at `ξ`, relative to the first (an
    /// estimate of the truncation error), or `∞` if the terms are not decreasing.
    pub(super) fn truncation(&self, xi: f64) -> f64 {
        let x = xi.abs();
        let size = |k: usize| {
            let r0 = self.r[0].abs();
            (self.b[k].abs()
                + (self.r[k].abs() + self.rc[k].abs() + self.rs[k].abs()) / r0
                + self.kr[k].abs() / self.kr[0].abs().max(r0 * r0 * 1e-300))
                * x.powi(k as i32)
        };
        let (a, b, c) = (size(TERMS - 3), size(TERMS - 2), size(TERMS - 1));
        if !(c <= b && b <= a) && c + b > 0.0 {
            return f64::INFINITY;
        }
        b + c
    }

    /// The increments from `s = 0` (slip `σ₀`, normal coordinate `ξ₀`, normal velocity
    /// `vn0`) to `s` (`s = −∞` for the halt toward a centripetal ray).
    pub(super) fn increment(&self, sigma0: f64, xi0: f64, vn0: f64, s: f64) -> Increment {
        // E(1 + kλ, s) and E(2 + kλ, s) from z_k = e^{(1+kλ)s} − 1 by
        // z_{k+1} = z_k + (e^{λs} − 1)(1 + z_k) and e^{(2+kλ)s} − 1 = z_k + (e^s − 1)(1 + z_k):
        // two exponentials in all, and no cancellation while λ > 0 (every term of one sign).
        // Otherwise each factor has its own exponential.
        let halt = s == f64::NEG_INFINITY;
        let recur = self.lambda > 0.0 && !halt;
        let (m1, ml) = if recur {
            (s.exp_m1(), (self.lambda * s).exp_m1())
        } else {
            (0.0, 0.0)
        };
        let mut z = m1;
        let (mut sp, mut sc, mut ss, mut sk, mut skr, mut sr2, mut ka) =
            (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        let mut x = 1.0;
        for k in 0..TERMS {
            let (e1, e2) = if halt {
                (-self.inv1[k], -self.inv2[k])
            } else if recur {
                let z2 = z + m1 * (1.0 + z);
                let e = (z * self.inv1[k], z2 * self.inv2[k]);
                z += ml * (1.0 + z);
                e
            } else {
                let kl = k as f64 * self.lambda;
                (expm1_ratio(1.0 + kl, s), expm1_ratio(2.0 + kl, s))
            };
            let (e1, e2) = (e1 * x, e2 * x);
            sp += self.r[k] * e1;
            sc += self.rc[k] * e1;
            ss += self.rs[k] * e1;
            sk += self.kappa[k] * e1;
            skr += self.kr[k] * e2;
            sr2 += self.r[k] * e2;
            ka += self.kappa[k] * x * self.inv1[k];
            x *= xi0;
        }
        let dp = sigma0 * sp;
        Increment {
            dp,
            dpt: Vec2::new(sc, ss) * (-self.mu * sigma0),
            dvn: sigma0 * sk,
            dwn: vn0 * dp + sigma0 * sigma0 * (skr - sp * ka),
            dwt: -self.mu * sigma0 * sigma0 * sr2,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Mat2;

    /// The u-system (φ, p, p_t, v_n, W_n, W_t) by classical RK4 with tiny steps, as an
    /// independent check of the series.
    fn reference(
        wtt: &Mat2,
        wtn: Vec2,
        wnn: f64,
        mu: f64,
        phi0: f64,
        sigma0: f64,
        s_end: f64,
    ) -> [f64; 7] {
        let rhs = |u: f64, y: &[f64; 7]| -> [f64; 7] {
            let s = Vec2::new(y[0].cos(), y[0].sin());
            let g = wtn - mu * (wtt * s);
            let q = s.dot(&g);
            let f = s.x * g.y - s.y * g.x;
            let sigma = sigma0 * u.exp();
            let dp = sigma / q;
            [
                f / q,
                dp,
                -mu * s.x * dp,
                -mu * s.y * dp,
                (wnn - mu * wtn.dot(&s)) * dp,
                y[4] * dp,
                -mu * sigma * dp,
            ]
        };
        let n = 200_000;
        let h = s_end / n as f64;
        let mut y = [phi0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0];
        let add = |y: &[f64; 7], k: &[f64; 7], c: f64| {
            let mut o = *y;
            for i in 0..7 {
                o[i] += c * k[i];
            }
            o
        };
        for i in 0..n {
            let u = i as f64 * h;
            let k1 = rhs(u, &y);
            let k2 = rhs(u + 0.5 * h, &add(&y, &k1, 0.5 * h));
            let k3 = rhs(u + 0.5 * h, &add(&y, &k2, 0.5 * h));
            let k4 = rhs(u + h, &add(&y, &k3, h));
            for j in 0..7 {
                y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
            }
        }
        y
    }

    /// The example field (`W_tt`, `w_tn`, `w_nn`, `μ`) and its series about the centripetal
    /// ray ahead of 1.8 rad.
    fn example() -> (Mat2, Vec2, f64, f64, RaySeries) {
        let wtt = Mat2::new(2.0, 0.6, 0.6, 1.0);
        let wtn = Vec2::new(0.3, -0.2);
        let (wnn, mu) = (1.5, 0.8);
        let field = Field::new(&wtt, wtn, mu);
        let phi = field.ray_ahead(1.8).expect("a ray ahead of 1.8");
        let ser = RaySeries::new(&field, wnn, phi).expect("series");
        (wtt, wtn, wnn, mu, ser)
    }

    #[test]
    fn series_agrees_with_a_fine_integration() {
        let (wtt, wtn, wnn, mu, ser) = example();
        let phi = ser.phi;
        assert!(ser.attracts_to_halt(), "λ = {}", ser.lambda);
        for eta in [0.02, -0.05, 0.1] {
            let xi = ser.normal_coordinate(eta).expect("inverse");
            assert!((ser.angle_offset(xi) - eta).abs() < 1e-15);
            let sigma0 = 0.1;
            for s in [-2.0, -30.0] {
                let r = reference(&wtt, wtn, wnn, mu, phi + eta, sigma0, s);
                let inc = ser.increment(sigma0, xi, 0.3, s);
                let eta_s = ser.angle_offset(xi * (ser.lambda * s).exp());
                let got = [
                    phi + eta_s,
                    inc.dp,
                    inc.dpt.x,
                    inc.dpt.y,
                    0.3 + inc.dvn,
                    inc.dwn,
                    inc.dwt,
                ];
                for j in 0..7 {
                    assert!(
                        (got[j] - r[j]).abs() <= 1e-11 * (1.0 + r[j].abs()),
                        "η {eta} s {s} component {j}: series {} reference {} (trunc {})",
                        got[j],
                        r[j],
                        ser.truncation(xi)
                    );
                }
            }
        }
    }

    /// The increments by the exponential recurrences agree with the factor-by-factor
    /// `E(a, s) = (e^{as} − 1)/a` to round-off for every `s ≤ 0`, and tend to the halt.
    #[test]
    fn increments_by_recurrence_match_direct_exponentials() {
        let (_, _, _, mu, ser) = example();
        assert!(ser.lambda > 0.0);
        let xi = 0.05;
        for s in [-1e-9, -1e-4, -0.3, -2.0, -15.0, -80.0] {
            let inc = ser.increment(0.2, xi, 0.1, s);
            // Factor by factor.
            let (mut sp, mut sc, mut ss, mut sk, mut skr, mut sr2, mut ka) =
                (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            let mut x = 1.0;
            for k in 0..TERMS {
                let kl = k as f64 * ser.lambda;
                let (e1, e2) = (expm1_ratio(1.0 + kl, s) * x, expm1_ratio(2.0 + kl, s) * x);
                sp += ser.r[k] * e1;
                sc += ser.rc[k] * e1;
                ss += ser.rs[k] * e1;
                sk += ser.kappa[k] * e1;
                skr += ser.kr[k] * e2;
                sr2 += ser.r[k] * e2;
                ka += ser.kappa[k] * x / (1.0 + kl);
                x *= xi;
            }
            let dp = 0.2 * sp;
            let direct = [
                dp,
                -mu * 0.2 * sc,
                -mu * 0.2 * ss,
                0.2 * sk,
                0.1 * dp + 0.04 * (skr - sp * ka),
                -mu * 0.04 * sr2,
            ];
            let got = [inc.dp, inc.dpt.x, inc.dpt.y, inc.dvn, inc.dwn, inc.dwt];
            for (a, b) in got.iter().zip(&direct) {
                assert!(
                    (a - b).abs() <= 1e-14 * b.abs().max(1e-300) + 1e-300,
                    "s {s}: {a} vs {b}"
                );
            }
        }
        let halt = ser.increment(0.2, xi, 0.1, f64::NEG_INFINITY);
        let far = ser.increment(0.2, xi, 0.1, -800.0);
        assert!((halt.dp - far.dp).abs() <= 1e-15 * halt.dp.abs());
        assert!((halt.dwn - far.dwn).abs() <= 1e-14 * halt.dwn.abs());
    }
}
