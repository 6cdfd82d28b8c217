//! Regression (fixed): an unbounded energy gain was returned as an ordinary result, not as a
//! gain. A result with a non-finite number is now the breakdown `overflow`, in 3D and in the
//! plane.
//!
//! `whittaker` keeps friction `μ p_n` against the initial slip whatever happens, so a huge
//! `μ` drives the contact backwards with a huge tangential impulse and a huge energy gain.
//! `W = I`, `v⁻ = (1, 0, −1)`, `μ = 1e200`, `e = 1` (accepted by validation):
//! `p = (−2e200, 0, 2)`, `ΔT = ½ pᵀWp + v⁻·p ≈ 2e400`, not representable. Got `Ok` with
//! `work.friction = inf`, `energy_change = inf` and `Verdict::InconsistentAssumption`
//! (`is_energy_gain3` compares `inf > round_off = inf`, which is false). Expected: a
//! breakdown, or finite numbers, and in any case not a result whose energy gain is hidden —
//! `energy_change = +inf` must come with `Verdict::EnergyGained`. Found by
//! `spatial_validation::no_law_panics_on_extreme_valid_problems`.

use impax::spatial;
use impax::LawId;

#[test]
fn an_overflowing_gain_is_a_breakdown() {
    let p = spatial::ContactProblem::from_upper(
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        1e200,
        1.0,
    )
    .unwrap();
    match LawId::Whittaker.resolve(&p) {
        Err(b) => assert_eq!(b.reason.id(), "overflow", "{b}"),
        Ok(o) => panic!(
            "a result: ΔT = {}, work {:?}, verdict {:?}",
            o.energy_change, o.work, o.verdict
        ),
    }
    // A large but representable gain stays a result, and a gain.
    let p = spatial::ContactProblem::from_upper(
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        1e100,
        1.0,
    )
    .unwrap();
    let o = LawId::Whittaker.resolve(&p).expect("representable");
    assert!(o.energy_change.is_finite() && o.energy_change > 1e199);
    assert_eq!(o.verdict, impax::planar::Verdict::EnergyGained);
}

#[test]
fn an_overflowing_planar_gain_is_a_breakdown() {
    let p =
        impax::planar::ContactProblem::from_entries(1.0, 0.0, 1.0, 1.0, -1.0, 1e200, 1.0).unwrap();
    for law in [LawId::Whittaker, LawId::TwoPhase] {
        match law.resolve(&p) {
            Err(b) => assert_eq!(b.reason.id(), "overflow", "{law}: {b}"),
            Ok(o) => assert!(o.is_finite(), "{law}: {o:?}"),
        }
    }
    let b = LawId::Whittaker.resolve(&p).expect_err("overflow");
    assert_eq!(b.reason.id(), "overflow");
    // The brief of an outcome (what a sweep's tally reads) agrees with the full record.
    use impax::planar::laws::{Energetic, ImpactLaw, Newton, Poisson};
    assert_eq!(Newton.resolve(&p).is_ok(), Newton.resolve_brief(&p).is_ok());
    assert_eq!(
        Poisson.resolve(&p).is_ok(),
        Poisson.resolve_brief(&p).is_ok()
    );
    assert_eq!(
        Energetic.resolve(&p).is_ok(),
        Energetic.resolve_brief(&p).is_ok()
    );
}
