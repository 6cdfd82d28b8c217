//! `impax compare scenario.toml` with `space = "3d"`: every spatial law on 3D bodies, the
//! JSON keys, a sphere that reproduces the planar seed, and bad 3D scenarios.

use serde_json::Value;

/// A scratch scenario file of this module.
fn write(name: &str, text: &str) -> std::path::PathBuf {
    crate::support::write(&format!("compare3d-{name}"), text)
}

fn run(args: &[&str]) -> std::process::Output {
    crate::support::impax().args(args).output().unwrap()
}

#[test]
fn sphere_in_3d_matches_the_planar_seed() {
    let a = 30f64.to_radians();
    let p = write(
        "sphere.toml",
        &format!(
            "space = \"3d\"\nfriction = 0.4\nrestitution = 0.7\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nvelocity = [{}, 0.0, {}]\n",
            a.sin(),
            -a.cos()
        ),
    );
    let out = run(&["compare", p.to_str().unwrap(), "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let d3: Value = serde_json::from_slice(&out.stdout).unwrap();
    let out = run(&["compare", "--json"]);
    let d2: Value = serde_json::from_slice(&out.stdout).unwrap();
    for r3 in d3["results"].as_array().unwrap() {
        let law = r3["law"].as_str().unwrap();
        let r2 = d2["results"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["law"] == law)
            .unwrap();
        let x3 = r3["energy_change_ratio"].as_f64().unwrap();
        let x2 = r2["energy_change_ratio"].as_f64().unwrap();
        assert!((x3 - x2).abs() < 1e-12, "{law}: {x3} vs {x2}");
        // Planar ω (counter-clockwise in x–z) is −ω_y in 3D.
        let w3 = r3["body_velocity_after"]["omega_y"].as_f64().unwrap();
        let w2 = r2["body_velocity_after"]["omega"].as_f64().unwrap();
        assert!((w3 + w2).abs() < 1e-12, "{law}: {w3} vs {w2}");
        for key in [
            "impulse",
            "contact_velocity_after",
            "phases",
            "compression_impulse",
            "energy_split",
            "work",
        ] {
            assert!(r3.get(key).is_some(), "{law} lacks {key}");
        }
    }
}

#[test]
fn every_3d_shape_resolves() {
    for (name, body) in [
        ("ell", "shape = \"ellipsoid\"\nmass = 1.0\nsemi_axes = [2.0, 1.0, 0.5]\norientation_deg = [10.0, 25.0, 30.0]"),
        ("box", "shape = \"box\"\nmass = 2.0\nhalf_extents = [1.0, 0.5, 0.3]\norientation_deg = [5.0, 10.0, 0.0]"),
        ("cyl", "shape = \"cylinder\"\nmass = 1.0\nradius = 0.5\nhalf_height = 1.0\norientation = [0.9, 0.3, 0.2, 0.0]"),
        ("rig", "shape = \"rigid\"\nmass = 1.0\ninertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.1], [0.0, 0.1, 2.5]]\ncontact = [0.3, -0.2, -0.8]"),
    ] {
        let p = write(
            &format!("{name}.toml"),
            &format!("space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\n{body}\nvelocity = [0.5, 0.2, -1.0]\nomega = [0.0, 1.0, 0.5]\n"),
        );
        let out = run(&["compare", p.to_str().unwrap(), "--json"]);
        assert!(out.status.success(), "{name}: {}", String::from_utf8_lossy(&out.stderr));
        let d: Value = serde_json::from_slice(&out.stdout).unwrap();
        let energetic = d["results"].as_array().unwrap().iter().find(|r| r["law"] == "energetic").unwrap();
        assert!(energetic["energy_change"].as_f64().unwrap() <= 0.0, "{name}");
        let table = run(&["compare", p.to_str().unwrap()]);
        assert!(String::from_utf8_lossy(&table.stdout).contains("impax compare (3D)"));
    }
}

#[test]
fn bad_3d_scenarios_exit_2_with_one_line() {
    for (name, text, needle) in [
        ("flat", "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\nshape = \"box\"\nmass = 1.0\nhalf_extents = [1.0, 1.0, 1.0]\nvelocity = [0.0, 0.0, -1.0]\n", "corner"),
        ("shape", "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\nshape = \"torus\"\nmass = 1.0\nvelocity = [0.0, 0.0, -1.0]\n", "body.shape"),
        ("up", "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nvelocity = [0.0, 0.0, 1.0]\n", "negative"),
        ("law", "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\nlaws = [\"smith\"]\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nvelocity = [0.0, 0.0, -1.0]\n", "planar"),
        ("key", "space = \"3d\"\nfriction = 0.5\nrestitution = 0.6\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\ncolour = 2\n", "colour"),
    ] {
        let p = write(&format!("bad-{name}.toml"), text);
        let out = run(&["compare", p.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert_eq!(err.lines().filter(|l| !l.trim().is_empty()).count(), 1, "{name}: {err}");
        assert!(err.contains(needle), "{name}: `{err}` lacks `{needle}`");
    }
}
