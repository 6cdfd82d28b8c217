//! Regression: a slip far below or far above the normal velocity broke the spatial
//! Darboux–Keller laws.
//!
//! Bug, found by an adversarial run for issue 17:
//!
//! ```text
//! impax resolve --w 1,0,0,1,0,1 --v 0,1e-200,-1 --friction 0.5 --restitution 0.6
//! impax resolve --w 3.5,0,0,3.5,0,1 --v 0.5,0,-1e-300 --friction 0.4 --restitution 0.7
//! ```
//!
//! gave `no-separation` for `newton`, `poisson` and `energetic` (after ≈ 60 ms each: the
//! step budget), where a slip of 0 and the planar laws (and spatial `whittaker`, `brach`,
//! `lcp`) resolve them: the first is the zero-slip result (`p_n = 1.6`, stick), the second
//! `v_n⁺ = −e v_n⁻ = 7e-301` (with `w_tn = 0` and an isotropic `W_tt` the slip keeps its
//! direction and the three terminations coincide). The integration runs in units where
//! `v_n⁻` and `w_nn` are near one, so the first slip is 1e-200 there and the second
//! 3.3e299: `|v_t|` was formed as `√(v_1² + v_2²)`, whose squares under- or overflow
//! (`σ = 0`, then `ŝ = v_t/σ` is NaN). Behind that, the error control used one velocity
//! scale `|v⁻|` and one impulse scale (which grew with the slip's halting impulse) for
//! every component: with a slip 1e6–1e20 times the normal velocity, `v_n` was controlled
//! to `rtol |v_t|` only and the first step leapt over the impact — the impulses of
//! `newton`, `poisson`, `energetic` at the default tolerance and at 1e-14 differed by up to
//! 600 times their size (`v_t⁻ = (cos φ, sin φ)`, `v_n⁻ ≈ −1e-19`), verdict `consistent`;
//! and `u = ln σ` was entered for a slip that shrinks by a few parts in 1e15 over the
//! impact, below the resolution of `u` itself.
//!
//! Expected: the slip speed without under- or overflow; each quantity controlled on its own
//! scale (tangential velocity `σ⁻ + |g|_max p`, normal velocity `|v_n⁻|`, impulse
//! `(1+e)|v_n⁻|/w_nn`, works their products); `ln σ` only for a slip that shrinks
//! appreciably before the next event. Then:
//!
//! * slips of `10^-k` (`k = 20 … 300`) in random directions give the zero-slip result to
//!   round-off where stick is stable (the slip halts within an impulse far below round-off
//!   of the impulse scale);
//! * a slip `10^k` times the normal velocity (`k = 20 … 300`, direction change over the
//!   impact below round-off) gives the slip-throughout closed form (Whittaker's impulse,
//!   the three terminations coinciding on a straight path) to 1e-12, and the default
//!   tolerance agrees with 1e-14 for every ratio from 1 to 1e20;
//! * every spatial law is invariant under `v → s_v v`, `W → s_w W` (the planar
//!   `regression_scale_invariance.rs` mirrored): impulses scale by `s_v/s_w`, velocities by
//!   `s_v`, works by `s_v²/s_w`; bit for bit for powers of two, to 1e-9 of each quantity's
//!   scale for factors from 1e-300 to 1e300.

use impax::law::Options;
use impax::math::{Mat3, SplitMix64, Vec3};
use impax::spatial::{sticking_ratio, ContactProblem, Outcome, Resolution};
use impax::LawId;

const DK: [LawId; 3] = [LawId::Newton, LawId::Poisson, LawId::Energetic];
const LAWS: [LawId; 6] = LawId::SPATIAL;

/// `L Lᵀ + δ I`: coupled and anisotropic.
fn random_w(rng: &mut SplitMix64) -> Mat3 {
    let mut l = Mat3::zeros();
    for i in 0..3 {
        for j in 0..=i {
            l[(i, j)] = if i == j {
                rng.range(0.3, 2.0)
            } else {
                rng.range(-1.0, 1.0)
            };
        }
    }
    l * l.transpose() + Mat3::identity() * rng.decades(-2.0, 0.0)
}

/// The size of the terms of `v⁻ + W p` (its round-off scale), per component.
fn velocity_scale(p: &ContactProblem, o: &Outcome) -> f64 {
    (p.velocity().abs() + p.w().abs() * o.impulse.abs()).max()
}

#[test]
fn the_issue_cases() {
    let law_results = |p: &ContactProblem| DK.map(|law| law.resolve(p));
    // A slip of 1e-200: the zero-slip result.
    let w = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0];
    let tiny = ContactProblem::from_upper(w, [0.0, 1e-200, -1.0], 0.5, 0.6).unwrap();
    let zero = ContactProblem::from_upper(w, [0.0, 0.0, -1.0], 0.5, 0.6).unwrap();
    for (a, b) in law_results(&tiny).iter().zip(law_results(&zero)) {
        let (a, b) = (a.as_ref().unwrap(), b.unwrap());
        assert!(
            (a.impulse - b.impulse).norm() <= 1e-15 * b.impulse.norm(),
            "{a:?}"
        );
        assert!(
            (a.velocity_after - b.velocity_after).norm() <= 1e-15,
            "{a:?}"
        );
        assert!((a.impulse.z - 1.6).abs() <= 1e-15 * 1.6);
    }
    // A grazing impact: v_n⁺ = −e v_n⁻ = 7e-301, and Whittaker's impulse.
    let grazing = ContactProblem::from_upper(
        [3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
        [0.5, 0.0, -1e-300],
        0.4,
        0.7,
    )
    .unwrap();
    let wh = LawId::Whittaker.resolve(&grazing).unwrap();
    for (law, o) in DK.iter().zip(law_results(&grazing)) {
        let o = o.unwrap();
        assert!(
            (o.velocity_after.z - 7e-301).abs() <= 1e-15 * 7e-301,
            "{law}: v_n⁺ = {:e}",
            o.velocity_after.z
        );
        assert!((o.impulse - wh.impulse).norm() <= 1e-15 * wh.impulse.norm());
    }
}

#[test]
fn tiny_slips_give_the_zero_slip_result_where_stick_is_stable() {
    let mut rng = SplitMix64(0x71_4E);
    let mut compared = 0;
    for _ in 0..200 {
        let w = random_w(&mut rng);
        let vn = -rng.range(0.1, 2.0);
        let probe = ContactProblem::new(w, Vec3::new(0.0, 0.0, vn), 1.0, 0.5).unwrap();
        // Stick stable: μ above the sticking ratio.
        let mu = sticking_ratio(&probe).norm() * rng.range(1.01, 3.0) + 0.01;
        let e = rng.unit();
        let zero = ContactProblem::new(w, Vec3::new(0.0, 0.0, vn), mu, e).unwrap();
        let base = DK.map(|law| law.resolve(&zero).unwrap());
        for k in (20..=300).step_by(10) {
            let phi = rng.range(0.0, std::f64::consts::TAU);
            let s = 10f64.powi(-k);
            let p =
                ContactProblem::new(w, Vec3::new(s * phi.cos(), s * phi.sin(), vn), mu, e).unwrap();
            for (law, b) in DK.iter().zip(&base) {
                let a = law
                    .resolve(&p)
                    .unwrap_or_else(|x| panic!("{law} at slip 1e-{k}: {x} for {p:?}"));
                let tol = 4.0 * f64::EPSILON;
                assert!(
                    (a.impulse - b.impulse).norm() <= tol * b.impulse.norm(),
                    "{law} at slip 1e-{k}: {:?} vs zero slip {:?}",
                    a.impulse,
                    b.impulse
                );
                assert!(
                    (a.velocity_after - b.velocity_after).abs().max()
                        <= tol * velocity_scale(&zero, b),
                    "{law} at slip 1e-{k}: {:?} vs {:?}",
                    a.velocity_after,
                    b.velocity_after
                );
                assert!(
                    (a.energy_change - b.energy_change).abs() <= tol * b.energy_change.abs(),
                    "{law} at slip 1e-{k}"
                );
                assert_eq!(a.verdict, b.verdict);
                compared += 1;
            }
        }
    }
    assert_eq!(compared, 200 * 29 * 3);
}

#[test]
fn slips_far_above_the_normal_velocity_are_resolved_accurately() {
    let mut rng = SplitMix64(0x05EE_DB16);
    let mut rigid = 0;
    for _ in 0..100 {
        let w = random_w(&mut rng);
        let (mu, e) = (rng.range(0.0, 2.0), rng.unit());
        for k in 0..=300 {
            let phi = rng.range(0.0, std::f64::consts::TAU);
            let vn = -10f64.powi(-k) * rng.range(0.1, 2.0);
            let p = ContactProblem::new(w, Vec3::new(phi.cos(), phi.sin(), vn), mu, e).unwrap();
            for law in DK {
                let a = law
                    .resolve(&p)
                    .unwrap_or_else(|x| panic!("{law} at ratio 1e{k}: {x} for {p:?}"));
                if k <= 20 {
                    // The default tolerance against 1e-14.
                    let b = law
                        .resolve_with(&p, &Options::default().rtol(1e-14))
                        .unwrap();
                    assert!(
                        (a.impulse - b.impulse).norm() <= 1e-10 * b.impulse.norm(),
                        "{law} at ratio 1e{k}: {:?} vs {:?} for {p:?}",
                        a.impulse,
                        b.impulse
                    );
                    assert!(
                        (a.velocity_after - b.velocity_after).abs().max()
                            <= 1e-10 * velocity_scale(&p, &b),
                        "{law} at ratio 1e{k}: {:?} vs {:?} for {p:?}",
                        a.velocity_after,
                        b.velocity_after
                    );
                }
                // Where the slip cannot turn over the impact (|dv_t/dp_n| ≤ G over Whittaker's
                // straight path, G p_f below round-off of σ⁻ = 1), the path is that
                // straight one: Whittaker's impulse.
                let Ok(wh) = LawId::Whittaker.resolve(&p) else {
                    continue;
                };
                let g = p.wtn().norm() + p.friction() * p.wtt().norm();
                if 4.0 * g * wh.impulse.z <= f64::EPSILON {
                    assert!(
                        (a.impulse - wh.impulse).norm() <= 1e-12 * wh.impulse.norm(),
                        "{law} at ratio 1e{k}: {:?} vs {:?}",
                        a.impulse,
                        wh.impulse
                    );
                    rigid += 1;
                }
            }
        }
    }
    assert!(rigid > 20_000, "{rigid}");
}

// ---- Scale invariance (mirrors tests/regression_scale_invariance.rs) ----

fn random_problem(rng: &mut SplitMix64) -> Option<ContactProblem> {
    let w = random_w(rng);
    let phi = rng.range(0.0, std::f64::consts::TAU);
    let m = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.decades(-3.0, 1.0)
    };
    let v = Vec3::new(m * phi.cos(), m * phi.sin(), -rng.decades(-2.0, 0.3));
    let mu = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.range(0.0, 2.0)
    };
    ContactProblem::new(w, v, mu, rng.unit()).ok()
}

fn scaled(p: &ContactProblem, sv: f64, sw: f64) -> Option<ContactProblem> {
    ContactProblem::new(p.w() * sw, p.velocity() * sv, p.friction(), p.restitution()).ok()
}

/// Whether `x · k` stays a normal number (or zero) with room to spare.
fn representable(x: f64, k: f64) -> bool {
    x == 0.0 || (1e-290..1e290).contains(&(x.abs() * k))
}

/// Every number of the outcome, scaled by the change of units, is representable.
fn fits(o: &Outcome, kp: f64, kv: f64) -> bool {
    let kw = kp * kv;
    o.impulse.iter().all(|&x| representable(x, kp))
        && o.velocity_after.iter().all(|&x| representable(x, kv))
        && [
            o.work.compression,
            o.work.restitution,
            o.work.friction,
            o.energy_change,
        ]
        .iter()
        .all(|&x| representable(x, kw))
}

/// `b` is `a` in the scaled units, exactly (`tol = 0`) or to `tol` of each quantity's scale.
#[allow(clippy::too_many_arguments)]
fn agree(
    law: LawId,
    p: &ContactProblem,
    a: &Resolution,
    b: &Resolution,
    kp: f64,
    kv: f64,
    tol: f64,
) {
    let kw = kp * kv;
    let close = |x: f64, y: f64, scale: f64| {
        if tol == 0.0 {
            x == y
        } else {
            (x - y).abs() <= tol * scale
        }
    };
    match (a, b) {
        (Ok(x), Ok(y)) => {
            let ps = x.impulse.abs().max() * kp;
            let vs = velocity_scale(p, x) * kv;
            let ws = x
                .work
                .compression
                .abs()
                .max(x.work.friction.abs())
                .max(x.work.restitution.abs())
                .max(x.energy_change.abs())
                * kw;
            for (u, w) in x.impulse.iter().zip(y.impulse.iter()) {
                assert!(close(u * kp, *w, ps), "{law}: impulse {x:?} vs {y:?}");
            }
            for (u, w) in x.velocity_after.iter().zip(y.velocity_after.iter()) {
                assert!(close(u * kv, *w, vs), "{law}: velocity {x:?} vs {y:?}");
            }
            assert!(
                close(x.energy_change * kw, y.energy_change, ws),
                "{law}: ΔT {x:?} vs {y:?}"
            );
            assert!(close(x.work.compression * kw, y.work.compression, ws));
            assert!(close(x.work.restitution * kw, y.work.restitution, ws));
            assert!(close(x.work.friction * kw, y.work.friction, ws));
            assert_eq!(x.verdict, y.verdict, "{law}: {x:?} vs {y:?}");
            let (fa, fb) = (x.phases.as_slice(), y.phases.as_slice());
            assert_eq!(fa.len(), fb.len(), "{law}: {x:?} vs {y:?}");
            for (u, w) in fa.iter().zip(fb) {
                assert!(close(u.ends_at * kp, w.ends_at, ps), "{law}: phases");
            }
        }
        (Err(x), Err(y)) => assert_eq!(x.reason.id(), y.reason.id(), "{law}"),
        _ => panic!("{law}: {a:?} vs {b:?} for {p:?}"),
    }
}

#[test]
fn powers_of_two_scale_every_spatial_law_exactly() {
    let mut rng = SplitMix64(41);
    let mut compared = 0;
    for _ in 0..1500 {
        let Some(p) = random_problem(&mut rng) else {
            continue;
        };
        let (i, j) = (
            rng.range(-1000.0, 1000.0) as i32,
            rng.range(-1000.0, 1000.0) as i32,
        );
        let (sv, sw) = (2f64.powi(i), 2f64.powi(j));
        let (kp, kv) = (sv / sw, sv);
        let Some(q) = scaled(&p, sv, sw) else {
            continue;
        };
        for law in LAWS {
            let a = law.resolve(&p);
            if a.as_ref().is_ok_and(|o| !fits(o, kp, kv)) {
                continue;
            }
            agree(law, &p, &a, &law.resolve(&q), kp, kv, 0.0);
            compared += 1;
        }
    }
    assert!(compared > 2000, "{compared}");
}

#[test]
fn any_factor_from_1e_minus_300_to_1e300_scales_every_spatial_law() {
    let mut rng = SplitMix64(42);
    let mut compared = 0;
    for _ in 0..1500 {
        let Some(p) = random_problem(&mut rng) else {
            continue;
        };
        let (sv, sw) = (rng.decades(-300.0, 300.0), rng.decades(-300.0, 300.0));
        let (kp, kv) = (sv / sw, sv);
        let Some(q) = scaled(&p, sv, sw) else {
            continue;
        };
        for law in LAWS {
            let a = law.resolve(&p);
            if a.as_ref().is_ok_and(|o| !fits(o, kp, kv)) {
                continue;
            }
            // Scaling by a decimal factor rounds W and v once: the result moves by that
            // round-off times the problem's conditioning.
            agree(law, &p, &a, &law.resolve(&q), kp, kv, 1e-9);
            compared += 1;
        }
    }
    assert!(compared > 2000, "{compared}");
}
