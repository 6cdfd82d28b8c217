//! The crate's one error type: every violation names the field and the reason.
//!
//! Numbers in messages are printed by [`Num`]: the shortest text that reads back to the same
//! `f64`, in scientific notation when fixed point would need many digits (`1e308`, not a
//! 309-digit integer).

use std::fmt;
use thiserror::Error;

/// A number as it appears in a message: the shortest text that reads back to the same `f64`,
/// in fixed point for magnitudes in `[1e-6, 1e9)` (and zero) and in scientific notation
/// outside (`1e308`, `1.5e-200`); NaN and infinities as Rust prints them (`NaN`, `inf`).
///
/// ```
/// use impax::error::Num;
/// assert_eq!(Num(0.7).to_string(), "0.7");
/// assert_eq!(Num(12.0).to_string(), "12");
/// assert_eq!(Num(-2.5e-3).to_string(), "-0.0025");
/// assert_eq!(Num(1e308).to_string(), "1e308");
/// assert_eq!(Num(-1.5e-200).to_string(), "-1.5e-200");
/// assert_eq!(Num(f64::NAN).to_string(), "NaN");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x.is_finite() && x != 0.0 && !(1e-6..1e9).contains(&x.abs()) {
            write!(f, "{x:e}")
        } else {
            write!(f, "{x}")
        }
    }
}

/// [`Num`] as a `String`: `fmt_number(1e308) == "1e308"`, `fmt_number(0.7) == "0.7"`.
pub fn fmt_number(x: f64) -> String {
    Num(x).to_string()
}

/// Errors returned by `impax` when an input cannot describe a physical impact.
///
/// Every variant names the offending field (as the user spells it: `w`, `v`, `friction`,
/// `restitution`, `mass`, …) so that a command-line front end can print one clear line.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A number is NaN or infinite.
    #[error("{field}: must be a finite number, got {}", Num(*.value))]
    NotFinite {
        /// The field, e.g. `w[0][1]` or `friction`.
        field: String,
        /// The value received.
        value: f64,
    },
    /// A number is outside the range the physics allows.
    #[error("{field}: {} is out of range: {reason}", Num(*.value))]
    OutOfRange {
        /// The field.
        field: String,
        /// The value received.
        value: f64,
        /// Why it is not allowed, e.g. `must be in [0, 1]`.
        reason: String,
    },
    /// The contact-space matrix is not symmetric.
    #[error(
        "{field}: must be symmetric, but entry (t,n) = {} differs from (n,t) = {}",
        Num(*.upper),
        Num(*.lower)
    )]
    NotSymmetric {
        /// The field (`w`).
        field: String,
        /// The upper off-diagonal entry.
        upper: f64,
        /// The lower off-diagonal entry.
        lower: f64,
    },
    /// The contact-space matrix is not positive definite.
    #[error("{field}: must be positive definite, but {reason}")]
    NotPositiveDefinite {
        /// The field (`w`).
        field: String,
        /// Which test failed, with numbers.
        reason: String,
    },
    /// The bodies are not approaching at the contact point.
    #[error(
        "{field}: the normal contact velocity must be negative (approach), got {}",
        Num(*.value)
    )]
    NotApproaching {
        /// The field (`v`).
        field: String,
        /// The normal velocity received.
        value: f64,
    },
    /// A law id that impax does not know.
    #[error("law: unknown impact law `{id}` (known: {known})")]
    UnknownLaw {
        /// The id received.
        id: String,
        /// The known ids, comma separated.
        known: String,
    },
    /// A numerical integration could not proceed (non-finite equations of motion, step-size
    /// underflow, too many steps).
    #[error("integration: {reason}")]
    Integration {
        /// What went wrong.
        reason: String,
    },
    /// A description that cannot be read (malformed TOML, a missing key, a value of the wrong
    /// type, an unknown key), with the line and column of the problem when known.
    #[error("{}{message}", .at.map_or(String::new(), |(l, c)| format!("{l}:{c}: ")))]
    Syntax {
        /// Line and column (1-based) of the problem.
        at: Option<(usize, usize)>,
        /// What is wrong.
        message: String,
    },
    /// Any other invalid description, e.g. a body shape with a missing parameter.
    #[error("{field}: {reason}")]
    Invalid {
        /// The field.
        field: String,
        /// The reason.
        reason: String,
    },
}

impl Error {
    /// The field the error names, as at the start of its message (`law` for an unknown law,
    /// `integration` for a failed integration).
    pub fn field(&self) -> &str {
        match self {
            Error::NotFinite { field, .. }
            | Error::OutOfRange { field, .. }
            | Error::NotSymmetric { field, .. }
            | Error::NotPositiveDefinite { field, .. }
            | Error::NotApproaching { field, .. }
            | Error::Invalid { field, .. } => field,
            Error::UnknownLaw { .. } => "law",
            Error::Integration { .. } => "integration",
            Error::Syntax { .. } => "syntax",
        }
    }
}

impl Error {
    /// The same error with its field named inside `prefix` (`mass` → `body.mass`): the field
    /// as a file spells it when the error comes from one of its sections. An empty prefix
    /// leaves the error as it is (a front end that names fields without a section).
    pub fn prefixed(self, prefix: &str) -> Self {
        if prefix.is_empty() {
            return self;
        }
        let name = |field: String| format!("{prefix}.{field}");
        match self {
            Error::NotFinite { field, value } => Error::NotFinite {
                field: name(field),
                value,
            },
            Error::OutOfRange {
                field,
                value,
                reason,
            } => Error::OutOfRange {
                field: name(field),
                value,
                reason,
            },
            Error::NotSymmetric {
                field,
                upper,
                lower,
            } => Error::NotSymmetric {
                field: name(field),
                upper,
                lower,
            },
            Error::NotPositiveDefinite { field, reason } => Error::NotPositiveDefinite {
                field: name(field),
                reason,
            },
            Error::NotApproaching { field, value } => Error::NotApproaching {
                field: name(field),
                value,
            },
            Error::Invalid { field, reason } => Error::Invalid {
                field: name(field),
                reason,
            },
            other => other,
        }
    }

    /// A TOML error of `text` as [`Error::Syntax`], with the line and column of its span.
    pub(crate) fn syntax(text: &str, err: &toml::de::Error) -> Self {
        let at = err.span().map(|span| {
            let before = &text[..span.start.min(text.len())];
            let line = before.matches('\n').count() + 1;
            let col = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            (line, col)
        });
        Error::Syntax {
            at,
            message: err.message().replace('\n', " "),
        }
    }
}

/// Result alias for this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Check that `value` is finite, naming `field` otherwise.
pub(crate) fn finite(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite {
            field: field.to_string(),
            value,
        })
    }
}

/// [`finite`] with the field's name built only for the error (names of matrix entries and
/// per-contact fields are formatted: a batch of valid problems should not pay for them).
pub(crate) fn finite_named(field: impl FnOnce() -> String, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite {
            field: field(),
            value,
        })
    }
}

/// Check that the kinetic energy `½ uᵀMu = energy` of generalized velocities whose largest
/// magnitude is `u_max` is representable with room to spare — below `1e300`, and above
/// `1e-290` unless the velocities are all zero — so that `ΔT`, `T⁺` and `T⁺/T⁻` are numbers;
/// an error naming `u` otherwise.
pub(crate) fn kinetic_energy(energy: f64, u_max: f64) -> Result<()> {
    let within = energy.is_finite() && energy <= 1e300 && (u_max == 0.0 || energy >= 1e-290);
    if within {
        return Ok(());
    }
    Err(Error::OutOfRange {
        field: "u".into(),
        value: u_max,
        reason: format!(
            "the kinetic energy ½ uᵀMu = {} is not representable with room to spare (it must be between 1e-290 and 1e300)",
            Num(energy)
        ),
    })
}

/// Check the coefficients shared by every contact problem: `μ ≥ 0`, `0 ≤ e ≤ 1`.
pub(crate) fn coefficients(friction: f64, restitution: f64) -> Result<()> {
    if let Some(reason) = friction_out_of_range(friction) {
        return Err(Error::OutOfRange {
            field: "friction".into(),
            value: friction,
            reason: reason.into(),
        });
    }
    if !(0.0..=1.0).contains(&restitution) {
        return Err(Error::OutOfRange {
            field: "restitution".into(),
            value: restitution,
            reason: "the coefficient of restitution must be in [0, 1]".into(),
        });
    }
    Ok(())
}

/// The largest friction coefficient accepted. A larger one acts as this one to round-off
/// (a slip halts within an impulse of order `1/μ`), and products of it with the other
/// numbers of a law could overflow.
pub const MAX_FRICTION: f64 = 1e300;

/// Why a friction coefficient is out of range (`μ < 0` or `μ > MAX_FRICTION`), if it is.
pub(crate) fn friction_out_of_range(friction: f64) -> Option<&'static str> {
    if friction < 0.0 {
        Some("the friction coefficient must be ≥ 0")
    } else if friction > MAX_FRICTION {
        Some("the friction coefficient must be ≤ 1e300 (beyond, products with it overflow; a slip already halts at once)")
    } else {
        None
    }
}

/// Check that the approach energy `½ vᵀ W⁻¹ v` is representable (every impulse and work of
/// the impact is bounded by its scale).
pub(crate) fn representable_energy(energy: f64, speed: f64) -> Result<()> {
    if energy.is_finite() {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            field: "v".into(),
            value: speed,
            reason: format!(
                "too large for W: the approach energy ½ vᵀW⁻¹v = {} is not representable",
                Num(energy)
            ),
        })
    }
}
