//! Regression (fixed): the spatial Darboux–Keller laws broke down on valid problems with
//! extreme but representable numbers, after exhausting the 200,000-step budget. Now: a
//! velocity or `W` outside `[2⁻⁶⁰, 2⁶⁰]` is integrated scaled by powers of two, the slip
//! rate's norm is taken without squaring (`hypot`), and the approach to a centripetal ray —
//! fast and stiff for an anisotropic `W_tt` — is run in closed form by the series about the
//! ray.
//!
//! All three problems have `W_tn = 0`, so the answer is known in closed form: the slip
//! halts, the contact sticks (`λ = 0 ≤ μ`), `p_t = −W_tt⁻¹ v_t⁻` and
//! `p_n = −(1+e) v_n⁻/w_nn`.
//!
//! * `|g| = |μ W_tt ŝ| > ~1e154` (`g.norm()` overflowed): `W = I`, `v⁻ = (1, 0, −1)`,
//!   `μ = 1e200`, `e = 0.5`: `p = (−1, 0, 1.5)`;
//! * `|v_t⁻| < ~1e-154` (`vt.norm()` underflowed to 0): `W = I`,
//!   `v⁻ = (6e-167, 8e-167, −1e-150)`, `μ = 1e-12`, `e = 0.5`:
//!   `p = (−6e-167, −8e-167, 1.5e-150)`;
//! * stiff `W_tt` (anisotropy 1e6; the explicit integrator needed about 5 steps per unit of
//!   anisotropy): `W = diag(1, 1e6, 1)`, `v⁻ = (0.6, 0.8, −1)`, `μ = 0.5`, `e = 0.5`:
//!   `p = (−0.6, −8e-7, 1.5)` (41 steps).
//!
//! Found by `spatial_validation::no_law_panics_on_extreme_valid_problems`, whose sweep now
//! covers these ranges.

use impax::spatial::ContactProblem;
use impax::LawId;

fn check(w: [f64; 6], v: [f64; 3], mu: f64, expect: [f64; 3]) {
    let p = ContactProblem::from_upper(w, v, mu, 0.5).unwrap();
    let o = LawId::Newton
        .resolve(&p)
        .unwrap_or_else(|b| panic!("{b} for {p:?}"));
    let scale = expect.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..3 {
        assert!(
            (o.impulse[i] - expect[i]).abs() <= 1e-9 * scale,
            "p = {:?}, expected {expect:?}",
            o.impulse
        );
    }
}

#[test]
fn huge_friction_does_not_overflow() {
    check(
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        1e200,
        [-1.0, 0.0, 1.5],
    );
}

#[test]
fn tiny_slip_does_not_underflow() {
    check(
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [6e-167, 8e-167, -1e-150],
        1e-12,
        [-6e-167, -8e-167, 1.5e-150],
    );
}

#[test]
fn stiff_tangential_block_is_integrated() {
    check(
        [1.0, 0.0, 0.0, 1e6, 0.0, 1.0],
        [0.6, 0.8, -1.0],
        0.5,
        [-0.6, -8e-7, 1.5],
    );
}
