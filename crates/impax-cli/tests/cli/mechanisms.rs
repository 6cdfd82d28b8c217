//! `impax compare MECHANISM` and `impax conserved MECHANISM` end to end: the JSON contract,
//! the physics it must show (Kane's paradox on the double pendulum; paper B's conserved
//! quantities), and bad input (one line, exit 2).

use crate::support::{bad, impax, json};

use std::io::Write;

#[test]
fn double_pendulum_compare_shows_kanes_paradox() {
    let doc = json(&[
        "compare",
        "double-pendulum",
        "--angles-deg",
        "30,0",
        "--rates",
        "-1,2",
        "--friction",
        "0.5",
        "--restitution",
        "0.5",
        "--json",
    ]);
    assert_eq!(doc["mechanism"], "double-pendulum");
    // T⁻ = ½ uᵀ M u with M = [[4/3, cos30°/2], [·, 1/3]] (unit rods), u = (−1, 2).
    let c = 30f64.to_radians().cos();
    let t0 = 0.5 * (4.0 / 3.0 - 2.0 * 0.5 * c * 2.0 + 1.0 / 3.0 * 4.0);
    let e0 = doc["energy_before"].as_f64().unwrap();
    assert!((e0 - t0).abs() < 1e-14, "{e0} vs {t0}");
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 8);
    let by = |id: &str| results.iter().find(|r| r["law"] == id).unwrap();
    let w = by("whittaker");
    assert!(w["energy_change"].as_f64().unwrap() > 0.0);
    assert_eq!(w["verdict"], "energy-gained");
    for id in ["newton", "poisson", "energetic"] {
        assert!(by(id)["energy_change"].as_f64().unwrap() < 0.0, "{id}");
    }
    for r in results {
        let (a, b) = (
            r["energy_change"].as_f64().unwrap(),
            r["energy_change_from_velocities"].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 1e-13, "{}: {a} vs {b}", r["law"]);
        let ratio = r["energy_ratio"].as_f64().unwrap();
        assert!((ratio - (e0 + a) / e0).abs() < 1e-13);
        assert_eq!(r["velocities_after"].as_array().unwrap().len(), 2);
    }
    // Newton-type laws fix v_n⁺ = −e v_n⁻; with rod 2 vertical only θ1 moves the tip
    // vertically: θ̇1⁺ = −e v_n⁻ / (l1 sin θ1) = 0.25 / 0.5.
    let th1 = by("newton")["velocities_after"][0].as_f64().unwrap();
    assert!((th1 - 0.5).abs() < 1e-12, "{th1}");
}

#[test]
fn mechanism_toml_and_flags_agree() {
    let mut f = tempfile_in_target("dp.toml");
    writeln!(
        f.1,
        "mechanism = \"double-pendulum\"\nfriction = 0.3\nrestitution = 0.8\nmasses = [2.0, 1.0]\nlengths = [1.5, 0.7]\nangles_deg = [20.0, -35.0]\nrates = [-1.0, 2.5]\nlaws = [\"energetic\", \"whittaker\"]"
    )
    .unwrap();
    let from_file = json(&["compare", f.0.to_str().unwrap(), "--json"]);
    let from_flags = json(&[
        "compare",
        "double-pendulum",
        "--friction",
        "0.3",
        "--restitution",
        "0.8",
        "--masses",
        "2,1",
        "--lengths",
        "1.5,0.7",
        "--angles-deg",
        "20,-35",
        "--rates",
        "-1,2.5",
        "--law",
        "energetic,whittaker",
        "--json",
    ]);
    assert_eq!(from_file["results"], from_flags["results"]);
    assert_eq!(from_file["results"].as_array().unwrap().len(), 2);
    // A flag overrides the file.
    let over = json(&[
        "compare",
        f.0.to_str().unwrap(),
        "--friction",
        "0",
        "--json",
    ]);
    assert_eq!(over["problem"]["friction"], 0.0);
}

fn tempfile_in_target(name: &str) -> (std::path::PathBuf, std::fs::File) {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-mech-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    let f = std::fs::File::create(&path).unwrap();
    (path, f)
}

#[test]
fn ring_pendulum_conserved_quantities() {
    let doc = json(&["conserved", "ring-pendulum", "--json"]);
    assert_eq!(doc["cyclic"], serde_json::json!(["x"]));
    let q = doc["quantities"].as_array().unwrap();
    let get = |name: &str| q.iter().find(|x| x["name"] == name).unwrap();
    for (name, conserved) in [
        ("p_x", true),
        ("P_x", false),
        ("energy", true),
        ("boost x", true),
        ("p_phi", false),
    ] {
        assert_eq!(get(name)["conserved"], conserved, "{name}: {}", get(name));
    }
    assert_eq!(get("boost x")["symmetry_check"]["holds"], true);
    assert!(get("p_x")["relative_deviation"].as_f64().unwrap() < 1e-10);
    assert!(get("P_x")["relative_deviation"].as_f64().unwrap() > 0.1);
    // Defaults: M = m = l = R = 1, ẋ = 0.5, φ̇ = 0: p_x = 3 m ẋ = 1.5.
    assert!((get("p_x")["initial"].as_f64().unwrap() - 1.5).abs() < 1e-14);
}

#[test]
fn cart_pendulum_momentum_is_the_cyclic_integral() {
    let doc = json(&["conserved", "cart-pendulum", "--masses", "2,1", "--json"]);
    let q = doc["quantities"].as_array().unwrap();
    let get = |name: &str| q.iter().find(|x| x["name"] == name).unwrap();
    for name in ["p_x", "P_x", "energy", "boost x"] {
        assert_eq!(get(name)["conserved"], true, "{name}");
    }
    assert_eq!(get("p_x")["initial"], get("P_x")["initial"]);
}

#[test]
fn conserved_table_and_plot() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-mech-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("ring.png");
    let out = impax()
        .args(["conserved", "ring-pendulum", "--samples", "200", "--plot"])
        .arg(&png)
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("cyclic coordinates (∂L/∂q ≡ 0): x"));
    assert!(text
        .lines()
        .any(|l| l.starts_with("P_x") && l.contains("NOT conserved")));
    assert!(text
        .lines()
        .any(|l| l.starts_with("boost x") && l.ends_with("conserved")));
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
}

#[test]
fn bad_mechanism_input_is_one_line_and_exit_2() {
    bad(&["conserved", "pendulum"], "not a built-in mechanism");
    bad(
        &["compare", "double-pendulum", "--masses", "-1,1"],
        "mass 1",
    );
    bad(
        &["compare", "double-pendulum", "--angles-deg", "30"],
        "angles_deg: needs 2",
    );
    bad(
        &["compare", "double-pendulum", "--rates", "1,nan"],
        "rates[1]",
    );
    bad(
        &["compare", "double-pendulum", "--alpha-deg", "30"],
        "--alpha-deg",
    );
    bad(&["compare", "ring-pendulum"], "no contact point");
    bad(&["compare", "--angles-deg", "30"], "--angles-deg");
    // A receding tip: not an impact.
    bad(
        &["compare", "double-pendulum", "--rates", "1,-2"],
        "approach",
    );
    bad(
        &["conserved", "ring-pendulum", "--duration", "-1"],
        "--duration",
    );
    bad(
        &["conserved", "ring-pendulum", "--gravity", "-9.81"],
        "gravity",
    );
    bad(&["conserved", "ring-pendulum", "--about", "1"], "about");
    bad(&["conserved", "cart-pendulum", "--radius", "2"], "radius");
    bad(
        &["conserved", "ring-pendulum", "--plot", "x.gif"],
        ".png or .svg",
    );
}

/// A mechanism file spinning at 10²⁰ rad/s: `conserved` refuses it at once, naming
/// `duration` (the pace of its first thousand steps projects far past the budget), instead of
/// spending the whole million-step budget (seconds) before failing.
#[test]
fn conserved_refuses_a_hopeless_pace_early() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/mechanisms/cart-pendulum.toml"
    ))
    .unwrap();
    let u = text.lines().find(|l| l.starts_with("u = ")).unwrap();
    let file = crate::support::write(
        "cart-pendulum-1e20.toml",
        &text.replace(u, "u = [-1, 1e20]"),
    );
    let path = file.to_str().unwrap();
    let line = bad(
        &["conserved", path, "--duration", "0.1", "--json"],
        "duration",
    );
    // The early verdict (after the first thousand steps), not the spent budget.
    assert!(line.contains("at its pace so far"), "{line}");
}
