//! Regression (fixed): `brach` broke down without friction.
//!
//! With `μ = 0` Brach's friction ratio is capped to `μ sign(μ0) = 0`, so the law is plain
//! Newton restitution without friction and must give `p = (0, −(1+e) v_n⁻ / W_nn)`, like
//! every other law (theory §5, "frictionless ⇒ every law gives p_n = −(1+e) v_n⁻/W_nn").
//! The library first checks the sign of the normal component of the *sticking* impulse
//! `p* = W⁻¹ (−v_t⁻, −(1+e) v_n⁻)` and returns `NegativeStickingImpulse` whenever it is
//! negative, although with `μ = 0` that impulse is never used (it is replaced by the capped
//! ratio). Found by `properties::frictionless_laws_all_give_the_normal_impulse`.
//!
//! Fix: the sticking impulse is only used when `p*_n > 0`; otherwise the ratio is beyond the
//! cone in the direction of `p*_t` and capped to `μ` (zero here), as `brach.rs` documents.

use impax::planar::ContactProblem;
use impax::LawId;

#[test]
fn brach_without_friction_is_frictionless_newton() {
    // p*_n = (W_tn v_t⁻ − (1+e) W_tt v_n⁻)/det W = (0.9·(−2) + 0.01)/0.19 < 0.
    let p = ContactProblem::from_entries(1.0, 0.9, 1.0, -2.0, -0.01, 0.0, 0.0).unwrap();
    let expected = 0.01; // −(1+e) v_n⁻ / W_nn
    for law in LawId::CONTACT_SPACE {
        let o = law
            .resolve(&p)
            .unwrap_or_else(|b| panic!("{law} breaks down without friction: {b}"));
        assert!(
            (o.impulse.y - expected).abs() < 1e-15,
            "{law}: {:?}",
            o.impulse
        );
        assert_eq!(o.impulse.x, 0.0, "{law}");
    }
}
