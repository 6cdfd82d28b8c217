//! Input validation of `spatial::ContactProblem` and robustness of every law on extreme problems.
//!
//! * every invalid input to `spatial::ContactProblem::new`, `from_upper`, `from_planar` and
//!   `rotated` returns the right `impax::Error` variant, naming the field (in the variant
//!   and at the start of its message): a NaN or infinite entry of `W` (all nine positions:
//!   `w[t1,t2]` …), of `v` (`v[t1]`, `v[t2]`, `v[n]`), `friction`, `restitution`;
//!   a non-symmetric `W` (each off-diagonal pair, with the two values); `W` not positive
//!   definite (non-positive diagonal, indefinite, singular, numerically singular);
//!   `v_n ≥ 0` (including `0` and `−0`); `μ < 0`; `e < 0` or `e > 1`; a velocity whose
//!   approach energy overflows;
//! * valid limits are accepted: `μ = 0`, `e = 0`, `e = 1`, `v_t = 0`, round-off asymmetry;
//! * no law (all eight ids through `LawId::resolve`) panics on extreme but valid problems: `W`
//!   scaled by 10^±100, near-singular through the coupling (Schur complement ~1e-6), `w_nn`
//!   from 1e-6 to 1e6 of `W_tt`, `W_tt` anisotropic up to 100; `|v|` over 10^±100,
//!   `|v_t|/|v_n| ∈ {0, 1e-12, 1, 1e12}`, `μ ∈ {0, 1e-300, 1e-12, 2, 1e3, 1e50}`,
//!   `e ∈ {0, 1e-300, 1e-16, 0.5, 1 − 1e-16, 1}`; every success is finite (impulse,
//!   velocity, works, `ΔT`) with `p_n ≥ 0`, every failure is a `Breakdown`, and the
//!   planar-only laws break down with `planar-only` / `needs-body`; and the same beyond
//!   the squares' range: `|v| = 1e-160`, `μ = 1e200`, `W_tt` anisotropic to 1e6 with a
//!   coupling (`regression_spatial_extreme_no_separation.rs` checks three of them against
//!   their closed form).

use impax::math::{Mat3, Vec3};
use impax::planar::ContactProblem;
use impax::spatial;
use impax::{Error, LawId};
use std::panic::{catch_unwind, AssertUnwindSafe};

const NAMES: [&str; 3] = ["t1", "t2", "n"];

fn w0() -> Mat3 {
    Mat3::new(2.0, 0.3, 0.2, 0.3, 1.5, -0.1, 0.2, -0.1, 1.0)
}

fn v0() -> Vec3 {
    Vec3::new(0.4, -0.3, -1.0)
}

/// The error names `field`, in the variant and at the start of its message.
fn assert_field(e: &Error, field: &str) {
    assert_eq!(e.field(), field, "{e:?}");
    assert!(
        e.to_string().starts_with(field),
        "message `{e}` does not start with {field}"
    );
}

#[test]
fn non_finite_entries_are_named() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for i in 0..3 {
            for j in 0..3 {
                let mut w = w0();
                w[(i, j)] = bad;
                let e = spatial::ContactProblem::new(w, v0(), 0.5, 0.5).unwrap_err();
                assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
                assert_field(&e, &format!("w[{},{}]", NAMES[i], NAMES[j]));
            }
            let mut v = v0();
            v[i] = bad;
            let e = spatial::ContactProblem::new(w0(), v, 0.5, 0.5).unwrap_err();
            assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
            assert_field(&e, &format!("v[{}]", NAMES[i]));
        }
        let e = spatial::ContactProblem::new(w0(), v0(), bad, 0.5).unwrap_err();
        assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
        assert_field(&e, "friction");
        let e = spatial::ContactProblem::new(w0(), v0(), 0.5, bad).unwrap_err();
        assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
        assert_field(&e, "restitution");
        // from_upper: the upper-triangle entry k lands at (i, j) and (j, i); the first one
        // checked is the upper one.
        let at = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)];
        for (k, &(i, j)) in at.iter().enumerate() {
            let mut u = [2.0, 0.3, 0.2, 1.5, -0.1, 1.0];
            u[k] = bad;
            let e =
                spatial::ContactProblem::from_upper(u, [0.4, -0.3, -1.0], 0.5, 0.5).unwrap_err();
            assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
            assert_field(&e, &format!("w[{},{}]", NAMES[i], NAMES[j]));
        }
        // from_planar: the second tangent's entry.
        let pl = ContactProblem::from_entries(2.0, 0.3, 1.0, 0.4, -1.0, 0.5, 0.5).unwrap();
        let e = spatial::ContactProblem::from_planar(&pl, bad).unwrap_err();
        assert_field(&e, "w[t2,t2]");
        // rotated by a non-finite angle.
        let p = spatial::ContactProblem::new(w0(), v0(), 0.5, 0.5).unwrap();
        let e = p.rotated(bad).unwrap_err();
        assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
    }
}

#[test]
fn non_symmetric_matrices_are_rejected_with_both_entries() {
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let mut w = w0();
        w[(i, j)] += 1e-6;
        let e = spatial::ContactProblem::new(w, v0(), 0.5, 0.5).unwrap_err();
        match &e {
            Error::NotSymmetric { upper, lower, .. } => {
                assert_eq!((*upper, *lower), (w[(i, j)], w[(j, i)]), "{e:?}");
            }
            other => panic!("({i},{j}): {other:?}"),
        }
        assert_field(&e, "w");
    }
    // Round-off asymmetry (1e-15 relative) is accepted.
    let mut w = w0();
    w[(0, 2)] *= 1.0 + 1e-15;
    assert!(spatial::ContactProblem::new(w, v0(), 0.5, 0.5).is_ok());
}

#[test]
fn matrices_that_are_not_positive_definite_are_rejected() {
    let bad: [[f64; 6]; 8] = [
        [0.0, 0.0, 0.0, 1.0, 0.0, 1.0],         // W11 = 0
        [1.0, 0.0, 0.0, -1.0, 0.0, 1.0],        // W22 < 0
        [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],         // W33 = 0
        [1.0, 2.0, 0.0, 1.0, 0.0, 1.0],         // indefinite tangential block
        [1.0, 1.0, 0.0, 1.0, 0.0, 1.0],         // singular tangential block
        [1.0, 0.0, 1.0, 1.0, 0.0, 1.0],         // Schur complement 0
        [1.0, 0.0, 0.8, 1.0, 0.8, 1.0],         // indefinite through the coupling
        [1.0, 0.0, 0.0, 1.0, 1.0, 1.0 + 1e-16], // numerically singular
    ];
    for u in bad {
        let e = spatial::ContactProblem::from_upper(u, [0.4, -0.3, -1.0], 0.5, 0.5).unwrap_err();
        assert!(
            matches!(e, Error::NotPositiveDefinite { .. }),
            "{u:?}: {e:?}"
        );
        assert_field(&e, "w");
    }
    let pl = ContactProblem::from_entries(2.0, 0.3, 1.0, 0.4, -1.0, 0.5, 0.5).unwrap();
    for w22 in [0.0, -1.0] {
        let e = spatial::ContactProblem::from_planar(&pl, w22).unwrap_err();
        assert!(matches!(e, Error::NotPositiveDefinite { .. }), "{e:?}");
        assert_field(&e, "w");
    }
}

#[test]
fn out_of_range_velocity_and_coefficients_are_named() {
    for vn in [0.0, -0.0, 1e-300, 1.0] {
        let e = spatial::ContactProblem::new(w0(), Vec3::new(0.4, -0.3, vn), 0.5, 0.5).unwrap_err();
        match &e {
            Error::NotApproaching { value, .. } => assert_eq!(value.to_bits(), vn.to_bits()),
            other => panic!("v_n = {vn}: {other:?}"),
        }
        assert_field(&e, "v");
    }
    for mu in [-1e-300, -0.5, -1e300] {
        let e = spatial::ContactProblem::new(w0(), v0(), mu, 0.5).unwrap_err();
        assert!(
            matches!(e, Error::OutOfRange { value, .. } if value == mu),
            "{e:?}"
        );
        assert_field(&e, "friction");
    }
    for r in [-1e-300, -0.1, 1.0 + f64::EPSILON, 2.0] {
        let e = spatial::ContactProblem::new(w0(), v0(), 0.5, r).unwrap_err();
        assert!(
            matches!(e, Error::OutOfRange { value, .. } if value == r),
            "{e:?}"
        );
        assert_field(&e, "restitution");
    }
    // The approach energy ½ vᵀW⁻¹v overflows.
    for (w, v) in [
        (Mat3::identity(), Vec3::new(0.0, 0.0, -1e160)),
        (Mat3::identity() * 1e-100, Vec3::new(1e105, 0.0, -1e105)),
        (Mat3::identity(), Vec3::new(1e300, 1e300, -1e300)),
    ] {
        let e = spatial::ContactProblem::new(w, v, 0.5, 0.5).unwrap_err();
        assert!(matches!(e, Error::OutOfRange { .. }), "{e:?}");
        assert_field(&e, "v");
    }
    // Valid limits.
    for (mu, r) in [(0.0, 0.0), (0.0, 1.0), (2.0, 1.0), (-0.0, 0.5)] {
        assert!(
            spatial::ContactProblem::new(w0(), v0(), mu, r).is_ok(),
            "μ = {mu}, e = {r}"
        );
    }
    assert!(spatial::ContactProblem::new(w0(), Vec3::new(0.0, 0.0, -1.0), 0.5, 0.5).is_ok());
}

/// Upper triangles of `W`: near-singular through the coupling (Schur complement ~1e-6),
/// `w_nn` tiny or large, anisotropic `W_tt` (up to 1e6, with a coupling), scaled by
/// `10^±100`.
fn matrices() -> Vec<[f64; 6]> {
    let mut out = vec![
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
        [1.0, 0.0, 0.0, 100.0, 0.0, 1e-6],
        [1.0, 0.0, 0.0, 1.0, 0.0, 1e6],
        [1.0, 0.0, 0.999_999, 1.0, 0.0, 1.0],
        [1.0, 0.0, 0.6, 1.0, 0.799_999, 1.0],
        [2.0, -1.9, 0.3, 2.0, -0.3, 1.0],
        [1e-3, 0.0, 0.0, 1e-1, 0.0031, 1.0],
        [1.0, 0.0, 0.2, 1e6, 0.3, 1.0],
        [1e4, 0.5, -0.3, 1.0, 0.2, 1.0],
    ];
    let base = out.clone();
    for s in [1e-100, 1e100] {
        for u in &base {
            out.push(u.map(|x| x * s));
        }
    }
    out
}

#[test]
fn no_law_panics_on_extreme_valid_problems() {
    let mut solved = 0usize;
    let mut broke = 0usize;
    let mut invalid = 0usize;
    let mut dk_broke = 0usize;
    let mut failures = Vec::new();
    let mags = [1e-160, 1e-100, 1.0, 1e100];
    let ratios = [0.0, 1e-12, 1.0, 1e12];
    let mus = [0.0, 1e-300, 1e-12, 2.0, 1e3, 1e50, 1e200];
    let es = [0.0, 1e-300, 1e-16, 0.5, 1.0 - 1e-16, 1.0];
    let mut k = 0usize;
    for u in matrices() {
        for &m in &mags {
            for &r in &ratios {
                k += 1;
                // A spread of directions, coefficients and signs without a full product.
                let phi = 0.7 * k as f64;
                let v = [m * r * phi.cos(), m * r * phi.sin(), -m];
                let mu = mus[k % mus.len()];
                let e = es[(k / mus.len()) % es.len()];
                for (mu, e) in [(mu, e), (mus[(k + 3) % mus.len()], es[(k + 1) % es.len()])] {
                    let p = match spatial::ContactProblem::from_upper(u, v, mu, e) {
                        Ok(p) => p,
                        Err(_) => {
                            invalid += 1;
                            continue;
                        }
                    };
                    for law in LawId::ALL {
                        let out = catch_unwind(AssertUnwindSafe(|| law.resolve(&p)));
                        match out {
                            Err(_) => failures.push(format!("{law} panicked on {p:?}")),
                            Ok(Ok(o)) => {
                                solved += 1;
                                let finite = o.impulse.iter().all(|x| x.is_finite())
                                    && o.velocity_after.iter().all(|x| x.is_finite())
                                    && o.energy_change.is_finite()
                                    && o.work.compression.is_finite()
                                    && o.work.restitution.is_finite()
                                    && o.work.friction.is_finite();
                                if !finite || o.impulse.z < 0.0 {
                                    failures.push(format!("{law}: {o:?} on {p:?}"));
                                }
                                if !matches!(
                                    law,
                                    LawId::Whittaker
                                        | LawId::Brach
                                        | LawId::Newton
                                        | LawId::Poisson
                                        | LawId::Energetic
                                        | LawId::Lcp
                                ) {
                                    failures.push(format!("{law} (planar only) solved {p:?}"));
                                }
                            }
                            Ok(Err(b)) => {
                                broke += 1;
                                if law.is_darboux_keller() {
                                    dk_broke += 1;
                                }
                                let want = match law {
                                    LawId::TwoPhase | LawId::Smith | LawId::SmithCentre => {
                                        Some(["planar-only", "needs-body"])
                                    }
                                    _ => None,
                                };
                                if let Some(w) = want {
                                    if !w.contains(&b.reason.id()) {
                                        failures.push(format!("{law}: {b} on {p:?}"));
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    eprintln!(
        "extreme problems: {solved} results, {broke} breakdowns ({dk_broke} of newton, poisson, \
         energetic), {invalid} rejected by validation"
    );
    for f in failures.iter().take(10) {
        eprintln!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} failures, first: {}",
        failures.len(),
        failures[0]
    );
    assert!(solved >= 500, "only {solved} solved");
}
