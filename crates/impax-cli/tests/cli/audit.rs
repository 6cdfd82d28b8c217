//! `impax audit`: the built-in sphere, rod and double pendulum, TOML scenarios (a body, a
//! mechanism and a 3D body), the JSON contract, and bad input (one line on stderr, exit
//! code 2).
//!
//! The rod is the built-in `rod` (uniform rod at 50° to the floor, μ = 0.8, e = 1, translating
//! at (0.5, −1)): `lcp` gains 18.3 % (T⁺/T⁻ = 1.1835, the figure pymunk gives too), equal to
//! `newton` because both stick; `energetic` dissipates 4.3 %.

use crate::support::{bad, json, run_ok};

use serde_json::Value;

/// A file in the temporary directory, removed on drop.
struct Temp(std::path::PathBuf);
impl Temp {
    fn new(name: &str, text: &str) -> Self {
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("impax-audit-tests-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        Temp(p)
    }
    fn path(&self) -> &str {
        self.0.to_str().unwrap()
    }
}
impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn result<'a>(doc: &'a Value, law: &str) -> &'a Value {
    doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == law)
        .unwrap_or_else(|| panic!("no {law}"))
}

fn engine<'a>(doc: &'a Value, law: &str) -> &'a Value {
    doc["engine_rules"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == law)
        .unwrap_or_else(|| panic!("no {law}"))
}

fn ratio(doc: &Value, law: &str) -> f64 {
    result(doc, law)["energy_ratio"].as_f64().unwrap()
}

#[test]
fn rod_the_engine_rule_gains_eighteen_percent() {
    let doc = json(&["audit", "rod", "--json"]);
    for key in [
        "scenario",
        "velocity_names",
        "velocities_before",
        "problem",
        "energy_before",
        "reference",
        "results",
        "engine_rules",
    ] {
        assert!(doc.get(key).is_some(), "missing {key}");
    }
    let laws: Vec<&str> = doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["law"].as_str().unwrap())
        .collect();
    assert_eq!(laws, ["newton", "poisson", "energetic", "lcp", "whittaker"]);
    assert_eq!(result(&doc, "lcp")["role"], "engine");
    assert_eq!(result(&doc, "energetic")["role"], "exact");
    // T⁻ = ½ (0.5² + 1²) = 0.625 (no spin).
    assert!((doc["energy_before"].as_f64().unwrap() - 0.625).abs() < 1e-15);
    assert!((ratio(&doc, "lcp") - 1.183466).abs() < 1e-6);
    assert!((ratio(&doc, "newton") - ratio(&doc, "lcp")).abs() < 1e-12);
    assert!((ratio(&doc, "whittaker") - 1.431929).abs() < 1e-6);
    assert!((ratio(&doc, "energetic") - 0.956587).abs() < 1e-6);
    assert!(ratio(&doc, "poisson") < 1.0);
    let lcp = engine(&doc, "lcp");
    assert_eq!(lcp["reference"], "energetic");
    assert_eq!(lcp["verdict"]["id"], "gains-energy");
    let text = lcp["verdict"]["text"].as_str().unwrap();
    assert!(text.contains("returns 18.3 % more energy"), "{text}");
    assert!(text.contains("dissipates 4.3 %"), "{text}");
    // The deviation record is the difference of the two results.
    let d = lcp["velocities_after_difference"].as_array().unwrap();
    let (a, b) = (
        result(&doc, "lcp")["velocities_after"].as_array().unwrap(),
        result(&doc, "energetic")["velocities_after"]
            .as_array()
            .unwrap(),
    );
    for i in 0..3 {
        let want = a[i].as_f64().unwrap() - b[i].as_f64().unwrap();
        assert!((d[i].as_f64().unwrap() - want).abs() < 1e-15);
    }
    let de = lcp["energy_change_difference"].as_f64().unwrap();
    let want = result(&doc, "lcp")["energy_change"].as_f64().unwrap()
        - result(&doc, "energetic")["energy_change"].as_f64().unwrap();
    assert!((de - want).abs() < 1e-15);
    assert_eq!(engine(&doc, "whittaker")["verdict"]["id"], "gains-energy");
    let table = run_ok(&["audit", "rod"]);
    assert!(table.contains("verdict — lcp: an engine of this kind"));
    assert!(table.contains("returns 18.3 % more energy"));
}

#[test]
fn sphere_the_engine_rule_is_right_and_whittaker_is_not() {
    let doc = json(&["audit", "sphere", "--json"]);
    // The seed's case: the slip halts and the sphere leaves rolling; lcp sticks.
    assert_eq!(engine(&doc, "lcp")["verdict"]["id"], "matches");
    assert!((ratio(&doc, "lcp") - ratio(&doc, "energetic")).abs() < 1e-12);
    assert_eq!(engine(&doc, "whittaker")["verdict"]["id"], "gains-energy");
    // Paper A eq. 13 at γ = 0: ΔT/T0 = +0.2424.
    assert!((ratio(&doc, "whittaker") - 1.242403).abs() < 1e-6);
    let table = run_ok(&["audit", "sphere", "--friction", "0.1"]);
    assert!(table.contains("μ = 0.1"));
}

#[test]
fn double_pendulum_the_engine_dissipates_less_than_it_should() {
    let doc = json(&["audit", "double-pendulum", "--json"]);
    assert_eq!(
        doc["velocity_names"],
        serde_json::json!(["theta1'", "theta2'"])
    );
    // Kane & Levinson's state: lcp sticks like newton (0.22291), energetic 0.15960.
    assert!((ratio(&doc, "lcp") - 0.22291).abs() < 1e-5);
    assert!((ratio(&doc, "energetic") - 0.15960).abs() < 1e-5);
    assert_eq!(engine(&doc, "lcp")["verdict"]["id"], "dissipates-less");
    assert!((ratio(&doc, "whittaker") - 1.26087).abs() < 1e-5);
    let other = json(&[
        "audit",
        "double-pendulum",
        "--angles-deg",
        "20,-35",
        "--rates",
        "-1,2.5",
        "--friction",
        "0.3",
        "--restitution",
        "0.8",
        "--json",
    ]);
    assert!(other["scenario"].as_str().unwrap().contains("θ1 = 20°"));
}

#[test]
fn toml_scenarios_a_body_and_a_mechanism() {
    let body = Temp::new(
        "rod.toml",
        "friction = 0.8\nrestitution = 1.0\n[body]\nshape = \"rod\"\nmass = 1.0\nlength = 1.0\nangle_deg = 50.0\nvelocity = [0.5, -1.0]\nomega = 0.0\n",
    );
    let doc = json(&["audit", body.path(), "--json"]);
    // The same rod as the built-in, described as a body: the same energy ratios.
    let builtin = json(&["audit", "rod", "--json"]);
    for law in ["newton", "poisson", "energetic", "lcp", "whittaker"] {
        assert!(
            (ratio(&doc, law) - ratio(&builtin, law)).abs() < 1e-12,
            "{law}"
        );
    }
    assert_eq!(
        doc["velocity_names"],
        serde_json::json!(["vx", "vy", "omega"])
    );
    let mech = Temp::new(
        "dp.toml",
        "mechanism = \"double-pendulum\"\nfriction = 0.5\nrestitution = 0.5\nlaws = [\"whittaker\"]\n",
    );
    let doc = json(&["audit", mech.path(), "--json"]);
    assert_eq!(doc["results"].as_array().unwrap().len(), 5);
    assert!((ratio(&doc, "whittaker") - 1.26087).abs() < 1e-5);
}

#[test]
fn bad_input_one_line_exit_2() {
    bad(&["audit", "nowhere.toml"], "scenario");
    bad(&["audit", "rod", "--friction", "-0.1"], "friction");
    bad(&["audit", "rod", "--restitution", "1.5"], "restitution");
    bad(&["audit", "rod", "--friction", "NaN"], "friction");
    bad(&["audit", "ring-pendulum"], "no impact");
    bad(
        &["audit", "double-pendulum", "--angles-deg", "30"],
        "angles_deg",
    );
    let body = Temp::new(
        "sphere.toml",
        "friction = 0.4\nrestitution = 0.7\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nspeed = 1.0\nalpha_deg = 30.0\n",
    );
    bad(&["audit", body.path(), "--rates", "1,2"], "--rates");
    let space = Temp::new(
        "s3.toml",
        "space = \"3d\"\nfriction = 0.5\nrestitution = 0.5\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nvelocity = [0.5, 0.0, -1.0]\nomega = [0.0, 0.0, 0.0]\n",
    );
    bad(
        &["audit", space.path(), "--angles-deg", "30,0"],
        "--angles-deg",
    );
    bad(
        &["audit", space.path(), "--restitution", "2"],
        "restitution",
    );
    let broken = Temp::new("broken.toml", "friction = \n");
    bad(&["audit", broken.path()], "broken.toml");
    bad(&["audit"], "SCENARIO");
}

fn docs_rod() -> String {
    format!(
        "{}/../../docs/engine-audit-rod.toml",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// The gain region of `lcp` drawn in docs/src/engine-audit.md: where the rod sticks at e = 1,
/// ΔT = ½ v_t⁻ p_t > 0 exactly when 12 sin θ cos θ > 1 + 3 cos² θ (W_tn = −3 sin θ cos θ,
/// W_nn = 1 + 3 cos² θ for m = l = 1, v⁻ = (0.5, −1)), whatever μ.
#[test]
fn sweep_and_map_show_the_lcp_gain_region() {
    let rod = docs_rod();
    let csv = run_ok(&[
        "sweep",
        &rod,
        "--grid",
        "angle-deg=5:89:85",
        "--set",
        "friction=1.0",
        "--law",
        "lcp",
        "--columns",
        "status,sequence,energy_ratio",
        "--quiet",
    ]);
    let mut sticks = 0;
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let theta = f[0].parse::<f64>().unwrap().to_radians();
        if f[3] != "stick" {
            continue;
        }
        sticks += 1;
        let (s, c) = theta.sin_cos();
        let margin = 12.0 * s * c - 1.0 - 3.0 * c * c;
        if margin.abs() > 1e-9 {
            assert_eq!(f[2] == "energy-gained", margin > 0.0, "{line}");
        }
    }
    assert!(sticks > 70, "{sticks}");
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-audit-map-{}.png", std::process::id()));
    run_ok(&[
        "map",
        &rod,
        "--grid",
        "angle-deg=1:89:45",
        "--grid",
        "friction=0:1.5:31",
        "--law",
        "lcp",
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    let png = std::fs::read(&out).unwrap();
    let _ = std::fs::remove_file(&out);
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

/// A 3D scenario: the seed's sphere in 3D gives the planar audit's energy ratios (the
/// sphere's W = diag(7/2, 7/2, 1) decouples the second tangent); a tilted box is audited
/// with the spatial laws, its `lcp` entry listing every solution.
#[test]
fn spatial_scenarios() {
    let (s, c) = 30f64.to_radians().sin_cos();
    let sphere = Temp::new(
        "sphere3.toml",
        &format!("space = \"3d\"\nfriction = 0.4\nrestitution = 0.7\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nvelocity = [{s:?}, 0.0, {:?}]\nomega = [0.0, 0.0, 0.0]\n", -c),
    );
    let doc = json(&["audit", sphere.path(), "--json"]);
    let planar = json(&["audit", "sphere", "--json"]);
    for law in ["newton", "poisson", "energetic", "lcp", "whittaker"] {
        assert!(
            (ratio(&doc, law) - ratio(&planar, law)).abs() < 1e-9,
            "{law}"
        );
    }
    assert_eq!(engine(&doc, "lcp")["verdict"]["id"], "matches");
    let boxed = Temp::new(
        "box3.toml",
        "space = \"3d\"\nfriction = 0.8\nrestitution = 1.0\n[body]\nshape = \"box\"\nmass = 1.0\nhalf_extents = [1.0, 0.2, 0.1]\norientation_deg = [10.0, 40.0, 25.0]\nvelocity = [0.5, 0.3, -1.0]\nomega = [0.0, 0.0, 0.0]\n",
    );
    let doc = json(&["audit", boxed.path(), "--json"]);
    assert_eq!(
        doc["velocity_names"],
        serde_json::json!(["vx", "vy", "vz", "omega_x", "omega_y", "omega_z"])
    );
    assert!(!result(&doc, "lcp")["all_solutions"]
        .as_array()
        .unwrap()
        .is_empty());
    assert_eq!(doc["problem"]["w"].as_array().unwrap().len(), 3);
    let text = run_ok(&["audit", boxed.path(), "--friction", "0.3"]);
    assert!(text.contains("contact space (3D)") && text.contains("μ = 0.3"));
}
