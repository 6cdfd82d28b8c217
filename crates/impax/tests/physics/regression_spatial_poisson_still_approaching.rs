//! Regression: spatial `poisson` ended with the bodies still approaching after a jamb.
//!
//! Bug: after a second compression (jamb: `v_n` falls back below zero after the end of the
//! first compression, Batlle 1996), `poisson` ended at `p_f = (1+e) p_c` even where `v_n`
//! was still negative there, with verdict `consistent`. 6 of 100,000 random problems, e.g.
//!
//! ```text
//! impax resolve --w 1.2008324287749725,0.7591989489860935,0.403401879441061,\
//!   1.4497343144842805,0.22396419839288853,1.1040311283093813 \
//!   --v -0.3175701672458717,-0.9220617217576841,-0.1422905376691409 \
//!   --friction 19.512088227010317 --restitution 1 --law poisson
//! poisson  p_n = 0.046504  v_n+ = -0.013729  consistent
//! ```
//!
//! (compression ends at 0.023252, `v_n` returns to zero at 0.036430, the slip halts at
//! 0.044084 with `v_n = −0.016` and sticks; `(1+e) p_c = 0.046504` falls in the second
//! compression). Found by an adversarial run for issue 17.
//!
//! Expected: an impact cannot end while the bodies approach. Poisson's hypothesis relates
//! the impulse of restitution to that of compression (`P_r = e P_c`; Stronge, *Impact
//! Mechanics*, 2000, treats it through a second compression): with several compression
//! phases the compression impulse is the whole impulse during which `v_n < 0`, the
//! restitution impulse the impulse during which `v_n ≥ 0`, and the impact ends at the
//! first point where `P_r = e P_c` — which is always reached with `v_n ≥ 0`, as `P_r` grows
//! only there. Here: the second compression lasts until stick brings `v_n` back to zero at
//! `p_3`, `P_c = p_c + (p_3 − p_2)`, and the impact ends at `p_f = P_r + P_c = (1 + e) P_c`
//! with `v_n⁺ = 0.0332 > 0`. `newton` (`v_n⁺ = −e v_n⁻`) and `energetic` (its termination
//! `W_n = (1 − e²) W_c` is reached only while `W_n` grows, `v_n > 0`) cannot end approaching.
//! Should an integration ever end with `v_n⁺ < 0` beyond round-off, the outcome carries the
//! inconsistency `still-approaching` instead of the verdict `consistent`.
//!
//! Checked: the issue's problem against the closed form of its last phase (the stick slope
//! `det W / det W_tt` computed here); over 100,000 random problems (jamb-prone: `μ` up to 20)
//! no Darboux–Keller law ends with `v_n⁺` below minus the round-off of `v⁻ + W p` without
//! that flag, and Poisson's end satisfies `P_r = e P_c` along the path where it jammed.

use impax::math::SplitMix64;
use impax::planar::{Inconsistency, Verdict};
use impax::spatial::laws::hodograph;
use impax::spatial::{ContactProblem, LawDetail, Outcome};
use impax::LawId;

const DK: [LawId; 3] = [LawId::Newton, LawId::Poisson, LawId::Energetic];

fn issue_problem() -> ContactProblem {
    ContactProblem::from_upper(
        [
            1.2008324287749725,
            0.7591989489860935,
            0.403401879441061,
            1.4497343144842805,
            0.22396419839288853,
            1.1040311283093813,
        ],
        [
            -0.3175701672458717,
            -0.9220617217576841,
            -0.1422905376691409,
        ],
        19.512088227010317,
        1.0,
    )
    .unwrap()
}

/// `16 ε (|v_n⁻| + (|W| |p|)_n)`: the round-off of `v_n⁻ + (W p)_n`.
fn round_off(p: &ContactProblem, o: &Outcome) -> f64 {
    16.0 * f64::EPSILON * (p.velocity().z.abs() + (p.w().abs() * o.impulse.abs()).z)
}

/// The compression impulse `P_c` (where `v_n < 0`) along the sampled path of a law, each
/// crossing of zero located by linear interpolation between samples (exact on the linear
/// stages).
fn compression_along(path: &[[f64; 4]]) -> f64 {
    let mut c = 0.0;
    for w in path.windows(2) {
        let ([p0, .., v0], [p1, .., v1]) = (w[0], w[1]);
        if v0 < 0.0 && v1 < 0.0 {
            c += p1 - p0;
        } else if v0 < 0.0 || v1 < 0.0 {
            let z = p0 + (p1 - p0) * v0 / (v0 - v1);
            c += if v0 < 0.0 { z - p0 } else { p1 - z };
        }
    }
    c
}

#[test]
fn the_issue_problem_ends_separating() {
    let p = issue_problem();
    let o = LawId::Poisson.resolve(&p).unwrap();
    assert_eq!(o.verdict, Verdict::Consistent);
    assert!(o.velocity_after.z > 0.0, "v_n⁺ = {}", o.velocity_after.z);
    let LawDetail::DarbouxKeller {
        slip_halt: Some(halt),
        second_compression: Some(p2),
        ..
    } = o.detail
    else {
        panic!("{:?}", o.detail)
    };
    let pc = o.compression_impulse.unwrap();
    assert!(pc < p2 && p2 < halt && halt < o.impulse.z, "{o:?}");
    // After the halt: stick, v_n linear with the slope det W / det W_tt.
    let w = p.w();
    let slope = w.determinant() / (w[(0, 0)] * w[(1, 1)] - w[(0, 1)] * w[(1, 0)]);
    let pf = o.impulse.z;
    let p3 = pf - o.velocity_after.z / slope;
    assert!(
        halt < p3 && p3 < pf,
        "the second compression ends in stick: {p3}"
    );
    // P_c = p_c + (p3 − p2), P_r = p_f − P_c = e P_c (e = 1).
    let compression = pc + (p3 - p2);
    let e = p.restitution();
    assert!(
        ((pf - compression) - e * compression).abs() <= 1e-12 * pf,
        "P_r = {} vs e P_c = {}",
        pf - compression,
        e * compression
    );
    assert!(
        (pf - 0.095_032_610_066_964_48).abs() <= 1e-10 * pf,
        "p_n = {pf}"
    );
    assert!((o.velocity_after.z - 0.033_223_270_308_522_72).abs() <= 1e-10);
    // The same along the sampled path.
    let path = hodograph(&p, LawId::Poisson, &impax::law::Options::default()).unwrap();
    let along = compression_along(&path);
    assert!(
        (along - compression).abs() <= 1e-12 * pf,
        "{along} vs {compression}"
    );
    // newton and energetic end separating too.
    for law in [LawId::Newton, LawId::Energetic] {
        let o = law.resolve(&p).unwrap();
        assert!(o.velocity_after.z >= 0.0, "{law}: {}", o.velocity_after.z);
        assert_eq!(o.inconsistency, None);
    }
}

#[test]
fn the_new_inconsistency_has_an_id_and_a_message() {
    let i = Inconsistency::StillApproaching {
        normal_velocity: -0.0137,
    };
    assert_eq!(i.id(), "still-approaching");
    assert!(i.to_string().contains("still approaching"), "{i}");
    assert!(i.to_string().contains("-1.37"), "{i}");
}

/// A random problem: `W = L Lᵀ + δ I` (coupled, anisotropic), `v_t⁻` of every size and
/// direction, `μ` up to 20 (a high friction makes jamb frequent), `e ∈ [0, 1]`.
fn random_problem(rng: &mut SplitMix64) -> ContactProblem {
    loop {
        let mut l = [[0.0; 3]; 3];
        for (i, row) in l.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate().take(i + 1) {
                *x = if i == j {
                    rng.range(0.2, 2.0)
                } else {
                    rng.range(-1.5, 1.5)
                };
            }
        }
        let d = rng.decades(-3.0, 0.0);
        let w = |i: usize, j: usize| {
            (0..3).map(|k| l[i][k] * l[j][k]).sum::<f64>() + if i == j { d } else { 0.0 }
        };
        let phi = rng.range(0.0, std::f64::consts::TAU);
        let m = rng.decades(-2.0, 1.0);
        let v = [m * phi.cos(), m * phi.sin(), -rng.decades(-2.0, 0.5)];
        let mu = if rng.unit() < 0.5 {
            rng.range(0.0, 2.0)
        } else {
            rng.decades(0.0, 1.3)
        };
        let e = if rng.unit() < 0.2 { 1.0 } else { rng.unit() };
        let upper = [w(0, 0), w(0, 1), w(0, 2), w(1, 1), w(1, 2), w(2, 2)];
        if let Ok(p) = ContactProblem::from_upper(upper, v, mu, e) {
            return p;
        }
    }
}

#[test]
fn no_darboux_keller_law_ends_approaching_unflagged() {
    let mut rng = SplitMix64(0x4A3B);
    let (mut jammed, mut extended) = (0, 0);
    let mut worst = 0.0f64;
    for _ in 0..100_000 {
        let p = random_problem(&mut rng);
        for law in DK {
            let Ok(o) = law.resolve(&p) else {
                continue;
            };
            let vn = o.velocity_after.z;
            if vn < -round_off(&p, &o) {
                assert!(
                    matches!(
                        o.inconsistency,
                        Some(Inconsistency::StillApproaching { .. })
                    ) && o.verdict != Verdict::Consistent,
                    "{law}: v_n⁺ = {vn:e} unflagged for {p:?}"
                );
            }
            let LawDetail::DarbouxKeller {
                second_compression: Some(_),
                ..
            } = o.detail
            else {
                continue;
            };
            if law != LawId::Poisson {
                continue;
            }
            jammed += 1;
            // Poisson: P_r = e P_c along the path (the compression impulse of every phase).
            let pc = o.compression_impulse.unwrap();
            let pf = o.impulse.z;
            let e = p.restitution();
            if pf > (1.0 + e) * pc * (1.0 + 1e-9) {
                extended += 1;
                let path = hodograph(&p, law, &impax::law::Options::default()).unwrap();
                let c = compression_along(&path);
                worst = worst.max(((pf - c) - e * c).abs() / pf);
                // (Every crossing of v_n = 0 is an event, hence a sample of the path.)
                assert!(
                    ((pf - c) - e * c).abs() <= 1e-12 * pf,
                    "P_r = {} vs e P_c = {} for {p:?}",
                    pf - c,
                    e * c
                );
            }
        }
    }
    eprintln!(
        "100,000 problems: poisson jammed in {jammed}, extended past (1+e) p_c in {extended}, \
         largest |P_r − e P_c| / p_n {worst:e}"
    );
    assert!(jammed >= 20 && extended >= 5, "{jammed}, {extended}");
}
