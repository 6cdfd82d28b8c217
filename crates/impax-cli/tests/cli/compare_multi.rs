//! `impax compare NAME` for the built-in systems struck at several contacts: the JSON keys,
//! the published answers through the command line (Housner's rocking ratio, the cradle's two
//! answers, the rod leaving level), and flags that do not apply refused with exit 2.

use crate::support::{f, fails, json};
use serde_json::Value;

fn law<'a>(doc: &'a Value, id: &str) -> &'a Value {
    doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == id)
        .unwrap_or_else(|| panic!("no {id}"))
}

#[test]
fn every_built_in_has_the_keys() {
    for name in ["rod-flat", "rocking-block", "cradle", "ball-ball-wall"] {
        let doc = json(&["compare", name, "--json"]);
        for key in [
            "scenario",
            "description",
            "coordinates",
            "u_before",
            "contact_names",
            "problem",
            "energy_before",
            "results",
        ] {
            assert!(doc.get(key).is_some(), "{name}: missing {key}");
        }
        assert_eq!(doc["scenario"], name);
        let n = doc["coordinates"].as_array().unwrap().len();
        for r in doc["results"].as_array().unwrap() {
            assert_eq!(r["velocities_after"].as_array().unwrap().len(), n);
            let (a, b) = (
                f(&r["energy_change"]),
                f(&r["energy_change_from_velocities"]),
            );
            assert!((a - b).abs() < 1e-12 * f(&doc["energy_before"]), "{name}");
            // lzb is integrated (relative tolerance 1e-12): its ΔT carries that error.
            assert!(f(&r["energy_ratio"]) <= 1.0 + 1e-10, "{name}");
        }
    }
}

#[test]
fn housners_ratio_from_the_command_line() {
    let (b, h, w) = (0.3, 0.9, -2.0);
    let doc = json(&[
        "compare",
        "rocking-block",
        "--half-width",
        "0.3",
        "--half-height",
        "0.9",
        "--omega",
        "-2",
        "--json",
    ]);
    let ratio = 1.0 - 1.5 * b * b / (b * b + h * h);
    for id in ["lcp", "sequential"] {
        let after = f(&law(&doc, id)["velocities_after"][2]);
        assert!((after / w - ratio).abs() < 1e-12, "{id}: {}", after / w);
    }
}

#[test]
fn the_cradles_two_answers() {
    let doc = json(&["compare", "cradle", "--balls", "4", "--v0", "2", "--json"]);
    let x = |id: &str, i: usize| f(&law(&doc, id)["velocities_after"][3 * i]);
    for i in 0..3 {
        assert!(x("sequential", i).abs() < 1e-12);
    }
    assert!((x("sequential", 3) - 2.0).abs() < 1e-12);
    // The LCP: momentum and energy conserved, the first ball not at rest.
    let p: f64 = (0..4).map(|i| x("lcp", i)).sum();
    let e: f64 = (0..4).map(|i| x("lcp", i).powi(2)).sum();
    assert!((p - 2.0).abs() < 1e-12 && (e - 4.0).abs() < 1e-12);
    assert!(x("lcp", 0) < -0.1);
}

#[test]
fn the_rod_leaves_level_under_lcp() {
    let doc = json(&[
        "compare",
        "rod-flat",
        "--vy",
        "-3",
        "--restitution",
        "0.4",
        "--law",
        "lcp",
        "--json",
    ]);
    let after = law(&doc, "lcp")["velocities_after"].as_array().unwrap();
    assert!(f(&after[0]).abs() < 1e-12);
    assert!((f(&after[1]) - 1.2).abs() < 1e-12);
    assert!(f(&after[2]).abs() < 1e-12);
}

#[test]
fn flags_that_do_not_apply_are_refused() {
    for (args, expected) in [
        (&["compare", "cradle", "--vy", "2"][..], "--vy"),
        (&["compare", "rod-flat", "--balls", "2"][..], "--balls"),
        (
            &["compare", "rod-flat", "--angles-deg", "2"][..],
            "--angles-deg",
        ),
        (&["compare", "rocking-block", "--speed", "2"][..], "--speed"),
        (&["compare", "--vy", "1"][..], "--vy"),
        (
            &["compare", "double-pendulum", "--balls", "3"][..],
            "--balls",
        ),
        (&["compare", "rod-flat", "--vy", "1"][..], "vy"),
        (&["compare", "rocking-block", "--omega", "1"][..], "omega"),
        (&["compare", "cradle", "--balls", "1"][..], "balls"),
        (&["compare", "cradle", "--law", "smith"][..], "law"),
        (
            &["compare", "ball-ball-wall", "--angle-deg", "95"][..],
            "angle-deg",
        ),
    ] {
        let err = fails(args);
        assert!(err.contains(expected), "{args:?}: {err}");
    }
}

/// `box-flat` in 3D: `lcp` lifts the box level at `e |v_z|` and takes
/// `μ m (1 + e) |v_z| ρ / I_z` from its spin (`ρ = √(a² + b²)`); the JSON has the spatial keys.
#[test]
fn box_flat_from_the_command_line() {
    let doc = json(&[
        "compare",
        "box-flat",
        "--omega",
        "6",
        "--friction",
        "0.1",
        "--restitution",
        "0.8",
        "--half-extents",
        "0.4,0.3,0.1",
        "--json",
    ]);
    assert_eq!(doc["scenario"], "box-flat");
    assert_eq!(doc["problem"]["rank"], 6);
    assert_eq!(doc["problem"]["w"].as_array().unwrap().len(), 12);
    let lcp = law(&doc, "lcp");
    let u: Vec<f64> = lcp["velocities_after"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    let iz = (0.16 + 0.09) / 3.0;
    let spin = 6.0 - 0.1 * 1.8 * 0.5 / iz;
    let expect = [0.0, 0.0, 0.8, 0.0, 0.0, spin];
    for i in 0..6 {
        assert!((u[i] - expect[i]).abs() < 1e-10, "{u:?}");
    }
    for c in lcp["contacts"].as_array().unwrap() {
        assert!((f(&c["impulse"]["n"]) - 0.45).abs() < 1e-12);
        assert!(c["impulse"].get("t2").is_some());
    }
    assert!(f(&law(&doc, "sequential")["energy_ratio"]) <= 1.0);
    assert!(fails(&["compare", "box-flat", "--vz", "1"]).contains("vz"));
    assert!(fails(&["compare", "box-flat", "--half-extents", "1,2"]).contains("--half-extents"));
    assert!(fails(&["compare", "box-flat", "--balls", "3"]).contains("--balls"));
    assert!(fails(&["compare", "box-flat", "--law", "newton"]).contains("law"));
    // lzb in 3D: a box landing level without spin leaves level at e |v_z| (symmetric,
    // equal stiffnesses), and the audit judges lcp by it.
    let doc = json(&[
        "compare", "box-flat", "--omega", "0", "--law", "lzb", "--json",
    ]);
    let u: Vec<f64> = doc["results"][0]["velocities_after"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    for (i, x) in [0.0, 0.0, 0.5, 0.0, 0.0, 0.0].iter().enumerate() {
        assert!((u[i] - x).abs() < 1e-10, "{u:?}");
    }
    let audit = json(&["audit", "box-flat", "--omega", "0", "--json"]);
    assert_eq!(audit["reference"], "lzb");
    assert_eq!(audit["engine_rules"][0]["verdict"]["id"], "matches");
}

/// `impax resolve --contacts 2` with a 6 × 6 W is spatial: the cradle of point masses.
#[test]
fn resolve_contacts_in_3d() {
    let w = "2,0,0,0,0,0,2,0,0,0,0,2,0,0,-1,2,0,0,2,0,2";
    let doc = json(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        w,
        "--v",
        "0,0,-1,0,0,0",
        "--friction",
        "0",
        "--restitution",
        "1",
        "--json",
    ]);
    let lcp = &doc["results"][0];
    assert_eq!(lcp["law"], "lcp");
    assert!((f(&lcp["contacts"][0]["impulse"]["n"]) - 4.0 / 3.0).abs() < 1e-12);
    let seq = &doc["results"][1];
    assert!((f(&seq["contacts"][1]["velocity_after"]["n"]) - 1.0).abs() < 1e-12);
    assert_eq!(doc["problem"]["v"][0]["n"], -1.0);
    let err = fails(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        w,
        "--v",
        "0,0,-1,0,0",
        "--friction",
        "0",
        "--restitution",
        "1",
    ]);
    assert!(err.contains("--v") || err.contains("v:"), "{err}");
}
