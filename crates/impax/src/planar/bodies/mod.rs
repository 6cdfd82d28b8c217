//! Planar bodies: from a body's state to the contact-space problem `(W, v⁻)` and from the
//! impulse back to body velocities, with the energy split into translational and rotational
//! parts (paper A §5).
//!
//! * [`RigidBody`]: any rigid body given mass, central moment of inertia and the contact
//!   point relative to the centre of mass (in the contact frame);
//! * shapes that build one: [`sphere`] and [`disc`], [`rod`], [`ellipse`], [`rectangle`] (a
//!   box striking with one corner);
//! * [`BodyImpact`]: one body against a fixed surface, or two free bodies
//!   (`W = W_A + W_B`).

mod ellipse;
mod impact;
mod rectangle;
mod rigid;
mod rod;
mod sphere;

pub use ellipse::ellipse;
pub use impact::{BodyImpact, BodyOutcome, EnergyParts};
pub use rectangle::rectangle;
pub use rigid::{BodyState, RigidBody, Side};
pub use rod::rod;
pub use sphere::{disc, sphere, spin_state};
