//! `impax.resolve`: one contact-space problem.

use crate::convert::{arg, lib, matrix, planar_law, spatial_law, vector, Matrix};
use crate::outcome::{Context, Outcome, Raw};
use impax::math::{Vec2, Vec3};
use impax::planar::ContactProblem;
use impax::spatial::ContactProblem3;
use pyo3::prelude::*;

/// Resolve one impact in contact space with one law.
///
/// `W` is the contact-space inverse inertia `J M⁻¹ Jᵀ` (2×2 planar or 3×3 spatial, or its
/// upper triangle: 3 or 6 numbers as `impax resolve --w`), `v` the contact velocity before
/// (tangent(s) first, normal last, `v_n < 0`), `friction` μ ≥ 0, `restitution` e ∈ [0, 1].
/// During the impact `v(p) = v⁻ + W p` (theory §1).
#[pyfunction]
#[pyo3(signature = (w, v, friction, restitution, law = "energetic"))]
pub fn resolve(
    w: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    #[pyo3(from_py_with = arg::friction)] friction: f64,
    #[pyo3(from_py_with = arg::restitution)] restitution: f64,
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
            let p = lib(ContactProblem3::new(
                m,
                Vec3::new(v[0], v[1], v[2]),
                friction,
                restitution,
            ))?;
            Ok(Outcome {
                law,
                raw: Raw::Spatial(law.resolve3(&p)),
                approach_energy: p.approach_energy(),
                context: Context::Contact,
                problem3: Some(p),
            })
        }
    }
}
