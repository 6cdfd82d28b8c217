//! The planar box, added to the core's table of shapes alone, through the command line: a
//! scenario file with `shape = "box"` is compared, audited and swept like any other, with the
//! numbers of the `rigid` shape of the same inertia and contact corner, and errors naming the
//! file's keys.

use crate::support::{f, fails, impax, json};
use serde_json::Value;

/// A scratch file of this module, its path as text.
fn write(name: &str, text: &str) -> String {
    let path = crate::support::write(&format!("shape-box-{name}"), text);
    path.to_str().unwrap().to_string()
}

const BOX: &str = "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"box\"\nmass = 2.0\n\
                   half_extents = [1.0, 0.5]\nangle_deg = 20\nvelocity = [0.3, -1.0]\nomega = 0.2\n";

/// Every number of two `compare --json` documents within `tol` (the same keys and strings).
fn same_numbers(x: &Value, y: &Value, tol: f64, path: &str) {
    match (x, y) {
        (Value::Number(_), Value::Number(_)) => {
            let (a, b) = (f(x), f(y));
            assert!((a - b).abs() <= tol * (1.0 + b.abs()), "{path}: {a} vs {b}");
        }
        (Value::Object(a), Value::Object(b)) => {
            assert_eq!(
                a.keys().collect::<Vec<_>>(),
                b.keys().collect::<Vec<_>>(),
                "{path}"
            );
            for (k, v) in a {
                same_numbers(v, &b[k], tol, &format!("{path}.{k}"));
            }
        }
        (Value::Array(a), Value::Array(b)) => {
            assert_eq!(a.len(), b.len(), "{path}");
            for (i, (u, v)) in a.iter().zip(b).enumerate() {
                same_numbers(u, v, tol, &format!("{path}[{i}]"));
            }
        }
        _ => assert_eq!(x, y, "{path}"),
    }
}

#[test]
fn a_box_file_is_the_rigid_body_with_its_inertia_and_lowest_corner() {
    let (m, a, b) = (2.0f64, 1.0f64, 0.5f64);
    let theta = 20f64.to_radians();
    let (s, c) = theta.sin_cos();
    // The lowest corner (−a, −b) turned by θ, and I = m (a² + b²)/3.
    let contact = [-a * c + b * s, -a * s - b * c];
    let inertia = m * (a * a + b * b) / 3.0;
    let rigid = format!(
        "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"rigid\"\nmass = 2.0\n\
         inertia = {inertia:?}\ncontact = [{:?}, {:?}]\nvelocity = [0.3, -1.0]\nomega = 0.2\n",
        contact[0], contact[1]
    );
    let mut x = json(&["compare", &write("box.toml", BOX), "--json"]);
    let mut y = json(&["compare", &write("rigid.toml", &rigid), "--json"]);
    assert!(x["scenario"]
        .as_str()
        .unwrap()
        .starts_with("box m = 2, a = 1, b = 0.5, at 20°, v = (0.3, -1), ω = 0.2"));
    for doc in [&mut x, &mut y] {
        doc.as_object_mut().unwrap().remove("scenario");
    }
    same_numbers(&x, &y, 1e-13, "");
    let w = &x["problem"]["w"];
    let wtn = -contact[0] * contact[1] / inertia;
    assert!((f(&w[0][1]) - wtn).abs() < 1e-15, "{w}");
}

#[test]
fn a_box_is_audited_and_swept_by_its_fields() {
    let path = write("box.toml", BOX);
    let out = impax().args(["audit", &path]).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = impax()
        .args([
            "sweep",
            &path,
            "--grid",
            "half-extent-a=0.5:2:4",
            "--grid",
            "half_extent_b=0.25:1:2",
            "--grid",
            "angle-deg=10:80:3",
            "--law",
            "energetic",
            "--quiet",
            "--threads",
            "1",
        ])
        .output()
        .unwrap();
    assert!(
        csv.status.success(),
        "{}",
        String::from_utf8_lossy(&csv.stderr)
    );
    let text = String::from_utf8(csv.stdout).unwrap();
    let mut rows = text.lines();
    assert!(rows
        .next()
        .unwrap()
        .starts_with("half-extent-a,half-extent-b,angle-deg,law,status"));
    let rows: Vec<&str> = rows.collect();
    assert_eq!(rows.len(), 4 * 2 * 3);
    // The energetic law never gains energy; every point of a tilted box is an impact.
    for r in rows {
        let cols: Vec<&str> = r.split(',').collect();
        assert_eq!(cols[4], "consistent", "{r}");
    }
    // A field of another shape is refused, naming the box.
    let e = fails(&["sweep", &path, "--grid", "radius=1:2:2"]);
    assert!(e.contains("not a parameter of shape `box`"), "{e}");
}

#[test]
fn box_errors_name_the_file_keys() {
    let flat = write("flat.toml", &BOX.replace("angle_deg = 20", "angle_deg = 0"));
    let e = fails(&["compare", &flat]);
    assert!(
        e.contains("body.corner: an edge touches, not one corner"),
        "{e}"
    );
    let chosen = write(
        "chosen.toml",
        &BOX.replace("angle_deg = 20", "angle_deg = 0\ncorner = [1, -1]"),
    );
    let doc = json(&["compare", &chosen, "--json"]);
    assert!(doc["scenario"].as_str().unwrap().contains("corner (1, -1)"));
    let missing = write(
        "missing.toml",
        &BOX.replace("half_extents = [1.0, 0.5]\n", ""),
    );
    let e = fails(&["compare", &missing]);
    assert!(
        e.contains("body.half_extents: required for shape `box`"),
        "{e}"
    );
    let unknown = write("unknown.toml", &BOX.replace("half_extents", "half_sizes"));
    let e = fails(&["compare", &unknown]);
    assert!(
        e.contains("half_sizes") && e.contains("half_extents"),
        "{e}"
    );
}
