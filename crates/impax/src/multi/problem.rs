//! The planar contact-space problem with `K` contacts `(W, v⁻, μ_j, e_j)`.

use super::validate::{check, exponent as exponent_checked, from_upper_triangle, stiffnesses};
use crate::error::Result;
use crate::math::{Mat2, Units, Vec2};
use crate::planar::{ContactProblem, InverseInertia};
use nalgebra::{DMatrix, DVector};

/// Eigenvalues of `W` within `RANK_TOL` of its largest, in magnitude, are zero: `W` is then
/// singular (redundant contacts). An eigenvalue below `−RANK_TOL` times the largest makes `W`
/// indefinite, which is refused.
pub const RANK_TOL: f64 = 1e-11;

/// The largest component of `v⁻` outside the range of a singular `W`, relative to `|v⁻|`,
/// accepted as round-off (and removed).
pub const RANGE_TOL: f64 = 1e-9;

/// The default exponent `η` of the contacts' force law `F = κ δ^η` of the law `lzb`: `3/2`,
/// Hertz's for smooth bodies.
pub const HERTZ_EXPONENT: f64 = 1.5;

/// A validated planar impact problem with `K ≥ 1` contacts (module docs of
/// [`crate::multi`]).
///
/// Contact-major: the velocity is `v = (v_t1, v_n1, …, v_tK, v_nK)`, and `W` (`2K × 2K`)
/// is ordered the same way, so contact `j`'s own `2 × 2` block is
/// `[[W_tjtj, W_tjnj], [W_njtj, W_njnj]]`. Contacts are numbered from 0 in the library (the
/// field names of errors and the command line count from 1: `v[n,2]` is the normal velocity of
/// the second contact).
///
/// Validation ([`MultiProblem::new`]): every entry finite; `W` symmetric to round-off
/// (relative `1e-12`; the mean of the two off-diagonal entries is kept); each contact's own
/// block positive definite (as [`InverseInertia::new`]); `W` positive *semi*definite — its
/// eigenvalues not below `−`[`RANK_TOL`] of the largest, those within [`RANK_TOL`] of zero
/// counted as zero (redundant contacts: a rod lying flat has four contact rows and three
/// degrees of freedom); when `W` is singular, `v⁻` in its range (a velocity `J u` of the bodies
/// always is, `W = J M⁻¹ Jᵀ`) up to [`RANGE_TOL`] of `|v⁻|`, that round-off removed;
/// `0 ≤ μ_j ≤ 1e300`, `e_j ∈ [0, 1]`; at least one contact approaching (`v_nj⁻ < 0`; the others may
/// touch or separate); the approach energy `½ v⁻ᵀ W⁺ v⁻` representable.
///
/// The law [`lzb`](super::lzb) also reads the contacts' compliance: the stiffness ratios
/// `κ_j` (default all 1, [`MultiProblem::with_stiffness`]) and the exponent `η` of the force
/// law `F_j = κ_j δ_j^η` (default [`HERTZ_EXPONENT`] `= 3/2`,
/// [`MultiProblem::with_exponent`]). The other laws ignore them.
///
/// ```
/// use impax::multi::MultiProblem;
/// // A uniform rod (m = 1, l = 1, I = 1/12) lying flat, both ends landing at 1:
/// // W_tt = 1, W_nn = 1 + (l/2)²/I = 4, the ends coupled by 1 − (l/2)²/I = −2.
/// let p = MultiProblem::from_upper(
///     2,
///     &[1.0, 0.0, 1.0, 0.0, /**/ 4.0, 0.0, -2.0, /**/ 1.0, 0.0, /**/ 4.0],
///     &[0.0, -1.0, 0.0, -1.0],
///     &[0.5],
///     &[0.8],
/// )
/// .unwrap();
/// assert_eq!(p.contacts(), 2);
/// assert_eq!(p.rank(), 3); // four rows, three degrees of freedom
/// assert!(MultiProblem::from_upper(2, &[1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0],
///     &[0.3, -1.0, 0.0, -1.0], &[0.5], &[0.8]).is_err()); // v_t1 ≠ v_t2: not J u
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MultiProblem {
    k: usize,
    /// `W` as given (symmetrised).
    w: DMatrix<f64>,
    /// `v⁻` as given (its round-off outside the range of a singular `W` removed).
    v: DVector<f64>,
    mu: Vec<f64>,
    e: Vec<f64>,
    rank: usize,
    approach_energy: f64,
    /// The canonical units: velocities times `units.a`, `W` times `units.b` (powers of two).
    units: Units,
    /// `W` and `v⁻` in the canonical units, where the laws work.
    ws: DMatrix<f64>,
    vs: DVector<f64>,
    /// Each contact's own block in the canonical units.
    blocks: Vec<InverseInertia>,
    /// The stiffness ratios `κ_j` of `lzb` (one per contact).
    stiffness: Vec<f64>,
    /// The exponent `η` of `lzb`'s force law.
    exponent: f64,
}

impl MultiProblem {
    /// Validate and build a problem from `W` (`2K × 2K`, contact-major), `v⁻` (`2K` numbers,
    /// contact by contact, tangent then normal), and the friction coefficients and
    /// restitutions (one value for every contact, or `K`).
    ///
    /// Errors name their field as the command line spells it: `w`, `w[t1,n2]` (row `t1`,
    /// column `n2`), `v`, `v[n,2]` (the second contact's normal velocity), `friction`,
    /// `friction[2]`, `restitution`, `restitution[2]`. See the type's docs for the checks.
    pub fn new(w: DMatrix<f64>, v: &[f64], friction: &[f64], restitution: &[f64]) -> Result<Self> {
        let c = check(2, w, v, friction, restitution, |w, j| {
            InverseInertia::new(block(w, j)).map(|_| ())
        })?;
        let blocks = (0..c.k)
            .map(|j| InverseInertia::new(block(&c.ws, j)))
            .collect::<Result<Vec<_>>>()?;
        Ok(Self {
            k: c.k,
            w: c.w,
            v: c.v,
            mu: c.mu,
            e: c.e,
            rank: c.rank,
            approach_energy: c.approach_energy,
            units: c.units,
            ws: c.ws,
            vs: c.vs,
            blocks,
            stiffness: vec![1.0; c.k],
            exponent: HERTZ_EXPONENT,
        })
    }

    /// The same problem with the stiffness ratios `κ_j` of the law [`lzb`](super::lzb): one
    /// value for every contact or one per contact, each positive and finite. Only the ratios
    /// matter (`lzb`'s result is unchanged when every `κ_j` is multiplied by the same factor:
    /// it sets the duration of the impact, not its outcome). Default: all 1.
    ///
    /// Errors name the field `stiffness` (or `stiffness[j]`, counted from 1, with one value
    /// per contact).
    ///
    /// ```
    /// use impax::multi::MultiProblem;
    /// let p = MultiProblem::from_upper(
    ///     2,
    ///     &[2.0, 0.0, 0.0, 0.0, /**/ 2.0, 0.0, -1.0, /**/ 2.0, 0.0, /**/ 2.0],
    ///     &[0.0, -1.0, 0.0, 0.0],
    ///     &[0.0],
    ///     &[1.0],
    /// )
    /// .unwrap();
    /// assert_eq!(p.stiffness(1), 1.0);
    /// let q = p.clone().with_stiffness(&[1.0, 4.0]).unwrap();
    /// assert_eq!(q.stiffness(1), 4.0);
    /// let e = p.with_stiffness(&[1.0, -4.0]).unwrap_err();
    /// assert_eq!(e.field(), "stiffness[2]");
    /// ```
    pub fn with_stiffness(mut self, stiffness: &[f64]) -> Result<Self> {
        self.stiffness = stiffnesses(stiffness, self.k)?;
        Ok(self)
    }

    /// The same problem with the exponent `η` of the contacts' force law `F = κ δ^η` of the
    /// law [`lzb`](super::lzb) (finite, `> 0`): `3/2` for Hertz's contact of smooth bodies
    /// (the default, [`HERTZ_EXPONENT`]), `1` for a linear spring.
    ///
    /// Errors name the field `exponent`.
    ///
    /// ```
    /// use impax::multi::MultiProblem;
    /// let p = MultiProblem::from_upper(1, &[3.5, 0.0, 1.0], &[0.5, -0.866], &[0.4], &[0.7])
    ///     .unwrap();
    /// assert_eq!(p.exponent(), 1.5);
    /// assert_eq!(p.clone().with_exponent(1.0).unwrap().exponent(), 1.0);
    /// assert_eq!(p.with_exponent(0.0).unwrap_err().field(), "exponent");
    /// ```
    pub fn with_exponent(mut self, exponent: f64) -> Result<Self> {
        self.exponent = exponent_checked(exponent)?;
        Ok(self)
    }

    /// Build from the upper triangle of `W`, row by row (`2K (2K + 1) / 2` numbers: row `t1`
    /// from its diagonal, then row `n1`, …), as the command line's `--w` takes it.
    pub fn from_upper(
        contacts: usize,
        upper: &[f64],
        v: &[f64],
        friction: &[f64],
        restitution: &[f64],
    ) -> Result<Self> {
        let w = from_upper_triangle(2, contacts, upper)?;
        Self::new(w, v, friction, restitution)
    }

    /// The one-contact problem as a problem with `K = 1` (the same `W`, `v⁻`, `μ`, `e`; an
    /// error only if its approach energy, computed here through the eigenvalues of `W`, is not
    /// representable).
    pub fn from_contact(problem: &ContactProblem) -> Result<Self> {
        let w = problem.w();
        let v = problem.velocity();
        Self::new(
            DMatrix::from_row_slice(2, 2, &[w[(0, 0)], w[(0, 1)], w[(1, 0)], w[(1, 1)]]),
            &[v.x, v.y],
            &[problem.friction()],
            &[problem.restitution()],
        )
    }

    /// The number of contacts `K`.
    #[inline]
    pub fn contacts(&self) -> usize {
        self.k
    }

    /// `W` (`2K × 2K`, contact-major, symmetrised).
    pub fn w(&self) -> &DMatrix<f64> {
        &self.w
    }

    /// The rank of `W` (eigenvalues within [`RANK_TOL`] of the largest counted as zero):
    /// `2K` unless contacts are redundant.
    pub fn rank(&self) -> usize {
        self.rank
    }

    /// Contact `j`'s own block `[[W_tt, W_tn], [W_nt, W_nn]]` (`j` from 0).
    pub fn block(&self, j: usize) -> Mat2 {
        block(&self.w, j)
    }

    /// The coupling block `[[W_titj, W_tinj], [W_nitj, W_ninj]]` of contacts `i` and `j`: the
    /// velocity change at contact `i` per unit impulse at contact `j`.
    pub fn coupling(&self, i: usize, j: usize) -> Mat2 {
        coupling(&self.w, i, j)
    }

    /// `v⁻` (`2K` numbers, contact by contact).
    pub fn velocity(&self) -> &DVector<f64> {
        &self.v
    }

    /// Contact `j`'s velocity before the impact `(v_t⁻, v_n⁻)`.
    pub fn contact_velocity(&self, j: usize) -> Vec2 {
        Vec2::new(self.v[2 * j], self.v[2 * j + 1])
    }

    /// Contact `j`'s friction coefficient `μ_j`.
    pub fn friction(&self, j: usize) -> f64 {
        self.mu[j]
    }

    /// Contact `j`'s coefficient of restitution `e_j`.
    pub fn restitution(&self, j: usize) -> f64 {
        self.e[j]
    }

    /// Contact `j`'s stiffness ratio `κ_j` of the law [`lzb`](super::lzb) (default 1).
    pub fn stiffness(&self, j: usize) -> f64 {
        self.stiffness[j]
    }

    /// The exponent `η` of the force law `F = κ δ^η` of the law [`lzb`](super::lzb)
    /// (default [`HERTZ_EXPONENT`] `= 3/2`).
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// Contact `j` alone: the one-contact problem of its own block, velocity and coefficients
    /// (an error if it does not approach).
    pub fn contact(&self, j: usize) -> Result<ContactProblem> {
        ContactProblem::new(
            self.block(j),
            self.contact_velocity(j),
            self.mu[j],
            self.e[j],
        )
    }

    /// The contact-space kinetic energy of the approach, `½ v⁻ᵀ W⁺ v⁻` (`W⁺` the
    /// pseudo-inverse): the energy of the bodies' motion that the contacts can see, the most
    /// an impulse can remove.
    pub fn approach_energy(&self) -> f64 {
        self.approach_energy
    }

    /// The contact velocities after the impulses `p` (one per contact): `v⁻ + W p`.
    pub fn velocity_after(&self, p: &[Vec2]) -> Vec<Vec2> {
        let flat = flatten(p);
        let v = &self.v + &self.w * flat;
        (0..self.k)
            .map(|j| Vec2::new(v[2 * j], v[2 * j + 1]))
            .collect()
    }

    /// The exact kinetic-energy change of any impulses `p` (one per contact):
    /// `ΔT = v⁻·p + ½ pᵀ W p`.
    pub fn energy_change(&self, p: &[Vec2]) -> f64 {
        let flat = flatten(p);
        self.v.dot(&flat) + 0.5 * flat.dot(&(&self.w * &flat))
    }

    /// The canonical units and `W`, `v⁻` and the blocks in them (for the laws).
    pub(crate) fn canonical(&self) -> (Units, &DMatrix<f64>, &DVector<f64>, &[InverseInertia]) {
        (self.units, &self.ws, &self.vs, &self.blocks)
    }

    /// The friction coefficients.
    pub(crate) fn frictions(&self) -> &[f64] {
        &self.mu
    }

    /// The restitutions.
    pub(crate) fn restitutions(&self) -> &[f64] {
        &self.e
    }

    /// The stiffness ratios.
    pub(crate) fn stiffnesses(&self) -> &[f64] {
        &self.stiffness
    }
}

/// Contact `j`'s own block of `w`.
fn block(w: &DMatrix<f64>, j: usize) -> Mat2 {
    coupling(w, j, j)
}

/// The block of rows of contact `i` and columns of contact `j`.
pub(crate) fn coupling(w: &DMatrix<f64>, i: usize, j: usize) -> Mat2 {
    Mat2::new(
        w[(2 * i, 2 * j)],
        w[(2 * i, 2 * j + 1)],
        w[(2 * i + 1, 2 * j)],
        w[(2 * i + 1, 2 * j + 1)],
    )
}

/// Per-contact vectors as one contact-major vector.
fn flatten(p: &[Vec2]) -> DVector<f64> {
    DVector::from_iterator(2 * p.len(), p.iter().flat_map(|x| [x.x, x.y]))
}
