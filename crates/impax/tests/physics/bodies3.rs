//! Spatial bodies: `W` equals the contact-velocity response to unit impulses, momentum
//! balance and energy split hold, the ellipsoid's contact point has the plane's normal, and a
//! sphere in 3D reproduces the planar sphere.

use impax::math::{Mat3, Vec3};
use impax::planar::bodies::{self, Side};
use impax::spatial::bodies::{
    cuboid, cylinder, ellipsoid, sphere, BodyImpact, BodyState, RigidBody,
};
use impax::LawId;
use nalgebra::UnitQuaternion;

fn q(roll: f64, pitch: f64, yaw: f64) -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(roll, pitch, yaw)
}

fn bodies() -> Vec<RigidBody> {
    vec![
        sphere(2.0, 0.5, Side::Below).unwrap(),
        ellipsoid(1.5, [2.0, 1.0, 0.5], q(0.3, -0.7, 1.1), Side::Below).unwrap(),
        cuboid(3.0, [1.0, 0.6, 0.3], q(0.2, 0.4, 0.1), None, Side::Below).unwrap(),
        cylinder(1.0, 0.4, 1.0, q(0.5, 0.2, 0.0), Side::Below).unwrap(),
        RigidBody::new(
            2.0,
            Mat3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 2.5),
            q(1.0, 0.5, -0.3),
            Vec3::new(0.3, -0.2, -0.8),
        )
        .unwrap(),
    ]
}

#[test]
fn w_is_the_response_to_unit_impulses_and_momentum_balances() {
    let state = BodyState::new(Vec3::new(0.3, -0.2, -1.0), Vec3::new(0.5, 1.0, -2.0));
    for b in bodies() {
        let w = b.inverse_inertia();
        assert!((w - w.transpose()).abs().max() < 1e-14);
        assert!(w.cholesky().is_some());
        let v0 = b.contact_velocity(&state);
        for i in 0..3 {
            let mut p = Vec3::zeros();
            p[i] = 1.0;
            let after = b.apply(&state, p);
            let dv = b.contact_velocity(&after) - v0;
            assert!(
                (dv - w.column(i)).abs().max() < 1e-13,
                "{dv:?} vs {:?}",
                w.column(i)
            );
            // m Δv = p, I Δω = r × p
            assert!(
                ((after.velocity - state.velocity) * b.mass() - p)
                    .abs()
                    .max()
                    < 1e-14
            );
            let dl = b.inertia() * (after.omega - state.omega) - b.contact().cross(&p);
            assert!(dl.abs().max() < 1e-13);
        }
    }
}

#[test]
fn ellipsoid_contact_point_has_the_plane_normal() {
    let (axes, rot) = ([2.0, 1.0, 0.5], q(0.3, -0.7, 1.1));
    let b = ellipsoid(1.0, axes, rot, Side::Below).unwrap();
    let r_body = rot.inverse() * b.contact();
    // On the surface: Σ (x_i/a_i)² = 1.
    let s: f64 = (0..3).map(|i| (r_body[i] / axes[i]).powi(2)).sum();
    assert!((s - 1.0).abs() < 1e-14);
    // Outward normal ∝ (x/a², y/b², z/c²) in the body frame, rotated: must be −z.
    let n = rot * Vec3::new(r_body[0] / 4.0, r_body[1] / 1.0, r_body[2] / 0.25);
    let n = n / n.norm();
    assert!((n - Vec3::new(0.0, 0.0, -1.0)).norm() < 1e-14, "{n:?}");
}

#[test]
fn degenerate_contacts_are_errors_not_numbers() {
    assert!(cuboid(
        1.0,
        [1.0, 1.0, 1.0],
        UnitQuaternion::identity(),
        None,
        Side::Below
    )
    .is_err());
    assert!(cylinder(1.0, 1.0, 1.0, UnitQuaternion::identity(), Side::Below).is_err());
    assert!(cuboid(
        1.0,
        [1.0, 1.0, 1.0],
        UnitQuaternion::identity(),
        Some([1.0, -1.0, -1.0]),
        Side::Below
    )
    .is_ok());
    // Principal moments that no rigid body has.
    assert!(RigidBody::new(
        1.0,
        Mat3::from_diagonal(&Vec3::new(1.0, 1.0, 3.0)),
        UnitQuaternion::identity(),
        Vec3::zeros()
    )
    .is_err());
    assert!(sphere(-1.0, 1.0, Side::Below).is_err());
}

#[test]
fn sphere_in_3d_reproduces_the_planar_sphere() {
    let alpha = 30f64.to_radians();
    for gamma in [-1.5, -0.5, 0.0, 0.2, 1.0] {
        let s2 = bodies::spin_state(1.0, alpha, gamma, 1.0).unwrap();
        let i2 = bodies::BodyImpact::on_fixed_surface(
            bodies::sphere(1.0, 1.0, Side::Below).unwrap(),
            s2,
        );
        let p2 = i2.problem(0.4, 0.7).unwrap();
        // Planar ω (counter-clockwise in (t, n) = (x, z)) is a rotation about −y in 3D.
        let s3 = BodyState::new(
            Vec3::new(s2.velocity.x, 0.0, s2.velocity.y),
            Vec3::new(0.0, -s2.omega, 0.0),
        );
        let i3 = BodyImpact::on_fixed_surface(sphere(1.0, 1.0, Side::Below).unwrap(), s3);
        let p3 = i3.problem(0.4, 0.7).unwrap();
        for law in [
            LawId::Whittaker,
            LawId::Brach,
            LawId::Newton,
            LawId::Poisson,
            LawId::Energetic,
        ] {
            let a = i2.resolve(law, &p2).unwrap();
            let b = i3.resolve(law, &p3).unwrap();
            assert!(
                (a.outcome.impulse.x - b.outcome.impulse.x).abs() < 1e-12,
                "{law} γ={gamma}"
            );
            assert!(
                (a.outcome.impulse.y - b.outcome.impulse.z).abs() < 1e-12,
                "{law} γ={gamma}"
            );
            assert!(
                (a.body_after.omega + b.body_after.omega.y).abs() < 1e-12,
                "{law} γ={gamma}"
            );
            assert!((a.outcome.energy_change - b.outcome.energy_change).abs() < 1e-12);
            let split = b.body_energy_change;
            assert!((split.total() - b.outcome.energy_change).abs() < 1e-12);
        }
    }
}

#[test]
fn two_bodies_share_the_impulse_and_conserve_momentum() {
    let a = ellipsoid(1.0, [1.0, 0.7, 0.5], q(0.2, 0.3, 0.4), Side::Below).unwrap();
    let b = cuboid(2.0, [1.0, 0.8, 0.6], q(-0.3, 0.2, 0.1), None, Side::Above).unwrap();
    let sa = BodyState::new(Vec3::new(0.4, 0.1, -1.0), Vec3::new(0.3, -0.5, 1.0));
    let sb = BodyState::new(Vec3::new(-0.1, 0.2, 0.3), Vec3::new(0.0, 0.4, -0.2));
    let imp = BodyImpact::between(a, sa, b, sb);
    let p = imp.problem(0.5, 0.6).unwrap();
    for law in [LawId::Whittaker, LawId::Brach, LawId::Energetic] {
        let r = imp.resolve(law, &p).unwrap();
        let sb1 = r.other_after.unwrap();
        let momentum0 = sa.velocity * a.mass() + sb.velocity * b.mass();
        let momentum1 = r.body_after.velocity * a.mass() + sb1.velocity * b.mass();
        assert!((momentum0 - momentum1).abs().max() < 1e-13);
        let de = r.body_energy_change.total() + r.other_energy_change.total();
        assert!(
            (de - r.outcome.energy_change).abs() < 1e-12 * (1.0 + de.abs()),
            "{law}: {de} vs {}",
            r.outcome.energy_change
        );
        let v_after = a.contact_velocity(&r.body_after) - b.contact_velocity(&sb1);
        assert!((v_after - r.outcome.velocity_after).abs().max() < 1e-12);
    }
}
