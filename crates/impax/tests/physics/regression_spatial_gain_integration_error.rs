//! Regression: an elastic frictionless spatial impact reported as gaining energy.
//!
//! Found by fuzzing the contact-problem constructors with every law: with `e = 1` and
//! `μ = 9e-100` the exact `ΔT` is 0, and `energetic` returned `ΔT = +2.6e-14` (of an approach
//! energy of 0.33) with verdict `energy-gained`. The integrated laws end to the integration's
//! tolerance, not to round-off; the gain test allowed round-off only.
//!
//! Expected: a gain of an integrated law must also exceed the disagreement between its two
//! evaluations of `ΔT` — `½ (v⁻ + v⁺)·p` and the work split `W_n + W_t` — so that what is
//! flagged is a gain, not the integration's error; real gains (Newton's rule with slip
//! reversal) are still flagged.

use impax::math::{Mat3, Vec3};
use impax::planar::Verdict;
use impax::spatial::ContactProblem;
use impax::LawId;

#[test]
fn an_elastic_frictionless_impact_does_not_gain_energy() {
    let w = Mat3::new(
        2.0,
        0.5998779296875,
        0.2999997615814209,
        0.5998779296875,
        1.0,
        -0.200152587890625,
        0.2999997615814209,
        -0.200152587890625,
        1.5000000000000568,
    );
    let v = Vec3::new(
        6.984921824965129e-11,
        5.049285103674212e-130,
        -1.00000000372529,
    );
    let p = ContactProblem::new(w, v, 9.143899130258199e-100, 1.0).unwrap();
    for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
        let o = law.resolve(&p).unwrap();
        assert_ne!(o.verdict, Verdict::EnergyGained, "{law}: {o:?}");
        assert!(
            o.energy_change.abs() < 1e-12,
            "{law}: ΔT = {:e}",
            o.energy_change
        );
    }
}

#[test]
fn a_real_gain_of_newtons_rule_is_still_flagged() {
    // The rod of the engine audit embedded in 3D (W_22 = 4): Newton's rule gains
    // ΔT = +0.1147 (the slip halts and the rod sticks, v_n⁺ = e |v_n⁻|), energetic loses 0.027.
    let th = 50f64.to_radians();
    let (s, c) = th.sin_cos();
    let (wtt, wtn, wnn) = (1.0 + 3.0 * s * s, -3.0 * s * c, 1.0 + 3.0 * c * c);
    let w = Mat3::new(wtt, 0.0, wtn, 0.0, 1.0 + 3.0, 0.0, wtn, 0.0, wnn);
    let v = Vec3::new(0.5, 0.0, -1.0);
    let p = ContactProblem::new(w, v, 0.8, 1.0).unwrap();
    let newton = LawId::Newton.resolve(&p).unwrap();
    let energetic = LawId::Energetic.resolve(&p).unwrap();
    assert_eq!(energetic.verdict, Verdict::Consistent);
    assert!((newton.energy_change - 0.114666).abs() < 1e-5, "{newton:?}");
    assert_eq!(newton.verdict, Verdict::EnergyGained, "{newton:?}");
}
