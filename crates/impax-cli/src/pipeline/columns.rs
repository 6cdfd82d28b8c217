//! The output columns of a sweep (CSV of `impax sweep`, quantities of `impax map`).

use crate::pipeline::evaluate::PointView;
use impax::analysis::ImpactSummary;

/// One output column after the swept fields and `law`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    Status,
    Sequence,
    PT,
    PN,
    VtAfter,
    VnAfter,
    CompressionImpulse,
    WorkCompression,
    WorkRestitution,
    WorkFriction,
    EnergyChange,
    EnergyRatio,
    VxAfter,
    VyAfter,
    OmegaAfter,
}

impl Column {
    /// Every column, in CSV order.
    pub const ALL: [Column; 15] = [
        Column::Status,
        Column::Sequence,
        Column::PT,
        Column::PN,
        Column::VtAfter,
        Column::VnAfter,
        Column::CompressionImpulse,
        Column::WorkCompression,
        Column::WorkRestitution,
        Column::WorkFriction,
        Column::EnergyChange,
        Column::EnergyRatio,
        Column::VxAfter,
        Column::VyAfter,
        Column::OmegaAfter,
    ];

    /// The CSV header name (a public contract).
    pub fn name(self) -> &'static str {
        match self {
            Column::Status => "status",
            Column::Sequence => "sequence",
            Column::PT => "p_t",
            Column::PN => "p_n",
            Column::VtAfter => "vt_after",
            Column::VnAfter => "vn_after",
            Column::CompressionImpulse => "compression_impulse",
            Column::WorkCompression => "work_compression",
            Column::WorkRestitution => "work_restitution",
            Column::WorkFriction => "work_friction",
            Column::EnergyChange => "energy_change",
            Column::EnergyRatio => "energy_ratio",
            Column::VxAfter => "vx_after",
            Column::VyAfter => "vy_after",
            Column::OmegaAfter => "omega_after",
        }
    }

    /// A label with units for a colour bar.
    pub fn label(self) -> &'static str {
        match self {
            Column::Status => "status",
            Column::Sequence => "phase sequence",
            Column::PT => "tangential impulse p_t",
            Column::PN => "normal impulse p_n",
            Column::VtAfter => "slip velocity after v_t⁺",
            Column::VnAfter => "normal velocity after v_n⁺",
            Column::CompressionImpulse => "impulse at the end of compression p_c",
            Column::WorkCompression => "normal work in compression W_c",
            Column::WorkRestitution => "normal work in restitution W_r",
            Column::WorkFriction => "friction work W_t",
            Column::EnergyChange => "energy change ΔT",
            Column::EnergyRatio => "ΔT / T0 (–)",
            Column::VxAfter => "body A velocity after v_x⁺",
            Column::VyAfter => "body A velocity after v_y⁺",
            Column::OmegaAfter => "body A angular velocity after ω⁺",
        }
    }

    /// Whether the column is text (`status`, `sequence`).
    pub fn is_text(self) -> bool {
        matches!(self, Column::Status | Column::Sequence)
    }

    /// Whether the column needs the body state after the impact.
    pub fn needs_body(self) -> bool {
        matches!(self, Column::VxAfter | Column::VyAfter | Column::OmegaAfter)
    }

    /// Parse a column name.
    pub fn parse(name: &str) -> Option<Column> {
        Column::ALL
            .iter()
            .copied()
            .find(|c| c.name() == name.trim())
    }

    /// All names, comma separated.
    pub fn names() -> String {
        Column::ALL.map(|c| c.name()).join(", ")
    }

    /// The numeric value (NaN when not resolved). `body` is body A's `(v_x, v_y, ω)` after.
    #[inline]
    pub fn value(self, s: &ImpactSummary, point: Option<PointView<'_>>, body: [f64; 3]) -> f64 {
        match self {
            Column::Status | Column::Sequence => f64::NAN,
            Column::PT => s.impulse.x,
            Column::PN => s.impulse.y,
            Column::VtAfter => s.velocity_after.x,
            Column::VnAfter => s.velocity_after.y,
            Column::CompressionImpulse => s.compression_impulse,
            Column::WorkCompression => s.work.compression,
            Column::WorkRestitution => s.work.restitution,
            Column::WorkFriction => s.work.friction,
            Column::EnergyChange => s.energy_change,
            Column::EnergyRatio => point.map_or(f64::NAN, |p| s.energy_change / p.t0),
            Column::VxAfter => body[0],
            Column::VyAfter => body[1],
            Column::OmegaAfter => body[2],
        }
    }
}

/// Body A's `(v_x, v_y, ω)` after the summary's impulse (NaN when not resolved).
#[inline]
pub fn body_after(s: &ImpactSummary, point: Option<PointView<'_>>) -> [f64; 3] {
    match point {
        Some(PointView {
            impact: Some(imp), ..
        }) if s.status.is_resolved() => {
            let (a, _) = imp.apply(s.impulse);
            [a.velocity.x, a.velocity.y, a.omega]
        }
        _ => [f64::NAN; 3],
    }
}
