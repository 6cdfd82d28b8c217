//! Impacts of spatial multibodies (theory §1, §5): the momentum balance
//! `M (u⁺ − u⁻) = Jᵀ p`, `ΔT` from the contact problem equal to `ΔT` from the speeds, every
//! spatial law on robot feet, `energetic` never gaining energy over 10⁴ random solo12 foot
//! impacts (floating base, random `q`, `u`, `μ ∈ [0, 2]`, `e ∈ [0, 1]`), four feet landing
//! at once as a multi-contact problem, and the refusals.

use super::multibody_models::*;
use impax::law::Verdict;
use impax::math::{Mat3, SplitMix64, Vec3};
use impax::multibody::{
    Body, ContactPoint, Joint, Model, Placement, SpatialMechanismImpact,
    SpatialMechanismMultiImpact,
};
use impax::LawId;
use nalgebra::DVector;

/// A random approaching impact of a random contact: `u` is reversed if the contact
/// separates (`v_n → −v_n`).
fn random_impact<'a>(model: &'a Model, rng: &mut SplitMix64) -> SpatialMechanismImpact<'a> {
    loop {
        let (q, mut u) = random_state(model, rng);
        let k = (rng.unit() * model.contacts().len() as f64) as usize;
        let imp = SpatialMechanismImpact::new(model, &q, &u, k).unwrap();
        if imp.contact_velocity().z == 0.0 {
            continue;
        }
        if imp.contact_velocity().z > 0.0 {
            u.iter_mut().for_each(|x| *x = -*x);
            return SpatialMechanismImpact::new(model, &q, &u, k).unwrap();
        }
        return imp;
    }
}

/// The backward error of the momentum balance, `|M (u⁺ − u⁻) − Jᵀ p|` over
/// `|M| |u⁺ − u⁻| + |Jᵀ p|` (largest entries: round-off of the Cholesky solve, whatever the
/// condition number of `M`, about 10⁵ for solo12's light legs on its heavy base), and `ΔT`
/// from the speeds against the contact problem's over `T⁻`.
fn identities(
    imp: &SpatialMechanismImpact,
    p: Vec3,
    after: &[f64],
    de_contact: f64,
    de_speeds: f64,
) -> (f64, f64) {
    let du = DVector::from_iterator(
        after.len(),
        after
            .iter()
            .zip(imp.velocities_before())
            .map(|(a, b)| a - b),
    );
    let scale = imp.mass_matrix().amax() * du.amax();
    let lhs = imp.mass_matrix() * du;
    let rhs = imp.jacobian().transpose() * p;
    let scale = scale + rhs.amax();
    let e_momentum = (0..lhs.len())
        .map(|i| (lhs[i] - rhs[i]).abs())
        .fold(0.0, f64::max)
        / scale;
    let e_energy = (de_contact - de_speeds).abs() / imp.energy_before();
    (e_momentum, e_energy)
}

#[test]
fn multibody_impact_every_spatial_law_balances_momentum_and_energy() {
    let mut worst = (0.0f64, 0.0f64);
    for (name, model) in [
        ("solo12", solo12(true)),
        ("hand tree", hand_tree(true, 4)),
        ("ur5", ur5()),
    ] {
        let mut rng = SplitMix64(21);
        for _ in 0..30 {
            let imp = random_impact(&model, &mut rng);
            let (mu, e) = (rng.range(0.0, 1.5), rng.range(0.0, 1.0));
            for law in LawId::SPATIAL {
                let Ok(out) = imp.resolve(law, mu, e) else {
                    // (ur5's tool flange cannot move in every direction at some configurations:
                    // a singular W is refused by the problem.)
                    continue;
                };
                let Ok(o) = &out.resolution else { continue };
                let after = out.velocities_after.as_ref().unwrap();
                let (em, ee) = identities(
                    &imp,
                    o.impulse,
                    after,
                    o.energy_change,
                    out.energy_change_from_velocities.unwrap(),
                );
                assert!(em < 1e-12, "{name}, {law}: momentum {em:e}");
                assert!(ee < 1e-10, "{name}, {law}: ΔT {ee:e}");
                // The contact velocity after, from the speeds, is the law's.
                let v = imp.jacobian() * DVector::from_column_slice(after);
                let ev = (0..3)
                    .map(|i| (v[i] - o.velocity_after[i]).abs())
                    .fold(0.0, f64::max)
                    / imp.contact_velocity().amax();
                assert!(ev < 1e-9, "{name}, {law}: v⁺ {ev:e}");
                worst = (worst.0.max(em), worst.1.max(ee));
            }
        }
    }
    println!(
        "every law: worst momentum residual {:.2e}, worst ΔT mismatch {:.2e} (of T⁻)",
        worst.0, worst.1
    );
}

/// `energetic` never gains energy over 10⁴ random solo12 foot impacts.
#[test]
fn multibody_impact_energetic_never_gains_energy_on_solo12() {
    let model = solo12(true);
    let mut rng = SplitMix64(2026);
    let (mut worst_gain, mut worst_momentum, mut worst_energy) =
        (f64::NEG_INFINITY, 0.0f64, 0.0f64);
    let mut breakdowns = 0;
    const N: usize = 10_000;
    for _ in 0..N {
        let imp = random_impact(&model, &mut rng);
        let (mu, e) = (rng.range(0.0, 2.0), rng.range(0.0, 1.0));
        let out = imp.resolve(LawId::Energetic, mu, e).unwrap();
        let Ok(o) = &out.resolution else {
            breakdowns += 1;
            continue;
        };
        assert_ne!(o.verdict, Verdict::EnergyGained, "{o:?}");
        let t0 = imp.energy_before();
        let gain = out.energy_change_from_velocities.unwrap() / t0;
        assert!(gain <= 1e-12, "ΔT/T⁻ = {gain:e}");
        let after = out.velocities_after.as_ref().unwrap();
        let (em, ee) = identities(
            &imp,
            o.impulse,
            after,
            o.energy_change,
            out.energy_change_from_velocities.unwrap(),
        );
        assert!(em < 1e-12 && ee < 1e-10, "momentum {em:e}, ΔT {ee:e}");
        worst_gain = worst_gain.max(gain);
        worst_momentum = worst_momentum.max(em);
        worst_energy = worst_energy.max(ee);
    }
    assert_eq!(breakdowns, 0);
    println!(
        "{N} solo12 foot impacts, energetic: largest ΔT/T⁻ {worst_gain:.2e}, momentum residual {worst_momentum:.2e}, ΔT mismatch {worst_energy:.2e}"
    );
}

/// A free sphere on its bottom point, off the origin and turned: `W = diag(7/2, 7/2, 1)/m`,
/// and a frictionless impact gives `p_n = −(1 + e) v_n⁻ / W_nn`.
#[test]
fn multibody_impact_free_sphere() {
    let (m, r) = (2.0, 0.3);
    let ball = Body::new(
        "ball",
        m,
        Vec3::zeros(),
        Mat3::identity() * (0.4 * m * r * r),
    );
    let foot = ContactPoint::new("bottom", 0, Vec3::zeros(), r);
    let model = Model::new(vec![ball], vec![Joint::free("root", 0)], vec![foot]).unwrap();
    let mut rng = SplitMix64(5);
    let quat = random_quaternion(&mut rng);
    let q = [3.0, -2.0, r, quat[0], quat[1], quat[2], quat[3]];
    let u = [0.4, -0.3, -1.5, 2.0, 1.0, -3.0];
    let imp = SpatialMechanismImpact::new(&model, &q, &u, 0).unwrap();
    assert!(imp.gap().abs() < 1e-15);
    let w = imp.inverse_inertia();
    let expected = Mat3::from_diagonal(&Vec3::new(3.5, 3.5, 1.0)) / m;
    assert!((w - expected).amax() < 1e-14, "{w}");
    // v = v_c + ω × (−r e_z).
    let v =
        Vec3::new(u[0], u[1], u[2]) + Vec3::new(u[3], u[4], u[5]).cross(&Vec3::new(0.0, 0.0, -r));
    assert!((imp.contact_velocity() - v).amax() < 1e-15);
    let out = imp.resolve(LawId::Energetic, 0.0, 0.6).unwrap();
    let p = out.resolution.unwrap().impulse;
    assert!((p.z - 1.6 * 1.5 / w[(2, 2)]).abs() < 1e-12);
}

/// A free sphere of radius 1e-7 (rotational entries of `M` 4e-15 of the translational
/// ones, refused as singular when pivots were judged against the largest diagonal entry)
/// strikes as the sphere of radius 1 does with its spin scaled by `1/r`: the same contact
/// problem, the same impulse, the same linear speeds after and the spin after scaled alike.
#[test]
fn multibody_impact_a_tiny_sphere_strikes_as_a_large_one() {
    let strike = |r: f64| {
        let ball = Body::new(
            "ball",
            1.5,
            Vec3::zeros(),
            Mat3::identity() * (0.4 * 1.5 * r * r),
        );
        let foot = ContactPoint::new("bottom", 0, Vec3::zeros(), r);
        let model = Model::new(vec![ball], vec![Joint::free("root", 0)], vec![foot]).unwrap();
        let q = [0.0, 0.0, r, 1.0, 0.0, 0.0, 0.0];
        let u = [0.4, -0.3, -1.5, 2.0 / r, 1.0 / r, -3.0 / r];
        let imp = SpatialMechanismImpact::new(&model, &q, &u, 0).unwrap();
        let out = imp.resolve(LawId::Energetic, 0.3, 0.6).unwrap();
        let p = out.resolution.unwrap().impulse;
        let after = out.velocities_after.unwrap();
        (imp.inverse_inertia(), p, after)
    };
    let (w1, p1, u1) = strike(1.0);
    let (w, p, u) = strike(1e-7);
    assert!((w - w1).amax() < 1e-14, "{w} against {w1}");
    assert!((p - p1).amax() < 1e-13 * p1.amax(), "{p} against {p1}");
    for i in 0..3 {
        assert!(
            (u[i] - u1[i]).abs() < 1e-13,
            "u[{i}]: {} against {}",
            u[i],
            u1[i]
        );
        let spin = u[3 + i] * 1e-7;
        assert!(
            (spin - u1[3 + i]).abs() < 1e-12,
            "spin {i}: {spin} against {}",
            u1[3 + i]
        );
    }
}

/// solo12 landing on four feet at once: `W` (12 × 12) of rank 12 from 18 dof; `lcp` and
/// `sequential` satisfy the momentum balance, and `sequential` (energetic binary impacts)
/// dissipates.
#[test]
fn multibody_impact_four_feet_at_once() {
    let model = solo12(true);
    let mut q = model.neutral();
    q[2] = 0.3;
    let hip = [0.0, 0.8, -1.6];
    for leg in 0..4 {
        q[7 + 3 * leg..10 + 3 * leg].copy_from_slice(&hip);
    }
    let mut u = vec![0.0; model.nv()];
    u[0] = 0.2;
    u[2] = -1.0;
    u[4] = 0.3;
    let imp = SpatialMechanismMultiImpact::new(&model, &q, &u, &[0, 1, 2, 3]).unwrap();
    assert_eq!(imp.inverse_inertia().shape(), (12, 12));
    let problem = imp.problem(&[0.8], &[0.2]).unwrap();
    assert_eq!(problem.rank(), 12);
    for law in [LawId::Lcp, LawId::Sequential] {
        let out = imp.resolve(law, &[0.8], &[0.2]).unwrap();
        let o = out.resolution.as_ref().unwrap();
        let after = out.velocities_after.as_ref().unwrap();
        let p: Vec<f64> = o.impulses().iter().flat_map(|p| [p.x, p.y, p.z]).collect();
        let du = DVector::from_iterator(u.len(), after.iter().zip(&u).map(|(a, b)| a - b));
        let r = imp.mass_matrix() * du - imp.jacobian().transpose() * DVector::from_vec(p);
        assert!(r.amax() < 1e-12, "{law}: {}", r.amax());
        let de = out.energy_change_from_velocities.unwrap();
        assert!(
            (de - o.energy_change).abs() < 1e-10 * imp.energy_before(),
            "{law}"
        );
        if law == LawId::Sequential {
            assert!(de < 0.0);
        }
    }
    let e = SpatialMechanismMultiImpact::new(&model, &q, &u, &[0, 0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "contacts: contact 0 (FL_FOOT) is listed twice"
    );
}

#[test]
fn multibody_impact_refusals() {
    let model = solo12(true);
    let (q, u) = (model.neutral(), vec![0.0; 18]);
    let e = SpatialMechanismImpact::new(&model, &q, &u, 4).unwrap_err();
    assert_eq!(e.to_string(), "contact: index 4 out of range: the model has 4 contact(s) (FL_FOOT, FR_FOOT, HL_FOOT, HR_FOOT)");
    let e = SpatialMechanismImpact::new(&model, &q, &u[..17], 0).unwrap_err();
    assert_eq!(e.field(), "u");
    // At rest nothing approaches.
    let imp = SpatialMechanismImpact::new(&model, &q, &u, 0).unwrap();
    assert_eq!(imp.problem(0.5, 0.5).unwrap_err().field(), "v");
    // A massless moving link: the mass matrix names its coordinate.
    let bodies = vec![
        Body::new("base", 1.0, Vec3::zeros(), Mat3::identity()),
        Body::new("flag", 0.0, Vec3::zeros(), Mat3::zeros()),
    ];
    let joints = vec![
        Joint::free("root", 0),
        Joint::revolute("spin", Vec3::z(), Some(0), 1, Placement::identity()),
    ];
    let model = Model::new(
        bodies,
        joints,
        vec![ContactPoint::new("c", 0, Vec3::zeros(), 0.0)],
    )
    .unwrap();
    let e = SpatialMechanismImpact::new(&model, &model.neutral(), &[0.0; 7], 0).unwrap_err();
    assert!(e.to_string().starts_with("mass matrix: must be positive definite, but the coordinate spin (speed 6) moves no mass"), "{e}");
}
