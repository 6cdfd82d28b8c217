//! `impax audit NAME` for the systems struck at several contacts (`lcp` and `sequential`
//! judged against `lzb`), and `lzb`'s force law from the command line (`--stiffness`,
//! `--exponent`): the published answers, the identities the force law must keep, and flags
//! refused with exit 2.

use crate::support::{f, fails, json};
use serde_json::Value;

fn result<'a>(doc: &'a Value, id: &str) -> &'a Value {
    doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == id)
        .unwrap_or_else(|| panic!("no {id}"))
}

fn rule<'a>(doc: &'a Value, id: &str) -> &'a Value {
    doc["engine_rules"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == id)
        .unwrap_or_else(|| panic!("no {id}"))
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(f).collect()
}

/// Newton's cradle: `lcp` gives (−1/3, 2/3, 2/3) v0, `sequential` (0, 0, 1) v0, `lzb`
/// conserves momentum and energy; both engine rules keep the energy but share it otherwise.
#[test]
fn the_cradle_audit_tells_the_engines_apart() {
    let doc = json(&["audit", "cradle", "--json"]);
    assert_eq!(doc["reference"], "lzb");
    // Only the balls' horizontal velocities move.
    let names: Vec<&str> = doc["velocity_names"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(names, ["x1'", "x2'", "x3'"]);
    let roles: Vec<(&str, &str)> = doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["law"].as_str().unwrap(), r["role"].as_str().unwrap()))
        .collect();
    assert_eq!(
        roles,
        [
            ("lzb", "exact"),
            ("lcp", "engine"),
            ("sequential", "engine")
        ]
    );
    let near = |a: &[f64], b: &[f64], tol: f64| a.iter().zip(b).all(|(x, y)| (x - y).abs() < tol);
    let lcp = numbers(&result(&doc, "lcp")["velocities_after"]);
    assert!(
        near(&lcp, &[-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0], 1e-12),
        "{lcp:?}"
    );
    let seq = numbers(&result(&doc, "sequential")["velocities_after"]);
    assert!(near(&seq, &[0.0, 0.0, 1.0], 1e-12), "{seq:?}");
    let lzb = numbers(&result(&doc, "lzb")["velocities_after"]);
    assert!((lzb.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    assert!((0.5 * lzb.iter().map(|x| x * x).sum::<f64>() - 0.5).abs() < 1e-10);
    assert!(
        lzb[0] < 0.0 && lzb[0] < lzb[1] && lzb[1] < lzb[2],
        "{lzb:?}"
    );
    for id in ["lcp", "sequential"] {
        let r = rule(&doc, id);
        assert_eq!(r["verdict"]["id"], "redistributes", "{id}");
        let u = numbers(&result(&doc, id)["velocities_after"]);
        let d = numbers(&r["velocities_after_difference"]);
        for i in 0..3 {
            assert!((d[i] - (u[i] - lzb[i])).abs() < 1e-15);
        }
        let largest = d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert_eq!(f(&r["largest_velocity_difference"]), largest);
    }
}

/// The rod landing flat: `lcp` and `lzb` agree on u⁺ = (0, e|v_y|, 0); `sequential` hits one
/// end first and dissipates more.
#[test]
fn the_rod_audit_matches_lcp_and_faults_sequential() {
    let doc = json(&["audit", "rod-flat", "--restitution", "0.6", "--json"]);
    assert_eq!(rule(&doc, "lcp")["verdict"]["id"], "matches");
    assert_eq!(rule(&doc, "sequential")["verdict"]["id"], "dissipates-more");
    let lzb = numbers(&result(&doc, "lzb")["velocities_after"]);
    // Moving before or after under some law: y and θ (x stays 0).
    assert_eq!(lzb.len(), 2);
    assert!(
        (lzb[0] - 0.6).abs() < 1e-10 && lzb[1].abs() < 1e-10,
        "{lzb:?}"
    );
    assert!((f(&result(&doc, "lzb")["energy_ratio"]) - 0.36).abs() < 1e-10);
}

/// Housner's block: every law gives ω⁺/ω⁻ = 1 − (3/2) sin²α, so every engine rule matches.
#[test]
fn the_rocking_block_audit_matches_everywhere() {
    let doc = json(&["audit", "rocking-block", "--half-width", "0.25", "--json"]);
    let sin2 = 0.25f64.powi(2) / (0.25f64.powi(2) + 0.36);
    for id in ["lzb", "lcp", "sequential"] {
        let u = numbers(&result(&doc, id)["velocities_after"]);
        let omega = *u.last().unwrap();
        assert!(
            (omega / -1.0 - (1.0 - 1.5 * sin2)).abs() < 1e-12,
            "{id}: {omega}"
        );
    }
    for id in ["lcp", "sequential"] {
        assert_eq!(rule(&doc, id)["verdict"]["id"], "matches", "{id}");
    }
}

/// The table names the reference and the roles.
#[test]
fn the_audit_table_names_its_reference() {
    let out = crate::support::impax()
        .args(["audit", "ball-ball-wall"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("engine rule − lzb"), "{text}");
    assert!(text.contains("verdict — lcp:") && text.contains("verdict — sequential:"));
}

#[test]
fn flags_that_do_not_apply_are_refused() {
    assert!(fails(&["audit", "cradle", "--lengths", "1,1"]).contains("--lengths"));
    assert!(fails(&["audit", "sphere", "--balls", "4"]).contains("--balls"));
    assert!(fails(&["audit", "rod", "--stiffness", "2"]).contains("--stiffness"));
    assert!(fails(&["audit", "cradle", "--half-width", "1"]).contains("--half-width"));
    assert!(fails(&["audit", "cradle", "--balls", "1"]).contains("balls"));
    assert!(fails(&["audit", "rod-flat", "--stiffness", "1,2,3"]).contains("stiffness"));
    assert!(fails(&["audit", "rod-flat", "--exponent", "0"]).contains("exponent"));
    assert!(fails(&["audit", "rod-flat", "--friction", "nan"]).contains("friction"));
}

/// A rod lying flat (m = 1, l = 1) on both ends at v_y = −1: W of rank 3.
const ROD_W: &str = "1,0,1,0,4,0,-2,1,0,4";

fn resolve_rod(extra: &[&str]) -> Value {
    let mut args = vec![
        "resolve",
        "--contacts",
        "2",
        "--w",
        ROD_W,
        "--v",
        "0,-1,0,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.5",
        "--law",
        "lzb",
        "--json",
    ];
    args.extend_from_slice(extra);
    json(&args)
}

fn velocities(entry: &Value) -> Vec<f64> {
    entry["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|c| [f(&c["velocity_after"]["t"]), f(&c["velocity_after"]["n"])])
        .collect()
}

/// Only the stiffnesses' ratios matter; a symmetric rod leaves level whatever the exponent;
/// unequal stiffnesses make it rotate.
#[test]
fn lzb_force_law_from_the_command_line() {
    let base = velocities(&resolve_rod(&[]));
    let scaled = velocities(&resolve_rod(&["--stiffness", "3,3"]));
    for (a, b) in base.iter().zip(&scaled) {
        assert!((a - b).abs() < 1e-10, "{base:?} {scaled:?}");
    }
    for eta in ["1", "2.5"] {
        let v = velocities(&resolve_rod(&["--exponent", eta]));
        // Both ends leave at e |v_y| = 0.5 without slip.
        for (x, y) in v.iter().zip([0.0, 0.5, 0.0, 0.5]) {
            assert!((x - y).abs() < 1e-10, "η = {eta}: {v:?}");
        }
    }
    let v = velocities(&resolve_rod(&["--stiffness", "1,4"]));
    assert!((v[1] - v[3]).abs() > 1e-3, "unequal stiffnesses: {v:?}");
    let doc = json(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        ROD_W,
        "--v",
        "0,-1,0,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.5",
        "--stiffness",
        "1,4",
        "--exponent",
        "1",
        "--json",
    ]);
    assert_eq!(numbers(&doc["problem"]["stiffness"]), [1.0, 4.0]);
    assert_eq!(f(&doc["problem"]["exponent"]), 1.0);
}

#[test]
fn force_law_flags_are_checked() {
    let base = [
        "resolve",
        "--w",
        "1,0,1",
        "--v",
        "0,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.5",
    ];
    let with = |extra: &[&str]| {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        fails(&a)
    };
    assert!(with(&["--stiffness", "2"]).contains("--stiffness"));
    assert!(with(&["--exponent", "1"]).contains("--exponent"));
    let k2 = |extra: &[&str]| {
        let mut a = vec![
            "resolve",
            "--contacts",
            "2",
            "--w",
            ROD_W,
            "--v",
            "0,-1,0,-1",
            "--friction",
            "0.3",
            "--restitution",
            "0.5",
        ];
        a.extend_from_slice(extra);
        fails(&a)
    };
    assert!(k2(&["--stiffness", "1,2,3"]).contains("stiffness"));
    assert!(k2(&["--stiffness", "1,-2"]).contains("stiffness[2]"));
    assert!(k2(&["--exponent", "-1"]).contains("exponent"));
    assert!(k2(&["--exponent", "inf"]).contains("exponent"));
    assert!(fails(&["compare", "sphere", "--stiffness", "2"]).contains("--stiffness"));
}
