//! `impax._impax`: the compiled core of the `impax` Python package.
//!
//! Thin bindings over the `impax` library (no physics here): every number comes from the
//! library's laws, bodies and mechanisms, and every error is the library's (or the CLI's)
//! message, raised as `ValueError`. The pure-Python package (`python/impax/`) re-exports these
//! functions and adds the study helpers and the Dask sweeps.
//!
//! * [`single`]: `resolve` — one contact-space problem, a small `Outcome` object;
//! * [`batch`]: `resolve_batch` — many problems on numpy arrays, the GIL released, rayon
//!   inside, no allocation per row; with `contacts=K`, [`batch_multi`];
//! * [`bodies`]: `sphere`, `disc`, `rod`, `ellipse`, `rigid_body`, `double_pendulum`,
//!   `mechanism`, and `compare` — every law side by side, as `impax compare --json`;
//! * [`scenarios`]: `rod_rows`, `sphere_rows` — the rows of many bodies at once, for
//!   `impax.study`.

use pyo3::prelude::*;

mod batch;
mod batch_multi;
mod bodies;
mod convert;
mod multi;
mod outcome;
mod scenarios;
mod single;

/// The `impax._impax` extension module.
#[pymodule]
fn _impax(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add(
        "LAWS",
        impax::LawId::ALL
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>(),
    )?;
    m.add(
        "CONTACT_SPACE_LAWS",
        impax::LawId::CONTACT_SPACE
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>(),
    )?;
    m.add(
        "SPATIAL_LAWS",
        impax::LawId::SPATIAL
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>(),
    )?;
    m.add(
        "MULTI_CONTACT_LAWS",
        impax::LawId::MULTI_CONTACT
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>(),
    )?;
    m.add("MAX_THREADS", convert::MAX_THREADS)?;
    m.add("STATUSES", batch::STATUSES.to_vec())?;
    m.add("SEQUENCES", batch::SEQUENCES.to_vec())?;
    m.add("SEQUENCES_3D", batch::SEQUENCES_3D.to_vec())?;
    m.add(
        "MECHANISMS",
        impax::mechanism::builtin::BuiltIn::NAMES.to_vec(),
    )?;
    m.add_class::<outcome::Outcome>()?;
    m.add_class::<multi::MultiOutcome>()?;
    m.add_class::<bodies::Body>()?;
    m.add_class::<bodies::BodyImpact>()?;
    m.add_class::<bodies::MechanismImpact>()?;
    m.add_function(wrap_pyfunction!(single::resolve, m)?)?;
    m.add_function(wrap_pyfunction!(batch::resolve_batch, m)?)?;
    m.add_function(wrap_pyfunction!(batch::check_threads, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::sphere, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::disc, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::rod, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::ellipse, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::rigid_body, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::body, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::double_pendulum, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::mechanism, m)?)?;
    m.add_function(wrap_pyfunction!(bodies::compare, m)?)?;
    m.add_function(wrap_pyfunction!(scenarios::rod_rows, m)?)?;
    m.add_function(wrap_pyfunction!(scenarios::sphere_rows, m)?)?;
    Ok(())
}
