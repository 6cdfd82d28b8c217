//! fixed: without friction, a spatial Darboux–Keller law breaks down
//! when the contact starts at rest or the slip halts.
//!
//! With `μ = 0` and `w_tn ≠ 0` stick is impossible (`|W_tt⁻¹ w_tn| > 0 = μ`) and slip
//! resumes along `ŝ = w_tn/|w_tn|` at rate `λ' = |w_tn|` (`(λ'I + 0·W_tt) ŝ = w_tn`).
//! `resumption_direction` returns `None` instead: its secular equation
//! `Σ w̃ᵢ²/(λ' + μ dᵢ)² = 1` is infinite at the Newton start `λ' = 0` when `μ = 0`, the
//! step `−f/f'` is `NaN`, the loop stops at `λ' = 0` and `(0·I + 0·W_tt)` is singular. The
//! Darboux–Keller integration then reports `NoSeparation` for `newton`, `poisson` and
//! `energetic`.
//!
//! `W = [[1, 0, 0.5], [0, 1, 0], [0.5, 0, 1]]`, `μ = 0`, `e = 0.5`:
//! * `v⁻ = (0, 0, −1)` (at rest): expected `p = (0, 0, 1.5)` (frictionless:
//!   `p_n = −(1+e) v_n⁻/w_nn`, `p_t = 0`); got `Err(NoSeparation)` from all three laws;
//! * `v⁻ = (−0.25, 0, −1)` (the slip halts at `p_n = 0.5`): same;
//! * `resumption_direction`: expected `Some(((1, 0), 0.5))`; got `None`.
//!
//! Found by `spatial_reference` (every `μ = 0`, `v_t⁻ = 0` problem), `spatial_planar_embedding`,
//! `spatial_properties::frictionless_laws_give_the_normal_impulse` and
//! `spatial_invariants::resumption_direction_solves_the_shifted_system_and_is_the_centrifugal_ray`.

use impax::spatial::{resumption_direction, ContactProblem};
use impax::LawId;

const W: [f64; 6] = [1.0, 0.0, 0.5, 1.0, 0.0, 1.0];

#[test]
fn frictionless_darboux_keller_laws_resume_slip_from_rest() {
    for v in [[0.0, 0.0, -1.0], [-0.25, 0.0, -1.0]] {
        let p = ContactProblem::from_upper(W, v, 0.0, 0.5).unwrap();
        for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
            let o = law
                .resolve(&p)
                .unwrap_or_else(|b| panic!("v⁻ = {v:?}: {b}"));
            assert_eq!(
                (o.impulse.x, o.impulse.y),
                (0.0, 0.0),
                "{law}: {:?}",
                o.impulse
            );
            assert!((o.impulse.z - 1.5).abs() <= 1e-14, "{law}: {:?}", o.impulse);
        }
    }
}

#[test]
fn frictionless_resumption_direction_is_the_coupling() {
    let p = ContactProblem::from_upper(W, [0.0, 0.0, -1.0], 0.0, 0.5).unwrap();
    let (s, rate) = resumption_direction(&p).expect("stick is impossible, slip resumes");
    assert!(
        (s.x - 1.0).abs() <= 1e-15 && s.y.abs() <= 1e-15,
        "ŝ = {s:?}"
    );
    assert!((rate - 0.5).abs() <= 1e-15, "λ' = {rate}");
}
