//! Adaptive integration of smooth ordinary differential equations `y' = f(t, y)`.
//!
//! [`Dopri5`] is the Dormand–Prince 5(4) pair with local extrapolation, the step-size
//! control of Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I* (2nd ed.,
//! 1993), §II.4 (error norm eq. 4.11, step factor eq. 4.13), and the fourth-order continuous
//! extension of §II.6 (Dormand & Prince 1986 / Shampine 1986) for output between steps and
//! for event location. State vectors are slices of any length; the workspace is allocated
//! once per integrator, never per step.
//!
//! (The integrator lives with the library's other numerical building blocks, in the private
//! module `numerics`; this is its public path.)

pub use crate::numerics::dopri5::{Dopri5, Step, Tolerances};
