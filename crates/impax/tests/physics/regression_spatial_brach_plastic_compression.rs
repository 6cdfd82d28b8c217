//! fixed: spatial `brach` with `e = 0` reports that compression
//! never ended.
//!
//! With `e = 0` Newton's restitution gives `v_n⁺ = 0`: compression ends exactly at the end,
//! `compression_impulse = Some(p_n)` (the planar `brach` says so). The 3D `straight` record
//! computes `p_c = −v_n⁻/slope_n` and compares it with `p_f`, which `brach` takes from the
//! Cholesky solve (`p*_n`) or from `newton_pn` (`w_nn + w_tn·k`, summed in another order):
//! when `p_c` rounds one ulp above `p_f` the record says `None` and files all the normal work
//! under compression.
//!
//! `W = [[1, 0, 0.1], [0, 1, 0], [0.1, 0, 1]]`, `v⁻ = (0, 0, −0.7)`, `μ = 1`, `e = 0`
//! (stick): expected `compression_impulse = Some(0.70707…) = Some(p_n)`; got `None`.
//!
//! Found by `spatial_planar_embedding` (53 of the 10,000 planar problems) and
//! `spatial_properties::plastic_impacts_end_at_the_end_of_compression`.

use impax::spatial::ContactProblem;
use impax::LawId;

#[test]
fn plastic_brach_ends_at_the_end_of_compression() {
    let p = ContactProblem::from_upper([1.0, 0.0, 0.1, 1.0, 0.0, 1.0], [0.0, 0.0, -0.7], 1.0, 0.0)
        .unwrap();
    let o = LawId::Brach.resolve(&p).unwrap();
    let pc = o
        .compression_impulse
        .expect("compression ends where the impact ends");
    assert!(
        (pc - o.impulse.z).abs() <= 1e-15 * o.impulse.z,
        "p_c = {pc}, p_n = {}",
        o.impulse.z
    );
}

/// An ill-conditioned sticking `brach` impact at `e = 0` (found by
/// `spatial_properties::plastic_impacts_end_at_the_end_of_compression`): the normal impulse
/// from the Cholesky solve and `−v_n⁻/slope` differed by 1.2e-11 relative; the compression
/// ends at the end of the impact, exactly.
#[test]
fn plastic_sticking_brach_ends_at_the_end_of_compression() {
    let w = [
        0.6221982193243969,
        0.02245065754257838,
        -0.18794654826583992,
        2.0616962914366073,
        0.6076392086965461,
        0.241674497009648,
    ];
    let p = impax::spatial::ContactProblem::from_upper(
        w,
        [-5.085453246422038, 6.745601455720763, -0.01],
        1.2013314902089984,
        0.0,
    )
    .unwrap();
    let o = impax::LawId::Brach.resolve(&p).unwrap();
    assert_eq!(o.compression_impulse, Some(o.impulse.z));
}
