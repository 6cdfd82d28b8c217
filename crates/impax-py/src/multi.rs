//! `impax.resolve(..., contacts=K)`: a planar problem with several contacts at once, and its
//! outcome ([`MultiOutcome`]) with the keys of `impax resolve --contacts K --json`.

use crate::convert::{float_array, lib, value_error};
use impax::law::WorkSplit;
use impax::math::Vec2;
use impax::multi::{MultiDetail, MultiProblem, MultiResolution};
use impax::LawId;
use nalgebra::DMatrix;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

/// The outcome of a multi-contact law: per contact the impulse, the velocity after, the
/// phases and the work; `ΔT`, the verdict, the inconsistency or the breakdown, the detail.
#[pyclass(frozen, module = "impax._impax")]
pub struct MultiOutcome {
    law: LawId,
    raw: MultiResolution,
}

/// Read `W`: a `2K × 2K` matrix, or its upper triangle row by row (`2K (2K + 1) / 2`
/// numbers, as `impax resolve --contacts K --w`).
fn matrix(w: &Bound<'_, PyAny>, k: usize) -> PyResult<DMatrix<f64>> {
    let n = 2 * k;
    let a = float_array(w, "w")?;
    let view = a.as_array();
    let data: Vec<f64> = view.iter().copied().collect();
    match view.shape() {
        [r, c] if *r == n && *c == n => Ok(DMatrix::from_row_slice(n, n, &data)),
        [m] if *m == n * (n + 1) / 2 => {
            let mut out = DMatrix::zeros(n, n);
            let mut it = data.iter();
            for i in 0..n {
                for j in i..n {
                    let x = *it.next().expect("counted");
                    out[(i, j)] = x;
                    out[(j, i)] = x;
                }
            }
            Ok(out)
        }
        s => Err(value_error(format!(
            "w: expected a {n} × {n} matrix or its upper triangle of {} numbers for {k} contacts, got shape {s:?}",
            n * (n + 1) / 2
        ))),
    }
}

/// Read `v`: `2K` numbers or `K` pairs `(v_t, v_n)`.
fn velocities(v: &Bound<'_, PyAny>, k: usize) -> PyResult<Vec<f64>> {
    let a = float_array(v, "v")?;
    let view = a.as_array();
    match view.shape() {
        [m] if *m == 2 * k => Ok(view.iter().copied().collect()),
        [r, 2] if *r == k => Ok(view.iter().copied().collect()),
        s => Err(value_error(format!(
            "v: expected {} numbers (tangent and normal of each of {k} contacts) or shape ({k}, 2), got shape {s:?}",
            2 * k
        ))),
    }
}

/// `lzb`'s force law as given (`stiffness=`, `exponent=`; defaults when `None`).
pub struct ForceLaw {
    /// The contacts' stiffnesses `κ_j` (one or `K`).
    pub stiffness: Option<Vec<f64>>,
    /// The exponent `η`.
    pub exponent: Option<f64>,
}

/// Resolve a planar problem with `k` contacts (`impax.resolve(..., contacts=k)`).
pub fn resolve(
    w: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    friction: &[f64],
    restitution: &[f64],
    law: &str,
    k: usize,
    force: &ForceLaw,
) -> PyResult<MultiOutcome> {
    if k == 0 {
        return Err(value_error("contacts: must be at least 1"));
    }
    let w = matrix(w, k)?;
    let v = velocities(v, k)?;
    let mut problem = lib(MultiProblem::new(w, &v, friction, restitution))?;
    if let Some(kappa) = &force.stiffness {
        problem = lib(problem.with_stiffness(kappa))?;
    }
    if let Some(eta) = force.exponent {
        problem = lib(problem.with_exponent(eta))?;
    }
    let law = crate::convert::law(law)?;
    let raw = lib(law.resolve_multi(&problem))?;
    Ok(MultiOutcome { law, raw })
}

fn pair<'py>(py: Python<'py>, v: Vec2) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(py, [v.x, v.y])
}

fn work<'py>(py: Python<'py>, w: &WorkSplit) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("compression", w.compression)?;
    d.set_item("restitution", w.restitution)?;
    d.set_item("friction", w.friction)?;
    Ok(d)
}

#[pymethods]
impl MultiOutcome {
    /// The law's stable id (`"lcp"`, `"sequential"`, …).
    #[getter]
    fn law(&self) -> &'static str {
        self.law.as_str()
    }

    /// `"consistent"`, `"energy-gained"`, `"inconsistent-assumption"` or `"breakdown"`.
    #[getter]
    fn verdict(&self) -> &'static str {
        match &self.raw {
            Ok(o) => o.verdict.id(),
            Err(_) => "breakdown",
        }
    }

    /// `ΔT = ½ (v⁻ + v⁺)·p` of the whole impact (`None` after a breakdown).
    #[getter]
    fn energy_change(&self) -> Option<f64> {
        self.raw.as_ref().ok().map(|o| o.energy_change)
    }

    /// The impulses `(p_t, p_n)`, one per contact (`None` after a breakdown).
    #[getter]
    fn impulses<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        match &self.raw {
            Ok(o) => Ok(Some(PyList::new(
                py,
                o.contacts
                    .iter()
                    .map(|c| pair(py, c.impulse))
                    .collect::<PyResult<Vec<_>>>()?,
            )?)),
            Err(_) => Ok(None),
        }
    }

    /// The contact velocities after `(v_t⁺, v_n⁺)`, one per contact.
    #[getter]
    fn velocities_after<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        match &self.raw {
            Ok(o) => Ok(Some(PyList::new(
                py,
                o.contacts
                    .iter()
                    .map(|c| pair(py, c.velocity_after))
                    .collect::<PyResult<Vec<_>>>()?,
            )?)),
            Err(_) => Ok(None),
        }
    }

    /// Per contact `{"impulse", "velocity_after", "phases", "work"}` as in the CLI's JSON
    /// (`phases`: `(kind, ends_at)` pairs; `work`: `{"compression", "restitution",
    /// "friction"}`).
    #[getter]
    fn contacts<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        let Ok(o) = &self.raw else { return Ok(None) };
        let list = PyList::empty(py);
        for c in &o.contacts {
            let d = PyDict::new(py);
            d.set_item("impulse", pair(py, c.impulse)?)?;
            d.set_item("velocity_after", pair(py, c.velocity_after)?)?;
            let phases = PyList::empty(py);
            for p in &c.phases {
                phases.append((p.kind.label(), p.ends_at))?;
            }
            d.set_item("phases", phases)?;
            d.set_item("work", work(py, &c.work)?)?;
            list.append(d)?;
        }
        Ok(Some(list))
    }

    /// `None`, or `{"id", "message"}` (`multiple-solutions` for `lcp`, `still-approaching`).
    #[getter]
    fn inconsistency<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.raw {
            Ok(o) => match o.inconsistency {
                Some(i) => {
                    let d = PyDict::new(py);
                    d.set_item("id", i.id())?;
                    d.set_item("message", i.to_string())?;
                    Ok(Some(d))
                }
                None => Ok(None),
            },
            Err(_) => Ok(None),
        }
    }

    /// `None`, or `{"id", "message"}` when the law broke down (e.g. `too-many-impacts`).
    #[getter]
    fn breakdown<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.raw {
            Err(b) => {
                let d = PyDict::new(py);
                d.set_item("id", b.reason.id())?;
                d.set_item("message", b.reason.to_string())?;
                Ok(Some(d))
            }
            Ok(_) => Ok(None),
        }
    }

    /// `lcp`: `{"solutions": [...]}` (each `energy_change` and per contact `kind`, `impulse`,
    /// `velocity_after`; least kinetic energy after first); `sequential`: `{"impacts": [...]}`
    /// (each `contact` counted from 1, `velocity_before`, `impulse`, `velocity_after`,
    /// `energy_change`); otherwise `None`.
    #[getter]
    fn detail<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Ok(o) = &self.raw else { return Ok(None) };
        let d = PyDict::new(py);
        match &o.detail {
            MultiDetail::Lcp { solutions } => {
                let list = PyList::empty(py);
                for s in solutions {
                    let e = PyDict::new(py);
                    e.set_item("energy_change", s.energy_change)?;
                    let cs = PyList::empty(py);
                    for j in 0..s.regimes.len() {
                        let c = PyDict::new(py);
                        c.set_item("kind", s.regimes[j].label())?;
                        c.set_item("impulse", pair(py, s.impulses[j])?)?;
                        c.set_item("velocity_after", pair(py, s.velocities_after[j])?)?;
                        cs.append(c)?;
                    }
                    e.set_item("contacts", cs)?;
                    list.append(e)?;
                }
                d.set_item("solutions", list)?;
            }
            MultiDetail::Sequential { impacts } => {
                let list = PyList::empty(py);
                for b in impacts {
                    let e = PyDict::new(py);
                    e.set_item("contact", b.contact + 1)?;
                    e.set_item("velocity_before", pair(py, b.velocity_before)?)?;
                    e.set_item("impulse", pair(py, b.outcome.impulse)?)?;
                    e.set_item("velocity_after", pair(py, b.outcome.velocity_after)?)?;
                    e.set_item("energy_change", b.outcome.energy_change)?;
                    list.append(e)?;
                }
                d.set_item("impacts", list)?;
            }
            MultiDetail::Lzb { primaries, steps } => {
                let list = PyList::empty(py);
                for p in primaries {
                    list.append((p.contact + 1, p.impulse))?;
                }
                d.set_item("primaries", list)?;
                d.set_item("steps", *steps)?;
            }
            _ => return Ok(None),
        }
        Ok(Some(d))
    }

    fn __repr__(&self) -> String {
        match &self.raw {
            Ok(o) => format!(
                "MultiOutcome(law={}, contacts={}, energy_change={}, verdict={})",
                self.law,
                o.contacts.len(),
                o.energy_change,
                o.verdict.id()
            ),
            Err(b) => format!(
                "MultiOutcome(law={}, breakdown={})",
                self.law,
                b.reason.id()
            ),
        }
    }
}
