//! Regressions (issue 17, item 12): numbers and angles in messages of the command line.
//!
//! * `impax resolve --w 1,0,1 --v 0.1,-1 --friction -1e308 --restitution 0.5` printed
//!   `friction: -1000…000 is out of range` with 309 digits (Rust's `{}` of an `f64`).
//!   Expected: numbers in messages in the shortest round-trip form, in scientific notation
//!   for large and small magnitudes (`-1e308`, `1.5e-200`), unchanged otherwise (`0.7`, `12`).
//! * `impax simulate rod-drop --angle-deg 1e308` ran (and printed the angle with 309 digits).
//!   Expected: an angle of more than 360° in magnitude is bad input naming the field
//!   (`angle-deg`, `alpha-deg` of the bouncing ball, `angles-deg` of the double pendulum, and
//!   `--angles-deg` of the built-in mechanisms of `impax compare`).

/// Bad input: exit code 2, one line on stderr, returned.
fn bad(args: &[&str]) -> String {
    let out = crate::support::impax().args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "impax {args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "impax {args:?} printed to stdout");
    assert_eq!(stderr.trim().lines().count(), 1, "impax {args:?}: {stderr}");
    assert!(!stderr.contains("panicked"));
    stderr.trim().to_string()
}

fn resolve(w: &str, v: &str, friction: &str, restitution: &str) -> String {
    bad(&[
        "resolve",
        "--w",
        w,
        "--v",
        v,
        "--friction",
        friction,
        "--restitution",
        restitution,
    ])
}

#[test]
fn huge_and_tiny_numbers_are_printed_in_scientific_notation() {
    assert_eq!(
        resolve("1,0,1", "0.1,-1", "-1e308", "0.5"),
        "error: friction: -1e308 is out of range: the friction coefficient must be ≥ 0"
    );
    assert_eq!(
        resolve("-1.5e-200,0,1", "0.1,-1", "0.4", "0.5"),
        "error: w: must be positive definite, but W_tt = -1.5e-200 is not positive"
    );
    assert_eq!(
        resolve("1,0,1", "0.1,1e300", "0.4", "0.5"),
        "error: v: the normal contact velocity must be negative (approach), got 1e300"
    );
    assert_eq!(
        resolve("-1e200,0,1", "0.1,-1", "0.4", "0.5"),
        "error: w: must be positive definite, but W_tt = -1e200 is not positive"
    );
    assert_eq!(
        resolve("1,0,1", "0.1,-1", "0.4", "12"),
        "error: restitution: 12 is out of range: the coefficient of restitution must be in [0, 1]"
    );
    assert_eq!(
        resolve("1,0,1", "0.1,-1", "-0.7", "0.5"),
        "error: friction: -0.7 is out of range: the friction coefficient must be ≥ 0"
    );
    let e = bad(&["sweep", "--grid", "alpha-deg=1e300:0:3"]);
    assert!(e.contains("START = 1e300 > STOP = 0"), "{e}");
    let e = bad(&["simulate", "bouncing-ball", "--until", "1e200"]);
    assert!(e.ends_with("got 1e200"), "{e}");
}

#[test]
fn angles_beyond_a_full_turn_are_refused() {
    for (args, field) in [
        (
            &["simulate", "rod-drop", "--angle-deg", "1e308"][..],
            "angle-deg",
        ),
        (
            &["simulate", "rod-drop", "--angle-deg", "-361"][..],
            "angle-deg",
        ),
        (
            &["simulate", "bouncing-ball", "--alpha-deg", "1e308"][..],
            "alpha-deg",
        ),
        (
            &[
                "simulate",
                "double-pendulum-drop",
                "--angles-deg",
                "90,1e308",
            ][..],
            "angles-deg",
        ),
        (
            &["compare", "double-pendulum", "--angles-deg", "30,1e300"][..],
            "angles_deg[1]",
        ),
    ] {
        let e = bad(args);
        assert!(e.starts_with(&format!("error: {field}")), "{args:?}: {e}");
        assert!(e.contains("between -360 and 360 degrees"), "{args:?}: {e}");
        assert!(!e.contains("00000000"), "{args:?}: {e}");
    }
}

#[test]
fn angles_within_a_full_turn_still_run() {
    for args in [
        &[
            "simulate",
            "rod-drop",
            "--angle-deg",
            "360",
            "--until",
            "0.1",
        ][..],
        &[
            "simulate",
            "rod-drop",
            "--angle-deg",
            "-30",
            "--until",
            "0.1",
        ][..],
        &[
            "simulate",
            "bouncing-ball",
            "--alpha-deg",
            "45",
            "--until",
            "0.1",
        ][..],
        &[
            "simulate",
            "double-pendulum-drop",
            "--angles-deg",
            "-360,120",
            "--until",
            "0.1",
        ][..],
    ] {
        let out = crate::support::impax().args(args).output().unwrap();
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}
