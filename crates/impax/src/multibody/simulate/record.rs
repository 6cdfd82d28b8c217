//! What a spatial simulation returns: samples, impacts, events, the energy ledger and the
//! stop — the planar [`crate::simulation`]'s records where they fit (its [`Sample`],
//! [`EventKind`]), spatial ones named alike where they do not.

use crate::law::LawId;
use crate::math::Vec3;
use crate::multi::spatial::MultiOutcome;
use crate::simulation::{EventKind, Sample};

/// Why a contact is persistent: it would stay on the floor, which the spatial simulation
/// does not integrate (contacts that stay closed in 3D, with the circular friction cone at the
/// acceleration level, are not modelled).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Persistence {
    /// An impact left it with zero normal velocity (to round-off of the run's speeds): a
    /// plastic impact, or a contact the impulses of the others hold on the floor.
    Closed,
    /// An impact left it leaving, but its bounce `φ̇²/(2|φ̈|)` is lower than the touching
    /// tolerance: it cannot leave the floor measurably.
    LowBounce {
        /// The height of the bounce, metres.
        height: f64,
    },
    /// Its impacts accumulate (Zeno): the intervals between the last impacts shrink
    /// geometrically with a steady ratio (as the planar run detects them) and the rest of the
    /// series, `Δt_k r/(1 − r)`, is below a thousandth of the sample interval.
    Accumulation {
        /// `t∞ = t_k + Δt_k r/(1 − r)`, where the bouncing would end.
        limit_time: f64,
        /// The common ratio `r` of the intervals.
        ratio: f64,
    },
    /// It touches the floor without approaching (`|φ̇|` below round-off) and its gap's
    /// acceleration `φ̈` presses it into the floor.
    Pressed,
}

impl Persistence {
    /// Stable id: `closed`, `low-bounce`, `accumulation`, `pressed`.
    pub fn id(&self) -> &'static str {
        match self {
            Persistence::Closed => "closed",
            Persistence::LowBounce { .. } => "low-bounce",
            Persistence::Accumulation { .. } => "accumulation",
            Persistence::Pressed => "pressed",
        }
    }
}

/// Why a spatial simulation ended.
#[derive(Debug, Clone, PartialEq)]
pub enum StopReason {
    /// The end time was reached.
    TimeLimit,
    /// [`crate::simulation::SimulationOptions::max_impacts`] impacts happened.
    ImpactLimit,
    /// The law does not apply at an impact (its breakdown reason), or the impact's contact
    /// problem is not one the laws take (e.g. a contact that fewer than three degrees of
    /// freedom move has a singular `W`).
    Breakdown {
        /// Why.
        reason: String,
    },
    /// More contacts touch at once than the law resolves (more than
    /// [`crate::multi::spatial::lcp::MAX_CONTACTS`] under `lcp`, or than `lzb` takes).
    UnsupportedContact {
        /// The contact that struck.
        contact: usize,
        /// The other contacts touching the floor at that time.
        touching: Vec<usize>,
    },
    /// A contact would stay on the floor: contacts that stay closed are not integrated in
    /// 3D, so the run ends at that instant (the last sample is the state there, on or above
    /// the floor) rather than integrate through the floor.
    PersistentContact {
        /// The contact.
        contact: usize,
        /// Why it is persistent.
        cause: Persistence,
    },
}

impl StopReason {
    /// Stable id: `time-limit`, `impact-limit`, `breakdown`, `unsupported-contact`,
    /// `persistent-contact`.
    pub fn id(&self) -> &'static str {
        match self {
            StopReason::TimeLimit => "time-limit",
            StopReason::ImpactLimit => "impact-limit",
            StopReason::Breakdown { .. } => "breakdown",
            StopReason::UnsupportedContact { .. } => "unsupported-contact",
            StopReason::PersistentContact { .. } => "persistent-contact",
        }
    }
}

/// One impact of a spatial simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactRecord {
    /// Time of the impact.
    pub time: f64,
    /// The contact that struck.
    pub contact: usize,
    /// Every contact of the impact: the struck one first, then the others touching the floor
    /// at that time, in order. One entry for an impact at one contact.
    pub contacts: Vec<usize>,
    /// The law applied: the run's; for an impact at several contacts under a one-contact law,
    /// `lcp`.
    pub law: LawId,
    /// Configuration at the impact (quaternions normalised).
    pub q: Vec<f64>,
    /// Speeds before.
    pub u_before: Vec<f64>,
    /// Speeds after, `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
    pub u_after: Vec<f64>,
    /// The contact velocities before, `(v_t1, v_t2, v_n)`, one per entry of `contacts`.
    pub contact_velocities_before: Vec<Vec3>,
    /// The law's result, one entry per entry of `contacts` (a one-contact law's outcome as
    /// [`MultiOutcome::from_outcome`] carries it over).
    pub outcome: MultiOutcome,
    /// Kinetic energy before, `½ u⁻ᵀ M u⁻`.
    pub kinetic_before: f64,
    /// `ΔT` from the speeds, `½ (u⁺ − u⁻)ᵀ M (u⁺ + u⁻)`.
    pub energy_change: f64,
    /// `ΔT` of the law in contact space, `½ (v⁻ + v⁺)·p` (the ledger's; equal to
    /// `energy_change` up to round-off).
    pub law_energy_change: f64,
    /// Total mechanical energy `T + V` before (`V` is continuous across the impact).
    pub total_energy_before: f64,
}

impl ImpactRecord {
    /// The contact velocity before of the struck contact.
    pub fn contact_velocity_before(&self) -> Vec3 {
        self.contact_velocities_before[0]
    }

    /// The struck contact's result (impulse, velocity after, phases, work).
    pub fn struck(&self) -> &crate::multi::spatial::ContactResult {
        &self.outcome.contacts[0]
    }
}

/// Where the mechanical energy went: `end = initial + impacts + drift` up to round-off
/// ([`Ledger::residual`]).
///
/// `drift` is measured, not inferred: it is the sum over the flights between impacts of the
/// change of `T + V` along the integrated motion (zero for the exact motion, which conserves
/// it), and `impacts` is the sum of the laws' own `ΔT` in contact space. The residual is
/// therefore `Σ (ΔT from the speeds − ΔT of the law)` over the impacts plus round-off: it
/// checks that every impact's speeds after carry the energy its law says.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Ledger {
    /// `T + V` at the start.
    pub initial: f64,
    /// `Σ ΔT` of the impacts (each law's, in contact space).
    pub impacts: f64,
    /// The integration's change of `T + V` over the flights.
    pub drift: f64,
    /// `T + V` at the end.
    pub end: f64,
}

impl Ledger {
    /// `end − initial − impacts − drift`: zero up to round-off.
    pub fn residual(&self) -> f64 {
        self.end - self.initial - self.impacts - self.drift
    }
}

/// The result of a spatial simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Output samples (at the sample interval, plus before and after every impact and at the
    /// stop; quaternions normalised).
    pub samples: Vec<Sample>,
    /// Every impact.
    pub impacts: Vec<ImpactRecord>,
    /// Every event, with its time: [`EventKind::Impact`], and [`EventKind::Zeno`] when
    /// impacts accumulate.
    pub events: Vec<(f64, EventKind)>,
    /// Why the run ended.
    pub stop: StopReason,
    /// When it ended.
    pub end_time: f64,
    /// Accepted and rejected integrator steps.
    pub steps: (usize, usize),
    /// The energy ledger.
    pub ledger: Ledger,
    /// The largest departure `|‖q_quat‖ − 1|` of a free joint's quaternion after a step, before
    /// it was renormalised (0 without a free joint).
    pub quaternion_drift: f64,
}
