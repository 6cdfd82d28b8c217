//! Conserved quantities of a mechanism (paper B): generalized momenta, cyclic coordinates,
//! Noether charges of given symmetries (with a gauge term), total energy, Newtonian linear
//! momentum and angular momentum about given points — evaluated along the integrated motion.
//!
//! With `L(q, u) = T − V` (mechanisms here are autonomous):
//!
//! * generalized momentum `p_i = ∂L/∂u_i = (M u)_i`; coordinate `i` is cyclic when
//!   `∂L/∂q_i ≡ 0`, and then `p_i` is conserved;
//! * Noether: an infinitesimal transformation `q → q + ε ξ(q, t)` is a symmetry with gauge
//!   `F(q, t)` when `δL = Σ_i ∂L/∂q_i ξ_i + Σ_i ∂L/∂u_i ξ̇_i = dF/dt` identically; its charge
//!   `Σ_i p_i ξ_i − F` is then conserved (time translations give the energy `T + V`);
//! * Newton: `P = Σ_b m_b v_b`, `L_o = Σ_b [m_b (r_b − o) × v_b + I_b ω_b]`.
//!
//! Every quantity comes with a *magnitude* — the sum of the absolute values of its terms —
//! against which its drift is judged, so that a quantity which happens to be zero (e.g. the
//! momentum of a system started at rest) is judged on the scale of its parts.

use super::dynamics::{self, check_state, potential_of};
use super::{Dual64, HyperDual64, Mechanism, Pose};
use crate::error::{Error, Result};
use crate::math::{SplitMix64, Vec2};
use crate::numerics::budget::StepBudget;
use crate::ode::{Dopri5, Tolerances};

/// An infinitesimal transformation `q → q + ε ξ(q, t)` with gauge term `F(q, t)`.
///
/// Both are evaluated with dual numbers whose derivative part is the rate along the motion
/// (`q̇ = u`, `ṫ = 1`), so that `ξ̇` and `dF/dt` come out exactly.
pub trait Symmetry {
    /// A name for tables, e.g. `boost x`.
    fn name(&self) -> &str;
    /// The generator `ξ(q, t)` (one entry per coordinate).
    fn generator(&self, q: &[Dual64], t: Dual64, xi: &mut [Dual64]);
    /// The gauge term `F(q, t)`.
    fn gauge(&self, q: &[Dual64], t: Dual64) -> Dual64;
}

/// A [`Symmetry`] from two closures.
pub struct Noether<G, F> {
    name: String,
    generator: G,
    gauge: F,
}

impl<G, F> Noether<G, F>
where
    G: Fn(&[Dual64], Dual64, &mut [Dual64]),
    F: Fn(&[Dual64], Dual64) -> Dual64,
{
    /// The transformation with generator `generator` and gauge `gauge`.
    pub fn new(name: impl Into<String>, generator: G, gauge: F) -> Self {
        Noether {
            name: name.into(),
            generator,
            gauge,
        }
    }
}

/// The translation `q_i → q_i + ε` (no gauge): a symmetry exactly when `q_i` is cyclic.
pub type Translation =
    Noether<Box<dyn Fn(&[Dual64], Dual64, &mut [Dual64])>, fn(&[Dual64], Dual64) -> Dual64>;

impl Translation {
    /// Translation of coordinate `coordinate`.
    pub fn translation(name: impl Into<String>, coordinate: usize) -> Translation {
        fn no_gauge(_: &[Dual64], _: Dual64) -> Dual64 {
            Dual64::from(0.0)
        }
        Noether {
            name: name.into(),
            generator: Box::new(move |_q: &[Dual64], _t: Dual64, xi: &mut [Dual64]| {
                for (i, x) in xi.iter_mut().enumerate() {
                    *x = Dual64::from(if i == coordinate { 1.0 } else { 0.0 });
                }
            }),
            gauge: no_gauge,
        }
    }
}

impl<G, F> Symmetry for Noether<G, F>
where
    G: Fn(&[Dual64], Dual64, &mut [Dual64]),
    F: Fn(&[Dual64], Dual64) -> Dual64,
{
    fn name(&self) -> &str {
        &self.name
    }
    fn generator(&self, q: &[Dual64], t: Dual64, xi: &mut [Dual64]) {
        (self.generator)(q, t, xi)
    }
    fn gauge(&self, q: &[Dual64], t: Dual64) -> Dual64 {
        (self.gauge)(q, t)
    }
}

/// A value with the magnitude of its terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// The value.
    pub value: f64,
    /// `Σ |terms|` (≥ `|value|`).
    pub magnitude: f64,
}

/// The first variation of the Lagrangian along `δq = dq`, `δu = du`:
/// `δL = Σ_b [m_b v_b·δv_b + I_b ω_b δω_b] − δV`, by one hyper-dual pass seeded
/// `q + ε₁ u + ε₂ dq` with `ε₁ε₂` part `du` (so `ε₁` carries velocities, `ε₂` variations).
pub fn lagrangian_variation<M: Mechanism + ?Sized>(
    m: &M,
    q: &[f64],
    u: &[f64],
    dq: &[f64],
    du: &[f64],
) -> Measured {
    let qh: Vec<HyperDual64> = (0..q.len())
        .map(|i| HyperDual64::new(q[i], u[i], dq[i], du[i]))
        .collect();
    let zero = HyperDual64::from(0.0);
    let mut poses = vec![Pose::new(zero, zero, zero); m.bodies().len()];
    m.poses(&qh, &mut poses);
    let (mut value, mut magnitude) = (0.0, 0.0);
    for (b, p) in m.bodies().iter().zip(&poses) {
        for term in [
            b.mass * p.x.eps1 * p.x.eps1eps2,
            b.mass * p.y.eps1 * p.y.eps1eps2,
            b.inertia * p.angle.eps1 * p.angle.eps1eps2,
            -b.mass * m.gravity() * p.y.eps2,
        ] {
            value += term;
            magnitude += term.abs();
        }
    }
    let extra = m.potential(&qh).eps2;
    Measured {
        value: value - extra,
        magnitude: magnitude + extra.abs(),
    }
}

/// Coordinates found cyclic (`∂L/∂q_i = 0`) at `samples` pseudo-random states around
/// `(q0, u0)` (coordinates perturbed by up to ±1, velocities drawn in ±(1 + |u0|)): a
/// coordinate is reported cyclic when `|∂L/∂q_i|` stays below `1e-12` of the magnitude of its
/// terms at every sample. The derivatives are exact (automatic differentiation); the sampling
/// makes "identically zero" a numerical, not a symbolic, statement.
pub fn cyclic_coordinates<M: Mechanism + ?Sized>(
    m: &M,
    q0: &[f64],
    u0: &[f64],
    samples: usize,
) -> Result<Vec<usize>> {
    check_state(m, q0, Some(u0))?;
    let n = m.dof();
    let mut rng = SplitMix64(0x5eed_1234_abcd_ef01);
    let mut cyclic = vec![true; n];
    let zeros = vec![0.0; n];
    for s in 0..samples.max(1) {
        let (q, u): (Vec<f64>, Vec<f64>) = if s == 0 {
            (q0.to_vec(), u0.to_vec())
        } else {
            (
                q0.iter().map(|&x| x + symmetric(&mut rng)).collect(),
                u0.iter()
                    .map(|&x| (1.0 + x.abs()) * symmetric(&mut rng))
                    .collect(),
            )
        };
        for (i, c) in cyclic.iter_mut().enumerate() {
            if !*c {
                continue;
            }
            let mut e = zeros.clone();
            e[i] = 1.0;
            let d = lagrangian_variation(m, &q, &u, &e, &zeros);
            if d.value.abs() > 1e-12 * d.magnitude {
                *c = false;
            }
        }
    }
    Ok((0..n).filter(|&i| cyclic[i]).collect())
}

/// The check of a symmetry at one state: `δL` and `dF/dt`, which agree for a symmetry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SymmetryCheck {
    /// `δL = Σ ∂L/∂q_i ξ_i + Σ ∂L/∂u_i ξ̇_i`.
    pub variation: f64,
    /// `dF/dt = ∂F/∂t + Σ ∂F/∂q_i u_i`.
    pub gauge_rate: f64,
    /// Magnitude of the terms of both.
    pub magnitude: f64,
}

impl SymmetryCheck {
    /// `|δL − dF/dt| ≤ 1e-10 · magnitude`.
    pub fn holds(&self) -> bool {
        (self.variation - self.gauge_rate).abs() <= 1e-10 * self.magnitude.max(f64::MIN_POSITIVE)
    }
}

fn dual_state(q: &[f64], u: &[f64]) -> Vec<Dual64> {
    q.iter().zip(u).map(|(&x, &v)| Dual64::new(x, v)).collect()
}

/// `δL` against `dF/dt` for `sym` at `(q, u, t)`.
pub fn check_symmetry<M: Mechanism + ?Sized>(
    m: &M,
    sym: &dyn Symmetry,
    q: &[f64],
    u: &[f64],
    t: f64,
) -> SymmetryCheck {
    let qd = dual_state(q, u);
    let td = Dual64::new(t, 1.0);
    let mut xi = vec![Dual64::from(0.0); q.len()];
    sym.generator(&qd, td, &mut xi);
    let dq: Vec<f64> = xi.iter().map(|x| x.re).collect();
    let du: Vec<f64> = xi.iter().map(|x| x.eps).collect();
    let var = lagrangian_variation(m, q, u, &dq, &du);
    let f = sym.gauge(&qd, td);
    SymmetryCheck {
        variation: var.value,
        gauge_rate: f.eps,
        magnitude: var.magnitude + f.eps.abs(),
    }
}

/// Check `sym` at the state `(q0, u0, t0)` and at `samples − 1` pseudo-random states around
/// it (as in [`cyclic_coordinates`]); returns the worst check (largest relative residual).
pub fn verify_symmetry<M: Mechanism + ?Sized>(
    m: &M,
    sym: &dyn Symmetry,
    q0: &[f64],
    u0: &[f64],
    t0: f64,
    samples: usize,
) -> Result<SymmetryCheck> {
    check_state(m, q0, Some(u0))?;
    let mut rng = SplitMix64(0x0b5e_55ed_c0ff_ee00);
    let mut worst: Option<(f64, SymmetryCheck)> = None;
    for s in 0..samples.max(1) {
        let (q, u, t): (Vec<f64>, Vec<f64>, f64) = if s == 0 {
            (q0.to_vec(), u0.to_vec(), t0)
        } else {
            (
                q0.iter().map(|&x| x + symmetric(&mut rng)).collect(),
                u0.iter()
                    .map(|&x| (1.0 + x.abs()) * symmetric(&mut rng))
                    .collect(),
                t0 + 5.0 * symmetric(&mut rng),
            )
        };
        let c = check_symmetry(m, sym, &q, &u, t);
        let rel = (c.variation - c.gauge_rate).abs() / c.magnitude.max(f64::MIN_POSITIVE);
        if worst.is_none_or(|(w, _)| rel > w) {
            worst = Some((rel, c));
        }
    }
    Ok(worst.expect("at least one sample").1)
}

/// The Noether charge `Σ_i p_i ξ_i − F` of `sym` at `(q, u, t)`.
pub fn noether_charge<M: Mechanism + ?Sized>(
    m: &M,
    sym: &dyn Symmetry,
    q: &[f64],
    u: &[f64],
    t: f64,
) -> Measured {
    let qd = dual_state(q, u);
    let td = Dual64::new(t, 1.0);
    let mut xi = vec![Dual64::from(0.0); q.len()];
    sym.generator(&qd, td, &mut xi);
    let p = generalized_momenta(m, q, u);
    let f = sym.gauge(&qd, td).re;
    let (mut value, mut magnitude) = (-f, f.abs());
    for (pi, x) in p.iter().zip(&xi) {
        value += pi.value * x.re;
        magnitude += pi.magnitude * x.re.abs();
    }
    Measured { value, magnitude }
}

/// Generalized momenta `p = M(q) u`, each with the magnitude `Σ_j |M_ij u_j|`.
pub fn generalized_momenta<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> Vec<Measured> {
    let mass = dynamics::mass_matrix(m, q);
    (0..q.len())
        .map(|i| {
            let terms = (0..q.len()).map(|j| mass[(i, j)] * u[j]);
            Measured {
                value: terms.clone().sum(),
                magnitude: terms.map(f64::abs).sum(),
            }
        })
        .collect()
}

/// Total energy `T + V`, magnitude `T + Σ_b |m_b g y_b| + |V_extra|`.
pub fn energy<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> Measured {
    let t = dynamics::kinetic_energy(m, q, u);
    let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
    m.poses(q, &mut poses);
    let v = potential_of(m, q, &poses);
    let extra = m.potential(q);
    let magnitude = t
        + extra.abs()
        + m.bodies()
            .iter()
            .zip(&poses)
            .map(|(b, p)| (b.mass * m.gravity() * p.y).abs())
            .sum::<f64>();
    Measured {
        value: t + v,
        magnitude,
    }
}

/// Newtonian linear momentum `P = Σ_b m_b v_b` (x then y).
pub fn linear_momentum<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64]) -> [Measured; 2] {
    let kin = dynamics::kinematics(m, q);
    let vel = dynamics::body_velocities(&kin, u);
    let mut out = [Measured {
        value: 0.0,
        magnitude: 0.0,
    }; 2];
    for (b, v) in m.bodies().iter().zip(&vel) {
        for (o, &vi) in out.iter_mut().zip(&v[..2]) {
            o.value += b.mass * vi;
            o.magnitude += (b.mass * vi).abs();
        }
    }
    out
}

/// Angular momentum about the fixed point `o`: `Σ_b [m_b (r_b − o) × v_b + I_b ω_b]`.
pub fn angular_momentum<M: Mechanism + ?Sized>(m: &M, q: &[f64], u: &[f64], o: Vec2) -> Measured {
    let kin = dynamics::kinematics(m, q);
    let vel = dynamics::body_velocities(&kin, u);
    let mut out = Measured {
        value: 0.0,
        magnitude: 0.0,
    };
    for ((b, p), v) in m.bodies().iter().zip(&kin.poses).zip(&vel) {
        let (rx, ry) = (p.x - o.x, p.y - o.y);
        for term in [b.mass * rx * v[1], -b.mass * ry * v[0], b.inertia * v[2]] {
            out.value += term;
            out.magnitude += term.abs();
        }
    }
    out
}

/// What a tracked quantity is.
#[derive(Debug, Clone, PartialEq)]
pub enum QuantityKind {
    /// `p_i = ∂L/∂u_i` of coordinate `i` (marked cyclic or not).
    GeneralizedMomentum {
        /// The coordinate's index.
        coordinate: usize,
        /// Whether the coordinate was found cyclic.
        cyclic: bool,
    },
    /// `T + V`.
    Energy,
    /// A component of `Σ m_b v_b` (0 = x, 1 = y).
    LinearMomentum {
        /// 0 for x, 1 for y.
        axis: usize,
    },
    /// `Σ [m_b (r_b − o) × v_b + I_b ω_b]` about `o`.
    AngularMomentum {
        /// The fixed point.
        about: Vec2,
    },
    /// The charge of a [`Symmetry`], with the check `δL = dF/dt`.
    Noether {
        /// The worst check over the sampled states.
        check: SymmetryCheck,
    },
}

/// One quantity along the motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// Name for tables, e.g. `p_x`, `P_x`, `energy`, `boost x`.
    pub name: String,
    /// What it is.
    pub kind: QuantityKind,
    /// Its value at each sample time.
    pub values: Vec<f64>,
    /// The largest magnitude of its terms over the run.
    pub magnitude: f64,
}

impl Track {
    /// The value at the start.
    pub fn initial(&self) -> f64 {
        self.values[0]
    }

    /// `max_t |Q(t) − Q(0)|`.
    pub fn largest_deviation(&self) -> f64 {
        self.values
            .iter()
            .map(|v| (v - self.values[0]).abs())
            .fold(0.0, f64::max)
    }

    /// The deviation relative to the magnitude of the quantity's terms (0 when nothing moves).
    pub fn relative_deviation(&self) -> f64 {
        if self.magnitude > 0.0 {
            self.largest_deviation() / self.magnitude
        } else {
            0.0
        }
    }

    /// Conserved when the relative deviation is at most `tolerance` (and, for a Noether
    /// charge, its symmetry check holds).
    pub fn conserved(&self, tolerance: f64) -> bool {
        let symmetric = match &self.kind {
            QuantityKind::Noether { check } => check.holds(),
            _ => true,
        };
        symmetric && self.relative_deviation() <= tolerance
    }

    /// The kind's stable id: `generalized-momentum`, `energy`, `linear-momentum`,
    /// `angular-momentum` or `noether-charge`.
    pub fn kind_id(&self) -> &'static str {
        match self.kind {
            QuantityKind::GeneralizedMomentum { .. } => "generalized-momentum",
            QuantityKind::Energy => "energy",
            QuantityKind::LinearMomentum { .. } => "linear-momentum",
            QuantityKind::AngularMomentum { .. } => "angular-momentum",
            QuantityKind::Noether { .. } => "noether-charge",
        }
    }

    /// What the quantity is, in words, with the mechanism's coordinate names: `generalized
    /// momentum of x (cyclic)`, `total energy T + V`, `Newtonian momentum Σ m v_x`, …
    pub fn description(&self, coordinates: &[&str]) -> String {
        match &self.kind {
            QuantityKind::GeneralizedMomentum { coordinate, cyclic } => format!(
                "generalized momentum of {}{}",
                coordinates[*coordinate],
                if *cyclic { " (cyclic)" } else { "" }
            ),
            QuantityKind::Energy => "total energy T + V".into(),
            QuantityKind::LinearMomentum { axis } => {
                format!(
                    "Newtonian momentum Σ m v_{}",
                    if *axis == 0 { "x" } else { "y" }
                )
            }
            QuantityKind::AngularMomentum { about } => {
                format!("angular momentum about ({}, {})", about.x, about.y)
            }
            QuantityKind::Noether { .. } => "Noether charge Σ p ξ − F".into(),
        }
    }

    /// The verdict in words: `conserved`, `NOT conserved`, or for a Noether charge whose
    /// transformation fails the check, `not a symmetry (δL ≠ dF/dt)`.
    pub fn verdict(&self, tolerance: f64) -> &'static str {
        match &self.kind {
            QuantityKind::Noether { check } if !check.holds() => "not a symmetry (δL ≠ dF/dt)",
            _ if self.conserved(tolerance) => "conserved",
            _ => "NOT conserved",
        }
    }
}

/// Largest number of integrator steps (accepted and rejected) [`track`] takes over the
/// whole motion. It gives up earlier, after a thousand steps, when the pace so far projects
/// more than twice as many: a state spinning at 10²⁰ rad/s fails at once, not after seconds.
/// The error names `duration`.
pub const TRACK_MAX_STEPS: usize = 1_000_000;

/// Quantities tracked along an integrated motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Tracking {
    /// Sample times.
    pub times: Vec<f64>,
    /// The generalized coordinates `q` at each sample time (for drawing the motion: the
    /// bodies' poses are [`Mechanism::poses`] of these).
    pub positions: Vec<Vec<f64>>,
    /// The quantities.
    pub tracks: Vec<Track>,
    /// Coordinates found cyclic.
    pub cyclic: Vec<usize>,
    /// Accepted and rejected integrator steps.
    pub steps: (usize, usize),
}

/// Options of [`track`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackOptions {
    /// Duration of the motion (> 0).
    pub duration: f64,
    /// Number of sample intervals (≥ 1); samples are equally spaced, both ends included.
    pub intervals: usize,
    /// Integrator tolerances.
    pub tolerances: Tolerances,
}

impl Default for TrackOptions {
    fn default() -> Self {
        TrackOptions {
            duration: 10.0,
            intervals: 1000,
            tolerances: Tolerances::TIGHT,
        }
    }
}

/// Integrate the free motion from `(q0, u0)` at `t = 0` and evaluate, at every sample: the
/// generalized momenta, the energy, `P_x`, `P_y`, the angular momentum about each point of
/// `about`, and the charge of each symmetry (checked `δL = dF/dt` first).
///
/// # Errors
/// Invalid state or options; a singular mass matrix or a failed integration along the way.
pub fn track<M: Mechanism + ?Sized>(
    m: &M,
    q0: &[f64],
    u0: &[f64],
    symmetries: &[Box<dyn Symmetry>],
    about: &[Vec2],
    options: TrackOptions,
) -> Result<Tracking> {
    check_state(m, q0, Some(u0))?;
    dynamics::check_precision(m, q0)?;
    if !(options.duration.is_finite() && options.duration > 0.0) {
        return Err(Error::OutOfRange {
            field: "duration".into(),
            value: options.duration,
            reason: "must be finite and positive".into(),
        });
    }
    if options.intervals == 0 || options.intervals > 10_000_000 {
        return Err(Error::OutOfRange {
            field: "samples".into(),
            value: options.intervals as f64,
            reason: "must be between 1 and 10⁷".into(),
        });
    }
    for (i, o) in about.iter().enumerate() {
        crate::error::finite(&format!("about[{i}]"), o.x)?;
        crate::error::finite(&format!("about[{i}]"), o.y)?;
    }
    dynamics::accelerations(m, q0, u0)?;
    let n = m.dof();
    let cyclic = cyclic_coordinates(m, q0, u0, 16)?;
    let checks = symmetries
        .iter()
        .map(|s| verify_symmetry(m, s.as_ref(), q0, u0, 0.0, 16))
        .collect::<Result<Vec<_>>>()?;

    // The quantities, in the order they are measured at each sample.
    let mut kinds: Vec<(String, QuantityKind)> = m
        .coordinates()
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let cyclic = cyclic.contains(&i);
            let kind = QuantityKind::GeneralizedMomentum {
                coordinate: i,
                cyclic,
            };
            (format!("p_{name}"), kind)
        })
        .collect();
    kinds.push(("energy".into(), QuantityKind::Energy));
    for (axis, name) in ["P_x", "P_y"].iter().enumerate() {
        kinds.push(((*name).into(), QuantityKind::LinearMomentum { axis }));
    }
    for o in about {
        let kind = QuantityKind::AngularMomentum { about: *o };
        kinds.push((format!("L({}, {})", o.x, o.y), kind));
    }
    for (s, check) in symmetries.iter().zip(&checks) {
        kinds.push((
            s.name().to_string(),
            QuantityKind::Noether { check: *check },
        ));
    }
    let mut tracks: Vec<Track> = kinds
        .into_iter()
        .map(|(name, kind)| Track {
            name,
            kind,
            values: Vec::new(),
            magnitude: 0.0,
        })
        .collect();

    let record = |tracks: &mut [Track], y: &[f64], t: f64| {
        let (q, u) = y.split_at(n);
        let mut measured: Vec<Measured> = generalized_momenta(m, q, u);
        measured.push(energy(m, q, u));
        measured.extend(linear_momentum(m, q, u));
        for o in about {
            measured.push(angular_momentum(m, q, u, *o));
        }
        for s in symmetries {
            measured.push(noether_charge(m, s.as_ref(), q, u, t));
        }
        for (tr, mv) in tracks.iter_mut().zip(measured) {
            tr.values.push(mv.value);
            tr.magnitude = tr.magnitude.max(mv.magnitude);
        }
    };

    let mut y: Vec<f64> = q0.iter().chain(u0).copied().collect();
    let mut ode = Dopri5::new(2 * n, options.tolerances)?;
    let mut times = Vec::with_capacity(options.intervals + 1);
    let mut positions = Vec::with_capacity(options.intervals + 1);
    times.push(0.0);
    positions.push(y[..n].to_vec());
    record(&mut tracks, &y, 0.0);
    let budget = StepBudget {
        max: TRACK_MAX_STEPS,
        duration: options.duration,
        field: "duration",
    };
    for k in 1..=options.intervals {
        // One budget for the whole motion, not per sample interval (a state spinning at
        // 10⁷ rad/s would otherwise take 10⁶ steps in each of a thousand intervals), judged
        // after every step: a pace that projects past twice the budget stops early.
        let mut used = ode.accepted + ode.rejected;
        ode.max_steps = budget.remaining(used);
        let (t0, t1) = (
            times[k - 1],
            options.duration * k as f64 / options.intervals as f64,
        );
        let mut verdict = Ok(());
        let result = ode.integrate(
            |_, y, dy| dynamics::state_derivative(m, y, dy),
            t0,
            &mut y,
            t1,
            |step| {
                used += 1;
                verdict = budget.check(used, step.t1);
                verdict.is_err().then_some(step.t1)
            },
        );
        verdict?;
        if result.is_err() && ode.accepted + ode.rejected >= budget.max {
            budget.check(ode.accepted + ode.rejected, ode.time())?;
        }
        result?;
        times.push(t1);
        positions.push(y[..n].to_vec());
        record(&mut tracks, &y, t1);
    }
    representable(&tracks, q0, u0)?;
    Ok(Tracking {
        times,
        positions,
        tracks,
        cyclic,
        steps: (ode.accepted, ode.rejected),
    })
}

/// Every value, magnitude and deviation of the tracks must be a number: an angular momentum
/// about a point ~1e308 away overflows (the field to change is the point), as may any
/// quantity of an extreme state (the field named is then `q`).
fn representable(tracks: &[Track], q0: &[f64], u0: &[f64]) -> Result<()> {
    for tr in tracks {
        let bad = tr.values.iter().any(|v| !v.is_finite())
            || !tr.magnitude.is_finite()
            || !tr.largest_deviation().is_finite();
        if bad {
            let (field, value) = match tr.kind {
                QuantityKind::AngularMomentum { about } => ("about", about.norm()),
                _ => ("q", q0.iter().chain(u0).fold(0.0f64, |a, x| a.max(x.abs()))),
            };
            return Err(Error::OutOfRange {
                field: field.into(),
                value,
                reason: format!(
                    "the quantity {} is not representable along the motion (it overflows)",
                    tr.name
                ),
            });
        }
    }
    Ok(())
}

/// Uniform in `[−1, 1)` from the sampled checks' generator.
fn symmetric(rng: &mut SplitMix64) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}
