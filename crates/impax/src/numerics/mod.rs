//! The numerical building blocks the laws and the simulation share: the Runge–Kutta
//! integrators, Chebyshev–Lobatto panels and the scalar root finders. Nothing here knows
//! about impacts.
//!
//! * [`dop853`] — the explicit Runge–Kutta pair of order 8(5,3) with its seventh-order dense
//!   output on fixed-size arrays, allocation-free (the spatial Darboux–Keller slip stage);
//! * [`dopri5`] — the Dormand–Prince 5(4) pair with dense output on slices, public as
//!   [`crate::ode::Dopri5`] (mechanisms' free motion, the simulation);
//! * [`chebyshev`] — quadrature and interpolation on 17-node Chebyshev–Lobatto panels (the
//!   spatial slip in the angle variable);
//! * [`roots`] — every scalar root finder of the library, each with its contract;
//! * [`budget`] — the step budget of a whole integrated motion, with an early verdict.

pub(crate) mod budget;
pub(crate) mod chebyshev;
pub(crate) mod dop853;
pub(crate) mod dopri5;
pub(crate) mod roots;
