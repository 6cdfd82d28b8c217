//! The command line's tests, one crate: each module one command or one regression (their
//! headers say what they check), the harness they share in [`support`].

mod support;

mod audit;
mod audit_multi;
mod book_commands;
mod commands;
mod compare3d;
mod compare_multi;
mod contract;
mod explore;
mod golden;
mod mechanisms;
#[cfg(feature = "parquet")]
mod parquet;
mod plots;
mod regression_message_numbers;
mod regression_non_finite_output;
mod regression_simulate_floor;
mod regression_sweep_inputs;
mod resolve3d;
mod resolve_contacts;
mod robots;
mod robots_motion;
mod shape_box;
mod simulate;
mod sweep;
