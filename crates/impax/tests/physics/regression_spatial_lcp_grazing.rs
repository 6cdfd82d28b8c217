//! Regression: the spatial `lcp` missed the solution of grazing, strongly coupled impacts.
//!
//! Bug: 2 of 100,000 random problems reported the breakdown `no-solution`, e.g.
//!
//! ```text
//! impax resolve --w 614327.3694481789,341336.2451532919,347013.5943548623,\
//!   189656.59358945338,192810.08142403685,196018.03696236789 \
//!   --v 1,0.12097437381250864,-1e-9 --friction 1.0598928366735887 \
//!   --restitution 0.9615509061531089 --law lcp
//! lcp: breakdown: the complementarity conditions have no solution
//! ```
//!
//! while high-precision arithmetic (and Lemke's method) find slip at −33.18° with
//! `p_n = 0.36186`. Found by an adversarial run for issue 17. The root of the slip-angle
//! equation `F(θ) = D(θ) ŝ × u + N ŝ × g(ŝ)` was found, but the normal impulse was taken
//! as `p_n = N / D(θ)` with `D = w_nn − μ w_tn·ŝ = 5.4e-9` a difference of terms of 2e5
//! whose rate `dD/dθ = 3.7e5` turns the last bit of `θ` alone into 6 % of `D`:
//! `p_n = 0.385`, the slip velocity came out backwards (`σ = −7.8e-4`) and the only solution
//! was rejected. The reported compression impulse of such straight laws had the same
//! cancellation (`p_c = |v_n⁻| / D`).
//!
//! Expected: at a root the normal impulse is also `p_n = −(ŝ × u)/(ŝ × g)` (the slip
//! velocity has no component across its direction), whose error is ~3e-10 here; the law
//! takes whichever expression has the smaller estimated error, the compression impulse as
//! `p_c = p_f/(1+e)` (Newton's rule on a straight path), and reports `v_n⁺ = −e v_n⁻` and
//! `v_t⁺ = σ ŝ` as the conditions give them. The returned solution satisfies
//! `0 ≤ p_n ⊥ v_n⁺ + e v_n⁻ = 0`, `|p_t| ≤ μ p_n`, `p_t = −μ p_n v̂_t⁺` to 1e-12 — impulses
//! relative to `|p|`, `v⁻ + W p` relative to the size of its terms `|v⁻| + |W||p|` (the
//! round-off of evaluating it) — and agrees with the 60-digit solution to its conditioning.
//! A randomized search over grazing strongly coupled problems finds a solution for every one.

use crate::support::rotation;
use impax::math::{Mat3, SplitMix64, Vec2, Vec3};
use impax::planar::BreakdownReason;
use impax::spatial::laws::lcp::{solutions, LcpSolution};
use impax::spatial::{ContactProblem, PhaseKind};
use impax::LawId;

/// The largest violation of the conditions by `s`: impulses relative to `|p|`, `v⁻ + W p`
/// relative to `|v⁻| + |W||p|`; and the reported velocity against `v⁻ + W p` the same way.
fn residual(p: &ContactProblem, s: &LcpSolution) -> f64 {
    let imp = s.impulse;
    let v = p.velocity();
    let direct = v + p.w() * imp;
    let pscale = imp.norm();
    let vscale = (v.abs() + p.w().abs() * imp.abs()).max();
    let (mu, e) = (p.friction(), p.restitution());
    let (pt, pn) = (imp.xy(), imp.z);
    assert!(pn > 0.0, "{s:?}");
    // Normal: p_n > 0 and v_n⁺ = −e v_n⁻ (reported exactly; v⁻ + W p to its round-off).
    assert_eq!(s.velocity_after.z, -e * v.z);
    let mut r = (direct.z + e * v.z).abs() / vscale;
    r = r.max((s.velocity_after - direct).abs().max() / vscale);
    // The cone.
    r = r.max((pt.norm() - mu * pn).max(0.0) / pscale);
    match s.kind {
        PhaseKind::Stick => {
            assert_eq!(s.velocity_after.xy(), Vec2::zeros());
            r.max(direct.xy().norm() / vscale)
        }
        PhaseKind::Slip { to, .. } => {
            // p_t = −μ p_n v̂_t⁺ for the reported v_t⁺, and the slip direction is `to`.
            let vt = s.velocity_after.xy();
            assert!(vt.norm() > 0.0, "{s:?}");
            let along = vt / vt.norm();
            let sh = Vec2::new(to.cos(), to.sin());
            r.max((pt + mu * pn * along).norm() / pscale)
                .max((along - sh).norm())
                .max((sh.x * direct.y - sh.y * direct.x).abs() / vscale)
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_issue_problem_has_its_solution() {
    let p = ContactProblem::from_upper(
        [
            614327.3694481789,
            341336.2451532919,
            347013.5943548623,
            189656.59358945338,
            192810.08142403685,
            196018.03696236789,
        ],
        [1.0, 0.12097437381250864, -1e-9],
        1.0598928366735887,
        0.9615509061531089,
    )
    .unwrap();
    let sols = solutions(&p);
    assert_eq!(sols.len(), 1, "{sols:?}");
    let s = sols[0];
    let r = residual(&p, &s);
    assert!(r <= 1e-12, "residual {r:e}: {s:?}");
    // The solution in 60-digit arithmetic (mpmath: the root of F, p_n = N / D there).
    let want = Vec3::new(
        -0.321_013_825_700_473_15,
        0.209_871_826_278_980_47,
        0.361_858_320_181_445_2,
    );
    let PhaseKind::Slip { to, .. } = s.kind else {
        panic!("{s:?}")
    };
    assert!(
        (to.to_degrees() + 33.175_782_270_746_37).abs() <= 1e-10,
        "slip angle {}°",
        to.to_degrees()
    );
    // The last bit of the angle moves p_n by 4e5 · 1e-15 relative (|f'/f|·δθ).
    assert!(
        (s.impulse - want).norm() <= 1e-9 * want.norm(),
        "{:?} vs {want:?}",
        s.impulse
    );
    // v_t⁺ = u + p_n g: the error of p_n times |g| = 2.7, beside |v_t⁺| = 0.046.
    let vt = Vec2::new(0.038_379_839_189_389_14, -0.025_091_900_404_583_76);
    assert!(
        (s.velocity_after.xy() - vt).norm() <= 2e-8 * vt.norm(),
        "{:?} vs {vt:?}",
        s.velocity_after
    );
    let o = LawId::Lcp.resolve(&p).unwrap();
    assert_eq!(o.impulse, s.impulse);
    // Compression ends where v_n = 0 on the straight path: p_c = p_n/(1+e).
    let pc = o.compression_impulse.unwrap();
    assert!((pc - want.z / (1.0 + p.restitution())).abs() <= 1e-9 * pc);
    // ΔT = ½ (v⁻ + v⁺)·p = v⁻·p + ½ pᵀWp to the size of the terms of the latter.
    let pa = o.impulse.abs();
    let terms = p.velocity().abs().dot(&pa) + 0.5 * pa.dot(&(p.w().abs() * pa));
    assert!((o.energy_change - p.energy_change(o.impulse)).abs() <= 1e-12 * terms);
    assert!(o.energy_change < 0.0);
}

/// Grazing (`|v_n⁻|` from 1e-12 to 1e-3 of the slip) and strongly coupled (`W` one large
/// eigenvalue, 1e3 to 1e8 times the others, in a random direction: the issue's problem has
/// eigenvalues (1, 1, 1e6)): every problem has a solution, and every solution satisfies the
/// conditions.
#[test]
fn grazing_strongly_coupled_problems_always_have_a_solution() {
    let mut rng = SplitMix64(0x9A2_1A6);
    let mut worst = 0.0f64;
    let mut slips = 0;
    for _ in 0..20_000 {
        let big = rng.decades(3.0, 8.0);
        let lambda = Vec3::new(rng.range(0.5, 2.0), rng.range(0.5, 2.0), big);
        let q = rotation(&mut rng);
        let w = q * Mat3::from_diagonal(&lambda) * q.transpose();
        let w = 0.5 * (w + w.transpose());
        let phi = rng.range(0.0, std::f64::consts::TAU);
        let m = rng.range(0.1, 2.0);
        let v = Vec3::new(m * phi.cos(), m * phi.sin(), -m * rng.decades(-12.0, -3.0));
        let Ok(p) = ContactProblem::new(w, v, rng.range(0.05, 2.0), rng.unit()) else {
            panic!("condition {big:e} refused: {w:?}");
        };
        let sols = solutions(&p);
        assert!(!sols.is_empty(), "no solution for {p:?}");
        for s in &sols {
            let r = residual(&p, s);
            worst = worst.max(r);
            assert!(r <= 1e-12, "residual {r:e} for {p:?}: {s:?}");
            slips += usize::from(matches!(s.kind, PhaseKind::Slip { .. }));
        }
        match LawId::Lcp.resolve(&p) {
            Ok(o) => assert_eq!(o.impulse, sols[0].impulse),
            Err(b) => assert_ne!(b.reason, BreakdownReason::NoSolution, "{p:?}"),
        }
    }
    eprintln!("20,000 grazing strongly coupled problems: {slips} slip solutions, worst residual {worst:e}");
    assert!(slips > 5_000, "{slips}");
}
