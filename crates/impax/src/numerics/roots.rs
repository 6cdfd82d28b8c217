//! Scalar root finders: every root of a function of one variable that the library locates
//! goes through one of these.
//!
//! All of them work on a bracket, an interval at whose ends the function has opposite signs,
//! and keep it (every iterate narrows it), so none can leave the root's interval. They differ
//! in what they are given (values only, or the derivative too, or a good first guess), in
//! when they stop and in which point they return: an event must be reported on the side of
//! the crossing where it has happened, a root of a polynomial as close as the arithmetic
//! allows.
//!
//! * [`bisection`] (`f`; used by `paper::liu2012`): bisection to two adjacent numbers; the
//!   end with the smaller `|f|`.
//! * [`illinois`] (`g` with `g(a) < 0 ≤ g(b)`; the spatial Darboux–Keller events): Illinois
//!   false position until the bracket is within `4ε` relative; its end where `g ≥ 0`.
//! * [`illinois_with_bisection`] (as above; the simulation's contact events): Illinois with a
//!   bisection after three steps on one side, until the bracket is within `2ε` relative;
//!   its end where `g ≥ 0`.
//! * [`newton_from_seed`] (`g` on `[0, 1]`, a seed and a slope; the Darboux–Keller events
//!   located by re-stepping): Newton until its correction is below 16 ulp, else
//!   [`illinois`] on `±1e-9` about the seed.
//! * [`newton_crossing`] (`g`, `g'` with `g(a) < 0 ≤ g(b)`; the events on the panels of the
//!   angle variable): Newton from the secant point, bisection where it leaves the bracket,
//!   until the bracket is within `4ε` absolute; its end where `g ≥ 0`.
//! * [`newton_in_bracket`] (`f`, `f'` and a start; the invariant rays of the spatial slip):
//!   Newton, bisection where it leaves the bracket, until its correction is within
//!   `2ε max(|x|, 1)`; the corrected point.
//! * [`newton_bisection`] (`f`, `f'`; `spatial::lcp`'s slip angles): Newton from the secant
//!   point for 30 steps, then bisection, until the bracket is two adjacent numbers or the
//!   iterate stalls; the iterate.
//! * [`newton_wide_bracket`] (`f`, `f'` and a floor; the roots of `smith`'s cubic): Newton,
//!   with bisection of the exponent on brackets spanning orders of magnitude, until the step
//!   or the bracket is within `2ε max(|x|, floor)`; the better of the last two points.
//!
//! The methods: bisection and false position as in Press, Teukolsky, Vetterling & Flannery,
//! *Numerical Recipes* (3rd ed., Cambridge 2007), §9.1–9.2; the Illinois modification of false
//! position, Dowell & Jarratt, *BIT* 11 (1971) 168; Newton's method kept inside a bracket,
//! ibid. §9.4 (`rtsafe`).
//!
//! The finders differ in their stopping rules and in the point they return, and one cannot
//! stand in for another without changing its callers' results: tried when they were gathered
//! here, [`newton_in_bracket`] for [`newton_bisection`] moved `lcp`'s impulses on 2,160 of
//! 4,500 random spatial problems (by up to 3.5e-8 relative, where the slip angle is
//! ill-conditioned), [`illinois`] for [`illinois_with_bisection`] moved the simulation's late
//! impacts (by up to 7.5e-9 relative), and [`illinois`] for [`bisection`] the last digit of
//! two of `paper liu2012`'s values.

// Tests of the form `!(x > 0.0)` are meant: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

/// Bisection of `f` on `[lo, hi]` (a sign change) to the last bit: the end of the final
/// bracket with the smaller `|f|` (a zero found on the way is returned at once; NaN if `f`
/// has the same sign at both ends).
pub(crate) fn bisection(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let mut flo = f(lo);
    let mut fhi = f(hi);
    if flo == 0.0 {
        return lo;
    }
    if fhi == 0.0 || flo.signum() == fhi.signum() {
        return if fhi == 0.0 { hi } else { f64::NAN };
    }
    for _ in 0..2000 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo.min(hi) || mid >= lo.max(hi) {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return mid;
        }
        if fm.signum() == flo.signum() {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
            fhi = fm;
        }
    }
    if flo.abs() <= fhi.abs() {
        lo
    } else {
        hi
    }
}

/// The crossing of `g` through zero in `(a, b]` given `g(a) = ga < 0 ≤ g(b) = gb`, by the
/// Illinois iteration (false position, the value kept at an end halved whenever the same
/// end is kept twice in a row): the end of the final bracket where `g ≥ 0`, once the bracket
/// is within `4ε` of its ends (or a zero of `g`, or after 100 steps).
pub(crate) fn illinois(mut g: impl FnMut(f64) -> f64, a: f64, fa: f64, b: f64, fb: f64) -> f64 {
    let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
    let mut side = 0;
    for _ in 0..100 {
        if fb == 0.0 || (b - a).abs() <= 4.0 * f64::EPSILON * b.abs().max(a.abs()) {
            break;
        }
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !(c > a.min(b) && c < a.max(b)) {
            c = 0.5 * (a + b);
        }
        let fc = g(c);
        if fc == 0.0 {
            return c;
        }
        if (fc < 0.0) == (fa < 0.0) {
            a = c;
            fa = fc;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            b = c;
            fb = fc;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
    }
    b
}

/// The crossing of `g` through zero in `(a, b]` (`a < b`) given `g(a) = ga < 0 ≤ g(b) = gb`,
/// by the Illinois iteration with a safeguard: the value kept at an end is halved when the
/// same end is kept a second time, and the fourth step on one side is a bisection. Returns
/// the end of the final bracket where `g ≥ 0`, once the bracket is within `2ε` of `b` (or at
/// a zero of `g`, or after 200 steps).
pub(crate) fn illinois_with_bisection(
    mut g: impl FnMut(f64) -> f64,
    a: f64,
    ga: f64,
    b: f64,
    gb: f64,
) -> f64 {
    let (mut a, mut ga, mut b, mut gb) = (a, ga, b, gb);
    // The number of steps in a row on one side: negative on the side of `a`.
    let mut side = 0i32;
    for _ in 0..200 {
        if b - a <= 2.0 * f64::EPSILON * b.abs().max(f64::MIN_POSITIVE) {
            break;
        }
        let mut c = (a * gb - b * ga) / (gb - ga);
        if !(c > a && c < b) || side.abs() > 2 {
            c = 0.5 * (a + b);
            side = 0;
        }
        let gc = g(c);
        if gc < 0.0 {
            a = c;
            ga = gc;
            if side == -1 {
                gb *= 0.5;
            }
            side = if side < 0 { side - 1 } else { -1 };
        } else {
            b = c;
            gb = gc;
            if side == 1 {
                ga *= 0.5;
            }
            side = if side > 0 { side + 1 } else { 1 };
        }
        if gc == 0.0 {
            break;
        }
    }
    b
}

/// The crossing of `g` through zero in `(0, 1]` given `g(0) = g0 < 0 ≤ g(1) = g1`, starting
/// from an estimate `seed` of the root and the slope `dg/dθ` there (both from a cheap
/// approximation of `g`, such as an integrator's dense output). Newton's iteration with that
/// slope (at most four evaluations of `g`) stops once its correction is below sixteen units
/// in the last place of `θ`, returning the last point where `g` was evaluated. Otherwise the
/// root is bracketed within `±1e-9` of the seed (two evaluations), where [`illinois`]
/// converges in a few steps; if the seed is off, the search falls back to the remaining part
/// of `[0, 1]`.
pub(crate) fn newton_from_seed(
    mut g: impl FnMut(f64) -> f64,
    g0: f64,
    g1: f64,
    seed: f64,
    slope: f64,
) -> f64 {
    const DELTA: f64 = 1e-9;
    if !(seed > 0.0 && seed < 1.0) {
        return illinois(g, 0.0, g0, 1.0, g1);
    }
    if slope > 0.0 && slope.is_finite() {
        let mut th = seed;
        for _ in 0..4 {
            let gt = g(th);
            if gt == 0.0 {
                return th;
            }
            let next = th - gt / slope;
            if !(next > 0.0 && next <= 1.0) {
                break;
            }
            if (next - th).abs() <= 16.0 * f64::EPSILON * th {
                return th;
            }
            th = next;
        }
    }
    let lo = (seed - DELTA).max(0.0);
    let hi = (seed + DELTA).min(1.0);
    let f_lo = if lo > 0.0 { g(lo) } else { g0 };
    if f_lo >= 0.0 {
        return illinois(g, 0.0, g0, lo, f_lo);
    }
    let f_hi = if hi < 1.0 { g(hi) } else { g1 };
    if f_hi < 0.0 {
        return illinois(g, hi, f_hi, 1.0, g1);
    }
    illinois(g, lo, f_lo, hi, f_hi)
}

/// The crossing of an event function `g` (with its rate `g'`, from `g_dg`) through zero in
/// `(a, b]`, given `g(a) < 0 ≤ g(b)` on a variable of order one (a Chebyshev panel's
/// `[−1, 1]`): Newton's method from the secant point, kept inside the shrinking bracket
/// (bisection where a step would leave it or the rate is unusable). Returns a point where
/// `g ≥ 0` within `4ε` of the crossing (the end of the final bracket).
pub(crate) fn newton_crossing(
    g_dg: impl Fn(f64) -> (f64, f64),
    a: f64,
    ga: f64,
    b: f64,
    gb: f64,
) -> f64 {
    let (mut a, mut b) = (a, b);
    let mut t = a - ga * (b - a) / (gb - ga);
    for _ in 0..60 {
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let (g, dg) = g_dg(t);
        if g >= 0.0 {
            b = t;
        } else {
            a = t;
        }
        // (The variable is of order one.)
        let tol = 4.0 * f64::EPSILON;
        if b - a <= tol {
            return b;
        }
        let step = g / dg;
        t = if !step.is_finite() {
            // No usable rate: bisect (at the top of the loop).
            f64::NAN
        } else if step.abs() <= tol {
            // At the crossing to round-off: close the bracket from the side still open.
            if g >= 0.0 {
                t - tol
            } else {
                t + tol
            }
        } else {
            t - step
        };
    }
    b
}

/// The root of a function with value and derivative `f_df` in the bracket `[a, b]` (`f(a)`
/// of the sign of `fa`, `f(b)` of the other), from `x` inside it: Newton's method kept
/// inside the shrinking bracket (bisection where a step would leave it), to the last bit:
/// the Newton-corrected point once the correction is within `2ε max(|x|, 1)`.
pub(crate) fn newton_in_bracket(
    f_df: impl Fn(f64) -> (f64, f64),
    mut a: f64,
    mut fa: f64,
    mut b: f64,
    mut x: f64,
) -> f64 {
    for _ in 0..60 {
        let (fx, dfx) = f_df(x);
        if fx == 0.0 {
            return x;
        }
        if (fx < 0.0) == (fa < 0.0) {
            a = x;
            fa = fx;
        } else {
            b = x;
        }
        let newton = x - fx / dfx;
        // Converged (checked before the bracket test: at the root the step is nil and the
        // point sits on the bracket's end).
        if (newton - x).abs() <= 2.0 * f64::EPSILON * x.abs().max(1.0) {
            return newton;
        }
        x = if newton > a.min(b) && newton < a.max(b) {
            newton
        } else {
            0.5 * (a + b)
        };
    }
    x
}

/// A root of `g` (value and derivative) in `[a, b]` (`a < b`), where `g(a)` and `g(b)` have
/// opposite signs (or one is zero): from the secant point, Newton's steps while they stay
/// inside the shrinking bracket, bisection otherwise (and only bisection after 30 steps); to
/// the last bit (the bracket two adjacent numbers, or an iterate that no longer moves).
pub(crate) fn newton_bisection(g: impl Fn(f64) -> (f64, f64), mut a: f64, mut b: f64) -> f64 {
    let (ga, gb) = (g(a).0, g(b).0);
    if ga == 0.0 {
        return a;
    }
    if gb == 0.0 {
        return b;
    }
    let neg_at_a = ga < 0.0;
    let secant = a - ga * (b - a) / (gb - ga);
    let mut x = if secant > a && secant < b {
        secant
    } else {
        0.5 * (a + b)
    };
    for iteration in 0..300 {
        let (gx, dx) = g(x);
        if gx == 0.0 {
            return x;
        }
        if (gx < 0.0) == neg_at_a {
            a = x;
        } else {
            b = x;
        }
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            return x; // the bracket is two adjacent numbers
        }
        let newton = x - gx / dx;
        let next = if iteration < 30 && newton > a && newton < b {
            newton
        } else {
            mid
        };
        if next == x {
            return x;
        }
        x = next;
    }
    x
}

/// The root of `f` in `[x0, x1]`, where `f` is monotone and changes sign (`f0 = f(x0)`), with
/// `df` its derivative (or that of a positive multiple of `f` that `f` itself carries, such
/// as a damping that keeps it representable): safeguarded Newton, a bisection step whenever
/// Newton leaves the bracket or stalls — a bisection of the exponent where the bracket spans
/// orders of magnitude on one side of zero (`[0.1, 1e100]`: a few steps instead of
/// hundreds). Stops when the step or the bracket is within `2ε max(|x|, floor)` (`floor`
/// the absolute scale below which round-off noise is not chased), returning the better of
/// the last iterate and its successor.
pub(crate) fn newton_wide_bracket(
    eval: &impl Fn(f64) -> f64,
    df: impl Fn(f64) -> f64,
    mut x0: f64,
    mut x1: f64,
    f0: f64,
    floor: f64,
) -> f64 {
    let s0 = f0.signum();
    // Bisection in the exponent where the bracket spans orders of magnitude on one side of
    // zero (ζ ∈ [0.1, 1e100] at μ = 1e100): a few steps instead of hundreds.
    let split = |x0: f64, x1: f64| {
        let (a, b) = (x0.max(floor), x1);
        if x0 < 0.0 && x1 > 0.0 && (-x0 > 4.0 * x1.max(floor) || x1 > -4.0 * x0.min(-floor)) {
            // A wide bracket about zero: split at zero, leaving one side.
            0.0
        } else if x0 >= 0.0 && b > 4.0 * a {
            (a * b).sqrt()
        } else if x1 <= 0.0 && -x0 > 4.0 * (-x1).max(floor) {
            -(x0 * x1.min(-floor)).sqrt()
        } else {
            0.5 * (x0 + x1)
        }
    };
    // The bracket's size in the same measure: orders of magnitude where `split` bisects the
    // exponent, length elsewhere.
    let size = |x0: f64, x1: f64| {
        let (a, b) = (x0.max(floor), x1);
        if x0 >= 0.0 && b > 4.0 * a {
            (b / a).ln()
        } else if x1 <= 0.0 && -x0 > 4.0 * (-x1).max(floor) {
            (x0 / x1.min(-floor)).ln()
        } else {
            x1 - x0
        }
    };
    let mut x = split(x0, x1);
    // Newton is taken while it at least halves the bracket every other step (far from the
    // root of a cubic it may crawl, halving x each step from ζ = 1e100).
    let mut width = size(x0, x1);
    let mut slow = false;
    for _ in 0..200 {
        let f = eval(x);
        if f == 0.0 {
            return x;
        }
        if f.signum() == s0 {
            x0 = x;
        } else {
            x1 = x;
        }
        let newton = x - f / df(x);
        let now = size(x0, x1);
        let halved = now <= 0.5 * width;
        width = now;
        let crawling = !halved && slow;
        slow = !halved;
        let next = if newton > x0 && newton < x1 && !crawling {
            newton
        } else {
            split(x0, x1)
        };
        // Converged when the step or the bracket is at the last bit of x; near zero an
        // absolute floor (`floor · ε`) stops the chase of round-off noise.
        let tol = 2.0 * f64::EPSILON * x.abs().max(floor);
        if (next - x).abs() <= tol || x1 - x0 <= tol {
            // Converged: the better of the bracket ends and the iterate.
            return [x, next]
                .into_iter()
                .min_by(|a, b| eval(*a).abs().total_cmp(&eval(*b).abs()))
                .unwrap_or(next);
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::SplitMix64;

    /// A monotone test function with one root and a curvature that makes false position
    /// keep one end: `k (t − r) + c (t − r)³`.
    fn cubic(r: f64, k: f64, c: f64) -> impl Fn(f64) -> f64 {
        move |t| k * (t - r) + c * (t - r).powi(3)
    }

    /// The bracketing finders return a point within a few ulp of the root, on the side the
    /// contract names.
    #[test]
    fn bracketing_finders_converge_to_the_root_on_their_side() {
        let mut g = SplitMix64(0x1234_5678_9abc_def0);
        for _ in 0..2000 {
            let r = g.range(-0.9, 0.9);
            let (k, c) = (g.decades(-2.0, 2.0), g.decades(-2.0, 3.0));
            let f = cubic(r, k, c);
            let (a, b) = (-1.0, 1.0);
            let close = |x: f64| (x - r).abs() <= 8.0 * f64::EPSILON;
            let x = illinois(&f, a, f(a), b, f(b));
            assert!(f(x) >= 0.0 && close(x), "illinois {x} vs {r}");
            let x = illinois_with_bisection(&f, a, f(a), b, f(b));
            assert!(
                f(x) >= 0.0 && close(x),
                "illinois_with_bisection {x} vs {r}"
            );
            let x = bisection(&f, a, b);
            assert!(close(x), "bisection {x} vs {r}");
            let f_df = |t: f64| (f(t), k + 3.0 * c * (t - r) * (t - r));
            let x = newton_in_bracket(f_df, a, f(a), b, 0.0);
            assert!(close(x), "newton_in_bracket {x} vs {r}");
            let x = newton_bisection(f_df, a, b);
            assert!(close(x), "newton_bisection {x} vs {r}");
            let x = newton_crossing(f_df, a, f(a), b, f(b));
            assert!(f(x) >= 0.0 && close(x), "newton_crossing {x} vs {r}");
            let x = newton_wide_bracket(&f, |t| f_df(t).1, a, b, f(a), 1.0);
            assert!(close(x), "newton_wide_bracket {x} vs {r}");
            // On [0, 1]: a seed near the root with the slope there, and one that is off.
            let h = |t: f64| f(2.0 * t - 1.0);
            let th = 0.5 * (r + 1.0);
            for (seed, slope) in [(th + 1e-7, 2.0 * f_df(r).1), (0.5 * th, 1.0)] {
                let x = newton_from_seed(h, h(0.0), h(1.0), seed, slope);
                assert!(
                    (x - th).abs() <= 16.0 * f64::EPSILON,
                    "newton_from_seed {x} vs {th}"
                );
            }
        }
    }

    /// Events: the crossing is found within 4ε of the root of an increasing function, and of
    /// one that is not monotone in the bracket, always on the side where `g ≥ 0`.
    #[test]
    fn the_crossing_is_located_to_round_off_on_its_far_side() {
        let mut g = SplitMix64(0xbb67_ae85_84ca_a73b);
        for _ in 0..2000 {
            let root = g.range(-0.9, 0.9);
            let k = g.range(0.1, 10.0);
            // (|wiggle (t − root)| < 1: one root, and g' changes sign for the larger ones.)
            let wiggle = g.range(0.0, 0.5);
            let f = |t: f64| {
                (
                    k * (t - root) + wiggle * k * (t - root) * (t - root) * (3.0 * t).cos(),
                    k + wiggle
                        * k
                        * (2.0 * (t - root) * (3.0 * t).cos()
                            - 3.0 * (t - root) * (t - root) * (3.0 * t).sin()),
                )
            };
            let (a, b) = (-1.0, 1.0);
            let (fa, fb) = (f(a).0, f(b).0);
            if !(fa < 0.0 && fb >= 0.0) {
                continue;
            }
            let t = newton_crossing(f, a, fa, b, fb);
            assert!(f(t).0 >= 0.0, "g({t}) < 0");
            assert!((t - root).abs() <= 8.0 * f64::EPSILON, "{t} vs {root}");
        }
    }

    /// A bracket over a hundred orders of magnitude is closed in tens of steps, not
    /// hundreds: the root of `x − 3` in `[0.1, 1e100]`, with the count of evaluations.
    #[test]
    fn a_wide_bracket_is_split_in_the_exponent() {
        let count = std::cell::Cell::new(0);
        let f = |x: f64| {
            count.set(count.get() + 1);
            (x - 3.0) / x.max(1.0)
        };
        let df = |x: f64| if x >= 1.0 { 3.0 / (x * x) } else { 1.0 };
        let x = newton_wide_bracket(&f, df, 0.1, 1e100, f(0.1), 1.0);
        assert!((x - 3.0).abs() <= 4.0 * f64::EPSILON, "{x}");
        assert!(count.get() < 60, "{} evaluations", count.get());
    }
}
