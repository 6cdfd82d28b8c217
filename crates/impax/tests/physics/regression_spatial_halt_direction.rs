//! Regression (fixed): the slip direction reported at a halt is the direction in which the
//! slip halts.
//!
//! A slip that halts runs into the origin along a centripetal invariant ray (theory §2); the
//! direction at the halt — `to` of the `Slip { from, to }` phase followed by stick or resumed
//! slip — is that ray's angle. The integration used to report the direction at the point where
//! it switched to its straight closed-form tail (`σ` about `e⁻⁴⁰` of the switch value), still
//! far from a weakly attracting ray (`δφ ∝ σ^κ` with small `κ`); it now reports the ray the
//! direction tends to (reached by the series about the ray, or located from the last
//! direction).
//!
//! `W = [[6, 0, 0.7], [0, 6, 0], [0.7, 0, 1]]`, `v⁻ = (−0.4, 0.9, −1.5)`, `μ = 1.45`,
//! `e = 0.5`, `newton`: the invariant rays are `φ = 0` and `φ = π` (both centripetal;
//! `κ = |w_tn|/(μ W_11 − |w_tn|) ≈ 0.087` at `φ = 0`), the slip starts at 114° and halts
//! along `φ = 0`. Expected `to = 0` (within 1e-6); got `to = 0.2139` rad (12.3°). Found by
//! `spatial_properties::rotation_of_the_tangent_plane`.

use impax::spatial::{invariant_rays, ContactProblem, PhaseKind};
use impax::LawId;

#[test]
fn the_slip_halts_along_a_centripetal_ray() {
    let p =
        ContactProblem::from_upper([6.0, 0.0, 0.7, 6.0, 0.0, 1.0], [-0.4, 0.9, -1.5], 1.45, 0.5)
            .unwrap();
    let rays = invariant_rays(&p);
    let o = LawId::Newton.resolve(&p).unwrap();
    let ph = o.phases.as_slice();
    assert_eq!(ph.len(), 2, "the slip halts: {}", o.phases.summary());
    let PhaseKind::Slip { to, .. } = ph[0].kind else {
        panic!("{}", o.phases.summary())
    };
    let gap = rays
        .as_slice()
        .iter()
        .map(|r| {
            let d = (to - r.angle).rem_euclid(std::f64::consts::TAU);
            d.min(std::f64::consts::TAU - d)
        })
        .fold(f64::INFINITY, f64::min);
    assert!(
        gap <= 1e-6,
        "halted at {to} rad, {gap} rad from the nearest ray {rays:?}"
    );
}
