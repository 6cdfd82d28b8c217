//! The command-line harness every CLI test module shares: run the built `impax`, read its
//! output or JSON, require a one-line error with exit 2, write scratch files.

#![allow(dead_code)]

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

/// The built `impax` binary.
pub fn impax() -> Command {
    Command::cargo_bin("impax").expect("the impax binary is built")
}

/// Run `impax args…`, require success and return standard output as bytes.
pub fn run_bytes(args: &[&str]) -> Vec<u8> {
    let out = impax().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "impax {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// Run `impax args…`, require success and return standard output.
pub fn run_ok(args: &[&str]) -> String {
    String::from_utf8(run_bytes(args)).expect("UTF-8 output")
}

/// Run `impax args…`, require success and parse standard output as JSON.
pub fn json(args: &[&str]) -> Value {
    serde_json::from_slice(&run_bytes(args)).expect("valid JSON")
}

/// Run `impax args…`, require exit code 2, nothing on standard output and a one-line message
/// on standard error (no panic); return the line.
pub fn fails(args: &[&str]) -> String {
    let out = impax().args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "impax {args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "impax {args:?} printed to stdout");
    assert!(!stderr.contains("panicked"), "impax {args:?} panicked");
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(
        lines.len(),
        1,
        "impax {args:?}: one line expected, got {stderr:?}"
    );
    lines[0].to_string()
}

/// [`fails`], and the line mentions `needle`.
pub fn bad(args: &[&str], needle: &str) -> String {
    let line = fails(args);
    assert!(
        line.contains(needle),
        "impax {args:?}: `{line}` does not mention `{needle}`"
    );
    line
}

/// A JSON number.
pub fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// A scratch path `name` in this test process's own directory under the system's temporary
/// directory (created).
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-cli-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Write `text` to the scratch file `name` ([`scratch`]) and return its path.
pub fn write(name: &str, text: &str) -> PathBuf {
    let path = scratch(name);
    std::fs::write(&path, text).unwrap();
    path
}
