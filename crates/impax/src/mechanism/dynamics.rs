//! Mass matrix, generalized forces, velocity-product terms and equations of motion of a
//! [`Mechanism`], by forward-mode automatic differentiation of its kinematics.
//!
//! With `p_b(q) = (x_b, y_b, θ_b)` the pose of body `b` and `D_b = diag(m_b, m_b, I_b)`:
//!
//! * `J_b = ∂p_b/∂q`, one dual-number pass per coordinate (seed `q_i + ε`);
//! * `M(q) = Σ_b J_bᵀ D_b J_b` (so `T = ½ uᵀ M u`);
//! * `J̇_b u = Σ_ij ∂²p_b/∂q_i∂q_j u_i u_j`, one hyper-dual pass seeded `q + ε₁u + ε₂u`;
//! * `V(q) = Σ_b m_b g y_b + V_extra(q)`, `Q = −∂V/∂q` (in the same passes as `J_b`);
//! * `M u̇ = Q − Σ_b J_bᵀ D_b J̇_b u` (Lagrange's equations written with the body Jacobians,
//!   i.e. Kane's form; theory.md §4).

use super::{Mechanism, Pose};
use crate::error::{Error, Result};
use crate::math::Vec2;
use nalgebra::{DMatrix, DVector};
use num_dual::{Dual64, HyperDual64};

/// Everything first-order at one configuration `q`: body poses and Jacobians, the potential
/// and its gradient.
#[derive(Debug, Clone)]
pub struct Kinematics {
    /// Pose of every body.
    pub poses: Vec<Pose<f64>>,
    /// `J_b = ∂(x_b, y_b, θ_b)/∂q` of every body (3 × n).
    pub jacobians: Vec<DMatrix<f64>>,
    /// Total potential energy `V(q)` (gravity plus the mechanism's own).
    pub potential: f64,
    /// `∂V/∂q`.
    pub potential_gradient: DVector<f64>,
}

/// Check that `q` (and `u`) have the mechanism's length and are finite.
///
/// # Errors
/// A wrong length (naming `q` or `u` and listing the coordinates); a non-finite entry
/// (naming it, e.g. `u[1] (theta2)`).
pub fn check_state<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: Option<&[f64]>) -> Result<()> {
    let n = m.dof();
    for (field, v) in [("q", Some(q)), ("u", u)] {
        let Some(v) = v else { continue };
        if v.len() != n {
            return Err(Error::Invalid {
                field: field.into(),
                reason: format!(
                    "needs {n} generalized coordinates ({}), got {}",
                    m.coordinates().join(", "),
                    v.len()
                ),
            });
        }
        for (i, &x) in v.iter().enumerate() {
            if !x.is_finite() {
                return Err(Error::NotFinite {
                    field: format!("{field}[{}] ({})", i, m.coordinates()[i]),
                    value: x,
                });
            }
        }
    }
    Ok(())
}

/// How far from the origin, in radii of gyration, a body may be before round-off of its
/// absolute position eats its geometry: `|r_b| ≤ 4·10⁷ k_b` (`k_b = √(I_b/m_b)`), where the
/// round-off of positions, `ε |r_b|`, reaches 10⁻⁸ of the body's size.
const FAR: f64 = 4e7;

/// Check that no body of `m` at `q` is so far from the origin that its geometry (a contact
/// point's lever about its centre of mass) is lost to the round-off of absolute positions: a
/// sphere of radius 1 at y = 1e20 has its lowest point at its centre in double precision,
/// and every impact would be computed without its rotation. Point masses are not checked.
pub(crate) fn check_precision<M: Mechanism + ?Sized>(m: &M, q: &[f64]) -> Result<()> {
    let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
    m.poses(q, &mut poses);
    for (b, pose) in m.bodies().iter().zip(&poses) {
        let k = (b.inertia / b.mass).sqrt();
        let far = pose.x.hypot(pose.y);
        if k > 0.0 && far > FAR * k {
            return Err(Error::Invalid {
                field: "q".into(),
                reason: format!(
                    "the {} is {} from the origin, {} times its radius of gyration: so far out its geometry is lost to round-off (at most {} times); move the origin",
                    b.name,
                    crate::error::Num(far),
                    crate::error::Num(far / k),
                    crate::error::Num(FAR)
                ),
            });
        }
    }
    Ok(())
}

/// `V(q)` for any scalar: `Σ_b m_b g y_b + V_extra(q)`.
pub(crate) fn potential_of<M: Mechanism + ?Sized, D: super::Real>(
    m: &M,
    q: &[D],
    poses: &[Pose<D>],
) -> D {
    let g = m.gravity();
    let mut v = m.potential(q);
    for (b, pose) in m.bodies().iter().zip(poses) {
        v += pose.y * (b.mass * g);
    }
    v
}

/// Poses, body Jacobians, potential and its gradient at `q` (`n` dual-number passes).
pub fn kinematics<M: Mechanism + ?Sized>(m: &M, q: &[f64]) -> Kinematics {
    let n = m.dof();
    let nb = m.bodies().len();
    let zero = Pose::new(Dual64::from(0.0), Dual64::from(0.0), Dual64::from(0.0));
    let mut poses_d = vec![zero; nb];
    let mut qd: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let mut jacobians = vec![DMatrix::zeros(3, n); nb];
    let mut gradient = DVector::zeros(n);
    let mut poses = vec![Pose::new(0.0, 0.0, 0.0); nb];
    let mut potential = 0.0;
    for i in 0..n.max(1) {
        if n > 0 {
            qd[i].eps = 1.0;
        }
        m.poses(&qd, &mut poses_d);
        let v = potential_of(m, &qd, &poses_d);
        if i == 0 {
            potential = v.re;
            for (p, d) in poses.iter_mut().zip(&poses_d) {
                *p = Pose::new(d.x.re, d.y.re, d.angle.re);
            }
        }
        if n > 0 {
            gradient[i] = v.eps;
            for (jac, d) in jacobians.iter_mut().zip(&poses_d) {
                jac[(0, i)] = d.x.eps;
                jac[(1, i)] = d.y.eps;
                jac[(2, i)] = d.angle.eps;
            }
            qd[i].eps = 0.0;
        }
    }
    Kinematics {
        poses,
        jacobians,
        potential,
        potential_gradient: gradient,
    }
}

/// The mass matrix `M(q) = Σ_b J_bᵀ diag(m_b, m_b, I_b) J_b` from the body Jacobians.
pub fn mass_matrix_of<M: Mechanism + ?Sized>(m: &M, kin: &Kinematics) -> DMatrix<f64> {
    let n = m.dof();
    let mut mass = DMatrix::zeros(n, n);
    for (b, jac) in m.bodies().iter().zip(&kin.jacobians) {
        let d = [b.mass, b.mass, b.inertia];
        for i in 0..n {
            for j in i..n {
                let s: f64 = (0..3).map(|r| d[r] * jac[(r, i)] * jac[(r, j)]).sum();
                mass[(i, j)] += s;
            }
        }
    }
    for i in 0..n {
        for j in 0..i {
            mass[(i, j)] = mass[(j, i)];
        }
    }
    mass
}

/// The mass matrix `M(q)`.
pub fn mass_matrix<M: Mechanism + ?Sized>(m: &M, q: &[f64]) -> DMatrix<f64> {
    mass_matrix_of(m, &kinematics(m, q))
}

/// The velocity-product terms `J̇_b u = Σ_ij ∂²p_b/∂q_i∂q_j u_i u_j` of every body, as
/// `(ẍ, ÿ, θ̈)` at `u̇ = 0` (one hyper-dual pass seeded `q + ε₁u + ε₂u`).
pub fn velocity_products<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> Vec<[f64; 3]> {
    let qh: Vec<HyperDual64> = q
        .iter()
        .zip(u)
        .map(|(&x, &v)| HyperDual64::new(x, v, v, 0.0))
        .collect();
    let zero = HyperDual64::from(0.0);
    let mut poses = vec![Pose::new(zero, zero, zero); m.bodies().len()];
    m.poses(&qh, &mut poses);
    poses
        .iter()
        .map(|p| [p.x.eps1eps2, p.y.eps1eps2, p.angle.eps1eps2])
        .collect()
}

/// The mass matrix's Cholesky factor, or an error naming the state when `M` is singular
/// (a coordinate that moves no mass).
///
/// Near-singular factors are refused coordinate by coordinate: the pivot `L_ii²` (what
/// coordinate `i` moves beyond the coordinates before it) below `1e-13` of its own diagonal
/// entry `M_ii`, or `M_ii` itself below `1e-26` of the largest diagonal entry (a rate that
/// moves only round-off). The first test does not depend on the coordinates' units (a rod of
/// 1 µm has `M_θθ = m l²/12 ≈ 1e-13 m`, which a test against the largest entry refused); the
/// second accepts levers down to `1e-13` of the unit of length.
pub(crate) fn cholesky(mass: DMatrix<f64>) -> Result<nalgebra::Cholesky<f64, nalgebra::Dyn>> {
    let diag: Vec<f64> = mass.diagonal().iter().copied().collect();
    let scale = diag.iter().copied().fold(0.0, f64::max);
    let chol = mass.cholesky().ok_or_else(|| Error::NotPositiveDefinite {
        field: "mass matrix".into(),
        reason: "a generalized coordinate moves no mass at this configuration".into(),
    })?;
    let l = chol.l_dirty();
    for (i, &d) in diag.iter().enumerate() {
        let pivot = l[(i, i)] * l[(i, i)];
        if pivot.is_nan() || pivot <= 1e-13 * d || d <= 1e-26 * scale {
            return Err(Error::NotPositiveDefinite {
                field: "mass matrix".into(),
                reason: format!(
                    "singular at this configuration (coordinate {}: pivot {pivot:e}, its diagonal entry {d:e}, the largest {scale:e})",
                    i + 1
                ),
            });
        }
    }
    Ok(chol)
}

/// Generalized accelerations `u̇` from `M u̇ = −∂V/∂q − Σ_b J_bᵀ D_b J̇_b u`.
///
/// # Errors
/// Wrong lengths or non-finite `q`, `u`; a singular mass matrix.
pub fn accelerations<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> Result<DVector<f64>> {
    check_state(m, q, Some(u))?;
    let kin = kinematics(m, q);
    let chol = cholesky(mass_matrix_of(m, &kin))?;
    Ok(chol.solve(&generalized_force(m, &kin, q, u)))
}

/// The right-hand side `Q − Σ_b J_bᵀ D_b J̇_b u` of the equations of motion.
pub(crate) fn generalized_force<M: Mechanism + ?Sized>(
    m: &M,
    kin: &Kinematics,
    q: &[f64],
    u: &[f64],
) -> DVector<f64> {
    let mut rhs = -kin.potential_gradient.clone();
    for ((b, jac), acc) in m
        .bodies()
        .iter()
        .zip(&kin.jacobians)
        .zip(velocity_products(m, q, u))
    {
        let d = [b.mass, b.mass, b.inertia];
        for i in 0..rhs.len() {
            rhs[i] -= (0..3).map(|r| jac[(r, i)] * d[r] * acc[r]).sum::<f64>();
        }
    }
    rhs
}

/// Kinetic energy `T = ½ uᵀ M(q) u`.
pub fn kinetic_energy<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> f64 {
    let mass = mass_matrix(m, q);
    let u = DVector::from_column_slice(u);
    0.5 * u.dot(&(&mass * &u))
}

/// Potential energy `V(q) = Σ_b m_b g y_b + V_extra(q)`.
pub fn potential_energy<M: Mechanism + ?Sized>(m: &M, q: &[f64]) -> f64 {
    let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
    m.poses(q, &mut poses);
    potential_of(m, q, &poses)
}

/// Velocity `(ẋ, ẏ)` and angular velocity `ω` of every body: `J_b u`.
pub fn body_velocities(kin: &Kinematics, u: &[f64]) -> Vec<[f64; 3]> {
    kin.jacobians
        .iter()
        .map(|jac| {
            let mut v = [0.0; 3];
            for (r, vr) in v.iter_mut().enumerate() {
                *vr = (0..u.len()).map(|i| jac[(r, i)] * u[i]).sum();
            }
            v
        })
        .collect()
}

/// The gap `φ(q) = (c(q) − s(q))·n` of contact `k` (negative: penetration), with `s` the
/// surface's point ([`Mechanism::surface_point`]: fixed, or the other body's point).
pub fn gap<M: Mechanism + ?Sized>(m: &M, k: usize, q: &[f64]) -> f64 {
    let n = m.contacts()[k].surface.normal;
    let c = m.contact_point(k, q);
    let s = m.surface_point(k, q);
    (c[0] - s[0]) * n.x + (c[1] - s[1]) * n.y
}

/// The normal velocity of contact `k`, `φ̇ = ∇φ(q)·u` (one dual-number pass seeded `q + εu`;
/// negative: approaching its surface).
pub fn gap_rate<M: Mechanism + ?Sized>(m: &M, k: usize, q: &[f64], u: &[f64]) -> f64 {
    let n = m.contacts()[k].surface.normal;
    let qd: Vec<Dual64> = q.iter().zip(u).map(|(&x, &v)| Dual64::new(x, v)).collect();
    let c = m.contact_point(k, &qd);
    let s = m.surface_point(k, &qd);
    (c[0].eps - s[0].eps) * n.x + (c[1].eps - s[1].eps) * n.y
}

/// Relative size, on the contact's own length scale, of a gap that counts as touching.
const TOUCHING: f64 = 1e-12;

/// The gap below which contact `k` counts as touching its surface at `q`:
/// `10⁻¹² |c − r_b| + 64 ε (|c| + |s|)`, with `|c − r_b|` the distance of the contact point
/// from its body's centre of mass (the lever of the contact: a rod's half-length, a ball's
/// radius) and the second term the round-off of the gap's evaluation far from the origin.
/// Two contacts whose gaps are both within it touch at once.
pub fn touching_tolerance<M: Mechanism + ?Sized>(m: &M, k: usize, q: &[f64]) -> f64 {
    let contact = m.contacts()[k];
    let c = m.contact_point(k, q);
    let s = m.surface_point(k, q);
    let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
    m.poses(q, &mut poses);
    let b = poses[contact.body];
    touching_tolerance_of(c, s, [b.x, b.y])
}

/// [`touching_tolerance`] of a contact point `c` on a body whose centre of mass is at `b`,
/// its surface's point `s`.
pub(crate) fn touching_tolerance_of(c: [f64; 2], s: [f64; 2], b: [f64; 2]) -> f64 {
    let lever = (c[0] - b[0]).hypot(c[1] - b[1]);
    let far = c[0].hypot(c[1]) + s[0].hypot(s[1]);
    TOUCHING * lever + 64.0 * f64::EPSILON * far
}

/// The gap of contact `k` and its first two time derivatives along the motion
/// `(q, u, u̇)`: `φ`, `φ̇ = ∇φ·u`, `φ̈ = ∇φ·u̇ + uᵀ ∇²φ u` (a dual pass seeded `q + εu̇`
/// and a hyper-dual pass seeded `q + ε₁u + ε₂u`).
pub fn gap_rates<M: Mechanism + ?Sized>(
    m: &M,
    k: usize,
    q: &[f64],
    u: &[f64],
    udot: &[f64],
) -> [f64; 3] {
    let nrm = m.contacts()[k].surface.normal;
    let project = |c: [f64; 2]| c[0] * nrm.x + c[1] * nrm.y;
    let qh: Vec<HyperDual64> = q
        .iter()
        .zip(u)
        .map(|(&x, &v)| HyperDual64::new(x, v, v, 0.0))
        .collect();
    let ch = m.contact_point(k, &qh);
    let sh = m.surface_point(k, &qh);
    let qd: Vec<Dual64> = q
        .iter()
        .zip(udot)
        .map(|(&x, &a)| Dual64::new(x, a))
        .collect();
    let cd = m.contact_point(k, &qd);
    let sd = m.surface_point(k, &qd);
    [
        project([ch[0].re - sh[0].re, ch[1].re - sh[1].re]),
        project([ch[0].eps1 - sh[0].eps1, ch[1].eps1 - sh[1].eps1]),
        project([cd[0].eps - sd[0].eps, cd[1].eps - sd[1].eps])
            + project([
                ch[0].eps1eps2 - sh[0].eps1eps2,
                ch[1].eps1eps2 - sh[1].eps1eps2,
            ]),
    ]
}

/// The contact Jacobian of contact `k` at `q` (2 × n, rows tangent then normal): the
/// velocity of the touching body's material point at `c(q)`,
/// `v_c = v_b + ω_b × (c − r_b)`, projected on the contact frame; for a contact between two
/// bodies ([`Mechanism::surface_body`]), minus the velocity of the other body's material
/// point at the surface point `s(q)`.
pub fn contact_jacobian_of<M: Mechanism + ?Sized>(
    m: &M,
    k: usize,
    q: &[f64],
    kin: &Kinematics,
) -> DMatrix<f64> {
    let contact = m.contacts()[k];
    let (t, nrm) = (contact.surface.tangent(), contact.surface.normal);
    let n = m.dof();
    let mut out = DMatrix::zeros(2, n);
    let mut add = |body: usize, point: [f64; 2], sign: f64| {
        let pose = kin.poses[body];
        let r = Vec2::new(point[0] - pose.x, point[1] - pose.y);
        let jac = &kin.jacobians[body];
        for i in 0..n {
            let vx = jac[(0, i)] - r.y * jac[(2, i)];
            let vy = jac[(1, i)] + r.x * jac[(2, i)];
            out[(0, i)] += sign * (t.x * vx + t.y * vy);
            out[(1, i)] += sign * (nrm.x * vx + nrm.y * vy);
        }
    };
    add(contact.body, m.contact_point(k, q), 1.0);
    if let Some(other) = m.surface_body(k) {
        add(other, m.surface_point(k, q), -1.0);
    }
    out
}

/// The velocity-product terms `J̇ u` of contact `k`'s rows at `(q, u)`: `(J̇_t u, J̇_n u)`,
/// what the rows' rates `d(J u)/dt = J u̇ + J̇ u` are at `u̇ = 0`.
///
/// * Normal: `J̇_n u = uᵀ ∇²φ u`, the second derivative of the gap along `u` (as
///   [`gap_rates`]; `J_n = ∇φ` at a contact).
/// * Tangent: the tangential velocity is that of the body's *material* point at the contact,
///   `J_t(q) u = t·(v_b + ω_b ẑ × (c(q) − r_b))` (`v_b`, `ω_b` from the body Jacobian `J_b u`).
///   Its rate at `u̇ = 0` is
///   `t·(a_b⁰ + α_b⁰ ẑ × (c − r_b) + ω_b ẑ × (ċ − ṙ_b))`, with `(a_b⁰, α_b⁰) = J̇_b u` and
///   `ċ` the velocity of the (geometric) contact point — which differs from the material
///   point's for a rolling body. Minus the same for the other body of a contact between two.
///
/// Everything comes from one hyper-dual pass of the poses and the contact points seeded
/// `q + ε₁u + ε₂u` (`.eps1` = rate along `u`, `.eps1eps2` = second rate): no finite
/// differences.
pub fn contact_velocity_products<M: Mechanism + ?Sized>(
    m: &M,
    k: usize,
    q: &[f64],
    u: &[f64],
) -> [f64; 2] {
    let contact = m.contacts()[k];
    let (t, nrm) = (contact.surface.tangent(), contact.surface.normal);
    let qh: Vec<HyperDual64> = q
        .iter()
        .zip(u)
        .map(|(&x, &v)| HyperDual64::new(x, v, v, 0.0))
        .collect();
    let zero = HyperDual64::from(0.0);
    let mut poses = vec![Pose::new(zero, zero, zero); m.bodies().len()];
    m.poses(&qh, &mut poses);
    // The rate at u̇ = 0 of the material velocity of `body`'s point currently at `p`.
    let material = |body: usize, p: [HyperDual64; 2]| -> [f64; 2] {
        let b = poses[body];
        let (w, alpha) = (b.angle.eps1, b.angle.eps1eps2);
        let (rx, ry) = (p[0].re - b.x.re, p[1].re - b.y.re);
        let (drx, dry) = (p[0].eps1 - b.x.eps1, p[1].eps1 - b.y.eps1);
        [
            b.x.eps1eps2 - alpha * ry - w * dry,
            b.y.eps1eps2 + alpha * rx + w * drx,
        ]
    };
    let c = m.contact_point(k, &qh);
    let s = m.surface_point(k, &qh);
    let mut tangential = material(contact.body, c);
    if let Some(other) = m.surface_body(k) {
        let o = material(other, s);
        tangential = [tangential[0] - o[0], tangential[1] - o[1]];
    }
    let normal = [c[0].eps1eps2 - s[0].eps1eps2, c[1].eps1eps2 - s[1].eps1eps2];
    [
        t.x * tangential[0] + t.y * tangential[1],
        nrm.x * normal[0] + nrm.y * normal[1],
    ]
}

/// The state derivative `(q̇, u̇) = (u, M⁻¹(Q − Σ J_bᵀ D_b J̇_b u))` for `y = (q, u)`, for the
/// integrators of [`crate::ode`]. Non-finite output signals a singular configuration.
pub fn state_derivative<M: Mechanism + ?Sized>(m: &M, y: &[f64], dy: &mut [f64]) {
    let n = m.dof();
    let (q, u) = y.split_at(n);
    dy[..n].copy_from_slice(u);
    let kin = kinematics(m, q);
    match cholesky(mass_matrix_of(m, &kin)) {
        Ok(chol) => {
            let a = chol.solve(&generalized_force(m, &kin, q, u));
            dy[n..].copy_from_slice(a.as_slice());
        }
        Err(_) => dy[n..].fill(f64::NAN),
    }
}
