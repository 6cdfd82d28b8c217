//! The mass matrix `M(q)` by the composite-rigid-body algorithm, and its Cholesky factor.
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

/// The smallest Cholesky pivot accepted, relative to the largest diagonal entry of `M`.
pub const MASS_PIVOT_TOL: f64 = 1e-13;

/// Factor the workspace's mass matrix, `M = L Lᵀ`, into the workspace.
///
/// # Errors
/// `M` not positive definite beyond round-off: the error names the speed whose pivot fails
/// (the coordinate that moves no mass beyond what the earlier ones move, e.g. a massless
/// link's joint).
pub fn factor(model: &Model, ws: &mut Workspace) -> Result<()> {
    let n = model.nv();
    let scale = (0..n).map(|i| ws.mass[(i, i)]).fold(0.0, f64::max);
    let l = &mut ws.factor;
    for j in 0..n {
        let mut d = ws.mass[(j, j)];
        for k in 0..j {
            d -= l[(j, k)] * l[(j, k)];
        }
        if d.is_nan() || d <= MASS_PIVOT_TOL * scale {
            return Err(Error::NotPositiveDefinite {
                field: "mass matrix".into(),
                reason: format!(
                    "the coordinate {} (speed {j}) moves no mass at this configuration beyond the earlier ones (Cholesky pivot {} against a largest diagonal entry {}): a massless link's joint, or an axis through a point mass",
                    model.speeds()[j],
                    Num(d),
                    Num(scale)
                ),
            });
        }
        let djj = d.sqrt();
        l[(j, j)] = djj;
        for i in j + 1..n {
            let mut s = ws.mass[(i, j)];
            for k in 0..j {
                s -= l[(i, k)] * l[(j, k)];
            }
            l[(i, j)] = s / djj;
        }
    }
    Ok(())
}

/// Solve `M x = b` in place with the factor of [`factor`].
pub fn solve(ws: &Workspace, b: &mut [f64]) {
    let l = &ws.factor;
    let n = b.len();
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[(i, k)] * b[k];
        }
        b[i] = s / l[(i, i)];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= l[(k, i)] * b[k];
        }
        b[i] = s / l[(i, i)];
    }
}
