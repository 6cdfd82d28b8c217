//! The spatial contact-space problem with `K` contacts `(W, v⁻, μ_j, e_j)`.

use crate::error::Result;
use crate::math::{Mat3, Units, Vec3};
use crate::multi::problem::HERTZ_EXPONENT;
use crate::multi::validate::{check, exponent as exponent_checked, stiffnesses, Checked};
use crate::spatial::ContactProblem;
use nalgebra::{DMatrix, DVector};

/// A validated spatial impact problem with `K ≥ 1` contacts: the planar
/// [`crate::multi::MultiProblem`] with two tangents per contact.
///
/// Contact-major: `v = (v_t1,1, v_t2,1, v_n,1, …, v_t1,K, v_t2,K, v_n,K)` and `W` (`3K × 3K`)
/// ordered the same way; contact `j`'s own `3 × 3` block is that of the one-contact
/// [`ContactProblem`]. Errors name rows and columns `t1_1, t2_1, n_1, t1_2, …`
/// (`w[t1_1,n_2]`) and velocities `v[t1,2]`, `v[n,2]` (component, contact counted from 1).
///
/// The checks are the planar problem's: every entry finite; `W` symmetric to round-off;
/// each contact's own block positive definite (as [`ContactProblem::new`]); `W` positive
/// *semi*definite (redundant contacts: a box lying flat on four corners has twelve contact
/// rows and six degrees of freedom); `v⁻` in the range of a singular `W` up to
/// [`RANGE_TOL`](crate::multi::RANGE_TOL) of `|v⁻|`; `0 ≤ μ_j ≤ 1e300`, `e_j ∈ [0, 1]`; at least one
/// contact approaching; the approach energy `½ v⁻ᵀ W⁺ v⁻` representable.
///
/// ```
/// use impax::multi::spatial::MultiProblem;
/// // A sphere (m = 1) on a plane, as a problem with one contact: W = diag(7/2, 7/2, 1).
/// let p = MultiProblem::from_upper(
///     1,
///     &[3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
///     &[0.3, 0.0, -1.0],
///     &[0.4],
///     &[0.7],
/// )
/// .unwrap();
/// assert_eq!(p.contacts(), 1);
/// assert_eq!(p.rank(), 3);
/// assert_eq!(MultiProblem::from_upper(1, &[3.5, 0.0, 0.0, 3.5, 0.0, 1.0], &[0.3, 0.0, 1.0],
///     &[0.4], &[0.7]).unwrap_err().field(), "v");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MultiProblem {
    checked: Checked,
    /// The stiffness ratios `κ_j` of `lzb` (one per contact).
    stiffness: Vec<f64>,
    /// The exponent `η` of `lzb`'s force law.
    exponent: f64,
}

impl MultiProblem {
    /// Validate and build a problem from `W` (`3K × 3K`, contact-major), `v⁻` (`3K` numbers,
    /// contact by contact, the two tangents then the normal), and the friction coefficients
    /// and restitutions (one value for every contact, or `K`). See the type's docs for the
    /// checks; errors name their field.
    pub fn new(w: DMatrix<f64>, v: &[f64], friction: &[f64], restitution: &[f64]) -> Result<Self> {
        let checked = check(3, w, v, friction, restitution, |w, j| {
            crate::spatial::problem::positive_definite(&block(w, j))
        })?;
        let k = checked.k;
        Ok(Self {
            checked,
            stiffness: vec![1.0; k],
            exponent: HERTZ_EXPONENT,
        })
    }

    /// Build from the upper triangle of `W`, row by row (`3K (3K + 1) / 2` numbers: row
    /// `t1_1` from its diagonal, then row `t2_1`, …), as the command line's `--w` takes it.
    pub fn from_upper(
        contacts: usize,
        upper: &[f64],
        v: &[f64],
        friction: &[f64],
        restitution: &[f64],
    ) -> Result<Self> {
        let w = crate::multi::validate::from_upper_triangle(3, contacts, upper)?;
        Self::new(w, v, friction, restitution)
    }

    /// The one-contact problem as a problem with `K = 1`.
    pub fn from_contact(problem: &ContactProblem) -> Result<Self> {
        let w = problem.w();
        let v = problem.velocity();
        Self::new(
            DMatrix::from_fn(3, 3, |i, j| w[(i, j)]),
            &[v.x, v.y, v.z],
            &[problem.friction()],
            &[problem.restitution()],
        )
    }

    /// The same problem with the stiffness ratios `κ_j` of `lzb` (as
    /// [`crate::multi::MultiProblem::with_stiffness`]).
    pub fn with_stiffness(mut self, stiffness: &[f64]) -> Result<Self> {
        self.stiffness = stiffnesses(stiffness, self.checked.k)?;
        Ok(self)
    }

    /// The same problem with the exponent `η` of `lzb`'s force law (as
    /// [`crate::multi::MultiProblem::with_exponent`]).
    pub fn with_exponent(mut self, exponent: f64) -> Result<Self> {
        self.exponent = exponent_checked(exponent)?;
        Ok(self)
    }

    /// The number of contacts `K`.
    #[inline]
    pub fn contacts(&self) -> usize {
        self.checked.k
    }

    /// `W` (`3K × 3K`, contact-major, symmetrised).
    pub fn w(&self) -> &DMatrix<f64> {
        &self.checked.w
    }

    /// The rank of `W` (eigenvalues within [`RANK_TOL`](crate::multi::RANK_TOL) of the
    /// largest counted as zero): `3K` unless contacts are redundant.
    pub fn rank(&self) -> usize {
        self.checked.rank
    }

    /// Contact `j`'s own block (`j` from 0).
    pub fn block(&self, j: usize) -> Mat3 {
        block(&self.checked.w, j)
    }

    /// The coupling block of contacts `i` and `j`: the velocity change at contact `i` per unit
    /// impulse at contact `j`.
    pub fn coupling(&self, i: usize, j: usize) -> Mat3 {
        coupling(&self.checked.w, i, j)
    }

    /// `v⁻` (`3K` numbers, contact by contact).
    pub fn velocity(&self) -> &DVector<f64> {
        &self.checked.v
    }

    /// Contact `j`'s velocity before the impact `(v_t1⁻, v_t2⁻, v_n⁻)`.
    pub fn contact_velocity(&self, j: usize) -> Vec3 {
        let v = &self.checked.v;
        Vec3::new(v[3 * j], v[3 * j + 1], v[3 * j + 2])
    }

    /// Contact `j`'s friction coefficient `μ_j`.
    pub fn friction(&self, j: usize) -> f64 {
        self.checked.mu[j]
    }

    /// Contact `j`'s coefficient of restitution `e_j`.
    pub fn restitution(&self, j: usize) -> f64 {
        self.checked.e[j]
    }

    /// Contact `j`'s stiffness ratio `κ_j` of `lzb` (default 1).
    pub fn stiffness(&self, j: usize) -> f64 {
        self.stiffness[j]
    }

    /// The exponent `η` of `lzb`'s force law (default 3/2).
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// Contact `j` alone: the one-contact problem of its own block, velocity and coefficients
    /// (an error if it does not approach).
    pub fn contact(&self, j: usize) -> Result<ContactProblem> {
        ContactProblem::new(
            self.block(j),
            self.contact_velocity(j),
            self.friction(j),
            self.restitution(j),
        )
    }

    /// The contact-space kinetic energy of the approach, `½ v⁻ᵀ W⁺ v⁻`.
    pub fn approach_energy(&self) -> f64 {
        self.checked.approach_energy
    }

    /// The contact velocities after the impulses `p` (one per contact): `v⁻ + W p`.
    pub fn velocity_after(&self, p: &[Vec3]) -> Vec<Vec3> {
        let v = &self.checked.v + &self.checked.w * flatten(p);
        (0..self.contacts())
            .map(|j| Vec3::new(v[3 * j], v[3 * j + 1], v[3 * j + 2]))
            .collect()
    }

    /// The exact kinetic-energy change of any impulses `p`: `ΔT = v⁻·p + ½ pᵀ W p`.
    pub fn energy_change(&self, p: &[Vec3]) -> f64 {
        let flat = flatten(p);
        self.checked.v.dot(&flat) + 0.5 * flat.dot(&(&self.checked.w * &flat))
    }

    /// The canonical units and `W`, `v⁻` in them (for the laws).
    pub(crate) fn canonical(&self) -> (Units, &DMatrix<f64>, &DVector<f64>) {
        (self.checked.units, &self.checked.ws, &self.checked.vs)
    }
}

/// Contact `j`'s own block of `w`.
fn block(w: &DMatrix<f64>, j: usize) -> Mat3 {
    coupling(w, j, j)
}

/// The block of rows of contact `i` and columns of contact `j`.
pub(crate) fn coupling(w: &DMatrix<f64>, i: usize, j: usize) -> Mat3 {
    Mat3::from_fn(|r, c| w[(3 * i + r, 3 * j + c)])
}

/// Per-contact vectors as one contact-major vector.
pub(crate) fn flatten(p: &[Vec3]) -> DVector<f64> {
    DVector::from_iterator(3 * p.len(), p.iter().flat_map(|x| [x.x, x.y, x.z]))
}
