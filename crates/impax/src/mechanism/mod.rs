//! Planar mechanisms in generalized coordinates, with their dynamics obtained by automatic
//! differentiation of one kinematic function.
//!
//! A [`Mechanism`] states, once and generically over dual numbers ([`Real`]), where each of
//! its rigid bodies is for given generalized coordinates `q` ([`Mechanism::poses`]), where
//! each contact point is ([`Mechanism::contact_point`]), and any potential beyond uniform
//! gravity ([`Mechanism::potential`]). Holonomic constraints such as rolling without slip on a
//! line are written into the kinematics (a ring's angle is `−x/R`). Everything else follows by
//! forward-mode automatic differentiation (theory.md §4; the `num-dual` crate):
//!
//! * body Jacobians `J_b = ∂(x_b, y_b, θ_b)/∂q` ⇒ mass matrix `M(q) = Σ_b J_bᵀ diag(m_b, m_b, I_b) J_b`;
//! * a hyper-dual derivative along `u` twice gives the velocity-product terms `J̇_b u`, and the
//!   equations of motion `M u̇ = Q(q) − Σ_b J_bᵀ diag(m_b, m_b, I_b) J̇_b u` with
//!   `Q = −∂V/∂q` ([`dynamics`]);
//! * the gap `φ(q)` of a contact and the Jacobian of the body's material point there give the
//!   contact-space problem `W = J M⁻¹ Jᵀ`, `v⁻ = J u` of an impact ([`impact`]);
//! * the Lagrangian `L = T − V` gives generalized momenta, cyclic coordinates and Noether
//!   charges ([`conserved`]).
//!
//! Built-in mechanisms: [`builtin::DoublePendulum`] (Kane & Levinson's), [`builtin::RingPendulum`]
//! (paper B's rolling ring carrying a pendulum), [`builtin::CartPendulum`] (the contrast case),
//! and the free [`builtin::Sphere`] and [`builtin::Rod`].
//!
//! Conventions: `y` up, gravity `g` along `−y`, angles in radians counter-clockwise, the
//! contact frame tangent first, normal last, with the tangent `t = (n_y, −n_x)`.

pub mod builtin;
pub mod conserved;
pub mod dynamics;
pub mod impact;
pub mod linkage;

use crate::math::Vec2;
pub use num_dual::{Dual64, DualNum, HyperDual64};

/// The scalars a mechanism's kinematics is evaluated with: `f64`, and the dual numbers
/// [`Dual64`] and [`HyperDual64`] that carry first and mixed second derivatives.
pub trait Real: DualNum<Primitive = f64> + Copy {}
impl<T: DualNum<Primitive = f64> + Copy> Real for T {}

/// The planar pose of a body: the position of its centre of mass and its orientation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose<D> {
    /// Centre of mass, horizontal.
    pub x: D,
    /// Centre of mass, vertical (up).
    pub y: D,
    /// Orientation, counter-clockwise.
    pub angle: D,
}

impl<D: Real> Pose<D> {
    /// A pose from its three parts.
    pub fn new(x: D, y: D, angle: D) -> Self {
        Pose { x, y, angle }
    }
}

/// Mass and central moment of inertia of one body of a mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyInertia {
    /// The body's name, e.g. `rod 1`.
    pub name: &'static str,
    /// Mass `m_b > 0`.
    pub mass: f64,
    /// Moment of inertia about the centre of mass, `I_b ≥ 0` (0 for a point mass).
    pub inertia: f64,
}

/// A fixed straight surface (a line in the plane) that a contact point can strike.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surface {
    /// A point of the line.
    pub point: Vec2,
    /// Its unit normal, out of the surface (towards the mechanism).
    pub normal: Vec2,
}

impl Surface {
    /// The horizontal floor `y = height`, normal up.
    pub fn floor(height: f64) -> Self {
        Surface {
            point: Vec2::new(0.0, height),
            normal: Vec2::new(0.0, 1.0),
        }
    }

    /// The contact-frame tangent `t = (n_y, −n_x)` (so that `(t, n)` is right-handed).
    pub fn tangent(&self) -> Vec2 {
        Vec2::new(self.normal.y, -self.normal.x)
    }
}

/// A contact of a mechanism: which body touches which surface.
///
/// The surface is a fixed line, or, when [`Mechanism::surface_body`] names a body of the
/// mechanism, a line carried by that body that keeps the direction of [`Surface::normal`]
/// (bodies that translate along a line and meet each other, like the balls of a cradle): its
/// point is then [`Mechanism::surface_point`], and the contact's velocity is that of the
/// touching body's point relative to the other body's point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// A name for messages and tables, e.g. `tip of rod 2`.
    pub name: &'static str,
    /// Index of the body that touches (into [`Mechanism::bodies`]).
    pub body: usize,
    /// The surface it touches (for a contact between two bodies, its normal; its point is
    /// [`Mechanism::surface_point`]).
    pub surface: Surface,
}

/// A planar mechanism: rigid bodies whose poses are one function of generalized
/// coordinates `q`, under uniform gravity, with optional extra potential and contacts.
///
/// Implementors write [`Mechanism::poses`] and [`Mechanism::contact_point`] once, generically
/// over [`Real`]; impax differentiates them.
pub trait Mechanism {
    /// Names of the generalized coordinates (their number is the number of degrees of
    /// freedom).
    fn coordinates(&self) -> &[&'static str];

    /// The bodies, in the order of [`Mechanism::poses`].
    fn bodies(&self) -> &[BodyInertia];

    /// Gravitational acceleration `g ≥ 0`, acting along `−y`.
    fn gravity(&self) -> f64;

    /// The pose of every body at `q` (`poses.len() == bodies().len()`).
    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]);

    /// Potential energy beyond uniform gravity (springs), default none.
    fn potential<D: Real>(&self, _q: &[D]) -> D {
        D::zero()
    }

    /// The contacts of the mechanism (default none).
    fn contacts(&self) -> &[Contact] {
        &[]
    }

    /// Where contact `k` touches at `q`: the point of the body nearest the surface (its gap is
    /// `φ(q) = (c(q) − point)·n`). The default has no contacts and is never called.
    fn contact_point<D: Real>(&self, _k: usize, _q: &[D]) -> [D; 2] {
        unreachable!("a mechanism without contacts has no contact point")
    }

    /// The body that carries the surface of contact `k`, for a contact between two bodies of
    /// the mechanism (default: `None`, the surface is fixed). The impulse or force of the
    /// contact acts on the touching body ([`Contact::body`]) and its opposite on this one.
    fn surface_body(&self, _k: usize) -> Option<usize> {
        None
    }

    /// The point of the surface of contact `k` at `q` that the contact point meets: the fixed
    /// surface's [`Surface::point`] (the default), or, for a contact between two bodies, the
    /// other body's point nearest the contact point (its gap is
    /// `φ(q) = (c(q) − surface_point(q))·n`).
    fn surface_point<D: Real>(&self, k: usize, _q: &[D]) -> [D; 2] {
        let p = self.contacts()[k].surface.point;
        [D::from(p.x), D::from(p.y)]
    }

    /// Number of generalized coordinates.
    fn dof(&self) -> usize {
        self.coordinates().len()
    }

    /// A round body (sphere, disc) on a horizontal floor, with `q = (x, y, θ)`: lets a
    /// simulation continue through persistent contact with Coulomb sliding and then rolling,
    /// in closed form. Default: not such a body.
    fn round_on_floor(&self) -> Option<RoundOnFloor> {
        None
    }
}

/// What a simulation needs to continue a round body's motion in persistent contact with a
/// horizontal floor: `q = (x, y, θ)`, contact point `(x, y − r)`, slip `ẋ + r θ̇`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundOnFloor {
    /// Mass `m`.
    pub mass: f64,
    /// Central moment of inertia `I`.
    pub inertia: f64,
    /// Radius `r`.
    pub radius: f64,
    /// Height of the floor.
    pub floor: f64,
}
