//! The planar engine rule `lcp` (velocity-level complementarity impact).
//!
//! Checked against independent derivations, not against its own enumeration:
//!
//! * on 200,000 random problems (`W = L Lᵀ + δ I` over two decades, `W_tn` of both signs and
//!   sometimes 0, `v_t` sometimes exactly 0, `μ ∈ [0, 2]` with 0 and 2, `e ∈ [0, 1]` with 0
//!   and 1) the returned impulse satisfies the complementarity conditions to 1e-12
//!   (Newton's target, the cone, stick or friction against the final slip);
//! * it equals the minimiser of the strictly convex problem `min ½ s p_t² + v* p_t` over the
//!   cone interval (computed here in closed form by clamping, the uniqueness proof of the
//!   law's rustdoc) and Brach's rule (the identity in the plane), to 1e-12;
//! * at most two of the three candidates pass their exact tests, and two only with the same
//!   impulse (uniqueness);
//! * it equals Darboux–Keller `newton` whenever `newton`'s slip does not reverse (slip
//!   throughout, or slip then stick), and differs when it reverses;
//! * mirror symmetry, frictionless `p_n = −(1+e) v_n⁻/W_nn`, and the audit's rod (`impax audit rod`)
//!   (`T⁺/T⁻ = 1.183466`, from the hand-derived sticking impulse).

use impax::math::SplitMix64;
use impax::planar::laws::{ImpactLaw, Lcp};
use impax::planar::{ContactProblem, LawDetail, PhaseKind, SlipDirection, Verdict};
use impax::LawId;

fn random_problem(rng: &mut SplitMix64) -> ContactProblem {
    crate::support::random_planar(rng, -3.0)
}

/// The impulse scale of a problem: `|p|` plus the forward error of solving with `W`.
fn impulse_scale(p: &ContactProblem, imp: impax::math::Vec2) -> f64 {
    let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
    let det = a * c - b * b;
    let inv_norm = (a.abs() + b.abs()).max(b.abs() + c.abs()) / det;
    imp.norm() + inv_norm * (1.0 + p.restitution()) * p.velocity().norm()
}

/// The convex-minimisation solution: the sticking `p_t` clamped to the cone interval on
/// Newton's line (`p_n = (N − b p_t)/c`). Independent of the law's enumeration.
fn clamp_solution(p: &ContactProblem) -> (f64, f64) {
    let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
    let v = p.velocity();
    let mu = p.friction();
    let n = -(1.0 + p.restitution()) * v.y;
    let s = (a * c - b * b) / c;
    let vstar = v.x + b * n / c;
    let pstar = -vstar / s;
    // |p_t| ≤ μ (N − b p_t)/c:  p_t (c + μ b) ≤ μ N  and  −p_t (c − μ b) ≤ μ N.
    let hi = if c + mu * b > 0.0 {
        mu * n / (c + mu * b)
    } else {
        f64::INFINITY
    };
    let lo = if c - mu * b > 0.0 {
        -mu * n / (c - mu * b)
    } else {
        f64::NEG_INFINITY
    };
    let pt = pstar.clamp(lo, hi);
    (pt, (n - b * pt) / c)
}

#[test]
fn complementarity_uniqueness_and_identities_on_random_problems() {
    let mut rng = SplitMix64(0x1c9);
    let mut worst_residual = 0.0f64;
    let mut worst_clamp = 0.0f64;
    let mut worst_brach = 0.0f64;
    let (mut sticks, mut slips, mut gains, mut boundary) = (0, 0, 0, 0);
    for _ in 0..200_000 {
        let p = random_problem(&mut rng);
        let o = LawId::Lcp
            .resolve(&p)
            .expect("lcp always has a solution in the plane");
        let v = p.velocity();
        let (pt, pn) = (o.impulse.x, o.impulse.y);
        let vplus = p.velocity_after(o.impulse);
        let scale = impulse_scale(&p, o.impulse);
        let vscale = v.norm() + (p.wtt().abs() + p.wtn().abs() + p.wnn().abs()) * scale;
        // Newton's target.
        let r_n = (vplus.y + p.restitution() * v.y).abs() / vscale;
        // Cone.
        let r_cone = (pt.abs() - p.friction() * pn).max(0.0) / scale;
        assert!(pn > 0.0);
        // Stick, or friction on the cone against the final slip.
        let r_fric = match o.phases.as_slice()[0].kind {
            PhaseKind::Stick => {
                sticks += 1;
                vplus.x.abs() / vscale
            }
            PhaseKind::Slip(dir) => {
                slips += 1;
                let on_cone = (pt.abs() - p.friction() * pn).abs() / scale;
                let against = (vplus.x * pt).max(0.0) / (vscale * scale);
                if p.friction() > 0.0 {
                    assert_eq!(dir.sign() * pt.signum(), -1.0, "{p:?}");
                }
                on_cone.max(against)
            }
        };
        let residual = r_n.max(r_cone).max(r_fric);
        worst_residual = worst_residual.max(residual);
        assert!(residual < 1e-12, "residual {residual:e} for {p:?}");
        // The convex minimiser.
        let (cpt, cpn) = clamp_solution(&p);
        let d = ((pt - cpt).abs().max((pn - cpn).abs())) / scale;
        worst_clamp = worst_clamp.max(d);
        assert!(d < 1e-12, "clamp differs by {d:e} for {p:?}");
        // Brach's rule.
        let b = LawId::Brach.resolve(&p).expect("brach");
        let d = (b.impulse - o.impulse).norm() / scale;
        worst_brach = worst_brach.max(d);
        assert!(d < 1e-12, "brach differs by {d:e} for {p:?}");
        assert_eq!(b.verdict, o.verdict);
        // Uniqueness: one candidate, or two on the boundary (same impulse, checked above
        // because every passing candidate equals the clamp: the first one is returned).
        let LawDetail::Lcp {
            consistent_candidates,
            ..
        } = o.detail
        else {
            panic!("detail")
        };
        assert!(consistent_candidates <= 2);
        if consistent_candidates == 2 {
            boundary += 1;
        }
        assert_eq!(consistent_candidates, Lcp::consistent_candidates(&p));
        if o.verdict == Verdict::EnergyGained {
            gains += 1;
        }
        // ΔT identity.
        let dt = p.energy_change(o.impulse);
        assert!((dt - o.energy_change).abs() <= 1e-12 * (vscale * scale).max(1e-300));
    }
    println!(
        "lcp: 200000 problems, {sticks} stick, {slips} slip, {boundary} on the boundary, {gains} gain energy; \
         worst residual {worst_residual:.2e}, vs clamp {worst_clamp:.2e}, vs brach {worst_brach:.2e}"
    );
    assert!(sticks > 10_000 && slips > 10_000 && gains > 1000);
}

#[test]
fn equals_newton_unless_the_slip_reverses() {
    let mut rng = SplitMix64(77);
    let (mut same, mut reversed, mut reversed_differs) = (0, 0, 0);
    for _ in 0..50_000 {
        let p = random_problem(&mut rng);
        let o = LawId::Lcp.resolve(&p).unwrap();
        let Ok(n) = LawId::Newton.resolve(&p) else {
            continue;
        };
        let ph = n.phases.as_slice();
        let reverses =
            p.friction() > 0.0 && ph.len() == 2 && matches!(ph[1].kind, PhaseKind::Slip(_));
        let scale = impulse_scale(&p, n.impulse);
        let d = (n.impulse - o.impulse).norm() / scale;
        if reverses {
            reversed += 1;
            if d > 1e-9 {
                reversed_differs += 1;
            }
        } else {
            same += 1;
            assert!(d < 1e-12, "lcp ≠ newton ({d:e}) without reversal: {p:?}");
        }
    }
    println!("lcp = newton on {same} problems without reversal; differs on {reversed_differs} of {reversed} reversing ones");
    assert!(reversed > 1000 && reversed_differs == reversed);
}

#[test]
fn mirror_symmetry_and_frictionless() {
    let mut rng = SplitMix64(5);
    for _ in 0..20_000 {
        let p = random_problem(&mut rng);
        let o = LawId::Lcp.resolve(&p).unwrap();
        let m = LawId::Lcp.resolve(&p.mirrored()).unwrap();
        let scale = impulse_scale(&p, o.impulse);
        assert!((o.impulse.x + m.impulse.x).abs() < 1e-12 * scale);
        assert!((o.impulse.y - m.impulse.y).abs() < 1e-12 * scale);
        let f = LawId::Lcp
            .resolve(&p.with_coefficients(0.0, p.restitution()).unwrap())
            .unwrap();
        let pn = -(1.0 + p.restitution()) * p.velocity().y / p.wnn();
        assert_eq!(f.impulse.x, 0.0);
        assert!((f.impulse.y - pn).abs() <= 1e-14 * pn);
    }
}

/// The audit's rod (`impax audit rod`): uniform rod (m = 1, l = 1, I = 1/12) at 50° to the floor, lower end on
/// the floor, translating at (0.5, −1), μ = 0.8, e = 1. By hand: the sticking impulse is
/// `W⁻¹ (−0.5, 2)`; its ratio is inside the cone, so the engine rule sticks and
/// `T⁺ = T⁻ + ½ (v⁻ + v⁺)·p` with `v⁺ = (0, 1)`.
#[test]
fn the_audit_rod_gains_energy() {
    let th = 50f64.to_radians();
    let (rt, rn) = (-0.5 * th.cos(), -0.5 * th.sin());
    let i = 1.0 / 12.0;
    let (a, b, c) = (1.0 + rn * rn / i, -rt * rn / i, 1.0 + rt * rt / i);
    let p = ContactProblem::from_entries(a, b, c, 0.5, -1.0, 0.8, 1.0).unwrap();
    let det = a * c - b * b;
    let (pt, pn) = ((c * -0.5 - b * 2.0) / det, (-b * -0.5 + a * 2.0) / det);
    assert!(pt.abs() < 0.8 * pn);
    let t_minus = 0.5 * (0.25 + 1.0);
    let t_plus = t_minus + 0.5 * (0.5 * pt + (-1.0 + 1.0) * pn);
    let o = LawId::Lcp.resolve(&p).unwrap();
    assert!((o.impulse.x - pt).abs() < 1e-14 && (o.impulse.y - pn).abs() < 1e-14);
    let ratio = (t_minus + o.energy_change) / t_minus;
    assert!((ratio - t_plus / t_minus).abs() < 1e-14);
    assert!((ratio - 1.183466).abs() < 1e-6, "{ratio}");
    assert_eq!(o.verdict, Verdict::EnergyGained);
    assert_eq!(o.phases.summary(), "stick");
    // Darboux–Keller newton sticks too (slip+ → stick): the same impulse; energetic dissipates.
    let n = LawId::Newton.resolve(&p).unwrap();
    assert!((n.impulse - o.impulse).norm() < 1e-14);
    assert!(LawId::Energetic.resolve(&p).unwrap().energy_change < 0.0);
}

#[test]
fn slip_direction_labels() {
    // Slip throughout in the initial direction: a sphere thrown fast and low.
    let p = ContactProblem::from_entries(3.5, 0.0, 1.0, 3.0, -1.0, 0.1, 0.5).unwrap();
    let o = Lcp.resolve(&p).unwrap();
    assert_eq!(
        o.phases.as_slice()[0].kind,
        PhaseKind::Slip(SlipDirection::Positive)
    );
    assert!(o.velocity_after.x > 0.0);
    assert!((o.impulse.x + 0.1 * o.impulse.y).abs() < 1e-15);
}
