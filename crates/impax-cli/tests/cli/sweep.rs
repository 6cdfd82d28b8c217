//! `impax sweep`: rows equal single library calls, output independent of the thread count,
//! `--out`, the summary, and every kind of bad grid (one line on stderr, exit code 2).

use crate::support::{bad, impax, run_bytes};

use impax::planar::bodies::{sphere, spin_state, BodyImpact, Side};
use impax::LawId;

/// A CSV cell as a number (empty: NaN). The writer prints the shortest round-trip form, so
/// parsing gives back the exact value.
fn cell(s: &str) -> f64 {
    if s.is_empty() {
        f64::NAN
    } else {
        s.parse().unwrap()
    }
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()) || (a == 0.0 && b == 0.0)
}

#[test]
fn sweep_rows_equal_single_resolve_calls() {
    let csv = String::from_utf8(run_bytes(&[
        "sweep",
        "--grid",
        "alpha-deg=0:80:5",
        "--grid",
        "spin-ratio=-2:1:7",
        "--set",
        "friction=0.3",
        "--quiet",
    ]))
    .unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header,
        [
            "alpha-deg",
            "spin-ratio",
            "law",
            "status",
            "sequence",
            "p_t",
            "p_n",
            "vt_after",
            "vn_after",
            "compression_impulse",
            "work_compression",
            "work_restitution",
            "work_friction",
            "energy_change",
            "energy_ratio",
            "vx_after",
            "vy_after",
            "omega_after"
        ]
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 5 * 7 * LawId::ALL.len());
    let mut k = 0;
    for i in 0..5 {
        for j in 0..7 {
            let alpha = 80.0 * i as f64 / 4.0;
            let gamma = (-2.0 * (6 - j) as f64 + 1.0 * j as f64) / 6.0;
            let body = sphere(1.0, 1.0, Side::Below).unwrap();
            let state = spin_state(1.0, alpha.to_radians(), gamma, 1.0).unwrap();
            let impact = BodyImpact::on_fixed_surface(body, state);
            let problem = impact.problem(0.3, 0.7).unwrap();
            for law in LawId::ALL {
                let r = &rows[k];
                k += 1;
                assert_eq!(cell(r[0]), alpha);
                assert_eq!(cell(r[1]), gamma, "row {k}");
                assert_eq!(r[2], law.as_str());
                match impact.resolve(law, &problem) {
                    Ok(b) => {
                        let o = b.outcome;
                        assert_eq!(r[3], o.verdict.id());
                        let want = [
                            o.impulse.x,
                            o.impulse.y,
                            o.velocity_after.x,
                            o.velocity_after.y,
                            o.compression_impulse.unwrap_or(f64::NAN),
                            o.work.compression,
                            o.work.restitution,
                            o.work.friction,
                            o.energy_change,
                            // T0 as `impax compare`: the translational energy before.
                            o.energy_change / impact.energy_before().translational,
                            b.body_after.velocity.x,
                            b.body_after.velocity.y,
                            b.body_after.omega,
                        ];
                        for (n, (c, w)) in r[5..].iter().zip(want).enumerate() {
                            assert!(
                                same(cell(c), w),
                                "{law} at α={alpha} γ={gamma}, column {}: {c} vs {w}",
                                header[5 + n]
                            );
                        }
                    }
                    Err(_) => assert_eq!(r[3], "breakdown"),
                }
            }
        }
    }
}

#[test]
fn reduced_columns_take_the_same_numbers() {
    // Without body columns the point is built without its `BodyImpact`: same numbers.
    let grid = [
        "sweep",
        "--grid",
        "alpha-deg=0:89:30",
        "--grid",
        "spin-ratio=-2:2:31",
        "--quiet",
    ];
    let full = String::from_utf8(run_bytes(&grid)).unwrap();
    let mut args = grid.to_vec();
    args.extend([
        "--law",
        "whittaker,energetic",
        "--columns",
        "status,p_t,energy_ratio",
    ]);
    let reduced = String::from_utf8(run_bytes(&args)).unwrap();
    let want: Vec<String> = full
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|c| c[2] == "whittaker" || c[2] == "energetic")
        .map(|c| [c[0], c[1], c[2], c[3], c[5], c[14]].join(","))
        .collect();
    let got: Vec<&str> = reduced.lines().skip(1).collect();
    assert_eq!(got, want);
}

#[test]
fn output_is_identical_for_any_thread_count() {
    // 24 000 points: three chunks of the ordered driver, two laws per point.
    let args = |t: &'static str| {
        vec![
            "sweep",
            "--grid",
            "alpha-deg=0:89:120",
            "--grid",
            "spin-ratio=-3:3:200",
            "--law",
            "whittaker,energetic",
            "--columns",
            "status,sequence,energy_ratio",
            "--threads",
            t,
            "--quiet",
        ]
    };
    let one = run_bytes(&args("1"));
    let three = run_bytes(&args("3"));
    assert_eq!(one.len(), three.len());
    assert!(one == three, "1 and 3 threads differ");
    assert_eq!(
        one.iter().filter(|&&b| b == b'\n').count(),
        1 + 120 * 200 * 2
    );
    let random = |t: &'static str| {
        run_bytes(&[
            "sweep",
            "--random",
            "friction=0:1",
            "--random",
            "restitution=0:1",
            "--samples",
            "10000",
            "--seed",
            "42",
            "--law",
            "poisson",
            "--threads",
            t,
            "--quiet",
        ])
    };
    assert!(random("1") == random("2"));
}

#[test]
fn out_file_and_summary() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("rows.csv");
    let args = [
        "sweep",
        "--grid",
        "restitution=0:1:11",
        "--law",
        "newton",
        "--quiet",
    ];
    let stdout = run_bytes(&args);
    let mut with_out = args.to_vec();
    let p = path.to_str().unwrap();
    with_out.extend(["--out", p]);
    assert!(run_bytes(&with_out).is_empty());
    assert_eq!(std::fs::read(&path).unwrap(), stdout);
    let _ = std::fs::remove_dir_all(&dir);

    let text = String::from_utf8(run_bytes(&[
        "sweep",
        "--grid",
        "spin-ratio=-1:0.5:31",
        "--format",
        "summary",
        "--law",
        "whittaker,energetic",
        "--quiet",
    ]))
    .unwrap();
    let row = |law: &str| -> Vec<String> {
        text.lines()
            .find(|l| l.starts_with(law))
            .unwrap()
            .split_whitespace()
            .map(String::from)
            .collect()
    };
    let w = row("whittaker");
    let e = row("energetic");
    // γ in (−1.206, 0.206) except γ = −sin 30° gains energy under Whittaker: 24 of the 31.
    assert_eq!(w[1], "31");
    assert_eq!(w[3], "24", "{text}");
    assert_eq!(e[3], "0");
    let counts: u64 = e[2..7].iter().map(|c| c.parse::<u64>().unwrap()).sum();
    assert_eq!(counts, 31);
}

#[test]
fn invalid_points_are_rows_not_errors() {
    // vy = 0 at one point: no approach there.
    let f = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-sweep-rigid-{}.toml", std::process::id()));
    std::fs::write(
        &f,
        "friction = 0.3\nrestitution = 0.5\n[body]\nshape = \"rigid\"\nmass = 1\ninertia = 0.5\ncontact = [0.2, -1.0]\nvelocity = [0.5, -1.0]\n",
    )
    .unwrap();
    let out = impax()
        .args([
            "sweep",
            f.to_str().unwrap(),
            "--grid",
            "vy=-1:0:3",
            "--law",
            "energetic",
        ])
        .output()
        .unwrap();
    let _ = std::fs::remove_file(&f);
    assert!(out.status.success());
    let csv = String::from_utf8(out.stdout).unwrap();
    let last = csv.lines().last().unwrap();
    assert!(last.starts_with("0.0,energetic,invalid,none,"), "{last}");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("1 of 3 points are invalid"), "{stderr}");
}

#[test]
fn bad_grids_give_one_line_and_exit_2() {
    let sweep = |extra: &[&'static str]| {
        let mut v = vec!["sweep"];
        v.extend_from_slice(extra);
        v
    };
    bad(&sweep(&["--grid", "alpha-deg=0:90:0"]), "empty grid");
    bad(&sweep(&["--grid", "alpha-deg=90:0:10"]), "reversed");
    bad(&sweep(&["--grid", "alpha-deg=10:10:5"]), "START < STOP");
    bad(&sweep(&["--grid", "alpha-deg=0:10:1"]), "START = STOP");
    bad(
        &sweep(&["--grid", "colour=0:1:3"]),
        "unknown field `colour`",
    );
    bad(
        &sweep(&["--grid", "length=1:2:3"]),
        "not a parameter of shape",
    );
    bad(&sweep(&["--grid", "vx=0:1:3"]), "velocity/omega");
    bad(&sweep(&["--grid", "other.mass=1:2:3"]), "no [other] body");
    bad(
        &sweep(&["--grid", "alpha-deg=0:90"]),
        "NAME=START:STOP:COUNT",
    );
    bad(&sweep(&["--grid", "alpha-deg"]), "NAME=START:STOP:COUNT");
    bad(&sweep(&["--grid", "alpha-deg=a:90:3"]), "not a number");
    bad(&sweep(&["--grid", "alpha-deg=0:90:-3"]), "whole number");
    bad(&sweep(&["--grid", "alpha-deg=0:inf:3"]), "finite");
    bad(&sweep(&["--grid", "restitution=0:2:11"]), "[0, 1]");
    bad(&sweep(&["--grid", "friction=-1:1:11"]), "≥ 0");
    bad(&sweep(&["--grid", "alpha-deg=0:120:11"]), "[-90, 90]");
    bad(&sweep(&["--grid", "mass=0:1:11"]), "> 0");
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--grid", "alpha_deg=0:1:3"]),
        "swept twice",
    );
    bad(
        &sweep(&[
            "--grid",
            "alpha-deg=0:90:10000",
            "--grid",
            "spin-ratio=-3:3:10000",
        ]),
        "--yes",
    );
    bad(
        &sweep(&[
            "--grid",
            "alpha-deg=0:90:4294967296",
            "--grid",
            "spin-ratio=-3:3:4294967296",
            "--yes",
        ]),
        "overflows",
    );
    bad(&sweep(&[]), "no points");
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--random", "friction=0:1"]),
        "not both",
    );
    bad(&sweep(&["--random", "friction=0:1"]), "--samples");
    bad(
        &sweep(&["--random", "friction=1:0", "--samples", "5"]),
        "reversed",
    );
    bad(
        &sweep(&["--random", "friction=0:1", "--samples", "0"]),
        "at least 1",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--samples", "3"]),
        "--samples",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--set", "friction"]),
        "NAME=VALUE",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--set", "restitution=3"]),
        "[0, 1]",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--law", "bogus"]),
        "bogus",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--format", "xml"]),
        "xml",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--columns", "p_x"]),
        "p_x",
    );
    bad(
        &sweep(&["--grid", "alpha-deg=0:1:3", "--threads", "0"]),
        "--threads",
    );
    bad(
        &sweep(&[
            "--grid",
            "alpha-deg=0:1:3",
            "--out",
            "/nonexistent/dir/x.csv",
        ]),
        "cannot create",
    );
    bad(
        &["sweep", "/nonexistent/s.toml", "--grid", "alpha-deg=0:1:3"],
        "cannot read",
    );
}

#[cfg(not(feature = "parquet"))]
#[test]
fn parquet_needs_the_feature() {
    bad(
        &[
            "sweep",
            "--grid",
            "alpha-deg=0:1:3",
            "--format",
            "parquet",
            "--out",
            "x.parquet",
        ],
        "without Parquet support",
    );
}

#[test]
fn throughput_line_without_a_terminal_and_nothing_when_quiet() {
    let args = ["sweep", "--grid", "friction=0:1:11", "--format", "summary"];
    let out = impax().args(args).output().unwrap();
    assert!(out.status.success());
    let stderr = String::from_utf8(out.stderr).unwrap();
    // No progress bar when stderr is not a terminal: exactly the throughput line.
    assert_eq!(stderr.lines().count(), 1, "{stderr:?}");
    assert!(stderr.contains("11 points × 9 laws = 99 impacts") && stderr.contains("M impacts/s"));
    let mut quiet = args.to_vec();
    quiet.push("--quiet");
    let out = impax().args(quiet).output().unwrap();
    assert!(out.stderr.is_empty());
}
