//! The map of the sector between two invariant rays onto the real line (theory §2,
//! "Spatial"): with `θ` the angle turned in the sense of `f`, `δ_b`, `δ_a` the distances to the
//! rays behind and ahead and `D = δ_a + δ_b`, `x = ln(sin(δ_b/2)/sin(δ_a/2))`.
//!
//! The map is rational in `e^x`: the half-angle vector `h = e_b' + e^x e_a'` (`e'` the unit
//! vectors at half the rays' angles) points at `θ/2`, so `ŝ = (h_x² − h_y², 2 h_x h_y)/|h|²`
//! and `dθ/dx = 2 e^x sin(D/2)/|h|²` (`e^{−x}` and `h e^{−x}` for `x > 0`): no sine or
//! cosine, and nine exponentials for a panel's seventeen nodes (they are symmetric about its
//! middle; [`node_exponentials`]).
//!
//! Near a ray `r`, `f` is evaluated from its expansion about the ray with `f(r) = 0` imposed
//! (a change of the data by the round-off of the root, ~1e-16):
//!
//! ```text
//! f(r + ε) = sin ε [Q + 2 S cos ε − R sin ε (2 cos ε + 1)/(1 + cos ε)],
//! Q = B cos r − A sin r,  R = C cos 2r + D sin 2r,  S = D cos 2r − C sin 2r,
//! ```
//!
//! so `ρ` keeps full relative accuracy however close the direction gets to the ray.

// Tests of the form `!(x > 0.0)` are meant: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::super::field::Field;
use crate::math::Vec2;
use crate::numerics::chebyshev::{M, N};

/// One invariant ray with the coefficients of `f`'s expansion about it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ray {
    /// The ray's angle `r`.
    pub phi: f64,
    /// `(cos r, sin r)`.
    pub dir: Vec2,
    /// `Q`, `R` and `S` of the expansion.
    q: f64,
    r: f64,
    s: f64,
}

impl Ray {
    /// The ray `phi` (a root of `f`) of `field`.
    pub(super) fn new(field: &Field, phi: f64) -> Ray {
        let (a, b, c, d) = field.f_coefficients();
        let (sr, cr) = phi.sin_cos();
        let (s2, c2) = (2.0 * sr * cr, cr * cr - sr * sr);
        Ray {
            phi,
            dir: Vec2::new(cr, sr),
            q: b * cr - a * sr,
            r: c * c2 + d * s2,
            s: d * c2 - c * s2,
        }
    }
}

/// The sector between the ray behind and the ray ahead, and its map onto the real line.
pub(super) struct Fan {
    /// The sign of `f` in the sector (the sense in which the direction turns).
    pub sgn: f64,
    /// `cos(D/2)`, `sin(D/2)`.
    pub cd: f64,
    pub sd: f64,
    /// The ray the direction turns toward.
    pub ahead: Ray,
    /// The ray it turns away from.
    pub behind: Ray,
}

/// The integrand data at one value of `x`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Node {
    /// The direction `ŝ`.
    pub s: Vec2,
    /// `q = ŝ·g`.
    pub q: f64,
    /// `ρ = (dθ/dx)/|f|`.
    pub rho: f64,
}

/// [`half_vectors_with`] with its own exponential.
#[cfg(test)]
fn half_vectors(cd: f64, sd: f64, x: f64) -> (f64, f64, f64, f64, f64) {
    half_vectors_with(cd, sd, x, (-x.abs()).exp())
}

/// The half-angle vector `h = (h_x, h_y)` of the map at `x` given `t = e^{−|x|}`, with the
/// sine and cosine of `δ_a/2` times `|h|` and `t`: `(cos(δ_b/2), sin(δ_b/2)) = h/|h|`.
#[inline]
fn half_vectors_with(cd: f64, sd: f64, x: f64, t: f64) -> (f64, f64, f64, f64, f64) {
    if x <= 0.0 {
        (1.0 + t * cd, t * sd, sd, cd + t, t)
    } else {
        (t + cd, sd, t * sd, 1.0 + t * cd, t)
    }
}

/// `e^{s x_j}` at the panel's nodes `x_j = x_c + L t_j` (`x_c` its middle, `L` half its
/// width, `s` the sign that makes `e^{s x_c} = e^{−|x_c|}`) from nine exponentials instead
/// of seventeen: the nodes are symmetric about the middle (`t_{N−j} = −t_j`), so with
/// `a_j = e^{L t_j}` (`j < N/2`), `e^{s x_j} = e^{−|x_c|} a_j^{±1}`. That is `e^{−|x_j|}` where
/// `x_j` is on the side of `x_c`, its reciprocal where it is not ([`e_abs`]). (Entry 0 is
/// not filled: the first node is the last panel's end.)
pub(super) fn node_exponentials(xc: f64, l: f64, t: &[f64; M]) -> [f64; M] {
    let ec = (-xc.abs()).exp();
    let mut out = [0.0; M];
    for j in 0..N / 2 {
        let a = (l * t[j]).exp();
        (out[j], out[N - j]) = if xc <= 0.0 {
            (ec * a, ec / a)
        } else {
            (ec / a, ec * a)
        };
    }
    out[N / 2] = ec;
    out
}

/// `e^{−|x|}` from `p = e^{s x}` of [`node_exponentials`] (`x_c` the panel's middle).
#[inline]
pub(super) fn e_abs(x: f64, xc: f64, p: f64) -> f64 {
    if (x <= 0.0) == (xc <= 0.0) {
        p
    } else {
        1.0 / p
    }
}

impl Fan {
    /// `δ_a` at `x`.
    #[cfg(test)]
    fn delta_ahead(&self, x: f64) -> f64 {
        let (_, _, sa, ca, _) = half_vectors(self.cd, self.sd, x);
        2.0 * sa.atan2(ca)
    }

    /// Whether `δ_a ≤ δ` at `x` (given `e = e^{−|x|}`), from `t = tan(δ/2)`: the half-angle
    /// vector of `δ_a/2` is in the first quadrant with `sin ≤ t cos` (no arctangent).
    #[inline]
    pub(super) fn ahead_within(&self, x: f64, e: f64, t: f64) -> bool {
        let (_, _, sa, ca, _) = half_vectors_with(self.cd, self.sd, x, e);
        ca > 0.0 && sa <= t * ca
    }

    /// The direction, `q` and `ρ` at `x`; `None` where `f` does not have the sign of the
    /// sector (round-off at the very ends).
    #[inline]
    pub(super) fn node(&self, field: &Field, x: f64) -> Option<Node> {
        self.node_with(field, x, (-x.abs()).exp())
    }

    /// [`Fan::node`] given `e^{−|x|}`.
    #[inline]
    pub(super) fn node_with(&self, field: &Field, x: f64, e: f64) -> Option<Node> {
        let (hx, hy, sa, ca, t) = half_vectors_with(self.cd, self.sd, x, e);
        let inv = 1.0 / (hx * hx + hy * hy);
        // The offset ε from the nearer ray, by its sine and cosine (double half-angles).
        let (se, ce, ray) = if x <= 0.0 {
            (
                self.sgn * 2.0 * hx * hy * inv,
                1.0 - 2.0 * hy * hy * inv,
                &self.behind,
            )
        } else {
            (
                -self.sgn * 2.0 * sa * ca * inv,
                1.0 - 2.0 * sa * sa * inv,
                &self.ahead,
            )
        };
        let s = Vec2::new(
            ray.dir.x * ce - ray.dir.y * se,
            ray.dir.y * ce + ray.dir.x * se,
        );
        // |ε| ≤ 1: the expansion about the ray.
        let f = if ce >= 0.5403 {
            se * (ray.q + 2.0 * ray.s * ce - ray.r * se * (2.0 * ce + 1.0) / (1.0 + ce))
        } else {
            field.f_at(s.x, s.y)
        };
        let fa = self.sgn * f;
        if !(fa > 0.0) {
            return None;
        }
        Some(Node {
            s,
            q: field.q_at(s.x, s.y),
            // dθ/dx = 2 e^{−|x|} sin(D/2)/|h|².
            rho: 2.0 * t * self.sd * inv / fa,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::field::{tests::random_field, Sector};
    use super::*;
    use crate::math::SplitMix64;
    use crate::numerics::chebyshev::lobatto;
    use crate::spatial::invariant_rays;

    /// `f` from its expansion about a ray equals `f` evaluated directly, to round-off of the
    /// size of `f`'s coefficients, across the whole range it is used on (`|ε| ≤ 1`).
    #[test]
    fn the_expansion_about_a_ray_is_f() {
        let mut g = SplitMix64(0x2545_f491_4f6c_dd1d);
        for _ in 0..500 {
            let (p, field) = random_field(&mut g);
            let (a, b, c, d) = field.f_coefficients();
            let scale = a.abs() + b.abs() + c.abs() + d.abs();
            for r in invariant_rays(&p).as_slice().iter().map(|x| x.angle) {
                let ray = Ray::new(&field, r);
                for k in 0..40 {
                    let eps = g.range(-1.0, 1.0) * 10f64.powi(-(k % 8));
                    let (se, ce) = eps.sin_cos();
                    let expanded = se
                        * (ray.q + 2.0 * ray.s * ce - ray.r * se * (2.0 * ce + 1.0) / (1.0 + ce));
                    let (s, co) = (r + eps).sin_cos();
                    let direct = field.f_at(co, s);
                    assert!(
                        (expanded - direct).abs() <= 1e-14 * scale,
                        "ε {eps}: {expanded} vs {direct}"
                    );
                }
            }
        }
    }

    /// The nodes' exponentials from the symmetric products are `e^{−|x_j|}` to a few ulp, on
    /// panels left of, right of and across `x = 0`.
    #[test]
    fn node_exponentials_are_the_exponentials_of_the_nodes() {
        let lb = lobatto();
        for &(x, h) in &[
            (-7.3, 1.1),
            (-0.4, 0.9),
            (-0.6, 0.6),
            (0.0, 1.2),
            (2.5, 4.0),
            (-3.0, 5.5),
        ] {
            let half = 0.5 * h;
            let xc = x + half;
            let ex = node_exponentials(xc, half, &lb.t);
            for (j, (&tj, &p)) in lb.t.iter().zip(&ex).enumerate().skip(1) {
                let xj = x + half * (1.0 + tj);
                let got = e_abs(xj, xc, p);
                let want = (-xj.abs()).exp();
                assert!(
                    (got - want).abs() <= 4.0 * f64::EPSILON * want,
                    "x {x} h {h} node {j}: {got} vs {want}"
                );
            }
        }
    }

    /// The half-angle map against the angle it stands for: `ŝ(x)` is the direction at
    /// `θ_b + sgn·2 atan2(e^x sin(D/2), 1 + e^x cos(D/2))`, `δ_a` is `D` less the angle
    /// turned, and `ρ |f| = dθ/dx` agrees with a central difference of that angle.
    #[test]
    fn the_half_angle_map_is_the_angle_it_stands_for() {
        let mut g = SplitMix64(0x6a09_e667_f3bc_c909);
        let mut checked = 0;
        for _ in 0..300 {
            let (_, field) = random_field(&mut g);
            let phi0 = g.range(-3.0, 3.0);
            let (s0, c0) = phi0.sin_cos();
            let f0 = field.f_at(c0, s0);
            let (a, b, c, d) = field.f_coefficients();
            if f0.abs() < 1e-3 * (a.abs() + b.abs() + c.abs() + d.abs()) {
                continue;
            }
            let Some(sector) = Sector::find(&field, phi0) else {
                continue;
            };
            let sgn = f0.signum();
            let (ra, rb) = if sgn > 0.0 {
                (sector.above, sector.below)
            } else {
                (sector.below, sector.above)
            };
            let big_d = sector.above - sector.below;
            if big_d > 6.0 {
                continue;
            }
            let (sd, cd) = (0.5 * big_d).sin_cos();
            let fan = Fan {
                sgn,
                cd,
                sd,
                ahead: Ray::new(&field, ra),
                behind: Ray::new(&field, rb),
            };
            let turned = |x: f64| 2.0 * (x.exp() * sd).atan2(1.0 + x.exp() * cd);
            for x in [-30.0, -4.0, -0.7, 0.0, 0.3, 2.5, 9.0] {
                let Some(n) = fan.node(&field, x) else {
                    continue;
                };
                let theta = rb + sgn * turned(x);
                assert!((n.s.x - theta.cos()).abs() < 1e-14 && (n.s.y - theta.sin()).abs() < 1e-14);
                assert!((n.s.norm() - 1.0).abs() < 1e-15);
                let da = fan.delta_ahead(x);
                assert!((da - (big_d - turned(x))).abs() < 1e-13 * big_d.max(1.0) + 1e-15);
                if x.abs() < 5.0 {
                    let e = 1e-5;
                    let rate = (turned(x + e) - turned(x - e)) / (2.0 * e);
                    let f = field.f_at(n.s.x, n.s.y).abs();
                    assert!(((n.rho * f) - rate).abs() < 1e-8 * rate, "x {x}");
                }
                checked += 1;
            }
        }
        assert!(checked > 1000, "{checked} checked");
    }
}
