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
}
