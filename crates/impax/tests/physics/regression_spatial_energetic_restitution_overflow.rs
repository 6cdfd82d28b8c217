//! Fixed: spatial `energetic` returned non-finite numbers for a large but representable
//! impact (now `x = e √2 √(−W_c)/√k_n`, no overflowing quotient).
//!
//! The energetic termination on a straight piece that contains the end of compression was
//! computed as `x = p_c − p_start + √(2 (−e² W_c) / k_n)`; the quotient `2 (−e² W_c)/k_n`
//! overflows although `x` itself is representable (it is `e p_c`, since
//! `−W_c = ½ k_n p_c²`).
//!
//! `W = 1e-100 · I`, `v⁻ = (0, 0, −1e100)`, `μ = 2`, `e = 1` (approach energy 5e299,
//! accepted by validation): expected stick from rest, `p = (0, 0, 2e200)`; it gave
//! `p = (NaN, NaN, inf)` as `Ok`. Found by
//! `spatial_validation::no_law_panics_on_extreme_valid_problems`.

use impax::spatial::ContactProblem;
use impax::LawId;

#[test]
fn large_energetic_impact_is_finite() {
    let s = 1e-100;
    let p =
        ContactProblem::from_upper([s, 0.0, 0.0, s, 0.0, s], [0.0, 0.0, -1e100], 2.0, 1.0).unwrap();
    let o = LawId::Energetic.resolve(&p).unwrap();
    assert_eq!(
        (o.impulse.x, o.impulse.y),
        (0.0, 0.0),
        "p = {:?}",
        o.impulse
    );
    assert!(
        (o.impulse.z - 2e200).abs() <= 1e-14 * 2e200,
        "p = {:?}",
        o.impulse
    );
}
