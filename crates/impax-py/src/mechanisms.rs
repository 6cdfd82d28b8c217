//! Built-in mechanisms striking with their contact: [`MechanismImpact`], [`mechanism`] by
//! name with the command line's defaults, and [`double_pendulum`]. Angles in radians.

use crate::convert::{arg, lib, mat2, value_error};
use crate::outcome::{Context, Outcome, Raw};
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

/// A built-in mechanism by name, with the CLI's defaults (`impax compare MECHANISM`); the
/// description, its checks and its defaults are the core's (`impax::scenario::MechanismSpec`),
/// with angles in radians.
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
    let spec = MechanismSpec {
        mechanism: name.into(),
        masses,
        lengths,
        radius,
        gravity,
        angles,
        rates,
        position,
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
