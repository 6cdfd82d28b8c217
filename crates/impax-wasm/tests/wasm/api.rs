//! The explorer's module on the host: the same numbers as the library, every law listed,
//! clear errors for bad requests, the map against paper A eq. 13, and the C-ABI round trip.

use impax::analysis::whittaker_sphere_thresholds;
use impax::planar::bodies::{self, BodyImpact, Side};
use impax::LawId;
use serde_json::{json, Value};

fn seed() -> Value {
    json!({"friction": 0.4, "restitution": 0.7,
           "body": {"shape": "sphere", "mass": 1, "radius": 1,
                    "speed": 1, "alpha_deg": 30, "spin_ratio": 0}})
}

fn compare(request: &Value) -> Value {
    serde_json::from_str(&impax_wasm::compare_json(&request.to_string())).unwrap()
}

fn error_of(request: &str) -> String {
    let v: Value = serde_json::from_str(&impax_wasm::compare_json(request)).unwrap();
    v["error"]
        .as_str()
        .unwrap_or_else(|| panic!("no error for {request}: {v}"))
        .to_string()
}

#[test]
fn seed_matches_the_library_for_every_law() {
    let v = compare(&seed());
    let results = v["results"].as_array().unwrap();
    let ids: Vec<&str> = results.iter().map(|r| r["law"].as_str().unwrap()).collect();
    assert_eq!(ids, LawId::ALL.map(|l| l.as_str()).to_vec());
    let a = 30f64.to_radians();
    let impact = BodyImpact::on_fixed_surface(
        bodies::sphere(1.0, 1.0, Side::Below).unwrap(),
        bodies::spin_state(1.0, a, 0.0, 1.0).unwrap(),
    );
    let problem = impact.problem(0.4, 0.7).unwrap();
    for (r, law) in results.iter().zip(LawId::ALL) {
        let b = impact.resolve(law, &problem).unwrap();
        let values: Vec<f64> = r["values"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let expected = [
            b.body_after.velocity.x,
            b.body_after.velocity.y,
            b.body_after.omega,
            b.outcome.velocity_after.x,
            b.outcome.energy_change / 0.5,
        ];
        for (x, y) in values.iter().zip(expected) {
            // The module is the library; JSON prints the shortest round trip, which
            // serde_json's default parser reads back to within an ulp.
            assert!(
                (x - y).abs() <= 4.0 * f64::EPSILON * y.abs(),
                "{law}: {x} vs {y}"
            );
        }
        assert_eq!(r["verdict"], b.outcome.verdict.id());
        let path = r["path"].as_array().unwrap();
        let last = path.last().unwrap();
        let (pt, pn) = (last[0].as_f64().unwrap(), last[1].as_f64().unwrap());
        assert!((pt - b.outcome.impulse.x).abs() <= 4.0 * f64::EPSILON * pt.abs());
        assert!((pn - b.outcome.impulse.y).abs() <= 4.0 * f64::EPSILON * pn.abs());
    }
    assert!(results[0]["energy_change_ratio"].as_f64().unwrap() > 0.24);
    let energetic = results.iter().find(|r| r["law"] == "energetic").unwrap();
    assert!((energetic["energy_change_ratio"].as_f64().unwrap() + 0.45393).abs() < 1e-5);
    // Paper A eq. 13's threshold of the seed: γ*₊ = 0.205811.
    assert!((v["threshold"]["upper"].as_f64().unwrap() - 0.205811).abs() < 1e-6);
    assert!((v["threshold"]["lower"].as_f64().unwrap() + 1.205811).abs() < 1e-6);
    assert!((v["threshold"]["edge"].as_f64().unwrap() + 0.5).abs() < 1e-15);
}

#[test]
fn energy_bars_sum_to_the_energy_change() {
    let v = compare(&seed());
    for r in v["results"].as_array().unwrap() {
        let e = &r["energy"];
        let dt = r["energy_change_ratio"].as_f64().unwrap();
        let work = e["normal"].as_f64().unwrap() + e["friction"].as_f64().unwrap();
        let parts = e["translational"].as_f64().unwrap() + e["rotational"].as_f64().unwrap();
        assert!((work - dt).abs() < 1e-12, "{}", r["law"]);
        assert!((parts - dt).abs() < 1e-12, "{}", r["law"]);
    }
}

#[test]
fn double_pendulum_is_kanes_paradox() {
    let v = compare(&json!({"friction": 0.5, "restitution": 0.5,
        "mechanism": {"name": "double-pendulum", "masses": [1, 1], "lengths": [1, 1],
                      "angles_deg": [30, 0], "rates": [-1, 2]}}));
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), LawId::CONTACT_SPACE.len());
    let w = &results[0];
    assert_eq!(w["law"], "whittaker");
    assert_eq!(w["verdict"], "energy-gained");
    // T⁺/T⁻ = 1.26087 (the book's Mechanisms chapter: Kane & Levinson's pendulum).
    assert!((w["energy_ratio"].as_f64().unwrap() - 1.26087).abs() < 5e-6);
    above_the_floor(&v["animation"]);
    let frames = v["animation"]["before"].as_array().unwrap();
    // At the impact the tip is at the origin: the end of rod 2 from its centre.
    let last = &frames.last().unwrap()[1];
    let (x, y, angle) = (
        last[0].as_f64().unwrap(),
        last[1].as_f64().unwrap(),
        last[2].as_f64().unwrap(),
    );
    assert!((x + 0.5 * angle.sin()).abs() < 1e-12 && (y - 0.5 * angle.cos()).abs() < 1e-12);
}

#[test]
fn every_shape_resolves() {
    for body in [
        json!({"shape": "disc", "mass": 2, "radius": 0.5}),
        json!({"shape": "rod", "mass": 1, "length": 2, "angle_deg": 50}),
        json!({"shape": "ellipse", "mass": 1, "semi_axes": [2, 1], "angle_deg": 20}),
        json!({"shape": "rigid", "mass": 1, "inertia": 0.5, "contact": [0.3, -1]}),
    ] {
        let mut b = body.clone();
        for (k, x) in [("speed", 1.0), ("alpha_deg", 30.0), ("spin_ratio", 0.2)] {
            b[k] = json!(x);
        }
        let v = compare(&json!({"friction": 0.4, "restitution": 0.7, "body": b}));
        assert!(v["error"].is_null(), "{body}: {v}");
        assert_eq!(v["results"].as_array().unwrap().len(), LawId::ALL.len());
        assert_eq!(v["animation"]["before"].as_array().unwrap().len(), 49);
        above_the_floor(&v["animation"]);
    }
}

/// Every shape the module lists (`info().shapes`, the core's table) is requested as the page
/// requests a shape it has no preset for: its numbers from `shape_parameters`, put where `key`
/// and `index` say, valued by their quantity. Each resolves with every law and an animation
/// that stays above the floor.
#[test]
fn every_listed_shape_resolves_from_its_parameters() {
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    let shapes = info["shapes"].as_array().unwrap();
    assert_eq!(shapes.len(), impax::scenario::Shape::ALL.len());
    for shape in shapes {
        let name = shape.as_str().unwrap();
        let mut b =
            json!({"shape": name, "mass": 1.5, "speed": 1, "alpha_deg": 30, "spin_ratio": 0.2});
        let numbers = info["shape_parameters"][name].as_array().unwrap();
        assert!(!numbers.is_empty(), "{name}");
        for p in numbers {
            let x = match p["quantity"].as_str().unwrap() {
                "length" => 0.8,
                "angle" => 20.0,
                "inertia" => 0.5,
                "offset" => -0.5,
                q => panic!("{name}: unknown quantity {q}"),
            };
            let key = p["key"].as_str().unwrap();
            match p["index"].as_u64() {
                None => b[key] = json!(x),
                Some(i) => {
                    if b[key].is_null() {
                        b[key] = json!([f64::NAN, f64::NAN]);
                    }
                    b[key][i as usize] = json!(x);
                }
            }
        }
        let v = compare(&json!({"friction": 0.4, "restitution": 0.7, "body": b}));
        assert!(v["error"].is_null(), "{b}: {v}");
        let scenario = v["scenario"].as_str().unwrap();
        assert!(scenario.starts_with(name) || name == "rigid", "{scenario}");
        assert_eq!(v["results"].as_array().unwrap().len(), LawId::ALL.len());
        above_the_floor(&v["animation"]);
    }
}

/// No frame of the animation takes a body through the floor `y = 0`.
fn above_the_floor(animation: &Value) {
    use impax_wasm::animation::Outline;
    let f = |x: &Value| x.as_f64().unwrap();
    let outlines: Vec<Outline> = animation["shapes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| match s["kind"].as_str().unwrap() {
            "circle" => Outline::Circle {
                radius: f(&s["radius"]),
            },
            "segment" => Outline::Segment {
                half_length: f(&s["half_length"]),
                direction: f(&s["direction"]),
            },
            "ellipse" => Outline::Ellipse {
                a: f(&s["a"]),
                b: f(&s["b"]),
                direction: f(&s["direction"]),
            },
            _ => Outline::Rigid {
                contact: [f(&s["contact"][0]), f(&s["contact"][1])],
                gyration: f(&s["gyration"]),
            },
        })
        .collect();
    let mut halves = vec![&animation["before"]];
    halves.extend(animation["after"].as_object().unwrap().values());
    for frames in halves {
        for frame in frames.as_array().unwrap() {
            for (o, p) in outlines.iter().zip(frame.as_array().unwrap()) {
                let pose = [f(&p[0]), f(&p[1]), f(&p[2])];
                assert!(
                    o.lowest(pose) > -1e-9,
                    "{o:?} at {pose:?} is below the floor"
                );
            }
        }
    }
}

#[test]
fn bad_requests_are_one_line_errors() {
    let body = |extra: &str| {
        format!(
            r#"{{"friction": 0.4, "restitution": 0.7, "body": {{"shape": "sphere", "mass": 1, "radius": 1, "speed": 1, "alpha_deg": 30, "spin_ratio": 0{extra}}}}}"#
        )
    };
    assert!(error_of("not json").starts_with("request:"));
    assert!(error_of(r#"{"friction": 0.4}"#).contains("restitution"));
    assert!(error_of(r#"{"friction": 0.4, "restitution": 0.7}"#).contains("exactly one"));
    assert!(error_of(&body(r#", "colour": 1"#)).contains("colour"));
    let e = error_of(&body("").replace(r#""restitution": 0.7"#, r#""restitution": 1.5"#));
    assert!(e.starts_with("restitution"), "{e}");
    let e = error_of(&body("").replace(r#""friction": 0.4"#, r#""friction": -1"#));
    assert!(e.starts_with("friction"), "{e}");
    let e = error_of(&body("").replace(r#""alpha_deg": 30"#, r#""alpha_deg": 90"#));
    assert!(e.starts_with("alpha_deg"), "{e}");
    let e = error_of(&body("").replace(r#""mass": 1"#, r#""mass": 0"#));
    assert!(e.starts_with("mass"), "{e}");
    let e = error_of(&body("").replace(r#""sphere""#, r#""cube""#));
    assert!(e.contains("unknown shape"), "{e}");
    let e = error_of(&body("").replace(r#""speed": 1"#, r#""speed": 1e999"#));
    assert!(!e.is_empty());
    // A pendulum whose tip leaves the floor does not strike it.
    let e = error_of(
        r#"{"friction": 0.5, "restitution": 0.5, "mechanism": {"name": "double-pendulum",
            "masses": [1, 1], "lengths": [1, 1], "angles_deg": [30, 0], "rates": [1, -2]}}"#,
    );
    assert!(e.contains("approach"), "{e}");
}

fn map(request: &Value) -> (Value, Vec<f32>, Vec<u8>) {
    let (mut values, mut classes) = (Vec::new(), Vec::new());
    let v: Value = serde_json::from_str(&impax_wasm::map_json(
        &request.to_string(),
        &mut values,
        &mut classes,
    ))
    .unwrap();
    (v, values, classes)
}

#[test]
fn whittaker_map_agrees_with_paper_a_eq_13() {
    let (nx, ny) = (200, 200);
    let (v, values, classes) = map(&json!({"scenario": seed(), "law": "whittaker",
        "x": {"name": "spin_ratio", "min": -2, "max": 2, "count": nx},
        "y": {"name": "alpha_deg", "min": 0, "max": 89, "count": ny}}));
    assert!(v["error"].is_null(), "{v}");
    assert_eq!(values.len(), nx * ny);
    assert_eq!(classes.len(), nx * ny);
    let mut checked = 0;
    for j in 0..ny {
        let alpha = 89.0 * j as f64 / (ny - 1) as f64;
        let t = whittaker_sphere_thresholds(alpha.to_radians(), 0.7, 0.4);
        for i in 0..nx {
            let gamma = -2.0 + 4.0 * i as f64 / (nx - 1) as f64;
            let ratio =
                impax::analysis::whittaker_sphere_energy_ratio(alpha.to_radians(), 0.7, 0.4, gamma);
            if ratio.abs() < 1e-9 {
                continue; // on the boundary itself
            }
            let cell = j * nx + i;
            assert_eq!(
                classes[cell] == 0,
                t.gains(gamma, alpha.to_radians()),
                "α = {alpha}, γ = {gamma}"
            );
            assert!((values[cell] as f64 - ratio).abs() < 1e-6 * (1.0 + ratio.abs()));
            checked += 1;
        }
    }
    assert!(checked > 39_000);
    assert_eq!(v["marker"], json!([0.0, 30.0]));
    assert!(!v["threshold"]["upper"].as_array().unwrap().is_empty());
}

#[test]
fn map_cell_equals_compare_at_the_same_point() {
    let (_, values, classes) = map(&json!({"scenario": seed(), "law": "energetic",
        "x": {"name": "friction", "min": 0, "max": 0.8, "count": 5},
        "y": {"name": "restitution", "min": 0, "max": 0.7, "count": 3}}));
    // Cell (i = 2, j = 2): μ = 0.4, e = 0.7, the seed.
    let v = compare(&seed());
    let results = v["results"].as_array().unwrap();
    let energetic = results.iter().find(|r| r["law"] == "energetic").unwrap();
    let expected = energetic["energy_change_ratio"].as_f64().unwrap() as f32;
    assert_eq!(values[2 * 5 + 2], expected);
    assert!(classes.iter().all(|&c| c == 1), "energetic never gains");
}

#[test]
fn bad_maps_are_errors() {
    for (req, needle) in [
        (
            json!({"scenario": seed(), "law": "nope", "x": {"name": "spin_ratio", "min": -1, "max": 1, "count": 3}, "y": {"name": "alpha_deg", "min": 0, "max": 80, "count": 3}}),
            "unknown impact law",
        ),
        (
            json!({"scenario": seed(), "law": "whittaker", "x": {"name": "mass", "min": -1, "max": 1, "count": 3}, "y": {"name": "alpha_deg", "min": 0, "max": 80, "count": 3}}),
            "unknown parameter",
        ),
        (
            json!({"scenario": seed(), "law": "whittaker", "x": {"name": "spin_ratio", "min": 1, "max": 1, "count": 3}, "y": {"name": "alpha_deg", "min": 0, "max": 80, "count": 3}}),
            "min < max",
        ),
        (
            json!({"scenario": seed(), "law": "whittaker", "x": {"name": "spin_ratio", "min": -1, "max": 1, "count": 2000}, "y": {"name": "alpha_deg", "min": 0, "max": 80, "count": 2000}}),
            "at most",
        ),
        (
            json!({"scenario": seed(), "law": "whittaker", "x": {"name": "spin_ratio", "min": -1, "max": 1, "count": 3}, "y": {"name": "spin_ratio", "min": 0, "max": 80, "count": 3}}),
            "same parameter",
        ),
    ] {
        let (v, _, _) = map(&req);
        let e = v["error"].as_str().unwrap_or_default();
        assert!(e.contains(needle), "{e} lacks {needle}");
    }
    // Points outside the domain are invalid cells, not errors.
    let (v, values, classes) = map(&json!({"scenario": seed(), "law": "whittaker",
        "x": {"name": "spin_ratio", "min": -1, "max": 1, "count": 3},
        "y": {"name": "alpha_deg", "min": 0, "max": 90, "count": 3}}));
    assert_eq!(v["counts"]["invalid"], 3);
    assert!(v["first_invalid"].as_str().unwrap().contains("alpha_deg"));
    assert!(values[6..].iter().all(|x| x.is_nan()));
    assert!(classes[6..].iter().all(|&c| c == 4));
}

#[test]
fn c_abi_round_trip() {
    let text = seed().to_string();
    let ptr = impax_wasm::impax_alloc(text.len());
    // SAFETY: `ptr` has room for `text.len()` bytes; it is freed by `impax_compare`.
    let out = unsafe {
        std::ptr::copy_nonoverlapping(text.as_ptr(), ptr, text.len());
        impax_wasm::impax_compare(ptr, text.len())
    };
    let len = impax_wasm::impax_output_len();
    // SAFETY: the module keeps the answer until the next call.
    let answer = unsafe { std::slice::from_raw_parts(out, len) };
    let v: Value = serde_json::from_slice(answer).unwrap();
    assert_eq!(v["results"][0]["law"], "whittaker");
    let info: Value = {
        let p = impax_wasm::impax_info();
        // SAFETY: as above.
        serde_json::from_slice(unsafe {
            std::slice::from_raw_parts(p, impax_wasm::impax_output_len())
        })
        .unwrap()
    };
    assert_eq!(info["laws"].as_array().unwrap().len(), LawId::ALL.len());
}

/// The planar box, added to the core's table alone, in the explorer's requests: listed, with
/// sliders for its numbers, and the `W` of the rigid body of the same inertia and corner.
#[test]
fn a_box_request_is_the_rigid_body_with_its_inertia_and_corner() {
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    assert!(info["shapes"].as_array().unwrap().contains(&json!("box")));
    let names: Vec<&str> = info["shape_parameters"]["box"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["angle_deg", "half_extent_a", "half_extent_b"]);
    let (m, a, b, theta) = (1.5f64, 1.0f64, 0.4f64, 25f64.to_radians());
    let (s, c) = theta.sin_cos();
    let motion = |mut body: Value| {
        for (k, x) in [("speed", 1.0), ("alpha_deg", 30.0), ("spin_ratio", 0.2)] {
            body[k] = json!(x);
        }
        compare(&json!({"friction": 0.4, "restitution": 0.7, "body": body}))
    };
    let boxed = motion(json!({"shape": "box", "mass": m, "half_extents": [a, b], "angle_deg": 25}));
    let rigid = motion(
        json!({"shape": "rigid", "mass": m, "inertia": m * (a * a + b * b) / 3.0,
                              "contact": [-a * c + b * s, -a * s - b * c]}),
    );
    assert!(boxed["error"].is_null(), "{boxed}");
    assert!(boxed["scenario"]
        .as_str()
        .unwrap()
        .starts_with("box m = 1.5, a = 1, b = 0.4, at 25°"));
    for (x, y) in [(&boxed["problem"]["w"], &rigid["problem"]["w"])] {
        for i in 0..2 {
            for j in 0..2 {
                let (p, q) = (x[i][j].as_f64().unwrap(), y[i][j].as_f64().unwrap());
                assert!((p - q).abs() <= 1e-15, "W[{i}][{j}]: {p} vs {q}");
            }
        }
    }
    // Flat on an edge: an error naming the corner, not a trap.
    let flat = motion(json!({"shape": "box", "mass": m, "half_extents": [a, b]}));
    assert!(
        flat["error"].as_str().unwrap().starts_with("corner:"),
        "{flat}"
    );
}
