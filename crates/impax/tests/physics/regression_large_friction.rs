//! Regression: `lcp` listed spurious solutions at large friction, `lzb` broke down there, and
//! friction coefficients near the largest double were taken in.
//!
//! Found by trying `μ = 10⁶ … 10³⁰⁰` on `impax resolve --contacts 2 --w
//! 1,0.2,0,0.1,1,0.1,0,1,0.3,1 --v 0.1,-1,0.2,-0.5 --restitution 0.7 --law lcp`: from
//! `μ = 1e10` the law reported four solutions and `inconsistent-assumption`. Three of them
//! slipped with an impulse reversed (normal part `−10⁻¹⁰`, friction `μ` times that pushing the
//! slip on): the cone test of a slip judged the normal part alone against the round-off of
//! the impulses' scale, which its own friction dominates when `μ` is large. Listed as
//! `p = 0`, they showed velocities after that `v⁻ + W p` does not give.
//!
//! Expected: a slip's impulse `y (∓μ, 1)/|(μ, 1)|` (planar) or `p_n (−μ ŝ, 1)` (spatial) is in
//! its cone when `y ≥ 0` to round-off, and a stick's when its distance from the cone is; the
//! problem has the one solution (both contacts stick) at every `μ` from `10⁸`, each listed
//! solution of random problems satisfies the conditions with `v⁺ = v⁻ + W p` whatever `μ`;
//! `μ > 1e300` is refused naming `friction` (a slip halts at once long before; products of
//! `μ` with the problem's numbers overflowed: a fuzzed spatial problem with `μ = 1.4e308`
//! integrated for 0.6 s to a breakdown).

use crate::support::{assert_spatial_lcp_solution, random_spatial_space};
use impax::law::BreakdownReason;
use impax::math::{Mat2, Mat3, SplitMix64, Vec2, Vec3};
use impax::multi::spatial;
use impax::multi::{lcp, ContactPhaseKind, MultiDetail, MultiProblem};
use impax::planar::{ContactProblem, Verdict};
use impax::{Error, LawId};
use nalgebra::{DMatrix, DVector};

const W: [f64; 10] = [1.0, 0.2, 0.0, 0.1, 1.0, 0.1, 0.0, 1.0, 0.3, 1.0];
const V: [f64; 4] = [0.1, -1.0, 0.2, -0.5];

/// Every listed solution of a planar problem: `v⁺ = v⁻ + W p`, `p_n ≥ 0`, in the cone,
/// friction against a slip, `ΔT = ½ (v⁻ + v⁺)·p`; the number of solutions.
fn check_planar(p: &MultiProblem, mu: f64, what: &str) -> usize {
    let o = lcp::resolve(p).unwrap_or_else(|b| panic!("{what}: {b}"));
    let MultiDetail::Lcp { solutions } = &o.detail else {
        panic!("{what}: detail")
    };
    let (w, v) = (p.w(), p.velocity());
    for s in solutions {
        let flat = DVector::from_iterator(w.nrows(), s.impulses.iter().flat_map(|x| [x.x, x.y]));
        let after = v + w * &flat;
        let scale = v.amax() + (w.abs() * flat.abs()).amax();
        let tol = 1e-12 * scale;
        for (c, (pc, regime)) in s.impulses.iter().zip(s.regimes.iter()).enumerate() {
            let vc = Vec2::new(after[2 * c], after[2 * c + 1]);
            assert!(
                (vc - s.velocities_after[c]).amax() <= tol,
                "{what}: reported v⁺ {:?} against v⁻ + W p = {vc:?}",
                s.velocities_after[c]
            );
            assert!(pc.y >= 0.0, "{what}: p_n {}", pc.y);
            assert!(
                pc.x.abs() <= mu * pc.y * (1.0 + 1e-12) + 1e-300,
                "{what}: cone"
            );
            if matches!(regime, ContactPhaseKind::Slip(_)) {
                assert!(
                    pc.x * vc.x <= tol * pc.x.abs(),
                    "{what}: friction drives the slip"
                );
            }
        }
        // (ΔT may be positive: Newton's targets at several contacts can add energy.)
        let dt = 0.5 * (v + &after).dot(&flat);
        assert!(
            (dt - s.energy_change).abs() <= 1e-12 * scale * flat.amax(),
            "{what}: ΔT"
        );
    }
    solutions.len()
}

#[test]
fn the_issue_case_has_its_one_solution_at_every_large_friction() {
    let w = |mu: f64| MultiProblem::from_upper(2, &W, &V, &[mu], &[0.7]).unwrap();
    let reference = lcp::resolve(&w(1e8)).unwrap();
    for mu in [1e8, 1e10, 1e12, 1e20, 1e50, 1e100, 1e200, 1e300] {
        let what = format!("μ = {mu:e}");
        assert_eq!(check_planar(&w(mu), mu, &what), 1, "{what}");
        let o = lcp::resolve(&w(mu)).unwrap();
        assert_eq!(o.verdict, Verdict::Consistent, "{what}");
        for (a, b) in o.contacts.iter().zip(&reference.contacts) {
            assert!((a.impulse - b.impulse).amax() < 1e-14, "{what}");
            assert_eq!(a.phases.len(), 1);
            assert_eq!(a.phases[0].kind, ContactPhaseKind::Stick, "{what}");
        }
    }
}

#[test]
fn planar_lcp_solutions_hold_at_any_friction() {
    let mut rng = SplitMix64(0x1ae6_ef1c);
    let mut several = 0;
    for round in 0..3000 {
        let k = 2 + round % 3;
        let r = crate::support::random_multi(&mut rng, k);
        let mu = 10f64.powf(rng.range(2.0, 300.0));
        let e: Vec<f64> = (0..k).map(|_| rng.unit()).collect();
        let v: Vec<f64> = r.v.iter().copied().collect();
        let Ok(p) = MultiProblem::new(r.w.clone(), &v, &[mu], &e) else {
            continue;
        };
        if lcp::resolve(&p).is_err() {
            continue; // (a wedged singular W has no solution: multi_contact.rs)
        }
        if check_planar(&p, mu, &format!("round {round}, μ = {mu:e}")) > 1 {
            several += 1;
        }
    }
    println!("planar lcp, μ = 1e2 … 1e300: {several} of 3000 problems with several solutions");
}

#[test]
fn spatial_lcp_solutions_hold_at_any_friction() {
    let mut rng = SplitMix64(0x03d1_ae6e);
    let mut solved = 0;
    for round in 0..300 {
        let k = 2 + round % 2;
        let Some((w, v)) = random_spatial_space(&mut rng, k) else {
            continue;
        };
        let mu = 10f64.powf(rng.range(2.0, 300.0));
        let e: Vec<f64> = (0..k).map(|_| rng.unit()).collect();
        let Ok(p) = spatial::MultiProblem::new(w.clone(), &v, &[mu], &e) else {
            continue;
        };
        let Ok(out) = spatial::lcp::resolve(&p) else {
            continue;
        };
        solved += 1;
        let spatial::MultiDetail::Lcp { solutions } = &out.detail else {
            panic!("lcp detail")
        };
        for s in solutions {
            assert_spatial_lcp_solution(&p, s, &format!("round {round}, μ = {mu:e}"));
        }
    }
    assert!(solved > 200, "{solved}");
}

#[test]
fn friction_above_1e300_is_refused_naming_the_field() {
    let field = |r: Result<(), Error>| match r {
        Err(Error::OutOfRange { field, reason, .. }) => {
            assert!(reason.contains("1e300"), "{reason}");
            field
        }
        other => panic!("{other:?}"),
    };
    for mu in [1.0000001e300, 1.4e308, f64::MAX] {
        let planar =
            ContactProblem::new(Mat2::new(2.0, 0.6, 0.6, 0.3), Vec2::new(1.0, -0.2), mu, 0.5);
        assert_eq!(field(planar.map(|_| ())), "friction");
        let w3 = Mat3::new(2.0, 0.6, 0.3, 0.6, 1.0, -0.2, 0.3, -0.2, 1.5);
        let sp = impax::spatial::ContactProblem::new(w3, Vec3::new(0.3, 0.8, -1.0), mu, 0.5);
        assert_eq!(field(sp.map(|_| ())), "friction");
        let multi = MultiProblem::from_upper(2, &W, &V, &[0.5, mu], &[0.7]);
        assert_eq!(field(multi.map(|_| ())), "friction[2]");
        let w6 = DMatrix::<f64>::identity(6, 6);
        let s3 = spatial::MultiProblem::new(w6, &[0.0, 0.0, -1.0, 0.0, 0.0, -1.0], &[mu], &[0.5]);
        assert_eq!(field(s3.map(|_| ())), "friction");
    }
    // The largest accepted resolves with every law to a finite result or a breakdown.
    let p = ContactProblem::new(
        Mat2::new(2.0, 0.6, 0.6, 0.3),
        Vec2::new(1.0, -0.2),
        1e300,
        0.5,
    )
    .unwrap();
    for law in impax::LawId::CONTACT_SPACE {
        if let Ok(o) = law.resolve(&p) {
            assert!(o.is_finite(), "{law}");
        }
    }
}

/// `lzb` broke down on the issue case from about μ = 1e60 (`too-many-steps`): its first
/// DOP853 step overflowed (the slip's friction `μ F` stops it within `τ ≈ 1/μ`) and was
/// accepted — the error measure's maximum passed over the NaN ratios — so the path went on in
/// NaN to the step limit. A step with a non-finite result is now rejected (every DOP853 user:
/// `lzb` planar and spatial, the spatial Darboux–Keller laws). Expected: the results converge
/// as `1/μ` to the limit of infinite friction (from μ = 1e30 on, equal to the integration's
/// tolerance).
#[test]
fn lzb_converges_at_large_friction() {
    let resolve = |mu: f64| {
        let p = MultiProblem::from_upper(2, &W, &V, &[mu], &[0.7]).unwrap();
        impax::multi::lzb::resolve(&p).unwrap_or_else(|b| panic!("μ = {mu:e}: {b}"))
    };
    let limit = resolve(1e30);
    let near = resolve(1e8);
    for mu in [1e8, 1e30, 1e60, 1e100, 1e200, 1e300] {
        let o = resolve(mu);
        assert_eq!(o.verdict, Verdict::Consistent, "μ = {mu:e}");
        let tol = if mu < 1e10 { 1e-5 } else { 1e-10 };
        for (a, b) in o.contacts.iter().zip(&limit.contacts) {
            assert!((a.impulse - b.impulse).amax() < tol, "μ = {mu:e}");
        }
    }
    // (μ = 1e8 still differs from the limit, by about 2e-6: the slip phases shrink as 1/μ
    // but the path after them carries the change.)
    let d = (near.contacts[0].impulse - limit.contacts[0].impulse).amax();
    assert!(d > 0.0 && d < 1e-5, "{d:e}");
}

/// With non-finite steps rejected, a spatial problem whose right-hand side overflows at the
/// start shrank its step without end: the fuzzer (`contact_problem`) found `W ≈ [[3.5, 0, 1],
/// [0, 0.5, 0], [1, 0, 1]]` (entries of `±1e-300` and `2.2e-308` off the diagonal), `v⁻ =
/// (0.5, 0, −1e-300)`, `μ = 1.9e185`: `newton`, `poisson` and `energetic` ran past the
/// fuzzer's 20 s limit. The slip's friction (`μ` times a slip `5e299` times the normal
/// scale in canonical units) overflows; a rejected step that is already negligible (below
/// `1e-300`, or lost in the round-off of the variable) now ends the integration. Expected:
/// the `overflow` breakdown at once, as before non-finite steps were rejected.
#[test]
fn spatial_laws_stop_where_the_step_cannot_shrink() {
    let w = Mat3::new(
        3.5,
        2.225_073_858_507_201_4e-308,
        1.0,
        2.225_073_858_507_201_4e-308,
        0.5,
        -1e-300,
        1.0,
        -1e-300,
        1.0,
    );
    let v = Vec3::new(0.5, 0.0, -1e-300);
    let p = impax::spatial::ContactProblem::new(w, v, 1.903_664_958_504_395_5e185, 0.7).unwrap();
    for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
        match law.resolve(&p) {
            Err(b) => assert_eq!(b.reason, BreakdownReason::Overflow, "{law}"),
            Ok(o) => panic!("{law}: a result {:?}", o.impulse),
        }
    }
}
