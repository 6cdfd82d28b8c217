//! Spatial (3D) bodies: from a body's state to the spatial contact problem `(W, v⁻)` and
//! from the impulse back to body velocities, with the energy split into translational and
//! rotational parts per body.
//!
//! The contact frame is the world frame: tangents `x`, `y`, normal `z` (out of the struck
//! surface). Orientations are unit quaternions (body → world); inertia tensors and contact
//! points are given in the body frame.
//!
//! * [`RigidBody`]: any rigid body given mass, inertia tensor, orientation and contact
//!   point;
//! * shapes: [`sphere`], [`ellipsoid`] (contact where its normal is the plane's — Liu 1997,
//!   the seed's ref. 8), [`cuboid`] (a corner), [`cylinder`] (a rim point);
//! * [`BodyImpact`]: one body on a fixed plane, or two free bodies (`W = W_A + W_B`).

mod impact;
mod rigid;
mod shapes;

pub use impact::{BodyImpact, BodyOutcome};
pub use rigid::{BodyState, EnergyParts, RigidBody};
pub use shapes::{cuboid, cylinder, ellipsoid, sphere};
