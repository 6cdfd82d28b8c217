//! `impax.resolve_batch(..., contacts=K)`: one multi-contact law over many problems with `K`
//! contacts, given as numpy arrays (planar or spatial), in parallel with the GIL released.
//!
//! Each row is validated into a [`MultiProblem`] or a spatial one (the library's checks and
//! messages) and resolved exactly as `impax.resolve(w[i], v[i], friction[i], restitution[i],
//! law, contacts=K)`; a multi-contact law's work per row (a mode enumeration, an integration)
//! dwarfs the collection of its results, which are gathered per row and copied into the
//! arrays once.

use crate::batch::STATUSES;
use crate::convert::{float_array, threads as thread_count, value_error};
use impax::law::Verdict;
use impax::multi::spatial as multi3;
use impax::multi::MultiProblem;
use impax::LawId;
use nalgebra::DMatrix;
use numpy::{PyArray1, PyArray3, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

/// One row's result: `(impulses, velocities after)` flat (`K d` each), `ΔT`, status code.
type Row = Result<(Vec<f64>, Vec<f64>, f64, u8), String>;

/// The inputs, checked for shape.
struct Input {
    n: usize,
    k: usize,
    d: usize,
    /// Row-major `W` per row, `(dK)²` numbers.
    w: Vec<f64>,
    v: Vec<f64>,
    /// Per row `K` coefficients.
    friction: Vec<f64>,
    restitution: Vec<f64>,
    law: LawId,
}

fn shape_text(s: &[usize]) -> String {
    format!(
        "({})",
        s.iter()
            .map(|d| d.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// `W` as `(N, dK, dK)` or the upper triangles `(N, dK (dK + 1)/2)`; `d` from the size.
fn read_w(w: &Bound<'_, PyAny>, k: usize) -> PyResult<(usize, usize, Vec<f64>)> {
    let a = float_array(w, "w")?;
    let view = a.as_array();
    let data: Vec<f64> = view.iter().copied().collect();
    for d in [2, 3] {
        let m = d * k;
        match view.shape() {
            [n, r, c] if *r == m && *c == m => return Ok((*n, d, data)),
            [n, t] if *t == m * (m + 1) / 2 => {
                let mut full = vec![0.0; n * m * m];
                for row in 0..*n {
                    let mut it = data[row * t..(row + 1) * t].iter();
                    for i in 0..m {
                        for j in i..m {
                            let x = *it.next().expect("counted");
                            full[row * m * m + i * m + j] = x;
                            full[row * m * m + j * m + i] = x;
                        }
                    }
                }
                return Ok((*n, d, full));
            }
            _ => {}
        }
    }
    let (m2, m3) = (2 * k, 3 * k);
    Err(value_error(format!(
        "w: expected shape (N, {m2}, {m2}) or (N, {}) for {k} planar contacts, or (N, {m3}, {m3}) or (N, {}) in 3D, got {}",
        m2 * (m2 + 1) / 2,
        m3 * (m3 + 1) / 2,
        shape_text(view.shape())
    )))
}

/// A coefficient: a number, `(N,)` or `(N, K)`, as `K` numbers per row.
fn read_coef(x: &Bound<'_, PyAny>, name: &str, n: usize, k: usize) -> PyResult<Vec<f64>> {
    let a = float_array(x, name)?;
    let view = a.as_array();
    let data: Vec<f64> = view.iter().copied().collect();
    match view.shape() {
        [] => Ok(vec![data[0]; n * k]),
        [m] if *m == n => Ok(data
            .iter()
            .flat_map(|&x| std::iter::repeat_n(x, k))
            .collect()),
        [m, c] if *m == n && *c == k => Ok(data),
        s => Err(value_error(format!(
            "{name}: expected a number, shape ({n},) or ({n}, {k}), got {}",
            shape_text(s)
        ))),
    }
}

fn status(v: Verdict) -> u8 {
    match v {
        Verdict::Consistent => 0,
        Verdict::EnergyGained => 1,
        Verdict::InconsistentAssumption => 2,
    }
}

/// Resolve row `i`.
fn row(input: &Input, i: usize) -> Row {
    let (k, d) = (input.k, input.d);
    let m = d * k;
    let w = DMatrix::from_row_slice(m, m, &input.w[i * m * m..(i + 1) * m * m]);
    let v = &input.v[i * m..(i + 1) * m];
    let mu = &input.friction[i * k..(i + 1) * k];
    let e = &input.restitution[i * k..(i + 1) * k];
    let text = |e: impax::Error| e.to_string();
    if d == 2 {
        let p = MultiProblem::new(w, v, mu, e).map_err(text)?;
        match input.law.resolve(&p).map_err(text)? {
            Ok(o) => Ok((
                o.contacts
                    .iter()
                    .flat_map(|c| [c.impulse.x, c.impulse.y])
                    .collect(),
                o.contacts
                    .iter()
                    .flat_map(|c| [c.velocity_after.x, c.velocity_after.y])
                    .collect(),
                o.energy_change,
                status(o.verdict),
            )),
            Err(_) => Ok((vec![f64::NAN; m], vec![f64::NAN; m], f64::NAN, 3)),
        }
    } else {
        let p = multi3::MultiProblem::new(w, v, mu, e).map_err(text)?;
        match multi3::resolve(input.law, &p).map_err(text)? {
            Ok(o) => Ok((
                o.contacts
                    .iter()
                    .flat_map(|c| [c.impulse.x, c.impulse.y, c.impulse.z])
                    .collect(),
                o.contacts
                    .iter()
                    .flat_map(|c| [c.velocity_after.x, c.velocity_after.y, c.velocity_after.z])
                    .collect(),
                o.energy_change,
                status(o.verdict),
            )),
            Err(_) => Ok((vec![f64::NAN; m], vec![f64::NAN; m], f64::NAN, 3)),
        }
    }
}

/// `resolve_batch(..., contacts=K)` (the docs of `impax.resolve_batch`).
#[allow(clippy::too_many_arguments)] // the keyword arguments of one Python function
pub fn resolve<'py>(
    py: Python<'py>,
    w: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    restitution: &Bound<'py, PyAny>,
    law: &str,
    k: usize,
    raise: bool,
    threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    if k == 0 {
        return Err(value_error("contacts: must be at least 1"));
    }
    let threads = thread_count(threads)?;
    let (n, d, w) = read_w(w, k)?;
    let va = float_array(v, "v")?;
    let view = va.as_array();
    let m = d * k;
    if view.shape() != [n, m] && view.shape() != [n, k, d] {
        return Err(value_error(format!(
            "v: expected shape ({n}, {m}) or ({n}, {k}, {d}) for W of {k} contacts in {}, got {}",
            if d == 2 { "the plane" } else { "3D" },
            shape_text(view.shape())
        )));
    }
    let input = Input {
        n,
        k,
        d,
        w,
        v: view.iter().copied().collect(),
        friction: read_coef(friction, "friction", n, k)?,
        restitution: read_coef(restitution, "restitution", n, k)?,
        law: crate::convert::law(law)?,
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
    let rows: Vec<Row> = py.detach(|| {
        let all = || {
            (0..input.n)
                .into_par_iter()
                .map(|i| row(&input, i))
                .collect()
        };
        match &pool {
            Some(p) => p.install(all),
            None => all(),
        }
    });
    let mut impulse = Vec::with_capacity(n * m);
    let mut velocity = Vec::with_capacity(n * m);
    let mut energy = Vec::with_capacity(n);
    let mut codes = Vec::with_capacity(n);
    for (i, r) in rows.into_iter().enumerate() {
        match r {
            Ok((p, va, de, s)) => {
                impulse.extend(p);
                velocity.extend(va);
                energy.push(de);
                codes.push(s);
            }
            Err(e) if raise => return Err(value_error(format!("row {i}: {e}"))),
            Err(_) => {
                impulse.extend(std::iter::repeat_n(f64::NAN, m));
                velocity.extend(std::iter::repeat_n(f64::NAN, m));
                energy.push(f64::NAN);
                codes.push(4);
            }
        }
    }
    debug_assert!(codes.iter().all(|&c| (c as usize) < STATUSES.len()));
    let shaped = |data: Vec<f64>| -> PyResult<Bound<'py, PyArray3<f64>>> {
        PyArray1::from_vec(py, data).reshape([n, k, d])
    };
    let out = PyDict::new(py);
    out.set_item("law", input.law.as_str())?;
    out.set_item("impulse", shaped(impulse)?)?;
    out.set_item("velocity_after", shaped(velocity)?)?;
    out.set_item("energy_change", PyArray1::from_vec(py, energy))?;
    out.set_item("status", PyArray1::from_vec(py, codes))?;
    Ok(out)
}
