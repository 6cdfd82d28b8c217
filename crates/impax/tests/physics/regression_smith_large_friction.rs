//! Regression: `smith` drifted, then gained energy, at large friction.
//!
//! Found by an adversarial run: results drifted from μ ≈ 1e20, and `impax resolve --w 3.5,0,1
//! --v 0.5,-0.866 --friction 1e30 --restitution 0.7 --law smith` reported `ΔT = +3.4e11`,
//! `energy-gained`, although `smith` never gains energy on a sphere. Smith's factor η was the
//! root of a cubic whose coefficients grow as μ² while the root shrinks as 1/μ, located to an
//! absolute resolution of `1e-9 ε` — far coarser than η ≈ 2e-31.
//!
//! Expected: the law solved in the friction ratio `ζ = μ η` (`p_t = −ζ p_n`), in which μ only
//! bounds the root and multiplies one side; results converge as μ → ∞ to the limit where the
//! slip reverses with its own speed (`u⁺ = −u⁻`), and no sphere gains energy at any μ.

use impax::math::{Mat2, SplitMix64, Vec2};
use impax::planar::{ContactProblem, LawDetail, Verdict};
use impax::LawId;

#[test]
fn the_issue_case_converges_to_the_reversal_limit_without_gaining_energy() {
    // Sphere, W = diag(7/2, 1): as μ → ∞ the root ζ → 2 u⁻/(N W_tt), N = (1 + e)|v_n⁻|, and
    // p_t → −2 u⁻ / W_tt, u⁺ → −u⁻.
    let limit_pt = -2.0 * 0.5 / 3.5;
    for mu in [1e20, 1e30, 1e60, 1e100, 1e154, 1e200, 1e300] {
        let p = ContactProblem::from_entries(3.5, 0.0, 1.0, 0.5, -0.866, mu, 0.7).unwrap();
        let o = LawId::Smith.resolve(&p).unwrap();
        assert_eq!(o.verdict, Verdict::Consistent, "μ = {mu:e}");
        assert!(
            o.energy_change < 0.0,
            "μ = {mu:e}: ΔT = {}",
            o.energy_change
        );
        assert!(
            (o.impulse.x - limit_pt).abs() < 1e-14,
            "μ = {mu:e}: p_t = {}",
            o.impulse.x
        );
        assert!((o.velocity_after.x + 0.5).abs() < 1e-14, "μ = {mu:e}");
        let LawDetail::Smith { eta, .. } = o.detail else {
            panic!("detail")
        };
        assert!(((eta * mu) / (-limit_pt / 1.4722) - 1.0).abs() < 1e-13);
    }
}

#[test]
fn no_sphere_gains_energy_at_any_friction() {
    let mut rng = SplitMix64(11);
    for _ in 0..20_000 {
        let m = rng.decades(-2.0, 2.0);
        let w = Mat2::new(3.5 / m, 0.0, 0.0, 1.0 / m);
        let vt = rng.range(-2.0, 2.0);
        let v = Vec2::new(vt, -rng.decades(-2.0, 0.3));
        let mu = rng.decades(-3.0, 300.0);
        let e = rng.unit();
        let p = ContactProblem::new(w, v, mu, e).unwrap();
        let o = LawId::Smith.resolve(&p).unwrap();
        assert_ne!(
            o.verdict,
            Verdict::EnergyGained,
            "{p:?}: ΔT = {}",
            o.energy_change
        );
    }
}

/// Smith's equation holds for the reported η: with `u⁺` the slip after,
/// `η (u⁺² + u⁻²) = u⁺|u⁺| + u⁻|u⁻|`, and `p_t = −μ η p_n`.
#[test]
fn smiths_equation_holds_over_three_hundred_decades_of_friction() {
    let mut rng = SplitMix64(12);
    let mut checked = 0;
    for _ in 0..20_000 {
        let (l11, l22) = (rng.decades(-1.0, 1.0), rng.decades(-1.0, 1.0));
        let l21 = rng.range(-1.0, 1.0) * rng.decades(-1.0, 1.0);
        let (a, b, c) = (l11 * l11, l11 * l21, l21 * l21 + l22 * l22);
        let v = Vec2::new(rng.range(-2.0, 2.0), -rng.decades(-2.0, 0.3));
        let mu = rng.decades(-3.0, 300.0);
        let Ok(p) = ContactProblem::new(Mat2::new(a, b, b, c), v, mu, rng.unit()) else {
            continue;
        };
        let Ok(o) = LawId::Smith.resolve(&p) else {
            continue;
        };
        let LawDetail::Smith { eta, .. } = o.detail else {
            panic!("detail")
        };
        let (u0, u1) = (v.x, o.velocity_after.x);
        let scale = u1 * u1 + u0 * u0;
        let residual = eta * scale - (u1 * u1.abs() + u0 * u0.abs());
        // u⁺ carries the round-off of p_n, amplified near the pole of p_n by up to the
        // condition number of W.
        let cond = (a + c) * (a + c) / (a * c - b * b);
        assert!(
            residual.abs() <= 1e-12 * cond * scale,
            "{p:?}: η = {eta:e}, u⁺ = {u1}, residual {residual:e}, cond {cond:e}"
        );
        let ratio = -o.impulse.x / o.impulse.y;
        assert!(
            (ratio - mu * eta).abs() <= 1e-12 * ratio.abs().max(1e-300),
            "{p:?}: p_t/p_n = {ratio:e}, μη = {:e}",
            mu * eta
        );
        checked += 1;
    }
    assert!(checked > 15_000, "{checked}");
}
