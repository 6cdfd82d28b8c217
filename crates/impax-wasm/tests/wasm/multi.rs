//! The module's view with several contacts on the host: every multi-contact law's numbers
//! equal the core's (`MultiImpact::resolve` on the same built-in), the known answers (the
//! cradle's LCP `(−1/3, 2/3, 2/3) v0` and binary impacts `(0, 0, v0)`, the rod landing flat
//! at `e |v_y|`, Housner's rocking block), the motions after the impact (free flight under
//! gravity, never through the floor; the balls' free motion), errors naming their field, and
//! the C-ABI round trip.

use impax::multi::scenarios::{BallBallWall, Cradle, RockingBlock, RodFlat};
use impax::multi::MultiScenario;
use impax::LawId;
use serde_json::{json, Value};

fn multi(request: &Value) -> Value {
    let v: Value = serde_json::from_str(&impax_wasm::multi_json(&request.to_string())).unwrap();
    assert!(v["error"].is_null(), "{request}: {}", v["error"]);
    v
}

fn error_of(request: &str) -> String {
    let v: Value = serde_json::from_str(&impax_wasm::multi_json(request)).unwrap();
    v["error"]
        .as_str()
        .unwrap_or_else(|| panic!("no error for {request}"))
        .to_string()
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not a list: {v}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// `a` read back from JSON is `b`: the module prints the shortest round trip, which
/// serde_json's default parser reads back to within an ulp.
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4.0 * f64::EPSILON * b.abs()
}

fn same_list(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(*x, *y))
}

/// Every law of the answer equals the core's on the same system, number for number.
fn equals_the_core(answer: &Value, sc: &MultiScenario, friction: f64, restitution: f64) {
    let problem = sc.impact.problem(&[friction], &[restitution]).unwrap();
    let results = answer["results"].as_array().unwrap();
    let laws: Vec<&str> = results.iter().map(|r| r["law"].as_str().unwrap()).collect();
    assert_eq!(laws, LawId::MULTI_CONTACT.map(|l| l.as_str()));
    let t0 = sc.impact.energy_before();
    assert_eq!(answer["energy_before"].as_f64().unwrap(), t0);
    for (r, law) in results.iter().zip(LawId::MULTI_CONTACT) {
        let core = sc.impact.resolve(law, &problem).unwrap();
        let o = core.resolution.as_ref().unwrap();
        assert_eq!(r["verdict"], o.verdict.id(), "{law}");
        let u = core.velocities_after.clone().unwrap();
        assert!(same_list(&numbers(&r["velocities_after"]), &u), "{law}");
        let pn: Vec<f64> = o.contacts.iter().map(|c| c.impulse.y).collect();
        assert!(same_list(&numbers(&r["normal_impulses"]), &pn), "{law}");
        assert!(same(r["energy_change"].as_f64().unwrap(), o.energy_change));
        assert!(same(
            r["energy_ratio"].as_f64().unwrap(),
            (t0 + o.energy_change) / t0
        ));
        // The table's row: the columns' values in order.
        let columns = answer["columns"].as_array().unwrap();
        let values = numbers(&r["values"]);
        assert_eq!(values.len(), columns.len());
        let coords = sc.impact.coordinates();
        for (c, x) in columns.iter().zip(&values) {
            let key = c["key"].as_str().unwrap();
            let expected = match key {
                "dT" => o.energy_change,
                "ratio" => (t0 + o.energy_change) / t0,
                k if k.starts_with("pn") => pn[k[2..].parse::<usize>().unwrap() - 1],
                k => core.velocities_after.as_ref().unwrap()
                    [coords.iter().position(|c| c == k).unwrap()],
            };
            assert!(same(*x, expected), "{law} {key}: {x} vs {expected}");
        }
    }
}

#[test]
fn the_cradle_is_the_core_s_lcp_minus_a_third_and_binary_impacts() {
    let v0 = 1.5;
    let answer = multi(&json!({"system": "cradle", "balls": 3, "v0": v0}));
    let sc = Cradle {
        v0,
        ..Cradle::default()
    }
    .build()
    .unwrap();
    equals_the_core(&answer, &sc, 0.0, 1.0);
    let x = |law: usize| {
        let u = numbers(&answer["results"][law]["velocities_after"]);
        [u[0], u[3], u[6]]
    };
    for (got, want) in x(0).iter().zip([-v0 / 3.0, 2.0 * v0 / 3.0, 2.0 * v0 / 3.0]) {
        assert!((got - want).abs() < 1e-14, "lcp: {:?}", x(0));
    }
    for (got, want) in x(1).iter().zip([0.0, 0.0, v0]) {
        assert!((got - want).abs() < 1e-14, "sequential: {:?}", x(1));
    }
    // The table shows the balls' velocities along the row only (the others stay zero).
    let keys: Vec<&str> = answer["columns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["key"].as_str().unwrap())
        .collect();
    assert_eq!(keys, ["x1", "x2", "x3", "pn1", "pn2", "dT", "ratio"]);
    assert_eq!(answer["columns"][0]["label"], "ẋ₁⁺");
    // The scene: three balls touching along y = 0, the first moving at v0.
    let bodies = answer["scene"]["bodies"].as_array().unwrap();
    assert_eq!(bodies.len(), 3);
    assert_eq!(bodies[1]["shape"], "ball");
    assert_eq!(numbers(&bodies[2]["position"]), [2.0, 0.0]);
    assert_eq!(numbers(&bodies[0]["velocity"]), [v0, 0.0, 0.0]);
    assert_eq!(answer["scene"]["layout"], "row");
}

#[test]
fn lcp_is_left_out_beyond_its_contacts_with_the_reason() {
    let answer = multi(&json!({"system": "cradle", "balls": 8, "restitution": 0.8}));
    let laws: Vec<&str> = answer["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["law"].as_str().unwrap())
        .collect();
    assert_eq!(laws, ["sequential", "lzb"]);
    assert_eq!(answer["omitted"][0]["law"], "lcp");
    assert!(answer["omitted"][0]["reason"]
        .as_str()
        .unwrap()
        .contains("at most 6 contacts"));
}

#[test]
fn the_rod_landing_flat_is_the_core_s_and_rebounds_level() {
    let answer = multi(&json!({"system": "rod-flat", "vy": -2, "restitution": 0.6}));
    let sc = RodFlat {
        vy: -2.0,
        ..RodFlat::default()
    }
    .build()
    .unwrap();
    equals_the_core(&answer, &sc, 0.5, 0.6);
    // Symmetric landing: u⁺ = (0, e |v_y|, 0) under lcp and lzb (sequential resolves one end
    // after the other and tilts the rod).
    for r in answer["results"].as_array().unwrap() {
        let u = numbers(&r["velocities_after"]);
        if r["law"] == "sequential" {
            assert!(u[2].abs() > 0.1, "{u:?}");
            continue;
        }
        assert!(u[0].abs() < 1e-12 && (u[1] - 1.2).abs() < 1e-9 && u[2].abs() < 1e-9);
    }
    let asymmetric =
        json!({"system": "rod-flat", "vx": 0.5, "omega": 1.5, "friction": 0.3, "length": 2});
    let sc = RodFlat {
        vx: 0.5,
        omega: 1.5,
        length: 2.0,
        ..RodFlat::default()
    }
    .build()
    .unwrap();
    equals_the_core(&multi(&asymmetric), &sc, 0.3, 0.5);
}

#[test]
fn housner_s_rocking_block() {
    let (b, h) = (0.25, 0.75);
    let answer = multi(&json!({"system": "rocking-block", "half_width": b, "half_height": h}));
    let block = RockingBlock {
        half_width: b,
        half_height: h,
        ..RockingBlock::default()
    };
    equals_the_core(&answer, &block.build().unwrap(), 1.0, 0.0);
    for r in answer["results"].as_array().unwrap() {
        let ratio = numbers(&r["velocities_after"])[2] / -1.0;
        assert!(
            (ratio - block.housner_ratio()).abs() < 1e-12,
            "{}",
            r["law"]
        );
    }
    let body = &answer["scene"]["bodies"][0];
    assert_eq!(body["shape"], "block");
    assert_eq!(numbers(&body["position"]), [0.0, h]);
}

#[test]
fn ball_ball_wall_is_the_core_s() {
    let answer = multi(&json!({"system": "ball-ball-wall", "angle_deg": 20, "v0": 2}));
    let sc = BallBallWall {
        angle_deg: 20.0,
        v0: 2.0,
        ..BallBallWall::default()
    }
    .build()
    .unwrap();
    equals_the_core(&answer, &sc, 0.0, 1.0);
    let bodies = answer["scene"]["bodies"].as_array().unwrap();
    let (s, c) = 20f64.to_radians().sin_cos();
    let p2 = numbers(&bodies[1]["position"]);
    assert!((p2[0] - (0.5 + c)).abs() < 1e-15 && (p2[1] - s).abs() < 1e-15);
    assert_eq!(answer["scene"]["layout"], "wall");
}

/// The poses of one law's motion, `[x, y, θ]` per body per frame.
fn poses(answer: &Value, law: &str) -> Vec<Vec<[f64; 3]>> {
    answer["animation"]["motion"][law]["poses"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            f.as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    let p = numbers(p);
                    [p[0], p[1], p[2]]
                })
                .collect()
        })
        .collect()
}

#[test]
fn the_rod_flies_under_gravity_until_it_lands_again() {
    let answer = multi(&json!({"system": "rod-flat", "vy": -1, "omega": 0.8}));
    let g = answer["scene"]["gravity"].as_f64().unwrap();
    assert_eq!(g, 9.81);
    let window = answer["animation"]["window"].as_f64().unwrap();
    let frames = answer["animation"]["frames"].as_u64().unwrap() as usize;
    for r in answer["results"].as_array().unwrap() {
        let law = r["law"].as_str().unwrap();
        let u = numbers(&r["velocities_after"]);
        let end = &answer["animation"]["motion"][law]["end"];
        assert_eq!(end["id"], "next-impact", "{law}: {end}");
        let t_end = end["time"].as_f64().unwrap();
        assert!(t_end > 0.0 && t_end <= window);
        let p = poses(&answer, law);
        assert_eq!(p.len(), frames + 1);
        assert_eq!(p[0][0], [0.0, 0.0, 0.0]);
        for (k, f) in p.iter().enumerate() {
            let t = window * k as f64 / frames as f64;
            let [x, y, th] = f[0];
            // Never through the floor: both ends at or above it.
            assert!(y - 0.5 * th.sin().abs() > -1e-9, "{law} at t = {t}: {f:?}");
            // Free flight until the landing (the simulation's samples are 1 ms apart and
            // interpolated: to the curvature's error, ½ g (0.5 ms)² ≈ 1.2e-6).
            if t < t_end {
                let flight = [u[0] * t, u[1] * t - 0.5 * g * t * t, u[2] * t];
                for (a, b) in [x, y, th].iter().zip(flight) {
                    assert!(
                        (a - b).abs() < 2e-6,
                        "{law} at t = {t}: {f:?} vs {flight:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn housner_s_block_rocks_on_about_its_other_corner() {
    let answer = multi(&json!({"system": "rocking-block"}));
    let (b, h) = (0.2, 0.6);
    let p = poses(&answer, "lcp");
    let end = &answer["animation"]["motion"]["lcp"]["end"];
    assert_eq!(end["id"], "next-impact", "{end}");
    assert!(end["text"]
        .as_str()
        .unwrap()
        .starts_with("corner A strikes"));
    let mut highest: f64 = 0.0;
    for f in &p {
        let [x, y, th] = f[0];
        let (s, c) = th.sin_cos();
        // Corner B, (b, −h) in the block's frame, stays where it struck: (b, 0).
        let corner_b = [x + c * b + s * h, y + s * b - c * h];
        assert!(
            (corner_b[0] - b).abs() < 1e-6 && corner_b[1].abs() < 1e-6,
            "{f:?}"
        );
        // Corner A rises and falls back.
        highest = highest.max(y - s * b - c * h);
    }
    assert!(highest > 0.005, "corner A rose by {highest}");
}

#[test]
fn the_cradle_s_balls_move_freely_along_the_row() {
    let answer = multi(&json!({"system": "cradle", "balls": 3}));
    let window = answer["animation"]["window"].as_f64().unwrap();
    assert!((window - 4.0 * 0.5 / 1.0).abs() < 1e-12);
    for r in answer["results"].as_array().unwrap() {
        let law = r["law"].as_str().unwrap();
        let u = numbers(&r["velocities_after"]);
        let p = poses(&answer, law);
        let last = p.last().unwrap();
        for (i, ball) in last.iter().enumerate() {
            let expected = [i as f64 + u[3 * i] * window, 0.0, 0.0];
            for (a, b) in ball.iter().zip(expected) {
                assert!((a - b).abs() < 1e-12, "{law} ball {i}: {ball:?}");
            }
        }
        assert_eq!(
            answer["animation"]["motion"][law]["end"]["id"], "moving",
            "{law}"
        );
    }
}

#[test]
fn bad_requests_name_their_field() {
    assert!(error_of("not json").starts_with("request:"));
    assert!(error_of(r#"{"friction": 0.4}"#).contains("system"));
    assert!(error_of(r#"{"system": "cradle", "colour": 1}"#).contains("colour"));
    let cases = [
        (
            r#"{"system": "pendulum"}"#,
            "system: unknown system `pendulum`",
        ),
        (
            r#"{"system": "cradle", "half_width": 1}"#,
            "half_width: not a parameter of `cradle`",
        ),
        (
            r#"{"system": "rod-flat", "balls": 3}"#,
            "balls: not a parameter of `rod-flat`",
        ),
        (
            r#"{"system": "cradle", "balls": 2.5}"#,
            "balls: must be a whole number",
        ),
        (r#"{"system": "cradle", "balls": 1}"#, "balls:"),
        (r#"{"system": "cradle", "v0": -1}"#, "v0:"),
        (
            r#"{"system": "rocking-block", "half_width": -1}"#,
            "half_width:",
        ),
        (
            r#"{"system": "rocking-block", "half_height": 0}"#,
            "half_height:",
        ),
        (r#"{"system": "rocking-block", "omega": 1}"#, "omega:"),
        (
            r#"{"system": "ball-ball-wall", "angle_deg": 95}"#,
            "angle_deg:",
        ),
        (r#"{"system": "rod-flat", "length": 0}"#, "length:"),
        (
            r#"{"system": "rod-flat", "vy": 1}"#,
            "vy, omega: no end of the rod comes down",
        ),
        (
            r#"{"system": "rod-flat", "restitution": 1.5}"#,
            "restitution",
        ),
        (r#"{"system": "cradle", "friction": -1}"#, "friction"),
        (r#"{"system": "cradle", "mass": 0}"#, "mass:"),
    ];
    for (request, start) in cases {
        let e = error_of(request);
        assert!(e.starts_with(start), "{request}: {e}");
        assert!(!e.contains('\n'));
    }
}

#[test]
fn info_lists_the_systems_with_the_core_s_defaults() {
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    assert_eq!(
        info["multi_laws"],
        json!(LawId::MULTI_CONTACT.map(|l| l.as_str()))
    );
    let systems = &info["multi_systems"];
    let rod = RodFlat::default();
    assert_eq!(systems["rod-flat"]["parameters"]["vy"], json!(rod.vy));
    assert_eq!(systems["rod-flat"]["friction"], json!(0.5));
    assert_eq!(systems["cradle"]["parameters"]["balls"], json!(3.0));
    assert_eq!(systems["cradle"]["restitution"], json!(1.0));
    assert_eq!(
        systems["rocking-block"]["parameters"]["half_width"],
        json!(RockingBlock::default().half_width)
    );
    assert_eq!(
        systems["ball-ball-wall"]["parameters"]["angle_deg"],
        json!(30.0)
    );
}

#[test]
fn c_abi_round_trip() {
    let text = r#"{"system": "cradle", "balls": 4}"#;
    let ptr = impax_wasm::impax_alloc(text.len());
    // SAFETY: `ptr` has room for `text.len()` bytes; it is freed by `impax_multi`.
    let out = unsafe {
        std::ptr::copy_nonoverlapping(text.as_ptr(), ptr, text.len());
        impax_wasm::impax_multi(ptr, text.len())
    };
    let len = impax_wasm::impax_output_len();
    // SAFETY: the module keeps the answer until the next call.
    let v: Value = serde_json::from_slice(unsafe { std::slice::from_raw_parts(out, len) }).unwrap();
    assert_eq!(v["system"], "cradle");
    assert_eq!(v["scene"]["bodies"].as_array().unwrap().len(), 4);
}
