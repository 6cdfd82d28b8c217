//! fixed: spatial `energetic` with `e = 0` does not end at the end of
//! compression.
//!
//! With `e = 0` Stronge's termination `W_n = (1 − e²) W_c` is reached exactly where
//! compression ends (`v_n = 0`, the minimum of `W_n`), so `p_f = p_c`, `v_n⁺ = 0` and
//! `ΔT = W_c + W_t < 0`. In `spatial::darboux_keller::linear` (`Linear::run`, then
//! `linear_piece`) the termination on a straight piece solves
//! `v x + ½ k_n x² = (1 − e²) W_c − W_n(start)`; for `e = 0` this is the double root at the
//! vertex, its discriminant `v² + 2 k_n · need` is zero in exact
//! arithmetic and ±round-off in floating point:
//!
//! * negative on a *finite* piece (the straight run into a halt): the termination is skipped,
//!   the piece is run to the halt and the law ends at the start of the stick, far past `p_c`.
//!   `W = diag(1, 1, 0.7)`, `v⁻ = (1, 0, −0.3)`, `μ = 0.5`, `e = 0`:
//!   expected `p = (−0.5·3/7, 0, 3/7) = (−0.2142857…, 0, 0.4285714…)`, `ΔT < 0`;
//!   got `p = (−1, 0, 2)`, `ΔT = +0.3` (approach energy 0.564) and `Verdict::EnergyGained` —
//!   energetic gaining energy;
//! * negative on the *infinite* stick piece: `Err(NoSeparation)`.
//!   `W = [[1, 0, 0.1], [0, 1, 0], [0.1, 0, 1]]`, `v⁻ = (0, 0, −0.7)`, `μ = 2`, `e = 0`:
//!   expected stick, `p_n = 0.7/0.99 = 0.70707…`, `p_t1 = −0.1 p_n`; got `NoSeparation`;
//! * positive: the root is off by `√ε` relative.
//!   `W = [[1, 0, 0.3], [0, 1, 0], [0.3, 0, 1]]`, `v⁻ = (0, 0, −1)`, `μ = 1`, `e = 0`:
//!   expected `p_n = 1/0.91 = 1.0989010989…` (= the compression impulse); got
//!   `p_n = 1.0989011104799034` (relative error 1.05e-8).
//!
//! The same happens for `e` below about 1e-8 (`e² < ε`). Found by
//! `spatial_reference` (55 of 200 `e = 0` problems), `spatial_planar_embedding` and
//! `spatial_properties::plastic_impacts_end_at_the_end_of_compression`.

use impax::planar::Verdict;
use impax::spatial::ContactProblem;
use impax::LawId;

fn energetic(w: [f64; 6], v: [f64; 3], mu: f64) -> impax::spatial::Outcome {
    let p = ContactProblem::from_upper(w, v, mu, 0.0).unwrap();
    LawId::Energetic
        .resolve(&p)
        .unwrap_or_else(|b| panic!("{b} for {p:?}"))
}

#[test]
fn plastic_energetic_ends_at_compression_inside_a_straight_slip() {
    let o = energetic([1.0, 0.0, 0.0, 1.0, 0.0, 0.7], [1.0, 0.0, -0.3], 0.5);
    let pc = 0.3 / 0.7;
    assert!(
        (o.impulse.z - pc).abs() <= 1e-14,
        "p = {:?}, expected p_n = {pc}",
        o.impulse
    );
    assert!(
        (o.impulse.x + 0.5 * pc).abs() <= 1e-14,
        "p = {:?}",
        o.impulse
    );
    assert!(o.energy_change < 0.0, "ΔT = {}", o.energy_change);
    assert_ne!(o.verdict, Verdict::EnergyGained);
}

#[test]
fn plastic_energetic_separates_in_stick() {
    let o = energetic([1.0, 0.0, 0.1, 1.0, 0.0, 1.0], [0.0, 0.0, -0.7], 2.0);
    let pn = 0.7 / 0.99;
    assert!(
        (o.impulse.z - pn).abs() <= 1e-14,
        "p = {:?}, expected p_n = {pn}",
        o.impulse
    );
    assert!(
        (o.impulse.x + 0.1 * pn).abs() <= 1e-14,
        "p = {:?}",
        o.impulse
    );
}

#[test]
fn plastic_energetic_stick_ends_exactly_at_compression() {
    let o = energetic([1.0, 0.0, 0.3, 1.0, 0.0, 1.0], [0.0, 0.0, -1.0], 1.0);
    let pn = 1.0 / 0.91;
    assert!(
        (o.impulse.z - pn).abs() <= 1e-14 * pn,
        "p_n = {}, expected {pn} (compression impulse {:?})",
        o.impulse.z,
        o.compression_impulse
    );
}
