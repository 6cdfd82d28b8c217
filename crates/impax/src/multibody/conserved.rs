//! Conserved quantities of a spatial multibody along its free motion (no contact): the
//! generalized momenta, the cyclic coordinates, the total energy, the linear momentum and the
//! angular momentum about fixed points — the spatial counterpart of
//! [`crate::mechanism::conserved`], with the same report (initial value, largest deviation,
//! relative deviation, conserved or not).
//!
//! With `L(q, u) = T − V`, `T = ½ uᵀ M(q) u`, `V = g Σ_b m_b z_b`:
//!
//! * generalized momentum `p_k = ∂L/∂u_k = (M u)_k`, one per speed. A coordinate whose rate is
//!   a speed (a hinge's or slider's angle, a free joint's `x`, `y`, `z`, whose rates are
//!   `vx`, `vy`, `vz`) is *cyclic* when `∂L/∂q_i ≡ 0`, and then its momentum is conserved
//!   (Euler–Lagrange). The quaternion's four coordinates are not independent and their rates
//!   are no speeds: they are never tested, and the momenta of a free joint's angular speeds
//!   (`wx`, `wy`, `wz`: the angular momentum about the moving base origin) have no cyclic
//!   verdict;
//! * `P = Σ_b m_b v_b` (`v_b` the velocity of body `b`'s centre of mass), conserved without
//!   external force: a floating system without gravity, and horizontally under gravity;
//! * `L_o = Σ_b [m_b (c_b − o) × v_b + R_b I_b R_bᵀ ω_b]` about a fixed point `o`;
//! * `E = T + V`, conserved along every free motion (no friction, no actuation).
//!
//! Each track says whether a symmetry of the model conserves it ([`Track::expected`], by
//! [`expected`]): the energy always, the momentum of a cyclic coordinate, and for a free
//! system (a floating base) `P_x`, `P_y` and `L_z` about any point under gravity, all of `P`
//! and `L` without. The others are free to change, and do when the symmetry is broken (`P_z`
//! under gravity, `P` and `L` of a fixed base).
//!
//! `∂L/∂q_i` is exact, by forward-mode automatic differentiation of the kinematics: one
//! hyper-dual pass seeded `q + ε₁ q̇ + ε₂ e_i` gives each body's centre-of-mass velocity
//! `v = c^{(ε₁)}` and its derivative `∂v/∂q_i = c^{(ε₁ε₂)}`, its body-frame angular velocity
//! `Ω = vee(Rᵀ Ṙ)` and `∂Ω/∂q_i = vee(∂Rᵀ Ṙ + Rᵀ ∂Ṙ)`, so that
//! `∂L/∂q_i = Σ_b [m_b v_b·∂v_b + Ω_bᵀ I_b ∂Ω_b − m_b g ∂z_b]` (`∂q̇/∂q_i = 0` for the
//! coordinates tested, whose rates are speeds). "Identically zero" is checked at sampled
//! states, as in the plane. Noether charges of other symmetries are not offered in 3D.
//!
//! ```
//! use impax::multibody::conserved::{track, QuantityKind, TrackOptions};
//! use impax::multibody::{Body, Joint, Model};
//! use impax::math::{Mat3, Vec3};
//! // A spinning brick thrown upwards: x and y are cyclic, P_x and P_y conserved, P_z not.
//! let brick = Body::new("brick", 1.0, Vec3::zeros(), Mat3::from_diagonal(&Vec3::new(0.1, 0.2, 0.3)));
//! let model = Model::new(vec![brick], vec![Joint::free("root", 0)], vec![])?;
//! let q = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0];
//! let u = [0.5, 0.2, 3.0, 1.0, 2.0, 0.5];
//! let options = TrackOptions { duration: 1.0, intervals: 100, ..TrackOptions::default() };
//! let tracking = track(&model, &q, &u, &[Vec3::zeros()], options)?;
//! assert_eq!(tracking.cyclic, [0, 1]);
//! let p = |axis| tracking.tracks.iter().find(|t| t.kind == QuantityKind::LinearMomentum { axis }).unwrap();
//! assert!(p(0).conserved(1e-10) && p(1).conserved(1e-10) && !p(2).conserved(1e-3));
//! // What the symmetries promise: everything conserved that is expected, P_z not expected.
//! assert!(tracking.tracks.iter().all(|t| !t.expected || t.conserved(1e-10)));
//! assert!(!p(2).expected);
//! # Ok::<(), impax::Error>(())
//! ```

use super::crba::crba;
use super::energy::{body_velocities, kinetic_energy, potential_energy};
use super::kinematics::{forward_kinematics, BodyPose};
use super::{configuration_rate, forward_dynamics_in, JointKind, Model, Workspace};
use crate::error::{Error, Result};
use crate::math::{Mat3, SplitMix64, Vec3};
use crate::numerics::budget::StepBudget;
use crate::ode::Dopri5;
use num_dual::HyperDual64;

pub use crate::mechanism::conserved::{Measured, TrackOptions};

/// What a tracked quantity is.
#[derive(Debug, Clone, PartialEq)]
pub enum QuantityKind {
    /// `p_k = ∂L/∂u_k = (M u)_k` of speed `k`, with the cyclic verdict of the coordinate whose
    /// rate it is (`None` for a free joint's angular speeds, which are no coordinate's rate).
    GeneralizedMomentum {
        /// The speed's index.
        speed: usize,
        /// Whether its coordinate was found cyclic.
        cyclic: Option<bool>,
    },
    /// `T + V`.
    Energy,
    /// A component of `P = Σ m_b v_b` (0 = x, 1 = y, 2 = z).
    LinearMomentum {
        /// 0, 1 or 2.
        axis: usize,
    },
    /// A component of `L_o = Σ [m_b (c_b − o) × v_b + R_b I_b R_bᵀ ω_b]` about `o`.
    AngularMomentum {
        /// The fixed point `o`.
        about: Vec3,
        /// 0, 1 or 2.
        axis: usize,
    },
}

/// One quantity along the motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// Name for tables, e.g. `p_vx`, `P_z`, `energy`, `L_z(0, 0, 0)`.
    pub name: String,
    /// What it is.
    pub kind: QuantityKind,
    /// Its value at each sample time.
    pub values: Vec<f64>,
    /// The largest magnitude of its terms over the run.
    pub magnitude: f64,
    /// Whether a symmetry of the model conserves it ([`expected`]): then its deviation
    /// measures the integration's error; otherwise it is free to change.
    pub expected: bool,
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

    /// Conserved when the relative deviation is at most `tolerance`.
    pub fn conserved(&self, tolerance: f64) -> bool {
        self.relative_deviation() <= tolerance
    }
}

/// Largest number of integrator steps (accepted and rejected) [`track`] takes over the whole
/// motion. It gives up earlier, after a thousand steps, when the pace so far projects more than
/// twice as many: a state spinning at 10⁷ rad/s fails at once, not after minutes. The error
/// names `duration`.
pub const TRACK_MAX_STEPS: usize = 200_000;

/// Quantities tracked along an integrated free motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Tracking {
    /// Sample times.
    pub times: Vec<f64>,
    /// The quantities.
    pub tracks: Vec<Track>,
    /// The coordinates (indices into `q`) found cyclic.
    pub cyclic: Vec<usize>,
    /// The coordinates tested (those whose rate is a speed).
    pub tested: Vec<usize>,
    /// Accepted and rejected integrator steps.
    pub steps: (usize, usize),
}

/// Generalized momenta `p = M(q) u` at the workspace's configuration, each with the magnitude
/// `Σ_j |M_kj u_j|`.
pub fn generalized_momenta(model: &Model, ws: &mut Workspace, u: &[f64]) -> Vec<Measured> {
    let m = crba(model, ws);
    (0..u.len())
        .map(|k| {
            let terms = (0..u.len()).map(|j| m[(k, j)] * u[j]);
            Measured {
                value: terms.clone().sum(),
                magnitude: terms.map(f64::abs).sum(),
            }
        })
        .collect()
}

/// `T + V` at the workspace's configuration, magnitude `T + g Σ_b m_b |z_b|`.
pub fn energy(model: &Model, ws: &mut Workspace, u: &[f64]) -> Measured {
    let t = kinetic_energy(model, ws, u);
    let (v, magnitude) = potential_energy(model, ws);
    Measured {
        value: t + v,
        magnitude: t + magnitude,
    }
}

/// `P = Σ_b m_b v_b` at the workspace's configuration, each component with the magnitude
/// `Σ_b |m_b v_b,i|`.
pub fn linear_momentum(model: &Model, ws: &Workspace, u: &[f64]) -> [Measured; 3] {
    let mut out = [Measured {
        value: 0.0,
        magnitude: 0.0,
    }; 3];
    for (body, v) in model.bodies().iter().zip(body_velocities(model, ws, u)) {
        for (o, x) in out.iter_mut().zip(v.linear.iter()) {
            o.value += body.mass * x;
            o.magnitude += (body.mass * x).abs();
        }
    }
    out
}

/// `L_o = Σ_b [m_b (c_b − o) × v_b + R_b I_b R_bᵀ ω_b]` at the workspace's configuration,
/// each component with the magnitude of its terms.
pub fn angular_momentum(model: &Model, ws: &Workspace, u: &[f64], about: &Vec3) -> [Measured; 3] {
    let mut out = [Measured {
        value: 0.0,
        magnitude: 0.0,
    }; 3];
    let velocities = body_velocities(model, ws, u);
    for ((body, v), pose) in model.bodies().iter().zip(velocities).zip(ws.poses()) {
        let r = pose.rotation_matrix();
        let orbital = (v.com - about).cross(&v.linear) * body.mass;
        let spin = r * body.inertia * r.transpose() * v.angular;
        for (i, o) in out.iter_mut().enumerate() {
            o.value += orbital[i] + spin[i];
            o.magnitude += orbital[i].abs() + spin[i].abs();
        }
    }
    out
}

/// The coordinates whose rate is a speed (so that `∂q̇/∂q_i = 0`): hinges, sliders and a free
/// joint's `x`, `y`, `z` — every coordinate but the quaternions'.
pub fn tested_coordinates(model: &Model) -> Vec<usize> {
    let mut out = Vec::new();
    for (j, joint) in model.joints().iter().enumerate() {
        let o = model.joint_offsets(j).0;
        match joint.kind {
            JointKind::Free => out.extend(o..o + 3),
            JointKind::Fixed => {}
            _ => out.push(o),
        }
    }
    out
}

/// `∂L/∂q_i` at `(q, u)` for a coordinate `i` whose rate is a speed
/// ([`tested_coordinates`]), with the magnitude of its terms (see the module docs).
///
/// `q`, `u` must have `nq`, `nv` entries with unit quaternions (unchecked).
pub fn lagrangian_gradient(model: &Model, q: &[f64], u: &[f64], i: usize) -> Measured {
    let mut qdot = vec![0.0; q.len()];
    configuration_rate(model, q, u, &mut qdot);
    let qh: Vec<HyperDual64> = (0..q.len())
        .map(|k| HyperDual64::new(q[k], qdot[k], if k == i { 1.0 } else { 0.0 }, 0.0))
        .collect();
    let mut poses = vec![BodyPose::identity(); model.bodies().len()];
    forward_kinematics(model, &qh, &mut poses);
    let part =
        |r: &[[HyperDual64; 3]; 3], f: fn(&HyperDual64) -> f64| Mat3::from_fn(|a, b| f(&r[a][b]));
    let vee = |s: Mat3| {
        Vec3::new(
            0.5 * (s[(2, 1)] - s[(1, 2)]),
            0.5 * (s[(0, 2)] - s[(2, 0)]),
            0.5 * (s[(1, 0)] - s[(0, 1)]),
        )
    };
    let (mut value, mut magnitude) = (0.0, 0.0);
    for (body, pose) in model.bodies().iter().zip(&poses) {
        let c = pose.point(&body.com);
        let r0 = part(&pose.rotation, |x| x.re);
        let rdot = part(&pose.rotation, |x| x.eps1);
        let dr = part(&pose.rotation, |x| x.eps2);
        let drdot = part(&pose.rotation, |x| x.eps1eps2);
        let omega = vee(r0.transpose() * rdot);
        let domega = vee(dr.transpose() * rdot + r0.transpose() * drdot);
        let spin = body.inertia * omega;
        let mut terms: Vec<f64> = (0..3)
            .map(|a| body.mass * c[a].eps1 * c[a].eps1eps2)
            .collect();
        terms.extend((0..3).map(|a| spin[a] * domega[a]));
        terms.push(-body.mass * model.gravity() * c[2].eps2);
        for t in terms {
            value += t;
            magnitude += t.abs();
        }
    }
    Measured { value, magnitude }
}

/// The coordinates found cyclic (`∂L/∂q_i = 0`, among [`tested_coordinates`]) at `(q0, u0)`
/// and `samples − 1` pseudo-random states around it (hinges, sliders and positions moved by up
/// to ±1, each free joint turned by up to a radian about a random axis, the speeds drawn in
/// `±(1 + |u0|)`): cyclic when `|∂L/∂q_i|` stays below `1e-12` of the magnitude of its terms
/// at every sample (the planar criterion).
///
/// # Errors
/// As [`Model::check_state`].
pub fn cyclic_coordinates(
    model: &Model,
    q0: &[f64],
    u0: &[f64],
    samples: usize,
) -> Result<Vec<usize>> {
    let q0 = model.check_state(q0, Some(u0))?;
    let tested = tested_coordinates(model);
    let mut cyclic = vec![true; tested.len()];
    let mut rng = SplitMix64(0x5eed_3d3d_c1c1_0001);
    for s in 0..samples.max(1) {
        let (q, u) = if s == 0 {
            (q0.clone(), u0.to_vec())
        } else {
            perturbed(model, &q0, u0, &mut rng)
        };
        for (c, &i) in cyclic.iter_mut().zip(&tested) {
            if *c {
                let d = lagrangian_gradient(model, &q, &u, i);
                *c = d.value.abs() <= 1e-12 * d.magnitude;
            }
        }
    }
    Ok(tested
        .iter()
        .zip(&cyclic)
        .filter(|(_, &c)| c)
        .map(|(&i, _)| i)
        .collect())
}

/// A pseudo-random state around `(q0, u0)` (see [`cyclic_coordinates`]).
fn perturbed(model: &Model, q0: &[f64], u0: &[f64], rng: &mut SplitMix64) -> (Vec<f64>, Vec<f64>) {
    let mut q = q0.to_vec();
    for (j, joint) in model.joints().iter().enumerate() {
        let o = model.joint_offsets(j).0;
        match joint.kind {
            JointKind::Free => {
                for x in &mut q[o..o + 3] {
                    *x += rng.range(-1.0, 1.0);
                }
                // Turn by a quaternion (cos a/2, sin a/2 n) on the left.
                let n = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0).normalize();
                let (s, c) = (0.5 * rng.range(-1.0, 1.0)).sin_cos();
                let (w, v) = (q[o + 3], Vec3::new(q[o + 4], q[o + 5], q[o + 6]));
                let nv = n * s;
                let w2 = c * w - nv.dot(&v);
                let v2 = v * c + nv * w + nv.cross(&v);
                q[o + 3] = w2;
                q[o + 4..o + 7].copy_from_slice(v2.as_slice());
            }
            JointKind::Fixed => {}
            _ => q[o] += rng.range(-1.0, 1.0),
        }
    }
    let u = u0
        .iter()
        .map(|&x| (1.0 + x.abs()) * rng.range(-1.0, 1.0))
        .collect();
    (q, u)
}

/// Whether a symmetry of `model` conserves the quantity `kind` along every free motion, by
/// Noether's theorem (theory §4: a transformation leaving `L` invariant conserves its charge)
/// for the symmetries a tree of bodies under gravity along `−z` has:
///
/// * time: `E = T + V` always (no friction, no actuation);
/// * a cyclic coordinate `q_i` (`∂L/∂q_i ≡ 0`): its momentum `p_i = (M u)_i`;
/// * translations, when the system is *free* — every joint on the world is a `free` joint
///   (a floating base; no support force): the components of `P` perpendicular to gravity,
///   `P_x` and `P_y` (all three when `g = 0`), since `Ṗ = Σ_b m_b g = −m g e_z`;
/// * rotations about the vertical, when the system is free: `L_z` about any fixed point `o`
///   (all three components when `g = 0`), since the torque of gravity
///   `Σ_b (c_b − o) × (−m_b g e_z)` has no `z` component.
///
/// A fixed base breaks the translations and rotations (the support's reaction acts); a cyclic
/// joint of a fixed base still conserves its momentum (e.g. the vertical hinge of a turntable,
/// whose momentum is the `L_z` the support leaves alone).
pub fn expected(model: &Model, kind: &QuantityKind) -> bool {
    let free = model
        .joints()
        .iter()
        .filter(|j| j.parent.is_none())
        .all(|j| j.kind == JointKind::Free);
    let no_gravity = model.gravity() == 0.0;
    match kind {
        QuantityKind::Energy => true,
        QuantityKind::GeneralizedMomentum { cyclic, .. } => *cyclic == Some(true),
        QuantityKind::LinearMomentum { axis } => free && (no_gravity || *axis != 2),
        QuantityKind::AngularMomentum { axis, .. } => free && (no_gravity || *axis == 2),
    }
}

/// The coordinate whose rate is speed `speed` (an index into `q`), if any: a hinge's or
/// slider's coordinate, a free joint's `x`, `y`, `z` for `vx`, `vy`, `vz`; `None` for a free
/// joint's angular speeds (the quaternion's rates are no speeds).
pub fn rate_coordinate(model: &Model, speed: usize) -> Option<usize> {
    let mut s = speed;
    for (j, joint) in model.joints().iter().enumerate() {
        let nv = joint.kind.nv();
        if s < nv {
            let oq = model.joint_offsets(j).0;
            return match joint.kind {
                JointKind::Free if s < 3 => Some(oq + s),
                JointKind::Free => None,
                _ => Some(oq),
            };
        }
        s -= nv;
    }
    None
}

/// The tracks of the quantities (empty values): the momenta, the energy, `P`, and `L` about
/// each point of `about`.
fn tracks(model: &Model, cyclic: &[usize], tested: &[usize], about: &[Vec3]) -> Vec<Track> {
    let track = |name: String, kind: QuantityKind| Track {
        name,
        expected: expected(model, &kind),
        kind,
        values: Vec::new(),
        magnitude: 0.0,
    };
    let mut out = Vec::new();
    for (speed, name) in model.speeds().iter().enumerate() {
        let verdict = rate_coordinate(model, speed)
            .filter(|i| tested.contains(i))
            .map(|i| cyclic.contains(&i));
        out.push(track(
            format!("p_{name}"),
            QuantityKind::GeneralizedMomentum {
                speed,
                cyclic: verdict,
            },
        ));
    }
    out.push(track("energy".into(), QuantityKind::Energy));
    for (axis, n) in ["x", "y", "z"].iter().enumerate() {
        out.push(track(
            format!("P_{n}"),
            QuantityKind::LinearMomentum { axis },
        ));
    }
    for o in about {
        for (axis, n) in ["x", "y", "z"].iter().enumerate() {
            out.push(track(
                format!("L_{n}({}, {}, {})", o.x, o.y, o.z),
                QuantityKind::AngularMomentum { about: *o, axis },
            ));
        }
    }
    out
}

/// Integrate the free motion from `(q0, u0)` at `t = 0` (Dormand–Prince 5(4), the options'
/// tolerances; the quaternions renormalised at every sample) and evaluate at every sample the
/// generalized momenta, the energy, `P` and the angular momentum about each point of `about`.
///
/// # Errors
/// Invalid state or options (each naming its field); a singular mass matrix or a failed
/// integration along the way; a motion that needs more than [`TRACK_MAX_STEPS`] steps (or
/// whose pace projects more than twice as many), naming `duration`; a quantity that
/// overflows.
pub fn track(
    model: &Model,
    q0: &[f64],
    u0: &[f64],
    about: &[Vec3],
    options: TrackOptions,
) -> Result<Tracking> {
    let q0 = model.check_state(q0, Some(u0))?;
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
        for x in o.iter() {
            crate::error::finite(&format!("about[{i}]"), *x)?;
        }
    }
    let (nq, nv) = (model.nq(), model.nv());
    let mut ws = Workspace::new(model);
    let tau = vec![0.0; nv];
    let mut y: Vec<f64> = q0.iter().chain(u0).copied().collect();
    {
        ws.update(model, &q0)?;
        forward_dynamics_in(model, &mut ws, u0, &tau, &mut vec![0.0; nv])?;
    }
    let tested = tested_coordinates(model);
    let cyclic = cyclic_coordinates(model, &q0, u0, 16)?;
    let mut tracks = tracks(model, &cyclic, &tested, about);
    let record = |tracks: &mut [Track], y: &[f64], ws: &mut Workspace| -> Result<()> {
        let (q, u) = y.split_at(nq);
        ws.update(model, q)?;
        let mut measured = generalized_momenta(model, ws, u);
        measured.push(energy(model, ws, u));
        measured.extend(linear_momentum(model, ws, u));
        for o in about {
            measured.extend(angular_momentum(model, ws, u, o));
        }
        for (tr, mv) in tracks.iter_mut().zip(measured) {
            tr.values.push(mv.value);
            tr.magnitude = tr.magnitude.max(mv.magnitude);
        }
        Ok(())
    };
    let mut ode = Dopri5::new(nq + nv, options.tolerances)?;
    let budget = StepBudget {
        max: TRACK_MAX_STEPS,
        duration: options.duration,
        field: "duration",
    };
    let mut times = Vec::with_capacity(options.intervals + 1);
    times.push(0.0);
    record(&mut tracks, &y, &mut ws)?;
    let mut eq = Workspace::new(model);
    for k in 1..=options.intervals {
        let t1 = options.duration * k as f64 / options.intervals as f64;
        let f = |_t: f64, y: &[f64], dy: &mut [f64]| {
            let (q, u) = y.split_at(nq);
            let (dq, du) = dy.split_at_mut(nq);
            let ok = eq.update(model, q).is_ok()
                && forward_dynamics_in(model, &mut eq, u, &tau, du).is_ok();
            configuration_rate(model, q, u, dq);
            if !ok {
                dy.iter_mut().for_each(|x| *x = f64::NAN);
            }
        };
        // One budget for the whole motion, judged after every step.
        let mut used = ode.accepted + ode.rejected;
        ode.max_steps = budget.remaining(used);
        let mut verdict = Ok(());
        let result = ode.integrate(f, times[k - 1], &mut y, t1, |step| {
            used += 1;
            verdict = budget.check(used, step.t1);
            verdict.is_err().then_some(step.t1)
        });
        verdict?;
        if result.is_err() && ode.accepted + ode.rejected >= budget.max {
            budget.check(ode.accepted + ode.rejected, ode.time())?;
        }
        result?;
        super::simulate::renormalise(model, &mut y[..nq]);
        times.push(t1);
        record(&mut tracks, &y, &mut ws)?;
    }
    if let Some(tr) = tracks.iter().find(|tr| {
        tr.values.iter().any(|v| !v.is_finite())
            || !tr.magnitude.is_finite()
            || !tr.largest_deviation().is_finite()
    }) {
        let (field, value) = match tr.kind {
            QuantityKind::AngularMomentum { about, .. } => ("about", about.norm()),
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
    Ok(Tracking {
        times,
        tracks,
        cyclic,
        tested,
        steps: (ode.accepted, ode.rejected),
    })
}
