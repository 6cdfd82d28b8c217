//! The explorer module's tests on the host, one crate: the one-contact API (`api`) and the
//! view with several contacts (`multi`).

mod api;
mod multi;
