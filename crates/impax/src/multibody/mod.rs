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
//! The `f64` algorithms share a reusable [`Workspace`]: [`Workspace::update`], [`crba()`],
//! [`factor`], [`solve`], [`bias_forces`] and [`inverse_dynamics`] allocate nothing once it
//! exists; a contact's reduction ([`contact_space`]) allocates its three `3 × nv` matrices.
//! A solo12 foot impact (floating base, 18 speeds) from `(q, u)` to `u⁺` under `energetic`
//! takes about 16 µs (`cargo bench -p impax --bench robots`), half of it the law's
//! Darboux–Keller integration.
//!
//! ```
//! use impax::multibody::{read_urdf, ContactSpec, SpatialMechanismImpact, UrdfOptions};
//! use impax::LawId;
//! let text = r#"<robot name="hopper">
//!   <link name="body"><inertial><mass value="3"/>
//!     <inertia ixx="0.05" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.05"/></inertial></link>
//!   <link name="leg"><inertial><origin xyz="0 0 -0.25"/><mass value="0.5"/>
//!     <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/></inertial></link>
//!   <joint name="hip" type="revolute"><parent link="body"/><child link="leg"/>
//!     <axis xyz="0 1 0"/></joint>
//! </robot>"#;
//! let options = UrdfOptions::default()
//!     .floating_base(true)
//!     .contact(ContactSpec::parse("leg:0,0,-0.5")?);
//! let robot = read_urdf(text, &options)?;
//! assert_eq!(robot.model.speeds(), ["vx", "vy", "vz", "wx", "wy", "wz", "hip"]);
//! // Standing on its foot (the base 0.5 m up, upright), falling at 1 m/s and swinging.
//! let q = [0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 0.2];
//! let u = [0.3, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0];
//! let impact = SpatialMechanismImpact::new(&robot.model, &q, &u, 0)?;
//! let out = impact.resolve(LawId::Energetic, 0.6, 0.3)?;
//! assert!(out.energy_change_from_velocities.unwrap() < 0.0);
//! # Ok::<(), impax::Error>(())
//! ```

pub mod conserved;
pub mod crba;
pub mod energy;
pub mod impact;
pub mod jacobian;
pub mod joint;
pub mod kinematics;
pub mod model;
pub mod multi_impact;
pub mod rnea;
pub mod simulate;
pub mod urdf;
pub mod workspace;

pub use crba::{crba, factor, mass_matrix, solve};
pub use energy::{body_velocities, kinetic_energy, potential_energy, total_energy, BodyVelocity};
pub use impact::{SpatialMechanismImpact, SpatialMechanismOutcome};
pub use jacobian::{
    contact_jacobian, contact_space, point_jacobian, point_jacobian_at, ContactSpace,
};
pub use joint::{Joint, JointKind, Placement};
pub use kinematics::{contact_position, forward_kinematics, gap, gap_rates, BodyPose};
pub use model::{Body, ContactPoint, Model, STANDARD_GRAVITY};
pub use multi_impact::{SpatialMechanismMultiImpact, SpatialMechanismMultiOutcome};
pub use rnea::{
    bias_forces, configuration_acceleration, configuration_rate, forward_dynamics,
    forward_dynamics_in, inverse_dynamics,
};
pub use simulate::simulate;
pub use urdf::{read_urdf, ContactSpec, LinkFrame, MimicJoint, UrdfOptions, UrdfRobot};
pub use workspace::Workspace;

pub use crate::mechanism::Real;
