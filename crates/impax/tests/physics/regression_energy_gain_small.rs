//! Regression: a small true gain of energy was not flagged.
//!
//! Found by an adversarial sweep: with mass 1e12, `two-phase` returned `ΔT = +0.113` with
//! verdict `consistent` (1,247 of 800,000 rows). A gain was reported only above `1e-12` of
//! the approach energy, a fixed fraction unrelated to the round-off of `ΔT`: near the
//! threshold where Whittaker's slip reversal starts to gain energy, gains of `10⁻¹³` of the
//! approach energy — hundreds of times the round-off — were called consistent, whatever the
//! mass (`ΔT/T0` does not depend on it; `ΔT` itself does, which made the miss visible).
//!
//! Expected: a gain is flagged when `ΔT` exceeds the round-off of its own evaluation,
//! relative to the problem's own energy scale (`planar::laws::is_energy_gain`), so the verdict
//! is the same at every mass.
//!
//! The reference is exact: for a sphere (`W = diag(7/2, 1)/m`) Whittaker's rule gives
//! `p_n = (1 + e) m |v_n|`, `p_t = −μ p_n` and
//! `ΔT = P (7P/(4m) − v_t) − (1 − e²) m v_n²/2` with `P = μ p_n`. With `m = 1`, `v = (1/2, −1)`,
//! `e = 1/2` and `μ = k/2⁵²`, `16·2¹⁰⁴ ΔT = 63 k² − 12·2⁵² k − 6·2¹⁰⁴` is an integer, computed
//! here in `i128`.

use impax::math::{Mat2, Vec2};
use impax::planar::{ContactProblem, Verdict};
use impax::LawId;

/// `16·2¹⁰⁴ ΔT(μ = k/2⁵²)` exactly.
fn scaled_gain(k: i128) -> i128 {
    63 * k * k - 12 * (1i128 << 52) * k - 6 * (1i128 << 104)
}

/// The smallest `k` with an exact gain, plus `offset`.
fn mu_above_threshold(offset: i128) -> (f64, f64) {
    // The root of 3.9375 μ² − 0.75 μ − 0.375, then the exact integer search around it.
    let root = (0.75 + (0.5625f64 + 4.0 * 3.9375 * 0.375).sqrt()) / (2.0 * 3.9375);
    let mut k = (root * 2f64.powi(52)) as i128 - 8;
    while scaled_gain(k) <= 0 {
        k += 1;
    }
    let k = k + offset;
    let exact = scaled_gain(k) as f64 / (16.0 * 2f64.powi(104));
    (k as f64 / 2f64.powi(52), exact)
}

fn sphere(mass: f64, mu: f64) -> ContactProblem {
    ContactProblem::new(
        Mat2::new(3.5 / mass, 0.0, 0.0, 1.0 / mass),
        Vec2::new(0.5, -1.0),
        mu,
        0.5,
    )
    .unwrap()
}

#[test]
fn a_gain_of_a_ten_trillionth_of_the_energy_is_a_gain_at_every_mass() {
    let (mu, exact) = mu_above_threshold(100);
    let p = sphere(1.0, mu);
    let relative = exact / p.approach_energy();
    assert!(
        relative > 2e-14 && relative < 1e-12,
        "ΔT/T0 = {relative:e}: below the former threshold"
    );
    for law in [LawId::Whittaker, LawId::TwoPhase] {
        let o = law.resolve(&p).unwrap();
        // The computed ΔT is the exact one to round-off of the energy scale.
        assert!(
            (o.energy_change - exact).abs() < 1e-15,
            "{law}: ΔT = {:e}, exact {exact:e}",
            o.energy_change
        );
        assert_eq!(o.verdict, Verdict::EnergyGained, "{law}: ΔT = {exact:e}");
        // The same impact at mass 2⁴⁰ (exactly scaled) and 10¹²: the same verdict.
        for mass in [2f64.powi(40), 1e12] {
            let o = law.resolve(&sphere(mass, mu)).unwrap();
            assert!(
                (o.energy_change / mass - exact).abs() < 1e-15,
                "{law}, m = {mass:e}: ΔT/m = {:e}, exact {exact:e}",
                o.energy_change / mass
            );
            assert_eq!(o.verdict, Verdict::EnergyGained, "{law}, m = {mass:e}");
        }
    }
}

#[test]
fn just_below_the_threshold_there_is_no_gain() {
    let (mu, exact) = mu_above_threshold(-100);
    assert!(exact < 0.0);
    for law in [LawId::Whittaker, LawId::TwoPhase] {
        let o = law.resolve(&sphere(1.0, mu)).unwrap();
        assert_ne!(
            o.verdict,
            Verdict::EnergyGained,
            "{law}: exact ΔT = {exact:e}"
        );
    }
}
