//! The view "Your mechanism" on the host: a mechanism file's answer is the command line's
//! (`impax compare FILE --json`, the command line's golden snapshots), Kane & Levinson's pendulum from its
//! file equals the built-in under the change to relative angles, the page's `q`, `u`, μ and e
//! are used, the menu is the repository's `examples/mechanisms/`, and a broken file is one
//! line saying where — never a trap.

use impax::mechanism::builtin::{DoublePendulum, STANDARD_GRAVITY};
use impax::mechanism::impact::MechanismImpact;
use impax::LawId;
use serde_json::{json, Value};

const DOUBLE_PENDULUM: &str = include_str!("../../../../examples/mechanisms/double-pendulum.toml");
const ARM: &str = include_str!("../../../../examples/mechanisms/arm-3d.toml");

fn answer(request: &Value) -> Value {
    serde_json::from_str(&impax_wasm::mechanism_json(&request.to_string())).unwrap()
}

fn ok(request: &Value) -> Value {
    let v = answer(request);
    assert!(v["error"].is_null(), "{}", v["error"]);
    v
}

fn error_of(request: &Value) -> String {
    let v = answer(request);
    v["error"]
        .as_str()
        .unwrap_or_else(|| panic!("no error: {v}"))
        .to_string()
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not a list: {v}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// `a` and `b` agree to `tol` relative to the larger (absolute below 1).
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0)
}

/// Every key of `expected` is in `actual` with the same value: strings, booleans and nulls
/// equal, numbers to 4 ulps (JSON's shortest round trip read back).
pub fn contains(actual: &Value, expected: &Value, path: &str) {
    match (actual, expected) {
        (Value::Object(a), Value::Object(e)) => {
            for (k, v) in e {
                let at = format!("{path}.{k}");
                contains(a.get(k).unwrap_or_else(|| panic!("{at}: missing")), v, &at);
            }
        }
        (Value::Array(a), Value::Array(e)) => {
            assert_eq!(a.len(), e.len(), "{path}: length");
            for (i, (x, y)) in a.iter().zip(e).enumerate() {
                contains(x, y, &format!("{path}[{i}]"));
            }
        }
        (Value::Number(a), Value::Number(e)) => {
            let (a, e) = (a.as_f64().unwrap(), e.as_f64().unwrap());
            assert!(
                (a - e).abs() <= 4.0 * f64::EPSILON * e.abs(),
                "{path}: {a} vs {e}"
            );
        }
        (a, e) => assert_eq!(a, e, "{path}"),
    }
}

/// The golden output of `impax compare FILE --json` (the command line's insta snapshot).
pub fn golden(snapshot: &str) -> Value {
    let text = std::fs::read_to_string(format!(
        "{}/../impax-cli/tests/cli/snapshots/{snapshot}",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let body = text.splitn(3, "---\n").nth(2).expect("an insta snapshot");
    serde_json::from_str(body).unwrap()
}

/// `impax compare examples/mechanisms/double-pendulum.toml --json`, number for number (the
/// browser test checks the page against the live command too).
#[test]
fn double_pendulum_file_is_the_command_lines() {
    let v = ok(&json!({ "file": DOUBLE_PENDULUM }));
    let cli = golden("cli__golden__compare_double_pendulum_file_json.snap");
    contains(&v, &cli, "");
    assert_eq!(v["space"], "2d");
    assert_eq!(v["friction"], 0.5);
    assert_eq!(v["restitution"], 0.5);
    assert_eq!(v["speeds"], json!(["theta1", "theta2"]));
}

/// `impax compare examples/mechanisms/arm-3d.toml --json`: the spatial document.
#[test]
fn spatial_file_is_the_command_lines() {
    let v = ok(&json!({ "file": ARM }));
    let cli = golden("cli__golden__compare_arm_3d_file_json.snap");
    contains(&v, &cli, "");
    assert_eq!(v["space"], "3d");
    let results = v["results"].as_array().unwrap();
    let laws: Vec<&str> = results.iter().map(|r| r["law"].as_str().unwrap()).collect();
    assert_eq!(laws, LawId::SPATIAL.map(|l| l.as_str()));
    // The table's rows: u⁺ per speed, v⁺ (t1, t2, n), p (t1, t2, n), ΔT, T⁺/T⁻.
    let keys: Vec<&str> = v["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["key"].as_str().unwrap())
        .collect();
    assert_eq!(keys.len(), 3 + 3 + 3 + 2);
    for r in results {
        let values = numbers(&r["values"]);
        assert_eq!(values[..3], numbers(&r["velocities_after"])[..]);
        assert_eq!(values[5], r["velocity_after"]["n"].as_f64().unwrap());
        assert_eq!(values[8], r["impulse"]["n"].as_f64().unwrap());
        assert_eq!(values[10], r["energy_ratio"].as_f64().unwrap());
    }
}

/// The built-in double pendulum at absolute angles θ and rates θ̇, every law (μ = e = 0.5).
fn built_in(
    angles_deg: [f64; 2],
    rates: [f64; 2],
    friction: f64,
) -> Vec<(LawId, Vec<f64>, [f64; 3])> {
    let mut dp = DoublePendulum::new(1.0, 1.0, 1.0, 1.0, STANDARD_GRAVITY, 0.0).unwrap();
    let q = angles_deg.map(f64::to_radians);
    dp.put_floor_at_tip(q);
    let impact = MechanismImpact::new(&dp, &q, &rates, 0).unwrap();
    LawId::CONTACT_SPACE
        .iter()
        .map(|&law| {
            let r = impact.resolve(law, friction, 0.5).unwrap();
            let o = r.resolution.unwrap();
            let u = r.velocities_after.unwrap();
            (
                law,
                u,
                [o.velocity_after.x, o.velocity_after.y, o.energy_change],
            )
        })
        .collect()
}

/// The file's relative angles are the built-in's absolute ones changed: `q = (θ1, θ2 − θ1)`,
/// `u = (θ̇1, θ̇2 − θ̇1)`; every law's velocities after, contact velocity after and ΔT agree
/// to 1e-12 — at the file's state (Kane & Levinson's case), and at the page's `u` and μ.
#[test]
fn double_pendulum_file_is_the_built_in_in_relative_angles() {
    for (request, rates, friction) in [
        (json!({ "file": DOUBLE_PENDULUM }), [-1.0, 2.0], 0.5),
        (
            json!({ "file": DOUBLE_PENDULUM, "u": [-1.0, 2.5], "friction": 0.3, "q": null }),
            [-1.0, 1.5],
            0.3,
        ),
    ] {
        let v = ok(&request);
        assert_eq!(v["friction"], friction);
        let results = v["results"].as_array().unwrap();
        for (r, (law, u, [vt, vn, de])) in
            results.iter().zip(built_in([30.0, 0.0], rates, friction))
        {
            assert_eq!(r["law"], law.as_str());
            let after = numbers(&r["velocities_after"]);
            assert!(
                close(after[0], u[0], 1e-12) && close(after[1], u[1] - u[0], 1e-12),
                "{law}: {after:?} vs {u:?}"
            );
            assert!(
                close(
                    r["contact_velocity_after"]["t"].as_f64().unwrap(),
                    vt,
                    1e-12
                ),
                "{law}"
            );
            assert!(
                close(
                    r["contact_velocity_after"]["n"].as_f64().unwrap(),
                    vn,
                    1e-12
                ),
                "{law}"
            );
            assert!(
                close(r["energy_change"].as_f64().unwrap(), de, 1e-12),
                "{law}"
            );
        }
        assert_eq!(v["u_before"], json!([rates[0], rates[1] - rates[0]]));
    }
    // Kane's paradox from the file: Whittaker's rule gains 26 % (T⁺/T⁻ = 1.26087).
    let v = ok(&json!({ "file": DOUBLE_PENDULUM }));
    let w = &v["results"][0];
    assert_eq!(w["verdict"], "energy-gained");
    assert!((w["energy_ratio"].as_f64().unwrap() - 1.26087).abs() < 5e-6);
    let values = numbers(&w["values"]);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(values.len(), rows.len());
    assert_eq!(rows[0]["label"], "theta1⁺");
    assert_eq!(rows[0]["before"], -1.0);
    assert!(w["phase_summary"].as_str().unwrap().starts_with("slip"));
}

/// The menu is `examples/mechanisms/`: every file, with its text, and nothing else.
#[test]
fn the_menu_is_the_repositorys_examples() {
    let info: Value = serde_json::from_str(&impax_wasm::info_json()).unwrap();
    let listed = info["mechanism_files"].as_array().unwrap();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/mechanisms");
    let mut on_disk: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    on_disk.sort();
    let mut menu: Vec<(String, String)> = listed
        .iter()
        .map(|f| {
            (
                f["name"].as_str().unwrap().into(),
                f["text"].as_str().unwrap().into(),
            )
        })
        .collect();
    assert_eq!(
        menu[0].0, "double-pendulum.toml",
        "the view opens on Kane's pendulum"
    );
    menu.sort();
    assert_eq!(menu, on_disk);
    // Each answers, or says why it cannot strike: the ring- and cart-pendulum have no contact
    // point, the hopper is thrown upwards (its foot leaving the floor at the file's state).
    for (name, text) in &menu {
        let v = answer(&json!({ "file": text }));
        match v["error"].as_str() {
            Some(e) => assert!(
                (e.starts_with("contact: ") && e.contains("has no contact point to strike"))
                    || e.starts_with("v: the normal contact velocity must be negative (approach)"),
                "{name}: {e}"
            ),
            None => assert!(!v["results"].as_array().unwrap().is_empty(), "{name}"),
        }
    }
}

#[test]
fn a_broken_file_is_one_line_saying_where() {
    let with = |from: &str, to: &str| json!({ "file": DOUBLE_PENDULUM.replacen(from, to, 1) });
    // The TOML reader's line and column.
    assert_eq!(
        error_of(&with("mass = 1.0", "mas = 1.0")),
        "line 16, column 1: unknown field `mas`, expected one of `name`, `mass`, `inertia`, `com`"
    );
    assert!(error_of(&with("[[joint]]", "[[joint]")).starts_with("line 25, column "));
    // The checks after it: the field, found back in the text.
    assert_eq!(
        error_of(&with("parent = \"rod 1\"", "parent = \"rod 3\"")),
        "line 36: joint[theta2].parent: `rod 3` is not a body of the file"
    );
    assert!(error_of(&with("mass = 1.0", "mass = -1.0")).starts_with("line 16: body[rod 1].mass: "));
    assert!(error_of(&with(
        "q = [0.5235987755982988, -0.5235987755982988]",
        "q = [0.5]"
    ))
    .starts_with("line 11: q: needs 2 value(s) (theta1, theta2), got 1"));
    // A value the page gives is named, not located in the file.
    let e = error_of(&json!({ "file": DOUBLE_PENDULUM, "q": [0.1, 0.2, 0.3] }));
    assert_eq!(e, "q: needs 2 value(s) (theta1, theta2), got 3");
    let e = error_of(&json!({ "file": DOUBLE_PENDULUM, "restitution": 1.5 }));
    assert!(e.starts_with("restitution: 1.5 is out of range"), "{e}");
    // A planar file said to be spatial.
    let e = error_of(&json!({ "file": format!("space = \"3d\"\n{DOUBLE_PENDULUM}") }));
    assert!(
        e.starts_with("line ") && e.contains("body[rod 1].inertia"),
        "{e}"
    );
    // The request itself.
    assert!(error_of(&json!({ "text": "" })).starts_with("request: unknown field `text`"));
    assert!(error_of(&json!({ "file": DOUBLE_PENDULUM, "u": [null, 1] })).starts_with("request: "));
}

/// Any prefix of a file, any line dropped: an answer or one line of error, never a trap.
#[test]
fn any_cut_of_a_file_answers() {
    for text in [DOUBLE_PENDULUM, ARM] {
        let lines: Vec<&str> = text.lines().collect();
        for k in 0..=lines.len() {
            for cut in [
                lines[..k].join("\n"),
                [&lines[..k], &lines[(k + 1).min(lines.len())..]]
                    .concat()
                    .join("\n"),
            ] {
                let v = answer(&json!({ "file": cut }));
                match v["error"].as_str() {
                    Some(e) => assert!(!e.is_empty() && !e.contains('\n'), "{e}"),
                    None => assert!(v["results"].is_array()),
                }
            }
        }
    }
}

#[test]
fn c_abi_round_trip() {
    for (text, call) in [
        (
            json!({ "file": DOUBLE_PENDULUM }).to_string(),
            impax_wasm::impax_mechanism as unsafe extern "C" fn(*mut u8, usize) -> *const u8,
        ),
        (
            json!({ "mechanism": "ring-pendulum", "samples": 10 }).to_string(),
            impax_wasm::impax_conserved,
        ),
    ] {
        let ptr = impax_wasm::impax_alloc(text.len());
        // SAFETY: `ptr` has room for `text.len()` bytes; it is freed by the call.
        let out = unsafe {
            std::ptr::copy_nonoverlapping(text.as_ptr(), ptr, text.len());
            call(ptr, text.len())
        };
        // SAFETY: the module keeps the answer until the next call.
        let answer = unsafe { std::slice::from_raw_parts(out, impax_wasm::impax_output_len()) };
        let v: Value = serde_json::from_slice(answer).unwrap();
        assert!(v["error"].is_null(), "{v}");
    }
}
