//! The command line's contract on any input, as a check: what the fuzz targets (`fuzz/`) and
//! the regression tests assert of every invocation.
//!
//! * the exit code is 0 (success) or 2 (bad input) — never 1 for an input, never a panic;
//! * on exit 2, standard output is empty and standard error is one line `error: …`;
//! * on success, `--json` output holds no `null` where a number is documented: a null is
//!   allowed only under the keys of optional records ([`NULLABLE`]) and inside the entry of
//!   a law that broke down; and no text output shows `NaN` or `inf` as a number.

use crate::Invocation;
use serde_json::Value;

/// Keys whose value is documented as possibly null in a successful JSON document.
pub const NULLABLE: [&str; 10] = [
    "detail",
    "inconsistency",
    "breakdown",
    "compression_impulse",
    "slip_halt",
    "second_compression",
    "switch_impulse",
    "other_body_velocity_after",
    "hodograph",
    "energy_change_from_velocities",
];

/// Check `run` against the contract; `Err` says what is wrong.
pub fn check(run: &Invocation) -> Result<(), String> {
    match run.code {
        0 => {
            let text = String::from_utf8_lossy(&run.stdout);
            if let Ok(doc) = serde_json::from_str::<Value>(&text) {
                nulls(&doc, "", "$")
            } else {
                for bad in [" NaN", " inf", " -inf", "+inf", "(NaN", "(inf"] {
                    if text.contains(bad) {
                        return Err(format!("output shows `{bad}` as a number:\n{text}"));
                    }
                }
                Ok(())
            }
        }
        2 => {
            if !run.stdout.is_empty() {
                return Err("exit 2 with output on stdout".into());
            }
            let lines: Vec<&str> = run
                .stderr
                .lines()
                .filter(|l| !l.trim().is_empty())
                .collect();
            if lines.len() != 1 || !lines[0].starts_with("error: ") {
                return Err(format!(
                    "exit 2 without one `error: ` line on stderr: {:?}",
                    run.stderr
                ));
            }
            Ok(())
        }
        code => Err(format!("exit code {code}: {}", run.stderr)),
    }
}

/// No null under a key where a number is documented.
fn nulls(v: &Value, key: &str, path: &str) -> Result<(), String> {
    match v {
        Value::Null if !NULLABLE.contains(&key) && !path.ends_with("detail.ratio") => {
            Err(format!("null at {path}"))
        }
        Value::Array(a) => a
            .iter()
            .enumerate()
            .try_for_each(|(i, x)| nulls(x, key, &format!("{path}[{i}]"))),
        Value::Object(m) => {
            // A law's entry that broke down, or an audit judgement without one of its two
            // answers, carries nulls by contract.
            let verdict = m
                .get("verdict")
                .and_then(|v| v.as_str().or(v["id"].as_str()));
            let broke_down = matches!(verdict, Some("breakdown" | "no-reference"))
                || m.get("breakdown").is_some_and(|b| !b.is_null());
            if broke_down {
                return Ok(());
            }
            m.iter()
                .try_for_each(|(k, x)| nulls(x, k, &format!("{path}.{k}")))
        }
        _ => Ok(()),
    }
}
