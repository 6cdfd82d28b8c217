//! The options of a resolution: one type for every law, with defaults, that can grow.

/// Options of a resolution (faer's `LltParams` pattern: `Default`, fields that can grow).
///
/// Today one option: the relative tolerance of the laws that integrate — the spatial
/// `newton`, `poisson` and `energetic` (the Darboux–Keller integration in the normal
/// impulse, with the slip direction turning). The planar laws are exact, event by event, and
/// the multiple-impact laws keep their own fixed tolerances: they ignore it.
///
/// ```
/// use impax::{law::Options, spatial::ContactProblem, LawId};
/// let p = ContactProblem::from_upper([2.0, 0.6, 0.3, 1.0, -0.2, 1.5], [0.3, 0.8, -1.0], 0.8, 0.7)
///     .unwrap();
/// let fine = LawId::Energetic.resolve_with(&p, &Options::default().rtol(1e-13)).unwrap();
/// let default = LawId::Energetic.resolve(&p).unwrap();
/// assert!((fine.impulse - default.impulse).norm() < 1e-10 * default.impulse.norm());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Options {
    /// Relative tolerance per step of an integrating law (clamped to `[1e-14, 1e-4]`; NaN
    /// gives the default [`Options::DEFAULT_RTOL`]).
    pub rtol: f64,
}

impl Options {
    /// The default relative tolerance, `1e-12` (per step, on the velocity, impulse and work
    /// scales of the problem): with it the spatial integration agrees with an independent
    /// reference to better than 1e-10 relative (`tests/physics/spatial_reference.rs`).
    pub const DEFAULT_RTOL: f64 = 1e-12;

    /// These options with the relative tolerance `rtol`.
    #[must_use]
    pub fn rtol(mut self, rtol: f64) -> Self {
        self.rtol = rtol;
        self
    }

    /// The tolerance actually used.
    #[inline]
    pub fn effective_rtol(&self) -> f64 {
        if self.rtol.is_nan() {
            Self::DEFAULT_RTOL
        } else {
            self.rtol.clamp(1e-14, 1e-4)
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Options {
            rtol: Self::DEFAULT_RTOL,
        }
    }
}
