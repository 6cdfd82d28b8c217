//! Impacts of a spatial multibody at several contacts at once: the contact Jacobians stacked
//! contact-major, `J` (3K × nv), give the multi-contact problem `W = J M⁻¹ Jᵀ` (3K × 3K,
//! positive semidefinite), `v⁻ = J u⁻` (theory §6) for the laws of
//! [`crate::multi::spatial`]; the impulses map back to the speeds by
//! `u⁺ = u⁻ + M⁻¹ Jᵀ p`.

use super::impact::quadratic;
use super::jacobian::{check_contact_index, contact_jacobian};
use super::kinematics::gap;
use super::model::Model;
use super::workspace::Workspace;
use super::{crba, factor, solve};
use crate::error::{Error, Result};
use crate::law::LawId;
use crate::math::Vec3;
use crate::multi::spatial::{MultiProblem, MultiResolution};
use nalgebra::DMatrix;

/// The result of one law on a [`SpatialMechanismMultiImpact`].
#[derive(Debug, Clone)]
pub struct SpatialMechanismMultiOutcome {
    /// The contact-space result (or why the law does not apply).
    pub resolution: MultiResolution,
    /// The speeds after, `u⁺ = u⁻ + M⁻¹ Jᵀ p` (when the law applies).
    pub velocities_after: Option<Vec<f64>>,
    /// `T⁺ − T⁻ = ½ (u⁺ − u⁻)ᵀ M (u⁺ + u⁻)` (when the law applies).
    pub energy_change_from_velocities: Option<f64>,
}

/// Several contacts of a spatial multibody at one state, reduced to contact space together.
#[derive(Debug, Clone)]
pub struct SpatialMechanismMultiImpact<'a> {
    model: &'a Model,
    contacts: Vec<usize>,
    u: Vec<f64>,
    workspace: Workspace,
    jacobian: DMatrix<f64>,
    /// `J M⁻¹` (3K × nv).
    response: DMatrix<f64>,
    w: DMatrix<f64>,
    v: Vec<f64>,
    gaps: Vec<f64>,
}

impl<'a> SpatialMechanismMultiImpact<'a> {
    /// Reduce the contacts `contacts` (indices into [`Model::contacts`], in the order of the
    /// problem) at `(q, u)` to contact space.
    ///
    /// # Errors
    /// As [`Model::check_state`]; no contact, an unknown or repeated one; a singular mass
    /// matrix.
    pub fn new(model: &'a Model, q: &[f64], u: &[f64], contacts: &[usize]) -> Result<Self> {
        if contacts.is_empty() {
            return Err(Error::Invalid {
                field: "contacts".into(),
                reason: "at least one contact is needed".into(),
            });
        }
        for (i, &k) in contacts.iter().enumerate() {
            check_contact_index(model, k)?;
            if contacts[..i].contains(&k) {
                return Err(Error::Invalid {
                    field: "contacts".into(),
                    reason: format!("contact {k} ({}) is listed twice", model.contacts[k].name),
                });
            }
        }
        let mut ws = Workspace::new(model);
        ws.update(model, q)?;
        model.check_speeds(u)?;
        crba(model, &mut ws);
        factor(model, &mut ws)?;
        let (n, rows) = (model.nv(), 3 * contacts.len());
        let mut jacobian = DMatrix::zeros(rows, n);
        for (i, &k) in contacts.iter().enumerate() {
            let j = contact_jacobian(model, &ws, k)?;
            jacobian.view_mut((3 * i, 0), (3, n)).copy_from(&j);
        }
        let mut response = DMatrix::zeros(rows, n);
        let mut b = vec![0.0; n];
        for r in 0..rows {
            b.iter_mut()
                .enumerate()
                .for_each(|(i, x)| *x = jacobian[(r, i)]);
            solve(model, &ws, &mut b);
            b.iter()
                .enumerate()
                .for_each(|(i, x)| response[(r, i)] = *x);
        }
        let w = &jacobian * response.transpose();
        let w = (&w + w.transpose()) * 0.5;
        let v = (&jacobian * nalgebra::DVector::from_column_slice(u))
            .as_slice()
            .to_vec();
        let gaps = contacts.iter().map(|&k| gap(model, &ws.poses, k)).collect();
        Ok(SpatialMechanismMultiImpact {
            model,
            contacts: contacts.to_vec(),
            u: u.to_vec(),
            workspace: ws,
            jacobian,
            response,
            w,
            v,
            gaps,
        })
    }

    /// `W = J M⁻¹ Jᵀ` (3K × 3K, contact-major).
    pub fn inverse_inertia(&self) -> &DMatrix<f64> {
        &self.w
    }

    /// `v⁻ = J u⁻` (3K numbers, contact by contact `t1, t2, n`).
    pub fn contact_velocity(&self) -> &[f64] {
        &self.v
    }

    /// The stacked Jacobian `J` (3K × nv).
    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.jacobian
    }

    /// The mass matrix `M(q)`.
    pub fn mass_matrix(&self) -> &DMatrix<f64> {
        &self.workspace.mass
    }

    /// The contacts' gaps, in order.
    pub fn gaps(&self) -> &[f64] {
        &self.gaps
    }

    /// The contacts' indices, in order.
    pub fn contacts(&self) -> &[usize] {
        &self.contacts
    }

    /// The model.
    pub fn model(&self) -> &Model {
        self.model
    }

    /// Kinetic energy before impact, `½ u⁻ᵀ M u⁻`.
    pub fn energy_before(&self) -> f64 {
        0.5 * quadratic(&self.workspace.mass, &self.u, &self.u)
    }

    /// The multi-contact problem with each contact's `μ_j`, `e_j` (one value for all, or
    /// one per contact).
    ///
    /// # Errors
    /// As [`MultiProblem::new`], e.g. when no contact approaches.
    pub fn problem(&self, friction: &[f64], restitution: &[f64]) -> Result<MultiProblem> {
        MultiProblem::new(self.w.clone(), &self.v, friction, restitution)
    }

    /// Speeds after the impulses `p` (one per contact): `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
    pub fn velocities_after(&self, p: &[Vec3]) -> Vec<f64> {
        let mut out = self.u.clone();
        for (c, pc) in p.iter().enumerate() {
            for (a, x) in pc.iter().enumerate() {
                let row = self.response.row(3 * c + a);
                out.iter_mut()
                    .zip(row.iter())
                    .for_each(|(o, r)| *o += r * x);
            }
        }
        out
    }

    /// Resolve the impact with one law ([`crate::multi::spatial::resolve`]).
    ///
    /// # Errors
    /// As [`SpatialMechanismMultiImpact::problem`], and a law that does not take this many
    /// contacts.
    pub fn resolve(
        &self,
        law: LawId,
        friction: &[f64],
        restitution: &[f64],
    ) -> Result<SpatialMechanismMultiOutcome> {
        let problem = self.problem(friction, restitution)?;
        let resolution = crate::multi::spatial::resolve(law, &problem)?;
        let (velocities_after, energy_change_from_velocities) = match &resolution {
            Ok(outcome) => {
                let after = self.velocities_after(&outcome.impulses());
                let sum: Vec<f64> = after.iter().zip(&self.u).map(|(a, b)| a + b).collect();
                let diff: Vec<f64> = after.iter().zip(&self.u).map(|(a, b)| a - b).collect();
                let de = 0.5 * quadratic(&self.workspace.mass, &diff, &sum);
                (Some(after), Some(de))
            }
            Err(_) => (None, None),
        };
        Ok(SpatialMechanismMultiOutcome {
            resolution,
            velocities_after,
            energy_change_from_velocities,
        })
    }
}
