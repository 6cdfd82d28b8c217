//! The command-line harness shared by the CLI test files that include it (`mod support;`):
//! run the built `impax`, read its JSON, require a one-line error with exit 2.

#![allow(dead_code)]

use assert_cmd::Command;
use serde_json::Value;

/// The built `impax` binary.
pub fn impax() -> Command {
    Command::cargo_bin("impax").expect("the impax binary is built")
}

/// Run `impax args…`, require success and parse standard output as JSON.
pub fn json(args: &[&str]) -> Value {
    let out = impax().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Run `impax args…`, require exit code 2 and a one-line message on standard error; return it.
pub fn fails(args: &[&str]) -> String {
    let out = impax().args(args).output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    err
}

/// A JSON number.
pub fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}
