//! The crate's one error type: every violation names the field and the reason.

use thiserror::Error;

/// Errors returned by `impax` when an input cannot describe a physical impact.
///
/// Every variant names the offending field (as the user spells it: `w`, `v`, `friction`,
/// `restitution`, `mass`, …) so that a command-line front end can print one clear line.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A number is NaN or infinite.
    #[error("{field}: must be a finite number, got {value}")]
    NotFinite {
        /// The field, e.g. `w[0][1]` or `friction`.
        field: String,
        /// The value received.
        value: f64,
    },
    /// A number is outside the range the physics allows.
    #[error("{field}: {value} is out of range: {reason}")]
    OutOfRange {
        /// The field.
        field: String,
        /// The value received.
        value: f64,
        /// Why it is not allowed, e.g. `must be in [0, 1]`.
        reason: String,
    },
    /// The contact-space matrix is not symmetric.
    #[error("{field}: must be symmetric, but entry (t,n) = {upper} differs from (n,t) = {lower}")]
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
    #[error("{field}: the normal contact velocity must be negative (approach), got {value}")]
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

/// Check the coefficients shared by every contact problem: `μ ≥ 0`, `0 ≤ e ≤ 1`.
pub(crate) fn coefficients(friction: f64, restitution: f64) -> Result<()> {
    if friction < 0.0 {
        return Err(Error::OutOfRange {
            field: "friction".into(),
            value: friction,
            reason: "the friction coefficient must be ≥ 0".into(),
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
                "too large for W: the approach energy ½ vᵀW⁻¹v = {energy} is not representable"
            ),
        })
    }
}
