//! End-to-end tests of the `impax` binary: the seed table, the JSON contract, and every kind
//! of bad input (one line on stderr, exit code 2, no panic).

use crate::support::{bad, json, run_ok};

use std::io::Write;

fn scenario_file(text: &str) -> tempfile_path::TempToml {
    tempfile_path::TempToml::new(text)
}

/// A scenario file in the target directory, removed on drop.
mod tempfile_path {
    use std::path::PathBuf;
    pub struct TempToml(pub PathBuf);
    impl TempToml {
        pub fn new(text: &str) -> Self {
            use std::sync::atomic::{AtomicUsize, Ordering};
            static N: AtomicUsize = AtomicUsize::new(0);
            let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
                .join(format!("impax-cli-tests-{}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            let p = dir.join(format!(
                "commands-s{}.toml",
                N.fetch_add(1, Ordering::SeqCst)
            ));
            let mut f = std::fs::File::create(&p).unwrap();
            super::Write::write_all(&mut f, text.as_bytes()).unwrap();
            TempToml(p)
        }
        pub fn path(&self) -> &str {
            self.0.to_str().unwrap()
        }
    }
    impl Drop for TempToml {
        fn drop(&mut self) {
            let _ = std::fs::remove_file(&self.0);
        }
    }
}

#[test]
fn compare_seed_table_snapshot() {
    insta::assert_snapshot!("compare_seed", run_ok(&["compare"]));
}

#[test]
fn compare_seed_json_has_the_contract_keys_and_seed_values() {
    let doc = json(&["compare", "--json"]);
    let results = doc["results"].as_array().unwrap();
    let ids: Vec<&str> = results.iter().map(|r| r["law"].as_str().unwrap()).collect();
    for law in [
        "whittaker",
        "two-phase",
        "smith",
        "brach",
        "newton",
        "poisson",
        "energetic",
    ] {
        assert!(ids.contains(&law), "missing {law}");
    }
    for r in results {
        for key in [
            "law",
            "verdict",
            "impulse",
            "contact_velocity_after",
            "body_velocity_after",
            "energy_change",
            "energy_change_ratio",
            "phases",
            "compression_impulse",
        ] {
            assert!(r.get(key).is_some(), "{} lacks {key}", r["law"]);
        }
        for key in ["vx", "vy", "omega"] {
            assert!(r["body_velocity_after"][key].is_f64());
        }
    }
    let by = |id: &str| results.iter().find(|r| r["law"] == id).unwrap();
    // Independent numbers (paper A eqs. 2, 9, 13 derived by hand; T0 = 1/2).
    let a = 30f64.to_radians();
    let k = 0.4 * 1.7 * a.cos();
    let w = by("whittaker");
    assert_eq!(w["verdict"], "energy-gained");
    let vx = a.sin() - k;
    let om = -2.5 * k;
    let ratio = vx * vx + (0.7 * a.cos()).powi(2) + 0.4 * om * om - 1.0;
    assert!((w["body_velocity_after"]["vx"].as_f64().unwrap() - vx).abs() < 1e-12);
    assert!((w["body_velocity_after"]["omega"].as_f64().unwrap() - om).abs() < 1e-12);
    assert!((w["energy_change_ratio"].as_f64().unwrap() - ratio).abs() < 1e-12);
    let e = by("energetic");
    assert_eq!(e["verdict"], "consistent");
    assert!(e["energy_change_ratio"].as_f64().unwrap() < 0.0);
    assert_eq!(e["phases"][0]["kind"], "slip+");
    assert_eq!(e["phases"][1]["kind"], "stick");
    let ps = 2.0 / 7.0 / 0.4 * a.sin();
    assert!((e["phases"][0]["ends_at"].as_f64().unwrap() - ps).abs() < 1e-12);
    assert!((e["compression_impulse"].as_f64().unwrap() - a.cos()).abs() < 1e-12);
    assert_eq!(
        by("two-phase")["inconsistency"]["id"],
        "reversal-did-not-happen"
    );
}

#[test]
fn compare_flags_change_the_case() {
    // γ = 0.3 is past Whittaker's threshold (≈ 0.206): no more energy gain.
    let doc = json(&[
        "compare",
        "--json",
        "--spin-ratio",
        "0.3",
        "--law",
        "whittaker",
    ]);
    let r = &doc["results"][0];
    assert_eq!(doc["results"].as_array().unwrap().len(), 1);
    assert!(r["energy_change_ratio"].as_f64().unwrap() < 0.0);
    let doc = json(&[
        "compare",
        "--json",
        "--alpha-deg",
        "10",
        "--friction",
        "0",
        "--restitution",
        "1",
        "--mass",
        "2",
        "--radius",
        "0.5",
        "--speed",
        "3",
    ]);
    for r in doc["results"].as_array().unwrap() {
        // Frictionless, elastic: energy conserved, v_y+ = v0 cos α.
        assert!(r["energy_change"].as_f64().unwrap().abs() < 1e-12);
        let vy = r["body_velocity_after"]["vy"].as_f64().unwrap();
        assert!((vy - 3.0 * 10f64.to_radians().cos()).abs() < 1e-12);
    }
}

#[test]
fn compare_reads_toml_scenarios() {
    let rod = scenario_file(
        r#"friction = 0.8
restitution = 1.0
[body]
shape = "rod"
mass = 1.0
length = 1.0
angle_deg = 50.0
velocity = [0.5, -1.0]
omega = 0.0
"#,
    );
    let doc = json(&["compare", rod.path(), "--json"]);
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 9);
    let table = run_ok(&["compare", rod.path()]);
    assert!(table.contains("rod m = 1"));
    let pair = scenario_file(
        r#"friction = 0.3
restitution = 0.5
laws = ["energetic", "whittaker"]
[body]
shape = "disc"
mass = 1.0
radius = 1.0
velocity = [1.0, -1.0]
omega = 2.0
[other]
shape = "ellipse"
mass = 3.0
semi_axes = [2.0, 1.0]
angle_deg = 20.0
velocity = [0.0, 0.5]
omega = -1.0
"#,
    );
    let doc = json(&["compare", pair.path(), "--json"]);
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    assert!(results[0]["other_body_velocity_after"]["vx"].is_f64());
}

#[test]
fn resolve_prints_one_entry_per_law() {
    let doc = json(&[
        "resolve",
        "--w",
        "3.5,0,1",
        "--v",
        "0.5,-0.8660254037844386",
        "--friction",
        "0.4",
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
    ] {
        assert!(doc.get(key).is_some(), "missing {key}");
    }
    assert!(doc.get("body_velocity_after").is_none());
    assert!((doc["velocity_after"]["t"].as_f64().unwrap()).abs() < 1e-15);
    // Negative tangential velocity with a leading minus is accepted.
    let doc = json(&[
        "resolve",
        "--w",
        "2,-0.5,1",
        "--v",
        "-0.5,-1",
        "--friction",
        "0.3",
        "--restitution",
        "0.5",
        "--json",
    ]);
    assert_eq!(doc["results"].as_array().unwrap().len(), 8);
    let text = run_ok(&[
        "resolve",
        "--w",
        "3.5,0,1",
        "--v",
        "0.5,-0.866",
        "--friction",
        "0.4",
        "--restitution",
        "0.7",
    ]);
    assert!(text.contains("energetic") && text.contains("slip+ → stick"));
}

#[test]
fn whittaker_breakdown_is_reported_not_a_number() {
    // W_nn − μ s0 W_tn = 1 − 2·0.9 < 0: Whittaker needs a negative normal impulse.
    let doc = json(&[
        "resolve",
        "--w",
        "2,0.9,1",
        "--v",
        "1,-1",
        "--friction",
        "2",
        "--restitution",
        "0.5",
        "--law",
        "whittaker",
        "--json",
    ]);
    assert_eq!(doc["verdict"], "breakdown");
    assert!(doc["impulse"].is_null() && doc["energy_change"].is_null());
    assert_eq!(doc["breakdown"]["id"], "negative-normal-impulse");
}

#[test]
fn bad_inputs_give_one_line_and_exit_2() {
    let r = |w: &str, v: &str, mu: &str, e: &str| {
        vec![
            "resolve".to_string(),
            "--w".into(),
            w.into(),
            "--v".into(),
            v.into(),
            "--friction".into(),
            mu.into(),
            "--restitution".into(),
            e.into(),
        ]
    };
    let cases: Vec<(Vec<String>, &str)> = vec![
        (r("1,2,1", "0.5,-1", "0.3", "0.5"), "positive definite"),
        (r("-1,0,1", "0.5,-1", "0.3", "0.5"), "positive definite"),
        (r("1,0,1", "0.5,0", "0.3", "0.5"), "v"),
        (r("1,0,1", "0.5,1", "0.3", "0.5"), "negative"),
        (r("1,0,1", "0.5,-1", "-0.1", "0.5"), "friction"),
        (r("1,0,1", "0.5,-1", "0.3", "1.5"), "restitution"),
        (r("1,0,1", "0.5,-1", "0.3", "-0.5"), "restitution"),
        (r("1,0,1", "NaN,-1", "0.3", "0.5"), "--v"),
        (r("1,0,1", "0.5,-1", "NaN", "0.5"), "friction"),
        (r("1,0,1", "0.5,-1", "inf", "0.5"), "friction"),
        (r("1,0,x", "0.5,-1", "0.3", "0.5"), "--w"),
        (r("1,0", "0.5,-1", "0.3", "0.5"), "--w"),
        (r("1,0,1", "0.5,-1,3", "0.3", "0.5"), "--v"),
        (r("1,0,1", "0.5,-1", "abc", "0.5"), "friction"),
    ];
    for (args, needle) in cases {
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        bad(&refs, needle);
    }
    bad(
        &[
            "resolve",
            "--w",
            "1,0,1",
            "--v",
            "0.5,-1",
            "--friction",
            "0.3",
            "--restitution",
            "0.5",
            "--law",
            "bogus",
        ],
        "bogus",
    );
    bad(
        &[
            "resolve",
            "--w",
            "1,0,1",
            "--v",
            "0.5,-1",
            "--friction",
            "0.3",
            "--restitution",
            "0.5",
            "--law",
            "smith-centre",
        ],
        "needs a body",
    );
    bad(&["resolve", "--w", "1,0,1", "--v", "0.5,-1"], "--friction");
    bad(&["compare", "--law", "nope"], "nope");
    bad(&["compare", "--friction", "-1"], "friction");
    bad(&["compare", "--restitution", "2"], "restitution");
    bad(&["compare", "--alpha-deg", "95"], "alpha_deg");
    bad(&["compare", "--alpha-deg", "nan"], "alpha-deg");
    bad(&["compare", "--mass", "0"], "mass");
    bad(&["compare", "--radius", "-1"], "radius");
    bad(&["compare", "--speed", "zero"], "speed");
    bad(&["compare", "/nonexistent/impax.toml"], "cannot read");
    bad(&["frobnicate"], "frobnicate");
    bad(&["paper", "nobody1999"], "nobody1999");
    let broken = scenario_file("friction = 0.4\nrestitution = \n");
    bad(&["compare", broken.path()], ":2:");
    let unknown = scenario_file(
        "friction = 0.4\nrestitution = 0.5\ncolour = 1\n[body]\nshape = \"sphere\"\nmass = 1\nradius = 1\n",
    );
    bad(&["compare", unknown.path()], "colour");
    let shape = scenario_file(
        "friction = 0.4\nrestitution = 0.5\n[body]\nshape = \"torus\"\nmass = 1\nradius = 1\n",
    );
    bad(&["compare", shape.path()], "body.shape");
    let missing = scenario_file(
        "friction = 0.4\nrestitution = 0.5\n[body]\nshape = \"rod\"\nmass = 1\nangle_deg = 40\n",
    );
    bad(&["compare", missing.path()], "body.length");
    let flat = scenario_file(
        "friction = 0.4\nrestitution = 0.5\n[body]\nshape = \"rod\"\nmass = 1\nlength = 1\nangle_deg = 0\nvelocity = [0, -1]\n",
    );
    bad(&["compare", flat.path()], "angle");
    let receding = scenario_file(
        "friction = 0.4\nrestitution = 0.5\n[body]\nshape = \"rigid\"\nmass = 1\ninertia = 1\ncontact = [0, -1]\nvelocity = [0, 1]\n",
    );
    bad(&["compare", receding.path()], "negative");
    let radius_for_rod = scenario_file(
        "friction = 0.4\nrestitution = 0.5\n[body]\nshape = \"rod\"\nmass = 1\nlength = 1\nangle_deg = 40\nvelocity = [0, -1]\n",
    );
    bad(
        &["compare", radius_for_rod.path(), "--radius", "2"],
        "--radius",
    );
}
