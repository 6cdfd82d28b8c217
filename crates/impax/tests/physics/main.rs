//! The physics tests of the `impax` library, one module per subject: independent derivations,
//! identities and invariances, property tests, published answers, and one `regression_*` module
//! per fixed bug whose header tells the bug, its reproducer and the expected physics. One test
//! crate (`cargo test -p impax --test physics`), so they build and link once; run one module
//! with a filter, e.g. `cargo test -p impax --test physics spatial_reference -- --nocapture`.

mod analysis;
mod bodies3;
mod box_shape;
mod brute_force;
mod impact_contract;
mod lcp;
mod lcp_spatial;
mod mechanism_files;
mod mechanism_specs;
mod mechanisms;
mod multi_contact;
mod multi_lzb;
mod multi_scenarios;
mod multi_spatial;
mod multi_spatial_lzb;
mod multibody;
mod multibody_conserved;
mod multibody_impact;
mod multibody_models;
mod multibody_simulation;
mod multibody_urdf;
mod multibody_validation;
mod paper_liu2012;
mod properties;
mod regression_brach_frictionless;
mod regression_energetic_overflow;
mod regression_energy_gain_round_off;
mod regression_energy_gain_small;
mod regression_lzb_cradle_friction;
mod regression_scale_invariance;
mod regression_simulation_penetration;
mod regression_smith_accuracy;
mod regression_smith_large_friction;
mod regression_spatial_brach_frictionless_phase;
mod regression_spatial_brach_plastic_compression;
mod regression_spatial_energetic_plastic;
mod regression_spatial_energetic_restitution_overflow;
mod regression_spatial_extreme_no_separation;
mod regression_spatial_frictionless_resumption;
mod regression_spatial_gain_integration_error;
mod regression_spatial_halt_direction;
mod regression_spatial_isotropic_slip_angle;
mod regression_spatial_lcp_grazing;
mod regression_spatial_marginal_stick;
mod regression_spatial_poisson_still_approaching;
mod regression_spatial_rotated_w_rejected;
mod regression_spatial_slip_scale;
mod regression_spatial_whittaker_overflow;
mod robot_load;
mod seed_sphere;
mod simulation;
mod simulation_closed;
mod simulation_painleve;
mod simulation_rocking_cradle;
mod spatial_invariants;
mod spatial_options;
mod spatial_planar_embedding;
mod spatial_properties;
mod spatial_reference;
mod spatial_validation;
mod support;
mod validation;
