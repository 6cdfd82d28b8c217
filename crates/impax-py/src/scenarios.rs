//! Contact-space problems of built-in bodies for many parameter values at once: the rows
//! `impax.study` feeds to `resolve_batch`, computed by the library's bodies (the same code as
//! `impax.rod(...)` and `impax.sphere(...)`, so the rows equal theirs bit for bit), in
//! parallel with the GIL released.

use crate::convert::{float_array, value_error};
use impax::planar::bodies::{self, BodyState, RigidBody, Side};
use numpy::ndarray::ArrayViewD;
use numpy::{PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use rayon::prelude::*;
use std::borrow::Cow;

/// Rows per parallel task.
const CHUNK: usize = 8192;

/// A parameter: one value for every row, or one per row.
#[derive(Clone, Copy)]
enum Param<'a> {
    Scalar(f64),
    Column(&'a [f64]),
}

impl Param<'_> {
    #[inline(always)]
    fn at(&self, i: usize) -> f64 {
        match self {
            Param::Scalar(x) => *x,
            Param::Column(c) => c[i],
        }
    }
}

/// The common length of the parameters (1-D arrays of one length, or numbers).
fn rows(names: &[&str], views: &[ArrayViewD<'_, f64>]) -> PyResult<usize> {
    let mut n: Option<usize> = None;
    for (name, v) in names.iter().zip(views) {
        match v.shape() {
            [] => {}
            [m] => match n {
                None => n = Some(*m),
                Some(k) if k == *m => {}
                Some(k) => {
                    return Err(value_error(format!(
                        "{name}: expected a number or shape ({k},), got ({m},)"
                    )))
                }
            },
            s => {
                return Err(value_error(format!(
                    "{name}: expected a number or a 1-D array, got {} dimensions",
                    s.len()
                )))
            }
        }
    }
    Ok(n.unwrap_or(1))
}

fn contiguous<'a>(a: &'a ArrayViewD<'_, f64>) -> Cow<'a, [f64]> {
    match a.as_slice() {
        Some(s) => Cow::Borrowed(s),
        None => Cow::Owned(a.iter().copied().collect()),
    }
}

fn param<'a>(view: &ArrayViewD<'_, f64>, s: &'a [f64]) -> Param<'a> {
    if view.shape().is_empty() {
        Param::Scalar(s[0])
    } else {
        Param::Column(s)
    }
}

type Row = impax::Result<(RigidBody, BodyState)>;

/// `(W, v)`: arrays of shape (N, 3) and (N, 2).
type Rows<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>);

/// Fill `w` (N×3: W_tt, W_tn, W_nn) and `v` (N×2) from `body(i)`, in parallel; the first
/// invalid row (index, error) if any.
fn fill(
    n: usize,
    w: &mut [f64],
    v: &mut [f64],
    body: &(impl Fn(usize) -> Row + Sync),
) -> Option<(usize, impax::Error)> {
    w.par_chunks_mut(3 * CHUNK)
        .zip(v.par_chunks_mut(2 * CHUNK))
        .enumerate()
        .map(|(c, (wc, vc))| {
            let start = c * CHUNK;
            for k in 0..(n - start).min(CHUNK) {
                match body(start + k) {
                    Ok((b, s)) => {
                        let m = b.inverse_inertia();
                        let u = b.contact_velocity(&s);
                        wc[3 * k..3 * k + 3].copy_from_slice(&[m[(0, 0)], m[(0, 1)], m[(1, 1)]]);
                        vc[2 * k..2 * k + 2].copy_from_slice(&[u.x, u.y]);
                    }
                    Err(e) => return Some((start + k, e)),
                }
            }
            None
        })
        .find_first(Option::is_some)
        .flatten()
}

fn problems<'py>(
    py: Python<'py>,
    n: usize,
    body: impl Fn(usize) -> Row + Sync + Send,
) -> PyResult<Rows<'py>> {
    let w = PyArray2::<f64>::zeros(py, [n, 3], false);
    let v = PyArray2::<f64>::zeros(py, [n, 2], false);
    // SAFETY: the arrays are new; nothing else references them.
    let (ws, vs) = unsafe { (w.as_slice_mut()?, v.as_slice_mut()?) };
    if let Some((row, e)) = py.detach(|| fill(n, ws, vs, &body)) {
        return Err(value_error(format!("row {row}: {e}")));
    }
    Ok((w, v))
}

/// Contact-space rows `(W, v)` of uniform rods striking a fixed surface with their lower end:
/// `bodies::rod(mass, length, angle)` (`I = m L²/12`, contact `r = −(L/2)(cos θ, sin θ)`),
/// centre velocity `speed (sin d, −cos d)` (`d` = `direction` from the downward normal), spin
/// `omega`. `W = [[1/m + r_n²/I, −r_t r_n/I], [·, 1/m + r_t²/I]]`, `v = (v_x − ω r_n, v_y + ω r_t)`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn rod_rows<'py>(
    py: Python<'py>,
    angle: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    direction: &Bound<'py, PyAny>,
    omega: &Bound<'py, PyAny>,
    mass: &Bound<'py, PyAny>,
    length: &Bound<'py, PyAny>,
) -> PyResult<Rows<'py>> {
    let angle = float_array(angle, "angle")?;
    let speed = float_array(speed, "speed")?;
    let direction = float_array(direction, "direction")?;
    let omega = float_array(omega, "omega")?;
    let mass = float_array(mass, "mass")?;
    let length = float_array(length, "length")?;
    let views = [
        angle.as_array(),
        speed.as_array(),
        direction.as_array(),
        omega.as_array(),
        mass.as_array(),
        length.as_array(),
    ];
    let n = rows(
        &["angle", "speed", "direction", "omega", "mass", "length"],
        &views,
    )?;
    let s: Vec<Cow<'_, [f64]>> = views.iter().map(contiguous).collect();
    let p: Vec<Param<'_>> = views.iter().zip(&s).map(|(v, s)| param(v, s)).collect();
    let [a, sp, d, om, m, l] = [p[0], p[1], p[2], p[3], p[4], p[5]];
    problems(py, n, move |i| {
        let body = bodies::rod(m.at(i), l.at(i), a.at(i), Side::Below)?;
        let (sd, cd) = d.at(i).sin_cos();
        let speed = sp.at(i);
        Ok((body, BodyState::new(speed * sd, -speed * cd, om.at(i))))
    })
}

/// Contact-space rows `(W, v)` of paper A's sphere: `bodies::sphere(mass, radius)` and
/// `bodies::spin_state(speed, alpha, spin_ratio, radius)` (eq. 1: `v = v0 (sin α, −cos α)`,
/// `ω = γ v0 / r`), so `W = (1/m) diag(7/2, 1)` and `v = (v0 (sin α + γ), −v0 cos α)` (eq. 6).
#[pyfunction]
pub fn sphere_rows<'py>(
    py: Python<'py>,
    alpha: &Bound<'py, PyAny>,
    spin_ratio: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    mass: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
) -> PyResult<Rows<'py>> {
    let alpha = float_array(alpha, "alpha")?;
    let spin_ratio = float_array(spin_ratio, "spin_ratio")?;
    let speed = float_array(speed, "speed")?;
    let mass = float_array(mass, "mass")?;
    let radius = float_array(radius, "radius")?;
    let views = [
        alpha.as_array(),
        spin_ratio.as_array(),
        speed.as_array(),
        mass.as_array(),
        radius.as_array(),
    ];
    let n = rows(&["alpha", "spin_ratio", "speed", "mass", "radius"], &views)?;
    let s: Vec<Cow<'_, [f64]>> = views.iter().map(contiguous).collect();
    let p: Vec<Param<'_>> = views.iter().zip(&s).map(|(v, s)| param(v, s)).collect();
    let [a, g, sp, m, r] = [p[0], p[1], p[2], p[3], p[4]];
    problems(py, n, move |i| {
        let body = bodies::sphere(m.at(i), r.at(i), Side::Below)?;
        let state = bodies::spin_state(sp.at(i), a.at(i), g.at(i), r.at(i))?;
        Ok((body, state))
    })
}
