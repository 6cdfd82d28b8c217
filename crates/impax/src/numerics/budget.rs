//! A step budget for a whole integrated motion, with an early verdict.
//!
//! A hard limit alone is a poor guard: an integration that cannot finish (a state spinning at
//! 10⁷ rad/s over seconds) runs the whole limit before it fails — minutes for a robot. After
//! [`StepBudget::PROBE`] steps the budget also *projects* the steps the motion needs from the
//! pace so far, `n · T / t` (`n` steps to reach `t` of the motion's duration `T`), and gives up
//! at once when the projection exceeds twice the limit. The pace of a free motion changes
//! little (its speeds are bounded by its energy), so a motion that fits is not refused; one
//! that slows down enough to fit after a projection over twice the limit is refused early,
//! which the message says.

use crate::error::{Error, Result};

/// The step budget of one motion of duration `duration`, the field that sets it named
/// `field` (`duration`, `until`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct StepBudget {
    /// The largest number of steps (accepted and rejected) over the whole motion.
    pub max: usize,
    /// The motion's duration (from its start, `t = 0`).
    pub duration: f64,
    /// The field that sets the duration, for the error.
    pub field: &'static str,
}

impl StepBudget {
    /// Steps before the first projection.
    pub const PROBE: usize = 1000;

    /// The steps still allowed after `used`.
    pub fn remaining(&self, used: usize) -> usize {
        self.max.saturating_sub(used)
    }

    /// After `used` steps the motion has reached `t`: an error, naming the field, when the
    /// budget is spent or the projected need `used · duration / t` exceeds twice the budget.
    pub fn check(&self, used: usize, t: f64) -> Result<()> {
        let projected = if t > 0.0 {
            used as f64 * self.duration / t
        } else {
            f64::INFINITY
        };
        if used < self.max && (used < Self::PROBE || projected <= 2.0 * self.max as f64) {
            return Ok(());
        }
        let pace = if used >= self.max {
            format!(
                "the motion took the {} integrator steps allowed to reach t = {t:.3e} s of it",
                self.max
            )
        } else if projected.is_finite() {
            format!(
                "the motion needs about {projected:.1e} integrator steps over it at its pace so \
                 far ({used} steps to t = {t:.3e} s), more than twice the {} allowed",
                self.max
            )
        } else {
            format!("the motion does not advance ({used} integrator steps without leaving t = 0)")
        };
        Err(Error::OutOfRange {
            field: self.field.into(),
            value: self.duration,
            reason: format!("{pace}: shorten it, or start from slower speeds"),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::StepBudget;

    #[test]
    fn projection_and_limit() {
        let b = StepBudget {
            max: 10_000,
            duration: 10.0,
            field: "duration",
        };
        // Too few steps to judge the pace.
        assert!(b.check(999, 1e-9).is_ok());
        // 1000 steps to t = 1: 10 000 projected, within twice the limit.
        assert!(b.check(1000, 1.0).is_ok());
        // 1000 steps to t = 0.1: 100 000 projected.
        let e = b.check(1000, 0.1).unwrap_err().to_string();
        assert!(e.starts_with("duration: 10 is out of range"), "{e}");
        // The hard limit.
        assert!(b.check(10_000, 9.9).is_err());
        assert_eq!(b.remaining(12_000), 0);
    }
}
