//! The one contract of every struck system ([`impax::impact::Impact`]): the kinetic energy of
//! the whole system after the law's impulse, less the energy before, is the outcome's
//! `ΔT = v⁻·p + ½ pᵀ W p` (theory §1) — for bodies on a surface and between two bodies,
//! planar and spatial, and for mechanisms (planar, and spatial: solo12 with a floating base),
//! under every law that resolves, at random states.

use impax::impact::Impact;
use impax::math::{SplitMix64, UnitQuat, Vec3};
use impax::mechanism::builtin::DoublePendulum;
use impax::mechanism::impact::MechanismImpact;
use impax::planar::bodies::{self as planar_bodies, Side};
use impax::spatial::bodies as spatial_bodies;
use impax::LawId;

/// `|a − b| ≤ 1e-12` of the energy scale `T⁻ + T⁺`.
fn agree(from_velocities: f64, from_outcome: f64, before: f64, what: &str) {
    let scale = before + (before + from_outcome).abs();
    assert!(
        (from_velocities - from_outcome).abs() <= 1e-12 * scale,
        "{what}: ΔT from the velocities {from_velocities} vs the outcome's {from_outcome} \
         (T⁻ = {before})"
    );
}

#[test]
fn planar_bodies_one_and_two() {
    let mut rng = SplitMix64(0x1a2b_3c4d);
    let mut checked = 0;
    for i in 0..400 {
        let body = match i % 3 {
            0 => planar_bodies::sphere(rng.range(0.1, 10.0), rng.range(0.1, 2.0), Side::Below),
            1 => planar_bodies::rod(
                rng.range(0.1, 10.0),
                rng.range(0.1, 3.0),
                rng.range(0.1, 3.0),
                Side::Below,
            ),
            _ => planar_bodies::ellipse(
                rng.range(0.1, 10.0),
                rng.range(0.1, 2.0),
                rng.range(0.1, 2.0),
                rng.range(-3.0, 3.0),
                Side::Below,
            ),
        }
        .unwrap();
        let state = planar_bodies::BodyState::new(
            rng.range(-2.0, 2.0),
            rng.range(-3.0, -0.1),
            rng.range(-5.0, 5.0),
        );
        let impact = if i % 2 == 0 {
            planar_bodies::BodyImpact::on_fixed_surface(body, state)
        } else {
            let other = planar_bodies::sphere(rng.range(0.1, 10.0), 0.5, Side::Above).unwrap();
            let other_state = planar_bodies::BodyState::new(
                rng.range(-1.0, 1.0),
                rng.range(-0.5, 0.5),
                rng.range(-2.0, 2.0),
            );
            planar_bodies::BodyImpact::between(body, state, other, other_state)
        };
        let Ok(problem) = Impact::problem(&impact, rng.range(0.0, 1.5), rng.unit()) else {
            continue;
        };
        for law in LawId::ALL {
            let Ok(out) = impact.resolve(law, &problem) else {
                continue;
            };
            let de = impact.energy_change(&out.outcome.impulse);
            agree(
                de,
                out.outcome.energy_change,
                impact.kinetic_energy_before(),
                law.as_str(),
            );
            // The outcome's own split (translational + rotational) is of the same ΔT.
            agree(
                out.energy_change.translational + out.energy_change.rotational,
                de,
                impact.kinetic_energy_before(),
                law.as_str(),
            );
            checked += 1;
        }
    }
    assert!(checked > 2_000, "{checked}");
}

#[test]
fn spatial_bodies_one_and_two() {
    let mut rng = SplitMix64(0x5e6f_7a8b);
    let mut checked = 0;
    for i in 0..300 {
        let q = UnitQuat::from_euler_angles(
            rng.range(-3.0, 3.0),
            rng.range(-1.5, 1.5),
            rng.range(-3.0, 3.0),
        );
        let body = if i % 2 == 0 {
            spatial_bodies::cuboid(
                rng.range(0.1, 10.0),
                [
                    rng.range(0.1, 2.0),
                    rng.range(0.1, 2.0),
                    rng.range(0.1, 2.0),
                ],
                q,
                None,
                Side::Below,
            )
        } else {
            spatial_bodies::ellipsoid(
                rng.range(0.1, 10.0),
                [
                    rng.range(0.1, 2.0),
                    rng.range(0.1, 2.0),
                    rng.range(0.1, 2.0),
                ],
                q,
                Side::Below,
            )
        }
        .unwrap();
        let state = spatial_bodies::BodyState::new(
            Vec3::new(
                rng.range(-2.0, 2.0),
                rng.range(-2.0, 2.0),
                rng.range(-3.0, -0.1),
            ),
            Vec3::new(
                rng.range(-4.0, 4.0),
                rng.range(-4.0, 4.0),
                rng.range(-4.0, 4.0),
            ),
        );
        let impact = if i % 3 == 0 {
            let other = spatial_bodies::sphere(rng.range(0.1, 10.0), 0.5, Side::Above).unwrap();
            let s = spatial_bodies::BodyState::new(
                Vec3::new(
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                    rng.range(-0.5, 0.5),
                ),
                Vec3::new(
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                ),
            );
            spatial_bodies::BodyImpact::between(body, state, other, s)
        } else {
            spatial_bodies::BodyImpact::on_fixed_surface(body, state)
        };
        let Ok(problem) = Impact::problem(&impact, rng.range(0.0, 1.5), rng.unit()) else {
            continue;
        };
        for law in LawId::SPATIAL {
            let Ok(out) = impact.resolve(law, &problem) else {
                continue;
            };
            let de = impact.energy_change(&out.outcome.impulse);
            agree(
                de,
                out.outcome.energy_change,
                impact.kinetic_energy_before(),
                law.as_str(),
            );
            checked += 1;
        }
    }
    assert!(checked > 1_000, "{checked}");
}

#[test]
fn mechanisms() {
    let mut rng = SplitMix64(0x9c0d_1e2f);
    let mut checked = 0;
    for _ in 0..150 {
        let q = [rng.range(-1.4, 1.4), rng.range(-1.4, 1.4)];
        let u = [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)];
        let pendulum = DoublePendulum::unit_at(q);
        let Ok(impact) = MechanismImpact::new(&pendulum, &q, &u, 0) else {
            continue;
        };
        let Ok(problem) = Impact::problem(&impact, rng.range(0.0, 1.5), rng.unit()) else {
            continue;
        };
        for law in LawId::CONTACT_SPACE {
            let Ok(out) = law.resolve(&problem) else {
                continue;
            };
            let de = impact.energy_change(&out.impulse);
            agree(
                de,
                out.energy_change,
                impact.kinetic_energy_before(),
                law.as_str(),
            );
            checked += 1;
        }
    }
    assert!(checked > 300, "{checked}");
}

#[test]
fn spatial_mechanisms() {
    use crate::multibody_models::{random_state, solo12};
    use impax::multibody::SpatialMechanismImpact;
    let model = solo12(true);
    let mut rng = SplitMix64(0x3141_5926);
    let mut checked = 0;
    for _ in 0..60 {
        let (q, u) = random_state(&model, &mut rng);
        let k = (rng.unit() * model.contacts().len() as f64) as usize;
        let Ok(impact) = SpatialMechanismImpact::new(&model, &q, &u, k) else {
            continue;
        };
        let Ok(problem) = Impact::problem(&impact, rng.range(0.0, 1.5), rng.unit()) else {
            continue; // a separating contact
        };
        for law in LawId::SPATIAL {
            let Ok(out) = law.resolve(&problem) else {
                continue;
            };
            let de = impact.energy_change(&out.impulse);
            agree(
                de,
                out.energy_change,
                impact.kinetic_energy_before(),
                law.as_str(),
            );
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked}");
}
