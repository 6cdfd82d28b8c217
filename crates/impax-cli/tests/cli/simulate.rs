//! `impax simulate` end to end: the five built-ins with table, JSON, CSV, plot and
//! animation; the first bounce against `impax compare`; impacts at several contacts and
//! contacts that stay closed (rocking block, cradle, rod dropped flat); bad input.

use crate::support::{bad, impax, json, run_ok};

use serde_json::Value;

/// A scratch path of this module.
fn tmp(name: &str) -> std::path::PathBuf {
    crate::support::scratch(&format!("simulate-{name}"))
}

#[test]
fn every_builtin_runs_with_every_output() {
    for name in [
        "bouncing-ball",
        "rod-drop",
        "double-pendulum-drop",
        "rocking-block",
        "cradle",
    ] {
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
    bad(&["simulate", "cradle", "--balls", "1"], "balls");
    bad(&["simulate", "cradle", "--balls", "21"], "balls");
    bad(&["simulate", "cradle", "--gap", "-0.1"], "gap");
    bad(&["simulate", "cradle", "--v0", "0"], "v0");
    bad(&["simulate", "cradle", "--radius", "nan"], "radius");
    bad(
        &["simulate", "cradle", "--gravity", "9.81"],
        "gravity: not a parameter of cradle",
    );
    bad(&["simulate", "rocking-block", "--angle-deg", "95"], "angle");
    bad(
        &["simulate", "rocking-block", "--half-width", "0"],
        "half-width",
    );
    bad(
        &["simulate", "rocking-block", "--half-height", "-1"],
        "half-height",
    );
    bad(&["simulate", "rocking-block", "--omega", "inf"], "omega");
    bad(
        &["simulate", "rocking-block", "--balls", "3"],
        "balls: not a parameter of rocking-block",
    );
    bad(
        &["simulate", "rod-drop", "--v0", "1"],
        "v0: not a parameter of rod-drop",
    );
}

#[test]
fn the_rocking_block_rocks_by_housner_and_comes_to_rest() {
    let doc = json(&["simulate", "rocking-block", "--json"]);
    assert_eq!(doc["stop"]["id"], "rest");
    let impacts = doc["impacts"].as_array().unwrap();
    assert!(impacts.len() > 20);
    for i in impacts {
        // Both bottom corners in every impact, the striking one first, under lcp (the run's
        // law, energetic, takes one contact).
        assert_eq!(i["law"], "lcp");
        let contacts = i["contacts"].as_array().unwrap();
        assert_eq!(contacts.len(), 2);
        assert_eq!(contacts[0]["contact"], i["contact"]);
        // Housner: ω⁺/ω⁻ = 1 − (3/2) sin²α = 0.85 for b = 0.2, h = 0.6.
        let ratio = i["u_after"][2].as_f64().unwrap() / i["u_before"][2].as_f64().unwrap();
        assert!((ratio - 0.85).abs() < 1e-12, "{ratio}");
    }
    let closes = doc["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "closes")
        .count();
    assert!(closes >= impacts.len());
    let l = &doc["ledger"];
    assert!(l["residual"].as_f64().unwrap().abs() < 1e-10, "{l}");
    // The table names the contacts of each impact and the law.
    let text = run_ok(&["simulate", "rocking-block"]);
    assert!(
        text.contains("corner B: stick; corner A: off (lcp)"),
        "{text}"
    );
    assert!(text.contains("rest (at rest)"));
}

#[test]
fn the_cradle_passes_the_velocity_with_gaps_and_is_one_impact_without() {
    let speeds = |doc: &Value| -> Vec<f64> {
        let last = doc["impacts"].as_array().unwrap().last().unwrap();
        let u = last["u_after"].as_array().unwrap();
        (0..u.len() / 3)
            .map(|i| u[3 * i].as_f64().unwrap())
            .collect()
    };
    let gaps = json(&[
        "simulate", "cradle", "--balls", "4", "--gap", "0.05", "--json",
    ]);
    assert_eq!(gaps["impacts"].as_array().unwrap().len(), 3);
    assert_eq!(speeds(&gaps), vec![0.0, 0.0, 0.0, 1.0]);
    let touching = json(&["simulate", "cradle", "--law", "lcp", "--json"]);
    let impacts = touching["impacts"].as_array().unwrap();
    assert_eq!(impacts.len(), 1);
    assert_eq!(impacts[0]["contacts"].as_array().unwrap().len(), 2);
    for (v, x) in speeds(&touching)
        .iter()
        .zip([-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0])
    {
        assert!((v - x).abs() < 1e-12);
    }
    let sequential = json(&["simulate", "cradle", "--law", "sequential", "--json"]);
    assert_eq!(sequential["impacts"][0]["law"], "sequential");
    assert_eq!(speeds(&sequential), vec![0.0, 0.0, 1.0]);
    // Eight touching balls are seven contacts: more than lcp takes.
    let many = json(&["simulate", "cradle", "--balls", "8", "--json"]);
    assert_eq!(many["stop"]["id"], "unsupported-contact");
    assert_eq!(many["stop"]["touching"].as_array().unwrap().len(), 6);
}

#[test]
fn a_rod_dropped_flat_lands_on_both_ends_and_rests_lying_flat() {
    let doc = json(&["simulate", "rod-drop", "--angle-deg", "0", "--json"]);
    assert_eq!(doc["stop"]["id"], "rest");
    let first = &doc["impacts"][0];
    assert_eq!(first["law"], "lcp");
    let names: Vec<&str> = first["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["contact"].as_str().unwrap())
        .collect();
    assert_eq!(names, vec!["end A", "end B"]);
    let events = doc["events"].as_array().unwrap();
    assert!(events.iter().any(|e| e["kind"] == "rest"));
    // CSV: the modes of the samples include closed contacts and rest.
    let csv = tmp("flat.csv");
    impax()
        .args(["simulate", "rod-drop", "--angle-deg", "10", "--csv"])
        .arg(&csv)
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.lines().any(|l| l.contains(",contact,")), "{text}");
    assert!(text.lines().last().unwrap().contains(",rest,"));
}
