//! What several test modules share.

use impax::math::{Mat3, SplitMix64};

/// A uniformly random rotation (from a random unit quaternion).
pub fn rotation(rng: &mut SplitMix64) -> Mat3 {
    loop {
        let q = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let n2: f64 = q.iter().map(|x| x * x).sum();
        if !(1e-3..=1.0).contains(&n2) {
            continue;
        }
        let n = n2.sqrt();
        let (w, x, y, z) = (q[0] / n, q[1] / n, q[2] / n, q[3] / n);
        return Mat3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - z * w),
            2.0 * (x * z + y * w),
            2.0 * (x * y + z * w),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - x * w),
            2.0 * (x * z - y * w),
            2.0 * (y * z + x * w),
            1.0 - 2.0 * (x * x + y * y),
        );
    }
}
