//! The view of conserved quantities on the host: the ring-pendulum's answer is
//! `impax conserved ring-pendulum --json` (the command line's committed golden output), the
//! series are the tracker's, paper B's verdicts (p_x, the energy and the boost conserved,
//! P_x not; the cart's P_x conserved), the page's defaults are the core's, the poses roll
//! without slip, and bad requests are one line naming the field.

use crate::mechanism::{contains, golden};
use impax::mechanism::conserved::{track, TrackOptions};
use impax::scenario::MechanismSpec;
use serde_json::{json, Value};

fn conserved(request: &Value) -> Value {
    let v: Value = serde_json::from_str(&impax_wasm::conserved_json(&request.to_string())).unwrap();
    assert!(v["error"].is_null(), "{request}: {}", v["error"]);
    v
}

fn error_of(request: &Value) -> String {
    let v: Value = serde_json::from_str(&impax_wasm::conserved_json(&request.to_string())).unwrap();
    v["error"]
        .as_str()
        .unwrap_or_else(|| panic!("no error for {request}"))
        .to_string()
}

fn quantity<'a>(v: &'a Value, name: &str) -> &'a Value {
    v["quantities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|q| q["name"] == name)
        .unwrap_or_else(|| panic!("no quantity {name}"))
}

#[test]
fn ring_pendulum_is_the_command_lines() {
    let v = conserved(&json!({ "mechanism": "ring-pendulum" }));
    contains(
        &v,
        &golden("cli__golden__conserved_ring_pendulum_json.snap"),
        "",
    );
    // The same with the page's request: the defaults given explicitly.
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    let mut request = info["conserved_systems"]["ring-pendulum"].clone();
    request["mechanism"] = json!("ring-pendulum");
    let w = conserved(&request);
    assert_eq!(w["quantities"], v["quantities"]);
}

#[test]
fn the_series_are_the_trackers() {
    let v = conserved(&json!({ "mechanism": "ring-pendulum", "masses": [2.0, 0.5],
        "radius": 0.5, "lengths": [0.8], "angles_deg": [60], "rates": [1.0, -2.0],
        "duration": 3, "samples": 300 }));
    let spec = MechanismSpec {
        mechanism: "ring-pendulum".into(),
        masses: Some(vec![2.0, 0.5]),
        radius: Some(0.5),
        lengths: Some(vec![0.8]),
        angles: Some(vec![60.0]),
        rates: Some(vec![1.0, -2.0]),
        ..MechanismSpec::default()
    };
    let case = spec.build().unwrap();
    let options = TrackOptions {
        duration: 3.0,
        intervals: 300,
        ..TrackOptions::default()
    };
    let run = track(
        &case.mechanism,
        &case.q,
        &case.u,
        &case.mechanism.symmetries(),
        &[impax::math::Vec2::zeros()],
        options,
    )
    .unwrap();
    assert_eq!(v["times"], json!(run.times));
    assert_eq!(
        v["tolerances"]["relative"],
        json!(options.tolerances.relative)
    );
    assert_eq!(v["quantities"].as_array().unwrap().len(), run.tracks.len());
    for t in &run.tracks {
        let q = quantity(&v, &t.name);
        let values: Vec<f64> = q["values"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        assert_eq!(values.len(), 301);
        for (a, b) in values.iter().zip(&t.values) {
            assert!((a - b).abs() <= 4.0 * f64::EPSILON * b.abs(), "{}", t.name);
        }
        assert_eq!(q["conserved"], t.conserved(1e-8));
        assert_eq!(q["verdict"], t.verdict(1e-8));
    }
}

/// Paper B: on the ring, x is cyclic and p_x, the energy and the boost charge are conserved
/// while the horizontal momentum P_x is not (the rolling contact pushes); on the cart,
/// p_x = P_x is conserved.
#[test]
fn paper_b_verdicts() {
    let ring = conserved(&json!({ "mechanism": "ring-pendulum" }));
    assert_eq!(ring["cyclic"], json!(["x"]));
    for (name, conserved) in [
        ("p_x", true),
        ("p_phi", false),
        ("energy", true),
        ("P_x", false),
        ("P_y", false),
        ("translation x", true),
        ("boost x", true),
    ] {
        assert_eq!(
            quantity(&ring, name)["conserved"],
            conserved,
            "ring: {name}"
        );
    }
    assert_eq!(quantity(&ring, "P_x")["verdict"], "NOT conserved");
    assert_eq!(quantity(&ring, "boost x")["kind"], "noether-charge");
    let cart = conserved(&json!({ "mechanism": "cart-pendulum" }));
    assert_eq!(quantity(&cart, "P_x")["conserved"], true);
    assert_eq!(quantity(&cart, "p_x")["conserved"], true);
}

/// The sliders' starting values are the core's defaults: the same mechanism and state as
/// the name alone.
#[test]
fn the_pages_defaults_are_the_cores() {
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    let systems = info["conserved_systems"].as_object().unwrap();
    let names: Vec<&str> = systems.keys().map(String::as_str).collect();
    assert_eq!(
        names.len(),
        impax_wasm::conserved::SYSTEMS.len(),
        "{names:?}"
    );
    assert_eq!(systems["ring-pendulum"]["angles_deg"], json!([30.0]));
    assert_eq!(systems["ring-pendulum"]["radius"], json!(1.0));
    for (name, defaults) in systems {
        let mut request = defaults.clone();
        request["mechanism"] = json!(name);
        let spec: MechanismSpec = serde_json::from_value(request).unwrap();
        let given = spec.build().unwrap();
        let alone = MechanismSpec {
            mechanism: name.clone(),
            ..MechanismSpec::default()
        }
        .build()
        .unwrap();
        assert_eq!(given, alone, "{name}");
    }
}

/// The ring rolls without slip (its angle −x/R), the bob stays on its arm, and the first
/// pose is the state's.
#[test]
fn the_poses_roll_without_slip() {
    let v = conserved(&json!({ "mechanism": "ring-pendulum", "radius": 0.5,
        "lengths": [0.8], "rates": [2.0, 1.0], "samples": 200, "duration": 2 }));
    let scene = &v["scene"];
    assert_eq!(scene["bodies"][0]["radius"], 0.5);
    assert_eq!(scene["length"], 0.8);
    let poses = v["poses"].as_array().unwrap();
    assert_eq!(poses.len(), 201);
    let at = |k: usize, b: usize, i: usize| poses[k][b][i].as_f64().unwrap();
    assert_eq!(at(0, 0, 0), 0.0);
    assert!((at(0, 1, 2) - 30f64.to_radians()).abs() < 1e-15);
    for k in 0..poses.len() {
        let (x, y, angle) = (at(k, 0, 0), at(k, 0, 1), at(k, 0, 2));
        assert!((y - 0.5).abs() < 1e-15 && (angle + x / 0.5).abs() < 1e-12);
        let arm = (at(k, 1, 0) - x).hypot(at(k, 1, 1) - y);
        assert!((arm - 0.8).abs() < 1e-12);
    }
    // It moves: the ring has rolled forwards.
    assert!(at(200, 0, 0) > 0.5);
}

#[test]
fn bad_requests_name_their_field() {
    let ring = |extra: Value| {
        let mut r = json!({ "mechanism": "ring-pendulum" });
        for (k, v) in extra.as_object().unwrap() {
            r[k] = v.clone();
        }
        error_of(&r)
    };
    assert_eq!(
        ring(json!({ "masses": [1.0] })),
        "masses: needs 2 value(s), got 1"
    );
    assert!(ring(json!({ "radius": 0.0 })).starts_with("radius: 0 is out of range"));
    assert!(ring(json!({ "friction": 0.5 })).starts_with("friction: not used here"));
    assert!(ring(json!({ "samples": 0 })).starts_with("samples: must be a whole number"));
    assert!(ring(json!({ "samples": 1.5 })).starts_with("samples: "));
    assert!(ring(json!({ "duration": -1 })).starts_with("duration: must be positive"));
    assert!(ring(json!({ "duration": "long" })).starts_with("duration: must be a number"));
    assert!(ring(json!({ "spin": 1 })).starts_with("request: unknown field `spin`"));
    assert!(ring(json!({ "angles_deg": [400] })).starts_with("angles_deg[0]: must be between"));
    assert!(
        error_of(&json!({ "mechanism": "pendulum" })).starts_with("mechanism: unknown mechanism")
    );
    assert!(error_of(&json!([1, 2])).starts_with("request: "));
}
