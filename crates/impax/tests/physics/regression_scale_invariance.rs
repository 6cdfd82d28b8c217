//! Regression: the laws were not invariant under scaling of the velocities and of `W`.
//!
//! Found by an adversarial run: `energetic` lost its restitution for `|v_n⁻| ≲ 1e-155`
//! (`--w 3.5,0,1 --v 0.5,-1e-300 --friction 0.4 --restitution 0.7 --law energetic` gave
//! `v_n⁺ = 0` where `newton` and `poisson` give `7e-301`: the compression work `∝ v_n²`
//! underflowed); scaling 20,000 random problems to `|v| ≈ 1e-200` made every energetic impulse
//! wrong (by up to 92 %) with verdict `consistent`; `smith` was off by up to 27 % at 1e-160.
//!
//! Expected: every planar law is invariant under `v → s_v v`, `W → s_w W` (a change of the
//! units of velocity and of mass) wherever the numbers are representable: the impulse scales
//! by `s_v/s_w`, velocities by `s_v`, works and `ΔT` by `s_v²/s_w`, and the verdict, phases and
//! breakdowns are the same. For powers of two the results are identical to the last bit (the
//! laws work in units where `v_n⁻` and `W_nn` are near one, scaled by powers of two); for any
//! other factor, to round-off. Scales from 1e-300 to 1e300.

use impax::math::{Mat2, SplitMix64, Vec2};
use impax::planar::{ContactProblem, Outcome, Resolution};
use impax::LawId;

const LAWS: [LawId; 8] = LawId::CONTACT_SPACE;

fn random_problem(rng: &mut SplitMix64) -> Option<ContactProblem> {
    let (l11, l22) = (rng.decades(-1.0, 1.0), rng.decades(-1.0, 1.0));
    let l21 = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.range(-1.0, 1.0) * rng.decades(-1.0, 1.0)
    };
    let w = Mat2::new(l11 * l11, l11 * l21, l11 * l21, l21 * l21 + l22 * l22);
    let vt = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.range(-2.0, 2.0)
    };
    let v = Vec2::new(vt, -rng.decades(-2.0, 0.3));
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
            // v⁺ = v⁻ + W p: its round-off is on the scale of its terms.
            let vs = (p.velocity().abs() + p.w().abs() * x.impulse.abs()).max() * kv;
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
            assert_eq!(fa.len(), fb.len(), "{law}");
            for (u, w) in fa.iter().zip(fb) {
                assert_eq!(u.kind, w.kind, "{law}");
                assert!(close(u.ends_at * kp, w.ends_at, ps), "{law}: phases");
            }
        }
        (Err(x), Err(y)) => assert_eq!(x.reason.id(), y.reason.id(), "{law}"),
        _ => panic!("{law}: {a:?} vs {b:?}"),
    }
}

#[test]
fn the_issue_cases() {
    // A grazing impact: v_n⁻ = −1e-300 with v_t⁻ = 0.5.
    let p = ContactProblem::from_entries(3.5, 0.0, 1.0, 0.5, -1e-300, 0.4, 0.7).unwrap();
    for law in LAWS {
        let o = law.resolve(&p).unwrap();
        // W_tn = 0: the slip never halts within the impact and v_n⁺ = −e v_n⁻.
        assert!(
            (o.velocity_after.y - 7e-301).abs() <= 1e-15 * 7e-301,
            "{law}: v_n⁺ = {:e}",
            o.velocity_after.y
        );
    }
    // The seed's problem at 1e-200 of its speed, and smith at 1e-160.
    let a = 30f64.to_radians();
    let seed = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
    for (s, law) in [(1e-200, LawId::Energetic), (1e-160, LawId::Smith)] {
        let small = scaled(&seed, s, 1.0).unwrap();
        let (x, y) = (law.resolve(&seed), law.resolve(&small));
        agree(law, &seed, &x, &y, s, s, 1e-15);
    }
}

#[test]
fn powers_of_two_scale_every_law_exactly() {
    let mut rng = SplitMix64(31);
    let mut compared = 0;
    for _ in 0..3000 {
        let Some(p) = random_problem(&mut rng) else {
            continue;
        };
        let (i, j) = (
            (rng.range(-1000.0, 1000.0)) as i32,
            (rng.range(-1000.0, 1000.0)) as i32,
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
    assert!(compared > 4000, "{compared}");
}

#[test]
fn any_factor_from_1e_minus_300_to_1e300_scales_every_law() {
    let mut rng = SplitMix64(32);
    let mut compared = 0;
    for _ in 0..3000 {
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
    assert!(compared > 4000, "{compared}");
}

/// Found by fuzzing the scaled laws: with `W_nn = 6.4e-232` the law works in units where the
/// numbers are fine, but back in the problem's units the friction work `∝ W_tt p_t²`
/// overflows; the result was an outcome holding an infinity.
#[test]
fn a_result_that_overflows_in_the_problems_units_is_the_overflow_breakdown() {
    let p = ContactProblem::from_entries(3.5, 0.0, 6.441148769597133e-232, 0.5, -0.866, 0.4, 0.7)
        .unwrap();
    for law in LAWS {
        match law.resolve(&p) {
            Ok(o) => assert!(o.is_finite(), "{law}: {o:?}"),
            Err(b) => assert_eq!(b.reason.id(), "overflow", "{law}"),
        }
    }
    let o = LawId::Whittaker.resolve(&p);
    assert_eq!(o.unwrap_err().reason.id(), "overflow");
}
