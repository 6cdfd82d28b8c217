//! `compare`: every law side by side on one impact, as `impax compare --json`.

use crate::body::BodyImpact;
use crate::convert::{law, value_error};
use crate::mechanisms::MechanismImpact;
use crate::shapes::{sphere, SEED_FRICTION, SEED_RESTITUTION};
use impax::LawId;
use pyo3::prelude::*;
use pyo3::types::PyList;

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
