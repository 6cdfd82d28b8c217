//! Python inputs to library values, and library errors to `ValueError`.
//!
//! Messages are the library's `Display` (the text the CLI prints after `error: `), so that a
//! problem rejected by `impax resolve` is rejected here with the same words.

use impax::math::{Mat2, Mat3};
use impax::LawId;
use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::fmt::Display;

/// `ValueError(message)`.
pub fn value_error(message: impl Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// A library result as a Python result (`ValueError` with the library's message).
pub fn lib<T>(r: impax::Result<T>) -> PyResult<T> {
    r.map_err(value_error)
}

/// A law id, parsed as the CLI parses it (`law: unknown impact law ...`).
pub fn law(id: &str) -> PyResult<LawId> {
    lib(id.parse::<LawId>())
}

/// A law usable in contact space (every law but `smith-centre`, which reads a body).
pub fn planar_law(id: &str) -> PyResult<LawId> {
    let l = law(id)?;
    if l.needs_body() {
        return Err(value_error(format!(
            "law: `{l}` needs a body (it reads the centre velocity); use a body, e.g. `impax.compare(impax.sphere(...))`"
        )));
    }
    Ok(l)
}

/// A law defined for spatial problems (the CLI's message otherwise).
pub fn spatial_law(id: &str) -> PyResult<LawId> {
    let l = law(id)?;
    if !LawId::SPATIAL.contains(&l) {
        let known: Vec<&str> = LawId::SPATIAL.iter().map(|l| l.as_str()).collect();
        return Err(value_error(format!(
            "law: `{l}` is defined for planar impacts only (spatial laws: {})",
            known.join(", ")
        )));
    }
    Ok(l)
}

/// A small array (at most 9 numbers) read from a numpy array or a (nested) sequence.
#[derive(Debug, Clone, Copy)]
pub struct Small {
    /// Its shape: `[n]` (one dimension) or `[rows, cols]`.
    pub shape: [usize; 2],
    /// Number of dimensions, 1 or 2.
    pub ndim: usize,
    /// The numbers, row-major.
    pub data: [f64; 9],
}

impl Small {
    /// The number of entries.
    pub fn len(&self) -> usize {
        if self.ndim == 1 {
            self.shape[0]
        } else {
            self.shape[0] * self.shape[1]
        }
    }

    /// The shape as Python prints it: `(3,)` or `(2, 2)`.
    pub fn shape_text(&self) -> String {
        if self.ndim == 1 {
            format!("({},)", self.shape[0])
        } else {
            format!("({}, {})", self.shape[0], self.shape[1])
        }
    }
}

fn too_big(field: &str, what: &str) -> PyErr {
    value_error(format!("{field}: expected {what}"))
}

/// Read `obj` as a small array of floats (numpy fast path, else sequences).
pub fn small(obj: &Bound<'_, PyAny>, field: &str, what: &str) -> PyResult<Small> {
    let mut out = Small {
        shape: [0, 0],
        ndim: 1,
        data: [0.0; 9],
    };
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        let ro = a.readonly();
        let view = ro.as_array();
        let shape = view.shape();
        if shape.len() > 2 || view.len() > 9 {
            return Err(too_big(field, what));
        }
        out.ndim = shape.len().max(1);
        if shape.is_empty() {
            return Err(too_big(field, what));
        }
        out.shape[0] = shape[0];
        if shape.len() == 2 {
            out.shape[1] = shape[1];
        }
        for (k, x) in view.iter().enumerate() {
            out.data[k] = *x;
        }
        return Ok(out);
    }
    if let Ok(rows) = obj.extract::<Vec<Vec<f64>>>() {
        let cols = rows.first().map_or(0, Vec::len);
        if rows.iter().any(|r| r.len() != cols) || rows.len() * cols > 9 || cols == 0 {
            return Err(too_big(field, what));
        }
        out.ndim = 2;
        out.shape = [rows.len(), cols];
        for (k, x) in rows.iter().flatten().enumerate() {
            out.data[k] = *x;
        }
        return Ok(out);
    }
    if let Ok(v) = obj.extract::<Vec<f64>>() {
        if v.len() > 9 || v.is_empty() {
            return Err(too_big(field, what));
        }
        out.shape = [v.len(), 0];
        out.data[..v.len()].copy_from_slice(&v);
        return Ok(out);
    }
    Err(value_error(format!(
        "{field}: expected {what}, got an object of type {}",
        obj.get_type().name()?
    )))
}

/// The contact-space matrix of one problem, planar or spatial.
pub enum Matrix {
    /// 2×2.
    Planar(Mat2),
    /// 3×3.
    Spatial(Mat3),
}

const W_WHAT: &str =
    "a 2×2 or 3×3 matrix, or its upper triangle (3 numbers W_tt, W_tn, W_nn or 6 numbers W11, W12, W13, W22, W23, W33)";

/// `W` as a 2×2 / 3×3 matrix or its upper triangle (3 or 6 numbers, as `impax resolve --w`).
pub fn matrix(obj: &Bound<'_, PyAny>) -> PyResult<Matrix> {
    let s = small(obj, "w", W_WHAT)?;
    let d = &s.data;
    match (s.ndim, s.shape) {
        (2, [2, 2]) => Ok(Matrix::Planar(Mat2::new(d[0], d[1], d[2], d[3]))),
        (2, [3, 3]) => Ok(Matrix::Spatial(Mat3::new(
            d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8],
        ))),
        (1, [3, _]) => Ok(Matrix::Planar(Mat2::new(d[0], d[1], d[1], d[2]))),
        (1, [6, _]) => Ok(Matrix::Spatial(Mat3::new(
            d[0], d[1], d[2], d[1], d[3], d[4], d[2], d[4], d[5],
        ))),
        _ => Err(value_error(format!(
            "w: expected {W_WHAT}, got shape {}",
            s.shape_text()
        ))),
    }
}

/// The pre-impact contact velocity: `n` numbers.
pub fn vector(obj: &Bound<'_, PyAny>, n: usize, what: &str) -> PyResult<[f64; 3]> {
    let s = small(obj, "v", what)?;
    if s.ndim != 1 || s.len() != n {
        return Err(value_error(format!(
            "v: expected {what}, got shape {}",
            s.shape_text()
        )));
    }
    Ok([s.data[0], s.data[1], s.data[2]])
}

/// A fixed-length list of floats (body and mechanism parameters): the CLI's
/// `FIELD: needs N value(s), got M`.
pub fn list(field: &str, values: &[f64], n: usize) -> PyResult<()> {
    if values.len() != n {
        return Err(value_error(format!(
            "{field}: needs {n} value(s), got {}",
            values.len()
        )));
    }
    for (i, x) in values.iter().enumerate() {
        if !x.is_finite() {
            return Err(value_error(format!(
                "{field}[{i}]: must be a finite number, got {x}"
            )));
        }
    }
    Ok(())
}
