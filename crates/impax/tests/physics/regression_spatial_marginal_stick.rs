//! Regression: the spatial Darboux–Keller laws broke down with `no-separation` on a valid
//! problem where stick fails by a hair.
//!
//! `|W_tt⁻¹ w_tn| = 0.7731` against `μ = 0.7725`: stick is (barely) impossible, so the slip
//! resumes along the centrifugal ray, whose rate `λ'` is nearly zero, and the centripetal
//! ray the small initial slip approaches nearly coincides with it. The explicit integration
//! in the normal impulse ran out of its step budget instead of halting and resuming (its
//! stability limit kept the steps at `~σ/(μ|W_tt|)` while the slip was nearly frozen); the
//! slip in the angle variable between the two rays resolves it in a few panels. Expected: a
//! result (compression ends: `k_n ≈ 2.68 > 0` along the resumed ray) with `p_c = p_n` at
//! `e = 0`. Found by `spatial_properties::plastic_impacts_end_at_the_end_of_compression`;
//! `spatial_properties::marginal_stick_resolves` now samples the band `|ε| ∈ [1e-12, 1e-2]`.
use impax::spatial::ContactProblem;
use impax::LawId;

#[test]
fn marginal_stick_resolves() {
    let p = ContactProblem::from_upper(
        [
            0.9492171678682793,
            1.1112952706915435,
            0.9029402135349658,
            3.3492436446568927,
            1.4019343263091526,
            3.595109594923393,
        ],
        [
            -0.0021528601598625476,
            0.0023818595923932643,
            -1.8328454256569617,
        ],
        0.7725019922443639,
        0.0,
    )
    .unwrap();
    for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
        let o = law.resolve(&p).unwrap_or_else(|b| panic!("{b}"));
        assert_eq!(o.compression_impulse, Some(o.impulse.z));
    }
}
