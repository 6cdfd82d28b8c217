//! Built-in mechanisms striking with their contact: [`MechanismImpact`], [`mechanism`] by
//! name with the command line's defaults, and [`double_pendulum`]. Angles in radians.

use crate::convert::{arg, lib, mat2, value_error};
use crate::outcome::{Context, Outcome, Raw};
use crate::robot_load as robots;
use impax::math::Vec2;
use impax::mechanism::builtin::{BuiltIn, STANDARD_GRAVITY};
use impax::mechanism::impact::MechanismImpact as LibMechanismImpact;
use impax::mechanism::Mechanism;
use impax::scenario::{AngleUnit, BuiltMechanism, MechanismSpec};
use impax::LawId;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::f64::consts::FRAC_PI_6;

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

    pub(crate) fn outcome(&self, law: LawId) -> PyResult<Outcome> {
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
        mat2(py, self.impact()?.inverse_inertia())
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

/// A mechanism: a built-in by name, with the CLI's defaults (`impax compare MECHANISM`), or
/// a mechanism of one's own — a path to (or the text of) a mechanism file (`.toml`, planar or
/// `space = "3d"`) or a URDF robot (`.urdf`).
///
/// A built-in returns a [`MechanismImpact`] at its state; its description, checks and
/// defaults are the core's (`impax::scenario::MechanismSpec`), with angles in radians:
///
/// | name | coordinates | `masses`, `lengths`, `radius` | defaults |
/// |---|---|---|---|
/// | `double-pendulum` | θ1, θ2 from the downward vertical | m1, m2; l1, l2 | 30°, 0°; rates −1, 2 |
/// | `sphere` | x, y, θ | m; —; r | on the floor, velocity (sin 30°, −cos 30°) |
/// | `rod` | x, y, θ from the floor | m; l | 50°, lower end on the floor, velocity (0.5, −1) |
///
/// `ring-pendulum` and `cart-pendulum` have no contact to strike (see `impax conserved`).
///
/// A file or a robot returns a [`crate::robots::Mechanism`], read once, to evaluate at any
/// state: `floating_base` (URDF: a free joint first, `q = (x, y, z, qw, qx, qy, qz, …)`,
/// `u = (v, ω, …)` in the world frame), `contact` (the default contact of its calls: a
/// file's contact, a URDF robot's `LINK` or `LINK:x,y,z`), `floor` (the floor's height;
/// default: a file's `height`, else through the striking contact at each state),
/// `gravity`, `friction` and `restitution` (the defaults of its impacts; else the file's,
/// else 0.5). The built-ins' parameters (`masses`, `lengths`, `radius`, `angles`, `rates`,
/// `position`) are refused for them, and `floating_base`, `contact`, `floor` for a built-in.
#[pyfunction]
#[pyo3(signature = (source, /, *, floating_base = false, contact = None, floor = None, gravity = None, masses = None, lengths = None, radius = None, angles = None, rates = None, position = None, friction = None, restitution = None))]
#[allow(clippy::too_many_arguments)]
pub fn mechanism<'py>(
    py: Python<'py>,
    source: &Bound<'py, PyAny>,
    floating_base: bool,
    contact: Option<String>,
    #[pyo3(from_py_with = arg::floor)] floor: Option<f64>,
    #[pyo3(from_py_with = arg::gravity)] gravity: Option<f64>,
    #[pyo3(from_py_with = arg::masses)] masses: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::lengths)] lengths: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::radius)] radius: Option<f64>,
    #[pyo3(from_py_with = arg::angles)] angles: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::rates)] rates: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::position)] position: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::friction)] friction: Option<f64>,
    #[pyo3(from_py_with = arg::restitution)] restitution: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let Some(own) = robots::source(source)? else {
        for (field, given) in [
            ("floating_base", floating_base),
            ("contact", contact.is_some()),
            ("floor", floor.is_some()),
        ] {
            if given {
                return Err(value_error(format!(
                    "{field}: not a parameter of a built-in mechanism (of a mechanism file or a URDF robot)"
                )));
            }
        }
        let name: String = source.extract()?;
        let built = builtin(
            &name,
            BuiltInArgs {
                masses,
                lengths,
                radius,
                gravity,
                angles,
                rates,
                position,
            },
            friction.unwrap_or(0.5),
            restitution.unwrap_or(0.5),
        )?;
        return Ok(Bound::new(py, built)?.into_any());
    };
    for (field, given) in [
        ("masses", masses.is_some()),
        ("lengths", lengths.is_some()),
        ("radius", radius.is_some()),
        ("angles", angles.is_some()),
        ("rates", rates.is_some()),
        ("position", position.is_some()),
    ] {
        if given {
            return Err(value_error(format!(
                "{field}: a parameter of the built-in mechanisms; a mechanism file's or a robot's state is q and u, given to each call"
            )));
        }
    }
    let options = robots::Options {
        floating_base,
        contact,
        floor,
        gravity,
        friction,
        restitution,
    };
    Ok(Bound::new(py, robots::load(py, own, options)?)?.into_any())
}

/// The parameters of a built-in.
struct BuiltInArgs {
    masses: Option<Vec<f64>>,
    lengths: Option<Vec<f64>>,
    radius: Option<f64>,
    gravity: Option<f64>,
    angles: Option<Vec<f64>>,
    rates: Option<Vec<f64>>,
    position: Option<Vec<f64>>,
}

/// A built-in mechanism by name at its state (`mechanism(name, ...)`).
fn builtin(
    name: &str,
    a: BuiltInArgs,
    friction: f64,
    restitution: f64,
) -> PyResult<MechanismImpact> {
    let spec = MechanismSpec {
        mechanism: name.into(),
        masses: a.masses,
        lengths: a.lengths,
        radius: a.radius,
        gravity: a.gravity,
        angles: a.angles,
        rates: a.rates,
        position: a.position,
        angle_unit: AngleUnit::Radians,
        ..MechanismSpec::default()
    };
    let BuiltMechanism {
        mechanism,
        q,
        u,
        description,
    } = lib(spec.build())?;
    if mechanism.contacts().is_empty() {
        return Err(value_error(format!(
            "{name}: has no contact point to strike (try `impax conserved {name}`)"
        )));
    }
    let m = MechanismImpact {
        name: mechanism.name(),
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
    builtin(
        "double-pendulum",
        BuiltInArgs {
            masses: Some(vec![masses.0, masses.1]),
            lengths: Some(vec![lengths.0, lengths.1]),
            radius: None,
            gravity: Some(gravity),
            angles: Some(vec![angles.0, angles.1]),
            rates: Some(vec![rates.0, rates.1]),
            position: None,
        },
        friction,
        restitution,
    )
}
