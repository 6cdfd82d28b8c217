//! `impax.resolve`: one contact-space problem.

use crate::convert::{
    arg, lib, matrix, planar_law, spatial_law, value_error, vector, Matrix, OneOrMany,
};
use crate::multi::MultiOutcome;
use crate::outcome::{Context, Outcome, Raw};
use impax::math::{Vec2, Vec3};
use impax::planar::ContactProblem;
use impax::spatial;
use pyo3::prelude::*;

/// Resolve one impact in contact space with one law.
///
/// `W` is the contact-space inverse inertia `J M⁻¹ Jᵀ` (2×2 planar or 3×3 spatial, or its
/// upper triangle: 3 or 6 numbers as `impax resolve --w`), `v` the contact velocity before
/// (tangent(s) first, normal last, `v_n < 0`), `friction` μ ≥ 0, `restitution` e ∈ [0, 1].
/// During the impact `v(p) = v⁻ + W p` (theory §1).
///
/// With `contacts=K`: a planar problem with `K` contacts at once (`impax resolve --contacts
/// K`): `W` `2K × 2K` (or its upper triangle), `v` `2K` numbers or `K` pairs, `friction` and
/// `restitution` one number or `K`; the laws `lcp`, `sequential` and `lzb` (with `K = 1`
/// every contact-space law); a [`MultiOutcome`]. For `lzb`, `stiffness` (one number or `K`,
/// the contacts' `κ_j` of the force law `F_j = κ_j δ_j^η`, only ratios matter, default 1) and
/// `exponent` (`η`, default 1.5, Hertz), as `--stiffness` and `--exponent`.
#[pyfunction]
#[pyo3(signature = (w, v, friction, restitution, law = "energetic", *, contacts = None, stiffness = None, exponent = None))]
#[allow(clippy::too_many_arguments)] // the keyword arguments of one Python function
pub fn resolve(
    py: Python<'_>,
    w: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    #[pyo3(from_py_with = arg::friction)] friction: OneOrMany,
    #[pyo3(from_py_with = arg::restitution)] restitution: OneOrMany,
    law: &str,
    contacts: Option<usize>,
    #[pyo3(from_py_with = arg::stiffness)] stiffness: Option<OneOrMany>,
    #[pyo3(from_py_with = arg::exponent)] exponent: Option<f64>,
) -> PyResult<Py<PyAny>> {
    if let Some(k) = contacts {
        let force = crate::multi::ForceLaw {
            stiffness: stiffness.map(|s| s.0),
            exponent,
        };
        let out: MultiOutcome =
            crate::multi::resolve(w, v, &friction.0, &restitution.0, law, k, &force)?;
        return Ok(Py::new(py, out)?.into_any());
    }
    if stiffness.is_some() || exponent.is_some() {
        let name = if stiffness.is_some() {
            "stiffness"
        } else {
            "exponent"
        };
        return Err(value_error(format!(
            "{name}: a parameter of `lzb` at several contacts; only with contacts=K"
        )));
    }
    let friction = friction.single("friction")?;
    let restitution = restitution.single("restitution")?;
    Ok(Py::new(py, one(w, v, friction, restitution, law)?)?.into_any())
}

/// One contact.
fn one(
    w: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    friction: f64,
    restitution: f64,
    law: &str,
) -> PyResult<Outcome> {
    match matrix(w)? {
        Matrix::Planar(m) => {
            let v = vector(v, 2, "2 numbers (v_t, v_n) for a planar W")?;
            let law = planar_law(law)?;
            let p = lib(ContactProblem::new(
                m,
                Vec2::new(v[0], v[1]),
                friction,
                restitution,
            ))?;
            Ok(Outcome {
                law,
                raw: Raw::Planar(law.resolve(&p)),
                approach_energy: p.approach_energy(),
                context: Context::Contact,
                problem3: None,
            })
        }
        Matrix::Spatial(m) => {
            let v = vector(v, 3, "3 numbers (v_t1, v_t2, v_n) for a spatial W")?;
            let law = spatial_law(law)?;
            let p = lib(spatial::ContactProblem::new(
                m,
                Vec3::new(v[0], v[1], v[2]),
                friction,
                restitution,
            ))?;
            Ok(Outcome {
                law,
                raw: Raw::Spatial(law.resolve(&p)),
                approach_energy: p.approach_energy(),
                context: Context::Contact,
                problem3: Some(p),
            })
        }
    }
}
