//! Point Jacobians and the contact-space problem of a contact with the floor.
//!
//! The velocity of the body-`b` material point at `x` (world) is
//! `ẋ = Σ_{l ∈ support(b)} (v_O,l + ω_l × (x − O)) u_l` with `(ω_l, v_O,l) = S_l` the motion
//! subspace in world axes about `O` (Featherstone, *Rigid Body Dynamics Algorithms*, 2008,
//! §8.1 and eq. 2.13): the world-frame linear-velocity Jacobian `J` (3 × nv). With the floor's
//! contact frame `t1 = x`, `t2 = y`, `n = z`, the rows of `J` at the contact point are the
//! contact frame's, and an impact reduces to contact space (theory §1):
//! `W = J M⁻¹ Jᵀ` (3 × 3), `v⁻ = J u⁻`.

use super::crba::{crba, factor, solve_l, solve_lt};
use super::kinematics::contact_position;
use super::model::Model;
use super::workspace::Workspace;
use crate::error::{Error, Result};
use crate::math::{Mat3, Vec3};
use nalgebra::Matrix3xX;

/// The world-frame linear-velocity Jacobian (3 × nv) of the material point of body `body`
/// at the world position `x`, at the workspace's configuration.
pub fn point_jacobian_at(model: &Model, ws: &Workspace, body: usize, x: &Vec3) -> Matrix3xX<f64> {
    let mut j = Matrix3xX::zeros(model.nv());
    let r = x - ws.origin;
    for &l in &model.data.support[body] {
        j.set_column(l, &ws.subspace[l].point_velocity(&r));
    }
    j
}

/// The world-frame linear-velocity Jacobian (3 × nv) of the point `point` (body frame) of
/// body `body`, at the workspace's configuration.
pub fn point_jacobian(model: &Model, ws: &Workspace, body: usize, point: &Vec3) -> Matrix3xX<f64> {
    let x = ws.poses[body].rotation_matrix() * point + ws.poses[body].position_vector();
    point_jacobian_at(model, ws, body, &x)
}

/// The Jacobian (3 × nv, rows `t1 = x`, `t2 = y`, `n = z`) of contact `k`'s material point:
/// `v = J u` is its velocity relative to the floor.
///
/// # Errors
/// No such contact.
pub fn contact_jacobian(model: &Model, ws: &Workspace, k: usize) -> Result<Matrix3xX<f64>> {
    check_contact_index(model, k)?;
    let c = contact_position(model, &ws.poses, k);
    let x = Vec3::new(c[0], c[1], c[2]);
    Ok(point_jacobian_at(model, ws, model.contacts[k].body, &x))
}

/// Check a contact index.
pub(crate) fn check_contact_index(model: &Model, k: usize) -> Result<()> {
    if k < model.contacts.len() {
        return Ok(());
    }
    Err(Error::Invalid {
        field: "contact".into(),
        reason: if model.contacts.is_empty() {
            "this model has no contact point".into()
        } else {
            format!(
                "index {k} out of range: the model has {} contact(s) ({})",
                model.contacts.len(),
                model
                    .contacts
                    .iter()
                    .map(|c| c.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        },
    })
}

/// A contact reduced to contact space at one state: `J`, `M⁻¹ Jᵀ`, `W = J M⁻¹ Jᵀ`,
/// `v⁻ = J u`.
#[derive(Debug, Clone)]
pub struct ContactSpace {
    /// `J` (3 × nv).
    pub jacobian: Matrix3xX<f64>,
    /// `M⁻¹ Jᵀ` (nv × 3, stored as its transpose `J M⁻¹`, 3 × nv): the change of `u` per unit
    /// impulse along each contact axis.
    pub response: Matrix3xX<f64>,
    /// `W = J M⁻¹ Jᵀ`.
    pub w: Mat3,
    /// `v⁻ = J u`.
    pub velocity: Vec3,
}

/// Reduce contact `k` to contact space at the workspace's configuration and the speeds `u`:
/// the mass matrix by [`crba`], its factor `M = Lᵀ L` ([`factor`]), `Z = L⁻ᵀ Jᵀ`,
/// `W = Zᵀ Z` and `M⁻¹ Jᵀ = L⁻¹ Z` by sweeps along the tree.
///
/// # Errors
/// No such contact; `u` of the wrong length or not finite; `M` singular ([`factor`]).
pub fn contact_space(
    model: &Model,
    ws: &mut Workspace,
    k: usize,
    u: &[f64],
) -> Result<ContactSpace> {
    let jacobian = contact_jacobian(model, ws, k)?;
    model.check_speeds(u)?;
    crba(model, ws);
    factor(model, ws)?;
    let n = model.nv();
    // M = Lᵀ L: Z = L⁻ᵀ Jᵀ (nonzero only on the contact body's support), W = Zᵀ Z (symmetric
    // positive semidefinite by construction), M⁻¹ Jᵀ = L⁻¹ Z.
    let mut z = Matrix3xX::zeros(n);
    let mut b = std::mem::take(&mut ws.scratch);
    for row in 0..3 {
        b.iter_mut()
            .enumerate()
            .for_each(|(i, x)| *x = jacobian[(row, i)]);
        solve_lt(model, ws, &mut b);
        b.iter().enumerate().for_each(|(i, x)| z[(row, i)] = *x);
    }
    let w = &z * z.transpose();
    let mut response = z;
    for row in 0..3 {
        b.iter_mut()
            .enumerate()
            .for_each(|(i, x)| *x = response[(row, i)]);
        solve_l(model, ws, &mut b);
        b.iter()
            .enumerate()
            .for_each(|(i, x)| response[(row, i)] = *x);
    }
    ws.scratch = b;
    let velocity = Vec3::from_fn(|row, _| (0..n).map(|i| jacobian[(row, i)] * u[i]).sum());
    Ok(ContactSpace {
        jacobian,
        response,
        w,
        velocity,
    })
}
