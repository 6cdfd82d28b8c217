//! Regressions (issue 17, items 10 and 12): inputs of `impax sweep` / `impax map` that were
//! accepted or misreported.
//!
//! * `impax sweep --grid alpha-deg=0:1:3 --threads 100000` started 7 871 threads before the
//!   machine gave up (load 900). Expected: `--threads` outside 1..=256 (also 0 and negative
//!   values) is bad input, exit code 2, `--threads: must be between 1 and 256, got 100000`.
//! * `impax sweep --grid alpha-deg=0:1:3 --set alpha-deg=5` ran the grid and silently ignored
//!   the `--set`. Expected: a field both fixed by `--set` and swept (`--grid` or `--random`)
//!   is bad input naming the field.
//! * `impax sweep --grid alpha-deg=0:1:4611686018427387904` printed "… points × 9 laws =
//!   18446744073709551615 impacts": the saturated product, not the number of impacts.
//!   Expected: a product of points and laws (or of the grid's COUNTs) beyond `u64` says so
//!   without a wrapped or saturated number, even with `--yes`.

/// Bad input: exit code 2, one line on stderr containing every needle, nothing on stdout.
/// (The old binary ran the `--yes` sweeps below for ever: they are stopped after a minute, a
/// guard against a hanging test, not a measured time.)
fn bad(args: &[&str], needles: &[&str]) -> String {
    let out = crate::support::impax()
        .args(args)
        .timeout(std::time::Duration::from_secs(60))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "impax {args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "impax {args:?} printed to stdout");
    assert_eq!(stderr.trim().lines().count(), 1, "impax {args:?}: {stderr}");
    for needle in needles {
        assert!(stderr.contains(needle), "impax {args:?}: {stderr}");
    }
    assert!(!stderr.contains("panicked"));
    stderr
}

#[test]
fn threads_outside_1_to_256_are_refused() {
    let grid = ["sweep", "--grid", "alpha-deg=0:1:3", "--quiet"];
    for (n, message) in [
        ("100000", "--threads: must be between 1 and 256, got 100000"),
        ("257", "--threads: must be between 1 and 256, got 257"),
        ("0", "--threads: must be between 1 and 256, got 0"),
        ("-1", "--threads: must be between 1 and 256, got -1"),
    ] {
        let args: Vec<&str> = grid.iter().copied().chain(["--threads", n]).collect();
        bad(&args, &[message]);
    }
    let map = [
        "map",
        "--grid",
        "alpha-deg=0:1:3",
        "--grid",
        "spin-ratio=0:1:3",
        "--out",
        "never-written.png",
        "--threads",
        "1000",
    ];
    bad(&map, &["--threads: must be between 1 and 256, got 1000"]);
    // The limit itself is accepted.
    let out = crate::support::impax()
        .args(grid)
        .args(["--threads", "256", "--law", "energetic"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&out.stdout).lines().count(), 4);
}

#[test]
fn the_help_states_the_thread_limit() {
    let out = crate::support::impax()
        .args(["sweep", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("1 to 256"), "{help}");
}

#[test]
fn a_set_field_that_is_also_swept_is_refused() {
    bad(
        &["sweep", "--grid", "alpha-deg=0:1:3", "--set", "alpha-deg=5"],
        &["--set alpha-deg=5", "`alpha-deg`", "--grid"],
    );
    // The same field under its other spelling.
    bad(
        &["sweep", "--grid", "alpha_deg=0:1:3", "--set", "alpha-deg=5"],
        &["`alpha-deg`", "--grid"],
    );
    bad(
        &[
            "sweep",
            "--random",
            "friction=0:1",
            "--samples",
            "3",
            "--set",
            "friction=0.2",
        ],
        &["--set friction=0.2", "`friction`", "--random"],
    );
    bad(
        &[
            "map",
            "--grid",
            "alpha-deg=0:10:3",
            "--grid",
            "friction=0:1:3",
            "--set",
            "friction=0.2",
            "--out",
            "never-written.png",
        ],
        &["`friction`", "--grid"],
    );
}

#[test]
fn a_set_field_that_is_not_swept_still_applies() {
    let out = crate::support::impax()
        .args([
            "sweep",
            "--grid",
            "alpha-deg=0:1:2",
            "--set",
            "friction=0",
            "--law",
            "energetic",
            "--columns",
            "p_t",
            "--quiet",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // μ = 0: no tangential impulse.
    let csv = String::from_utf8(out.stdout).unwrap();
    for row in csv.lines().skip(1) {
        let p_t: f64 = row.rsplit(',').next().unwrap().parse().unwrap();
        assert_eq!(p_t, 0.0, "{csv}");
    }
}

#[test]
fn impacts_beyond_u64_are_refused_without_a_saturated_number() {
    const SATURATED: &str = "18446744073709551615 impacts";
    for yes in [false, true] {
        let mut args = vec!["sweep", "--grid", "alpha-deg=0:1:4611686018427387904"];
        if yes {
            args.push("--yes");
        }
        let e = bad(&args, &["--grid", "more than 2⁶⁴ − 1 impacts"]);
        assert!(!e.contains(SATURATED), "{e}");
        // The product of two COUNTs overflows before the laws are counted.
        let mut args = vec![
            "sweep",
            "--grid",
            "alpha-deg=0:1:4294967296",
            "--grid",
            "friction=0:1:4294967296",
        ];
        if yes {
            args.push("--yes");
        }
        let e = bad(&args, &["--grid", "the number of points overflows 2⁶⁴"]);
        assert!(!e.contains("18446744073709551615"), "{e}");
        let mut args = vec![
            "sweep",
            "--random",
            "friction=0:1",
            "--samples",
            "18446744073709551615",
        ];
        if yes {
            args.push("--yes");
        }
        let e = bad(&args, &["--random", "more than 2⁶⁴ − 1 impacts"]);
        assert!(!e.contains(SATURATED), "{e}");
    }
    // Below the overflow, the confirmation is unchanged.
    bad(
        &["sweep", "--grid", "alpha-deg=0:1:100000000"],
        &["100000000 points × 9 laws = 900000000 impacts", "--yes"],
    );
}
