//! Regression: a slip, coupling and friction all a few dozen orders of magnitude above the
//! subnormal range stalled the spatial integration.
//!
//! Found by the fuzzer (`contact_problem`, a slow unit: 2.4 s optimised, past libFuzzer's
//! limit unoptimised): `W ≈ diag(0.9999986, 1, 1)` with `w_t1n = 2.1e-314`, `v⁻ = (0,
//! 3.2e-319, −1)`, `μ = 2e-314`; `newton`, `poisson` and `energetic` ran their budget of
//! 200,000 steps in the angle variable and broke down (`no separation`). The same problem
//! with the three tangential numbers scaled to 1e-280 resolves in microseconds; from about
//! 1e-285 the direction of the slip, converging on an invariant ray, has components in the
//! subnormal range and is lost.
//!
//! Expected: a slip or coupling below `NEGLIGIBLE_SLIP = 1e-250` of the canonical units
//! (`|v_n⁻|`, `w_nn` in `[1, 2)`) is taken as zero; the result differs from the exact one by
//! less than that fraction of its scale, and above it the tangential path is that of the
//! problem scaled (the equations are homogeneous in `(v_t, w_tn, μ)` up to the coupling
//! `μ w_tn`, of second order).

use impax::math::{Mat3, Vec3};
use impax::planar::Verdict;
use impax::spatial::{ContactProblem, NEGLIGIBLE_SLIP};
use impax::LawId;

const LAWS: [LawId; 3] = [LawId::Newton, LawId::Poisson, LawId::Energetic];

fn problem(t: f64, v_n: f64, w_nn: f64) -> ContactProblem {
    let w = Mat3::new(
        0.999_998_569_488_525_4,
        0.0,
        2.1 * t,
        0.0,
        1.0,
        0.0,
        2.1 * t,
        0.0,
        1.0,
    );
    let w = w * w_nn;
    ContactProblem::new(w, Vec3::new(0.0, 3.2e-5 * t * v_n, -v_n), 2.0 * t, 0.5).unwrap()
}

#[test]
fn the_fuzzed_problem_resolves() {
    let w = Mat3::new(
        0.999_998_569_488_525_4,
        2.037_115_959_327e-312,
        2.121_995_791e-314,
        2.037_115_959_327e-312,
        1.0,
        7.252_915_3e-317,
        2.121_995_791e-314,
        7.252_915_3e-317,
        1.0,
    );
    let v = Vec3::new(0.0, 3.2379e-319, -1.000_000_000_003_634_4);
    let p = ContactProblem::new(w, v, 1.994_325_054e-314, 5.299_808_81e-315).unwrap();
    for law in LAWS {
        let o = law.resolve(&p).unwrap_or_else(|b| panic!("{law}: {b}"));
        assert_eq!(o.verdict, Verdict::Consistent, "{law}");
        // Frictionless and plastic to the last bit: p_n = |v_n⁻| / w_nn.
        assert!(
            (o.impulse.z - 1.000_000_000_003_634_4).abs() < 1e-15,
            "{law}"
        );
        assert!(o.velocity_after.z.abs() < 1e-15, "{law}");
    }
}

#[test]
fn a_tangential_world_far_below_the_normal_one_scales_then_vanishes() {
    for law in LAWS {
        let reference = law.resolve(&problem(1e-14, 1.0, 1.0)).unwrap();
        let tangential = |o: &impax::spatial::Outcome, t: f64| {
            Vec3::new(o.impulse.x / t, o.impulse.y / t, o.velocity_after.x / t)
        };
        let expected = tangential(&reference, 1e-14);
        // Homogeneous where it is integrated: the tangential numbers scale with t (the
        // neglected coupling μ w_tn is 1e-28 of w_nn at t = 1e-14).
        for t in [1e-60, 1e-150, 1e-200, 1e-240] {
            for (v_n, w_nn) in [(1.0, 1.0), (1e-20, 1e20), (3.0, 0.1)] {
                let o = law
                    .resolve(&problem(t, v_n, w_nn))
                    .unwrap_or_else(|b| panic!("{law}, t = {t:e}: {b}"));
                assert_eq!(o.verdict, Verdict::Consistent);
                let got = tangential(&o, t);
                let scale = Vec3::new(v_n / w_nn, v_n / w_nn, v_n);
                let d = (got - expected.component_mul(&scale))
                    .component_div(&scale)
                    .amax();
                assert!(d < 1e-10, "{law}, t = {t:e}, ({v_n}, {w_nn}): {d:e}");
            }
        }
        // Below NEGLIGIBLE_SLIP: within that fraction of the scale of the exact result.
        for t in [1e-251, 1e-290, 1e-300, 1e-305] {
            let o = law.resolve(&problem(t, 1.0, 1.0)).unwrap();
            assert_eq!(o.verdict, Verdict::Consistent);
            assert!((o.impulse.z - 1.5).abs() < 1e-15);
            assert!(o.impulse.xy().amax() < 10.0 * NEGLIGIBLE_SLIP);
            assert!(o.velocity_after.xy().amax() < 10.0 * NEGLIGIBLE_SLIP);
        }
    }
}
