//! `impax resolve` with a 3×3 W: the planar JSON keys plus `hodograph` and
//! `invariant_rays`, agreement with the planar command on an embedded planar problem, and
//! bad 3D input (one line, exit 2).

use crate::support::{impax, json};

#[test]
fn spatial_entry_has_the_planar_keys_plus_hodograph() {
    let doc = json(&[
        "resolve",
        "--w",
        "2,0.6,0.3,1,-0.2,1.5",
        "--v",
        "0.3,0.8,-1",
        "--friction",
        "0.8",
        "--restitution",
        "0.7",
        "--law",
        "energetic",
        "--json",
    ]);
    for key in [
        "law",
        "verdict",
        "impulse",
        "velocity_after",
        "energy_change",
        "phases",
        "compression_impulse",
        "work",
        "hodograph",
        "invariant_rays",
    ] {
        assert!(doc.get(key).is_some(), "missing {key}");
    }
    let hodo = doc["hodograph"].as_array().unwrap();
    assert!(hodo.len() > 10);
    // The hodograph starts at v⁻ and ends at the velocity after.
    assert_eq!(hodo[0][1].as_f64().unwrap(), 0.3);
    let last = hodo.last().unwrap();
    assert!(
        (last[3].as_f64().unwrap() - doc["velocity_after"]["n"].as_f64().unwrap()).abs() < 1e-12
    );
    assert_eq!(doc["phases"][1]["kind"], "stick");
    assert!(doc["invariant_rays"].as_array().unwrap().len() >= 2);
}

#[test]
fn embedded_planar_problem_matches_the_planar_command() {
    let d3 = json(&[
        "resolve",
        "--w",
        "2,0,0.5,1.3,0,1",
        "--v",
        "0.4,0,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.6",
        "--json",
    ]);
    let d2 = json(&[
        "resolve",
        "--w",
        "2,0.5,1",
        "--v",
        "0.4,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.6",
        "--json",
    ]);
    for r3 in d3["results"].as_array().unwrap() {
        let law = r3["law"].as_str().unwrap();
        let r2 = d2["results"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["law"] == law)
            .unwrap();
        let a = r3["impulse"]["t1"].as_f64().unwrap();
        let b = r2["impulse"]["t"].as_f64().unwrap();
        assert!((a - b).abs() < 1e-12, "{law}: {a} vs {b}");
        let a = r3["impulse"]["n"].as_f64().unwrap();
        let b = r2["impulse"]["n"].as_f64().unwrap();
        assert!((a - b).abs() < 1e-12, "{law}: {a} vs {b}");
    }
}

#[test]
fn bad_spatial_input_is_one_line_and_exit_2() {
    for (w, v, mu, e, law, needle) in [
        (
            "1,2,0,1,0,1",
            "0.1,0,-1",
            "0.3",
            "0.5",
            "energetic",
            "positive definite",
        ),
        ("1,0,0,1,0,1", "0.1,-1", "0.3", "0.5", "energetic", "--v"),
        (
            "1,0,0,1,0,1",
            "0.1,0,1",
            "0.3",
            "0.5",
            "energetic",
            "negative",
        ),
        ("1,0,0,1,0", "0.1,0,-1", "0.3", "0.5", "energetic", "--w"),
        (
            "1,0,0,1,0,1",
            "0.1,0,-1",
            "-1",
            "0.5",
            "energetic",
            "friction",
        ),
        ("1,0,0,1,0,1", "0.1,0,-1", "0.3", "0.5", "smith", "planar"),
        (
            "1,0,0,1,0,nan",
            "0.1,0,-1",
            "0.3",
            "0.5",
            "energetic",
            "--w",
        ),
    ] {
        let out = impax()
            .args([
                "resolve",
                "--w",
                w,
                "--v",
                v,
                "--friction",
                mu,
                "--restitution",
                e,
                "--law",
                law,
            ])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{w} {v}: {err}");
        assert_eq!(
            err.lines().filter(|l| !l.trim().is_empty()).count(),
            1,
            "{err}"
        );
        assert!(err.contains(needle), "`{err}` lacks `{needle}`");
    }
}

/// The spatial `lcp` lists every solution of the complementarity conditions. This problem
/// (an anisotropic, coupled W found by a seeded random search, see
/// crates/impax/tests/lcp_spatial.rs) has three: a stick and two slips; the least-energy one
/// is the result, flagged `multiple-solutions`. A sphere has one.
#[test]
fn lcp_lists_all_solutions() {
    let doc = json(&[
        "resolve",
        "--w",
        "8.692015037824595,4.6411520047113655,-3.900836733792748,6.574816256667819,0.29757123475977565,4.097896762849426",
        "--v",
        "1.46566513942255,1.9939154706775324,-0.19369561711812847",
        "--friction",
        "1.9481176108815623",
        "--restitution",
        "0.5110468279631739",
        "--law",
        "lcp",
        "--json",
    ]);
    let all = doc["all_solutions"].as_array().unwrap();
    assert_eq!(all.len(), 3);
    assert_eq!(doc["inconsistency"]["id"], "multiple-solutions");
    assert_eq!(doc["detail"]["solutions"], 3);
    assert_eq!(doc["verdict"], "inconsistent-assumption");
    let kinds: Vec<&str> = all.iter().map(|s| s["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["stick", "slip", "slip"]);
    assert!(all[1]["slip_angle_deg"].is_number() && all[0].get("slip_angle_deg").is_none());
    let energies: Vec<f64> = all
        .iter()
        .map(|s| s["energy_change"].as_f64().unwrap())
        .collect();
    assert!(energies[0] < energies[1] && energies[1] < energies[2]);
    assert_eq!(doc["impulse"], all[0]["impulse"]);
    // Every solution meets Newton's target v_n⁺ = −e v_n⁻.
    for s in all {
        let vn = s["velocity_after"]["n"].as_f64().unwrap();
        assert!((vn - 0.5110468279631739 * 0.19369561711812847).abs() < 1e-14);
    }
    let sphere = json(&[
        "resolve",
        "--w",
        "3.5,0,0,3.5,0,1",
        "--v",
        "0.5,0.2,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.5",
        "--law",
        "lcp",
        "--json",
    ]);
    assert_eq!(sphere["all_solutions"].as_array().unwrap().len(), 1);
    assert!(sphere["inconsistency"].is_null());
}
