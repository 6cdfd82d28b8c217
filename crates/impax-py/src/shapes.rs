//! The planar bodies by shape: `sphere`, `disc`, `rod`, `ellipse`, `rigid_body` (body A
//! striking a fixed surface), `body_impact` (body A of any shape, by name) and `body` (a struck
//! body B, by name).
//!
//! These functions only translate Python's arguments into the core's description of a body
//! (`impax::scenario::BodySpec`, angles in radians) and let the core check and build it: the
//! shapes, their parameters, their errors and their descriptions are the core's, so that a shape
//! added there is known here too (`body_impact("box", …)`, `body("box", …)`). Shape parameters
//! other than the named keywords are given by keyword as the core names them, with angles in
//! radians (`angle`).

use crate::body::{Body, BodyImpact};
use crate::convert::{arg, lib, real, Numbers};
use impax::planar::bodies::Side;
use impax::scenario::{AngleUnit, BodySpec, Shape, ShapeParam};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::f64::consts::FRAC_PI_6;

/// The seed's friction coefficient and restitution (paper A: μ = 0.4, e = 0.7).
pub(crate) const SEED_FRICTION: f64 = 0.4;
pub(crate) const SEED_RESTITUTION: f64 = 0.7;

/// The default velocity of a body that is not round (`rod`, `ellipse`, `rigid_body`).
const DEFAULT_VELOCITY: (f64, f64) = (0.5, -1.0);

/// A body description with Python's conventions: angles in radians, keys without a section.
fn spec(shape: &str, mass: f64) -> BodySpec {
    BodySpec {
        shape: shape.into(),
        mass,
        angle_unit: AngleUnit::Radians,
        ..BodySpec::default()
    }
}

/// The motion of body A: paper A's `(speed, alpha, spin_ratio)` with Python's defaults
/// (1, π/6, 0) unless the velocity or the angular velocity is given (then the core refuses
/// both kinds at once).
struct Motion {
    speed: Option<f64>,
    alpha: Option<f64>,
    spin_ratio: Option<f64>,
    velocity: Option<(f64, f64)>,
    omega: Option<f64>,
}

impl Motion {
    /// Velocity and angular velocity given directly.
    fn direct(velocity: (f64, f64), omega: f64) -> Self {
        Self {
            speed: None,
            alpha: None,
            spin_ratio: None,
            velocity: Some(velocity),
            omega: Some(omega),
        }
    }

    fn fill(self, spec: &mut BodySpec) {
        if self.velocity.is_some() || self.omega.is_some() {
            spec.speed = self.speed;
            spec.alpha = self.alpha;
            spec.spin_ratio = self.spin_ratio;
            spec.velocity = self.velocity.map(|(x, y)| [x, y]);
            spec.omega = self.omega;
        } else {
            spec.speed = Some(self.speed.unwrap_or(1.0));
            spec.alpha = Some(self.alpha.unwrap_or(FRAC_PI_6));
            spec.spin_ratio = Some(self.spin_ratio.unwrap_or(0.0));
        }
    }
}

/// Shape parameters given by keyword (`half_extents=(1, 0.5)`, `angle=0.3`), as the core
/// names them with angles in radians; `None` values are left out.
fn shape_params(spec: &mut BodySpec, params: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let Some(params) = params else {
        return Ok(());
    };
    for (key, value) in params.iter() {
        let key: String = key.extract()?;
        let p = lib(ShapeParam::parse(&key, spec.angle_unit))?;
        if value.is_none() {
            continue;
        }
        let numbers = if p.count() == 1 {
            vec![real(&value, &key)?]
        } else {
            Vec::<f64>::read(&value, &key)?
        };
        lib(spec.set_param(p, &numbers))?;
    }
    Ok(())
}

/// Body A of `spec` with its motion, against the fixed surface or `other`.
fn striking(
    mut spec: BodySpec,
    motion: Motion,
    friction: f64,
    restitution: f64,
    other: Option<PyRef<'_, Body>>,
) -> PyResult<BodyImpact> {
    motion.fill(&mut spec);
    let built = lib(spec.build("", Side::Below))?;
    BodyImpact::new(built, other.as_deref(), friction, restitution)
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
    let mut s = spec(Shape::Sphere.name(), mass);
    s.radius = Some(radius);
    let motion = Motion {
        speed,
        alpha,
        spin_ratio,
        velocity,
        omega,
    };
    striking(s, motion, friction, restitution, other)
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
    let mut s = spec(Shape::Disc.name(), mass);
    s.radius = Some(radius);
    let motion = Motion {
        speed,
        alpha,
        spin_ratio,
        velocity,
        omega,
    };
    striking(s, motion, friction, restitution, other)
}

/// A uniform thin rod of length `L` at `angle` (radians, 0 < angle < π) from the surface,
/// striking with its lower end: `I = m L²/12`, contact at `r = −(L/2)(cos θ, sin θ)`.
#[pyfunction]
#[pyo3(signature = (mass = 1.0, length = 1.0, angle = 50f64.to_radians(), *, velocity = DEFAULT_VELOCITY, omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
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
    let mut s = spec(Shape::Rod.name(), mass);
    s.length = Some(length);
    s.angle = Some(angle);
    let motion = Motion::direct(velocity, omega);
    striking(s, motion, friction, restitution, other)
}

/// A uniform elliptical disc with semi-axes `a`, `b`, its `a` axis at `angle` (radians) from
/// the surface, striking with its support point: `I = m (a² + b²)/4`.
#[pyfunction]
#[pyo3(signature = (mass = 1.0, a = 2.0, b = 1.0, angle = 0.0, *, velocity = DEFAULT_VELOCITY, omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
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
    let mut s = spec(Shape::Ellipse.name(), mass);
    s.semi_axes = Some([a, b]);
    s.angle = Some(angle);
    let motion = Motion::direct(velocity, omega);
    striking(s, motion, friction, restitution, other)
}

/// Any planar rigid body: mass, central moment of inertia and the contact point
/// `contact = (r_t, r_n)` relative to the centre of mass, in the contact frame.
#[pyfunction]
#[pyo3(signature = (mass, inertia, contact, *, velocity = DEFAULT_VELOCITY, omega = 0.0, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None))]
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
    let mut s = spec(Shape::Rigid.name(), mass);
    s.inertia = Some(inertia);
    s.contact = Some([contact.0, contact.1]);
    let motion = Motion::direct(velocity, omega);
    striking(s, motion, friction, restitution, other)
}

/// A striking body A of any shape by name (one of `SHAPES`), its parameters by keyword as the
/// scenario files name them, angles in radians (`radius=1.0`, `length=2.0, angle=0.9`,
/// `semi_axes=(2, 1)`, `inertia=0.5, contact=(0.3, -1)`, …).
///
/// The motion: `velocity=(vx, vy)` and `omega`, or paper A's `speed`, `alpha`, `spin_ratio`
/// for a round body (sphere, disc). Without either: paper A's seed state (v0 = 1, α = 30°,
/// γ = 0) for a round body, `velocity=(0.5, -1)` for any other (the defaults of `sphere` and
/// of `rod`).
#[pyfunction]
#[pyo3(signature = (shape, mass = 1.0, *, speed = None, alpha = None, spin_ratio = None, velocity = None, omega = None, friction = SEED_FRICTION, restitution = SEED_RESTITUTION, other = None, **params))]
#[allow(clippy::too_many_arguments)]
pub fn body_impact(
    shape: &str,
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::speed)] speed: Option<f64>,
    #[pyo3(from_py_with = arg::alpha)] alpha: Option<f64>,
    #[pyo3(from_py_with = arg::spin_ratio)] spin_ratio: Option<f64>,
    #[pyo3(from_py_with = arg::velocity)] velocity: Option<(f64, f64)>,
    #[pyo3(from_py_with = arg::omega)] omega: Option<f64>,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
    other: Option<PyRef<'_, Body>>,
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<BodyImpact> {
    let mut s = spec(shape, mass);
    shape_params(&mut s, params)?;
    let given = [speed, alpha, spin_ratio, omega]
        .iter()
        .any(Option::is_some);
    let round = Shape::from_name(shape).is_some_and(Shape::is_round);
    let motion = if given || velocity.is_some() || round {
        Motion {
            speed,
            alpha,
            spin_ratio,
            velocity,
            omega,
        }
    } else {
        Motion::direct(DEFAULT_VELOCITY, 0.0)
    };
    striking(s, motion, friction, restitution, other)
}

/// A struck body B for `other=` (the `[other]` table of a scenario file), met at its highest
/// point: `shape` is one of `SHAPES` — `sphere`, `disc` (`radius`), `rod` (`length`, `angle`
/// from the surface), `ellipse` (`semi_axes`, `angle`), `rigid` (`inertia`, `contact` from the
/// centre), … — with its parameters by keyword as the scenario files name them (angles in
/// radians); `velocity` and `omega` its state (default: at rest).
#[pyfunction]
#[pyo3(signature = (shape, mass = 1.0, *, radius = None, length = None, angle = None, semi_axes = None, inertia = None, contact = None, velocity = (0.0, 0.0), omega = 0.0, **params))]
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
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<Body> {
    let mut s = spec(shape, mass);
    s.radius = radius;
    s.length = length;
    s.angle = angle;
    s.semi_axes = semi_axes.map(|(a, b)| [a, b]);
    s.inertia = inertia;
    s.contact = contact.map(|(t, n)| [t, n]);
    shape_params(&mut s, params)?;
    Motion::direct(velocity, omega).fill(&mut s);
    Ok(Body::new(lib(s.build("", Side::Above))?))
}
