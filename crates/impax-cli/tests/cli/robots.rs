//! Mechanisms of one's own at the command line: mechanism files (planar and `space = "3d"`)
//! and URDF robots through `impax compare` and `impax audit` — the JSON contract, the
//! physics of the records, and the errors (exit 2, one line, naming the field).

use crate::support::{bad, json, run_ok};
use serde_json::Value;

const DOUBLE_PENDULUM: &str = "../../examples/mechanisms/double-pendulum.toml";
const ARM_3D: &str = "../../examples/mechanisms/arm-3d.toml";
const SOLO12: &str = "../impax/tests/data/urdf/solo12.urdf";

/// A floating solo12 standing on its feet, falling at 1 m/s and turning.
const SOLO_Q: &str = "0,0,0.3,1,0,0,0,0,0.8,-1.6,0,0.8,-1.6,0,-0.8,1.6,0,-0.8,1.6";
const SOLO_U: &str = "0.1,0,-1,0.2,0.1,0,0,0,0,0,0,0,0,0,0,0,0,0";

fn f(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

/// The double pendulum as a file gives the built-in's contact problem and every law's
/// energy change; its generalized velocities are the built-in's in relative angles.
#[test]
fn a_planar_mechanism_file_is_the_built_in() {
    let file = json(&["compare", DOUBLE_PENDULUM, "--json"]);
    let built = json(&["compare", "double-pendulum", "--json"]);
    assert_eq!(file["coordinates"], serde_json::json!(["theta1", "theta2"]));
    fn numbers_of(v: &Value) -> Vec<f64> {
        match v {
            Value::Array(a) => a.iter().flat_map(numbers_of).collect(),
            Value::Object(m) => m.values().flat_map(numbers_of).collect(),
            x => vec![x.as_f64().unwrap()],
        }
    }
    for key in ["w", "v"] {
        let (a, b) = (
            numbers_of(&file["problem"][key]),
            numbers_of(&built["problem"][key]),
        );
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-14, "{key}: {x} vs {y}");
        }
    }
    for (a, b) in file["results"]
        .as_array()
        .unwrap()
        .iter()
        .zip(built["results"].as_array().unwrap())
    {
        assert_eq!(a["law"], b["law"]);
        let (da, db) = (f(&a["energy_change"]), f(&b["energy_change"]));
        assert!((da - db).abs() < 1e-12, "{da} vs {db}");
        // θ2(relative)' = θ2' − θ1'.
        let (ua, ub) = (&a["velocities_after"], &b["velocities_after"]);
        assert!((f(&ua[0]) - f(&ub[0])).abs() < 1e-12);
        assert!((f(&ua[1]) - (f(&ub[1]) - f(&ub[0]))).abs() < 1e-12);
    }
    // --q and --u replace the file's state.
    let moved = json(&[
        "compare",
        DOUBLE_PENDULUM,
        "--q",
        "0.2,-0.5",
        "--u",
        "-1,2",
        "--json",
    ]);
    assert_eq!(moved["q"], serde_json::json!([0.2, -0.5]));
    assert_eq!(moved["u_before"], serde_json::json!([-1.0, 2.0]));
}

/// The JSON keys for a robot, and the records' identities: the contact velocity after
/// is `v⁻ + W p`, ΔT from the contact problem equals ΔT from the velocities, the floor
/// passes through the foot.
#[test]
fn a_urdf_robot_compares_every_spatial_law() {
    let doc = json(&[
        "compare",
        SOLO12,
        "--floating-base",
        "--contact",
        "FL_FOOT",
        "--q",
        SOLO_Q,
        "--u",
        SOLO_U,
        "--json",
    ]);
    for key in [
        "mechanism",
        "coordinates",
        "q",
        "u_before",
        "contact",
        "gap",
        "problem",
        "energy_before",
        "results",
    ] {
        assert!(doc.get(key).is_some(), "{key}");
    }
    let coordinates = doc["coordinates"].as_array().unwrap();
    assert_eq!(coordinates.len(), 19);
    assert_eq!(
        coordinates[..7],
        ["x", "y", "z", "qw", "qx", "qy", "qz"].map(Value::from)
    );
    assert_eq!(coordinates[7], "FL_HAA");
    assert_eq!(doc["contact"], "FL_FOOT");
    assert!(f(&doc["gap"]).abs() < 1e-15);
    let w = &doc["problem"]["w"];
    assert_eq!(w.as_array().unwrap().len(), 3);
    let v = [
        &doc["problem"]["v"]["t1"],
        &doc["problem"]["v"]["t2"],
        &doc["problem"]["v"]["n"],
    ]
    .map(f);
    assert!(v[2] < 0.0);
    let t0 = f(&doc["energy_before"]);
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 6);
    for r in results {
        assert_eq!(
            r["velocities_after"].as_array().unwrap().len(),
            18,
            "{}",
            r["law"]
        );
        let p = [&r["impulse"]["t1"], &r["impulse"]["t2"], &r["impulse"]["n"]].map(f);
        let after = [
            &r["velocity_after"]["t1"],
            &r["velocity_after"]["t2"],
            &r["velocity_after"]["n"],
        ]
        .map(f);
        for i in 0..3 {
            let wp: f64 = (0..3).map(|j| f(&w[i][j]) * p[j]).sum();
            assert!((v[i] + wp - after[i]).abs() < 1e-9, "{}: v⁺[{i}]", r["law"]);
        }
        let (de, dv) = (
            f(&r["energy_change"]),
            f(&r["energy_change_from_velocities"]),
        );
        assert!(
            (de - dv).abs() < 1e-12 * t0,
            "{}: ΔT {de} vs {dv}",
            r["law"]
        );
        if r["law"] == "energetic" {
            assert!(de < 0.0);
        }
    }
    // The table shows every law too.
    let text = run_ok(&[
        "compare",
        SOLO12,
        "--floating-base",
        "--contact",
        "FL_FOOT",
        "--q",
        SOLO_Q,
        "--u",
        SOLO_U,
    ]);
    assert!(
        text.contains("energetic") && text.contains("FL_FOOT"),
        "{text}"
    );
}

/// A spatial mechanism file and its audit: the engine rules against the rigid-body answer.
#[test]
fn a_spatial_mechanism_file_compares_and_audits() {
    let doc = json(&["compare", ARM_3D, "--json"]);
    assert_eq!(
        doc["coordinates"],
        serde_json::json!(["hinge x", "hinge y", "elbow"])
    );
    assert_eq!(doc["contact"], "tip");
    let audit = json(&["audit", ARM_3D, "--json"]);
    assert!(audit.to_string().contains("energetic"));
    let text = run_ok(&[
        "audit",
        SOLO12,
        "--floating-base",
        "--contact",
        "FL_FOOT",
        "--q",
        SOLO_Q,
        "--u",
        SOLO_U,
    ]);
    assert!(text.contains("verdict — lcp"), "{text}");
}

/// Bad input: exit 2, one line naming what is wrong.
#[test]
fn errors_name_the_flag_or_field() {
    bad(&["compare", SOLO12, "--floating-base"], "contact");
    bad(
        &["compare", SOLO12, "--contact", "NO_SUCH_LINK"],
        "NO_SUCH_LINK",
    );
    bad(
        &[
            "compare",
            SOLO12,
            "--floating-base",
            "--contact",
            "FL_FOOT",
            "--q",
            "1,2",
        ],
        "q",
    );
    bad(
        &[
            "compare",
            SOLO12,
            "--floating-base",
            "--contact",
            "FL_FOOT",
            "--q",
            SOLO_Q,
            "--u",
            SOLO_U,
            "--law",
            "smith",
        ],
        "smith",
    );
    bad(
        &[
            "compare",
            SOLO12,
            "--contact",
            "FL_FOOT",
            "--angles-deg",
            "3",
        ],
        "angles-deg",
    );
    bad(&["compare", ARM_3D, "--contact", "elbow"], "elbow");
    bad(&["compare", ARM_3D, "--floating-base"], "floating_base");
    bad(
        &["compare", DOUBLE_PENDULUM, "--angles-deg", "30,0"],
        "angles_deg",
    );
    bad(&["compare", DOUBLE_PENDULUM, "--q", "1,2,3"], "q");
    // A contact moving away from the floor is not an impact.
    bad(&["compare", ARM_3D, "--u", "-0.5,1,-2"], "approach");
}

/// A mechanism's sweep over its state: each row is the impact `compare` gives at that state,
/// and the output is the same for any number of threads.
#[test]
fn a_mechanism_sweeps_over_its_state() {
    let args = [
        "sweep",
        ARM_3D,
        "--grid",
        "q.elbow=-1:-0.6:3",
        "--grid",
        "friction=0:1:2",
        "--law",
        "energetic,lcp",
        "--quiet",
    ];
    let one = run_ok(&[&args[..], &["--threads", "1"]].concat());
    let two = run_ok(&[&args[..], &["--threads", "2"]].concat());
    assert_eq!(one, two);
    let lines: Vec<&str> = one.lines().collect();
    assert_eq!(lines.len(), 1 + 3 * 2 * 2);
    assert!(lines[0].starts_with("q.elbow,friction,law,status,verdict,energy_change"));
    // The row at q.elbow = −0.8, friction = 1, energetic against compare at that state.
    let row: Vec<&str> = lines
        .iter()
        .find(|l| l.starts_with("-0.8,1,energetic,"))
        .expect("the row")
        .split(',')
        .collect();
    let doc = json(&[
        "compare",
        ARM_3D,
        "--q",
        "0.3,0.6,-0.8",
        "--friction",
        "1",
        "--law",
        "energetic",
        "--json",
    ]);
    let r = &doc["results"][0];
    let de: f64 = row[5].parse().unwrap();
    assert!((de - f(&r["energy_change"])).abs() < 1e-12, "{de}");
    let after: Vec<f64> = row[row.len() - 3..]
        .iter()
        .map(|x| x.parse().unwrap())
        .collect();
    for (a, b) in after.iter().zip(r["velocities_after"].as_array().unwrap()) {
        assert!((a - f(b)).abs() < 1e-12);
    }
    // Unknown fields name the known ones; a body scenario refuses the robot flags.
    bad(&["sweep", ARM_3D, "--grid", "q.nope=0:1:2"], "q.elbow");
    bad(
        &["sweep", "--grid", "alpha-deg=0:90:3", "--floating-base"],
        "floating-base",
    );
}
