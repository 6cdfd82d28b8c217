//! `impax.resolve(..., contacts=K)`: a problem with several contacts at once, planar or
//! spatial, and its outcome ([`MultiOutcome`]) with the keys of
//! `impax resolve --contacts K --json`.

use crate::convert::{float_array, lib, value_error};
use impax::law::WorkSplit;
use impax::multi::spatial as multi3;
use impax::multi::{MultiDetail, MultiProblem};
use impax::spatial;
use impax::LawId;
use nalgebra::DMatrix;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

/// The outcome of a multi-contact law: per contact the impulse, the velocity after, the
/// phases and the work; `ΔT`, the verdict, the inconsistency or the breakdown, the detail.
/// Vectors are `(p_t, p_n)` in the plane and `(p_t1, p_t2, p_n)` in 3D.
#[pyclass(frozen, module = "impax._impax")]
pub struct MultiOutcome {
    law: LawId,
    view: Result<View, (&'static str, String)>,
}

/// An outcome, planar or spatial, as Python sees it.
struct View {
    verdict: &'static str,
    energy_change: f64,
    contacts: Vec<ContactView>,
    inconsistency: Option<(&'static str, String)>,
    detail: DetailView,
}

struct ContactView {
    impulse: Vec<f64>,
    velocity_after: Vec<f64>,
    phases: Vec<(&'static str, f64)>,
    work: WorkSplit,
}

enum DetailView {
    None,
    /// Per solution `ΔT` and per contact `(kind, impulse, velocity_after, slip angle in 3D)`.
    Lcp(Vec<(f64, Vec<SolutionContact>)>),
    /// The binary impacts in order.
    Sequential(Vec<Binary>),
    /// The primaries `(contact from 1, impulse)` and the steps.
    Lzb(Vec<(usize, f64)>, usize),
}

/// One binary impact: `(contact from 1, velocity_before, impulse, velocity_after, ΔT)`.
type Binary = (usize, Vec<f64>, Vec<f64>, Vec<f64>, f64);

struct SolutionContact {
    kind: &'static str,
    impulse: Vec<f64>,
    velocity_after: Vec<f64>,
    slip_angle_deg: Option<f64>,
}

fn v2(v: impax::math::Vec2) -> Vec<f64> {
    vec![v.x, v.y]
}

fn v3(v: impax::math::Vec3) -> Vec<f64> {
    vec![v.x, v.y, v.z]
}

impl View {
    fn planar(o: &impax::multi::MultiOutcome) -> Self {
        let detail = match &o.detail {
            MultiDetail::Lcp { solutions } => DetailView::Lcp(
                solutions
                    .iter()
                    .map(|s| {
                        let cs = (0..s.regimes.len())
                            .map(|j| SolutionContact {
                                kind: s.regimes[j].label(),
                                impulse: v2(s.impulses[j]),
                                velocity_after: v2(s.velocities_after[j]),
                                slip_angle_deg: None,
                            })
                            .collect();
                        (s.energy_change, cs)
                    })
                    .collect(),
            ),
            MultiDetail::Sequential { impacts } => DetailView::Sequential(
                impacts
                    .iter()
                    .map(|b| {
                        (
                            b.contact + 1,
                            v2(b.velocity_before),
                            v2(b.outcome.impulse),
                            v2(b.outcome.velocity_after),
                            b.outcome.energy_change,
                        )
                    })
                    .collect(),
            ),
            MultiDetail::Lzb { primaries, steps } => DetailView::Lzb(
                primaries
                    .iter()
                    .map(|p| (p.contact + 1, p.impulse))
                    .collect(),
                *steps,
            ),
            MultiDetail::OneContact { .. } => DetailView::None,
        };
        Self {
            verdict: o.verdict.id(),
            energy_change: o.energy_change,
            contacts: o
                .contacts
                .iter()
                .map(|c| ContactView {
                    impulse: v2(c.impulse),
                    velocity_after: v2(c.velocity_after),
                    phases: c
                        .phases
                        .iter()
                        .map(|p| (p.kind.label(), p.ends_at))
                        .collect(),
                    work: c.work,
                })
                .collect(),
            inconsistency: o.inconsistency.map(|i| (i.id(), i.to_string())),
            detail,
        }
    }

    fn spatial(o: &multi3::MultiOutcome) -> Self {
        let detail = match &o.detail {
            multi3::MultiDetail::Lcp { solutions } => DetailView::Lcp(
                solutions
                    .iter()
                    .map(|s| {
                        let cs = (0..s.regimes.len())
                            .map(|j| SolutionContact {
                                kind: s.regimes[j].label(),
                                impulse: v3(s.impulses[j]),
                                velocity_after: v3(s.velocities_after[j]),
                                slip_angle_deg: match s.regimes[j] {
                                    multi3::ContactPhaseKind::Impact(spatial::PhaseKind::Slip {
                                        to,
                                        ..
                                    }) => Some(to.to_degrees()),
                                    _ => None,
                                },
                            })
                            .collect();
                        (s.energy_change, cs)
                    })
                    .collect(),
            ),
            multi3::MultiDetail::Sequential { impacts } => DetailView::Sequential(
                impacts
                    .iter()
                    .map(|b| {
                        (
                            b.contact + 1,
                            v3(b.velocity_before),
                            v3(b.outcome.impulse),
                            v3(b.outcome.velocity_after),
                            b.outcome.energy_change,
                        )
                    })
                    .collect(),
            ),
            multi3::MultiDetail::Lzb { primaries, steps } => DetailView::Lzb(
                primaries.iter().map(|p| (p.contact + 1, p.impulse)).collect(),
                *steps,
            ),
            multi3::MultiDetail::OneContact { .. } => DetailView::None,
        };
        Self {
            verdict: o.verdict.id(),
            energy_change: o.energy_change,
            contacts: o
                .contacts
                .iter()
                .map(|c| ContactView {
                    impulse: v3(c.impulse),
                    velocity_after: v3(c.velocity_after),
                    phases: c
                        .phases
                        .iter()
                        .map(|p| (p.kind.label(), p.ends_at))
                        .collect(),
                    work: c.work,
                })
                .collect(),
            inconsistency: o.inconsistency.map(|i| (i.id(), i.to_string())),
            detail,
        }
    }
}

/// Read `W`: a `dK × dK` matrix, or its upper triangle row by row (`dK (dK + 1) / 2`
/// numbers, as `impax resolve --contacts K --w`); `d` (2 or 3) from its size.
fn matrix(w: &Bound<'_, PyAny>, k: usize) -> PyResult<(usize, DMatrix<f64>)> {
    let a = float_array(w, "w")?;
    let view = a.as_array();
    let data: Vec<f64> = view.iter().copied().collect();
    for d in [2, 3] {
        let n = d * k;
        match view.shape() {
            [r, c] if *r == n && *c == n => return Ok((d, DMatrix::from_row_slice(n, n, &data))),
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
                return Ok((d, out));
            }
            _ => {}
        }
    }
    let (n, n3) = (2 * k, 3 * k);
    Err(value_error(format!(
        "w: expected a {n} × {n} matrix or its upper triangle of {} numbers for {k} planar contacts, or {n3} × {n3} ({} numbers) in 3D, got shape {:?}",
        n * (n + 1) / 2,
        n3 * (n3 + 1) / 2,
        view.shape()
    )))
}

/// Read `v`: `dK` numbers or `K` rows of `d`.
fn velocities(v: &Bound<'_, PyAny>, k: usize, d: usize) -> PyResult<Vec<f64>> {
    let a = float_array(v, "v")?;
    let view = a.as_array();
    match view.shape() {
        [m] if *m == d * k => Ok(view.iter().copied().collect()),
        [r, c] if *r == k && *c == d => Ok(view.iter().copied().collect()),
        s => Err(value_error(format!(
            "v: expected {} numbers ({} of each of {k} contacts) or shape ({k}, {d}), got shape {s:?}",
            d * k,
            if d == 2 {
                "tangent and normal"
            } else {
                "the two tangents and the normal"
            }
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

/// Resolve a problem with `k` contacts (`impax.resolve(..., contacts=k)`): planar for a
/// `2K × 2K` W, spatial for `3K × 3K`.
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
    let (d, w) = matrix(w, k)?;
    let v = velocities(v, k, d)?;
    let law = crate::convert::law(law)?;
    let raw = if d == 2 {
        let mut problem = lib(MultiProblem::new(w, &v, friction, restitution))?;
        if let Some(kappa) = &force.stiffness {
            problem = lib(problem.with_stiffness(kappa))?;
        }
        if let Some(eta) = force.exponent {
            problem = lib(problem.with_exponent(eta))?;
        }
        lib(law.resolve(&problem))?
            .as_ref()
            .map(View::planar)
            .map_err(|b| (b.reason.id(), b.reason.to_string()))
    } else {
        let mut problem = lib(multi3::MultiProblem::new(w, &v, friction, restitution))?;
        if let Some(kappa) = &force.stiffness {
            problem = lib(problem.with_stiffness(kappa))?;
        }
        if let Some(eta) = force.exponent {
            problem = lib(problem.with_exponent(eta))?;
        }
        lib(multi3::resolve(law, &problem))?
            .as_ref()
            .map(View::spatial)
            .map_err(|b| (b.reason.id(), b.reason.to_string()))
    };
    Ok(MultiOutcome { law, view: raw })
}

fn tuple<'py>(py: Python<'py>, v: &[f64]) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(py, v)
}

fn work<'py>(py: Python<'py>, w: &WorkSplit) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("compression", w.compression)?;
    d.set_item("restitution", w.restitution)?;
    d.set_item("friction", w.friction)?;
    Ok(d)
}

fn id_message<'py>(py: Python<'py>, x: &(&'static str, String)) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("id", x.0)?;
    d.set_item("message", &x.1)?;
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
        match &self.view {
            Ok(o) => o.verdict,
            Err(_) => "breakdown",
        }
    }

    /// `ΔT = ½ (v⁻ + v⁺)·p` of the whole impact (`None` after a breakdown).
    #[getter]
    fn energy_change(&self) -> Option<f64> {
        self.view.as_ref().ok().map(|o| o.energy_change)
    }

    /// The impulses, one tuple per contact: `(p_t, p_n)`, or `(p_t1, p_t2, p_n)` in 3D
    /// (`None` after a breakdown).
    #[getter]
    fn impulses<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        let Ok(o) = &self.view else { return Ok(None) };
        let items = o
            .contacts
            .iter()
            .map(|c| tuple(py, &c.impulse))
            .collect::<PyResult<Vec<_>>>()?;
        Ok(Some(PyList::new(py, items)?))
    }

    /// The contact velocities after, one tuple per contact (as [`MultiOutcome::impulses`]).
    #[getter]
    fn velocities_after<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        let Ok(o) = &self.view else { return Ok(None) };
        let items = o
            .contacts
            .iter()
            .map(|c| tuple(py, &c.velocity_after))
            .collect::<PyResult<Vec<_>>>()?;
        Ok(Some(PyList::new(py, items)?))
    }

    /// Per contact `{"impulse", "velocity_after", "phases", "work"}` as in the CLI's JSON
    /// (`phases`: `(kind, ends_at)` pairs; `work`: `{"compression", "restitution",
    /// "friction"}`).
    #[getter]
    fn contacts<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        let Ok(o) = &self.view else { return Ok(None) };
        let list = PyList::empty(py);
        for c in &o.contacts {
            let d = PyDict::new(py);
            d.set_item("impulse", tuple(py, &c.impulse)?)?;
            d.set_item("velocity_after", tuple(py, &c.velocity_after)?)?;
            let phases = PyList::empty(py);
            for p in &c.phases {
                phases.append(*p)?;
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
        match &self.view {
            Ok(View {
                inconsistency: Some(i),
                ..
            }) => Ok(Some(id_message(py, i)?)),
            _ => Ok(None),
        }
    }

    /// `None`, or `{"id", "message"}` when the law broke down (e.g. `too-many-impacts`).
    #[getter]
    fn breakdown<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.view {
            Err(b) => Ok(Some(id_message(py, b)?)),
            Ok(_) => Ok(None),
        }
    }

    /// `lcp`: `{"solutions": [...]}` (each `energy_change` and per contact `kind`, `impulse`,
    /// `velocity_after`, in 3D `slip_angle_deg` for a slip; least kinetic energy after
    /// first); `sequential`: `{"impacts": [...]}` (each `contact` counted from 1,
    /// `velocity_before`, `impulse`, `velocity_after`, `energy_change`); `lzb`:
    /// `{"primaries": [(contact, impulse), ...], "steps"}`; otherwise `None`.
    #[getter]
    fn detail<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Ok(o) = &self.view else { return Ok(None) };
        let d = PyDict::new(py);
        match &o.detail {
            DetailView::Lcp(solutions) => {
                let list = PyList::empty(py);
                for (energy, contacts) in solutions {
                    let e = PyDict::new(py);
                    e.set_item("energy_change", *energy)?;
                    let cs = PyList::empty(py);
                    for s in contacts {
                        let c = PyDict::new(py);
                        c.set_item("kind", s.kind)?;
                        c.set_item("impulse", tuple(py, &s.impulse)?)?;
                        c.set_item("velocity_after", tuple(py, &s.velocity_after)?)?;
                        if let Some(a) = s.slip_angle_deg {
                            c.set_item("slip_angle_deg", a)?;
                        }
                        cs.append(c)?;
                    }
                    e.set_item("contacts", cs)?;
                    list.append(e)?;
                }
                d.set_item("solutions", list)?;
            }
            DetailView::Sequential(impacts) => {
                let list = PyList::empty(py);
                for (contact, before, impulse, after, energy) in impacts {
                    let e = PyDict::new(py);
                    e.set_item("contact", *contact)?;
                    e.set_item("velocity_before", tuple(py, before)?)?;
                    e.set_item("impulse", tuple(py, impulse)?)?;
                    e.set_item("velocity_after", tuple(py, after)?)?;
                    e.set_item("energy_change", *energy)?;
                    list.append(e)?;
                }
                d.set_item("impacts", list)?;
            }
            DetailView::Lzb(primaries, steps) => {
                let list = PyList::empty(py);
                for p in primaries {
                    list.append(*p)?;
                }
                d.set_item("primaries", list)?;
                d.set_item("steps", *steps)?;
            }
            DetailView::None => return Ok(None),
        }
        Ok(Some(d))
    }

    fn __repr__(&self) -> String {
        match &self.view {
            Ok(o) => format!(
                "MultiOutcome(law={}, contacts={}, energy_change={}, verdict={})",
                self.law,
                o.contacts.len(),
                o.energy_change,
                o.verdict
            ),
            Err(b) => format!("MultiOutcome(law={}, breakdown={})", self.law, b.0),
        }
    }
}
