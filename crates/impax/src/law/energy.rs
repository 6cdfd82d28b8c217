//! The energy-gain test shared by the planar and spatial laws.
//!
//! A law gains energy (Kane's paradox) when `ΔT = ½ (v⁻ + v⁺)·p` exceeds the round-off of
//! its own evaluation: `v⁺ = v⁻ + W p` carries round-off of order `ε (|v⁻| + |W| |p|)`, so the
//! bound is relative to the problem's own energy scale, whatever its units,
//!
//! ```text
//! ΔT > 16 ε Σ_i (|v⁻_i| + |v⁺_i| + (|W| |p|)_i) |p_i|.
//! ```
//!
//! The planar test is [`crate::planar::laws::is_energy_gain`], the spatial one
//! [`crate::spatial::laws::is_energy_gain`].

/// The factor of the round-off bound of `ΔT` above which a rise of kinetic energy is
/// reported as a gain: `16 ε`.
pub const ENERGY_GAIN_ROUND_OFF: f64 = 16.0 * f64::EPSILON;
