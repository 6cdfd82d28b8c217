//! Planar problems embedded in 3D agree with the planar closed form.
//!
//! `spatial::ContactProblem::from_planar(p, w22)` puts a planar problem in the `(t1, n)` plane with a
//! decoupled second tangent. Nothing can then happen along `t2`, so every 3D law must give
//! the planar law's result (`LawId::resolve`) with zeros along `t2`:
//!
//! * for `whittaker`, `brach`, `newton`, `poisson`, `energetic` on 10,000 random planar
//!   problems (`W = L Lᵀ + δ I`, entries over two decades, `W_tn` of both signs and sometimes
//!   zero, `v_t` sometimes exactly zero, `μ ∈ [0, 2]` including 0 and 2, `e ∈ [0, 1]`
//!   including 0 and 1) and random `w22 ∈ [0.1, 10]`:
//!   * both succeed or both break down with the same reason;
//!   * impulse, velocity after, compression impulse, the three works and `ΔT` agree to
//!     `1e-12` relative — impulses relative to `|p| + ‖W⁻¹‖ (1+e) |v⁻|` (`|p|` plus the
//!     forward-error scale of solving with `W`, as `brach` does; both are of the order of
//!     `|p|` unless `W` is ill-conditioned), velocities to `|v⁻| + |W||p|`, works and
//!     energies to `|v⁻||p| + |W||p|²` (the size of the terms they are sums of);
//!   * the `t2` components of impulse and velocity are exactly zero;
//!   * the verdict is the same, and the phases correspond (planar `slip+`/`slip-` ↔ 3D slip
//!     at 0 / π, `no-slip` ↔ `no-slip`, `stick` ↔ `stick`, a planar reversed slip after
//!     the halt ↔ 3D resumed slip), ending at the same impulse (same scale as impulses);
//! * the largest deviation is printed (`-- --nocapture`).

use impax::math::SplitMix64;
use impax::planar::{ContactProblem, Outcome, PhaseKind, SlipDirection};
use impax::spatial;
use impax::LawId;
use std::f64::consts::PI;

/// Agreement required.
const TOL: f64 = 1e-12;
/// Number of random planar problems.
const PROBLEMS: usize = 10_000;
const LAWS: [LawId; 5] = [
    LawId::Whittaker,
    LawId::Brach,
    LawId::Newton,
    LawId::Poisson,
    LawId::Energetic,
];

fn random_planar(rng: &mut SplitMix64) -> ContactProblem {
    let l11 = rng.decades(-1.0, 1.0);
    let l22 = rng.decades(-1.0, 1.0);
    let l21 = if rng.unit() < 0.15 {
        0.0
    } else {
        let m = rng.decades(-1.0, 1.0);
        if rng.unit() < 0.5 {
            -m
        } else {
            m
        }
    };
    let delta = 1e-3 * rng.decades(-1.0, 1.0);
    let (a, b, c) = (l11 * l11 + delta, l11 * l21, l21 * l21 + l22 * l22 + delta);
    let vt = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.range(-2.0, 2.0)
    };
    let vn = rng.range(-2.0, -0.01);
    let u = rng.unit();
    let mu = if u < 0.1 {
        0.0
    } else if u < 0.15 {
        2.0
    } else {
        rng.range(0.0, 2.0)
    };
    let u = rng.unit();
    let e = if u < 0.1 {
        0.0
    } else if u < 0.2 {
        1.0
    } else {
        rng.unit()
    };
    ContactProblem::from_entries(a, b, c, vt, vn, mu, e).expect("valid by construction")
}

/// Whether a 3D phase corresponds to a planar one. `after_halt`: the phase follows a halt,
/// where a planar slip is the 3D resumed slip; `at_rest`: it starts from `v_t⁻ = 0`, where
/// a planar slip is the 3D resumed slip (Darboux–Keller) or a slip (algebraic laws).
fn phase_matches(
    planar: PhaseKind,
    spatial: spatial::PhaseKind,
    after_halt: bool,
    at_rest: bool,
) -> bool {
    let on_axis = |a: f64, dir: SlipDirection| match dir {
        SlipDirection::Positive => a == 0.0,
        SlipDirection::Negative => (a.abs() - PI).abs() <= 1e-15,
        SlipDirection::None => false,
    };
    match (planar, spatial) {
        (PhaseKind::Stick, spatial::PhaseKind::Stick) => true,
        (PhaseKind::Slip(SlipDirection::None), spatial::PhaseKind::NoSlip) => true,
        (PhaseKind::Slip(d), spatial::PhaseKind::Slip { from, to }) if !after_halt => {
            on_axis(from, d) && on_axis(to, d)
        }
        (PhaseKind::Slip(d), spatial::PhaseKind::Resumed { angle }) if after_halt || at_rest => {
            on_axis(angle, d)
        }
        _ => false,
    }
}

/// Deviations `[impulse, velocity, compression impulse, W_c, W_r, W_t, ΔT, phase ends]`,
/// or a description of a structural mismatch.
fn compare(
    problem: &ContactProblem,
    p2: &Outcome,
    p3: &spatial::Outcome,
) -> Result<[f64; 8], String> {
    let w = problem.w();
    let wn = w.norm();
    let v = problem.velocity();
    let pn = p2.impulse.norm();
    let vscale = v.norm() + wn * pn;
    let escale = v.norm() * pn + wn * pn * pn;
    // Impulses: |p| plus the forward-error scale of a solve with W, ‖W⁻¹‖ (1+e)|v⁻| (brach
    // solves W p* = (−v_t, −(1+e) v_n) — planar by the 2×2 formula, 3D by Cholesky — and
    // two correct solves differ by ~cond(W) ε relative); the same as |p| up to a constant
    // for well-conditioned W.
    let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
    let lmin = 0.5 * (a + c) - (0.25 * (a - c) * (a - c) + b * b).sqrt();
    let lmin = lmin.max((a * c - b * b) / (a + c));
    let pscale = pn + (1.0 + problem.restitution()) * v.norm() / lmin;
    if p3.impulse.y != 0.0 || p3.velocity_after.y != 0.0 {
        return Err(format!(
            "nonzero t2 components: impulse {:e}, velocity {:e}",
            p3.impulse.y, p3.velocity_after.y
        ));
    }
    if p2.verdict != p3.verdict {
        return Err(format!("verdict {:?} vs {:?}", p2.verdict, p3.verdict));
    }
    let (ph2, ph3) = (p2.phases.as_slice(), p3.phases.as_slice());
    if ph2.len() != ph3.len()
        || ph2
            .iter()
            .zip(ph3)
            .enumerate()
            .any(|(i, (a, b))| !phase_matches(a.kind, b.kind, i > 0, i == 0 && v.x == 0.0))
    {
        return Err(format!(
            "phases {} vs {}",
            p2.phases.summary(),
            p3.phases.summary()
        ));
    }
    let ends = ph2
        .iter()
        .zip(ph3)
        .map(|(a, b)| (a.ends_at - b.ends_at).abs())
        .fold(0.0f64, f64::max);
    let pc = match (p2.compression_impulse, p3.compression_impulse) {
        (Some(a), Some(b)) => (a - b).abs(),
        (None, None) => 0.0,
        (a, b) => return Err(format!("compression impulse {a:?} vs {b:?}")),
    };
    let dp = ((p2.impulse.x - p3.impulse.x).powi(2) + (p2.impulse.y - p3.impulse.z).powi(2)).sqrt();
    let dv = ((p2.velocity_after.x - p3.velocity_after.x).powi(2)
        + (p2.velocity_after.y - p3.velocity_after.z).powi(2))
    .sqrt();
    Ok([
        dp / pscale,
        dv / vscale,
        pc / pscale,
        (p2.work.compression - p3.work.compression).abs() / escale,
        (p2.work.restitution - p3.work.restitution).abs() / escale,
        (p2.work.friction - p3.work.friction).abs() / escale,
        (p2.energy_change - p3.energy_change).abs() / escale,
        ends / pscale,
    ])
}

const NAMES: [&str; 8] = [
    "impulse",
    "velocity after",
    "compression impulse",
    "W_c",
    "W_r",
    "W_t",
    "ΔT",
    "phase ends",
];

#[test]
fn planar_problems_embedded_in_3d_agree_with_the_planar_closed_form_for_all_five_laws() {
    let mut rng = SplitMix64(0x91A4_A12E_3D00_0001);
    let cases: Vec<(ContactProblem, f64)> = (0..PROBLEMS)
        .map(|_| {
            let p = random_planar(&mut rng);
            (p, rng.decades(-1.0, 1.0))
        })
        .collect();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(8);
    type Part = (Vec<String>, [[(f64, usize); 8]; 5], usize);
    let parts: Vec<Part> = std::thread::scope(|sc| {
        let cases = &cases;
        let hs: Vec<_> = (0..threads)
            .map(|k| {
                sc.spawn(move || {
                    let mut failures = Vec::new();
                    let mut worst = [[(0.0f64, 0usize); 8]; 5];
                    let mut breakdowns = 0;
                    for (i, (p, w22)) in cases.iter().enumerate().skip(k).step_by(threads) {
                        let p3 =
                            spatial::ContactProblem::from_planar(p, *w22).expect("valid embedding");
                        for (li, law) in LAWS.iter().enumerate() {
                            match (law.resolve(p), law.resolve(&p3)) {
                                (Ok(a), Ok(b)) => match compare(p, &a, &b) {
                                    Ok(devs) => {
                                        for (j, &d) in devs.iter().enumerate() {
                                            if d > worst[li][j].0 || d.is_nan() {
                                                worst[li][j] = (d, i);
                                            }
                                            if d > TOL || d.is_nan() {
                                                failures.push(format!(
                                                    "case {i} {law}: {} deviates by {d:e} \
                                                     (planar {:?} / 3D {:?}): {p:?}, w22 = {w22}",
                                                    NAMES[j], a.impulse, b.impulse
                                                ));
                                            }
                                        }
                                    }
                                    Err(m) => failures.push(format!("case {i} {law}: {m}: {p:?}")),
                                },
                                (Err(a), Err(b)) if a.reason.id() == b.reason.id() => {
                                    breakdowns += 1;
                                }
                                (a, b) => failures.push(format!(
                                    "case {i} {law}: planar {:?} vs 3D {:?}: {p:?}, w22 = {w22}",
                                    a.map(|o| o.impulse),
                                    b.map(|o| o.impulse)
                                )),
                            }
                        }
                    }
                    (failures, worst, breakdowns)
                })
            })
            .collect();
        hs.into_iter()
            .map(|h| h.join().expect("no panic"))
            .collect()
    });
    let mut failures = Vec::new();
    let mut worst = [[(0.0f64, 0usize); 8]; 5];
    let mut breakdowns = 0;
    for (f, w, b) in parts {
        failures.extend(f);
        breakdowns += b;
        for li in 0..5 {
            for j in 0..8 {
                if w[li][j].0 > worst[li][j].0 || w[li][j].0.is_nan() {
                    worst[li][j] = w[li][j];
                }
            }
        }
    }
    eprintln!(
        "planar embedding: {PROBLEMS} problems × {} laws, {breakdowns} agreeing breakdowns",
        LAWS.len()
    );
    for (li, law) in LAWS.iter().enumerate() {
        let (j, &(d, i)) = worst[li]
            .iter()
            .enumerate()
            .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
            .expect("eight");
        eprintln!(
            "  {law:<10} largest deviation {d:.3e} ({}, case {i})",
            NAMES[j]
        );
    }
    for f in failures.iter().take(12) {
        eprintln!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} disagreements (first: {})",
        failures.len(),
        failures[0]
    );
}
