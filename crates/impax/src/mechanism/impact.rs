//! Impacts of mechanisms: a mechanism, its state and one contact give the contact-space
//! problem `W = J M⁻¹ Jᵀ`, `v⁻ = J u⁻`; any law's impulse `p` maps back to generalized
//! velocities by the momentum balance `M (u⁺ − u⁻) = Jᵀ p` (theory.md §1, §4).

use super::dynamics::{self, check_state, Kinematics};
use super::Mechanism;
use crate::error::{Error, Result};
use crate::law::LawId;
use crate::math::{Mat2, Vec2};
use crate::planar::{ContactProblem, Resolution};
use nalgebra::{Cholesky, DMatrix, DVector, Dyn};

/// One contact of a mechanism at one state, reduced to contact space.
pub struct MechanismImpact<'a, M: Mechanism + ?Sized> {
    mechanism: &'a M,
    contact: usize,
    q: Vec<f64>,
    u: DVector<f64>,
    mass: DMatrix<f64>,
    chol: Cholesky<f64, Dyn>,
    jacobian: DMatrix<f64>,
    w: Mat2,
    v: Vec2,
    gap: f64,
    kinematics: Kinematics,
}

/// The result of one law on a mechanism impact.
#[derive(Debug, Clone)]
pub struct MechanismOutcome {
    /// The contact-space result (or why the law does not apply).
    pub resolution: Resolution,
    /// Generalized velocities after the impact, `u⁺ = u⁻ + M⁻¹ Jᵀ p` (when the law applies).
    pub velocities_after: Option<Vec<f64>>,
    /// `T⁺ − T⁻` from the generalized velocities, `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻` (when the law
    /// applies); equals the contact-space `v⁻·p + ½ pᵀ W p` up to round-off.
    pub energy_change_from_velocities: Option<f64>,
}

impl<'a, M: Mechanism + ?Sized> MechanismImpact<'a, M> {
    /// Reduce contact `contact` of `mechanism` at `(q, u)` to contact space.
    ///
    /// The configuration need not have a zero gap (the impact is instantaneous and only the
    /// local geometry matters); [`MechanismImpact::gap`] reports it.
    ///
    /// # Errors
    /// Wrong lengths or non-finite `q`, `u`; no such contact; a singular mass matrix; a
    /// contact that no coordinate can move (singular `W`).
    pub fn new(mechanism: &'a M, q: &[f64], u: &[f64], contact: usize) -> Result<Self> {
        check_state(mechanism, q, Some(u))?;
        if contact >= mechanism.contacts().len() {
            return Err(Error::Invalid {
                field: "contact".into(),
                reason: if mechanism.contacts().is_empty() {
                    "this mechanism has no contact point".into()
                } else {
                    format!(
                        "index {contact} out of range: the mechanism has {} contact(s)",
                        mechanism.contacts().len()
                    )
                },
            });
        }
        dynamics::check_precision(mechanism, q)?;
        let kinematics = dynamics::kinematics(mechanism, q);
        let mass = dynamics::mass_matrix_of(mechanism, &kinematics);
        let chol = dynamics::cholesky(mass.clone())?;
        let jacobian = dynamics::contact_jacobian_of(mechanism, contact, q, &kinematics);
        let minv_jt = chol.solve(&jacobian.transpose());
        let w_dyn = &jacobian * &minv_jt;
        // Symmetrise the round-off of J M⁻¹ Jᵀ.
        let wtn = 0.5 * (w_dyn[(0, 1)] + w_dyn[(1, 0)]);
        let w = Mat2::new(w_dyn[(0, 0)], wtn, wtn, w_dyn[(1, 1)]);
        let u = DVector::from_column_slice(u);
        let energy = 0.5 * u.dot(&(&mass * &u));
        crate::error::kinetic_energy(energy, u.amax())?;
        let vd = &jacobian * &u;
        Ok(MechanismImpact {
            mechanism,
            contact,
            q: q.to_vec(),
            gap: dynamics::gap(mechanism, contact, q),
            u,
            mass,
            chol,
            jacobian,
            w,
            v: Vec2::new(vd[0], vd[1]),
            kinematics,
        })
    }

    /// The impact of the contact that strikes at `(q, u)`: the one nearest its surface, with
    /// the smallest `|gap|` (the first of equals). A mechanism with several contact
    /// candidates (a rod's two ends, a double pendulum's tip and elbow) strikes with one of
    /// them at a time.
    ///
    /// # Errors
    /// As [`MechanismImpact::new`]; and, naming `q`, another contact below its surface (the
    /// state cannot be reached), or another contact touching at once (its gap within
    /// [`dynamics::touching_tolerance`] of the striking one's): an impact at several contacts
    /// at once is not a one-contact problem.
    pub fn striking(mechanism: &'a M, q: &[f64], u: &[f64]) -> Result<Self> {
        check_state(mechanism, q, Some(u))?;
        let contacts = mechanism.contacts();
        let gaps: Vec<f64> = (0..contacts.len())
            .map(|k| dynamics::gap(mechanism, k, q))
            .collect();
        let Some(k) = (0..gaps.len()).min_by(|&i, &j| gaps[i].abs().total_cmp(&gaps[j].abs()))
        else {
            return Self::new(mechanism, q, u, 0); // no contact: the error of `new`
        };
        let tol_k = dynamics::touching_tolerance(mechanism, k, q);
        for j in (0..gaps.len()).filter(|&j| j != k) {
            let tol_j = dynamics::touching_tolerance(mechanism, j, q);
            if gaps[j] < -tol_j {
                return Err(Error::Invalid {
                    field: "q".into(),
                    reason: format!(
                        "the {} is below its surface (gap {}) while the {} strikes",
                        contacts[j].name,
                        crate::error::Num(gaps[j]),
                        contacts[k].name
                    ),
                });
            }
            if (gaps[j] - gaps[k]).abs() <= tol_j + tol_k {
                return Err(Error::Invalid {
                    field: "q".into(),
                    reason: format!(
                        "the {} and the {} strike at once (gaps {} and {}): an impact at several \
                         contacts at once is not supported yet",
                        contacts[k].name,
                        contacts[j].name,
                        crate::error::Num(gaps[k]),
                        crate::error::Num(gaps[j])
                    ),
                });
            }
        }
        Self::new(mechanism, q, u, k)
    }

    /// The impact of the contact named `contact` (a name of [`Mechanism::contacts`]), or
    /// with `None` of the contact that strikes ([`MechanismImpact::striking`]).
    ///
    /// ```
    /// use impax::mechanism::builtin::DoublePendulum;
    /// use impax::mechanism::impact::MechanismImpact;
    /// let dp = DoublePendulum::unit_at([0.5, 0.0]);
    /// let (q, u) = ([0.5, 0.0], [-1.0, 2.0]);
    /// let tip = MechanismImpact::named(&dp, &q, &u, Some("tip of rod 2"))?;
    /// let striking = MechanismImpact::named(&dp, &q, &u, None)?; // the contact on the floor
    /// assert_eq!((tip.contact(), striking.contact()), (0, 0));
    /// let err = MechanismImpact::named(&dp, &q, &u, Some("knee")).err().unwrap();
    /// assert_eq!(err.field(), "contact");
    /// # Ok::<(), impax::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`MechanismImpact::new`] and [`MechanismImpact::striking`]; a name that is not one
    /// of the mechanism's contacts (the error lists them).
    pub fn named(mechanism: &'a M, q: &[f64], u: &[f64], contact: Option<&str>) -> Result<Self> {
        let Some(name) = contact else {
            return Self::striking(mechanism, q, u);
        };
        let contacts = mechanism.contacts();
        match contacts.iter().position(|c| c.name == name) {
            Some(k) => Self::new(mechanism, q, u, k),
            None => Err(Error::Invalid {
                field: "contact".into(),
                reason: format!(
                    "`{name}` is not a contact of the mechanism (its contacts: {})",
                    contacts
                        .iter()
                        .map(|c| c.name)
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            }),
        }
    }

    /// The contact-space inverse inertia `W = J M⁻¹ Jᵀ`.
    pub fn inverse_inertia(&self) -> Mat2 {
        self.w
    }

    /// The contact velocity before impact, `v⁻ = J u⁻` (tangent, normal).
    pub fn contact_velocity(&self) -> Vec2 {
        self.v
    }

    /// The contact Jacobian `J` (2 × n, rows tangent then normal).
    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.jacobian
    }

    /// The mass matrix `M(q)`.
    pub fn mass_matrix(&self) -> &DMatrix<f64> {
        &self.mass
    }

    /// The gap `φ(q)` of the contact at this configuration.
    pub fn gap(&self) -> f64 {
        self.gap
    }

    /// The kinematics (poses, body Jacobians) at this configuration.
    pub fn kinematics(&self) -> &Kinematics {
        &self.kinematics
    }

    /// The contact index.
    pub fn contact(&self) -> usize {
        self.contact
    }

    /// The configuration `q`.
    pub fn configuration(&self) -> &[f64] {
        &self.q
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &M {
        self.mechanism
    }

    /// Kinetic energy before impact, `½ u⁻ᵀ M u⁻`.
    pub fn energy_before(&self) -> f64 {
        0.5 * self.u.dot(&(&self.mass * &self.u))
    }

    /// The contact-space problem with coefficients `μ`, `e`.
    ///
    /// # Errors
    /// As [`ContactProblem::new`], e.g. when the contact is not approaching.
    pub fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        ContactProblem::new(self.w, self.v, friction, restitution)
    }

    /// Generalized velocities after an impulse `p` (tangent, normal) on the contact:
    /// `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
    pub fn velocities_after(&self, p: Vec2) -> Vec<f64> {
        let jt_p = self.jacobian.transpose() * nalgebra::DVector::from_column_slice(&[p.x, p.y]);
        (&self.u + self.chol.solve(&jt_p)).as_slice().to_vec()
    }

    /// Kinetic energy `½ uᵀ M u` at these generalized velocities.
    pub fn kinetic_energy(&self, u: &[f64]) -> f64 {
        let u = DVector::from_column_slice(u);
        0.5 * u.dot(&(&self.mass * &u))
    }

    /// Resolve the impact with one law.
    ///
    /// # Errors
    /// As [`MechanismImpact::problem`].
    pub fn resolve(&self, law: LawId, friction: f64, restitution: f64) -> Result<MechanismOutcome> {
        let problem = self.problem(friction, restitution)?;
        let resolution = law.resolve(&problem);
        let (velocities_after, energy_change_from_velocities) = match &resolution {
            Ok(outcome) => {
                let after = self.velocities_after(outcome.impulse);
                let de = self.kinetic_energy(&after) - self.energy_before();
                (Some(after), Some(de))
            }
            Err(_) => (None, None),
        };
        Ok(MechanismOutcome {
            resolution,
            velocities_after,
            energy_change_from_velocities,
        })
    }
}

impl<M: Mechanism + ?Sized> crate::impact::Impact for MechanismImpact<'_, M> {
    type Problem = ContactProblem;
    type Impulse = Vec2;
    type Velocities = Vec<f64>;

    fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem> {
        MechanismImpact::problem(self, friction, restitution)
    }

    fn velocities_after(&self, p: &Vec2) -> Vec<f64> {
        MechanismImpact::velocities_after(self, *p)
    }

    fn kinetic_energy(&self, u: &Vec<f64>) -> f64 {
        MechanismImpact::kinetic_energy(self, u)
    }

    fn kinetic_energy_before(&self) -> f64 {
        self.energy_before()
    }
}
