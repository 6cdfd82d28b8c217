//! The multiple-impact law `lzb` (Liu, Zhao & Brogliato), checked against independent
//! derivations:
//!
//! * `K = 1`: `lzb` is `energetic` to 1e-13 (10,000 random problems, whatever the stiffness
//!   and exponent), in contact space, through `LawId::resolve` and in 3D;
//! * decoupled contacts (block-diagonal `W`): each contact is its own `energetic` (the
//!   integrated law against the closed form);
//! * a rod lying flat landing on both ends (rank-3 `W` from `J M⁻¹ Jᵀ`): the body leaves at
//!   `(0, e |v_y|, 0)` for every `e` and `μ`; taken in closed form (no integration step), it
//!   is the limit of the integrated path of a slightly tilted landing (`O(δ)`);
//! * Housner's rocking block: with the resting corner not pressed by the impulse at the
//!   striking one (`b² < 2 h²`), `ω⁺/ω⁻ = 1 − (3/2) sin²α` to 1e-12, the resting corner
//!   untouched;
//! * Newton's cradle with 3, 4 and 5 equal balls: momentum and energy conserved, the balls
//!   leave in order, and the velocities equal those of an independent time integration of the
//!   chain of Hertz contacts in the balls' own coordinates (the middle contacts start at
//!   `v_n = 0` and join during the impact; with `e < 1` and unequal stiffnesses too);
//! * 100,000 random problems (`K = 2 … 4`, `W = J M⁻¹ Jᵀ` of random bodies, singular ones
//!   included, random `μ`, `e`, `κ`, `η`): never an energy gain, the contacts' works sum to
//!   `ΔT`, no consistent result leaves a contact approaching;
//! * scaling every stiffness leaves the result unchanged; bad parameters name their field.

use crate::support::{
    body_after, chain_jacobian, contact_space, flat, kinetic, random_multi, random_one,
    rod_jacobian, solved_in_parallel,
};
use impax::math::{SplitMix64, Vec2};
use impax::multi::{lzb, ContactPhaseKind, LzbPrimary, MultiDetail, MultiOutcome, MultiProblem};
use impax::planar::{ContactProblem, Verdict};
use impax::LawId;
use nalgebra::{DMatrix, DVector};

/// The problem as command-line arguments (for a failure message).
fn args(p: &MultiProblem) -> String {
    let k = p.contacts();
    let list = |x: Vec<f64>| {
        x.iter()
            .map(|y| format!("{y:e}"))
            .collect::<Vec<_>>()
            .join(",")
    };
    let upper: Vec<f64> = (0..2 * k)
        .flat_map(|i| (i..2 * k).map(move |j| (i, j)))
        .map(|(i, j)| p.w()[(i, j)])
        .collect();
    format!(
        "--contacts {k} --w {} --v {} --friction {} --restitution {} --stiffness {} --exponent {:e}",
        list(upper),
        list(p.velocity().iter().copied().collect()),
        list((0..k).map(|j| p.friction(j)).collect()),
        list((0..k).map(|j| p.restitution(j)).collect()),
        list((0..k).map(|j| p.stiffness(j)).collect()),
        p.exponent()
    )
}

fn steps(o: &MultiOutcome) -> usize {
    match &o.detail {
        MultiDetail::Lzb { steps, .. } => *steps,
        other => panic!("not lzb: {other:?}"),
    }
}

fn primaries(o: &MultiOutcome) -> &[LzbPrimary] {
    match &o.detail {
        MultiDetail::Lzb { primaries, .. } => primaries,
        other => panic!("not lzb: {other:?}"),
    }
}

// ---------------------------------------------------------------------------------------
// K = 1

#[test]
fn one_contact_is_energetic() {
    let mut rng = SplitMix64(0x6c7a_6231);
    let mut worst = 0.0f64;
    for trial in 0..10_000 {
        let one = random_one(&mut rng);
        let mut multi = MultiProblem::from_contact(&one).expect("one contact");
        if trial % 2 == 1 {
            // With one contact the force law does not matter.
            multi = multi
                .with_stiffness(&[rng.decades(-3.0, 3.0)])
                .unwrap()
                .with_exponent(rng.range(0.5, 3.0))
                .unwrap();
        }
        let r = LawId::Energetic.resolve(&one).expect("energetic");
        let m = LawId::Lzb.resolve(&multi).expect("valid").expect("outcome");
        assert_eq!(m.law, LawId::Lzb);
        let c = &m.contacts[0];
        let pscale = r.impulse.norm();
        let vscale = one.velocity().norm() + r.velocity_after.norm();
        let escale = pscale * vscale;
        let d = [
            (c.impulse - r.impulse).norm() / pscale,
            (c.velocity_after - r.velocity_after).norm() / vscale,
            (m.energy_change - r.energy_change).abs() / escale,
            (c.work.compression - r.work.compression).abs() / escale,
            (c.work.restitution - r.work.restitution).abs() / escale,
            (c.work.friction - r.work.friction).abs() / escale,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        worst = worst.max(d);
        assert!(d < 1e-13, "{d:e} from energetic on {one:?}");
        assert_eq!(m.verdict, r.verdict, "{one:?}");
        let phases: Vec<_> = r
            .phases
            .as_slice()
            .iter()
            .map(|p| (ContactPhaseKind::from(p.kind), p.ends_at))
            .collect();
        let mine: Vec<_> = c.phases.iter().map(|p| (p.kind, p.ends_at)).collect();
        assert_eq!(mine, phases);
        assert_eq!(steps(&m), 0);
        // The one-contact entry point: energetic relabelled.
        let l = LawId::Lzb.resolve(&one).unwrap();
        assert_eq!(l.law, LawId::Lzb);
        assert_eq!(l.impulse, r.impulse);
        assert_eq!(l.energy_change, r.energy_change);
    }
    println!("K = 1: lzb within {worst:.1e} of energetic");
}

#[test]
fn one_contact_everywhere_and_the_law_tables() {
    use impax::spatial;
    let p3 = spatial::ContactProblem::from_upper(
        [2.0, 0.3, 0.1, 1.5, 0.2, 1.0],
        [0.5, 0.2, -1.0],
        0.5,
        0.6,
    )
    .unwrap();
    let (l, e) = (
        LawId::Lzb.resolve(&p3).unwrap(),
        LawId::Energetic.resolve(&p3).unwrap(),
    );
    assert_eq!(l.law, LawId::Lzb);
    assert_eq!(l.impulse, e.impulse);
    assert!(LawId::Lzb.is_spatial() && LawId::Lzb.is_multi_contact());
    assert_eq!("lzb".parse::<LawId>().unwrap(), LawId::Lzb);
    assert_eq!(LawId::Lzb.to_string(), "lzb");
    assert!(!LawId::ALL.contains(&LawId::Lzb));
    assert!(!LawId::CONTACT_SPACE.contains(&LawId::Lzb));
    assert!(!LawId::SPATIAL.contains(&LawId::Lzb));
    assert_eq!(
        LawId::MULTI_CONTACT,
        [LawId::Lcp, LawId::Sequential, LawId::Lzb]
    );
}

// ---------------------------------------------------------------------------------------
// Decoupled contacts

#[test]
fn decoupled_contacts_are_their_own_energetic() {
    let mut rng = SplitMix64(0xdec0_126b);
    let mut worst = [0.0f64; 2];
    let (mut total_steps, mut coarse, mut contacts) = (0, 0, 0);
    for trial in 0..1500 {
        let k = 2 + trial % 3;
        let ones: Vec<ContactProblem> = (0..k).map(|_| random_one(&mut rng)).collect();
        let mut multi = crate::support::block_diagonal(&ones);
        if trial % 2 == 1 {
            let kappa: Vec<f64> = (0..k).map(|_| rng.decades(-2.0, 2.0)).collect();
            multi = multi
                .with_stiffness(&kappa)
                .unwrap()
                .with_exponent(rng.range(1.0, 2.5))
                .unwrap();
        }
        let o = lzb::resolve(&multi).expect("lzb");
        total_steps += steps(&o);
        assert_ne!(o.verdict, Verdict::EnergyGained);
        for (j, one) in ones.iter().enumerate() {
            let r = LawId::Energetic.resolve(one).unwrap();
            let c = &o.contacts[j];
            let pscale = r.impulse.norm();
            let vscale = one.velocity().norm() + r.velocity_after.norm();
            let dp = (c.impulse - r.impulse).norm() / pscale;
            let dv = (c.velocity_after - r.velocity_after).norm() / vscale;
            worst[0] = worst[0].max(dp);
            worst[1] = worst[1].max(dv);
            coarse += usize::from(dp.max(dv) > 1e-10);
            contacts += 1;
            // (1e-12 typically; up to 1e-8 where two contacts separate within a hair of each
            // other, their forces singular there and the regularising variable taken for one.)
            assert!(
                dp < 1e-7 && dv < 1e-7,
                "contact {j}: {:?} vs {:?}, {:?} vs {:?} ({})",
                c.impulse,
                r.impulse,
                c.velocity_after,
                r.velocity_after,
                args(&multi)
            );
        }
    }
    println!(
        "decoupled: impulses within {:.1e}, velocities within {:.1e} of energetic, {coarse} of {contacts} contacts beyond 1e-10 ({} steps per impact)",
        worst[0],
        worst[1],
        total_steps / 1500
    );
}

// ---------------------------------------------------------------------------------------
// A rod lying flat

#[test]
fn rod_landing_flat() {
    let mut worst = 0.0f64;
    for (m, l) in [(2.5, 0.8), (1.0, 1.0), (0.3, 4.0)] {
        let masses = [m, m, m * l * l / 12.0];
        let j = rod_jacobian(l);
        for vy in [-1.0, -3.7] {
            let u = DVector::from_column_slice(&[0.0, vy, 0.0]);
            let (w, v) = contact_space(&j, &masses, &u);
            for e in [0.0, 0.3, 0.8, 1.0] {
                for mu in [0.0, 0.2, 1.0] {
                    for eta in [1.5, 1.0] {
                        let p = MultiProblem::new(w.clone(), &v, &[mu], &[e])
                            .unwrap()
                            .with_exponent(eta)
                            .unwrap();
                        assert_eq!(p.rank(), 3);
                        let o = lzb::resolve(&p).unwrap();
                        let ua = body_after(&j, &masses, &u, &o);
                        let expected = [0.0, e * vy.abs(), 0.0];
                        for k in 0..3 {
                            let d = (ua[k] - expected[k]).abs() / vy.abs();
                            worst = worst.max(d);
                            assert!(d < 1e-10, "e = {e}, μ = {mu}, η = {eta}: {ua:?}");
                        }
                        assert_eq!(o.verdict, Verdict::Consistent);
                        // Symmetric: equal normal impulses, no tangential impulse.
                        let (a, b) = (o.contacts[0].impulse, o.contacts[1].impulse);
                        assert!((a.y - b.y).abs() < 1e-12 * m * vy.abs());
                        assert!(a.x.abs() < 1e-14 && b.x.abs() < 1e-14);
                    }
                }
            }
        }
    }
    println!("rod landing flat: within {worst:.1e} of (0, e |v_y|, 0)");
}

/// The rod landing flat is taken in closed form (both ends load in fixed proportions, no
/// integration step); tilting its landing by `δ` (one end approaching at `1 + δ`) breaks the
/// proportions and the path is integrated: its impulses tend to the closed form's as
/// `δ → 0`, by `O(δ)`.
#[test]
fn closed_form_is_the_limit_of_the_integrated_path() {
    // m = 1, l = 1 (W_tt = [[1, 1], [1, 1]]: rank 3).
    let w = [1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0];
    for (mu, e) in [(0.3, 0.5), (0.0, 1.0), (1.0, 0.0)] {
        let rod = |d: f64| {
            let p = MultiProblem::from_upper(2, &w, &[0.0, -1.0, 0.0, -1.0 - d], &[mu], &[e]);
            lzb::resolve(&p.unwrap()).unwrap()
        };
        let flat = rod(0.0);
        assert_eq!(steps(&flat), 0);
        for c in &flat.contacts {
            assert!((c.impulse.y - 0.5 * (1.0 + e)).abs() < 1e-15, "{c:?}");
            assert!((c.velocity_after.y - e).abs() < 1e-15, "{c:?}");
        }
        let mut gaps = Vec::new();
        for d in [1e-3, 1e-5] {
            let tilted = rod(d);
            assert!(steps(&tilted) > 0);
            let gap = flat
                .contacts
                .iter()
                .zip(&tilted.contacts)
                .map(|(a, b)| (a.impulse - b.impulse).norm())
                .fold(0.0, f64::max);
            assert!(gap < 10.0 * d, "μ = {mu}, e = {e}, δ = {d}: {gap:e}");
            gaps.push(gap);
        }
        // O(δ): a hundred times closer for a hundred times smaller δ.
        let ratio = gaps[0] / gaps[1];
        assert!((30.0..300.0).contains(&ratio), "{gaps:?}");
    }
}

#[test]
fn a_contact_barely_approaching_at_the_start_is_the_limit_of_one_at_rest() {
    // The second contact pushed into the first's impact (W_n1n2 = 0.1, v_n2 → 0⁻): its
    // result is continuous in v_n2, whether it starts compressing (the slowest approaches,
    // down to one whose force κ |v_n2|^η underflows) or at rest and joins.
    let w = [1.0, 0.2, 0.0, 0.1, 1.0, 0.1, 0.0, 1.0, 0.3, 1.0];
    let solve = |vn2: f64| {
        let p = MultiProblem::from_upper(2, &w, &[0.1, -1.0, 0.2, vn2], &[0.5], &[0.7]);
        lzb::resolve(&p.unwrap()).unwrap()
    };
    let rest = solve(0.0);
    assert!(rest.contacts[1].impulse.y > 0.09, "{rest:?}");
    // (Below 1e-12 of the largest velocity a contact approaching is at rest; above, its
    // result moves by O(v_n2).)
    for vn2 in [
        -1e-300, -1e-200, -1e-150, -1e-100, -1e-50, -1e-13, -1e-11, -1e-9, -1e-6,
    ] {
        let o = solve(vn2);
        for (a, b) in rest.contacts.iter().zip(&o.contacts) {
            let gap = (a.impulse - b.impulse).norm();
            assert!(
                gap < 1e-10 + 10.0 * vn2.abs(),
                "v_n2 = {vn2:e}: {gap:e} ({:?} vs {:?})",
                a.impulse,
                b.impulse
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Housner's rocking block

/// A uniform rectangular block (half-width b, half-height h, mass m, I = m (b² + h²)/3)
/// standing on a floor (t = x, n = y), rotating about its left corner A = (−b, −h) (from the
/// centre) with angular velocity ω < 0 (clockwise) as its right corner B = (b, −h) strikes:
/// u = (V_x, V_y, ω) = ω (−h, b, 1). Contact A is contact 1, B contact 2; a point r of the
/// block moves at V + ω ẑ × r = (V_x − ω r_y, V_y + ω r_x).
fn block(b: f64, h: f64, m: f64, omega: f64) -> (DMatrix<f64>, [f64; 3], DVector<f64>) {
    let j = DMatrix::from_row_slice(
        4,
        3,
        &[
            1.0, 0.0, h, //
            0.0, 1.0, -b, //
            1.0, 0.0, h, //
            0.0, 1.0, b,
        ],
    );
    let masses = [m, m, m * (b * b + h * h) / 3.0];
    let u = DVector::from_column_slice(&[-h * omega, b * omega, omega]);
    (j, masses, u)
}

#[test]
fn housner_rocking_block() {
    // Housner (1963): a plastic impact at B without slip conserves the angular momentum
    // about B: ω⁺/ω⁻ = 1 − (3/2) sin²α, α = atan(b/h). With lzb the resting corner A starts
    // with v_n = 0 and no stored energy: it carries no impulse as long as the impulse at B
    // lifts it, i.e. (along the straight stick path from 0 to Housner's end) as long as A
    // leaves upwards after, ω⁺ ≥ 0 relative to ω⁻: b² ≤ 2 h².
    let mut worst = 0.0f64;
    for (b, h) in [
        (0.2f64, 1.0f64),
        (0.5, 1.0),
        (1.0, 1.0),
        (1.3, 1.0),
        (0.05, 0.3),
    ] {
        let alpha = (b / h).atan();
        let ratio = 1.0 - 1.5 * alpha.sin().powi(2);
        for (m, omega) in [(1.0, -1.0), (7.5, -0.3)] {
            let (j, masses, u) = block(b, h, m, omega);
            let (w, v) = contact_space(&j, &masses, &u);
            assert!(v[0].abs() < 1e-15 && v[1].abs() < 1e-15 && v[2].abs() < 1e-15);
            // Enough friction to stick at B: |W_tn| ≤ μ W_tt of its block.
            let mu = 2.0;
            assert!(w[(2, 3)].abs() <= mu * w[(2, 2)]);
            let p = MultiProblem::new(w, &v, &[mu], &[0.5, 0.0]).unwrap();
            let o = lzb::resolve(&p).unwrap();
            let ua = body_after(&j, &masses, &u, &o);
            let d = (ua[2] / omega - ratio).abs();
            worst = worst.max(d);
            assert!(
                d < 1e-12,
                "b = {b}, h = {h}: ω⁺/ω⁻ = {} vs {ratio}",
                ua[2] / omega
            );
            // A never engaged; B stuck throughout and is at rest after.
            assert_eq!(o.contacts[0].impulse, Vec2::zeros());
            assert_eq!(o.contacts[0].phases[0].kind, ContactPhaseKind::Off);
            assert_eq!(o.contacts[1].phases.len(), 1);
            assert_eq!(o.contacts[1].phases[0].kind, ContactPhaseKind::Stick);
            assert!(
                o.contacts[1].velocity_after.norm() < 1e-12 * omega.abs() * b,
                "{:?}",
                o.contacts[1].velocity_after
            );
            assert!(o.contacts[0].velocity_after.y >= 0.0);
            assert_eq!(o.verdict, Verdict::Consistent);
        }
    }
    println!("Housner's block (b² ≤ 2h²): ω⁺/ω⁻ within {worst:.1e} of 1 − (3/2) sin²α");
    // A wide block (b² > 2 h²): the impulse at B presses A down, A engages and Housner's
    // single-impact assumption no longer holds.
    for (b, h) in [(1.6f64, 1.0f64), (3.0, 1.0)] {
        let (j, masses, u) = block(b, h, 1.0, -1.0);
        let (w, v) = contact_space(&j, &masses, &u);
        let p = MultiProblem::new(w, &v, &[2.0], &[0.5, 0.0]).unwrap();
        let o = lzb::resolve(&p).unwrap();
        let ua = body_after(&j, &masses, &u, &o);
        let alpha = (b / h).atan();
        println!(
            "wide block b/h = {}: lzb ω⁺/ω⁻ = {:.6}, Housner {:.6}, impulse at A {:?}",
            b / h,
            ua[2] / -1.0,
            1.0 - 1.5 * alpha.sin().powi(2),
            o.contacts[0].impulse
        );
        assert!(o.contacts[0].impulse.y > 0.0);
        assert_ne!(o.verdict, Verdict::EnergyGained);
    }
}

// ---------------------------------------------------------------------------------------
// Newton's cradle

/// The chain of `n` balls (masses `m`) along x with Hertz contacts of stiffness `kappa[j]`,
/// exponent `eta` and the same energetic restitution as `lzb` (stiffness `1/e²` times larger
/// on unloading: the deflection variable grows with the approach, and shrinks `1/e²` times
/// faster), integrated in time in the balls' own velocities by the classical Runge–Kutta
/// method with a fixed step: an independent computation of what `lzb` integrates in contact
/// space. Ball 1 moves at `v0`, the others rest, all touching. Returns the velocities after.
fn hertz_chain(m: &[f64], kappa: &[f64], eta: f64, e: f64, v0: f64, dt: f64) -> Vec<f64> {
    let n = m.len();
    // State: velocities (n), deflections (n − 1).
    let rhs = |x: &[f64]| -> Vec<f64> {
        let mut d = vec![0.0; 2 * n - 1];
        for c in 0..n - 1 {
            let s = x[n + c];
            let f = if s > 0.0 { kappa[c] * s.powf(eta) } else { 0.0 };
            d[c] -= f / m[c];
            d[c + 1] += f / m[c + 1];
            let approach = x[c] - x[c + 1];
            let unloading = approach < 0.0 && s > 0.0;
            d[n + c] = if unloading {
                approach / (e * e)
            } else {
                approach
            };
        }
        d
    };
    let mut x = vec![0.0; 2 * n - 1];
    x[0] = v0;
    for _ in 0..100_000_000 {
        let k1 = rhs(&x);
        let y: Vec<f64> = (0..x.len()).map(|i| x[i] + 0.5 * dt * k1[i]).collect();
        let k2 = rhs(&y);
        let y: Vec<f64> = (0..x.len()).map(|i| x[i] + 0.5 * dt * k2[i]).collect();
        let k3 = rhs(&y);
        let y: Vec<f64> = (0..x.len()).map(|i| x[i] + dt * k3[i]).collect();
        let k4 = rhs(&y);
        for i in 0..x.len() {
            x[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        // Done when every contact is open and opening.
        if (0..n - 1).all(|c| x[n + c] <= 0.0 && x[c] <= x[c + 1]) {
            break;
        }
    }
    x[..n].to_vec()
}

/// `lzb` on the chain of `n` equal balls (mass m, radius r), ball 1 at `v0`, the others at
/// rest, all touching; returns the outcome and the balls' velocities along x.
fn lzb_chain(
    n: usize,
    m: f64,
    v0: f64,
    e: f64,
    kappa: &[f64],
) -> (MultiOutcome, Vec<f64>, [f64; 2]) {
    let r = 0.2;
    let i = 0.4 * m * r * r;
    let masses: Vec<f64> = (0..n).flat_map(|_| [m, m, i]).collect();
    let j = chain_jacobian(n, r);
    let mut u = DVector::zeros(3 * n);
    u[0] = v0;
    let (w, v) = contact_space(&j, &masses, &u);
    let p = MultiProblem::new(w, &v, &[0.0], &[e])
        .unwrap()
        .with_stiffness(kappa)
        .unwrap();
    let o = lzb::resolve(&p).unwrap();
    let ua = body_after(&j, &masses, &u, &o);
    let after: Vec<f64> = (0..n).map(|b| ua[3 * b]).collect();
    for b in 0..n {
        assert!(ua[3 * b + 1].abs() < 1e-14 && ua[3 * b + 2].abs() < 1e-14);
    }
    (o, after, [kinetic(&masses, &u), kinetic(&masses, &ua)])
}

#[test]
fn newtons_cradle_elastic() {
    let (m, v0) = (1.3, 0.7);
    for n in [3, 4, 5] {
        let (o, after, [t0, t1]) = lzb_chain(n, m, v0, 1.0, &[1.0]);
        let momentum: f64 = after.iter().map(|x| m * x).sum();
        assert!((momentum - m * v0).abs() < 1e-10 * m * v0, "{after:?}");
        assert!((t1 - t0).abs() < 1e-10 * t0, "{t0} → {t1}");
        assert!(o.energy_change.abs() < 1e-10 * t0);
        assert_eq!(o.verdict, Verdict::Consistent);
        // The balls leave in order, no contact approaching.
        for b in 0..n - 1 {
            assert!(after[b] <= after[b + 1], "{after:?}");
        }
        for c in &o.contacts {
            assert!(c.velocity_after.y >= 0.0);
            // Every contact carried an impulse: those starting at v_n = 0 joined.
            assert!(c.impulse.y > 0.1 * m * v0, "{:?}", c.impulse);
        }
        assert_eq!(primaries(&o)[0].contact, 0);
        // The same chain integrated in the balls' own coordinates.
        let reference = hertz_chain(&vec![m; n], &vec![1.0; n - 1], 1.5, 1.0, v0, 2e-4);
        let d = after
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs() / v0)
            .fold(0.0, f64::max);
        println!(
            "cradle, {n} balls, e = 1: v⁺/v0 = {:?} ({} steps; independent integration within {d:.1e})",
            after.iter().map(|x| x / v0).collect::<Vec<_>>(),
            steps(&o)
        );
        assert!(d < 1e-8, "{after:?} vs {reference:?}");
    }
}

#[test]
fn newtons_cradle_inelastic_and_unequal_stiffness() {
    let (m, v0) = (0.8, 1.1);
    for (e, kappa) in [
        (0.6, vec![1.0, 1.0]),
        (1.0, vec![1.0, 4.0]),
        (0.8, vec![3.0, 0.5]),
    ] {
        let (o, after, [t0, t1]) = lzb_chain(3, m, v0, e, &kappa);
        let momentum: f64 = after.iter().map(|x| m * x).sum();
        assert!((momentum - m * v0).abs() < 1e-10 * m * v0);
        assert!(t1 <= t0 * (1.0 + 1e-10));
        assert!((o.energy_change - (t1 - t0)).abs() < 1e-10 * t0);
        let reference = hertz_chain(&[m; 3], &kappa, 1.5, e, v0, 1e-5);
        let d = after
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs() / v0)
            .fold(0.0, f64::max);
        println!(
            "cradle, 3 balls, e = {e}, κ = {kappa:?}: v⁺/v0 = {:?} (independent integration within {d:.1e})",
            after.iter().map(|x| x / v0).collect::<Vec<_>>()
        );
        assert!(d < 1e-4, "{after:?} vs {reference:?}");
        for c in &o.contacts {
            assert!(c.velocity_after.y >= 0.0);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Energy on random problems

#[test]
fn never_gains_energy_on_random_problems() {
    let mut rng = SplitMix64(0x1eb_0e6e);
    let (mut total_steps, mut most, mut breakdowns, mut jammed) = (0usize, 0usize, [0usize; 2], 0);
    let mut verdicts = [0usize; 3];
    let mut worst_works = 0.0f64;
    let n = 100_000;
    // Made in the generator's order, resolved in parallel, checked in order.
    let make = |trial: usize| {
        let k = 2 + trial % 3;
        let r = random_multi(&mut rng, k);
        let kappa: Vec<f64> = (0..k)
            .map(|_| {
                if rng.unit() < 0.5 {
                    1.0
                } else {
                    rng.decades(-2.0, 2.0)
                }
            })
            .collect();
        let eta = match rng.next_u64() % 4 {
            0 => 1.0,
            1 => rng.range(0.5, 3.0),
            _ => 1.5,
        };
        let p = r
            .problem
            .clone()
            .with_stiffness(&kappa)
            .unwrap()
            .with_exponent(eta)
            .unwrap();
        (r, p)
    };
    for ((r, p), out) in solved_in_parallel(n, make, |(_, p)| lzb::resolve(p)) {
        let k = p.contacts();
        let o = match out {
            Ok(o) => o,
            Err(b) => {
                match b.reason.id() {
                    "too-many-steps" => breakdowns[usize::from(p.rank() < 2 * k)] += 1,
                    "jammed" => {
                        // Energy held at rest: only redundant contacts can balance forces.
                        assert!(p.rank() < 2 * k, "{b} with W positive definite: {p:?}");
                        jammed += 1;
                    }
                    _ => panic!("{b}"),
                }
                continue;
            }
        };
        assert!(o.is_finite());
        let s = steps(&o);
        total_steps += s;
        most = most.max(s);
        verdicts[match o.verdict {
            Verdict::Consistent => 0,
            Verdict::EnergyGained => 1,
            Verdict::InconsistentAssumption => 2,
        }] += 1;
        assert_ne!(o.verdict, Verdict::EnergyGained, "{p:?}");
        let pv = flat(&o.impulses());
        let scale = r.v.amax() + (&r.w.abs() * pv.abs()).amax();
        let escale = scale * pv.amax();
        // ΔT ≤ 0 to the integration's tolerance; the works sum to ΔT; ΔT from the problem.
        assert!(
            o.energy_change <= 1e-9 * escale,
            "ΔT = {:e} on {p:?}",
            o.energy_change
        );
        let works: f64 = o.contacts.iter().map(|c| c.work.total()).sum();
        worst_works = worst_works.max((works - o.energy_change).abs() / escale);
        assert!((works - o.energy_change).abs() <= 1e-8 * escale, "{p:?}");
        let dt = p.energy_change(&o.impulses());
        assert!((dt - o.energy_change).abs() <= 1e-10 * escale);
        // Coulomb: every impulse inside its cone.
        for (j, c) in o.contacts.iter().enumerate() {
            assert!(c.impulse.y >= 0.0, "p_n {} on {p:?}", c.impulse.y);
            assert!(
                c.impulse.x.abs() <= p.friction(j) * c.impulse.y * (1.0 + 1e-9) + 1e-12 * escale
            );
        }
        if o.verdict == Verdict::Consistent {
            for c in &o.contacts {
                assert!(c.velocity_after.y >= -1e-9 * scale, "approaching: {p:?}");
            }
        }
    }
    println!(
        "lzb: {n} problems, {} steps per impact (at most {most}), verdicts {verdicts:?}, works within {worst_works:.1e} of ΔT, {jammed} jammed, {breakdowns:?} cut at {} steps (W positive definite, singular)",
        total_steps / (n - breakdowns[0] - breakdowns[1] - jammed),
        lzb::MAX_STEPS
    );
    assert_eq!(verdicts[1], 0);
    assert!(
        breakdowns[0] + breakdowns[1] < n / 200,
        "{breakdowns:?} breakdowns"
    );
}

// ---------------------------------------------------------------------------------------
// Stiffness scale, parameters

#[test]
fn only_the_stiffness_ratios_matter() {
    let mut rng = SplitMix64(0x5ca1e);
    for trial in 0..300 {
        let r = random_multi(&mut rng, 2 + trial % 2);
        let k = r.problem.contacts();
        let kappa: Vec<f64> = (0..k).map(|_| rng.decades(-1.0, 1.0)).collect();
        let factor = rng.decades(-6.0, 6.0);
        let scaled: Vec<f64> = kappa.iter().map(|x| x * factor).collect();
        let a = lzb::resolve(&r.problem.clone().with_stiffness(&kappa).unwrap());
        let b = lzb::resolve(&r.problem.clone().with_stiffness(&scaled).unwrap());
        match (a, b) {
            (Ok(a), Ok(b)) => {
                for (x, y) in a.contacts.iter().zip(&b.contacts) {
                    let scale = x.impulse.norm().max(1e-300);
                    assert!(
                        (x.impulse - y.impulse).norm() <= 1e-9 * scale,
                        "{x:?} vs {y:?}"
                    );
                }
            }
            (Err(a), Err(b)) => assert_eq!(a.reason.id(), b.reason.id()),
            (a, b) => panic!("{a:?} vs {b:?}"),
        }
    }
}

#[test]
fn bad_parameters_name_their_field() {
    let rod = [1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0];
    let p = MultiProblem::from_upper(2, &rod, &[0.0, -1.0, 0.0, -1.0], &[0.5], &[0.5]).unwrap();
    let field = |r: impax::Result<MultiProblem>| r.unwrap_err().field().to_string();
    assert_eq!(
        field(p.clone().with_stiffness(&[1.0, 2.0, 3.0])),
        "stiffness"
    );
    assert_eq!(field(p.clone().with_stiffness(&[])), "stiffness");
    assert_eq!(field(p.clone().with_stiffness(&[-1.0])), "stiffness");
    assert_eq!(field(p.clone().with_stiffness(&[0.0])), "stiffness");
    assert_eq!(field(p.clone().with_stiffness(&[1.0, 0.0])), "stiffness[2]");
    assert_eq!(
        field(p.clone().with_stiffness(&[f64::NAN, 1.0])),
        "stiffness[1]"
    );
    assert_eq!(
        field(p.clone().with_stiffness(&[f64::INFINITY])),
        "stiffness"
    );
    assert_eq!(field(p.clone().with_exponent(0.0)), "exponent");
    assert_eq!(field(p.clone().with_exponent(-1.5)), "exponent");
    assert_eq!(field(p.clone().with_exponent(f64::NAN)), "exponent");
    assert_eq!(field(p.clone().with_exponent(f64::INFINITY)), "exponent");
    let q = p
        .clone()
        .with_stiffness(&[2.0])
        .unwrap()
        .with_exponent(1.0)
        .unwrap();
    assert_eq!(
        (q.stiffness(0), q.stiffness(1), q.exponent()),
        (2.0, 2.0, 1.0)
    );
    assert_eq!((p.stiffness(1), p.exponent()), (1.0, 1.5));
    // Too many contacts for lzb: the law names its field, lzb::resolve breaks down.
    let k = lzb::MAX_CONTACTS + 1;
    let mut w = DMatrix::identity(2 * k, 2 * k);
    w[(1, 3)] = 0.1;
    w[(3, 1)] = 0.1;
    let mut v = vec![0.0; 2 * k];
    v[1] = -1.0;
    let p = MultiProblem::new(w, &v, &[0.3], &[0.5]).unwrap();
    let e = LawId::Lzb.resolve(&p).unwrap_err();
    assert_eq!(e.field(), "law");
    assert!(e.to_string().contains("at most 8"), "{e}");
    assert_eq!(
        lzb::resolve(&p).unwrap_err().reason.id(),
        "too-many-contacts"
    );
}
