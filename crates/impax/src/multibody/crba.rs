//! The mass matrix `M(q)` by the composite-rigid-body algorithm, and its sparse Cholesky
//! factor `M = Lᵀ L`.
//!
//! Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §6.2 (table 6.2), in absolute
//! coordinates (every spatial quantity in world axes about one point `O`, see
//! [`super::Workspace`]): the composite inertia of each body's subtree,
//! `I^c_b = I_b + Σ_{children c} I^c_c`, then for each speed `k` of the joint of body `b`,
//! `F = I^c_b S_k` and `M_lk = M_kl = S_lᵀ F` for every speed `l` supporting `b`. `M` is
//! symmetric positive definite when every coordinate moves some mass, and `T = ½ uᵀ M u`.

use super::model::Model;
use super::workspace::Workspace;
use crate::error::{Error, Num, Result};
use nalgebra::DMatrix;

/// `M(q)` (`nv × nv`) at the configuration of the workspace's last update.
pub fn crba<'a>(model: &Model, ws: &'a mut Workspace) -> &'a DMatrix<f64> {
    let d = &model.data;
    ws.composite.copy_from_slice(&ws.inertia);
    for joint in model.joints.iter().rev() {
        if let Some(p) = joint.parent {
            let c = ws.composite[joint.child];
            ws.composite[p].add(&c);
        }
    }
    for k in 0..model.nv() {
        let b = model.joints[d.dof_joint[k]].child;
        let f = ws.composite[b].apply(&ws.subspace[k]);
        for &l in d.support[b].iter().take_while(|&&l| l <= k) {
            let m = ws.subspace[l].dot(&f);
            ws.mass[(k, l)] = m;
            ws.mass[(l, k)] = m;
        }
    }
    // (Entries of speeds on different branches stay zero from `Workspace::new`.)
    &ws.mass
}

/// `M(q)` at `q` (a new workspace).
///
/// # Errors
/// As [`Model::check_state`].
///
/// ```
/// use impax::multibody::{mass_matrix, Body, Joint, Model};
/// use impax::math::{Mat3, Vec3};
/// // A free body: M = diag(m, m, m, I) in world axes about its centre of mass.
/// let i = Mat3::from_diagonal(&Vec3::new(1.0, 2.0, 3.0));
/// let model = Model::new(vec![Body::new("b", 5.0, Vec3::zeros(), i)], vec![Joint::free("root", 0)], vec![])?;
/// let m = mass_matrix(&model, &model.neutral())?;
/// assert_eq!((m[(0, 0)], m[(3, 3)], m[(5, 5)], m[(0, 4)]), (5.0, 1.0, 3.0, 0.0));
/// # Ok::<(), impax::Error>(())
/// ```
pub fn mass_matrix(model: &Model, q: &[f64]) -> Result<DMatrix<f64>> {
    let mut ws = Workspace::new(model);
    ws.update(model, q)?;
    Ok(crba(model, &mut ws).clone())
}

/// The smallest pivot of the factorisation accepted, relative to its own coordinate's
/// diagonal entry `M_kk` (what the coordinate moves beyond its descendants, against what it
/// moves alone).
pub const MASS_PIVOT_TOL: f64 = 1e-13;

/// The smallest diagonal entry `M_kk` accepted, relative to the largest: a coordinate that
/// moves only round-off of the others' masses (levers down to `1e-13` of the unit of length
/// are accepted).
pub const MASS_DIAGONAL_TOL: f64 = 1e-26;

/// Factor the workspace's mass matrix as `M = Lᵀ L` into the workspace, `L` lower triangular
/// with the sparsity of `M` itself (no fill-in): the LTL factorisation of Featherstone 2008,
/// §6.5 (table 6.3), which eliminates the speeds from the last to the first, each only
/// against its ancestors `λ(k)`:
///
/// ```text
/// for k = n … 1:  L_kk = √H_kk;  L_ki = H_ki / L_kk (i = λ(k), λ(λ(k)), …);
///                 H_ij −= L_ki L_kj  for every ancestor i of k and every ancestor j ≤ i.
/// ```
///
/// Its cost is `Σ_k depth(k)²` instead of `n³/6`; solves cost `Σ_k depth(k)`.
///
/// A pivot is judged against its own coordinate's diagonal entry ([`MASS_PIVOT_TOL`]) and
/// that entry against the largest ([`MASS_DIAGONAL_TOL`]): the test does not depend on the
/// coordinates' units (a free sphere of radius 1e-7 m has rotational entries 4e-15 of its
/// translational ones, which a test against the largest entry refused).
///
/// # Errors
/// `M` not positive definite beyond round-off: the error names the speed whose pivot fails,
/// the coordinate that moves no mass beyond its descendants (a massless link's joint, an axis
/// through a point mass).
pub fn factor(model: &Model, ws: &mut Workspace) -> Result<()> {
    let n = model.nv();
    let ancestors = &model.data.dof_ancestors;
    let scale = (0..n).map(|i| ws.mass[(i, i)]).fold(0.0, f64::max);
    ws.factor.copy_from(&ws.mass);
    // (Column-major storage: entry (r, c) at c n + r.)
    let h = ws.factor.as_mut_slice();
    for k in (0..n).rev() {
        let d = h[k * n + k];
        let own = ws.mass[(k, k)];
        if d.is_nan() || d <= MASS_PIVOT_TOL * own || own <= MASS_DIAGONAL_TOL * scale {
            return Err(Error::NotPositiveDefinite {
                field: "mass matrix".into(),
                reason: format!(
                    "the coordinate {} (speed {k}) moves no mass at this configuration (pivot {} of the LTL factorisation against its diagonal entry {}, the largest {}): a massless link's joint, or an axis through a point mass",
                    model.speeds()[k],
                    Num(d),
                    Num(own),
                    Num(scale)
                ),
            });
        }
        let lkk = d.sqrt();
        h[k * n + k] = lkk;
        let anc = &ancestors[k];
        for &a in anc {
            h[a * n + k] /= lkk;
        }
        // (The ancestors of `a` are the entries after it in `anc`.)
        for (i, &a) in anc.iter().enumerate() {
            let lka = h[a * n + k];
            for &b in &anc[i..] {
                h[b * n + a] -= lka * h[b * n + k];
            }
        }
    }
    Ok(())
}

/// `b ← L⁻ᵀ b` with the factor of [`factor`] (`Lᵀ y = b`, from the last speed to the first).
pub(crate) fn solve_lt(model: &Model, ws: &Workspace, b: &mut [f64]) {
    let n = b.len();
    let (ancestors, l) = (&model.data.dof_ancestors, ws.factor.as_slice());
    for k in (0..n).rev() {
        let y = b[k] / l[k * n + k];
        b[k] = y;
        for &a in &ancestors[k] {
            b[a] -= l[a * n + k] * y;
        }
    }
}

/// `b ← L⁻¹ b` with the factor of [`factor`] (`L x = b`, from the first speed to the last).
pub(crate) fn solve_l(model: &Model, ws: &Workspace, b: &mut [f64]) {
    let n = b.len();
    let (ancestors, l) = (&model.data.dof_ancestors, ws.factor.as_slice());
    for k in 0..n {
        let s: f64 = ancestors[k].iter().map(|&a| l[a * n + k] * b[a]).sum();
        b[k] = (b[k] - s) / l[k * n + k];
    }
}

/// Solve `M x = b` in place with the factor of [`factor`]: `x = L⁻¹ L⁻ᵀ b`.
pub fn solve(model: &Model, ws: &Workspace, b: &mut [f64]) {
    solve_lt(model, ws, b);
    solve_l(model, ws, b);
}
