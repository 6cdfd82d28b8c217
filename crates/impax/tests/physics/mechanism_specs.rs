//! The built-in mechanisms as front ends describe them (`impax::scenario::MechanismSpec`): the
//! same mechanism and state whether the angles are written in degrees (files, flags) or in
//! radians (Python); the defaults put the striking contact on its surface; errors name the key
//! as the caller spells it.

use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::dynamics;
use impax::scenario::{AngleUnit, MechanismSpec};

fn spec(name: &str) -> MechanismSpec {
    MechanismSpec {
        mechanism: name.into(),
        ..MechanismSpec::default()
    }
}

#[test]
fn degrees_and_radians_describe_the_same_state() {
    for (name, angles) in [
        ("double-pendulum", vec![25.0, -10.0]),
        ("sphere", vec![15.0]),
        ("rod", vec![35.0]),
        ("ring-pendulum", vec![40.0]),
        ("cart-pendulum", vec![-20.0]),
    ] {
        let deg = MechanismSpec {
            angles: Some(angles.clone()),
            ..spec(name)
        };
        let rad = MechanismSpec {
            angles: Some(angles.iter().map(|a: &f64| a.to_radians()).collect()),
            angle_unit: AngleUnit::Radians,
            ..spec(name)
        };
        let (d, r) = (deg.build().unwrap(), rad.build().unwrap());
        assert_eq!(d.mechanism, r.mechanism, "{name}");
        assert_eq!(d.q, r.q, "{name}");
        assert_eq!(d.u, r.u, "{name}");
        assert!(
            d.description.contains('°') && r.description.contains(" rad"),
            "{name}"
        );
    }
}

#[test]
fn defaults_strike_from_the_surface() {
    for name in ["double-pendulum", "sphere", "rod"] {
        let b = spec(name).build().unwrap();
        assert_eq!(b.mechanism.name(), name);
        let gap = dynamics::gap(&b.mechanism, 0, &b.q);
        assert!(gap.abs() < 1e-12, "{name}: gap {gap}");
    }
    let dp = spec("double-pendulum").build().unwrap();
    assert_eq!(dp.q, vec![30f64.to_radians(), 0.0]);
    assert_eq!(dp.u, vec![-1.0, 2.0]);
    for name in ["ring-pendulum", "cart-pendulum"] {
        let b = spec(name).build().unwrap();
        assert!(
            impax::mechanism::Mechanism::contacts(&b.mechanism).is_empty(),
            "{name}"
        );
    }
}

#[test]
fn errors_name_the_key_as_written() {
    let cases = [
        (
            MechanismSpec {
                angles: Some(vec![400.0, 0.0]),
                ..spec("double-pendulum")
            },
            "angles_deg[0]: must be between -360 and 360 degrees, got 400",
        ),
        (
            MechanismSpec {
                angles: Some(vec![7.0, 0.0]),
                angle_unit: AngleUnit::Radians,
                ..spec("double-pendulum")
            },
            "angles[0]: must be between -2π and 2π radians, got 7",
        ),
        (
            MechanismSpec {
                masses: Some(vec![1.0, 1.0, 1.0]),
                ..spec("double-pendulum")
            },
            "masses: needs 2 value(s), got 3",
        ),
        (
            MechanismSpec {
                rates: Some(vec![f64::NAN, 0.0, 0.0]),
                ..spec("rod")
            },
            "rates[0]: must be a finite number, got NaN",
        ),
        (
            MechanismSpec {
                radius: Some(1.0),
                ..spec("cart-pendulum")
            },
            "radius: not a parameter of cart-pendulum",
        ),
    ];
    for (s, message) in cases {
        assert_eq!(s.build().unwrap_err().to_string(), message);
    }
    let e = spec("pendulum").build().unwrap_err().to_string();
    assert_eq!(
        e,
        format!(
            "mechanism: unknown mechanism `pendulum` (known: {})",
            BuiltIn::NAMES.join(", ")
        )
    );
}
