//! Bodies and mechanisms that produce impact problems, and `compare` (every law side by side).
//!
//! The shapes are the library's (`impax::bodies`), the mechanisms its built-ins
//! (`impax::mechanism::builtin`) with the CLI's defaults; angles are radians, as in the
//! library.

use crate::convert::{arg, law, lib, list, value_error};
use crate::outcome::{Context, Outcome, Raw};
use impax::bodies::{self, BodyState2, PlanarImpact, RigidBody2, Side};
use impax::error::Num;
use impax::math::Vec2;
use impax::mechanism::builtin::{
    BuiltIn, CartPendulum, DoublePendulum, RingPendulum, Rod, Sphere, STANDARD_GRAVITY,
};
use impax::mechanism::impact::MechanismImpact as LibMechanismImpact;
use impax::mechanism::Mechanism;
use impax::planar::ContactProblem;
use impax::LawId;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use std::f64::consts::FRAC_PI_6;

/// The seed's friction coefficient and restitution (paper A: μ = 0.4, e = 0.7).
const SEED_FRICTION: f64 = 0.4;
const SEED_RESTITUTION: f64 = 0.7;

/// A planar body (with its state before the impact) striking a fixed surface, with the
/// coefficients of the contact: the input of `compare` and of `resolve`.
#[pyclass(frozen, module = "impax._impax")]
pub struct BodyImpact {
    impact: PlanarImpact,
    problem: ContactProblem,
    t0: f64,
    description: String,
}

fn parse_laws(ids: &[String]) -> PyResult<Vec<LawId>> {
    let mut laws = Vec::new();
    for id in ids {
        let l = law(id.trim())?;
        if !laws.contains(&l) {
            laws.push(l);
        }
    }
    Ok(laws)
}

fn matrix<'py>(py: Python<'py>, w: impax::math::Mat2) -> PyResult<Bound<'py, PyArray2<f64>>> {
    Ok(PyArray2::from_vec2(
        py,
        &[vec![w[(0, 0)], w[(0, 1)]], vec![w[(1, 0)], w[(1, 1)]]],
    )?)
}

impl BodyImpact {
    fn new(
        body: RigidBody2,
        state: BodyState2,
        other: Option<&Body>,
        friction: f64,
        restitution: f64,
        description: String,
    ) -> PyResult<Self> {
        let (impact, description) = match other {
            None => (PlanarImpact::on_fixed_surface(body, state), description),
            Some(o) => (
                PlanarImpact::between(body, state, o.body, o.state),
                format!("{description} striking {}", o.description),
            ),
        };
        let problem = lib(impact.problem(friction, restitution))?;
        let before = impact.energy_before();
        let t0 = if before.translational > 0.0 {
            before.translational
        } else {
            before.total()
        };
        Ok(Self {
            impact,
            problem,
            t0,
            description,
        })
    }

    fn outcome(&self, law: LawId) -> Outcome {
        let r = self.impact.resolve(law, &self.problem);
        let (raw, body_after, other_after, split) = match r {
            Ok(b) => (
                Ok(b.outcome),
                Some(b.body_after),
                b.other_after,
                Some(b.energy_change),
            ),
            Err(e) => (Err(e), None, None, None),
        };
        Outcome {
            law,
            raw: Raw::Planar(raw),
            approach_energy: self.problem.approach_energy(),
            context: Context::Body {
                body_after,
                other_after,
                two_bodies: self.impact.other.is_some(),
                split,
                t0: self.t0,
                energy_before: self.impact.energy_before().total(),
            },
            problem3: None,
        }
    }
}

#[pymethods]
impl BodyImpact {
    /// The contact-space inverse inertia `W = [[1/m + r_n²/I, −r_t r_n/I], [·, 1/m + r_t²/I]]`.
    #[getter]
    fn w<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, self.problem.w())
    }

    /// The contact velocity before, `(v_t, v_n) = (v_x − ω r_n, v_y + ω r_t)`.
    #[getter]
    fn v(&self) -> (f64, f64) {
        let v = self.problem.velocity();
        (v.x, v.y)
    }

    /// Coulomb friction coefficient μ.
    #[getter]
    fn friction(&self) -> f64 {
        self.problem.friction()
    }

    /// Coefficient of restitution e.
    #[getter]
    fn restitution(&self) -> f64 {
        self.problem.restitution()
    }

    /// Kinetic energy before the impact, `½ m |v|² + ½ I ω²`.
    #[getter]
    fn energy_before(&self) -> f64 {
        self.impact.energy_before().total()
    }

    /// The normalisation `T0` of `energy_change_ratio`: the translational kinetic energy
    /// before (`½ m v0²` in the seed's case), or the total if that is zero.
    #[getter]
    fn t0(&self) -> f64 {
        self.t0
    }

    /// One line describing the body and its state.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// Resolve the impact with one law (any law, including `smith-centre`).
    #[pyo3(signature = (law = "energetic"))]
    fn resolve(&self, law: &str) -> PyResult<Outcome> {
        Ok(self.outcome(crate::convert::law(law)?))
    }

    fn __repr__(&self) -> String {
        format!("BodyImpact({})", self.description)
    }
}

/// A built-in mechanism at a state, striking with its contact, with the coefficients.
#[pyclass(frozen, module = "impax._impax")]
pub struct MechanismImpact {
    name: &'static str,
    mechanism: BuiltIn,
    q: Vec<f64>,
    u: Vec<f64>,
    friction: f64,
    restitution: f64,
    description: String,
}

impl MechanismImpact {
    fn impact(&self) -> PyResult<LibMechanismImpact<'_, BuiltIn>> {
        lib(LibMechanismImpact::striking(
            &self.mechanism,
            &self.q,
            &self.u,
        ))
    }

    fn outcome(&self, law: LawId) -> PyResult<Outcome> {
        let impact = self.impact()?;
        let r = lib(impact.resolve(law, self.friction, self.restitution))?;
        let problem = lib(impact.problem(self.friction, self.restitution))?;
        Ok(Outcome {
            law,
            raw: Raw::Planar(r.resolution),
            approach_energy: problem.approach_energy(),
            context: Context::Mechanism {
                velocities_after: r.velocities_after,
                energy_before: impact.energy_before(),
                energy_change_from_velocities: r.energy_change_from_velocities,
            },
            problem3: None,
        })
    }
}

#[pymethods]
impl MechanismImpact {
    /// The mechanism's stable name, e.g. `"double-pendulum"`.
    #[getter]
    fn name(&self) -> &'static str {
        self.name
    }

    /// The generalized coordinates' names.
    #[getter]
    fn coordinates<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.mechanism.coordinates().iter().copied())
    }

    /// Generalized coordinates `q` (radians for angles).
    #[getter]
    fn q<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.q.iter().copied())
    }

    /// Generalized velocities before, `u⁻`.
    #[getter]
    fn u<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.u.iter().copied())
    }

    /// `W = J M⁻¹ Jᵀ` of the contact (mass matrix and Jacobian by automatic differentiation).
    #[getter]
    fn w<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, self.impact()?.inverse_inertia())
    }

    /// The contact velocity before, `v⁻ = J u⁻` (tangent, normal).
    #[getter]
    fn v(&self) -> PyResult<(f64, f64)> {
        let v: Vec2 = self.impact()?.contact_velocity();
        Ok((v.x, v.y))
    }

    /// Coulomb friction coefficient μ.
    #[getter]
    fn friction(&self) -> f64 {
        self.friction
    }

    /// Coefficient of restitution e.
    #[getter]
    fn restitution(&self) -> f64 {
        self.restitution
    }

    /// Kinetic energy before, `½ u⁻ᵀ M u⁻`.
    #[getter]
    fn energy_before(&self) -> PyResult<f64> {
        Ok(self.impact()?.energy_before())
    }

    /// The gap of the contact at `q` (0 when the contact touches).
    #[getter]
    fn gap(&self) -> PyResult<f64> {
        Ok(self.impact()?.gap())
    }

    /// One line describing the mechanism and its state.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// Resolve the impact with one law: the contact-space outcome and `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
    #[pyo3(signature = (law = "energetic"))]
    fn resolve(&self, law: &str) -> PyResult<Outcome> {
        self.outcome(crate::convert::law(law)?)
    }

    fn __repr__(&self) -> String {
        format!("MechanismImpact({})", self.description)
    }
}

fn positive(field: &str, x: f64, reason: &str) -> PyResult<f64> {
    if !x.is_finite() {
        return Err(value_error(format!(
            "{field}: must be a finite number, got {}",
            Num(x)
        )));
    }
    if x <= 0.0 {
        return Err(value_error(format!("{field}: {reason}, got {}", Num(x))));
    }
    Ok(x)
}

/// The state of a round body: `(speed, alpha, spin_ratio)` as in paper A, or
/// `(velocity, omega)` directly (not both).
#[allow(clippy::too_many_arguments)]
fn round_state(
    radius: f64,
    speed: Option<f64>,
    alpha: Option<f64>,
    spin_ratio: Option<f64>,
    velocity: Option<(f64, f64)>,
    omega: Option<f64>,
) -> PyResult<(BodyState2, String)> {
    let seed = speed.is_some() || alpha.is_some() || spin_ratio.is_some();
    let direct = velocity.is_some() || omega.is_some();
    if seed && direct {
        return Err(value_error(
            "speed: give either speed/alpha/spin_ratio or velocity/omega, not both",
        ));
    }
    if direct {
        return direct_state(velocity, omega);
    }
    let v0 = positive("speed", speed.unwrap_or(1.0), "must be > 0")?;
    let alpha = alpha.unwrap_or(FRAC_PI_6);
    if !alpha.is_finite()
        || alpha <= -std::f64::consts::FRAC_PI_2
        || alpha >= std::f64::consts::FRAC_PI_2
    {
        return Err(value_error(format!(
            "alpha: must be in (-π/2, π/2) for the body to approach the surface, got {}",
            Num(alpha)
        )));
    }
    let gamma = spin_ratio.unwrap_or(0.0);
    let state = lib(bodies::spin_state(v0, alpha, gamma, radius))?;
    Ok((state, format!("v0 = {v0}, α = {alpha} rad, γ = {gamma}")))
}

fn direct_state(
    velocity: Option<(f64, f64)>,
    omega: Option<f64>,
) -> PyResult<(BodyState2, String)> {
    let (vx, vy) = velocity.unwrap_or((0.0, 0.0));
    let omega = omega.unwrap_or(0.0);
    for (field, x) in [("velocity", vx), ("velocity", vy), ("omega", omega)] {
        if !x.is_finite() {
            return Err(value_error(format!(
                "{field}: must be a finite number, got {}",
                Num(x)
            )));
        }
    }
    Ok((
        BodyState2::new(vx, vy, omega),
        format!("v = ({vx}, {vy}), ω = {omega}"),
    ))
}

/// A solid sphere (`I = 2/5 m r²`) striking a fixed plane with its lowest point.
///
/// The state is paper A's (eq. 1): speed `v0`, angle `alpha` (radians) of the velocity from
/// the normal, spin ratio `γ = ω0 r / v0` — the slip before is `v0 (sin α + γ)` (eq. 6) —
/// or `velocity=(vx, vy)` and `omega` directly. `W = (1/m) diag(7/2, 1)`. With no arguments:
/// the seed's case (m = r = v0 = 1, α = 30°, γ = 0, μ = 0.4, e = 0.7).
#[pyfunction]
#[pyo3(signature = (mass = 1.0, radius = 1.0, *, speed = None, alpha = None, spin_ratio = None, velocity = None, omega = None, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
#[allow(clippy::too_many_arguments)]
pub fn sphere(
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::radius)] radius: f64,
    #[pyo3(from_py_with = arg::speed)] speed: Option<f64>,
    #[pyo3(from_py_with = arg::alpha)] alpha: Option<f64>,
    #[pyo3(from_py_with = arg::spin_ratio)] spin_ratio: Option<f64>,
    #[pyo3(from_py_with = arg::velocity)] velocity: Option<(f64, f64)>,
    #[pyo3(from_py_with = arg::omega)] omega: Option<f64>,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    let body = lib(bodies::sphere(mass, radius, Side::Below))?;
    let (state, d) = round_state(radius, speed, alpha, spin_ratio, velocity, omega)?;
    BodyImpact::new(
        body,
        state,
        other.as_deref(),
        friction,
        restitution,
        format!("sphere m = {mass}, r = {radius}, {d}"),
    )
}

/// A uniform disc (`I = ½ m r²`) striking a fixed line; the state as for `sphere`.
#[pyfunction]
#[pyo3(signature = (mass = 1.0, radius = 1.0, *, speed = None, alpha = None, spin_ratio = None, velocity = None, omega = None, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
#[allow(clippy::too_many_arguments)]
pub fn disc(
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::radius)] radius: f64,
    #[pyo3(from_py_with = arg::speed)] speed: Option<f64>,
    #[pyo3(from_py_with = arg::alpha)] alpha: Option<f64>,
    #[pyo3(from_py_with = arg::spin_ratio)] spin_ratio: Option<f64>,
    #[pyo3(from_py_with = arg::velocity)] velocity: Option<(f64, f64)>,
    #[pyo3(from_py_with = arg::omega)] omega: Option<f64>,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    let body = lib(bodies::disc(mass, radius, Side::Below))?;
    let (state, d) = round_state(radius, speed, alpha, spin_ratio, velocity, omega)?;
    BodyImpact::new(
        body,
        state,
        other.as_deref(),
        friction,
        restitution,
        format!("disc m = {mass}, r = {radius}, {d}"),
    )
}

/// A uniform thin rod of length `L` at `angle` (radians, 0 < angle < π) from the surface,
/// striking with its lower end: `I = m L²/12`, contact at `r = −(L/2)(cos θ, sin θ)`.
#[pyfunction]
#[pyo3(signature = (mass = 1.0, length = 1.0, angle = 50f64.to_radians(), *, velocity = (0.5, -1.0), omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
#[allow(clippy::too_many_arguments)]
pub fn rod(
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::length)] length: f64,
    #[pyo3(from_py_with = arg::angle)] angle: f64,
    #[pyo3(from_py_with = arg::velocity)] velocity: (f64, f64),
    #[pyo3(from_py_with = arg::omega)] omega: f64,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    let body = lib(bodies::rod(mass, length, angle, Side::Below))?;
    let (state, d) = direct_state(Some(velocity), Some(omega))?;
    BodyImpact::new(
        body,
        state,
        other.as_deref(),
        friction,
        restitution,
        format!("rod m = {mass}, L = {length}, at {angle} rad to the surface, {d}"),
    )
}

/// A uniform elliptical disc with semi-axes `a`, `b`, its `a` axis at `angle` (radians) from
/// the surface, striking with its support point: `I = m (a² + b²)/4`.
#[pyfunction]
#[pyo3(signature = (mass = 1.0, a = 2.0, b = 1.0, angle = 0.0, *, velocity = (0.5, -1.0), omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
#[allow(clippy::too_many_arguments)]
pub fn ellipse(
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::a)] a: f64,
    #[pyo3(from_py_with = arg::b)] b: f64,
    #[pyo3(from_py_with = arg::angle)] angle: f64,
    #[pyo3(from_py_with = arg::velocity)] velocity: (f64, f64),
    #[pyo3(from_py_with = arg::omega)] omega: f64,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    let body = lib(bodies::ellipse(mass, a, b, angle, Side::Below))?;
    let (state, d) = direct_state(Some(velocity), Some(omega))?;
    BodyImpact::new(
        body,
        state,
        other.as_deref(),
        friction,
        restitution,
        format!("ellipse m = {mass}, a = {a}, b = {b}, at {angle} rad, {d}"),
    )
}

/// Any planar rigid body: mass, central moment of inertia and the contact point
/// `contact = (r_t, r_n)` relative to the centre of mass, in the contact frame.
#[pyfunction]
#[pyo3(signature = (mass, inertia, contact, *, velocity = (0.5, -1.0), omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
#[allow(clippy::too_many_arguments)]
pub fn rigid_body(
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::inertia)] inertia: f64,
    #[pyo3(from_py_with = arg::contact)] contact: (f64, f64),
    #[pyo3(from_py_with = arg::velocity)] velocity: (f64, f64),
    #[pyo3(from_py_with = arg::omega)] omega: f64,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    let body = lib(RigidBody2::new(
        mass,
        inertia,
        Vec2::new(contact.0, contact.1),
    ))?;
    let (state, d) = direct_state(Some(velocity), Some(omega))?;
    BodyImpact::new(
        body,
        state,
        other.as_deref(),
        friction,
        restitution,
        format!(
            "rigid body m = {mass}, I = {inertia}, contact at ({}, {}), {d}",
            contact.0, contact.1
        ),
    )
}

/// A struck body B: a free planar body met at its highest point (`Side::Above`), with its
/// state; the `other=` of a body constructor (two free bodies: `W = W_A + W_B`, the relative
/// contact velocity `v_A − v_B`, impulse `p` on A and `−p` on B).
#[pyclass(frozen, module = "impax._impax")]
pub struct Body {
    body: RigidBody2,
    state: BodyState2,
    description: String,
}

#[pymethods]
impl Body {
    /// One line describing the body and its state.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// The body's contact-space inverse inertia `W_B` at its contact point.
    #[getter]
    fn w<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, self.body.inverse_inertia())
    }

    fn __repr__(&self) -> String {
        format!("Body({})", self.description)
    }
}

/// A struck body B for `other=` (the `[other]` table of a scenario file): `shape` is
/// `sphere`, `disc` (`radius`), `rod` (`length`, `angle` from the surface), `ellipse`
/// (`semi_axes`, `angle`) or `rigid` (`inertia`, `contact` from the centre), met at its highest
/// point; `velocity` and `omega` its state (default: at rest). Angles in radians.
#[pyfunction]
#[pyo3(signature = (shape, mass = 1.0, *, radius = None, length = None, angle = None, semi_axes = None, inertia = None, contact = None, velocity = (0.0, 0.0), omega = 0.0))]
#[allow(clippy::too_many_arguments)]
pub fn body(
    shape: &str,
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::radius)] radius: Option<f64>,
    #[pyo3(from_py_with = arg::length)] length: Option<f64>,
    #[pyo3(from_py_with = arg::angle)] angle: Option<f64>,
    #[pyo3(from_py_with = arg::semi_axes)] semi_axes: Option<(f64, f64)>,
    #[pyo3(from_py_with = arg::inertia)] inertia: Option<f64>,
    #[pyo3(from_py_with = arg::contact)] contact: Option<(f64, f64)>,
    #[pyo3(from_py_with = arg::velocity)] velocity: (f64, f64),
    #[pyo3(from_py_with = arg::omega)] omega: f64,
) -> PyResult<Body> {
    let need = |field: &str, x: Option<f64>| {
        x.ok_or_else(|| value_error(format!("{field}: required for shape `{shape}`")))
    };
    let reject = |field: &str, present: bool| {
        if present {
            Err(value_error(format!(
                "{field}: not a parameter of shape `{shape}`"
            )))
        } else {
            Ok(())
        }
    };
    let side = Side::Above;
    let (b, what) = match shape {
        "sphere" | "disc" => {
            let r = need("radius", radius)?;
            reject("length", length.is_some())?;
            reject("angle", angle.is_some())?;
            reject("semi_axes", semi_axes.is_some())?;
            reject("inertia", inertia.is_some())?;
            reject("contact", contact.is_some())?;
            let b = if shape == "sphere" {
                bodies::sphere(mass, r, side)
            } else {
                bodies::disc(mass, r, side)
            };
            (lib(b)?, format!("{shape} m = {mass}, r = {r}"))
        }
        "rod" => {
            let l = need("length", length)?;
            let a = need("angle", angle)?;
            reject("radius", radius.is_some())?;
            reject("semi_axes", semi_axes.is_some())?;
            reject("inertia", inertia.is_some())?;
            reject("contact", contact.is_some())?;
            (
                lib(bodies::rod(mass, l, a, side))?,
                format!("rod m = {mass}, L = {l}, at {a} rad"),
            )
        }
        "ellipse" => {
            let (sa, sb) =
                semi_axes.ok_or_else(|| value_error("semi_axes: required for shape `ellipse`"))?;
            let a = angle.unwrap_or(0.0);
            reject("radius", radius.is_some())?;
            reject("length", length.is_some())?;
            reject("inertia", inertia.is_some())?;
            reject("contact", contact.is_some())?;
            (
                lib(bodies::ellipse(mass, sa, sb, a, side))?,
                format!("ellipse m = {mass}, a = {sa}, b = {sb}, at {a} rad"),
            )
        }
        "rigid" => {
            let i = need("inertia", inertia)?;
            let (rt, rn) =
                contact.ok_or_else(|| value_error("contact: required for shape `rigid`"))?;
            reject("radius", radius.is_some())?;
            reject("length", length.is_some())?;
            reject("semi_axes", semi_axes.is_some())?;
            reject("angle", angle.is_some())?;
            (
                lib(RigidBody2::new(mass, i, Vec2::new(rt, rn)))?,
                format!("rigid body m = {mass}, I = {i}, contact at ({rt}, {rn})"),
            )
        }
        other => {
            return Err(value_error(format!(
                "shape: unknown shape `{other}` (known: sphere, disc, rod, ellipse, rigid)"
            )))
        }
    };
    let (state, d) = direct_state(Some(velocity), Some(omega))?;
    Ok(Body {
        body: b,
        state,
        description: format!("{what}, {d}"),
    })
}

fn values(field: &str, v: Option<Vec<f64>>, default: &[f64]) -> PyResult<Vec<f64>> {
    let v = v.unwrap_or_else(|| default.to_vec());
    list(field, &v, default.len())?;
    Ok(v)
}

fn reject(name: &str, field: &str, present: bool) -> PyResult<()> {
    if present {
        Err(value_error(format!("{field}: not a parameter of {name}")))
    } else {
        Ok(())
    }
}

/// A built-in mechanism by name, with the CLI's defaults (`impax compare MECHANISM`);
/// angles in radians.
///
/// | name | coordinates | `masses`, `lengths`, `radius` | defaults |
/// |---|---|---|---|
/// | `double-pendulum` | θ1, θ2 from the downward vertical | m1, m2; l1, l2 | 30°, 0°; rates −1, 2 |
/// | `sphere` | x, y, θ | m; —; r | on the floor, velocity (sin 30°, −cos 30°) |
/// | `rod` | x, y, θ from the floor | m; l | 50°, lower end on the floor, velocity (0.5, −1) |
///
/// `ring-pendulum` and `cart-pendulum` have no contact to strike (see `impax conserved`).
#[pyfunction]
#[pyo3(signature = (name, *, masses = None, lengths = None, radius = None, gravity = None, angles = None, rates = None, position = None, friction = 0.5, restitution = 0.5))]
#[allow(clippy::too_many_arguments)]
pub fn mechanism(
    name: &str,
    #[pyo3(from_py_with = arg::masses)] masses: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::lengths)] lengths: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::radius)] radius: Option<f64>,
    #[pyo3(from_py_with = arg::gravity)] gravity: Option<f64>,
    #[pyo3(from_py_with = arg::angles)] angles: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::rates)] rates: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::position)] position: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
) -> PyResult<MechanismImpact> {
    let g = gravity.unwrap_or(STANDARD_GRAVITY);
    let (static_name, mechanism, q, u, description) = match name {
        "double-pendulum" => {
            reject(name, "radius", radius.is_some())?;
            reject(name, "position", position.is_some())?;
            let m = values("masses", masses, &[1.0, 1.0])?;
            let l = values("lengths", lengths, &[1.0, 1.0])?;
            let q = values("angles", angles, &[FRAC_PI_6, 0.0])?;
            let u = values("rates", rates, &[-1.0, 2.0])?;
            let mut dp = lib(DoublePendulum::new(m[0], m[1], l[0], l[1], g, 0.0))?;
            dp.put_floor_at_tip([q[0], q[1]]);
            let d = format!(
                "double pendulum (m = {}, {}; l = {}, {}; g = {g}): θ = ({}, {}) rad, rates ({}, {}) rad/s; the tip of rod 2 strikes the floor",
                m[0], m[1], l[0], l[1], q[0], q[1], u[0], u[1]
            );
            ("double-pendulum", BuiltIn::DoublePendulum(dp), q, u, d)
        }
        "sphere" => {
            reject(name, "lengths", lengths.is_some())?;
            let m = values("masses", masses, &[1.0])?;
            let r = radius.unwrap_or(1.0);
            let p = values("position", position, &[0.0, r])?;
            let a = values("angles", angles, &[0.0])?;
            let (s, c) = FRAC_PI_6.sin_cos();
            let u = values("rates", rates, &[s, -c, 0.0])?;
            let d = format!(
                "sphere (m = {}, r = {r}; g = {g}) at ({}, {}), θ = {} rad, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                m[0], p[0], p[1], a[0], u[0], u[1], u[2]
            );
            let mech = BuiltIn::Sphere(lib(Sphere::new(m[0], r, g, 0.0))?);
            ("sphere", mech, vec![p[0], p[1], a[0]], u, d)
        }
        "rod" => {
            reject(name, "radius", radius.is_some())?;
            let m = values("masses", masses, &[1.0])?;
            let l = values("lengths", lengths, &[1.0])?;
            let a = values("angles", angles, &[50f64.to_radians()])?;
            let lift = 0.5 * l[0] * a[0].sin().abs();
            let p = values("position", position, &[0.0, lift])?;
            let u = values("rates", rates, &[0.5, -1.0, 0.0])?;
            let d = format!(
                "rod (m = {}, l = {}; g = {g}) at ({}, {}), θ = {} rad from the floor, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                m[0], l[0], p[0], p[1], a[0], u[0], u[1], u[2]
            );
            let mech = BuiltIn::Rod(lib(Rod::new(m[0], l[0], g, 0.0))?);
            ("rod", mech, vec![p[0], p[1], a[0]], u, d)
        }
        "ring-pendulum" | "cart-pendulum" => {
            // Built (so that bad parameters are named), then refused: no contact to strike.
            let m = values("masses", masses, &[1.0, 1.0])?;
            let l = values("lengths", lengths, &[1.0])?;
            if name == "ring-pendulum" {
                lib(RingPendulum::new(
                    m[0],
                    radius.unwrap_or(1.0),
                    m[1],
                    l[0],
                    g,
                ))?;
            } else {
                lib(CartPendulum::new(m[0], m[1], l[0], g))?;
            }
            return Err(value_error(format!(
                "{name}: has no contact point to strike (try `impax conserved {name}`)"
            )));
        }
        other => {
            return Err(value_error(format!(
                "mechanism: unknown mechanism `{other}` (known: {})",
                BuiltIn::NAMES.join(", ")
            )))
        }
    };
    let m = MechanismImpact {
        name: static_name,
        mechanism,
        q,
        u,
        friction,
        restitution,
        description,
    };
    // Validate now (singular W, no approach, bad coefficients), as the CLI does.
    let impact = m.impact()?;
    lib(impact.problem(friction, restitution))?;
    drop(impact);
    Ok(m)
}

/// Kane & Levinson's double pendulum (`mechanism("double-pendulum", ...)`): two uniform rods,
/// the upper one pinned, the tip of the lower one striking the floor through it.
///
/// With the defaults (unit rods, θ = (30°, 0°), u = (−1, 2) rad/s, μ = e = 0.5) Whittaker's
/// rule returns T⁺/T⁻ = 1.26087: energy gained (Kane's paradox).
#[pyfunction]
#[pyo3(signature = (masses = (1.0, 1.0), lengths = (1.0, 1.0), angles = (FRAC_PI_6, 0.0), rates = (-1.0, 2.0), gravity = STANDARD_GRAVITY, *, friction = 0.5, restitution = 0.5))]
pub fn double_pendulum(
    #[pyo3(from_py_with = arg::masses)] masses: (f64, f64),
    #[pyo3(from_py_with = arg::lengths)] lengths: (f64, f64),
    #[pyo3(from_py_with = arg::angles)] angles: (f64, f64),
    #[pyo3(from_py_with = arg::rates)] rates: (f64, f64),
    #[pyo3(from_py_with = arg::gravity)] gravity: f64,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
) -> PyResult<MechanismImpact> {
    mechanism(
        "double-pendulum",
        Some(vec![masses.0, masses.1]),
        Some(vec![lengths.0, lengths.1]),
        None,
        Some(gravity),
        Some(vec![angles.0, angles.1]),
        Some(vec![rates.0, rates.1]),
        None,
        friction,
        restitution,
    )
}

/// Every law side by side on one impact (default: the seed's sphere), as a list of dicts —
/// the `results` of `impax compare --json`, key for key (bodies: `contact_velocity_after`,
/// `body_velocity_after`, `energy_change_ratio`, `energy_split`; mechanisms:
/// `velocities_after`, `energy_after`, `energy_ratio`, `energy_change_from_velocities`).
///
/// `laws`: ids (default: every law for a body, every contact-space law for a mechanism).
#[pyfunction]
#[pyo3(signature = (impact = None, laws = None))]
pub fn compare<'py>(
    py: Python<'py>,
    impact: Option<&Bound<'py, PyAny>>,
    laws: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyList>> {
    let out = PyList::empty(py);
    let seed;
    let target = match impact {
        Some(obj) => obj.clone(),
        None => {
            seed = Bound::new(
                py,
                sphere(
                    1.0,
                    1.0,
                    None,
                    None,
                    None,
                    None,
                    None,
                    SEED_FRICTION,
                    SEED_RESTITUTION,
                    None,
                )?,
            )?;
            seed.into_any()
        }
    };
    if let Ok(b) = target.cast::<BodyImpact>() {
        let ids = match laws {
            Some(ids) => parse_laws(&ids)?,
            None => LawId::ALL.to_vec(),
        };
        for l in ids {
            out.append(b.get().outcome(l).to_dict(py)?)?;
        }
        return Ok(out);
    }
    if let Ok(m) = target.cast::<MechanismImpact>() {
        let ids = match laws {
            Some(ids) => parse_laws(&ids)?,
            None => LawId::CONTACT_SPACE.to_vec(),
        };
        for l in ids {
            out.append(m.get().outcome(l)?.to_dict(py)?)?;
        }
        return Ok(out);
    }
    Err(value_error(format!(
        "impact: expected a body (impax.sphere, impax.rod, …) or a mechanism (impax.mechanism), got an object of type {}",
        target.get_type().name()?
    )))
}
