//! Contact-problem constructors and every law on arbitrary numbers: a problem is either
//! refused with an error or resolved by every law to a finite outcome or a breakdown; the
//! energetic and Poisson laws never report an energy gain.
#![no_main]

use impax::math::{Mat2, Mat3, Vec2, Vec3};
use impax::planar::{ContactProblem, Verdict};
use impax::spatial;
use impax::LawId;
use libfuzzer_sys::fuzz_target;

/// Eleven numbers from the bytes: either raw bit patterns (any double, NaN and infinities
/// included) or, with the first byte odd, values of moderate size built from them.
fn numbers(data: &[u8]) -> Option<[f64; 11]> {
    if data.len() < 1 + 11 * 8 {
        return None;
    }
    let raw = data[0] & 1 == 0;
    let mut x = [0.0; 11];
    for (i, chunk) in data[1..].chunks_exact(8).take(11).enumerate() {
        let bits = u64::from_le_bytes(chunk.try_into().ok()?);
        x[i] = if raw {
            f64::from_bits(bits)
        } else {
            // Mantissa in [−1, 1), exponent in [−8, 8): what users type.
            let m = (bits >> 11) as f64 / (1u64 << 52) as f64 - 1.0;
            m * 2f64.powi((bits & 15) as i32 - 8)
        };
    }
    Some(x)
}

fuzz_target!(|data: &[u8]| {
    let Some(x) = numbers(data) else { return };
    let (mu, e) = (x[9].abs(), x[10].abs().min(1.0));
    if let Ok(p) = ContactProblem::new(
        Mat2::new(x[0], x[1], x[1], x[2]),
        Vec2::new(x[3], x[4]),
        mu,
        e,
    ) {
        for law in LawId::CONTACT_SPACE {
            if let Ok(o) = law.resolve(&p) {
                assert!(o.is_finite(), "{law}: {o:?} for {p:?}");
                if matches!(law, LawId::Energetic | LawId::Poisson) {
                    assert_ne!(o.verdict, Verdict::EnergyGained, "{law}: {o:?} for {p:?}");
                }
            }
        }
    }
    let w = Mat3::new(x[0], x[1], x[2], x[1], x[3], x[4], x[2], x[4], x[5]);
    if let Ok(p) = spatial::ContactProblem::new(w, Vec3::new(x[6], x[7], x[8]), mu, e) {
        for law in LawId::SPATIAL {
            if let Ok(o) = law.resolve(&p) {
                assert!(o.is_finite(), "{law}: {o:?} for {p:?}");
                if law == LawId::Energetic {
                    assert_ne!(o.verdict, Verdict::EnergyGained, "{law}: {o:?} for {p:?}");
                }
            }
        }
    }
});
