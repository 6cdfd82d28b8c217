//! Python inputs to library values, and library errors to `ValueError`.
//!
//! Messages are the library's `Display` (the text the CLI prints after `error: `), so that a
//! problem rejected by `impax resolve` is rejected here with the same words.

use impax::math::{Mat2, Mat3};
use impax::LawId;
use numpy::{
    AllowTypeChange, PyArray2, PyArrayDyn, PyArrayLikeDyn, PyArrayMethods, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyComplex, PyFloat, PyInt, PySequence, PyString};
use std::fmt::Display;

/// `ValueError(message)`.
pub fn value_error(message: impl Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// A library result as a Python result (`ValueError` with the library's message).
pub fn lib<T>(r: impax::Result<T>) -> PyResult<T> {
    r.map_err(value_error)
}

/// A 2×2 matrix (`W`) as a numpy array.
pub fn mat2<'py>(py: Python<'py>, w: Mat2) -> PyResult<Bound<'py, PyArray2<f64>>> {
    Ok(PyArray2::from_vec2(
        py,
        &[vec![w[(0, 0)], w[(0, 1)]], vec![w[(1, 0)], w[(1, 1)]]],
    )?)
}

/// A JSON record of the core's writers (`impax::json`) as the Python objects `json.loads`
/// gives for the command line's output: dicts, lists, strings, booleans, None, integers for
/// integers and floats for floats (the same `f64`, no text in between).
pub fn json_to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            _ => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| json_to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            pyo3::types::PyList::new(py, items)?.into_any()
        }
        Value::Object(m) => {
            let d = pyo3::types::PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, json_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
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

/// The most worker threads a batch accepts (`threads=`), as `impax sweep --threads`.
pub const MAX_THREADS: i64 = 256;

/// `threads=`: None (rayon's pool, one thread per core) or an integer from 1 to
/// [`MAX_THREADS`]; anything else is a `ValueError` (or a `TypeError` for a non-integer).
pub fn threads(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let range = format!("must be between 1 and {MAX_THREADS}");
    if obj.is_instance_of::<PyBool>() || obj.is_instance_of::<PyFloat>() {
        return Err(PyTypeError::new_err(format!(
            "threads: {range} (an integer) or None, got {}",
            obj.repr()?
        )));
    }
    match obj.extract::<i64>() {
        Ok(n) if (1..=MAX_THREADS).contains(&n) => Ok(Some(n as usize)),
        Ok(n) => Err(value_error(format!("threads: {range}, got {n}"))),
        Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => Err(value_error(format!(
            "threads: {range}, got {}",
            describe(obj)
        ))),
        Err(_) => Err(PyTypeError::new_err(format!(
            "threads: {range} (an integer) or None, got an object of type {}",
            obj.get_type().name()?
        ))),
    }
}

/// A short description of a number for a message: an integer by its digits (`an integer of
/// 401 digits`), anything else by its `repr`, shortened.
fn describe(obj: &Bound<'_, PyAny>) -> String {
    let py = obj.py();
    if obj.is_instance_of::<PyInt>() {
        let digits = py
            .import("math")
            .and_then(|m| m.getattr("log10"))
            .and_then(|log10| log10.call1((obj.abs()?,)))
            .and_then(|x| x.extract::<f64>());
        if let Ok(d) = digits {
            let sign = if obj.lt(0).unwrap_or(false) {
                "a negative"
            } else {
                "an"
            };
            return format!("{sign} integer of {} digits", d.floor() as u64 + 1);
        }
    }
    let text = obj
        .repr()
        .map(|r| r.to_string())
        .unwrap_or_else(|_| "?".into());
    if text.chars().count() > 40 {
        let head: String = text.chars().take(30).collect();
        format!("{head}…")
    } else {
        text
    }
}

/// Whether `obj` is a complex number or array (Python's `complex`, numpy's complex scalars
/// and arrays), which a conversion to `float` would silently cut to its real part.
fn is_complex(obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    if obj.is_instance_of::<PyComplex>() {
        return Ok(true);
    }
    Ok(dtype_kind(obj)? == Some('c'))
}

/// numpy's dtype kind of `obj` (`'f'`, `'i'`, `'c'`, `'O'`, …) if it has a dtype.
fn dtype_kind(obj: &Bound<'_, PyAny>) -> PyResult<Option<char>> {
    let Some(dtype) = obj.getattr_opt("dtype")? else {
        return Ok(None);
    };
    let Some(kind) = dtype.getattr_opt("kind")? else {
        return Ok(None);
    };
    Ok(kind.extract::<String>().ok().and_then(|k| k.chars().next()))
}

/// One real number read from Python for `field`: a float, an int, or anything with
/// `__float__` / `__index__` but a complex number. An int too large for a float is a
/// `ValueError` naming the field (not Python's `OverflowError`); a complex number or a
/// non-number a `TypeError` naming it.
pub fn real(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<f64> {
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Ok(f.value());
    }
    if is_complex(obj)? {
        return Err(PyTypeError::new_err(format!(
            "{field}: expected a real number, got a complex number {}",
            describe(obj)
        )));
    }
    match obj.extract::<f64>() {
        Ok(x) => Ok(x),
        Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => Err(value_error(format!(
            "{field}: {} is not representable as a float",
            describe(obj)
        ))),
        Err(e) if e.is_instance_of::<PyTypeError>(obj.py()) => Err(PyTypeError::new_err(format!(
            "{field}: expected a real number, got an object of type {}",
            obj.get_type().name()?
        ))),
        Err(e) => Err(e),
    }
}

/// The items of a sequence (a list, a tuple, an array), or None for anything else
/// (strings and bytes are not sequences of numbers).
fn items<'py>(obj: &Bound<'py, PyAny>) -> PyResult<Option<Vec<Bound<'py, PyAny>>>> {
    if obj.is_instance_of::<PyString>() || obj.is_instance_of::<PyBytes>() {
        return Ok(None);
    }
    if obj.cast::<PySequence>().is_err() {
        return Ok(None);
    }
    // A 0-d array is a sequence to Python's C API but has no items.
    if let Ok(a) = obj.cast::<PyUntypedArray>() {
        if a.ndim() == 0 {
            return Ok(None);
        }
    }
    Ok(Some(obj.try_iter()?.collect::<PyResult<Vec<_>>>()?))
}

/// Numbers read from a Python argument, every error naming the argument (see [`real`]).
pub trait Numbers: Sized {
    /// Read `obj` for the argument `field`.
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self>;
}

impl Numbers for f64 {
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        real(obj, field)
    }
}

impl Numbers for Vec<f64> {
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        let Some(items) = items(obj)? else {
            return Err(PyTypeError::new_err(format!(
                "{field}: expected a sequence of numbers, got an object of type {}",
                obj.get_type().name()?
            )));
        };
        items
            .iter()
            .enumerate()
            .map(|(i, x)| real(x, &format!("{field}[{i}]")))
            .collect()
    }
}

/// One number, or a sequence of them (per-contact coefficients: `friction=0.5` or
/// `friction=[0.5, 0.3]`).
#[derive(Debug, Clone, PartialEq)]
pub struct OneOrMany(pub Vec<f64>);

impl Numbers for OneOrMany {
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        if items(obj)?.is_some() {
            Vec::<f64>::read(obj, field).map(OneOrMany)
        } else {
            real(obj, field).map(|x| OneOrMany(vec![x]))
        }
    }
}

impl OneOrMany {
    /// The one value of a single-contact problem.
    pub fn single(&self, field: &str) -> PyResult<f64> {
        match self.0[..] {
            [x] => Ok(x),
            _ => Err(value_error(format!(
                "{field}: expected one number, got {} (one per contact needs contacts=K)",
                self.0.len()
            ))),
        }
    }
}

impl Numbers for (f64, f64) {
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        let v = Vec::<f64>::read(obj, field)?;
        match v[..] {
            [x, y] => Ok((x, y)),
            _ => Err(value_error(format!(
                "{field}: expected 2 numbers, got {}",
                v.len()
            ))),
        }
    }
}

impl<T: Numbers> Numbers for Option<T> {
    fn read(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        if obj.is_none() {
            Ok(None)
        } else {
            T::read(obj, field).map(Some)
        }
    }
}

/// Readers of numeric arguments by name, for `#[pyo3(from_py_with = arg::friction)]`: each
/// reads its argument with [`Numbers`], so that every error names the argument (pyo3's own
/// conversion raises `OverflowError` for `friction=10**400`, without the argument's name).
pub mod arg {
    use super::Numbers;
    use pyo3::prelude::*;

    macro_rules! readers {
        ($($name:ident),* $(,)?) => {
            $(
                #[doc = concat!("The argument `", stringify!($name), "`.")]
                pub fn $name<T: Numbers>(obj: &Bound<'_, PyAny>) -> PyResult<T> {
                    T::read(obj, stringify!($name))
                }
            )*
        };
    }

    readers!(
        a,
        alpha,
        angle,
        angles,
        b,
        contact,
        exponent,
        floor,
        friction,
        gravity,
        inertia,
        length,
        lengths,
        mass,
        masses,
        omega,
        position,
        radius,
        rates,
        restitution,
        semi_axes,
        speed,
        spin_ratio,
        stiffness,
        velocity,
    );
}

/// An array argument of `resolve_batch` as float64 (converted if needed): a complex array is
/// refused (numpy would keep only its real part), an int too large for a float is a
/// `ValueError`, both naming `field`.
pub fn float_array<'py>(
    obj: &Bound<'py, PyAny>,
    field: &str,
) -> PyResult<PyArrayLikeDyn<'py, f64, AllowTypeChange>> {
    let py = obj.py();
    let array = if obj.cast::<PyUntypedArray>().is_ok() {
        obj.clone()
    } else {
        let asarray = py.import("numpy")?.getattr("asarray")?;
        asarray.call1((obj,)).map_err(|e| {
            if e.is_instance_of::<PyOverflowError>(py) {
                value_error(format!(
                    "{field}: a number is not representable as a float ({})",
                    e.value(py)
                ))
            } else {
                value_error(format!("{field}: {}", e.value(py)))
            }
        })?
    };
    match dtype_kind(&array)? {
        Some('c') => {
            return Err(PyTypeError::new_err(format!(
                "{field}: expected real numbers, got complex numbers (dtype {})",
                array.getattr("dtype")?
            )))
        }
        Some('f' | 'i' | 'u' | 'b' | 'O') | None => {}
        Some(_) => {
            return Err(PyTypeError::new_err(format!(
                "{field}: expected real numbers, got an array of dtype {}",
                array.getattr("dtype")?
            )))
        }
    }
    array.extract().map_err(|e: PyErr| {
        if e.is_instance_of::<PyOverflowError>(py) {
            if obj.is_instance_of::<PyInt>() {
                value_error(format!(
                    "{field}: {} is not representable as a float",
                    describe(obj)
                ))
            } else {
                value_error(format!(
                    "{field}: a number is not representable as a float (an integer too large)"
                ))
            }
        } else if e.is_instance_of::<PyTypeError>(py) {
            PyTypeError::new_err(format!("{field}: expected real numbers ({})", e.value(py)))
        } else {
            value_error(format!("{field}: {}", e.value(py)))
        }
    })
}

/// Read `obj` as a small array of floats (numpy fast path, else sequences, element by
/// element: an element that is not a real number is named, e.g. `w[0]` or `w[1][0]`).
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
    if dtype_kind(obj)? == Some('c') && obj.cast::<PyUntypedArray>().is_ok() {
        return Err(PyTypeError::new_err(format!(
            "{field}: expected real numbers, got complex numbers (dtype {})",
            obj.getattr("dtype")?
        )));
    }
    let Some(rows) = items(obj)? else {
        return Err(value_error(format!(
            "{field}: expected {what}, got an object of type {}",
            obj.get_type().name()?
        )));
    };
    if rows.is_empty() || rows.len() > 9 {
        return Err(too_big(field, what));
    }
    let nested = rows
        .iter()
        .map(items)
        .collect::<PyResult<Vec<Option<Vec<Bound<'_, PyAny>>>>>>()?;
    if nested.iter().all(Option::is_some) {
        let nested: Vec<Vec<Bound<'_, PyAny>>> = nested.into_iter().flatten().collect();
        let cols = nested[0].len();
        if nested.iter().any(|r| r.len() != cols) || rows.len() * cols > 9 || cols == 0 {
            return Err(too_big(field, what));
        }
        out.ndim = 2;
        out.shape = [rows.len(), cols];
        for (i, row) in nested.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                out.data[i * cols + j] = real(x, &format!("{field}[{i}][{j}]"))?;
            }
        }
        return Ok(out);
    }
    if nested.iter().any(Option::is_some) {
        return Err(too_big(field, what));
    }
    out.shape = [rows.len(), 0];
    for (i, x) in rows.iter().enumerate() {
        out.data[i] = real(x, &format!("{field}[{i}]"))?;
    }
    Ok(out)
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
