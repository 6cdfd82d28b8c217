//! One contract for every struck system: what it gives a law and what it does with the law's
//! impulse.
//!
//! A body on a surface, two bodies, a mechanism in generalized coordinates — planar or
//! spatial — each freezes its configuration during the impact and is, to the law, one
//! contact-space problem `v(p) = v⁻ + W p` (theory §1): [`Impact::problem`] builds it for a
//! friction `μ` and a restitution `e`, and [`Impact::velocities_after`] maps the impulse `p`
//! back (`M (u⁺ − u⁻) = Jᵀ p`; for two bodies `p` on the first and `−p` on the second).
//!
//! **The contract for `ΔT`.** [`Impact::energy_change`] is the change of the kinetic energy of
//! the *whole* system — every body, every coordinate — between the velocities before and
//! after, and it equals the `energy_change` of the law's outcome, `ΔT = v⁻·p + ½ pᵀ W p`,
//! to round-off, whatever the law and whatever the impulse (the identity of theory §1; the
//! tests check it for every implementor and every law). Outcomes that split `ΔT` further
//! (by body, translational and rotational: paper A §5) split this same number.
//!
//! ```
//! use impax::impact::Impact;
//! use impax::planar::bodies::{sphere, spin_state, BodyImpact, Side};
//! use impax::LawId;
//! // The seed's sphere (paper A: α = 30°, e = 0.7, f = 0.4).
//! let body = sphere(1.0, 1.0, Side::Below)?;
//! let state = spin_state(1.0, 30f64.to_radians(), 0.0, 1.0)?;
//! let impact = BodyImpact::on_fixed_surface(body, state);
//! let problem = impact.problem(0.4, 0.7)?;
//! let out = LawId::Energetic.resolve(&problem).unwrap();
//! let from_bodies = impact.energy_change(&out.impulse);
//! assert!((from_bodies - out.energy_change).abs() < 1e-15);
//! # Ok::<(), impax::Error>(())
//! ```

use crate::error::Result;
use crate::law::Problem;

/// A system struck at one contact (module docs: the contract for `ΔT`).
pub trait Impact {
    /// Its contact-space problem.
    type Problem: Problem;
    /// The impulse a law returns for that problem (on the first body, in contact space).
    type Impulse: ?Sized;
    /// The system's velocities (the bodies' states, or generalized velocities).
    type Velocities;

    /// The contact-space problem with friction `friction` and restitution `restitution`
    /// (validated: errors name their field).
    fn problem(&self, friction: f64, restitution: f64) -> Result<Self::Problem>;

    /// The velocities after the impulse `impulse` (on the first body; its opposite on a
    /// second free body).
    fn velocities_after(&self, impulse: &Self::Impulse) -> Self::Velocities;

    /// The kinetic energy of the whole system with the velocities `velocities`.
    fn kinetic_energy(&self, velocities: &Self::Velocities) -> f64;

    /// The kinetic energy of the whole system before the impact.
    fn kinetic_energy_before(&self) -> f64;

    /// `ΔT` of the impulse `impulse`, from the velocities: the kinetic energy after less the
    /// kinetic energy before (equal to the outcome's `energy_change` to round-off).
    fn energy_change(&self, impulse: &Self::Impulse) -> f64 {
        self.kinetic_energy(&self.velocities_after(impulse)) - self.kinetic_energy_before()
    }
}
