//! Energies and momenta of a spatial multibody at a state: kinetic energy `T = ½ uᵀ M u`,
//! potential energy of gravity `V = g Σ_b m_b z_b` (`z_b` the height of body `b`'s centre of
//! mass above `z = 0`), each body's centre-of-mass velocity and angular velocity, the total
//! linear momentum `P = Σ_b m_b v_b` and the angular momentum about a fixed point `o`,
//! `L_o = Σ_b [m_b (c_b − o) × v_b + R_b I_b R_bᵀ ω_b]` (`I_b` about the centre of mass in the
//! body frame, `R_b` the body's orientation).

use super::crba::crba;
use super::impact::quadratic;
use super::model::Model;
use super::workspace::{Motion, Workspace};
use crate::math::Vec3;

/// Kinetic energy `T = ½ uᵀ M(q) u` at the workspace's configuration (the mass matrix by
/// [`crba`] into the workspace). `u` must have `nv` entries (unchecked).
pub fn kinetic_energy(model: &Model, ws: &mut Workspace, u: &[f64]) -> f64 {
    crba(model, ws);
    0.5 * quadratic(&ws.mass, u, u)
}

/// Potential energy of gravity `V = g Σ_b m_b z_b` at the workspace's configuration, with its
/// magnitude `g Σ_b m_b |z_b|`.
pub fn potential_energy(model: &Model, ws: &Workspace) -> (f64, f64) {
    let g = model.gravity;
    let (mut v, mut magnitude) = (0.0, 0.0);
    for (body, pose) in model.bodies.iter().zip(&ws.poses) {
        let z = pose.point(&body.com)[2];
        v += g * body.mass * z;
        magnitude += (g * body.mass * z).abs();
    }
    (v, magnitude)
}

/// `T + V` at `(q, u)` (the workspace updated to `q`).
///
/// # Errors
/// As [`Model::check_state`].
pub fn total_energy(
    model: &Model,
    ws: &mut Workspace,
    q: &[f64],
    u: &[f64],
) -> crate::error::Result<f64> {
    ws.update(model, q)?;
    Ok(kinetic_energy(model, ws, u) + potential_energy(model, ws).0)
}

/// The velocity of one body: its angular velocity `ω` and its centre of mass's velocity `v`,
/// with the centre of mass `c`, all in the world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyVelocity {
    /// Angular velocity `ω`.
    pub angular: Vec3,
    /// Velocity of the centre of mass `v = v_O + ω × (c − O)`.
    pub linear: Vec3,
    /// The centre of mass `c`.
    pub com: Vec3,
}

/// Every body's velocity at the workspace's configuration and the speeds `u`: its spatial
/// velocity `Σ_{l ∈ support(b)} S_l u_l` (motion subspaces in world axes about `O`), then the
/// velocity of its centre of mass. `u` must have `nv` entries (unchecked).
pub fn body_velocities(model: &Model, ws: &Workspace, u: &[f64]) -> Vec<BodyVelocity> {
    model
        .bodies
        .iter()
        .enumerate()
        .map(|(b, body)| {
            let mut m = Motion::default();
            for &l in &model.data.support[b] {
                m = m.add_scaled(&ws.subspace[l], u[l]);
            }
            let com = ws.poses[b].rotation_matrix() * body.com + ws.poses[b].position_vector();
            BodyVelocity {
                angular: m.w,
                linear: m.point_velocity(&(com - ws.origin)),
                com,
            }
        })
        .collect()
}
