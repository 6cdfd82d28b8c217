//! Contacts that stay closed: the acceleration-level contact problem, solved exactly by
//! enumerating the contacts' regimes, and the projection that keeps closed contacts on their
//! surfaces (theory §6).
//!
//! With `K` closed contacts at `(q, u)`, contact-major rows `J` (`2K × n`, tangent then normal),
//! the velocity-product terms `J̇ u` ([`dynamics::contact_velocity_products`]), the free
//! accelerations `a_free = M⁻¹ (Q − Σ_b J_bᵀ D_b J̇_b u)` and the contact forces
//! `λ = (λ_t1, λ_n1, …)` on the touching bodies,
//!
//! ```text
//! M a = Q − Σ_b J_bᵀ D_b J̇_b u + Jᵀ λ          a = a_free + M⁻¹ Jᵀ λ
//! α = J a + J̇ u = α⁰ + W λ,   α⁰ = J a_free + J̇ u,   W = J M⁻¹ Jᵀ
//! ```
//!
//! (`α` the contact accelerations: `α_n = φ̈`, `α_t` the rate of the tangential velocity of the
//! body's material point at the contact). At every closed contact `j`:
//!
//! ```text
//! normal:   0 ≤ λ_nj ⊥ α_nj ≥ 0
//! sliding   (v_tj ≠ 0, ŝ = sign v_tj):  λ_tj = −μ λ_nj ŝ
//! rolling   (v_tj = 0):  α_tj = 0 and |λ_tj| ≤ μ λ_nj,   or  λ_tj = −μ λ_nj ŝ with ŝ α_tj ≥ 0
//!           (slip starts in the direction of the tangential acceleration)
//! ```
//!
//! **Exact enumeration** (as [`crate::multi::lcp`] does for impulses): each contact is `off`
//! (`λ_j = 0`, needs `α_nj ≥ 0`) or closed in a [`Regime`] — a sliding contact in `slip` along
//! its velocity, a rolling one in `stick`, `slip+` or `slip−` (a frictionless one only
//! `frictionless`, `λ_t = 0`). Each combination is a square linear system for the unknown
//! forces (`stick`: `α_t = α_n = 0` for `λ_t, λ_n`; the others `α_n = 0` for `λ_n`), solved in
//! the least-squares, least-norm sense (the complete-pivoting elimination of
//! [`crate::multi::lcp`], pivots below `10⁻¹¹` of the largest entry taken as zero): a rod
//! lying flat has two closed contacts with the same tangent row, and the least-norm forces
//! share the friction equally between its ends. A
//! combination is a solution when its equations hold and every inequality holds to round-off
//! ([`FORCE_ROUND_OFF`] of the scales `max_i (|α⁰_i| + Σ_k |W_ik| |λ_k|)` and `max |λ|`).
//! Solutions whose generalized accelerations agree (to `10⁻⁸` of their scale) are one
//! solution (the forces may differ when `W` is singular; the motion does not).
//!
//! **Painlevé.** With friction a sliding contact's normal force has the coefficient
//! `W_nn − μ ŝ W_nt`, which is negative when `μ` is large enough (a rod sliding on its end:
//! `μ > (1 + 3 cos²θ)/(3 sin θ |cos θ|)`, at least 4/3). Then the problem has no solution
//! (`α⁰_n < 0`) or two (`α⁰_n > 0`: off, or a force pulling the contact down): Painlevé's
//! paradox. The way out of it is an impulsive "tangential impact" (Génot & Brogliato, *New
//! results on Painlevé paradoxes*, Eur. J. Mech. A/Solids 18, 1999), which the simulation does
//! not model: it detects the situation and stops (`painleve`). A contact sliding below the
//! bound can reach it as the body turns: where the coefficient and the free normal acceleration
//! `α⁰_n` vanish together, the force needed grows without bound (Génot & Brogliato's singular
//! point, the "dynamic jam"; for a uniform rod when `μ > 8/(3√3)`) and the integration cannot
//! step past it; the run stops there too, with no solution (where the step size underflows
//! with the coefficient within `1e-6` of the size of its terms: `run/step.rs`).
//!
//! ```
//! use impax::mechanism::builtin::Rod;
//! use impax::simulation::{simulate, SimulationOptions, StopReason};
//! use impax::LawId;
//! // A unit rod at tan θ = 2 (the bound 4/3) with its end A on the floor sliding towards −x,
//! // μ = 1.5: no force satisfies the conditions.
//! let rod = Rod::new(1.0, 1.0, 9.81, 0.0)?;
//! let th = 2f64.atan();
//! let q = [0.5 * th.cos(), 0.5 * th.sin(), th];
//! let options = SimulationOptions::new(LawId::Energetic, 1.5, 0.5, 1.0);
//! let run = simulate(&rod, &q, &[-1.0, 0.0, 0.0], &options)?;
//! assert_eq!(run.stop, StopReason::Painleve { contact: 0, solutions: 0 });
//! // Below the bound the end slides.
//! let options = SimulationOptions::new(LawId::Energetic, 1.2, 0.5, 1.0);
//! let run = simulate(&rod, &q, &[-1.0, 0.0, 0.0], &options)?;
//! assert!(!matches!(run.stop, StopReason::Painleve { .. }));
//! # Ok::<(), impax::Error>(())
//! ```
//!
//! **Drift.** The constraint `φ_j = 0` is kept at the acceleration level (`α_nj = 0`) and
//! integrated to tolerance; after every step the state is projected back:
//! the projection moves `q` to zero gaps (Newton steps `Δq = −M⁻¹Gᵀ (G M⁻¹ Gᵀ)⁺ φ`, `G` the normal
//! rows) and `u` to zero normal velocities at the closed contacts and zero tangential
//! velocities at the sticking ones (`Δu = −M⁻¹Rᵀ (R M⁻¹ Rᵀ)⁺ R u`): the least change in the
//! mass metric. The change of `T + V` it makes is recorded in the run's energy ledger.

use crate::error::{Error, Result};
use crate::mechanism::{dynamics, Mechanism};
use crate::multi::lcp;
use crate::planar::SlipDirection;
use nalgebra::{Cholesky, DMatrix, DVector, Dyn};

/// The most contacts the enumeration takes at once (`4⁶ = 4096` combinations).
pub const MAX_CLOSED: usize = 6;

/// The relative round-off of the conditions (accelerations, forces), as
/// [`crate::multi::VELOCITY_ROUND_OFF`] for impulses.
pub const FORCE_ROUND_OFF: f64 = 1e-9;

/// Singular values below this fraction of the largest are zero (redundant contacts).
const RANK_TOL: f64 = 1e-11;

/// Two solutions whose accelerations differ by less than this fraction of their scale are one.
const SAME: f64 = 1e-8;

/// The regime of a closed contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Regime {
    /// Rolling or sticking: `v_t = 0` kept (`α_t = 0`) by a force `|λ_t| ≤ μ λ_n`.
    Stick,
    /// Sliding (or starting to slide) with `v_t` along `Positive` (`+t`) or `Negative`,
    /// friction `λ_t = −μ λ_n sign(v_t)`.
    Slip(SlipDirection),
    /// No friction (`μ = 0`): `λ_t = 0`.
    Frictionless,
}

impl Regime {
    /// `stick`, `slip+`, `slip-`, `frictionless`.
    pub fn label(self) -> &'static str {
        match self {
            Regime::Stick => "stick",
            Regime::Slip(SlipDirection::Negative) => "slip-",
            Regime::Slip(_) => "slip+",
            Regime::Frictionless => "frictionless",
        }
    }

    /// The friction ratio `λ_t/λ_n` of a slip (`−μ ŝ`), 0 for `frictionless`.
    fn ratio(self, mu: f64) -> f64 {
        match self {
            Regime::Slip(d) => -mu * d.sign(),
            _ => 0.0,
        }
    }
}

/// A closed contact and its regime.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Closed {
    pub contact: usize,
    pub regime: Regime,
}

/// The dynamics of a mechanism at `(q, u)` with a set of contacts (module docs).
pub(crate) struct ContactDynamics {
    pub contacts: Vec<usize>,
    pub a_free: DVector<f64>,
    minv_jt: DMatrix<f64>,
    pub w: DMatrix<f64>,
    pub alpha0: DVector<f64>,
    /// The contact velocities `J u` (tangent, normal of each).
    pub v: DVector<f64>,
}

/// The forces of one combination of regimes and what they do.
#[derive(Debug, Clone)]
pub(crate) struct Forces {
    /// `λ` (tangent, normal of each contact).
    pub lambda: DVector<f64>,
    /// The contact accelerations `α = α⁰ + W λ`.
    pub alpha: DVector<f64>,
    /// The generalized accelerations `a = a_free + M⁻¹ Jᵀ λ`.
    pub accel: DVector<f64>,
    /// The linear system's matrix determinant relative to its scale (1 without unknowns):
    /// its sign change marks a sliding regime's force coefficient through zero.
    pub det: f64,
    /// The same determinant relative to the size of the terms its entries are made of (1
    /// without unknowns): for one sliding contact `(W_nn − μ ŝ W_nt)/(|W_nn| + μ |W_nt|)`,
    /// near zero where the coefficient of its force vanishes by cancellation (the Painlevé
    /// bound).
    pub coefficient: f64,
}

/// One solution of the enumeration: the closed contacts (those not `off`) and the forces.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    pub closed: Vec<Closed>,
    /// One entry per contact of the problem (`None`: off).
    pub choices: Vec<Option<Regime>>,
    pub forces: Forces,
}

/// A preference among equivalent solutions at an event.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Hint {
    None,
    /// The contact's normal force vanished: prefer it off.
    Open(usize),
    /// The contact's friction reached its bound: prefer it slipping.
    Slip(usize),
}

impl ContactDynamics {
    /// The problem of `contacts` at `(q, u)`.
    pub fn new<M: Mechanism + ?Sized>(
        m: &M,
        q: &[f64],
        u: &[f64],
        contacts: &[usize],
    ) -> Result<Self> {
        let kin = dynamics::kinematics(m, q);
        let chol = dynamics::cholesky(dynamics::mass_matrix_of(m, &kin))?;
        let a_free = chol.solve(&dynamics::generalized_force(m, &kin, q, u));
        let (n, k) = (m.dof(), contacts.len());
        let mut jac = DMatrix::zeros(2 * k, n);
        let mut bias = DVector::zeros(2 * k);
        for (j, &c) in contacts.iter().enumerate() {
            jac.rows_mut(2 * j, 2)
                .copy_from(&dynamics::contact_jacobian_of(m, c, q, &kin));
            let [bt, bn] = dynamics::contact_velocity_products(m, c, q, u);
            bias[2 * j] = bt;
            bias[2 * j + 1] = bn;
        }
        let minv_jt = chol.solve(&jac.transpose());
        let w = &jac * &minv_jt;
        let w = 0.5 * (&w + w.transpose());
        let alpha0 = &jac * &a_free + bias;
        let v = &jac * DVector::from_column_slice(u);
        Ok(ContactDynamics {
            contacts: contacts.to_vec(),
            a_free,
            minv_jt,
            w,
            alpha0,
            v,
        })
    }

    /// The forces of a combination of regimes (`None`: off), least-norm when the system is
    /// singular; no inequality is checked.
    pub fn forces(&self, choices: &[Option<Regime>], mu: f64) -> Forces {
        let k = self.contacts.len();
        // Unknowns: a stick contact (λ_t, λ_n), the others λ_n along (ratio, 1); equations:
        // the stick rows t and n, the others' row n.
        let mut cols: Vec<(usize, f64, f64)> = Vec::with_capacity(2 * k); // (contact, c_t, c_n)
        let mut rows: Vec<usize> = Vec::with_capacity(2 * k);
        for (j, choice) in choices.iter().enumerate() {
            match choice {
                None => {}
                Some(Regime::Stick) => {
                    cols.push((j, 1.0, 0.0));
                    cols.push((j, 0.0, 1.0));
                    rows.push(2 * j);
                    rows.push(2 * j + 1);
                }
                Some(r) => {
                    cols.push((j, r.ratio(mu), 1.0));
                    rows.push(2 * j + 1);
                }
            }
        }
        let dim = cols.len();
        let mut lambda = DVector::zeros(2 * k);
        let (mut det, mut coefficient) = (1.0, 1.0);
        if dim > 0 {
            let mut a = DMatrix::zeros(dim, dim);
            let mut rhs = DVector::zeros(dim);
            // Each row's terms before they cancel.
            let mut terms = vec![0.0f64; dim];
            for (r, &i) in rows.iter().enumerate() {
                for (c, &(j, ct, cn)) in cols.iter().enumerate() {
                    let (x, y) = (ct * self.w[(i, 2 * j)], cn * self.w[(i, 2 * j + 1)]);
                    a[(r, c)] = x + y;
                    terms[r] += x.abs() + y.abs();
                }
                rhs[r] = -self.alpha0[i];
            }
            let scale: f64 = (0..dim)
                .map(|r| (0..dim).fold(0.0f64, |s, c| s.max(a[(r, c)].abs())))
                .product();
            let determinant = a.determinant();
            det = if scale > 0.0 {
                determinant / scale
            } else {
                0.0
            };
            let size: f64 = terms.iter().product();
            coefficient = if size > 0.0 { determinant / size } else { 0.0 };
            let y = least_norm(a, rhs);
            for (c, &(j, ct, cn)) in cols.iter().enumerate() {
                lambda[2 * j] += ct * y[c];
                lambda[2 * j + 1] += cn * y[c];
            }
        }
        let alpha = &self.alpha0 + &self.w * &lambda;
        let accel = &self.a_free + &self.minv_jt * &lambda;
        Forces {
            lambda,
            alpha,
            accel,
            det,
            coefficient,
        }
    }

    /// The scale `max_i (|α⁰_i| + Σ_k |W_ik| |λ_k|)` of the contact accelerations.
    fn acceleration_scale(&self, lambda: &DVector<f64>) -> f64 {
        (0..self.alpha0.len())
            .map(|i| {
                self.alpha0[i].abs()
                    + (0..lambda.len())
                        .map(|k| self.w[(i, k)].abs() * lambda[k].abs())
                        .sum::<f64>()
            })
            .fold(0.0, f64::max)
    }

    /// Whether the forces of `choices` satisfy every condition (module docs); `sliding[j]`
    /// is the direction of contact `j`'s slip when it slides (`None`: rolling).
    fn admissible(
        &self,
        choices: &[Option<Regime>],
        f: &Forces,
        mu: f64,
        sliding: &[Option<SlipDirection>],
    ) -> bool {
        let tol_a = FORCE_ROUND_OFF * self.acceleration_scale(&f.lambda);
        let tol_l = FORCE_ROUND_OFF * f.lambda.amax();
        choices.iter().enumerate().all(|(j, choice)| {
            let (at, an) = (f.alpha[2 * j], f.alpha[2 * j + 1]);
            let (lt, ln) = (f.lambda[2 * j], f.lambda[2 * j + 1]);
            match choice {
                None => an >= -tol_a,
                Some(r) => {
                    let normal = an.abs() <= tol_a && ln >= -tol_l;
                    normal
                        && match r {
                            Regime::Stick => at.abs() <= tol_a && lt.abs() <= mu * ln + tol_l,
                            Regime::Slip(d) => sliding[j].is_some() || d.sign() * at >= -tol_a,
                            Regime::Frictionless => true,
                        }
                }
            }
        })
    }

    /// Every solution of the conditions (module docs), one per distinct motion, the preferred
    /// member of each (the hint's, else least `|λ|`, else fewest closed contacts).
    ///
    /// # Errors
    /// More than [`MAX_CLOSED`] contacts.
    pub fn solutions(
        &self,
        mu: f64,
        sliding: &[Option<SlipDirection>],
        hint: Hint,
    ) -> Result<Vec<Solution>> {
        let k = self.contacts.len();
        if k > MAX_CLOSED {
            return Err(Error::Invalid {
                field: "contacts".into(),
                reason: format!(
                    "{k} contacts touch at once; the contact problem takes at most {MAX_CLOSED}"
                ),
            });
        }
        let options: Vec<Vec<Option<Regime>>> = (0..k)
            .map(|j| {
                if mu == 0.0 {
                    vec![None, Some(Regime::Frictionless)]
                } else if let Some(d) = sliding[j] {
                    vec![None, Some(Regime::Slip(d))]
                } else {
                    vec![
                        None,
                        Some(Regime::Stick),
                        Some(Regime::Slip(SlipDirection::Positive)),
                        Some(Regime::Slip(SlipDirection::Negative)),
                    ]
                }
            })
            .collect();
        let mut digits = vec![0usize; k];
        let mut groups: Vec<Vec<Solution>> = Vec::new();
        loop {
            let choices: Vec<Option<Regime>> = (0..k).map(|j| options[j][digits[j]]).collect();
            let forces = self.forces(&choices, mu);
            if self.admissible(&choices, &forces, mu, sliding) {
                let sol = Solution {
                    closed: choices
                        .iter()
                        .enumerate()
                        .filter_map(|(j, c)| {
                            c.map(|regime| Closed {
                                contact: self.contacts[j],
                                regime,
                            })
                        })
                        .collect(),
                    choices,
                    forces,
                };
                let scale = |f: &Forces| {
                    (0..f.accel.len())
                        .map(|i| f.accel[i].abs().max(self.a_free[i].abs()))
                        .fold(0.0, f64::max)
                };
                let found = groups.iter_mut().find(|g| {
                    let other = &g[0].forces;
                    let tol = SAME * scale(other).max(scale(&sol.forces));
                    (&other.accel - &sol.forces.accel).amax() <= tol
                });
                match found {
                    Some(g) => g.push(sol),
                    None => groups.push(vec![sol]),
                }
            }
            // Next combination (contact 0 fastest).
            let mut j = 0;
            loop {
                if j == k {
                    return Ok(groups
                        .into_iter()
                        .map(|g| preferred(g, hint, &self.contacts))
                        .collect());
                }
                digits[j] += 1;
                if digits[j] < options[j].len() {
                    break;
                }
                digits[j] = 0;
                j += 1;
            }
        }
    }
}

/// The preferred member of a group of solutions with the same motion.
fn preferred(mut group: Vec<Solution>, hint: Hint, contacts: &[usize]) -> Solution {
    let wants = |s: &Solution| -> bool {
        let choice = |c: usize| {
            contacts
                .iter()
                .position(|&x| x == c)
                .and_then(|j| s.choices[j])
        };
        match hint {
            Hint::None => true,
            Hint::Open(c) => choice(c).is_none(),
            Hint::Slip(c) => matches!(choice(c), Some(Regime::Slip(_))),
        }
    };
    let better = |a: &Solution, b: &Solution| -> bool {
        let (wa, wb) = (wants(a), wants(b));
        if wa != wb {
            return wa;
        }
        let (na, nb) = (a.forces.lambda.norm(), b.forces.lambda.norm());
        if (na - nb).abs() > SAME * na.max(nb) {
            return na < nb;
        }
        a.closed.len() < b.closed.len()
    };
    let mut best = 0;
    for i in 1..group.len() {
        if better(&group[i], &group[best]) {
            best = i;
        }
    }
    group.swap_remove(best)
}

/// The least-squares, least-norm solution of the square system `a y = r`: Gaussian
/// elimination with complete pivoting, pivots below `10⁻¹¹` of the largest entry ending it, the
/// free unknowns chosen to minimise `|y|` ([`crate::multi::lcp`]'s solver; systems of more than
/// its 12 unknowns, which the contact counts here never reach, by the singular value
/// decomposition).
fn least_norm(a: DMatrix<f64>, r: DVector<f64>) -> DVector<f64> {
    let n = a.ncols();
    debug_assert_eq!(a.nrows(), n);
    if n <= lcp::DIM {
        let mut aa = [[0.0; lcp::DIM]; lcp::DIM];
        let mut rr = [0.0; lcp::DIM];
        for i in 0..n {
            for j in 0..n {
                aa[i][j] = a[(i, j)];
            }
            rr[i] = r[i];
        }
        let mut y = [0.0; lcp::DIM];
        lcp::least_norm(&mut aa, &mut rr, n, &mut y);
        return DVector::from_column_slice(&y[..n]);
    }
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    if smax.is_nan() || smax <= 0.0 {
        return DVector::zeros(n);
    }
    svd.solve(&r, RANK_TOL * smax)
        .unwrap_or_else(|_| DVector::zeros(n))
}

/// The pseudo-inverse solution `M⁻¹ Rᵀ (R M⁻¹ Rᵀ)⁺ r`: the least change `Δ` in the mass metric
/// with `R Δ = r`.
fn mass_metric_correction(
    chol: &Cholesky<f64, Dyn>,
    rows: &DMatrix<f64>,
    r: &DVector<f64>,
) -> DVector<f64> {
    let minv_rt = chol.solve(&rows.transpose());
    let g = rows * &minv_rt;
    let g = 0.5 * (&g + g.transpose());
    minv_rt * least_norm(g, r.clone())
}

/// Project `(q, u)` onto the closed contacts (module docs): gaps to zero (at most three
/// Newton steps), normal velocities to zero, and the sticking contacts' tangential velocities
/// to zero.
///
/// # Errors
/// A singular mass matrix.
pub(crate) fn project<M: Mechanism + ?Sized>(
    m: &M,
    q: &mut [f64],
    u: &mut [f64],
    closed: &[Closed],
) -> Result<()> {
    if closed.is_empty() {
        return Ok(());
    }
    let n = m.dof();
    for _ in 0..3 {
        let gaps: Vec<f64> = closed
            .iter()
            .map(|c| dynamics::gap(m, c.contact, q))
            .collect();
        let small = closed
            .iter()
            .zip(&gaps)
            .all(|(c, g)| g.abs() <= 1e-3 * dynamics::touching_tolerance(m, c.contact, q));
        if small {
            break;
        }
        let kin = dynamics::kinematics(m, q);
        let chol = dynamics::cholesky(dynamics::mass_matrix_of(m, &kin))?;
        let mut rows = DMatrix::zeros(closed.len(), n);
        for (i, c) in closed.iter().enumerate() {
            let j = dynamics::contact_jacobian_of(m, c.contact, q, &kin);
            rows.row_mut(i).copy_from(&j.row(1));
        }
        let dq = mass_metric_correction(&chol, &rows, &DVector::from_vec(gaps));
        for i in 0..n {
            q[i] -= dq[i];
        }
    }
    let kin = dynamics::kinematics(m, q);
    let chol = dynamics::cholesky(dynamics::mass_matrix_of(m, &kin))?;
    let count: usize = closed
        .iter()
        .map(|c| if c.regime == Regime::Stick { 2 } else { 1 })
        .sum();
    let mut rows = DMatrix::zeros(count, n);
    let mut i = 0;
    for c in closed {
        let j = dynamics::contact_jacobian_of(m, c.contact, q, &kin);
        rows.row_mut(i).copy_from(&j.row(1));
        i += 1;
        if c.regime == Regime::Stick {
            rows.row_mut(i).copy_from(&j.row(0));
            i += 1;
        }
    }
    let uv = DVector::from_column_slice(u);
    let r = &rows * &uv;
    if r.amax() > 0.0 {
        let du = mass_metric_correction(&chol, &rows, &r);
        for i in 0..n {
            u[i] -= du[i];
        }
    }
    Ok(())
}

/// The state derivative of the motion with the closed contacts `closed` in their regimes:
/// `(q̇, u̇, ẇ) = (u, a_free + M⁻¹ Jᵀ λ, λ·J u)` for `y = (q, u, w)`, `w` the work of the
/// contact forces. Non-finite output signals a singular configuration.
pub(crate) fn derivative<M: Mechanism + ?Sized>(
    m: &M,
    closed: &[Closed],
    mu: f64,
    y: &[f64],
    dy: &mut [f64],
) {
    let n = m.dof();
    let (q, u) = (&y[..n], &y[n..2 * n]);
    dy[..n].copy_from_slice(u);
    if closed.is_empty() {
        dynamics::state_derivative(m, &y[..2 * n], &mut dy[..2 * n]);
        dy[2 * n] = 0.0;
        return;
    }
    let contacts: Vec<usize> = closed.iter().map(|c| c.contact).collect();
    match ContactDynamics::new(m, q, u, &contacts) {
        Ok(cd) => {
            let choices: Vec<Option<Regime>> = closed.iter().map(|c| Some(c.regime)).collect();
            let f = cd.forces(&choices, mu);
            dy[n..2 * n].copy_from_slice(f.accel.as_slice());
            dy[2 * n] = f.lambda.dot(&cd.v);
        }
        Err(_) => dy[n..].fill(f64::NAN),
    }
}

/// What the closed contacts are doing at a state, for the event watch: per closed contact its
/// normal force, its tangential velocity, its friction force; and the system's relative
/// determinant.
pub(crate) struct Watch {
    pub lambda: DVector<f64>,
    pub v: DVector<f64>,
    pub det: f64,
    /// [`Forces::coefficient`] of the closed contacts' regimes.
    pub coefficient: f64,
}

/// The watch quantities of the closed contacts at `y = (q, u, …)`.
pub(crate) fn watch<M: Mechanism + ?Sized>(
    m: &M,
    closed: &[Closed],
    mu: f64,
    y: &[f64],
) -> Result<Watch> {
    let n = m.dof();
    let contacts: Vec<usize> = closed.iter().map(|c| c.contact).collect();
    let cd = ContactDynamics::new(m, &y[..n], &y[n..2 * n], &contacts)?;
    let choices: Vec<Option<Regime>> = closed.iter().map(|c| Some(c.regime)).collect();
    let f = cd.forces(&choices, mu);
    Ok(Watch {
        lambda: f.lambda,
        v: cd.v,
        det: f.det,
        coefficient: f.coefficient,
    })
}
