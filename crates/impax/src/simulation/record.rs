//! What a simulation returns: samples, impacts, events, the energy ledger and the stop.

use super::closed::Regime;
use crate::law::LawId;
use crate::math::Vec2;
use crate::mechanism::{dynamics, Mechanism};
use crate::multi::MultiOutcome;

/// Why a simulation ended.
#[derive(Debug, Clone, PartialEq)]
pub enum StopReason {
    /// The end time was reached.
    TimeLimit,
    /// Every body is at rest: a round body on the floor with neither slip nor speed left, or
    /// bodies whose closed contacts' forces balance gravity (velocities below round-off of the
    /// run's speeds, no acceleration). The velocities are then set to zero.
    Rest,
    /// [`super::SimulationOptions::max_impacts`] impacts happened.
    ImpactLimit,
    /// The law does not apply at an impact (its breakdown reason), or an impact's contact
    /// problem is not one the laws take (a contact that one coordinate alone moves, like a
    /// double pendulum's elbow, has a singular `W`).
    Breakdown {
        /// Why.
        reason: String,
    },
    /// More contacts touch at once than the simulator resolves: more than
    /// [`crate::multi::lcp::MAX_CONTACTS`] struck together under `lcp` (or under a one-contact
    /// law, which uses `lcp` for several contacts), or more than
    /// [`super::closed::MAX_CLOSED`] staying closed together. The run ends at that instant.
    UnsupportedContact {
        /// The contact that struck (or the first of those closing).
        contact: usize,
        /// The other contacts touching their surfaces at that time.
        touching: Vec<usize>,
    },
    /// The force problem of the closed contacts has no solution (`solutions = 0`) or several
    /// (`solutions ≥ 2`): Painlevé's paradox of sliding with friction (a rod sliding on a
    /// rough floor with `μ` above a bound set by its inertia and angle). The way out is an
    /// impulsive "tangential impact" (Génot & Brogliato 1999), which is not modelled: the run
    /// ends at that instant, without integrating through. A sliding contact can also reach
    /// the bound as the body turns, its force growing without bound as the force's coefficient
    /// and the free normal acceleration vanish together (the "dynamic jam"): the run ends
    /// there with `solutions = 0` (no bounded force continues the slip).
    Painleve {
        /// A sliding contact of the problem (the first; or the first closed contact).
        contact: usize,
        /// The number of distinct solutions (0, or 2 and more).
        solutions: usize,
    },
}

impl StopReason {
    /// Stable id: `time-limit`, `rest`, `impact-limit`, `breakdown`, `unsupported-contact`,
    /// `painleve`.
    pub fn id(&self) -> &'static str {
        match self {
            StopReason::UnsupportedContact { .. } => "unsupported-contact",
            StopReason::TimeLimit => "time-limit",
            StopReason::Rest => "rest",
            StopReason::ImpactLimit => "impact-limit",
            StopReason::Breakdown { .. } => "breakdown",
            StopReason::Painleve { .. } => "painleve",
        }
    }
}

/// The regime of the motion at a sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Free motion (no contact closed).
    Flight,
    /// A round body sliding on the floor (closed form).
    Sliding,
    /// A round body rolling on the floor (closed form).
    Rolling,
    /// One or more contacts closed (sticking, sliding or frictionless), the motion integrated
    /// with their forces.
    Contact,
    /// At rest.
    Rest,
}

impl Mode {
    /// `flight`, `sliding`, `rolling`, `contact`, `rest`.
    pub fn id(self) -> &'static str {
        match self {
            Mode::Flight => "flight",
            Mode::Sliding => "sliding",
            Mode::Rolling => "rolling",
            Mode::Contact => "contact",
            Mode::Rest => "rest",
        }
    }
}

/// Something that happened during the run.
#[derive(Debug, Clone, PartialEq)]
pub enum EventKind {
    /// Impact number `index` (into [`Run::impacts`]).
    Impact {
        /// Index into the impacts.
        index: usize,
    },
    /// An accumulation of impacts, completed at its limit time.
    Zeno {
        /// The contact of the last impact.
        contact: usize,
        /// `t∞`, the sum of the geometric series of impact intervals.
        limit_time: f64,
        /// The common ratio of the intervals.
        ratio: f64,
    },
    /// A round body's persistent sliding contact begins (closed form).
    Sliding,
    /// A round body's rolling begins (the slip vanished).
    Rolling,
    /// A contact closes: it stays on its surface with zero normal velocity, pressed by a
    /// force, in `regime`.
    Closes {
        /// The contact.
        contact: usize,
        /// Its regime.
        regime: Regime,
    },
    /// A closed contact opens: its normal force vanished (it leaves with zero normal
    /// velocity).
    Opens {
        /// The contact.
        contact: usize,
    },
    /// A closed contact changes regime: its slip halts (then it sticks or slips back), or its
    /// friction reaches `μ λ_n` (then it slips).
    Regime {
        /// The contact.
        contact: usize,
        /// The new regime.
        regime: Regime,
    },
    /// The bodies come to rest.
    Rest,
}

/// One output sample of the trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Time.
    pub t: f64,
    /// Generalized coordinates.
    pub q: Vec<f64>,
    /// Generalized velocities.
    pub u: Vec<f64>,
    /// Kinetic energy `T`.
    pub kinetic: f64,
    /// Potential energy `V`.
    pub potential: f64,
    /// The regime.
    pub mode: Mode,
}

/// One impact and its energy ledger.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactRecord {
    /// Time of the impact.
    pub time: f64,
    /// The contact that struck.
    pub contact: usize,
    /// Every contact of the impact: the struck one first, then the others touching their
    /// surfaces at that time (closed or not), in order. One entry for an impact at one contact.
    pub contacts: Vec<usize>,
    /// The law applied: the run's; for an impact at several contacts under a one-contact law,
    /// `lcp`.
    pub law: LawId,
    /// Configuration at the impact.
    pub q: Vec<f64>,
    /// Generalized velocities before.
    pub u_before: Vec<f64>,
    /// Generalized velocities after.
    pub u_after: Vec<f64>,
    /// The contact velocities before, `(v_t, v_n)`, one per entry of `contacts`.
    pub contact_velocities_before: Vec<Vec2>,
    /// The law's result, one entry per entry of `contacts` (impulse, velocity after, phases,
    /// work; a one-contact law's outcome as [`MultiOutcome::from_outcome`] carries it over).
    pub outcome: MultiOutcome,
    /// Kinetic energy before.
    pub kinetic_before: f64,
    /// `ΔT` from the generalized velocities.
    pub energy_change: f64,
    /// Translational part of `ΔT`, `Σ_b ½ m_b Δ|v_b|²`.
    pub translational_change: f64,
    /// Rotational part of `ΔT`, `Σ_b ½ I_b Δω_b²`.
    pub rotational_change: f64,
    /// Total mechanical energy `T + V` before (`V` is continuous across the impact).
    pub total_energy_before: f64,
}

impl ImpactRecord {
    /// The contact velocity before of the struck contact.
    pub fn contact_velocity_before(&self) -> Vec2 {
        self.contact_velocities_before[0]
    }

    /// The struck contact's result (impulse, velocity after, phases, work).
    pub fn struck(&self) -> &crate::multi::ContactResult {
        &self.outcome.contacts[0]
    }
}

/// Where the mechanical energy went: `end = initial + impacts + contact_work + corrections`
/// up to the integration's tolerance ([`Ledger::residual`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Ledger {
    /// `T + V` at the start.
    pub initial: f64,
    /// `Σ ΔT` of the impacts.
    pub impacts: f64,
    /// The work of the contact forces while contacts are closed, `∫ λ·J u dt` (friction's;
    /// the normal forces do none, to tolerance), integrated with the motion; and the closed
    /// form's sliding of a round body.
    pub contact_work: f64,
    /// The changes of `T + V` made by the projections onto the closed contacts, the
    /// completions of accumulations of impacts and the zero velocities set at rest (round-off
    /// and tolerance-sized).
    pub corrections: f64,
    /// `T + V` at the end.
    pub end: f64,
}

impl Ledger {
    /// `end − initial − impacts − contact_work − corrections`: zero up to the integration's
    /// tolerance.
    pub fn residual(&self) -> f64 {
        self.end - self.initial - self.impacts - self.contact_work - self.corrections
    }
}

/// The result of a simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Output samples (at the sample interval, plus before and after every impact and at
    /// every event).
    pub samples: Vec<Sample>,
    /// Every impact.
    pub impacts: Vec<ImpactRecord>,
    /// Every event, with its time.
    pub events: Vec<(f64, EventKind)>,
    /// Why the run ended.
    pub stop: StopReason,
    /// When it ended.
    pub end_time: f64,
    /// Accepted and rejected integrator steps.
    pub steps: (usize, usize),
    /// The energy ledger.
    pub ledger: Ledger,
}

/// The samples of a run as they are taken: regular ones every `dt`, and those at events.
pub(crate) struct Recorder<'a, M: Mechanism + ?Sized> {
    pub m: &'a M,
    pub dt: f64,
    pub next: u64,
    pub samples: Vec<Sample>,
}

impl<M: Mechanism + ?Sized> Recorder<'_, M> {
    /// Record the state `y = (q, u, …)` at `t`.
    pub fn push(&mut self, t: f64, y: &[f64], mode: Mode) {
        let n = self.m.dof();
        let (q, u) = (&y[..n], &y[n..2 * n]);
        self.samples.push(Sample {
            t,
            q: q.to_vec(),
            u: u.to_vec(),
            kinetic: dynamics::kinetic_energy(self.m, q, u),
            potential: dynamics::potential_energy(self.m, q),
            mode,
        });
    }
    /// The next regular sample time.
    pub fn next_time(&self) -> f64 {
        self.next as f64 * self.dt
    }
}
