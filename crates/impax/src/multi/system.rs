//! A rigid system struck at several contacts at once: generalized velocities, mass matrix and
//! the contacts' rows, reduced to the contact-space problem of [`crate::multi`] and mapped back.
//!
//! With `n` generalized velocities `u`, the symmetric positive definite mass matrix `M` and
//! `K` contacts whose velocities are `v_j = J_j u` (`J_j`: 2 × n, the tangent row then the
//! normal row), the impulses `p_j` on the system act through `Jᵀ` (theory §1, §4, §6):
//!
//! ```text
//! M (u⁺ − u⁻) = Σ_j J_jᵀ p_j,     W = J M⁻¹ Jᵀ (2K × 2K),   v⁻ = J u⁻,
//! T⁺ − T⁻ = ½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻ = v⁻·p + ½ pᵀ W p.
//! ```
//!
//! The rows of a contact between two bodies give the relative velocity of the second body's
//! point with respect to the first's (so `p_j` is the impulse on the second body, `−p_j` on the
//! first); a contact with a fixed surface gives the body point's velocity. A spatial system
//! ([`MultiImpact::spatial`]) has three rows per contact (the two tangents, then the normal)
//! and reduces to [`spatial::MultiProblem`](super::spatial::MultiProblem). Dependent rows (a
//! rod lying flat: four rows, three degrees of freedom) make `W` singular, which
//! [`MultiProblem`] accepts: the velocities after are then unique although the impulses are
//! not, and `u⁺` is computed from whichever impulses the law reports (`J u⁺` does not depend
//! on the choice; nor does `u⁺` itself, since `Jᵀ z = 0` whenever `W z = 0`).

use super::{spatial, MultiProblem, MultiResolution};
use crate::error::{Error, Result};
use crate::law::{self, LawId, Options};
use crate::mechanism::{dynamics, Mechanism};
use nalgebra::{Cholesky, DMatrix, DVector, Dyn, SVector};

/// A system at the instant of an impact at `K` contacts (module docs).
#[derive(Debug, Clone)]
pub struct MultiImpact {
    /// Rows per contact: 2 (planar) or 3 (spatial).
    dim: usize,
    coordinates: Vec<String>,
    contacts: Vec<String>,
    mass: DMatrix<f64>,
    chol: Cholesky<f64, Dyn>,
    jacobian: DMatrix<f64>,
    u: DVector<f64>,
}

/// The result of one law on a [`MultiImpact`] (planar; `SystemOutcome<spatial::MultiResolution>`
/// for a spatial system).
#[derive(Debug, Clone)]
pub struct SystemOutcome<R = MultiResolution> {
    /// The contact-space result (or why the law does not apply).
    pub resolution: R,
    /// `u⁺ = u⁻ + M⁻¹ Jᵀ p` (when the law applies).
    pub velocities_after: Option<Vec<f64>>,
    /// `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻` (when the law applies): the contact-space `ΔT` up to
    /// round-off, an independent check of it.
    pub energy_change_from_velocities: Option<f64>,
}

impl MultiImpact {
    /// A system from its mass matrix `M` (`n × n`, symmetric positive definite), its contact
    /// rows `J` (`2K × n`, contact `j`'s tangent row `2j`, normal row `2j + 1`) and its
    /// velocities before `u⁻` (`n`), with the names of the coordinates and of the contacts.
    ///
    /// # Errors
    /// Naming the field: mismatched sizes (`jacobian`, `u`, `coordinates`, `contacts`),
    /// non-finite entries, `M` not symmetric positive definite (`mass`), a kinetic energy
    /// above `1e300` (`u`).
    pub fn new(
        coordinates: Vec<String>,
        mass: DMatrix<f64>,
        contacts: Vec<String>,
        jacobian: DMatrix<f64>,
        u: &[f64],
    ) -> Result<Self> {
        Self::with_rows(2, coordinates, mass, contacts, jacobian, u)
    }

    /// A spatial system: as [`MultiImpact::new`] with three rows per contact (`J`: `3K × n`,
    /// contact `j`'s tangent rows `3j`, `3j + 1` and its normal row `3j + 2`).
    ///
    /// # Errors
    /// As [`MultiImpact::new`].
    pub fn spatial(
        coordinates: Vec<String>,
        mass: DMatrix<f64>,
        contacts: Vec<String>,
        jacobian: DMatrix<f64>,
        u: &[f64],
    ) -> Result<Self> {
        Self::with_rows(3, coordinates, mass, contacts, jacobian, u)
    }

    /// Whether the system is spatial (three rows per contact).
    pub fn is_spatial(&self) -> bool {
        self.dim == 3
    }

    fn with_rows(
        dim: usize,
        coordinates: Vec<String>,
        mass: DMatrix<f64>,
        contacts: Vec<String>,
        jacobian: DMatrix<f64>,
        u: &[f64],
    ) -> Result<Self> {
        let n = mass.nrows();
        let bad = |field: &str, reason: String| Error::Invalid {
            field: field.into(),
            reason,
        };
        if n == 0 || mass.ncols() != n {
            return Err(bad(
                "mass",
                format!(
                    "must be square and not empty, got {} × {}",
                    mass.nrows(),
                    mass.ncols()
                ),
            ));
        }
        if coordinates.len() != n {
            return Err(bad(
                "coordinates",
                format!("expected {n} names, got {}", coordinates.len()),
            ));
        }
        if contacts.is_empty() || jacobian.nrows() != dim * contacts.len() || jacobian.ncols() != n
        {
            return Err(bad(
                "jacobian",
                format!(
                    "must be {dim}K × n = {} × {n} ({} of each of {} contacts), got {} × {}",
                    dim * contacts.len(),
                    if dim == 2 {
                        "tangent and normal rows"
                    } else {
                        "two tangent rows and the normal row"
                    },
                    contacts.len(),
                    jacobian.nrows(),
                    jacobian.ncols()
                ),
            ));
        }
        if u.len() != n {
            return Err(bad("u", format!("expected {n} numbers, got {}", u.len())));
        }
        for (field, m) in [("mass", &mass), ("jacobian", &jacobian)] {
            if let Some(x) = m.iter().find(|x| !x.is_finite()) {
                return Err(bad(field, format!("has a non-finite entry {x}")));
            }
        }
        for (i, &x) in u.iter().enumerate() {
            crate::error::finite(&format!("u[{}]", coordinates[i]), x)?;
        }
        let scale = mass.amax();
        for i in 0..n {
            for j in i + 1..n {
                if (mass[(i, j)] - mass[(j, i)]).abs() > 1e-12 * scale {
                    return Err(bad("mass", "must be symmetric".into()));
                }
            }
        }
        let chol = Cholesky::new(mass.clone())
            .ok_or_else(|| bad("mass", "must be positive definite".into()))?;
        let u = DVector::from_column_slice(u);
        let energy = 0.5 * u.dot(&(&mass * &u));
        crate::error::kinetic_energy(energy, u.amax())?;
        Ok(Self {
            dim,
            coordinates,
            contacts,
            mass,
            chol,
            jacobian,
            u,
        })
    }

    /// Contacts `contacts` of a planar mechanism at `(q, u)`, struck together: `M(q)` and
    /// the contacts' Jacobians from the mechanism's kinematics (the same as
    /// [`crate::mechanism::impact::MechanismImpact`] uses for one contact).
    ///
    /// # Errors
    /// As [`MultiImpact::new`]; a contact index out of range or repeated (`contacts`); the
    /// mechanism's own state checks.
    pub fn from_mechanism<M: Mechanism + ?Sized>(
        mechanism: &M,
        q: &[f64],
        u: &[f64],
        contacts: &[usize],
    ) -> Result<Self> {
        dynamics::check_state(mechanism, q, Some(u))?;
        let all = mechanism.contacts();
        for (i, &k) in contacts.iter().enumerate() {
            if k >= all.len() || contacts[..i].contains(&k) {
                return Err(Error::Invalid {
                    field: "contacts".into(),
                    reason: format!(
                        "contact {k} is {} (the mechanism has {} contact point(s))",
                        if k >= all.len() {
                            "out of range"
                        } else {
                            "repeated"
                        },
                        all.len()
                    ),
                });
            }
        }
        dynamics::check_precision(mechanism, q)?;
        let kin = dynamics::kinematics(mechanism, q);
        let mass = dynamics::mass_matrix_of(mechanism, &kin);
        let n = mechanism.dof();
        let mut jacobian = DMatrix::zeros(2 * contacts.len(), n);
        for (j, &k) in contacts.iter().enumerate() {
            let jk = dynamics::contact_jacobian_of(mechanism, k, q, &kin);
            jacobian.rows_mut(2 * j, 2).copy_from(&jk);
        }
        Self::new(
            mechanism
                .coordinates()
                .iter()
                .map(|c| c.to_string())
                .collect(),
            mass,
            contacts.iter().map(|&k| all[k].name.to_string()).collect(),
            jacobian,
            u,
        )
    }

    /// The names of the generalized coordinates.
    pub fn coordinates(&self) -> &[String] {
        &self.coordinates
    }

    /// The names of the contacts, in order.
    pub fn contacts(&self) -> &[String] {
        &self.contacts
    }

    /// The mass matrix `M`.
    pub fn mass_matrix(&self) -> &DMatrix<f64> {
        &self.mass
    }

    /// The contact rows `J` (`2K × n`).
    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.jacobian
    }

    /// The generalized velocities before, `u⁻`.
    pub fn velocities_before(&self) -> &[f64] {
        self.u.as_slice()
    }

    /// `W = J M⁻¹ Jᵀ` (symmetrised).
    pub fn inverse_inertia(&self) -> DMatrix<f64> {
        let w = &self.jacobian * self.chol.solve(&self.jacobian.transpose());
        0.5 * (&w + w.transpose())
    }

    /// `v⁻ = J u⁻`, contact by contact (tangent, normal).
    pub fn contact_velocities(&self) -> Vec<f64> {
        (&self.jacobian * &self.u).as_slice().to_vec()
    }

    /// `T⁻ = ½ u⁻ᵀ M u⁻`.
    pub fn energy_before(&self) -> f64 {
        self.kinetic_energy(self.u.as_slice())
    }

    /// `½ uᵀ M u`.
    pub fn kinetic_energy(&self, u: &[f64]) -> f64 {
        let u = DVector::from_column_slice(u);
        0.5 * u.dot(&(&self.mass * &u))
    }

    /// The contact-space problem with per-contact coefficients (one value for every contact
    /// or `K`).
    ///
    /// # Errors
    /// As [`MultiProblem::new`] (e.g. no contact approaching).
    pub fn problem(&self, friction: &[f64], restitution: &[f64]) -> Result<MultiProblem> {
        if self.dim == 3 {
            return Err(Error::Invalid {
                field: "jacobian".into(),
                reason: "the system is spatial (three rows per contact): use spatial_problem"
                    .into(),
            });
        }
        MultiProblem::new(
            self.inverse_inertia(),
            &self.contact_velocities(),
            friction,
            restitution,
        )
    }

    /// The spatial contact-space problem of a spatial system ([`MultiImpact::spatial`]).
    ///
    /// # Errors
    /// As [`spatial::MultiProblem::new`]; a planar system (`jacobian`).
    pub fn spatial_problem(
        &self,
        friction: &[f64],
        restitution: &[f64],
    ) -> Result<spatial::MultiProblem> {
        if self.dim != 3 {
            return Err(Error::Invalid {
                field: "jacobian".into(),
                reason: "the system is planar (two rows per contact): use problem".into(),
            });
        }
        spatial::MultiProblem::new(
            self.inverse_inertia(),
            &self.contact_velocities(),
            friction,
            restitution,
        )
    }

    /// `u⁺ = u⁻ + M⁻¹ Jᵀ p` for the impulses `p` (one per contact): `Vec2` (tangent, normal)
    /// for a planar system, `Vec3` (two tangents, normal) for a spatial one.
    ///
    /// # Panics
    /// When `D` is not the system's number of rows per contact or `p` has not one impulse
    /// per contact.
    pub fn velocities_after<const D: usize>(&self, p: &[SVector<f64, D>]) -> Vec<f64> {
        assert_eq!(
            D, self.dim,
            "impulses of {D} components for {} rows per contact",
            self.dim
        );
        self.after_flat(DVector::from_iterator(
            D * p.len(),
            p.iter().flat_map(|x| x.iter().copied()),
        ))
    }

    fn after_flat(&self, flat: DVector<f64>) -> Vec<f64> {
        (&self.u + self.chol.solve(&(self.jacobian.transpose() * flat)))
            .as_slice()
            .to_vec()
    }

    /// Resolve `problem` (built by [`MultiImpact::problem`] for a planar system,
    /// [`MultiImpact::spatial_problem`] for a spatial one) with `law` and map the impulses back
    /// to the generalized velocities.
    ///
    /// # Errors
    /// As [`LawId::resolve`] (a one-contact law with several contacts names `law`).
    pub fn resolve<P: SystemProblem>(
        &self,
        law: LawId,
        problem: &P,
    ) -> Result<SystemOutcome<P::Outcome>> {
        let resolution = problem.resolve_by(law, &Options::default())?;
        let (velocities_after, energy_change_from_velocities) = match P::flat_impulses(&resolution)
        {
            Some(flat) => {
                let after = self.after_flat(flat);
                let de = self.kinetic_energy(&after) - self.energy_before();
                (Some(after), Some(de))
            }
            None => (None, None),
        };
        Ok(SystemOutcome {
            resolution,
            velocities_after,
            energy_change_from_velocities,
        })
    }
}

/// A contact-space problem of several contacts that a [`MultiImpact`] resolves and maps back:
/// the planar [`MultiProblem`] or the spatial [`spatial::MultiProblem`] (sealed).
pub trait SystemProblem:
    law::Problem<Resolution = Result<<Self as SystemProblem>::Outcome>> + sealed::Sealed
{
    /// The law's result: an outcome or a breakdown.
    type Outcome;

    /// The impulses of a result, contact by contact, flattened (`None` for a breakdown).
    fn flat_impulses(resolution: &Self::Outcome) -> Option<DVector<f64>>;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::MultiProblem {}
    impl Sealed for super::spatial::MultiProblem {}
}

impl SystemProblem for MultiProblem {
    type Outcome = MultiResolution;

    fn flat_impulses(resolution: &MultiResolution) -> Option<DVector<f64>> {
        let p = resolution.as_ref().ok()?.impulses();
        Some(DVector::from_iterator(
            2 * p.len(),
            p.iter().flat_map(|x| [x.x, x.y]),
        ))
    }
}

impl SystemProblem for spatial::MultiProblem {
    type Outcome = spatial::MultiResolution;

    fn flat_impulses(resolution: &spatial::MultiResolution) -> Option<DVector<f64>> {
        let p = resolution.as_ref().ok()?.impulses();
        Some(DVector::from_iterator(
            3 * p.len(),
            p.iter().flat_map(|x| [x.x, x.y, x.z]),
        ))
    }
}
