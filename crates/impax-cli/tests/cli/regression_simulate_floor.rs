//! Regression: `impax simulate` went through the floor with exit 0.
//!
//! Found by an adversarial run: `impax simulate rod-drop` (defaults) fell to y = −22 m by
//! t = 3 s after its 15th impact, stop reason `time-limit`; `--angle-deg 0` reached −74 m;
//! `impax simulate double-pendulum-drop --angles-deg 90,0 --floor -1.0` put the tip 0.73 m below
//! the floor. Only one contact point was watched.
//!
//! Expected: every sampled state keeps both rod ends (and the pendulum's tip and elbow) above
//! the floor, and the run ends with a named stop reason, `energy_final` being the `T + V` of the
//! state at the stop. (When this was fixed the rod dropped flat stopped with
//! `unsupported-contact` and the pendulum with `persistent-contact`; impacts at several
//! contacts and contacts that stay closed are simulated now, and both end at rest.)

use serde_json::Value;

fn simulate(args: &[&str]) -> Value {
    let out = crate::support::impax()
        .arg("simulate")
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn csv_rows(args: &[&str]) -> Vec<Vec<f64>> {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "impax-floor-{}-{}.csv",
        std::process::id(),
        args.join("_").replace(['/', ','], "-")
    ));
    let out = crate::support::impax()
        .arg("simulate")
        .args(args)
        .arg("--csv")
        .arg(&path)
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).ok();
    text.lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .enumerate()
                .filter(|(i, _)| *i != 1) // the mode column
                .map(|(_, x)| x.parse().unwrap())
                .collect()
        })
        .collect()
}

#[test]
fn rod_drop_keeps_both_ends_above_the_floor_and_names_its_stop() {
    for angle in ["30", "0", "5", "89"] {
        let doc = simulate(&["rod-drop", "--angle-deg", angle]);
        let stop = doc["stop"]["id"].as_str().unwrap();
        assert_ne!(stop, "time-limit", "--angle-deg {angle}: {}", doc["stop"]);
        // Columns: t, x, y, θ, ẋ, ẏ, θ̇, kinetic, potential, energy (unit rod, l = 1).
        for row in csv_rows(&["rod-drop", "--angle-deg", angle]) {
            let (y, theta) = (row[2], row[3]);
            let lowest = y - 0.5 * theta.sin().abs();
            assert!(lowest >= -1e-12, "--angle-deg {angle}: an end at {lowest}");
        }
    }
    let flat = simulate(&["rod-drop", "--angle-deg", "0"]);
    assert_eq!(flat["stop"]["id"], "rest");
    // The landing is one impact at both ends, under lcp.
    let first = &flat["impacts"][0];
    assert_eq!(first["law"], "lcp");
    assert_eq!(first["contacts"].as_array().unwrap().len(), 2);
    // At rest lying on the floor: T + V = 0 at the end, the ledger closed.
    let e1 = flat["energy_final"].as_f64().unwrap();
    assert!(e1.abs() < 1e-12, "{e1}");
    assert!(flat["ledger"]["residual"].as_f64().unwrap().abs() < 1e-9);
}

#[test]
fn a_pendulum_tip_resting_on_the_floor_rests_at_once() {
    let doc = simulate(&[
        "double-pendulum-drop",
        "--angles-deg",
        "90,0",
        "--floor",
        "-1.0",
    ]);
    assert_eq!(doc["stop"]["id"], "rest");
    assert_eq!(doc["stop"]["time"], 0.0);
    // Columns: t, θ1, θ2, θ̇1, θ̇2, … : tip y = −cos θ1 − cos θ2 ≥ −1, elbow y = −cos θ1 ≥ −1.
    for row in csv_rows(&[
        "double-pendulum-drop",
        "--angles-deg",
        "90,0",
        "--floor",
        "-1.0",
    ]) {
        let (a, b) = (row[1], row[2]);
        assert!(-a.cos() - b.cos() >= -1.0 - 1e-12);
        assert!(-a.cos() >= -1.0 - 1e-12);
    }
}
