//! Spatial impacts at several contacts (`impax::multi::spatial`): the one-contact and
//! decoupled reductions against the one-contact spatial laws (an independent derivation: the
//! one-contact `lcp` finds its slip angle as a root of a trigonometric polynomial), the
//! planar problem embedded in 3D against the planar multi-contact laws, a box landing flat
//! on four corners (W of rank 6), and random problems whose `lcp` solutions must satisfy
//! the conditions to 1e-12 and whose `sequential` never gains energy.

use super::support::{assert_spatial_lcp_solution, contact_space, random_spatial_space};
use impax::math::{SplitMix64, Vec3};
use impax::multi::spatial::{self, MultiProblem};
use impax::multi::MultiProblem as Planar;
use impax::spatial::ContactProblem;
use impax::LawId;
use nalgebra::{DMatrix, DVector};

/// A random positive definite 3 × 3 block and an approaching velocity.
fn random_block(rng: &mut SplitMix64) -> (DMatrix<f64>, Vec3) {
    let a = DMatrix::from_fn(3, 3, |_, _| rng.range(-1.0, 1.0));
    let w = &a * a.transpose() + DMatrix::identity(3, 3) * rng.range(0.05, 1.0);
    let v = Vec3::new(
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        -rng.range(0.05, 1.0),
    );
    (w, v)
}

fn one(w: &DMatrix<f64>, v: Vec3, mu: f64, e: f64) -> ContactProblem {
    let m = impax::math::Mat3::from_fn(|i, j| w[(i, j)]);
    ContactProblem::new(m, v, mu, e).unwrap()
}

/// With one contact, the enumeration (modes and Newton on the slip angle) agrees with the
/// one-contact spatial `lcp` (every solution of a trigonometric polynomial).
#[test]
fn one_contact_lcp_agrees_with_the_spatial_lcp() {
    let mut rng = SplitMix64(0x3d_1c);
    for _ in 0..800 {
        let (w, v) = random_block(&mut rng);
        let (mu, e) = (rng.range(0.0, 1.5), rng.unit());
        let p = MultiProblem::new(w.clone(), &[v.x, v.y, v.z], &[mu], &[e]).unwrap();
        let multi = spatial::lcp::resolve(&p).unwrap();
        let single = impax::LawId::Lcp.resolve(&one(&w, v, mu, e)).unwrap();
        let d = (multi.contacts[0].impulse - single.impulse).amax();
        assert!(
            d <= 1e-10 * single.impulse.amax().max(1e-300),
            "{w} {v} μ = {mu}, e = {e}: {} vs {}",
            multi.contacts[0].impulse,
            single.impulse
        );
        let count = |o: &spatial::MultiOutcome| match &o.detail {
            spatial::MultiDetail::Lcp { solutions } => solutions.len(),
            _ => 0,
        };
        let singles = impax::spatial::laws::lcp::solutions(&one(&w, v, mu, e)).len();
        assert_eq!(count(&multi), singles, "{w} {v} μ = {mu}, e = {e}");
    }
}

/// A block-diagonal W: each contact is its own one-contact problem, under `lcp` and
/// `sequential` (= `energetic`).
#[test]
fn decoupled_contacts_are_their_own_problems() {
    let mut rng = SplitMix64(0xdec0);
    for _ in 0..300 {
        let (w1, v1) = random_block(&mut rng);
        let (w2, v2) = random_block(&mut rng);
        let mut w = DMatrix::zeros(6, 6);
        w.view_mut((0, 0), (3, 3)).copy_from(&w1);
        w.view_mut((3, 3), (3, 3)).copy_from(&w2);
        let (mu, e) = (
            [rng.range(0.0, 1.2), rng.range(0.0, 1.2)],
            [rng.unit(), rng.unit()],
        );
        let v = [v1.x, v1.y, v1.z, v2.x, v2.y, v2.z];
        let p = MultiProblem::new(w, &v, &mu, &e).unwrap();
        let singles = [one(&w1, v1, mu[0], e[0]), one(&w2, v2, mu[1], e[1])];
        let seq = spatial::sequential::resolve(&p).unwrap();
        for (j, s) in singles.iter().enumerate() {
            let en = LawId::Energetic.resolve(s).unwrap();
            let d = (seq.contacts[j].impulse - en.impulse).amax();
            assert!(d <= 1e-12 * en.impulse.amax(), "sequential {j}: {d}");
        }
        if singles
            .iter()
            .all(|s| impax::spatial::laws::lcp::solutions(s).len() == 1)
        {
            let lcp = spatial::lcp::resolve(&p).unwrap();
            for (j, s) in singles.iter().enumerate() {
                let single = impax::LawId::Lcp.resolve(s).unwrap();
                let d = (lcp.contacts[j].impulse - single.impulse).amax();
                assert!(d <= 1e-10 * single.impulse.amax(), "lcp {j}: {d}");
            }
        }
    }
}

/// The planar problem embedded in 3D (a second tangent of its own, untouched): the spatial
/// laws give the planar multi-contact laws' velocities after.
#[test]
fn a_planar_problem_in_3d_is_the_planar_problem() {
    let mut rng = SplitMix64(0x91a4);
    let mut compared = 0;
    for _ in 0..400 {
        let r = super::support::random_multi(&mut rng, 2);
        let planar = &r.problem;
        let k = 2;
        // Rows t, n of each contact → t1, n; t2 decoupled with W_t2t2 = 1.
        let map = |i: usize| 3 * (i / 2) + if i.is_multiple_of(2) { 0 } else { 2 };
        let mut w = DMatrix::zeros(3 * k, 3 * k);
        for i in 0..2 * k {
            for j in 0..2 * k {
                w[(map(i), map(j))] = planar.w()[(i, j)];
            }
        }
        for c in 0..k {
            w[(3 * c + 1, 3 * c + 1)] = 1.0;
        }
        let mut v = vec![0.0; 3 * k];
        for i in 0..2 * k {
            v[map(i)] = planar.velocity()[i];
        }
        let mu: Vec<f64> = (0..k).map(|c| planar.friction(c)).collect();
        let e: Vec<f64> = (0..k).map(|c| planar.restitution(c)).collect();
        let Ok(p3) = MultiProblem::new(w, &v, &mu, &e) else {
            continue;
        };
        for law in [LawId::Lcp, LawId::Sequential] {
            let a = law.resolve(planar).unwrap();
            let b = spatial::resolve(law, &p3).unwrap();
            let (Ok(a), Ok(b)) = (a, b) else { continue };
            if matches!(&a.detail, impax::multi::MultiDetail::Lcp { solutions } if solutions.len() > 1)
            {
                continue;
            }
            let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for c in 0..k {
                let (pa, pb) = (a.contacts[c].velocity_after, b.contacts[c].velocity_after);
                assert!(
                    (pa.x - pb.x).abs() <= 1e-9 * scale
                        && (pa.y - pb.z).abs() <= 1e-9 * scale
                        && pb.y.abs() <= 1e-9 * scale,
                    "{law}: {pa} vs {pb}\n{planar:?}"
                );
            }
            compared += 1;
        }
    }
    assert!(compared > 500, "{compared}");
}

/// The contact rows of a box (half-sizes a, b, c; mass m) lying flat, its four lower
/// corners on the floor z = 0: per corner (t1 = x, t2 = y, n = z) the rows of
/// `v_corner = v + ω × r`, r = (±a, ±b, −c); u = (v, ω) and M = diag(m, m, m, I).
pub fn box_rows(a: f64, b: f64, c: f64) -> DMatrix<f64> {
    let corners = [(a, b), (-a, b), (-a, -b), (a, -b)];
    let mut j = DMatrix::zeros(12, 6);
    for (k, &(x, y)) in corners.iter().enumerate() {
        let r = Vec3::new(x, y, -c);
        for axis in 0..3 {
            j[(3 * k + axis, axis)] = 1.0;
            // (ω × r)_axis = Σ_q ε_{axis, q, s} ω_q r_s
            let e = Vec3::ith(axis, 1.0);
            let row = r.cross(&e); // ∂(ω × r)/∂ω · e_axis = r × e_axis
            for q in 0..3 {
                j[(3 * k + axis, 3 + q)] = row[q];
            }
        }
    }
    j
}

/// A box landing flat on four corners without spin: `lcp` lifts it level at `e |v_z|`,
/// each corner taking a quarter of `(1 + e) m |v_z|`, although `W` (12 × 12) has rank 6.
#[test]
fn a_box_landing_flat_leaves_level() {
    let (a, b, c, m) = (0.5, 0.3, 0.2, 2.0);
    let inertia = [
        m * (b * b + c * c) / 3.0,
        m * (a * a + c * c) / 3.0,
        m * (a * a + b * b) / 3.0,
    ];
    let masses = [m, m, m, inertia[0], inertia[1], inertia[2]];
    let j = box_rows(a, b, c);
    for (vx, vz, e, mu) in [
        (0.0, -1.0, 0.5, 0.4),
        (0.3, -2.0, 0.8, 0.1),
        (0.0, -1.0, 0.0, 1.0),
    ] {
        let u = DVector::from_vec(vec![vx, 0.0, vz, 0.0, 0.0, 0.0]);
        let (w, v) = contact_space(&j, &masses, &u);
        let p = MultiProblem::new(w, &v, &[mu], &[e]).unwrap();
        assert_eq!(p.rank(), 6);
        let out = spatial::lcp::resolve(&p).unwrap();
        let impulse = DVector::from_iterator(
            12,
            out.contacts
                .iter()
                .flat_map(|c| [c.impulse.x, c.impulse.y, c.impulse.z]),
        );
        let after = &u
            + DMatrix::from_diagonal(&DVector::from_iterator(6, masses.iter().map(|x| 1.0 / x)))
                * j.transpose()
                * impulse;
        // Level, at e |v_z|; the slide slowed by friction (μ (1 + e) |v_z| or to rest).
        let slide = (vx.abs() - mu * (1.0 + e) * vz.abs()).max(0.0) * vx.signum();
        let expect = [slide, 0.0, e * vz.abs(), 0.0, 0.0, 0.0];
        for i in 0..6 {
            assert!(
                (after[i] - expect[i]).abs() < 1e-12,
                "v = ({vx}, {vz}), e = {e}, μ = {mu}: u⁺ = {after}"
            );
        }
        if vx == 0.0 {
            // Symmetric: a quarter at each corner (the least-norm impulses of the family).
            for corner in &out.contacts {
                assert!((corner.impulse.z - m * (1.0 + e) * vz.abs() / 4.0).abs() < 1e-12);
            }
        }
    }
}

/// Random systems with 2 to 4 contacts (W singular for some): every `lcp` solution meets the
/// conditions to 1e-12 of the velocity scale, with `v⁺ = v⁻ + W p` recomputed here;
/// `sequential` never gains energy and leaves no contact approaching.
#[test]
fn random_problems_satisfy_the_conditions() {
    let mut rng = SplitMix64(0x5a7_1a1);
    let (mut solved, mut total) = (0usize, 0usize);
    for round in 0..400 {
        let k = 2 + round % 3;
        let Some((w, v)) = random_spatial_space(&mut rng, k) else {
            continue;
        };
        let mu: Vec<f64> = (0..k).map(|_| rng.range(0.0, 1.2)).collect();
        let e: Vec<f64> = (0..k).map(|_| rng.unit()).collect();
        let Ok(p) = MultiProblem::new(w.clone(), &v, &mu, &e) else {
            continue;
        };
        let seq = spatial::sequential::resolve(&p).unwrap();
        assert_ne!(seq.verdict, impax::law::Verdict::EnergyGained);
        assert!(seq.inconsistency.is_none(), "{:?}", seq.inconsistency);
        total += 1;
        let Ok(out) = spatial::lcp::resolve(&p) else {
            continue;
        };
        solved += 1;
        let spatial::MultiDetail::Lcp { solutions } = &out.detail else {
            panic!("lcp detail")
        };
        for s in solutions {
            assert_spatial_lcp_solution(&p, s, &format!("round {round}"));
        }
    }
    assert!(total > 330, "{total}");
    // Report how often a solution was found (existence is not proven for every W).
    assert!(
        solved as f64 >= 0.99 * total as f64,
        "lcp solved {solved} of {total}"
    );
}

/// The spatial dispatcher: a one-contact law at several contacts is refused naming `law`,
/// `lzb` runs; with one contact every spatial law runs.
#[test]
fn the_dispatcher_names_the_law() {
    let p = MultiProblem::from_upper(
        2,
        &[
            2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, -1.0, 2.0, 0.0,
            0.0, 2.0, 0.0, 2.0,
        ],
        &[0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
        &[0.0],
        &[1.0],
    )
    .unwrap();
    assert!(spatial::resolve(LawId::Lzb, &p).unwrap().is_ok());
    assert_eq!(
        spatial::resolve(LawId::Newton, &p).unwrap_err().field(),
        "law"
    );
    let lcp = spatial::resolve(LawId::Lcp, &p).unwrap().unwrap();
    assert!((lcp.contacts[0].impulse.z - 4.0 / 3.0).abs() < 1e-12);
    let q = MultiProblem::from_upper(
        1,
        &[3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
        &[0.5, 0.1, -1.0],
        &[0.3],
        &[0.6],
    )
    .unwrap();
    for law in LawId::SPATIAL {
        spatial::resolve(law, &q).unwrap().unwrap();
    }
    let _ = Planar::from_upper(1, &[1.0, 0.0, 1.0], &[0.0, -1.0], &[0.0], &[1.0]).unwrap();
}

/// The built-in `box-flat` spinning as it lands: `lcp` lifts it level at `e |v_z|`, the
/// corners slip round the vertical and friction takes `μ m (1 + e) |v_z| ρ` from `I_z ω_z`
/// (`ρ = √(a² + b²)`), or stops the spin; `sequential` never gains energy.
#[test]
fn box_flat_spin_under_lcp() {
    use impax::multi::scenarios::BoxFlat;
    for (spin, mu, e) in [
        (2.0, 0.3, 0.5),
        (5.0, 0.1, 1.0),
        (0.5, 1.0, 0.0),
        (-3.0, 0.2, 0.7),
    ] {
        let bx = BoxFlat {
            spin,
            ..BoxFlat::default()
        };
        let sc = bx.build().unwrap();
        let p = sc.impact.spatial_problem(&[mu], &[e]).unwrap();
        assert_eq!(p.rank(), 6);
        let r = sc.impact.resolve(LawId::Lcp, &p).unwrap();
        let out = r.resolution.as_ref().unwrap();
        let after = r.velocities_after.unwrap();
        let [a, b, _] = bx.half_extents;
        let m = bx.mass;
        let iz = m * (a * a + b * b) / 3.0;
        let pn = m * (1.0 + e);
        let slowed = spin.abs() - mu * pn * a.hypot(b) / iz;
        let expect_spin = slowed.max(0.0) * spin.signum();
        let expect = [0.0, 0.0, e, 0.0, 0.0, expect_spin];
        for i in 0..6 {
            assert!(
                (after[i] - expect[i]).abs() < 1e-10,
                "ω = {spin}, μ = {mu}, e = {e}: u⁺ = {after:?}, expected {expect:?}"
            );
        }
        assert!(
            (r.energy_change_from_velocities.unwrap() - out.energy_change).abs() < 1e-12,
            "ΔT two ways"
        );
        let seq = sc.impact.resolve(LawId::Sequential, &p).unwrap();
        let seq = seq.resolution.unwrap();
        assert!(seq.energy_change <= 1e-12, "{}", seq.energy_change);
    }
}
