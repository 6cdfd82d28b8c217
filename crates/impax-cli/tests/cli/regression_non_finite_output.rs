//! Regression: non-finite numbers in successful output, and errors that blamed the wrong field.
//!
//! Found by an adversarial run over the command line (issue "No silent wrong answers", items 9
//! and 12): `simulate bouncing-ball --height 1e308` printed `T + V: inf` (null in JSON); a 3D
//! body with `omega = [0, 1, 1e200]` gave `energy_before: null`; `conserved ring-pendulum
//! --about 1e308,1e308` gave null quantities; `sweep --grid speed=1e-300:1e300:5 --format
//! summary` printed inf and NaN; `map` on a 1 × 1 grid printed "γ grid step inf"; `compare
//! --speed 1e-300` printed NaN; a singular `W` (`--w 1e308,1e308,1e308`) and `compare
//! double-pendulum --masses 1e-200,1e-200` blamed `v: … approach energy = NaN`.
//!
//! Expected: a finite right answer, or exit 2 with one line naming the field that is out of
//! range.

use serde_json::Value;

fn impax(args: &[&str]) -> (Option<i32>, String, String) {
    let out = crate::support::impax().args(args).output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Exit 2, nothing on stdout, one line on stderr naming `field`.
fn refused(args: &[&str], field: &str) {
    let (code, out, err) = impax(args);
    assert_eq!(code, Some(2), "impax {args:?}: {out}{err}");
    assert!(out.is_empty(), "impax {args:?}: {out}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.starts_with(&format!("error: {field}:")),
        "impax {args:?}: `{err}` does not name `{field}`"
    );
}

/// Exit 0 and the command line's contract (`impax_cli::contract`): no NaN or infinity shown
/// as a number, and no null in JSON where a number is documented.
fn finite(args: &[&str]) -> String {
    let (code, out, err) = impax(args);
    assert_eq!(code, Some(0), "impax {args:?}: {err}");
    let run = impax_cli::Invocation {
        code: 0,
        stdout: out.clone().into_bytes(),
        stderr: err,
    };
    if let Err(why) = impax_cli::contract::check(&run) {
        panic!("impax {args:?}: {why}");
    }
    out
}

/// A scratch file of this module.
fn tmp(name: &str, text: &str) -> std::path::PathBuf {
    crate::support::write(&format!("nonfinite-{name}"), text)
}

#[test]
fn a_simulation_whose_energy_overflows_is_refused() {
    refused(
        &["simulate", "bouncing-ball", "--height", "1e308"],
        "height",
    );
    refused(
        &[
            "simulate", "rod-drop", "--height", "1e307", "--mass", "1e10",
        ],
        "height",
    );
}

#[test]
fn a_3d_body_whose_energy_overflows_is_refused_naming_omega() {
    let path = tmp(
        "spin.toml",
        "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\nshape = \"ellipsoid\"\nmass = 1.0\n\
         semi_axes = [2.0, 1.0, 0.5]\nvelocity = [0.5, 0.2, -1.0]\nomega = [0.0, 1.0, 1e200]\n",
    );
    refused(&["compare", path.to_str().unwrap(), "--json"], "body.omega");
}

#[test]
fn an_angular_momentum_that_overflows_is_refused_naming_about() {
    refused(
        &["conserved", "ring-pendulum", "--about", "1e308,1e308"],
        "about",
    );
}

#[test]
fn sweeps_and_maps_print_no_infinity() {
    let out = finite(&[
        "sweep",
        "--grid",
        "speed=1e-300:1e300:5",
        "--format",
        "summary",
    ]);
    assert!(out.contains("energetic"));
    let png = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-nonfinite-{}.png", std::process::id()));
    let (code, out, err) = impax(&[
        "map",
        "--grid",
        "alpha-deg=30:30:1",
        "--grid",
        "spin-ratio=0:0:1",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!format!("{out}{err}").contains("inf"), "{out}{err}");
}

#[test]
fn a_speed_whose_energy_underflows_is_refused_and_a_small_one_is_right() {
    refused(&["compare", "--speed", "1e-300"], "speed");
    // At 1e-140 every number is representable: the seed's ratios, e.g. Whittaker's gain.
    let doc: Value =
        serde_json::from_str(&finite(&["compare", "--speed", "1e-140", "--json"])).unwrap();
    let whittaker = doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["law"] == "whittaker")
        .unwrap();
    let ratio = whittaker["energy_change_ratio"].as_f64().unwrap();
    assert!((ratio - 0.2424).abs() < 1e-4, "{ratio}");
}

#[test]
fn a_singular_w_and_tiny_masses_blame_the_right_field_or_resolve() {
    refused(
        &[
            "resolve",
            "--w",
            "1e308,1e308,1e308",
            "--v",
            "0.5,-1",
            "--friction",
            "0.4",
            "--restitution",
            "0.5",
        ],
        "w",
    );
    // Masses of 1e-200: W ≈ 1e200, the same impact in other units; the ratios T⁺/T⁻ are
    // those of unit masses.
    let ratios = |masses: &str| -> Vec<f64> {
        let doc: Value = serde_json::from_str(&finite(&[
            "compare",
            "double-pendulum",
            "--masses",
            masses,
            "--json",
        ]))
        .unwrap();
        doc["results"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["energy_ratio"].as_f64().unwrap())
            .collect()
    };
    let (tiny, unit) = (ratios("1e-200,1e-200"), ratios("1,1"));
    for (a, b) in tiny.iter().zip(&unit) {
        assert!((a - b).abs() < 1e-9 * b.abs().max(1.0), "{a} vs {b}");
    }
}

/// Found by the adversarial run of mutated files: a spin of 1e308 (planar body, mechanism)
/// gave null energies; a sphere mechanism at y = 1e20 had its lowest point at its centre in
/// double precision, and its impact was computed without rotation (`W = I`, silently).
#[test]
fn extreme_spins_and_positions_are_refused_naming_the_field() {
    let seed = "friction = 0.4\nrestitution = 0.7\n[body]\nshape = \"sphere\"\nmass = 1.0\n\
                radius = 1.0\nspeed = 1.0\nalpha_deg = 30.0\nspin_ratio = 1e308\n";
    let path = tmp("spin-ratio.toml", seed);
    refused(
        &["compare", path.to_str().unwrap(), "--json"],
        "body.spin_ratio",
    );
    let far = tmp(
        "far.toml",
        "mechanism = \"sphere\"\nposition = [0.0, 1e20]\nrates = [0.5, -0.866, 0.0]\n",
    );
    refused(&["compare", far.to_str().unwrap(), "--json"], "q");
    refused(&["audit", far.to_str().unwrap(), "--json"], "q");
    let spin = tmp(
        "spin.toml",
        "mechanism = \"sphere\"\nrates = [0.5, -0.866, 1e300]\n",
    );
    refused(&["compare", spin.to_str().unwrap(), "--json"], "u");
    // Far, but within 4e7 radii of gyration: resolved, with the rotation (W_tt = 7/2).
    let near = tmp(
        "near.toml",
        "mechanism = \"sphere\"\nposition = [0.0, 1e6]\nrates = [0.5, -0.866, 0.0]\n",
    );
    let doc: Value =
        serde_json::from_str(&finite(&["compare", near.to_str().unwrap(), "--json"])).unwrap();
    let wtt = doc["problem"]["w"][0][0].as_f64().unwrap();
    assert!((wtt - 3.5).abs() < 1e-9, "W_tt = {wtt}");
}
