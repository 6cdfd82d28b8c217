//! Spatial mechanisms in motion at the command line: `impax simulate` and `impax conserved`
//! of a URDF robot (solo12 with a floating base) and of `space = "3d"` mechanism files — the
//! physics of the records (free-fall times, restitution between bounces, energy never gained
//! under `energetic`, the ledger balanced, the quantities each symmetry conserves), the CSV,
//! and the errors (exit 2, one line, naming the flag).

use crate::support::{bad, f, json, run_ok, scratch, write};
use serde_json::Value;

const ARM_3D: &str = "../../examples/mechanisms/arm-3d.toml";
const SOLO12: &str = "../impax/tests/data/urdf/solo12.urdf";
const G: f64 = 9.81;

/// solo12's legs bent, its base 0.8 m up and turned by 0.1 rad about (0.6, 0.8, 0): one foot
/// lowest.
const SOLO_TILTED: &str = "0,0,0.8,0.9987502603949663,0.029987503124565,0.03998333749942,0,\
                           0,0.8,-1.6,0,0.8,-1.6,0,-0.8,1.6,0,-0.8,1.6";

/// The four feet as `--contact` flags.
const FEET: [&str; 8] = [
    "--contact",
    "FL_FOOT",
    "--contact",
    "FR_FOOT",
    "--contact",
    "HL_FOOT",
    "--contact",
    "HR_FOOT",
];

/// A ball (m = 1, r = 0.1, J = 2/5 m r²) on a free joint, its round foot the lowest point.
const BALL: &str = r#"
name = "ball"
space = "3d"
friction = 0.3
restitution = 0.5

[[body]]
name = "ball"
mass = 1.0
inertia = [[0.004, 0.0, 0.0], [0.0, 0.004, 0.0], [0.0, 0.0, 0.004]]

[[joint]]
name = "root"
type = "free"
parent = "world"
child = "ball"

[[contact]]
name = "bottom"
body = "ball"
point = [0.0, 0.0, 0.0]
radius = 0.1
height = 0.0
"#;

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(f).collect()
}

/// The ledger balances: `end = initial + impacts + drift` to round-off, the drift is of the
/// integrator's tolerance, and no impact gains energy.
fn assert_ledger(doc: &Value) {
    let l = &doc["ledger"];
    let scale = f(&l["initial"]).abs().max(1.0);
    let sum = f(&l["initial"]) + f(&l["impacts"]) + f(&l["drift"]);
    assert!((f(&l["end"]) - sum).abs() < 1e-12 * scale, "{l}");
    assert!(f(&l["residual"]).abs() < 1e-12 * scale, "{l}");
    assert!(f(&l["drift"]).abs() < 1e-9 * scale, "{l}");
    assert_eq!(doc["energy_rises_at_impacts"], 0);
    for i in doc["impacts"].as_array().unwrap() {
        assert!(f(&i["energy_change"]) <= 0.0, "{i}");
        let (before, after) = (f(&i["total_energy_before"]), f(&i["total_energy_after"]));
        assert!(after <= before, "{before} → {after}");
        assert!(
            (f(&i["energy_change"]) - f(&i["law_energy_change"])).abs() < 1e-12 * scale,
            "{i}"
        );
    }
}

/// A ball dropped from 1 m: it strikes at √(2h/g), leaves at e times its speed, and strikes
/// again 2 e √(2h/g) later; the energy ledger balances.
#[test]
fn a_ball_file_bounces_at_the_free_fall_times() {
    let path = write("ball-3d.toml", BALL);
    let file = path.to_str().unwrap();
    let doc = json(&[
        "simulate",
        file,
        "--q",
        "0,0,1.1,1,0,0,0",
        "--until",
        "2",
        "--json",
    ]);
    assert_eq!(doc["law"], "energetic");
    assert_eq!(doc["contacts"][0]["name"], "bottom");
    assert!((f(&doc["contacts"][0]["gap"]) - 1.0).abs() < 1e-15);
    let impacts = doc["impacts"].as_array().unwrap();
    assert!(impacts.len() >= 3, "{}", impacts.len());
    let fall = (2.0 * 1.0 / G).sqrt();
    let t1 = f(&impacts[0]["time"]);
    assert!((t1 - fall).abs() < 1e-9, "{t1} vs {fall}");
    let v1 = f(&impacts[0]["contact_velocity_before"]["n"]);
    assert!((v1 + (2.0 * G).sqrt()).abs() < 1e-9, "{v1}");
    let after = f(&impacts[0]["contact_velocity_after"]["n"]);
    assert!((after + 0.5 * v1).abs() < 1e-9, "{after}");
    let t2 = f(&impacts[1]["time"]);
    assert!((t2 - t1 - 2.0 * 0.5 * fall).abs() < 1e-9, "{}", t2 - t1);
    assert_ledger(&doc);
    // The table says the same.
    let text = run_ok(&["simulate", file, "--q", "0,0,1.1,1,0,0,0", "--until", "2"]);
    assert!(text.contains("bottom") && text.contains("ledger"), "{text}");
}

/// solo12 dropped tilted: its lowest foot strikes at the free-fall time of its gap, every
/// impact is at a foot, no impact gains energy under `energetic`, the ledger balances, and the
/// run ends with a named stop.
#[test]
fn solo12_dropped_lands_on_its_feet() {
    let mut args = vec![
        "simulate",
        SOLO12,
        "--floating-base",
        "--q",
        SOLO_TILTED,
        "--floor",
        "0",
        "--law",
        "energetic",
        "--json",
    ];
    args.extend(FEET);
    let doc = json(&args);
    assert_eq!(doc["coordinates"].as_array().unwrap().len(), 19);
    assert_eq!(doc["speeds"][0], "vx");
    let gaps: Vec<(String, f64)> = doc["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| (c["name"].as_str().unwrap().to_string(), f(&c["gap"])))
        .collect();
    let (lowest, h) = gaps
        .iter()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .cloned()
        .unwrap();
    let impacts = doc["impacts"].as_array().unwrap();
    assert!(!impacts.is_empty());
    assert_eq!(impacts[0]["contact"], lowest.as_str());
    let fall = (2.0 * h / G).sqrt();
    assert!(
        (f(&impacts[0]["time"]) - fall).abs() < 1e-9,
        "{} vs {fall}",
        impacts[0]["time"]
    );
    for i in impacts {
        assert!(i["contact"].as_str().unwrap().ends_with("_FOOT"), "{i}");
        assert_eq!(numbers(&i["u_after"]).len(), 18);
        let vb = f(&i["contact_velocity_before"]["n"]);
        assert!(vb < 0.0, "{vb}");
    }
    assert_ledger(&doc);
    assert_ne!(doc["stop"]["id"], "time-limit");
    // The CSV: a row per sample, the base's speeds by name and the joints' rates.
    let csv = scratch("solo12.csv");
    let mut with_csv: Vec<&str> = args.iter().copied().filter(|a| *a != "--json").collect();
    with_csv.extend(["--csv", csv.to_str().unwrap()]);
    run_ok(&with_csv);
    let text = std::fs::read_to_string(&csv).unwrap();
    let header = text.lines().next().unwrap();
    assert!(
        header.starts_with("t,mode,x,y,z,qw,qx,qy,qz,FL_HAA,"),
        "{header}"
    );
    assert!(
        header.contains(",vx,vy,vz,wx,wy,wz,FL_HAA_rate,"),
        "{header}"
    );
    assert!(header.ends_with(",kinetic,potential,energy"), "{header}");
    assert_eq!(
        text.lines().count(),
        1 + doc["samples"].as_u64().unwrap() as usize
    );
}

/// Several `--contact`s in `compare`: the lowest at the state strikes, whatever their order,
/// and the floor passes through it.
#[test]
fn compare_strikes_with_the_lowest_of_several_contacts() {
    let u = "0,0,-1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0";
    let strike = |a: &str, b: &str| {
        let doc = json(&[
            "compare",
            SOLO12,
            "--floating-base",
            "--contact",
            a,
            "--contact",
            b,
            "--q",
            SOLO_TILTED,
            "--u",
            u,
            "--law",
            "energetic",
            "--json",
        ]);
        assert!(f(&doc["gap"]).abs() < 1e-15);
        doc["contact"].as_str().unwrap().to_string()
    };
    let (one, two) = (strike("FL_FOOT", "HL_FOOT"), strike("HL_FOOT", "FL_FOOT"));
    assert_eq!(one, two);
    // The simulation from the same state strikes first with that foot.
    let doc = json(&[
        "simulate",
        SOLO12,
        "--floating-base",
        "--contact",
        "FL_FOOT",
        "--contact",
        "HL_FOOT",
        "--q",
        SOLO_TILTED,
        "--floor",
        "0",
        "--json",
    ]);
    assert_eq!(doc["impacts"][0]["contact"], one.as_str());
}

/// The 3D arm of `examples/mechanisms/arm-3d.toml` falls onto the floor through its tip: the
/// file's contact, law and coefficients, and its ledger balanced.
#[test]
fn a_spatial_mechanism_file_simulates() {
    let doc = json(&["simulate", ARM_3D, "--json"]);
    assert_eq!(doc["scenario"], "arm-3d");
    assert_eq!((f(&doc["friction"]), f(&doc["restitution"])), (0.5, 0.5));
    assert_eq!(doc["impacts"][0]["contact"], "tip");
    assert_ledger(&doc);
    // Another state and a floor below: the first impact is later, approaching.
    let doc = json(&["simulate", ARM_3D, "--floor", "-1.9", "--json"]);
    let first = &doc["impacts"][0];
    assert!(f(&first["time"]) > 0.0 && f(&first["contact_velocity_before"]["n"]) < 0.0);
    assert_ledger(&doc);
}

fn quantity<'a>(doc: &'a Value, name: &str) -> &'a Value {
    doc["quantities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|q| q["name"] == name)
        .unwrap_or_else(|| panic!("no {name}"))
}

/// solo12 flying free: what its symmetries promise is conserved (the energy, P_x, P_y, L_z
/// about a point, the momenta of the cyclic x and y), what gravity acts on is not; without
/// gravity all of P and L; on a fixed base only the energy.
#[test]
fn solo12_conserves_what_its_symmetries_promise() {
    let u = "0.1,0.2,1,0.5,-0.3,1,1,2,-1,0,1,2,-2,1,0,1,2,-1";
    let base = [
        "conserved",
        SOLO12,
        "--floating-base",
        "--q",
        SOLO_TILTED,
        "--u",
        u,
        "--duration",
        "1",
        "--samples",
        "100",
        "--about",
        "1,-2,0.5",
        "--json",
    ];
    let doc = json(&base);
    assert_eq!(doc["cyclic"], serde_json::json!(["x", "y"]));
    for q in doc["quantities"].as_array().unwrap() {
        assert_eq!(q["conserved"], q["expected"], "{q}");
    }
    for name in ["energy", "P_x", "P_y", "p_vx", "p_vy", "L_z(1, -2, 0.5)"] {
        assert_eq!(quantity(&doc, name)["expected"], true, "{name}");
        assert!(
            f(&quantity(&doc, name)["relative_deviation"]) < 1e-10,
            "{name}"
        );
    }
    for name in ["P_z", "L_x(1, -2, 0.5)", "L_y(1, -2, 0.5)"] {
        assert_eq!(quantity(&doc, name)["expected"], false, "{name}");
        assert!(
            f(&quantity(&doc, name)["relative_deviation"]) > 1e-3,
            "{name}"
        );
    }
    assert_eq!(quantity(&doc, "p_vx")["coordinate"], "x");
    assert_eq!(quantity(&doc, "p_wz").get("cyclic"), None);
    assert_eq!(doc["expected_but_drifted"], serde_json::json!([]));
    // Without gravity: all of P and L, and z cyclic.
    let doc = json(&[&base[..], &["--gravity", "0"]].concat());
    assert_eq!(doc["cyclic"], serde_json::json!(["x", "y", "z"]));
    for name in ["P_z", "L_x(1, -2, 0.5)", "L_y(1, -2, 0.5)"] {
        let q = quantity(&doc, name);
        assert!(q["expected"] == true && q["conserved"] == true, "{q}");
    }
    // A fixed base: the support's reactions change P and L.
    let fixed = json(&[
        "conserved",
        SOLO12,
        "--q",
        "0,0.8,-1.6,0,0.8,-1.6,0,-0.8,1.6,0,-0.8,1.6",
        "--u",
        "1,2,-1,0,1,2,-2,1,0,1,2,-1",
        "--duration",
        "1",
        "--samples",
        "100",
        "--json",
    ]);
    for q in fixed["quantities"].as_array().unwrap() {
        assert_eq!(q["conserved"], q["kind"] == "energy", "{q}");
    }
    // The table has the columns of the planar one and `expected`.
    let text = run_ok(&base[..base.len() - 1]);
    assert!(
        text.contains("NOT conserved") && text.contains("expected"),
        "{text}"
    );
}

/// Bad input: exit 2 and one line naming the flag; a state spinning at 10⁷ rad/s is refused
/// at once, naming the duration.
#[test]
fn robot_motion_errors_name_the_flag() {
    let spin = "0,0,0,0,0,1e7,0,0,0,0,0,0,0,0,0,0,0,0";
    bad(&["simulate", SOLO12, "--floating-base"], "contact");
    bad(&["simulate", SOLO12, "--contact", "NOPE"], "NOPE");
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--q", "1,2"],
        "q",
    );
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--law", "smith"],
        "smith",
    );
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--mass", "2"],
        "--mass",
    );
    bad(
        &[
            "simulate",
            SOLO12,
            "--contact",
            "FL_FOOT",
            "--plot",
            "x.svg",
        ],
        "--plot",
    );
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--floor", "nan"],
        "floor",
    );
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--floor", "10"],
        "below the floor",
    );
    bad(
        &["simulate", SOLO12, "--contact", "FL_FOOT", "--until", "0"],
        "until",
    );
    bad(
        &[
            "simulate",
            SOLO12,
            "--floating-base",
            "--contact",
            "FL_FOOT",
            "--floor",
            "-1",
            "--u",
            spin,
        ],
        "until",
    );
    bad(
        &["simulate", ARM_3D, "--contact", "tip", "--contact", "tip"],
        "contact",
    );
    bad(
        &["simulate", "rod-drop", "--contact", "FL_FOOT"],
        "--contact",
    );
    bad(
        &["simulate", "rod-drop", "--floating-base"],
        "--floating-base",
    );
    bad(
        &["conserved", SOLO12, "--floating-base", "--about", "1,2"],
        "about",
    );
    bad(
        &["conserved", SOLO12, "--floating-base", "--u", spin],
        "duration",
    );
    bad(&["conserved", SOLO12, "--radius", "1"], "--radius");
    bad(&["conserved", ARM_3D, "--floating-base"], "floating_base");
    bad(&["conserved", ARM_3D, "--samples", "0"], "samples");
    bad(&["conserved", "rod", "--floating-base"], "floating-base");
}
