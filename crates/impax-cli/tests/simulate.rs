//! `impax simulate` end to end: the three built-ins with table, JSON, CSV, plot and
//! animation; the first bounce against `impax compare`; bad input.

use assert_cmd::Command;
use serde_json::Value;

fn impax() -> Command {
    Command::cargo_bin("impax").expect("the impax binary is built")
}

fn run_ok(args: &[&str]) -> String {
    let out = impax().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "impax {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn bad(args: &[&str], needle: &str) {
    let out = impax().args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "impax {args:?}: {stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(
        stderr.lines().filter(|l| !l.trim().is_empty()).count(),
        1,
        "{stderr}"
    );
    assert!(stderr.contains(needle), "`{stderr}` lacks `{needle}`");
}

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("impax-sim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn every_builtin_runs_with_every_output() {
    for name in ["bouncing-ball", "rod-drop", "double-pendulum-drop"] {
        let (csv, png, svg, anim) = (
            tmp(&format!("{name}.csv")),
            tmp(&format!("{name}.png")),
            tmp(&format!("{name}-plot.svg")),
            tmp(&format!("{name}-anim.svg")),
        );
        let out = impax()
            .args(["simulate", name, "--csv"])
            .arg(&csv)
            .arg("--plot")
            .arg(&png)
            .arg("--animate")
            .arg(&anim)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let table = String::from_utf8(out.stdout).unwrap();
        assert!(table.contains("stop at t ="), "{name}");
        assert!(
            table.lines().any(|l| l.trim_start().starts_with("1 ")),
            "{name}: no impact row"
        );
        // CSV: header and one row per sample.
        let text = std::fs::read_to_string(&csv).unwrap();
        let mut lines = text.lines();
        let header = lines.next().unwrap();
        assert!(header.starts_with("t,mode,") && header.ends_with("kinetic,potential,energy"));
        let cols = header.split(',').count();
        assert!(lines.clone().count() > 100);
        assert!(lines.all(|l| l.split(',').count() == cols));
        assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
        // The animation: valid SVG with SMIL animations.
        let doc = std::fs::read_to_string(&anim).unwrap();
        let xml = roxmltree::Document::parse(&doc).expect("well-formed SVG");
        assert!(
            xml.descendants()
                .filter(|n| n.has_tag_name("animate"))
                .count()
                >= 3
        );
        // SVG plot too.
        let out = impax()
            .args(["simulate", name, "--plot"])
            .arg(&svg)
            .output()
            .unwrap();
        assert!(out.status.success());
        roxmltree::Document::parse(&std::fs::read_to_string(&svg).unwrap())
            .expect("well-formed SVG plot");
    }
}

#[test]
fn json_has_the_impacts_and_the_stop_reason() {
    let doc: Value = serde_json::from_str(&run_ok(&[
        "simulate",
        "bouncing-ball",
        "--restitution",
        "0.5",
        "--friction",
        "0",
        "--alpha-deg",
        "0",
        "--speed",
        "0",
        "--json",
    ]))
    .unwrap();
    let impacts = doc["impacts"].as_array().unwrap();
    assert!(impacts.len() > 5);
    for i in impacts {
        assert!(i["time"].is_f64());
        assert!(i["energy_change"].as_f64().unwrap() <= 0.0);
        assert!(!i["phases"].as_array().unwrap().is_empty());
    }
    assert_eq!(doc["stop"]["id"], "rest");
    // Zeno time of a ball dropped from h = 1 with e = 0.5: t1 (1 + 2e/(1 − e)).
    let t1 = (2.0f64 / 9.81).sqrt();
    let expected = t1 * (1.0 + 2.0 * 0.5 / 0.5);
    let limit = doc["events"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["kind"] == "zeno")
        .unwrap()["limit_time"]
        .as_f64()
        .unwrap();
    assert!((limit - expected).abs() < 1e-9, "{limit} vs {expected}");
    assert!((doc["stop"]["time"].as_f64().unwrap() - expected).abs() < 1e-9);
}

#[test]
fn first_bounce_equals_impax_compare_for_the_same_state() {
    let doc: Value = serde_json::from_str(&run_ok(&[
        "simulate",
        "bouncing-ball",
        "--spin-ratio",
        "-0.8",
        "--json",
    ]))
    .unwrap();
    let first = &doc["impacts"][0];
    let u: Vec<f64> = first["u_before"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let after: Vec<f64> = first["u_after"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let r = 0.1;
    let speed = u[0].hypot(u[1]);
    let alpha = u[0].atan2(-u[1]).to_degrees();
    let gamma = u[2] * r / speed;
    let c: Value = serde_json::from_str(&run_ok(&[
        "compare",
        "--alpha-deg",
        &format!("{alpha:e}"),
        "--speed",
        &format!("{speed:e}"),
        "--spin-ratio",
        &format!("{gamma:e}"),
        "--radius",
        "0.1",
        "--friction",
        "0.3",
        "--restitution",
        "0.8",
        "--law",
        "energetic",
        "--json",
    ]))
    .unwrap();
    let b = &c["results"][0]["body_velocity_after"];
    let (vx, vy, w) = (
        b["vx"].as_f64().unwrap(),
        b["vy"].as_f64().unwrap(),
        b["omega"].as_f64().unwrap(),
    );
    assert!((vx - after[0]).abs() < 1e-12, "{vx} vs {}", after[0]);
    assert!((vy - after[1]).abs() < 1e-12, "{vy} vs {}", after[1]);
    assert!((w - after[2]).abs() < 1e-10, "{w} vs {}", after[2]);
}

#[test]
fn a_toml_scenario_and_flags_agree() {
    let path = tmp("rod.toml");
    std::fs::write(&path, "simulation = \"rod-drop\"\nlaw = \"poisson\"\nangle_deg = 40.0\nheight = 0.3\nuntil = 1.0\n").unwrap();
    let a = run_ok(&["simulate", path.to_str().unwrap(), "--json"]);
    let b = run_ok(&[
        "simulate",
        "rod-drop",
        "--law",
        "poisson",
        "--angle-deg",
        "40",
        "--height",
        "0.3",
        "--until",
        "1",
        "--json",
    ]);
    assert_eq!(a, b);
}

#[test]
fn whittaker_shows_the_energy_gain() {
    let text = run_ok(&[
        "simulate",
        "bouncing-ball",
        "--law",
        "whittaker",
        "--friction",
        "0.4",
        "--restitution",
        "0.7",
    ]);
    assert!(text.contains("GAIN"), "{text}");
    assert!(text.contains("energy rises at"));
}

#[test]
fn bad_simulations_are_one_line_and_exit_2() {
    bad(&["simulate", "trampoline"], "not a built-in scenario");
    bad(&["simulate", "bouncing-ball", "--height", "-1"], "height");
    bad(&["simulate", "bouncing-ball", "--until", "0"], "until");
    bad(
        &["simulate", "bouncing-ball", "--restitution", "2"],
        "restitution",
    );
    bad(
        &["simulate", "bouncing-ball", "--law", "smith-centre"],
        "law",
    );
    bad(
        &["simulate", "bouncing-ball", "--law", "magic"],
        "unknown impact law",
    );
    bad(
        &["simulate", "rod-drop", "--radius", "1"],
        "radius: not a parameter of rod-drop",
    );
    bad(
        &["simulate", "double-pendulum-drop", "--floor", "0.5"],
        "below its surface",
    );
    bad(
        &["simulate", "double-pendulum-drop", "--angles-deg", "1,2,3"],
        "angles_deg: needs 2",
    );
    bad(
        &["simulate", "bouncing-ball", "--animate", "x.png"],
        "animated SVG",
    );
    bad(&["simulate", "bouncing-ball", "--samples", "0"], "samples");
}
