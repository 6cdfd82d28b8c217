//! A robot read once ([`RobotSpec::load`]) and put at many states ([`Robot::at`]) is the robot
//! built from scratch at each ([`RobotSpec::build`]): the same model, state, contact and
//! floor; the contacts of a URDF robot named after reading it sit where the reader puts them;
//! a file's striking contact is the lowest at each state.

use super::multibody_models::{random_quaternion, FEET, SOLO12};
use impax::math::SplitMix64;
use impax::multibody::{read_urdf, ContactSpec, SpatialMechanismImpact, UrdfOptions};
use impax::scenario::{MechanismFile, RobotSource, RobotSpec};
use impax::LawId;

const ARM: &str = include_str!("../../../../examples/mechanisms/arm-3d.toml");

fn solo12_spec() -> RobotSpec {
    RobotSpec {
        floating_base: true,
        ..RobotSpec::new("", RobotSource::Urdf(SOLO12.into()))
    }
}

/// A random floating-base state of solo12.
fn state(rng: &mut SplitMix64) -> (Vec<f64>, Vec<f64>) {
    let mut q = vec![
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        rng.range(0.1, 0.5),
    ];
    q.extend(random_quaternion(rng));
    q.extend((0..12).map(|_| rng.range(-2.0, 2.0)));
    let u = (0..18).map(|_| rng.range(-2.0, 2.0)).collect();
    (q, u)
}

#[test]
fn robot_load_at_equals_build() {
    let robot = solo12_spec().load().unwrap();
    assert!(robot.is_urdf());
    assert_eq!(robot.name(), "solo");
    assert!(robot.contact_names().contains(&"FL_FOOT"));
    let mut rng = SplitMix64(20);
    for i in 0..40 {
        let (q, u) = state(&mut rng);
        let contact = format!("{}:0,0,{}", FEET[i % 4], -0.01 * (i % 3) as f64);
        let built = RobotSpec {
            q: Some(q.clone()),
            u: Some(u.clone()),
            contact: Some(contact.clone()),
            ..solo12_spec()
        }
        .build()
        .unwrap();
        let at = robot.at(Some(&q), Some(&u), Some(&contact)).unwrap();
        assert_eq!(at, built);
        assert!(at.impact().unwrap().gap().abs() < 1e-15);
        // The model struck at the contact, reused: the same impact, bit for bit.
        let model = robot.struck_by(Some(&contact)).unwrap();
        let q_checked = model.check_state(&q, None).unwrap();
        let k = robot
            .striking_contact(&model, Some(&contact), &q_checked)
            .unwrap();
        let a = SpatialMechanismImpact::new(&model, &q_checked, &u, k).unwrap();
        let b = at.impact().unwrap();
        assert_eq!(a.inverse_inertia(), b.inverse_inertia());
        assert_eq!(a.contact_velocity(), b.contact_velocity());
        if a.contact_velocity().z < 0.0 {
            let (ra, rb) = (
                a.resolve(LawId::Energetic, 0.6, 0.4).unwrap(),
                b.resolve(LawId::Energetic, 0.6, 0.4).unwrap(),
            );
            assert_eq!(ra.velocities_after, rb.velocities_after);
        }
    }
}

#[test]
fn robot_load_contacts_named_after_reading() {
    let urdf = read_urdf(SOLO12, &UrdfOptions::default()).unwrap();
    for spec in ["FL_FOOT", "HR_LOWER_LEG:0,0.008,-0.16", "base_link:0.1,0,0"] {
        let spec = ContactSpec::parse(spec).unwrap();
        let options = UrdfOptions::default().contact(spec.clone());
        let read = read_urdf(SOLO12, &options).unwrap().model.contacts()[0].clone();
        assert_eq!(urdf.contact_point(&spec).unwrap(), read);
    }
    let robot = solo12_spec().load().unwrap();
    for (contact, field, words) in [
        (None, "contact", "which link strikes"),
        (Some("TOE"), "contact[TOE]", "unknown link \"TOE\""),
        (Some("FL_FOOT:1,2"), "contact", "three finite numbers"),
    ] {
        let e = robot.at(None, None, contact).unwrap_err();
        assert_eq!(e.field(), field);
        assert!(e.to_string().contains(words), "{e}");
    }
}

#[test]
fn robot_load_file_strikes_with_its_lowest_contact() {
    let mut file = MechanismFile::parse(ARM).unwrap();
    // A second contact, at the elbow.
    let mut elbow = file.contacts[0].clone();
    elbow.name = Some("elbow".into());
    elbow.body = "upper arm".into();
    file.contacts.push(elbow);
    let robot = RobotSpec::new("arm", RobotSource::File(Box::new(file)))
        .load()
        .unwrap();
    assert!(!robot.is_urdf());
    assert_eq!(robot.contact_names(), ["tip", "elbow"]);
    let (q0, u0) = robot.default_state();
    assert_eq!((q0, u0), (vec![0.3, 0.6, -0.8], vec![0.5, -1.0, 2.0]));
    // Hanging straight down the tip is lowest; folded up by the elbow, the elbow is.
    let down = robot.at(Some(&[0.0, 0.0, 0.0]), None, None).unwrap();
    let folded = robot.at(Some(&[0.0, 0.0, 3.0]), None, None).unwrap();
    assert_eq!((down.contact, folded.contact), (0, 1));
    assert_eq!(down.model.floor(), -2.0);
    let named = robot.at(Some(&[0.0, 0.0, 3.0]), None, Some("tip")).unwrap();
    assert_eq!(named.contact, 0);
    let e = robot.at(None, None, Some("knee")).unwrap_err();
    assert_eq!(e.field(), "contact");
    assert!(e.to_string().contains("its contacts: tip, elbow"), "{e}");
    let e = RobotSpec {
        floor: Some(f64::NAN),
        ..RobotSpec::new(
            "arm",
            RobotSource::File(Box::new(MechanismFile::parse(ARM).unwrap())),
        )
    }
    .load()
    .unwrap_err();
    assert_eq!(e.field(), "floor");
}
