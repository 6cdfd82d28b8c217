//! The explorer module's tests on the host, one crate: the one-contact API (`api`), the view
//! with several contacts (`multi`), a mechanism file pasted in (`mechanism`) and the
//! conserved quantities of the ring-pendulum (`conserved`).

mod api;
mod conserved;
mod mechanism;
mod multi;
