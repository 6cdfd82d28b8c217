//! The direction field of the slip and its invariant rays (theory §2, "Spatial").
//!
//! During slip the direction `φ` of `v_t` turns at `dφ/dp_n = f(φ)/σ` and the speed changes
//! at `dσ/dp_n = q(φ)`, with `g = w_tn − μ W_tt ŝ`,
//!
//! ```text
//! f(φ) = ŝ × g = A cos φ + B sin φ + C cos 2φ + D sin 2φ,
//! q(φ) = ŝ · g = w₁ cos φ + w₂ sin φ − μ (M + P cos 2φ + Q sin 2φ)
//! ```
//!
//! ([`Field`]). The invariant rays are the roots of `f` (at least two where `f ≢ 0`: it has
//! zero mean over the circle); the direction turns monotonically from the ray behind it
//! toward the one ahead ([`Sector`]), and a shrinking slip (`q < 0`) turns toward the sign
//! of `f` ([`Field::ray_ahead`]).

// Tests of the form `!(x > 0.0)` are meant: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::math::{Mat2, Vec2};
use crate::numerics::roots::newton_in_bracket;
use std::f64::consts::TAU;

/// The direction field's trigonometric coefficients: `f(φ) = A cos φ + B sin φ + C cos 2φ +
/// D sin 2φ` (`A = w₂, B = −w₁, C = −μ W₁₂, D = −μ (W₂₂ − W₁₁)/2`), and
/// `q(φ) = w₁ cos φ + w₂ sin φ − μ (M + P cos 2φ + Q sin 2φ)` with `M = (W₁₁ + W₂₂)/2`,
/// `P = (W₁₁ − W₂₂)/2`, `Q = W₁₂`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Field {
    /// `A = w₂`.
    pub(super) a: f64,
    /// `B = −w₁`.
    pub(super) b: f64,
    /// `C = −μ W₁₂`.
    pub(super) c: f64,
    /// `D = −μ (W₂₂ − W₁₁)/2`.
    pub(super) d: f64,
    /// `w₁`.
    pub(super) w1: f64,
    /// `w₂`.
    pub(super) w2: f64,
    /// `M = (W₁₁ + W₂₂)/2`.
    pub(super) m: f64,
    /// `P = (W₁₁ − W₂₂)/2`.
    pub(super) p: f64,
    /// `Q = W₁₂`.
    pub(super) q: f64,
    /// `μ`.
    pub(super) mu: f64,
}

impl Field {
    /// The coefficients of `f` and `q` for `W_tt`, `w_tn` and `μ`.
    pub(super) fn new(wtt: &Mat2, wtn: Vec2, mu: f64) -> Field {
        Field {
            a: wtn.y,
            b: -wtn.x,
            c: -mu * wtt[(0, 1)],
            d: -0.5 * mu * (wtt[(1, 1)] - wtt[(0, 0)]),
            w1: wtn.x,
            w2: wtn.y,
            m: 0.5 * (wtt[(0, 0)] + wtt[(1, 1)]),
            p: 0.5 * (wtt[(0, 0)] - wtt[(1, 1)]),
            q: wtt[(0, 1)],
            mu,
        }
    }

    /// The coefficients `(A, B, C, D)` of `f`.
    #[inline]
    pub(super) fn f_coefficients(&self) -> (f64, f64, f64, f64) {
        (self.a, self.b, self.c, self.d)
    }

    /// `f = ŝ × g` at the direction `(c, s) = (cos φ, sin φ)`.
    #[inline]
    pub(super) fn f_at(&self, c: f64, s: f64) -> f64 {
        self.a * c + self.b * s + self.c * (c * c - s * s) + self.d * (2.0 * c * s)
    }

    /// `q = ŝ · g` at the direction `(c, s) = (cos φ, sin φ)`.
    #[inline]
    pub(super) fn q_at(&self, c: f64, s: f64) -> f64 {
        self.w1 * c + self.w2 * s
            - self.mu * (self.m + self.p * (c * c - s * s) + self.q * (2.0 * c * s))
    }

    /// `f(φ) = ŝ × g` and `f'(φ)`.
    #[inline]
    pub(super) fn f_df(&self, phi: f64) -> (f64, f64) {
        let (s, c) = phi.sin_cos();
        let (s2, c2) = (2.0 * s * c, c * c - s * s);
        (
            self.a * c + self.b * s + self.c * c2 + self.d * s2,
            -self.a * s + self.b * c - 2.0 * self.c * s2 + 2.0 * self.d * c2,
        )
    }

    /// The invariant ray that the direction reaches from `phi` as the slip shrinks (`q < 0`:
    /// `dφ/d(−ln σ) = f/|q|`, so the direction turns toward the sign of `f`): the first root of
    /// `f` ahead in that sense (scanned in steps of 0.1 rad, then Newton's method kept
    /// inside the bracket). `None` if none within 0.8 rad.
    pub(super) fn ray_ahead(&self, phi: f64) -> Option<f64> {
        let f = |x: f64| self.f_df(x).0;
        let (f0, df0) = self.f_df(phi);
        if f0 == 0.0 {
            return Some(phi);
        }
        // On a ray up to round-off (whose sign says nothing about the sense): Newton there.
        if (f0 / df0).abs() < 1e-6 {
            let mut x = phi;
            for _ in 0..3 {
                let (fx, dfx) = self.f_df(x);
                if fx == 0.0 || dfx == 0.0 {
                    break;
                }
                x -= fx / dfx;
            }
            return Some(x);
        }
        let step = 0.1f64.copysign(f0);
        let mut a = phi;
        for _ in 0..8 {
            let b = a + step;
            if (f(b) <= 0.0) != (f0 <= 0.0) {
                return Some(self.polish(a, f(a), b));
            }
            a = b;
        }
        None
    }

    /// The root of `f` in the bracket `[a, b]` (`f(a)`, `f(b)` of opposite signs).
    fn polish(&self, a: f64, fa: f64, b: f64) -> f64 {
        newton_in_bracket(|x| self.f_df(x), a, fa, b, 0.5 * (a + b))
    }
}

/// The two invariant rays around a direction `φ0` that is on none: the nearest roots of `f`
/// below and above it (`below < φ0 < above`, unwrapped), found by scans outward from `φ0`
/// that cannot miss a root (a bound on `|f''|` excludes roots between samples of `f` and
/// `f'`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Sector {
    /// The nearest ray below `φ0`.
    pub below: f64,
    /// The nearest ray above `φ0`.
    pub above: f64,
}

/// The roots found by one scan.
#[derive(Debug, Clone, Copy)]
struct Roots {
    phi: [f64; 4],
    len: usize,
    /// Subdivisions left to the scan.
    budget: u32,
}

/// Samples of the scan per turn.
const GRID: usize = 32;

/// `f` and `f'` at the direction `(c, s)` (double angles by the product formulas).
#[inline]
fn f_df_at((a, b, cc, d): (f64, f64, f64, f64), c: f64, s: f64) -> (f64, f64) {
    let (c2, s2) = (c * c - s * s, 2.0 * c * s);
    (
        a * c + b * s + cc * c2 + d * s2,
        -a * s + b * c - 2.0 * cc * s2 + 2.0 * d * c2,
    )
}

impl Sector {
    /// The sector of `phi0`, or `None` if `f ≡ 0` (every direction invariant), `f(φ0) = 0`
    /// or a near-tangency of two roots is not resolved.
    pub(super) fn find(field: &Field, phi0: f64) -> Option<Sector> {
        let (a, b, c, d) = field.f_coefficients();
        let scale = a.abs() + b.abs() + c.abs() + d.abs();
        if !(scale > 0.0) || !scale.is_finite() {
            return None;
        }
        // f scaled to unit size (no underflow in the tests below).
        let k = (a / scale, b / scale, c / scale, d / scale);
        let (a, b, c, d) = k;
        // |f''| ≤ |A| + |B| + 4 (|C| + |D|).
        let bound = a.abs() + b.abs() + 4.0 * (c.abs() + d.abs());
        let (s0, c0) = phi0.sin_cos();
        let (f0, df0) = f_df_at(k, c0, s0);
        if f0 == 0.0 {
            return None;
        }
        let start = (phi0, f0, df0);
        Some(Sector {
            below: Self::nearest(k, bound, start, (c0, s0), -1.0)?,
            above: Self::nearest(k, bound, start, (c0, s0), 1.0)?,
        })
    }

    /// The nearest root from `start` in the sense `dir`, sampling every `2π/GRID` (the
    /// samples by rotation, the subdivisions by `sin_cos`).
    fn nearest(
        k: (f64, f64, f64, f64),
        bound: f64,
        start: (f64, f64, f64),
        (mut c, mut s): (f64, f64),
        dir: f64,
    ) -> Option<f64> {
        let h = TAU / GRID as f64;
        let (sh, ch) = (dir * h).sin_cos();
        let mut roots = Roots {
            phi: [0.0; 4],
            len: 0,
            budget: 64,
        };
        let mut prev = start;
        for j in 1..=GRID {
            (c, s) = (c * ch - s * sh, s * ch + c * sh);
            let (fx, dfx) = f_df_at(k, c, s);
            let next = (start.0 + dir * j as f64 * h, fx, dfx);
            if dir > 0.0 {
                roots.scan(k, prev, next, bound, 1.0, 0);
            } else {
                roots.scan(k, next, prev, bound, 1.0, 0);
            }
            if roots.budget == 0 {
                // An unresolved near-tangency: the sector is not known for certain.
                return None;
            }
            if roots.len > 0 {
                let found = roots.phi[..roots.len].iter();
                return Some(if dir > 0.0 {
                    found.fold(f64::INFINITY, |m, &r| m.min(r))
                } else {
                    found.fold(f64::NEG_INFINITY, |m, &r| m.max(r))
                });
            }
            prev = next;
        }
        None
    }
}

impl Roots {
    fn push(&mut self, phi: f64) {
        let dup = self.phi[..self.len]
            .iter()
            .any(|&r| (r - phi).abs() < 1e-12);
        if !dup && self.len < 4 {
            self.phi[self.len] = phi;
            self.len += 1;
        }
    }

    /// Roots in `[a, b)` given `(φ, f, f')` at both ends.
    fn scan(
        &mut self,
        k: (f64, f64, f64, f64),
        (xa, fa, da): (f64, f64, f64),
        (xb, fb, db): (f64, f64, f64),
        bound: f64,
        scale: f64,
        depth: u32,
    ) {
        if fa == 0.0 {
            self.push(xa);
            return;
        }
        if fb != 0.0 && (fa < 0.0) != (fb < 0.0) {
            self.push(root_between(k, (xa, fa, da), (xb, fb, db)));
            return;
        }
        // Same sign at both ends: f stays away from zero within r_a of a and r_b of b
        // (f(a + t) ≥ |f_a| ± f'_a t − bound t²/2, oriented to the sign of f).
        let sgn = fa.signum();
        let (fa, da, fb, db) = (sgn * fa, sgn * da, sgn * fb, sgn * db);
        let width = xb - xa;
        // f ≥ min(f_a, f_b) − bound width²/8 on the interval.
        if fa.min(fb) > 0.125 * bound * width * width {
            return;
        }
        let reach = |f: f64, slope: f64| (slope + (slope * slope + 2.0 * bound * f).sqrt()) / bound;
        if reach(fa, da) + reach(fb.max(0.0), -db) >= width {
            return;
        }
        if depth >= 40 || width < 1e-12 {
            // A tangency (double root) to the resolution of the scan.
            if fa.min(fb) <= 1e-13 * scale {
                self.push(if fa <= fb { xa } else { xb });
            }
            return;
        }
        if self.budget == 0 {
            return;
        }
        self.budget -= 1;
        let xm = 0.5 * (xa + xb);
        let (sm, cm) = xm.sin_cos();
        let (fm, dm) = f_df_at(k, cm, sm);
        let mid = (xm, fm, dm);
        self.scan(k, (xa, sgn * fa, sgn * da), mid, bound, scale, depth + 1);
        self.scan(k, mid, (xb, sgn * fb, sgn * db), bound, scale, depth + 1);
    }
}

/// The root of `f` between `a` and `b` (`f` of opposite signs there): from a Newton step
/// off the end with the smaller `|f|` (or the secant point), [`newton_in_bracket`].
fn root_between(
    k: (f64, f64, f64, f64),
    (a, fa, da): (f64, f64, f64),
    (b, fb, db): (f64, f64, f64),
) -> f64 {
    // Start: Newton from the end with the smaller |f|, or the secant point.
    let mut x = if fa.abs() < fb.abs() && da != 0.0 {
        a - fa / da
    } else if db != 0.0 {
        b - fb / db
    } else {
        a - fa * (b - a) / (fb - fa)
    };
    if !(x > a.min(b) && x < a.max(b)) {
        x = a - fa * (b - a) / (fb - fa);
    }
    newton_in_bracket(
        |x| {
            let (s, c) = x.sin_cos();
            f_df_at(k, c, s)
        },
        a,
        fa,
        b,
        x,
    )
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::math::SplitMix64;
    use crate::spatial::{invariant_rays, ContactProblem};

    /// A random direction field (`W_tt` of condition up to 100, any coupling and `μ`), with
    /// its problem.
    pub(in super::super) fn random_field(g: &mut SplitMix64) -> (ContactProblem, Field) {
        let (a, c) = (g.decades(-1.0, 1.0), g.decades(-1.0, 1.0));
        let b = g.range(-0.9, 0.9) * (a * c).sqrt();
        let (w1, w2) = (g.range(-1.0, 1.0), g.range(-1.0, 1.0));
        let mu = g.decades(-1.5, 0.5);
        // w_nn above the Schur complement's bound w_tᵀ W_tt⁻¹ w_t.
        let wnn = 1.0 + (c * w1 * w1 - 2.0 * b * w1 * w2 + a * w2 * w2) / (a * c - b * b);
        let p = ContactProblem::from_upper([a, b, w1, c, w2, wnn], [0.1, 0.2, -1.0], mu, 0.5)
            .expect("SPD by construction");
        let field = Field::new(&p.wtt(), p.wtn(), mu);
        (p, field)
    }

    /// The scans find the nearest rays below and above a direction, the same as the
    /// companion matrix of the quartic in `tan(φ/2)` (`invariant_rays`, an independent
    /// method) gives, and each is a root of `f` to round-off.
    #[test]
    fn the_sector_scan_finds_the_rays_of_the_companion_matrix() {
        let mut g = SplitMix64(0x9e37_79b9_7f4a_7c15);
        let mut compared = 0;
        for _ in 0..5000 {
            let (p, field) = random_field(&mut g);
            let (a, b, c, d) = field.f_coefficients();
            let scale = a.abs() + b.abs() + c.abs() + d.abs();
            let phi0 = g.range(-10.0, 10.0);
            let (s0, c0) = phi0.sin_cos();
            if field.f_at(c0, s0).abs() < 1e-6 * scale {
                continue;
            }
            let sector = Sector::find(&field, phi0).expect("f is not identically zero");
            assert!(sector.below < phi0 && phi0 < sector.above);
            assert!(sector.above - sector.below <= TAU + 1e-12);
            for r in [sector.below, sector.above] {
                let (s, co) = r.sin_cos();
                assert!(field.f_at(co, s).abs() <= 1e-14 * scale, "f({r}) not zero");
            }
            let rays = invariant_rays(&p);
            let reference: Vec<f64> = rays.as_slice().iter().map(|x| x.angle).collect();
            // Near-tangencies (two roots closer than 1e-6) are left to the scan alone.
            let close = reference.windows(2).any(|w| (w[1] - w[0]).abs() < 1e-6);
            if close {
                continue;
            }
            // The nearest reference rays above and below φ0.
            let above = reference
                .iter()
                .map(|&r| phi0 + (r - phi0).rem_euclid(TAU))
                .fold(f64::INFINITY, f64::min);
            let below = reference
                .iter()
                .map(|&r| phi0 - (phi0 - r).rem_euclid(TAU))
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                (sector.above - above).abs() < 1e-12,
                "{sector:?} vs {above} for {p:?}"
            );
            assert!(
                (sector.below - below).abs() < 1e-12,
                "{sector:?} vs {below} for {p:?}"
            );
            compared += 1;
        }
        assert!(compared > 4500, "{compared} compared");
    }
}
