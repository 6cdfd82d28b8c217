//! One body on a fixed plane, or two free bodies, in 3D.

use super::rigid::{BodyState, EnergyParts, RigidBody};
use crate::error::Result;
use crate::law::Breakdown;
use crate::law::LawId;
use crate::math::{Mat3, Vec3};
use crate::spatial::{ContactProblem, Outcome};

/// A law applied to a [`BodyImpact`]: the contact-space outcome and the bodies after.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BodyOutcome {
    /// Contact-space outcome.
    pub outcome: Outcome,
    /// Body A after.
    pub body_after: BodyState,
    /// Body B after, when there is one.
    pub other_after: Option<BodyState>,
    /// Change of kinetic energy of body A, split.
    pub body_energy_change: EnergyParts,
    /// Change of kinetic energy of body B, split (zero without B).
    pub other_energy_change: EnergyParts,
}

/// Body A striking a fixed plane (`z` up) or body B (impulse `p` on A, `−p` on B).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyImpact {
    /// The striking body and its state.
    pub body: (RigidBody, BodyState),
    /// The struck body and its state, if free.
    pub other: Option<(RigidBody, BodyState)>,
}

impl BodyImpact {
    /// One body against a fixed plane.
    pub fn on_fixed_surface(body: RigidBody, state: BodyState) -> Self {
        Self {
            body: (body, state),
            other: None,
        }
    }

    /// Two free bodies.
    pub fn between(
        body: RigidBody,
        state: BodyState,
        other: RigidBody,
        other_state: BodyState,
    ) -> Self {
        Self {
            body: (body, state),
            other: Some((other, other_state)),
        }
    }

    /// `W = W_A (+ W_B)`.
    pub fn inverse_inertia(&self) -> Mat3 {
        let mut w = self.body.0.inverse_inertia();
        if let Some((b, _)) = &self.other {
            w += b.inverse_inertia();
        }
        w
    }

    /// Relative contact velocity `v_A − v_B`; a component below its own rounding error
    /// is exactly zero (as in the planar bodies).
    pub fn contact_velocity(&self) -> Vec3 {
        let va = self.body.0.contact_velocity(&self.body.1);
        let vb = self
            .other
            .map_or(Vec3::zeros(), |(b, s)| b.contact_velocity(&s));
        let raw_scale = self.body.1.velocity.abs()
            + (self.body.1.omega.cross(&self.body.0.contact())).abs()
            + self.other.map_or(Vec3::zeros(), |(b, s)| {
                s.velocity.abs() + s.omega.cross(&b.contact()).abs()
            });
        let v = va - vb;
        Vec3::from_fn(|i, _| {
            if v[i].abs() <= 8.0 * f64::EPSILON * raw_scale[i] {
                0.0
            } else {
                v[i]
            }
        })
    }

    /// The spatial contact problem (validated).
    pub fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        ContactProblem::new(
            self.inverse_inertia(),
            self.contact_velocity(),
            friction,
            restitution,
        )
    }

    /// Kinetic energy before: body A, body B.
    pub fn energy_before(&self) -> (EnergyParts, EnergyParts) {
        (
            self.body.0.energy(&self.body.1),
            self.other
                .map_or(EnergyParts::default(), |(b, s)| b.energy(&s)),
        )
    }

    /// Apply a law and map the impulse back to the bodies.
    pub fn resolve(
        &self,
        law: LawId,
        problem: &ContactProblem,
    ) -> std::result::Result<BodyOutcome, Breakdown> {
        let outcome = law.resolve(problem)?;
        let p = outcome.impulse;
        let a = self.body.0.apply(&self.body.1, p);
        let b = self.other.map(|(body, s)| body.apply(&s, -p));
        let (ea0, eb0) = self.energy_before();
        let ea1 = self.body.0.energy(&a);
        let eb1 = match (&self.other, &b) {
            (Some((body, _)), Some(s)) => body.energy(s),
            _ => EnergyParts::default(),
        };
        let diff = |x: EnergyParts, y: EnergyParts| EnergyParts {
            translational: x.translational - y.translational,
            rotational: x.rotational - y.rotational,
        };
        Ok(BodyOutcome {
            outcome,
            body_after: a,
            other_after: b,
            body_energy_change: diff(ea1, ea0),
            other_energy_change: diff(eb1, eb0),
        })
    }
}

impl crate::impact::Impact for BodyImpact {
    type Problem = ContactProblem;
    type Impulse = Vec3;
    type Velocities = (BodyState, Option<BodyState>);

    fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        BodyImpact::problem(self, friction, restitution)
    }

    fn velocities_after(&self, p: &Vec3) -> (BodyState, Option<BodyState>) {
        let a = self.body.0.apply(&self.body.1, *p);
        let b = self.other.map(|(body, s)| body.apply(&s, -*p));
        (a, b)
    }

    fn kinetic_energy(&self, (a, b): &(BodyState, Option<BodyState>)) -> f64 {
        let eb = match (&self.other, b) {
            (Some((body, _)), Some(s)) => body.energy(s).total(),
            _ => 0.0,
        };
        self.body.0.energy(a).total() + eb
    }

    fn kinetic_energy_before(&self) -> f64 {
        let (a, b) = self.energy_before();
        a.total() + b.total()
    }
}
