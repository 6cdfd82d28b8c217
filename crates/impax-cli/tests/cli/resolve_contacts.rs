//! `impax resolve --contacts K`: the JSON contract for several contacts (per result `law`,
//! `verdict`, `contacts` with `impulse`/`velocity_after` as `{t, n}`, `phases`, `work`;
//! `energy_change`, `inconsistency`, `breakdown`, `detail`), Newton's cradle and the rod landing
//! flat through the command line, K = 1 equal to the one-contact command, and bad input as one
//! line with exit 2 naming the field.

use crate::support::{f, fails, json};

/// Three equal balls (m = 1) in a row touching, frictionless, e = 1: contact 1 closes at 1.
const CRADLE: [&str; 9] = [
    "resolve",
    "--contacts",
    "2",
    "--w",
    "2,0,0,0,2,0,-1,2,0,2",
    "--v",
    "0,-1,0,0",
    "--friction",
    "0",
];

#[test]
fn newtons_cradle_lcp_and_sequential() {
    let mut args = CRADLE.to_vec();
    args.extend(["--restitution", "1", "--json"]);
    let doc = json(&args);
    assert_eq!(doc["problem"]["contacts"], 2);
    assert_eq!(doc["problem"]["rank"], 4);
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 3);
    for r in results {
        for key in [
            "law",
            "verdict",
            "contacts",
            "energy_change",
            "inconsistency",
            "breakdown",
            "detail",
        ] {
            assert!(r.get(key).is_some(), "missing {key}");
        }
        for c in r["contacts"].as_array().unwrap() {
            for key in ["impulse", "velocity_after", "phases", "work"] {
                assert!(c.get(key).is_some(), "missing contacts[].{key}");
            }
            assert!(c["impulse"].get("t").is_some() && c["impulse"].get("n").is_some());
        }
        // lcp and sequential exactly; lzb to its integration tolerance.
        assert!(f(&r["energy_change"]).abs() < 1e-10);
        assert_eq!(r["verdict"], "consistent");
    }
    // lcp: p = (4/3, 2/3): the balls leave at (−1/3, 2/3, 2/3), so the second contact
    // closes at 0 and the first opens at 1.
    let lcp = &results[0];
    assert_eq!(lcp["law"], "lcp");
    assert!((f(&lcp["contacts"][0]["impulse"]["n"]) - 4.0 / 3.0).abs() < 1e-12);
    assert!((f(&lcp["contacts"][1]["impulse"]["n"]) - 2.0 / 3.0).abs() < 1e-12);
    assert_eq!(lcp["detail"]["solutions"].as_array().unwrap().len(), 1);
    // lzb: the Hertz chain's wave, momentum conserved, the balls in order.
    let lzb = &results[2];
    assert_eq!(lzb["law"], "lzb");
    let v1 = f(&lzb["contacts"][0]["velocity_after"]["n"]);
    let v2 = f(&lzb["contacts"][1]["velocity_after"]["n"]);
    assert!(v1 > 0.0 && v2 > 0.0, "{v1} {v2}");
    assert!(lzb["detail"]["steps"].as_u64().unwrap() > 0);
    // sequential: two binary impacts, unit impulses, the third ball leaves alone.
    let seq = &results[1];
    assert_eq!(seq["law"], "sequential");
    let impacts = seq["detail"]["impacts"].as_array().unwrap();
    assert_eq!(impacts.len(), 2);
    assert_eq!(impacts[0]["contact"], 1);
    assert_eq!(impacts[1]["contact"], 2);
    for c in seq["contacts"].as_array().unwrap() {
        assert!((f(&c["impulse"]["n"]) - 1.0).abs() < 1e-15);
    }
    assert!(f(&seq["contacts"][0]["velocity_after"]["n"]).abs() < 1e-15);
    assert!((f(&seq["contacts"][1]["velocity_after"]["n"]) - 1.0).abs() < 1e-15);
}

#[test]
fn a_rod_landing_flat_leaves_level() {
    // m = 1, l = 1: W_nn = 4 at each end, coupled by −2 (rank 3); per-contact coefficients.
    let doc = json(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        "1,0,1,0,4,0,-2,1,0,4",
        "--v",
        "0,-1,0,-1",
        "--friction",
        "0.5,0.5",
        "--restitution",
        "0.8",
        "--law",
        "lcp",
        "--json",
    ]);
    assert_eq!(doc["law"], "lcp");
    for c in doc["contacts"].as_array().unwrap() {
        assert!((f(&c["velocity_after"]["n"]) - 0.8).abs() < 1e-12);
        assert!((f(&c["impulse"]["n"]) - 0.9).abs() < 1e-12);
        assert!(f(&c["impulse"]["t"]).abs() < 1e-12);
    }
    assert!((f(&doc["energy_change"]) - 0.5 * (0.64 - 1.0)).abs() < 1e-12);
}

#[test]
fn one_contact_is_the_one_contact_command() {
    let common = [
        "--w",
        "3.5,0.4,1.2",
        "--v",
        "0.5,-0.866",
        "--friction",
        "0.3",
        "--restitution",
        "0.7",
        "--json",
    ];
    for law in ["lcp", "energetic", "poisson"] {
        let mut one = vec!["resolve", "--law", law];
        one.extend(common);
        let single = json(&one);
        let mut many = vec!["resolve", "--contacts", "1", "--law", law];
        many.extend(common);
        let multi = json(&many);
        assert_eq!(multi["law"], law);
        assert_eq!(multi["verdict"], single["verdict"]);
        for key in ["impulse", "velocity_after"] {
            for c in ["t", "n"] {
                let (a, b) = (f(&multi["contacts"][0][key][c]), f(&single[key][c]));
                assert!((a - b).abs() <= 1e-13 * b.abs().max(1.0), "{law} {key}.{c}");
            }
        }
        let (a, b) = (f(&multi["energy_change"]), f(&single["energy_change"]));
        assert!((a - b).abs() <= 1e-13 * b.abs(), "{law} ΔT");
    }
    // sequential with one contact is energetic.
    let mut one = vec!["resolve", "--law", "energetic"];
    one.extend(common);
    let mut seq = vec!["resolve", "--contacts", "1", "--law", "sequential"];
    seq.extend(common);
    let (a, b) = (json(&one), json(&seq));
    let (x, y) = (
        f(&a["velocity_after"]["n"]),
        f(&b["contacts"][0]["velocity_after"]["n"]),
    );
    assert!((x - y).abs() <= 1e-13 * x.abs());
}

#[test]
fn bad_input_names_the_field() {
    let rod = "1,0,1,0,4,0,-2,1,0,4";
    let cases: [(&[&str], &str); 7] = [
        (
            &["--contacts", "2", "--w", "1,0,1", "--v", "0,-1,0,-1"],
            "--w",
        ),
        (&["--contacts", "2", "--w", rod, "--v", "0,-1"], "v"),
        (
            &["--contacts", "2", "--w", rod, "--v", "0.3,-1,0,-1"],
            "v: not a velocity",
        ),
        (
            &["--contacts", "0", "--w", rod, "--v", "0,-1,0,-1"],
            "--contacts",
        ),
        (
            &[
                "--contacts",
                "2",
                "--w",
                rod,
                "--v",
                "0,-1,0,-1",
                "--law",
                "smith",
            ],
            "law: `smith` is a one-contact law",
        ),
        (
            &[
                "--contacts",
                "2",
                "--w",
                "1,0,1,0,4,0,-2,1,0,-4",
                "--v",
                "0,-1,0,-1",
            ],
            "w",
        ),
        (&["--contacts", "2", "--w", rod, "--v", "0,1,0,1"], "v"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["resolve"];
        args.extend(extra);
        args.extend(["--friction", "0.5", "--restitution", "0.5"]);
        let err = fails(&args);
        assert!(err.contains(expected), "{args:?}: {err}");
    }
    let err = fails(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        rod,
        "--v",
        "0,-1,0,-1",
        "--friction",
        "0.5,0.5,0.5",
        "--restitution",
        "0.5",
    ]);
    assert!(err.contains("--friction"), "{err}");
    let err = fails(&[
        "resolve",
        "--contacts",
        "2",
        "--w",
        rod,
        "--v",
        "0,-1,0,-1",
        "--friction",
        "0.5",
        "--restitution",
        "0.5,1.5",
    ]);
    assert!(err.contains("restitution[2]"), "{err}");
}
