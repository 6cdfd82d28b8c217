//! The options of a simulation.

use crate::error::{Error, Result};
use crate::law::LawId;
use crate::ode::Tolerances;

/// Options of a simulation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulationOptions {
    /// The impact law applied at every impact at one contact; at several contacts at once the
    /// same law if it is a multi-contact law ([`LawId::is_multi_contact`]), else `lcp`.
    pub law: LawId,
    /// Coulomb friction `μ ≥ 0` (impacts and closed contacts).
    pub friction: f64,
    /// Coefficient of restitution `e ∈ [0, 1]`.
    pub restitution: f64,
    /// End time (> 0).
    pub until: f64,
    /// Spacing of the output samples (> 0, at most 10⁶ samples in all).
    pub sample_interval: f64,
    /// Largest number of impacts before stopping with [`super::StopReason::ImpactLimit`].
    pub max_impacts: usize,
    /// Integrator tolerances of the smooth motion.
    pub tolerances: Tolerances,
}

impl SimulationOptions {
    /// `law`, `μ`, `e` until `until`, with 1000 sample intervals, at most 10,000 impacts and
    /// tight tolerances (1e-12 relative).
    pub fn new(law: LawId, friction: f64, restitution: f64, until: f64) -> Self {
        SimulationOptions {
            law,
            friction,
            restitution,
            until,
            sample_interval: until / 1000.0,
            max_impacts: 10_000,
            tolerances: Tolerances::TIGHT,
        }
    }

    pub(crate) fn validate(&self) -> Result<()> {
        crate::error::finite("friction", self.friction)?;
        crate::error::finite("restitution", self.restitution)?;
        crate::error::coefficients(self.friction, self.restitution)?;
        if !(self.until.is_finite() && self.until > 0.0) {
            return Err(Error::OutOfRange {
                field: "until".into(),
                value: self.until,
                reason: "the end time must be finite and positive".into(),
            });
        }
        let count = self.until / self.sample_interval;
        if !(self.sample_interval > 0.0 && count.is_finite() && count <= 1e6) {
            return Err(Error::OutOfRange {
                field: "sample interval".into(),
                value: self.sample_interval,
                reason: "must be positive and give at most 10⁶ samples".into(),
            });
        }
        if self.law.needs_body() {
            return Err(Error::Invalid {
                field: "law".into(),
                reason: format!(
                    "`{}` needs a single body's centre velocity; choose a contact-space law",
                    self.law
                ),
            });
        }
        Ok(())
    }
}
