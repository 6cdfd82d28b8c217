//! The energy audit of an impact (theory §1).

/// The energy audit of an impact: `ΔT = W_c + W_r + W_t` (theory §1).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct WorkSplit {
    /// Normal work during compression `W_c = ∫₀^{p_c} v_n dp_n ≤ 0`.
    pub compression: f64,
    /// Normal work during restitution `W_r = ∫_{p_c}^{p_f} v_n dp_n`.
    pub restitution: f64,
    /// Friction work `W_t = ∫ v_t dp_t`.
    pub friction: f64,
}

impl WorkSplit {
    /// Total normal work `W_n = W_c + W_r`.
    pub fn normal(&self) -> f64 {
        self.compression + self.restitution
    }
    /// `W_n + W_t`, which equals `ΔT`.
    pub fn total(&self) -> f64 {
        self.normal() + self.friction
    }
}

/// Whether the numbers of an outcome record (impulse and velocity components, the work
/// split, `ΔT`, the compression impulse) are all finite; shared by the planar and spatial
/// records.
pub(crate) fn record_is_finite<'a>(
    components: impl IntoIterator<Item = &'a f64>,
    work: &WorkSplit,
    energy_change: f64,
    compression_impulse: Option<f64>,
) -> bool {
    components.into_iter().all(|x| x.is_finite())
        && [
            work.compression,
            work.restitution,
            work.friction,
            energy_change,
        ]
        .iter()
        .all(|x| x.is_finite())
        && compression_impulse.is_none_or(f64::is_finite)
}
