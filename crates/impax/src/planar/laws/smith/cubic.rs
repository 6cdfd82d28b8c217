//! The real roots of a cubic in an interval, each to the last bit: the equation of η in a
//! reversal is a cubic (paper A eq. 27 for the sphere).

use crate::math::quadratic_roots;
use crate::numerics::roots::newton_wide_bracket;

/// Evaluate `p[0] + p[1] x + p[2] x² + p[3] x³`.
#[cfg(test)]
fn horner(p: &[f64; 4], x: f64) -> f64 {
    ((p[3] * x + p[2]) * x + p[1]) * x + p[0]
}

/// The factor `1/max(1, x²)` by which the cubic is evaluated (its sign is the cubic's, and
/// its size stays representable for `|x|` up to the largest friction coefficients).
#[cfg(test)]
fn damping(x: f64) -> f64 {
    let r = 1.0 / x.abs().max(1.0);
    r * r
}

/// Real roots of the cubic with monomial coefficients `p` in `[lo, hi]`, each to the last
/// bit (ascending, deduplicated). `f` evaluates the same cubic times `1/max(1, x²)`,
/// possibly in a better conditioned (factored) form: the monomials only place the critical
/// points that split `[lo, hi]` into monotone pieces and guide Newton; every sign test uses
/// `f`.
pub(super) fn cubic_roots_in(
    p: &[f64; 4],
    f: impl Fn(f64) -> f64,
    lo: f64,
    hi: f64,
    floor: f64,
) -> ([f64; 3], usize) {
    let mut out = [0.0; 3];
    let mut n = 0;
    if p.iter().all(|&c| c == 0.0) {
        return (out, 0);
    }
    let mut cuts = [lo, hi, hi, hi];
    let mut ncuts = 1;
    let [r1, r2] = quadratic_roots(3.0 * p[3], 2.0 * p[2], p[1]);
    for r in [r1, r2] {
        if r > lo && r < hi {
            cuts[ncuts] = r;
            ncuts += 1;
        }
    }
    cuts[ncuts] = hi;
    ncuts += 1;
    cuts[..ncuts].sort_by(|x, y| x.total_cmp(y));
    let push = |x: f64, out: &mut [f64; 3], n: &mut usize| {
        if *n < 3 && (*n == 0 || out[*n - 1] != x) {
            out[*n] = x;
            *n += 1;
        }
    };
    for w in cuts[..ncuts].windows(2) {
        let (x0, x1) = (w[0], w[1]);
        let (f0, f1) = (f(x0), f(x1));
        if f0 == 0.0 {
            push(x0, &mut out, &mut n);
            continue;
        }
        if f1 == 0.0 || f0.signum() == f1.signum() {
            continue;
        }
        // The derivative damped like `f` (the damping's own derivative multiplies `f` ≈ 0
        // near the root): x r and r are at most 1, so nothing overflows.
        let df = |x: f64| {
            let r = 1.0 / x.abs().max(1.0);
            let xr = x * r;
            (3.0 * p[3] * xr + 2.0 * p[2] * r) * xr + p[1] * r * r
        };
        let root = newton_wide_bracket(&f, df, x0, x1, f0, floor);
        push(root, &mut out, &mut n);
    }
    if f(hi) == 0.0 {
        push(hi, &mut out, &mut n);
    }
    (out, n)
}

/// Product of two polynomials of degree ≤ 1 → degree ≤ 2 (coefficients ascending).
#[inline]
pub(super) fn mul1(a: [f64; 2], b: [f64; 2]) -> [f64; 3] {
    [a[0] * b[0], a[0] * b[1] + a[1] * b[0], a[1] * b[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_roots_found_to_the_last_bit() {
        // (x − 0.5)(x + 0.25)(x − 0.9) = x³ − 1.15x² + 0.1x + 0.1125
        let p = [0.1125, 0.1, -1.15, 1.0];
        let (r, n) = cubic_roots_in(&p, |x| horner(&p, x) * damping(x), -1.0, 1.0, 1e-9);
        assert_eq!(n, 3);
        for (x, y) in r.iter().zip([-0.25, 0.5, 0.9]) {
            assert!((x - y).abs() < 1e-15, "{x} vs {y}");
        }
    }
}
