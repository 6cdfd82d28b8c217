//! `Mechanism.impact_batch`: one law over many states of a mechanism of one's own, given as
//! numpy arrays (N × nq, N × nv), in parallel (rayon, the GIL released).
//!
//! Every row takes the path of `Mechanism.impact` ([`crate::robot_impact::strike`]), so that
//! row `i` equals `impact(q[i], u[i], ..., laws=[law])` bit for bit, whatever the thread
//! count: the model struck at the contact is built once, each worker thread reuses one
//! `Workspace`, and a row allocates only what one impact does (its contact-space matrices
//! and `u⁺`).

use crate::batch::{verdict_code, STATUS_BREAKDOWN, STATUS_INVALID};
use crate::convert::{float_array, threads as thread_count, value_error};
use crate::robot_impact::{strike, Resolved};
use crate::robots::{Kind, Mechanism};
use impax::LawId;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

/// One row's numbers.
struct Out {
    velocities_after: Option<Vec<f64>>,
    impulse: [f64; 3],
    velocity_after: [f64; 3],
    energy_before: f64,
    energy_change: f64,
    status: u8,
    error: Option<impax::Error>,
}

impl Out {
    fn invalid(error: impax::Error) -> Self {
        Out {
            velocities_after: None,
            impulse: [f64::NAN; 3],
            velocity_after: [f64::NAN; 3],
            energy_before: f64::NAN,
            energy_change: f64::NAN,
            status: STATUS_INVALID,
            error: Some(error),
        }
    }

    fn of(energy_before: f64, resolved: Resolved) -> Self {
        let mut out = Out {
            velocities_after: None,
            impulse: [f64::NAN; 3],
            velocity_after: [f64::NAN; 3],
            energy_before,
            energy_change: f64::NAN,
            status: STATUS_BREAKDOWN,
            error: None,
        };
        match resolved {
            Resolved::Planar(r) => {
                if let Ok(o) = &r.resolution {
                    out.impulse[..2].copy_from_slice(o.impulse.as_slice());
                    out.velocity_after[..2].copy_from_slice(o.velocity_after.as_slice());
                    out.energy_change = o.energy_change;
                    out.status = verdict_code(o.verdict);
                }
                out.velocities_after = r.velocities_after;
            }
            Resolved::Spatial(r) => {
                if let Ok(o) = &r.resolution {
                    out.impulse.copy_from_slice(o.impulse.as_slice());
                    out.velocity_after
                        .copy_from_slice(o.velocity_after.as_slice());
                    out.energy_change = o.energy_change;
                    out.status = verdict_code(o.verdict);
                }
                out.velocities_after = r.velocities_after;
            }
        }
        out
    }
}

/// The shape of an array as Python prints it.
fn shape_text(shape: &[usize]) -> String {
    let dims: Vec<String> = shape.iter().map(|d| d.to_string()).collect();
    if dims.len() == 1 {
        format!("({},)", dims[0])
    } else {
        format!("({})", dims.join(", "))
    }
}

/// `impact_batch` (see `Mechanism.impact_batch`).
#[allow(clippy::too_many_arguments)]
pub fn run<'py>(
    py: Python<'py>,
    m: &Mechanism,
    q: &Bound<'py, PyAny>,
    u: &Bound<'py, PyAny>,
    contact: Option<&str>,
    friction: f64,
    restitution: f64,
    law: LawId,
    on_invalid: &str,
    threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let raise = match on_invalid {
        "raise" => true,
        "mark" => false,
        other => {
            return Err(value_error(format!(
                "on_invalid: expected \"raise\" or \"mark\", got {other:?}"
            )))
        }
    };
    let threads = thread_count(threads)?;
    let (nq, nv, dim) = m.dimensions();
    let q = float_array(q, "q")?;
    let u = float_array(u, "u")?;
    let (qv, uv) = (q.as_array(), u.as_array());
    let n = match qv.shape() {
        [n, c] if *c == nq => *n,
        s => {
            return Err(value_error(format!(
                "q: expected shape (N, {nq}) (one row of {nq} coordinates per state), got {}",
                shape_text(s)
            )))
        }
    };
    if uv.shape() != [n, nv] {
        return Err(value_error(format!(
            "u: expected shape ({n}, {nv}) (one row of {nv} speeds per row of q), got {}",
            shape_text(uv.shape())
        )));
    }
    let qs: Vec<f64> = qv.iter().copied().collect();
    let us: Vec<f64> = uv.iter().copied().collect();
    let model = match &m.kind {
        Kind::Spatial(s) => Some(s.model(contact)?),
        Kind::Planar(_) => None,
    };
    let pool = match threads {
        Some(t) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(t)
                .build()
                .map_err(value_error)?,
        ),
        None => None,
    };
    let rows: Vec<Out> = py.detach(|| {
        let work = || {
            (0..n)
                .into_par_iter()
                .map_init(
                    || None,
                    |ws, i| {
                        let (qi, ui) = (&qs[i * nq..(i + 1) * nq], &us[i * nv..(i + 1) * nv]);
                        match strike(m, model.as_deref(), ws, qi, ui, contact, |s| {
                            Ok((s.energy_before(), s.resolve(law, friction, restitution)?))
                        }) {
                            Ok((e0, resolved)) => Out::of(e0, resolved),
                            Err(e) => Out::invalid(e),
                        }
                    },
                )
                .collect()
        };
        match &pool {
            Some(p) => p.install(work),
            None => work(),
        }
    });
    if raise {
        if let Some((i, e)) = rows
            .iter()
            .enumerate()
            .find_map(|(i, r)| r.error.as_ref().map(|e| (i, e)))
        {
            return Err(value_error(format!("row {i}: {e}")));
        }
    }
    write(py, law, &rows, nv, dim)
}

/// The arrays of the result.
fn write<'py>(
    py: Python<'py>,
    law: LawId,
    rows: &[Out],
    nv: usize,
    dim: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let n = rows.len();
    let velocities = PyArray2::<f64>::zeros(py, [n, nv], false);
    let impulse = PyArray2::<f64>::zeros(py, [n, dim], false);
    let velocity = PyArray2::<f64>::zeros(py, [n, dim], false);
    let (e0, de) = (
        PyArray1::<f64>::zeros(py, [n], false),
        PyArray1::<f64>::zeros(py, [n], false),
    );
    let status = PyArray1::<u8>::zeros(py, [n], false);
    {
        // SAFETY: the arrays are new and referenced nowhere else.
        let (va, ia, ca) = unsafe {
            (
                velocities.as_slice_mut()?,
                impulse.as_slice_mut()?,
                velocity.as_slice_mut()?,
            )
        };
        let (ea, da, sa) = unsafe {
            (
                e0.as_slice_mut()?,
                de.as_slice_mut()?,
                status.as_slice_mut()?,
            )
        };
        for (i, r) in rows.iter().enumerate() {
            match &r.velocities_after {
                Some(v) => va[i * nv..(i + 1) * nv].copy_from_slice(v),
                None => va[i * nv..(i + 1) * nv].fill(f64::NAN),
            }
            ia[i * dim..(i + 1) * dim].copy_from_slice(&r.impulse[..dim]);
            ca[i * dim..(i + 1) * dim].copy_from_slice(&r.velocity_after[..dim]);
            ea[i] = r.energy_before;
            da[i] = r.energy_change;
            sa[i] = r.status;
        }
    }
    let d = PyDict::new(py);
    d.set_item("law", law.as_str())?;
    d.set_item("velocities_after", velocities)?;
    d.set_item("impulse", impulse)?;
    d.set_item("velocity_after", velocity)?;
    d.set_item("energy_before", e0)?;
    d.set_item("energy_change", de)?;
    d.set_item("status", status)?;
    Ok(d)
}
