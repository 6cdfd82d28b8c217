//! Golden outputs: the exact text and JSON of the commands whose output the project promises
//! to keep byte for byte while the code underneath is rearranged (issue 18: `impax compare`,
//! `impax compare double-pendulum`, `impax paper liu2012`, `impax resolve` planar and spatial,
//! `impax audit rod`), and of `impax compare` on a scenario file of every planar shape (each
//! shape's builder, description and normalisation). Each snapshot is the whole standard
//! output; a change in any byte fails.

use crate::support::impax;
use std::path::PathBuf;

/// Run `impax args…`, require success and nothing on standard error; return standard output.
fn stdout(args: &[&str]) -> String {
    let out = impax().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty(), "{args:?}: stderr not empty");
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// Write a scenario file for this test run; its path.
fn scenario(name: &str, text: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-golden-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

/// Snapshots compare text up to trailing line ends: the end is pinned here, one `\n`.
fn one_final_newline(text: &str) {
    assert!(
        text.ends_with('\n') && !text.ends_with("\n\n"),
        "the output ends with exactly one newline"
    );
}

/// Snapshot the text and the JSON (`--json`) of one command.
fn text_and_json(name: &str, args: &[&str]) {
    let text = stdout(args);
    one_final_newline(&text);
    insta::assert_snapshot!(format!("{name}_text"), text);
    let mut json_args = args.to_vec();
    json_args.push("--json");
    let json = stdout(&json_args);
    one_final_newline(&json);
    serde_json::from_str::<serde_json::Value>(&json).expect("valid JSON");
    insta::assert_snapshot!(format!("{name}_json"), json);
}

#[test]
fn compare_seed() {
    text_and_json("compare_seed", &["compare"]);
}

#[test]
fn compare_double_pendulum() {
    text_and_json("compare_double_pendulum", &["compare", "double-pendulum"]);
}

#[test]
fn paper_liu2012() {
    text_and_json("paper_liu2012", &["paper", "liu2012"]);
}

#[test]
fn resolve_planar() {
    text_and_json(
        "resolve_planar",
        &[
            "resolve",
            "--w",
            "3.5,0,1",
            "--v",
            "0.5,-0.866",
            "--friction",
            "0.4",
            "--restitution",
            "0.7",
        ],
    );
}

#[test]
fn resolve_spatial() {
    text_and_json(
        "resolve_spatial",
        &[
            "resolve",
            "--w",
            "3.5,0.2,0.1,2.5,-0.3,1",
            "--v",
            "0.5,-0.2,-0.866",
            "--friction",
            "0.4",
            "--restitution",
            "0.7",
        ],
    );
}

#[test]
fn audit_rod() {
    text_and_json("audit_rod", &["audit", "rod"]);
}

/// One scenario file per planar shape, and two bodies: the shape dispatch, the descriptions
/// and the normalisation of the tables.
#[test]
fn compare_every_shape() {
    let files = [
        (
            "rod",
            "friction = 0.8\nrestitution = 1.0\n[body]\nshape = \"rod\"\nmass = 1.0\nlength = 2.0\nangle_deg = 50\nvelocity = [0.5, -1.0]\nomega = 0.25\n",
        ),
        (
            "ellipse",
            "friction = 0.3\nrestitution = 0.5\n[body]\nshape = \"ellipse\"\nmass = 2.0\nsemi_axes = [2.0, 1.0]\nangle_deg = 20\nvelocity = [0.3, -1.0]\nomega = -0.5\n",
        ),
        (
            "rigid",
            "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"rigid\"\nmass = 1.5\ninertia = 0.4\ncontact = [0.3, -1.0]\nvelocity = [0.2, -1.0]\nomega = 1.0\n",
        ),
        (
            "disc_spin",
            "friction = 0.2\nrestitution = 0.9\n[body]\nshape = \"disc\"\nmass = 1.0\nradius = 0.5\nspeed = 2.0\nalpha_deg = -20\nspin_ratio = 0.3\n",
        ),
        (
            "two_bodies",
            "friction = 0.4\nrestitution = 0.7\n[body]\nshape = \"sphere\"\nmass = 1.0\nradius = 1.0\nspeed = 1.0\nalpha_deg = 30.0\n[other]\nshape = \"rod\"\nmass = 2.0\nlength = 1.0\nangle_deg = 60\nvelocity = [0.1, 0.0]\nomega = 0.5\n",
        ),
    ];
    for (name, text) in files {
        let path = scenario(name, text);
        let path = path.to_str().unwrap();
        // The file's path is not in the output (only its description), so the snapshot is
        // independent of where the test runs.
        text_and_json(&format!("compare_{name}"), &["compare", path]);
    }
}

/// `impax sweep` sets the fields of a scenario by name and rebuilds its bodies: the CSV of
/// small grids over body parameters of every shape, one thread, every byte.
#[test]
fn sweep_body_fields() {
    let rod = scenario(
        "sweep_rod",
        "friction = 0.8\nrestitution = 1.0\n[body]\nshape = \"rod\"\nmass = 1.0\nlength = 2.0\nangle_deg = 50\nvelocity = [0.5, -1.0]\nomega = 0.25\n",
    );
    let ellipse = scenario(
        "sweep_ellipse",
        "friction = 0.3\nrestitution = 0.5\n[body]\nshape = \"ellipse\"\nmass = 2.0\nsemi_axes = [2.0, 1.0]\nvelocity = [0.3, -1.0]\nomega = -0.5\n",
    );
    let rigid = scenario(
        "sweep_rigid",
        "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"rigid\"\nmass = 1.5\ninertia = 0.4\ncontact = [0.3, -1.0]\nvelocity = [0.2, -1.0]\nomega = 1.0\n[other]\nshape = \"disc\"\nmass = 2.0\nradius = 0.5\n",
    );
    let (rod, ellipse, rigid) = (
        rod.to_str().unwrap(),
        ellipse.to_str().unwrap(),
        rigid.to_str().unwrap(),
    );
    let runs: [(&str, Vec<&str>); 4] = [
        (
            "seed",
            vec![
                "--grid",
                "alpha-deg=0:60:3",
                "--grid",
                "mass=0.5:2:2",
                "--grid",
                "radius=1:2:2",
            ],
        ),
        (
            "rod",
            vec![
                rod,
                "--grid",
                "angle-deg=30:150:3",
                "--grid",
                "length=1:2:2",
                "--grid",
                "omega=-1:1:2",
            ],
        ),
        (
            "ellipse",
            vec![
                ellipse,
                "--grid",
                "semi-axis-a=0.5:2:2",
                "--grid",
                "semi_axis_b=0.5:1:2",
                "--grid",
                "angle-deg=0:90:3",
            ],
        ),
        (
            "rigid",
            vec![
                rigid,
                "--grid",
                "contact-t=-0.5:0.5:3",
                "--grid",
                "inertia=0.2:0.8:2",
                "--grid",
                "other.radius=0.5:1:2",
            ],
        ),
    ];
    for (name, grid) in runs {
        let mut args = vec![
            "sweep",
            "--law",
            "whittaker,energetic",
            "--threads",
            "1",
            "--quiet",
        ];
        args.extend(grid);
        let csv = stdout(&args);
        one_final_newline(&csv);
        insta::assert_snapshot!(format!("sweep_{name}"), csv);
    }
}

/// The built-in mechanisms through their descriptions (flags and files): `conserved` of the
/// pendulums on a carrier and of the sphere, `audit sphere`, `compare` of a mechanism file.
#[test]
fn built_in_mechanisms() {
    text_and_json("conserved_ring_pendulum", &["conserved", "ring-pendulum"]);
    text_and_json(
        "conserved_cart_pendulum",
        &[
            "conserved",
            "cart-pendulum",
            "--angles-deg",
            "45",
            "--rates",
            "0.2,1",
            "--masses",
            "2,0.5",
        ],
    );
    text_and_json("conserved_sphere", &["conserved", "sphere"]);
    text_and_json("audit_sphere", &["audit", "sphere"]);
    let rod = scenario(
        "mechanism_rod",
        "mechanism = \"rod\"\nfriction = 0.6\nrestitution = 0.4\nmasses = [2.0]\nlengths = [1.5]\nangles_deg = [40.0]\nrates = [0.3, -1.0, 0.5]\n",
    );
    text_and_json("compare_mechanism_rod", &["compare", rod.to_str().unwrap()]);
}

/// `impax compare` on the mechanism files of `examples/mechanisms/`: Kane & Levinson's
/// double pendulum in the plane and the arm in space. The explorer's view "Your mechanism"
/// answers these files with the same JSON (the module's tests read these snapshots).
#[test]
fn compare_mechanism_files() {
    text_and_json(
        "compare_double_pendulum_file",
        &["compare", "../../examples/mechanisms/double-pendulum.toml"],
    );
    text_and_json(
        "compare_arm_3d_file",
        &["compare", "../../examples/mechanisms/arm-3d.toml"],
    );
}
