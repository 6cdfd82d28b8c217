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
//! * [`shapes`]: `sphere`, `disc`, `rod`, `ellipse`, `rigid_body`, `body_impact` (any shape by
//!   name) and `body` (a struck body B) — adapters over the core's `impax::scenario::BodySpec`,
//!   building the classes of [`body`] (`BodyImpact`, `Body`);
//! * [`mechanisms`]: `mechanism` (a built-in by name, or a mechanism of one's own),
//!   `double_pendulum`, `MechanismImpact`;
//! * [`robots`]: `Mechanism` — a mechanism file (planar or spatial) or a URDF robot read once
//!   ([`robot_load`]): `M(q)`, contact Jacobians and problems, impacts as the command line's
//!   records ([`robot_impact`]) and in batches over numpy arrays ([`robot_batch`]);
//! * [`compare`]: every law side by side, as `impax compare --json`;
//! * [`scenarios`]: `rod_rows`, `sphere_rows` — the rows of many bodies at once, for
//!   `impax.study`.

use pyo3::prelude::*;

mod batch;
mod batch_multi;
mod body;
mod compare;
mod convert;
mod mechanisms;
mod multi;
mod outcome;
mod robot_batch;
mod robot_impact;
mod robot_load;
mod robots;
mod scenarios;
mod shapes;
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
    m.add("SHAPES", impax::scenario::Shape::NAMES.to_vec())?;
    m.add(
        "MECHANISMS",
        impax::mechanism::builtin::BuiltIn::NAMES.to_vec(),
    )?;
    m.add_class::<outcome::Outcome>()?;
    m.add_class::<multi::MultiOutcome>()?;
    m.add_class::<body::Body>()?;
    m.add_class::<body::BodyImpact>()?;
    m.add_class::<mechanisms::MechanismImpact>()?;
    m.add_class::<robots::Mechanism>()?;
    m.add_function(wrap_pyfunction!(single::resolve, m)?)?;
    m.add_function(wrap_pyfunction!(batch::resolve_batch, m)?)?;
    m.add_function(wrap_pyfunction!(batch::check_threads, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::sphere, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::disc, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::rod, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::ellipse, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::rigid_body, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::body_impact, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::body, m)?)?;
    m.add_function(wrap_pyfunction!(mechanisms::double_pendulum, m)?)?;
    m.add_function(wrap_pyfunction!(mechanisms::mechanism, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare, m)?)?;
    m.add_function(wrap_pyfunction!(scenarios::rod_rows, m)?)?;
    m.add_function(wrap_pyfunction!(scenarios::sphere_rows, m)?)?;
    Ok(())
}
