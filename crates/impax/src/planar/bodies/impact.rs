//! A planar impact of one body on a fixed surface, or of two free bodies.

use super::rigid::{sum_or_zero, BodyState, RigidBody};
use crate::error::Result;
use crate::law::{ImpactLaw, LawId};
use crate::math::Vec2;
use crate::planar::laws::Smith;
use crate::planar::{ContactProblem, Outcome, Resolution};

/// Kinetic energy split into translational `Σ ½ m |v|²` and rotational `Σ ½ I ω²` parts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnergyParts {
    /// Translational part.
    pub translational: f64,
    /// Rotational part.
    pub rotational: f64,
}

impl EnergyParts {
    /// Sum of both parts.
    pub fn total(&self) -> f64 {
        self.translational + self.rotational
    }
}

/// The result of a law applied to a [`BodyImpact`]: the contact-space outcome and what it
/// does to the bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BodyOutcome {
    /// The contact-space outcome.
    pub outcome: Outcome,
    /// Body A after the impact.
    pub body_after: BodyState,
    /// Body B after the impact (when there is one).
    pub other_after: Option<BodyState>,
    /// Change of kinetic energy split as in paper A §5: `ΔT = ΔT₁ + ΔT₂`.
    pub energy_change: EnergyParts,
}

/// Body A striking a fixed surface, or body B (two free bodies: `W = W_A + W_B`, the
/// relative contact velocity `v = v_A − v_B`, impulse `p` on A and `−p` on B).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyImpact {
    /// The striking body and its state.
    pub body: (RigidBody, BodyState),
    /// The struck body and its state, if it is free (else the surface is fixed).
    pub other: Option<(RigidBody, BodyState)>,
}

impl BodyImpact {
    /// One body against a fixed surface.
    pub fn on_fixed_surface(body: RigidBody, state: BodyState) -> Self {
        Self {
            body: (body, state),
            other: None,
        }
    }

    /// Two free bodies: `body` (A) strikes `other` (B), whose contact point is its own.
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
    pub fn inverse_inertia(&self) -> crate::math::Mat2 {
        let mut w = self.body.0.inverse_inertia();
        if let Some((b, _)) = &self.other {
            w += b.inverse_inertia();
        }
        w
    }

    /// Relative contact velocity `v_A − v_B` at the contact point (a difference below its
    /// rounding error is exactly zero, see [`RigidBody::contact_velocity`]).
    pub fn contact_velocity(&self) -> Vec2 {
        let v = self.body.0.contact_velocity(&self.body.1);
        match &self.other {
            None => v,
            Some((b, s)) => {
                let w = b.contact_velocity(s);
                Vec2::new(sum_or_zero(v.x, -w.x), sum_or_zero(v.y, -w.y))
            }
        }
    }

    /// The contact-space problem with friction `μ` and restitution `e` (validated).
    pub fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        ContactProblem::new(
            self.inverse_inertia(),
            self.contact_velocity(),
            friction,
            restitution,
        )
    }

    /// Kinetic energy of the bodies before the impact, split.
    pub fn energy_before(&self) -> EnergyParts {
        self.energy_of(&self.body.1, self.other.as_ref().map(|o| &o.1))
    }

    fn energy_of(&self, a: &BodyState, b: Option<&BodyState>) -> EnergyParts {
        let mut e = EnergyParts {
            translational: self.body.0.translational_energy(a),
            rotational: self.body.0.rotational_energy(a),
        };
        if let (Some((body, _)), Some(s)) = (&self.other, b) {
            e.translational += body.translational_energy(s);
            e.rotational += body.rotational_energy(s);
        }
        e
    }

    /// States after the impulse `p` on A (and `−p` on B).
    pub fn apply(&self, p: Vec2) -> (BodyState, Option<BodyState>) {
        let a = self.body.0.apply(&self.body.1, p);
        let b = self.other.map(|(body, s)| body.apply(&s, -p));
        (a, b)
    }

    /// The reference of Smith's literal reading (paper A eq. 24): the tangential centre
    /// velocity of A relative to B and its change per unit impulse, `(1/m_A + 1/m_B, 0)`.
    pub fn centre_reference(&self) -> (f64, Vec2) {
        let mut u = self.body.1.velocity.x;
        let mut g = 1.0 / self.body.0.mass();
        if let Some((b, s)) = &self.other {
            u -= s.velocity.x;
            g += 1.0 / b.mass();
        }
        (u, Vec2::new(g, 0.0))
    }

    /// Apply a law: the contact-space resolution mapped back to the bodies.
    ///
    /// `smith-centre` uses [`Self::centre_reference`]; every other law sees only the problem.
    pub fn resolve(
        &self,
        law: LawId,
        problem: &ContactProblem,
    ) -> std::result::Result<BodyOutcome, crate::planar::Breakdown> {
        let res: Resolution = match law {
            LawId::SmithCentre => {
                let (u, g) = self.centre_reference();
                Smith::centre(u, g).resolve(problem)
            }
            other => other.resolve(problem),
        };
        let outcome = res?;
        let (body_after, other_after) = self.apply(outcome.impulse);
        let before = self.energy_before();
        let after = self.energy_of(&body_after, other_after.as_ref());
        Ok(BodyOutcome {
            outcome,
            body_after,
            other_after,
            energy_change: EnergyParts {
                translational: after.translational - before.translational,
                rotational: after.rotational - before.rotational,
            },
        })
    }
}

impl crate::impact::Impact for BodyImpact {
    type Problem = ContactProblem;
    type Impulse = Vec2;
    type Velocities = (BodyState, Option<BodyState>);

    fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        BodyImpact::problem(self, friction, restitution)
    }

    fn velocities_after(&self, impulse: &Vec2) -> (BodyState, Option<BodyState>) {
        self.apply(*impulse)
    }

    fn kinetic_energy(&self, (a, b): &(BodyState, Option<BodyState>)) -> f64 {
        self.energy_of(a, b.as_ref()).total()
    }

    fn kinetic_energy_before(&self) -> f64 {
        self.energy_before().total()
    }
}
