//! Impacts of a spatial multibody at one contact with the floor: the model, its state and a
//! contact give the contact-space problem `W = J M⁻¹ Jᵀ`, `v⁻ = J u⁻` (theory §1, §7); any
//! spatial law's impulse `p` maps back to the speeds by the momentum balance
//! `M (u⁺ − u⁻) = Jᵀ p`, `u⁺ = u⁻ + M⁻¹ Jᵀ p` — the spatial twin of
//! [`crate::mechanism::impact::MechanismImpact`].

use super::jacobian::{check_contact_index, contact_space, ContactSpace};
use super::kinematics::gap;
use super::model::Model;
use super::workspace::Workspace;
use crate::error::Result;
use crate::law::LawId;
use crate::math::{Mat3, Vec3};
use crate::spatial::{ContactProblem, Resolution};
use nalgebra::{DMatrix, Matrix3xX};

/// The result of one law on a [`SpatialMechanismImpact`].
#[derive(Debug, Clone)]
pub struct SpatialMechanismOutcome {
    /// The contact-space result (or why the law does not apply).
    pub resolution: Resolution,
    /// The speeds after the impact, `u⁺ = u⁻ + M⁻¹ Jᵀ p` (when the law applies).
    pub velocities_after: Option<Vec<f64>>,
    /// `T⁺ − T⁻` from the speeds, `½ (u⁺ − u⁻)ᵀ M (u⁺ + u⁻)` (when the law applies; the
    /// difference of `½ uᵀ M u` before and after, without its cancellation); equals the
    /// contact-space `v⁻·p + ½ pᵀ W p` up to round-off.
    pub energy_change_from_velocities: Option<f64>,
}

/// One contact of a spatial multibody at one state, reduced to contact space.
///
/// ```
/// use impax::multibody::{Body, ContactPoint, Joint, Model, SpatialMechanismImpact};
/// use impax::math::{Mat3, Vec3};
/// use impax::LawId;
/// // A free sphere (m = 1, I = 2/5) falling on its bottom point: W = diag(7/2, 7/2, 1).
/// let ball = Body::new("ball", 1.0, Vec3::zeros(), Mat3::identity() * 0.4);
/// let foot = ContactPoint::new("bottom", 0, Vec3::zeros(), 1.0);
/// let model = Model::new(vec![ball], vec![Joint::free("root", 0)], vec![foot])?;
/// let q = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0];
/// let impact = SpatialMechanismImpact::new(&model, &q, &[0.5, 0.0, -1.0, 0.0, 0.0, 0.0], 0)?;
/// let w = impact.inverse_inertia();
/// assert!((w[(0, 0)] - 3.5).abs() < 1e-14 && (w[(2, 2)] - 1.0).abs() < 1e-14);
/// assert_eq!(impact.gap(), 0.0);
/// let out = impact.resolve(LawId::Energetic, 0.4, 0.5)?;
/// let u = out.velocities_after.unwrap();
/// assert!((u[2] - 0.5).abs() < 1e-12); // bounces up at e |v_n⁻|
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct SpatialMechanismImpact<'a> {
    model: &'a Model,
    contact: usize,
    u: Vec<f64>,
    workspace: Workspace,
    space: ContactSpace,
    gap: f64,
    energy: f64,
}

impl<'a> SpatialMechanismImpact<'a> {
    /// Reduce contact `contact` of `model` at `(q, u)` to contact space.
    ///
    /// The configuration need not have a zero gap (the impact is instantaneous and only the
    /// local geometry matters); [`SpatialMechanismImpact::gap`] reports it.
    ///
    /// # Errors
    /// As [`Model::check_state`]; no such contact; a singular mass matrix (naming the
    /// coordinate that moves no mass); a kinetic energy beyond `1e300`.
    pub fn new(model: &'a Model, q: &[f64], u: &[f64], contact: usize) -> Result<Self> {
        Self::new_in(model, q, u, contact, Workspace::new(model))
    }

    /// As [`SpatialMechanismImpact::new`], reusing `workspace` (taken; get it back with
    /// [`SpatialMechanismImpact::into_workspace`]).
    pub fn new_in(
        model: &'a Model,
        q: &[f64],
        u: &[f64],
        contact: usize,
        mut workspace: Workspace,
    ) -> Result<Self> {
        check_contact_index(model, contact)?;
        workspace.update(model, q)?;
        let space = contact_space(model, &mut workspace, contact, u)?;
        let energy = 0.5 * quadratic(&workspace.mass, u, u);
        crate::error::kinetic_energy(energy, u.iter().fold(0.0, |m, x| m.max(x.abs())))?;
        Ok(SpatialMechanismImpact {
            model,
            contact,
            u: u.to_vec(),
            gap: gap(model, &workspace.poses, contact),
            workspace,
            space,
            energy,
        })
    }

    /// The workspace, to reuse for another impact.
    pub fn into_workspace(self) -> Workspace {
        self.workspace
    }

    /// The contact-space inverse inertia `W = J M⁻¹ Jᵀ` (rows and columns `t1 = x`,
    /// `t2 = y`, `n = z`).
    pub fn inverse_inertia(&self) -> Mat3 {
        self.space.w
    }

    /// The contact velocity before impact, `v⁻ = J u⁻`.
    pub fn contact_velocity(&self) -> Vec3 {
        self.space.velocity
    }

    /// The contact Jacobian `J` (3 × nv).
    pub fn jacobian(&self) -> &Matrix3xX<f64> {
        &self.space.jacobian
    }

    /// The mass matrix `M(q)`.
    pub fn mass_matrix(&self) -> &DMatrix<f64> {
        &self.workspace.mass
    }

    /// The gap `φ(q)` of the contact at this configuration.
    pub fn gap(&self) -> f64 {
        self.gap
    }

    /// The contact index.
    pub fn contact(&self) -> usize {
        self.contact
    }

    /// The configuration `q` (quaternions normalised).
    pub fn configuration(&self) -> &[f64] {
        &self.workspace.q
    }

    /// The speeds before impact `u⁻`.
    pub fn velocities_before(&self) -> &[f64] {
        &self.u
    }

    /// The model.
    pub fn model(&self) -> &Model {
        self.model
    }

    /// Kinetic energy before impact, `½ u⁻ᵀ M u⁻`.
    pub fn energy_before(&self) -> f64 {
        self.energy
    }

    /// The contact-space problem with coefficients `μ`, `e`.
    ///
    /// # Errors
    /// As [`ContactProblem::new`], e.g. when the contact is not approaching, or `W` is
    /// singular (a contact that the coordinates cannot move in every direction).
    pub fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        ContactProblem::new(self.space.w, self.space.velocity, friction, restitution)
    }

    /// Speeds after an impulse `p` (`t1, t2, n`) on the contact: `u⁺ = u⁻ + M⁻¹ Jᵀ p`, into
    /// `out` (`nv` entries).
    pub fn velocities_after_into(&self, p: Vec3, out: &mut [f64]) {
        let r = &self.space.response;
        for (i, (o, u)) in out.iter_mut().zip(&self.u).enumerate() {
            *o = u + r[(0, i)] * p.x + r[(1, i)] * p.y + r[(2, i)] * p.z;
        }
    }

    /// Speeds after an impulse `p` on the contact: `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
    pub fn velocities_after(&self, p: Vec3) -> Vec<f64> {
        let mut out = vec![0.0; self.u.len()];
        self.velocities_after_into(p, &mut out);
        out
    }

    /// Kinetic energy `½ uᵀ M u` at these speeds.
    pub fn kinetic_energy(&self, u: &[f64]) -> f64 {
        0.5 * quadratic(&self.workspace.mass, u, u)
    }

    /// `T(u⁺) − T(u⁻) = ½ (u⁺ − u⁻)ᵀ M (u⁺ + u⁻)`.
    pub fn energy_change_to(&self, after: &[f64]) -> f64 {
        let diff: Vec<f64> = after.iter().zip(&self.u).map(|(a, b)| a - b).collect();
        let sum: Vec<f64> = after.iter().zip(&self.u).map(|(a, b)| a + b).collect();
        0.5 * quadratic(&self.workspace.mass, &diff, &sum)
    }

    /// Resolve the impact with one law ([`LawId::resolve`]).
    ///
    /// # Errors
    /// As [`SpatialMechanismImpact::problem`].
    pub fn resolve(
        &self,
        law: LawId,
        friction: f64,
        restitution: f64,
    ) -> Result<SpatialMechanismOutcome> {
        let problem = self.problem(friction, restitution)?;
        let resolution = law.resolve(&problem);
        let (velocities_after, energy_change_from_velocities) = match &resolution {
            Ok(outcome) => {
                let after = self.velocities_after(outcome.impulse);
                let de = self.energy_change_to(&after);
                (Some(after), Some(de))
            }
            Err(_) => (None, None),
        };
        Ok(SpatialMechanismOutcome {
            resolution,
            velocities_after,
            energy_change_from_velocities,
        })
    }
}

/// `aᵀ M b`.
pub(crate) fn quadratic(m: &DMatrix<f64>, a: &[f64], b: &[f64]) -> f64 {
    let n = a.len();
    (0..n)
        .map(|i| a[i] * (0..n).map(|k| m[(i, k)] * b[k]).sum::<f64>())
        .sum()
}

impl crate::impact::Impact for SpatialMechanismImpact<'_> {
    type Problem = ContactProblem;
    type Impulse = Vec3;
    type Velocities = Vec<f64>;

    fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        SpatialMechanismImpact::problem(self, friction, restitution)
    }

    fn velocities_after(&self, p: &Vec3) -> Vec<f64> {
        SpatialMechanismImpact::velocities_after(self, *p)
    }

    fn kinetic_energy(&self, u: &Vec<f64>) -> f64 {
        SpatialMechanismImpact::kinetic_energy(self, u)
    }

    fn kinetic_energy_before(&self) -> f64 {
        self.energy_before()
    }

    /// `½ Δuᵀ M (u⁺ + u⁻)` ([`SpatialMechanismImpact::energy_change_to`]: no cancellation).
    fn energy_change(&self, p: &Vec3) -> f64 {
        SpatialMechanismImpact::energy_change_to(
            self,
            &SpatialMechanismImpact::velocities_after(self, *p),
        )
    }
}
