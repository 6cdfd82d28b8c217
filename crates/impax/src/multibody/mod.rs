//! Spatial multibody systems: kinematic trees of rigid bodies in 3D (robots), read by hand or
//! from URDF, with their dynamics by the classical recursive algorithms and their impacts
//! with the floor reduced to contact space for every spatial law (theory §1, §4, §7).
//!
//! * [`Model`]: bodies ([`Body`]), joints ([`Joint`], [`JointKind`]: revolute, prismatic,
//!   fixed, free) in tree order, contact points ([`ContactPoint`]) against the floor `z = h`,
//!   gravity along `−z`; generalized coordinates `q` ([`Model::coordinates`]; a floating
//!   base's `x, y, z, qw, qx, qy, qz`) and speeds `u` ([`Model::speeds`]; its
//!   `vx, vy, vz, wx, wy, wz`, linear velocity of the base frame's origin and angular
//!   velocity, both in the world frame).
//! * [`urdf`]: the URDF reader (fixed joints merged, a floating base on request, contact
//!   points by link name).
//! * [`kinematics`]: forward kinematics generic over the dual numbers of
//!   [`crate::mechanism::Real`], so that automatic differentiation can check everything
//!   else.
//! * [`crba`](crba()): `M(q)` by the composite-rigid-body algorithm;
//!   [`jacobian`]: point and contact Jacobians, `W = J M⁻¹ Jᵀ`, `v⁻ = J u`;
//!   [`rnea`]: bias forces `C(q, u) u + g(q)`, inverse and forward dynamics, `q̇` from `u`
//!   (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, ch. 2–7, in world axes about one
//!   point, see [`Workspace`]).
//! * [`SpatialMechanismImpact`]: one foot striking the floor, resolved by any spatial law,
//!   the speeds after by `M (u⁺ − u⁻) = Jᵀ p`; [`SpatialMechanismMultiImpact`]: several
//!   contacts at once as a [`crate::multi::spatial::MultiProblem`].
//!
//! The `f64` algorithms share a reusable [`Workspace`] (no allocation once it exists, but
//! for the checked copy of `q`).

pub mod crba;
pub mod impact;
pub mod jacobian;
pub mod joint;
pub mod kinematics;
pub mod model;
pub mod multi_impact;
pub mod rnea;
pub mod urdf;
pub mod workspace;

pub use crba::{crba, factor, mass_matrix, solve};
pub use impact::{SpatialMechanismImpact, SpatialMechanismOutcome};
pub use jacobian::{
    contact_jacobian, contact_space, point_jacobian, point_jacobian_at, ContactSpace,
};
pub use joint::{Joint, JointKind, Placement};
pub use kinematics::{contact_position, forward_kinematics, gap, BodyPose};
pub use model::{Body, ContactPoint, Model, STANDARD_GRAVITY};
pub use multi_impact::SpatialMechanismMultiImpact;
pub use rnea::{
    bias_forces, configuration_rate, forward_dynamics, forward_dynamics_in, inverse_dynamics,
};
pub use urdf::{read_urdf, ContactSpec, MimicJoint, UrdfOptions, UrdfRobot};
pub use workspace::Workspace;

pub use crate::mechanism::Real;
