//! Input errors of the command line and their one-line rendering.

use std::fmt::Display;

/// Whether the user or the program is at fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Bad input: exit code 2.
    BadInput,
    /// Anything else: exit code 1.
    Failure,
}

/// A CLI error: one line of text and its kind.
#[derive(Debug)]
pub struct CliError {
    pub kind: ErrorKind,
    pub message: String,
}

impl CliError {
    /// Bad input.
    pub fn input(message: impl Display) -> Self {
        Self {
            kind: ErrorKind::BadInput,
            message: message.to_string(),
        }
    }
}

impl CliError {
    /// A failure that is not the user's fault.
    pub fn failure(message: impl Display) -> Self {
        Self {
            kind: ErrorKind::Failure,
            message: message.to_string(),
        }
    }
}

impl From<impax::Error> for CliError {
    fn from(e: impax::Error) -> Self {
        Self::input(e)
    }
}

pub type CliResult<T> = Result<T, CliError>;

/// A clap error as one line: its first paragraph joined, without usage and tips.
pub fn one_line_clap_error(err: &clap::Error) -> String {
    let rendered = err.render().to_string();
    let mut parts = Vec::new();
    for line in rendered.lines().map(str::trim) {
        if line.is_empty() {
            if parts.is_empty() {
                continue;
            }
            break;
        }
        if line.starts_with("Usage:") || line.starts_with("tip:") {
            break;
        }
        parts.push(line);
    }
    let line = if parts.is_empty() {
        "invalid arguments".to_string()
    } else {
        parts.join(" ")
    };
    if line.starts_with("error:") {
        line
    } else {
        format!("error: {line}")
    }
}

/// Parse a comma-separated list of exactly `n` finite numbers for `--flag`.
pub fn parse_numbers(flag: &str, text: &str, n: usize, what: &str) -> CliResult<Vec<f64>> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != n {
        return Err(CliError::input(format!(
            "--{flag}: expected {n} comma-separated numbers ({what}), got {} in `{text}`",
            parts.len()
        )));
    }
    parts
        .iter()
        .map(|p| {
            let x: f64 = p.parse().map_err(|_| {
                CliError::input(format!("--{flag}: `{p}` is not a number (in `{text}`)"))
            })?;
            if !x.is_finite() {
                return Err(CliError::input(format!(
                    "--{flag}: must be finite numbers, got `{p}`"
                )));
            }
            Ok(x)
        })
        .collect()
}

/// Check a flag value is finite.
pub fn finite_flag(flag: &str, x: f64) -> CliResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(CliError::input(format!(
            "--{flag}: must be a finite number, got {}",
            crate::output::fmt::Plain(x)
        )))
    }
}
