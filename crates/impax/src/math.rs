//! Type aliases and small numeric helpers shared by every module.
//!
//! Contact-frame vectors are ordered tangent(s) first, normal last (see the crate docs).

/// A planar vector: `(t, n)` in the contact frame, or `(x, y)` for a body.
pub type Vec2 = nalgebra::Vector2<f64>;
/// A 2×2 matrix, e.g. the planar contact-space inverse inertia `W`.
pub type Mat2 = nalgebra::Matrix2<f64>;

/// A spatial vector: `(t1, t2, n)` in the contact frame, or `(x, y, z)` for a body.
pub type Vec3 = nalgebra::Vector3<f64>;
/// A 3×3 matrix, e.g. the spatial contact-space inverse inertia `W` or an inertia tensor.
pub type Mat3 = nalgebra::Matrix3<f64>;

/// A unit quaternion (orientation, body → world).
pub type UnitQuat = nalgebra::UnitQuaternion<f64>;
/// A quaternion `w + xi + yj + zk`.
pub type Quat = nalgebra::Quaternion<f64>;

/// Sign of `x` as `-1.0`, `0.0` or `1.0` (unlike [`f64::signum`], zero maps to zero).
#[inline]
pub fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// The power of two that brings `x > 0` near one, limited so that every nonzero entry of
/// `entries`, scaled by it, stays within `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰]`: the exact change of units in
/// which a law is evaluated when its inputs are extreme.
pub(crate) fn unit_factor(x: f64, entries: &[f64]) -> f64 {
    let exponent = |y: f64| y.abs().log2().round() as i32;
    let (mut lo, mut hi) = (i32::MIN, i32::MAX);
    for &y in entries.iter().filter(|y| **y != 0.0) {
        lo = lo.max(-1000 - exponent(y));
        hi = hi.min(1000 - exponent(y));
    }
    2f64.powi((-exponent(x)).max(lo).min(hi))
}

/// The binary exponent `E` of a finite nonzero `x = m 2^E`, `1 ≤ |m| < 2` (exact, from the
/// bits; subnormals too). `0` for zero or a non-finite `x`.
pub(crate) fn binary_exponent(x: f64) -> i32 {
    if x == 0.0 || !x.is_finite() {
        return 0;
    }
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: bring it into the normal range first (exactly).
        return binary_exponent(x * 2f64.powi(64)) - 64;
    }
    biased - 1023
}

/// The power of two `2^−E(x)` that brings `x ≠ 0` into `[1, 2)` (`E` its exact binary
/// exponent), limited so that every nonzero entry of `entries`, scaled by it, stays within
/// `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰]`. Unlike [`unit_factor`] it depends on `x` only through its exponent,
/// exactly: `x 2^k` gets the factor `2^−k` times that of `x`, so a problem and any
/// power-of-two multiple of it are brought to the same units, bit for bit.
pub(crate) fn exact_unit_factor(x: f64, entries: &[f64]) -> f64 {
    let (mut lo, mut hi) = (i32::MIN, i32::MAX);
    for &y in entries.iter().filter(|y| **y != 0.0) {
        lo = lo.max(-1000 - binary_exponent(y));
        hi = hi.min(1000 - binary_exponent(y));
    }
    let k = (-binary_exponent(x)).max(lo).min(hi).clamp(-1000, 1000);
    2f64.powi(k)
}

/// `|v|` without overflow or underflow of the squares (`hypot` only where they would).
#[inline]
pub(crate) fn norm_of(v: Vec2) -> f64 {
    let n = v.norm();
    if n.is_finite() && n > 1e-150 {
        n
    } else {
        v.x.hypot(v.y)
    }
}

/// `|v|` of a 3-vector without overflow or underflow of the squares.
#[inline]
pub(crate) fn norm3_of(v: Vec3) -> f64 {
    let n = v.norm();
    if n.is_finite() && n > 1e-150 {
        n
    } else {
        v.x.hypot(v.y).hypot(v.z)
    }
}

/// The change of units of `planar::ContactProblem::in_units` (and the spatial laws'): velocities times `a`, `W` times `b`,
/// hence impulses times `a/b` and works times `a²/b` (the Darboux–Keller equations and every
/// algebraic law are homogeneous in these units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Units {
    /// The factor of velocities.
    pub a: f64,
    /// The factor of `W`.
    pub b: f64,
}

impl Units {
    pub fn factor(x: f64, entries: &[f64]) -> f64 {
        unit_factor(x, entries)
    }

    /// Impulses back to the problem's units.
    #[inline]
    pub fn impulse(&self, p: f64) -> f64 {
        p * (self.b / self.a)
    }

    /// Velocities back to the problem's units.
    #[inline]
    pub fn velocity(&self, v: f64) -> f64 {
        v / self.a
    }

    /// Works and energies back to the problem's units.
    #[inline]
    pub fn work(&self, w: f64) -> f64 {
        // (b / a) / a: each factor a power of two, so exact.
        w * (self.b / self.a) / self.a
    }

    /// A quantity with the units of `W` (velocity per impulse) back to the problem's units.
    #[inline]
    pub fn inverse_inertia(&self, w: f64) -> f64 {
        w / self.b
    }
}

/// Planar cross product `a × b = a.x b.y − a.y b.x` (the z component).
#[inline]
pub fn cross2(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Numerically careful real roots of `q2 x² + q1 x + q0 = 0` (ascending; `NaN` marks "no root").
///
/// Uses the cancellation-free form `x = 2 q0 / (−q1 ∓ √Δ)` for the small root.
/// A degenerate (`q2 = 0`) equation is solved as linear.
#[inline]
pub fn quadratic_roots(q2: f64, q1: f64, q0: f64) -> [f64; 2] {
    if q2 == 0.0 {
        if q1 == 0.0 {
            return [f64::NAN, f64::NAN];
        }
        let x = -q0 / q1;
        return [x, f64::NAN];
    }
    let disc = q1 * q1 - 4.0 * q2 * q0;
    if disc < 0.0 {
        return [f64::NAN, f64::NAN];
    }
    let sq = disc.sqrt();
    let q = -0.5 * (q1 + if q1 >= 0.0 { sq } else { -sq });
    let (r1, r2) = if q == 0.0 {
        (0.0, 0.0)
    } else {
        (q / q2, q0 / q)
    };
    if r1 <= r2 {
        [r1, r2]
    } else {
        [r2, r1]
    }
}

/// The increment of [`SplitMix64`]'s state: `2⁶⁴/φ`, odd.
pub const GOLDEN_GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's output function, a bijection of 64-bit words whose every output bit depends
/// on every input bit (Steele, Lea & Flood, *Fast splittable pseudorandom number generators*,
/// OOPSLA 2014; the constants of Stafford's "Mix13").
#[inline]
pub fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A small deterministic pseudorandom generator (SplitMix64, Steele, Lea & Flood 2014): the
/// state advances by [`GOLDEN_GAMMA`] and each output is [`mix64`] of it. For reproducible
/// samples — random problems in tests, benchmarks and examples, sampled sweeps — not for
/// cryptography. The same seed gives the same sequence on every platform.
///
/// ```
/// use impax::math::SplitMix64;
/// let mut rng = SplitMix64(42);
/// let u = rng.unit();
/// assert!((0.0..1.0).contains(&u));
/// assert_eq!(SplitMix64(42).unit(), u);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 bits.
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GOLDEN_GAMMA);
        mix64(self.0)
    }

    /// Uniform in `[0, 1)`: the top 53 bits of [`SplitMix64::next_u64`] times `2⁻⁵³`.
    #[inline]
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in `[lo, hi)`: `lo + (hi − lo) u`.
    #[inline]
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Log-uniform over the decades `lo … hi`: `10^u` with `u` uniform in `[lo, hi)`.
    #[inline]
    pub fn decades(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.range(lo, hi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_roots_are_accurate_without_cancellation() {
        // (x − 1e-9)(x − 1e9) = x² − (1e9 + 1e-9) x + 1
        let [a, b] = quadratic_roots(1.0, -(1e9 + 1e-9), 1.0);
        assert!((a - 1e-9).abs() < 1e-24);
        assert!((b - 1e9).abs() < 1e-6);
        let [c, d] = quadratic_roots(1.0, 0.0, 1.0);
        assert!(c.is_nan() && d.is_nan());
        assert_eq!(sign(-0.0), 0.0);
    }

    /// The reference implementation's first outputs for the seed 0 (Vigna, `splitmix64.c`).
    #[test]
    fn splitmix64_matches_the_reference_sequence() {
        let mut rng = SplitMix64(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        let u = SplitMix64(7).unit();
        assert!((0.0..1.0).contains(&u));
    }
}

/// Double-double arithmetic: an unevaluated sum `hi + lo` with `|lo| ≤ ulp(hi)/2`, about 106
/// bits (Dekker 1971; Hida, Li & Bailey, *Algorithms for quad-double precision floating
/// point arithmetic*, 2001): for the few small eliminations whose result is a difference of
/// nearly equal terms (the Schur complement of an ill-conditioned `W`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    hi: f64,
    lo: f64,
}

/// `a + b = s + e` exactly (Knuth's two-sum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly, given `|a| ≥ |b|` (Dekker's fast two-sum).
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

impl Dd {
    /// The double `x`.
    #[inline]
    pub(crate) fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The nearest double.
    #[inline]
    pub(crate) fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    #[inline]
    fn renormalised((hi, lo): (f64, f64)) -> Dd {
        let (hi, lo) = quick_two_sum(hi, lo);
        Dd { hi, lo }
    }

    /// `self + o`.
    #[inline]
    pub(crate) fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = quick_two_sum(s, e + t);
        Dd::renormalised((s, e + f))
    }

    /// `self − o`.
    #[inline]
    pub(crate) fn sub(self, o: Dd) -> Dd {
        self.add(Dd {
            hi: -o.hi,
            lo: -o.lo,
        })
    }

    /// `self · o`.
    #[inline]
    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = self.hi * o.hi;
        let e = self.hi.mul_add(o.hi, -p);
        Dd::renormalised((p, e + (self.hi * o.lo + self.lo * o.hi)))
    }

    /// `self / o` (three correction steps of the long division).
    #[inline]
    pub(crate) fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul(Dd::from(q1)));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul(Dd::from(q2)));
        let q3 = r.hi / o.hi;
        Dd::renormalised(quick_two_sum(q1, q2)).add(Dd::from(q3))
    }
}

#[cfg(test)]
mod exponent_tests {
    use super::{binary_exponent, exact_unit_factor};

    #[test]
    fn exponents_are_exact_and_shift_with_powers_of_two() {
        assert_eq!(binary_exponent(1.0), 0);
        assert_eq!(binary_exponent(1.999), 0);
        assert_eq!(binary_exponent(-0.75), -1);
        assert_eq!(binary_exponent(f64::MIN_POSITIVE), -1022);
        assert_eq!(binary_exponent(f64::MIN_POSITIVE / 8.0), -1025);
        assert_eq!(binary_exponent(f64::MAX), 1023);
        for x in [0.7, 3.3e-200, 1.0e250, 5e-320] {
            for k in [-300, -1, 1, 40, 300] {
                let y = x * 2f64.powi(k);
                if y.is_finite() && y != 0.0 && y.abs() >= f64::MIN_POSITIVE {
                    assert_eq!(binary_exponent(y), binary_exponent(x) + k, "{x} {k}");
                    // (Within the limits of the factor, 2^±1000.)
                    if binary_exponent(x).abs() <= 1000 && binary_exponent(y).abs() <= 1000 {
                        let (fx, fy) = (exact_unit_factor(x, &[x]), exact_unit_factor(y, &[y]));
                        assert_eq!(x * fx, y * fy);
                        assert!((1.0..2.0).contains(&(x * fx)));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod dd_tests {
    use super::Dd;

    /// Products and quotients of doubles are exact to about 2⁻¹⁰⁴ relative; a cancellation
    /// that loses all of double precision keeps the rest.
    #[test]
    fn double_double_keeps_the_digits_that_double_loses() {
        // (1 + 2⁻⁴⁰)² − 1 − 2⁻³⁹ = 2⁻⁸⁰: zero in double.
        let x = Dd::from(1.0 + 2f64.powi(-40));
        let r = x
            .mul(x)
            .sub(Dd::from(1.0))
            .sub(Dd::from(2f64.powi(-39)))
            .to_f64();
        assert_eq!(r, 2f64.powi(-80));
        // 1/3 · 3 = 1 to 2⁻¹⁰⁴.
        let third = Dd::from(1.0).div(Dd::from(3.0));
        let back = third.mul(Dd::from(3.0)).sub(Dd::from(1.0)).to_f64();
        assert!(back.abs() <= 2f64.powi(-104), "{back:e}");
    }
}
