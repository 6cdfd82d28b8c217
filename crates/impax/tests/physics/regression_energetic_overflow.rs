//! Regression (fixed): `energetic` panicked on a problem whose
//! normal work overflows.
//!
//! `ContactProblem::from_entries(1, 0, 1, 0, −1e160, 0, 0)` passes validation. Its impulse
//! `p = (0, 1e160)` is representable but the compression work `−v_n⁻²/(2 W_nn) = −5e319` is
//! not: `W_c = −∞`, the energetic target `−e² W_c = −0 · (−∞) = NaN`, and
//! `energetic` panics with "the last Darboux–Keller segment is unbounded" (an `expect` in
//! `Energetic::resolve`). With `e = 0.5` it returns `p = (NaN, ∞)` instead of
//! `(0, 1.5e160)`. The other laws return the right impulse (with non-finite energies).
//! Either validation should reject velocities whose energy is not representable (an error
//! naming `v`), or the law must not panic; no panic on user input (style §6). Found by
//! `validation::no_law_panics_on_extreme_valid_problems`.
//!
//! Fix: `ContactProblem::new` rejects, naming `v`, a velocity whose approach energy
//! `½ v⁻ᵀ W⁻¹ v⁻` is not representable; every work of the impact is bounded by that scale.

use impax::planar::ContactProblem;
use impax::{Error, LawId};

#[test]
fn overflowing_approach_energy_is_rejected_naming_v() {
    for e in [0.0, 0.5] {
        match ContactProblem::from_entries(1.0, 0.0, 1.0, 0.0, -1e160, 0.0, e) {
            Err(Error::OutOfRange { field, .. }) => assert_eq!(field, "v"),
            other => panic!("expected an out-of-range error naming v, got {other:?}"),
        }
    }
}

#[test]
fn largest_representable_problems_still_resolve_without_panic() {
    // ½ v² / W_nn ≈ 5e299 is representable: every law returns finite numbers.
    let p = ContactProblem::from_entries(1.0, 0.3, 1.0, 2e149, -1e150, 0.5, 0.5).unwrap();
    for law in LawId::CONTACT_SPACE {
        if let Ok(o) = law.resolve(&p) {
            assert!(o.impulse.x.is_finite() && o.impulse.y.is_finite(), "{law}");
            assert!(o.energy_change.is_finite(), "{law}: {}", o.energy_change);
        }
    }
}
