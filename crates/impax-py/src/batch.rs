//! `impax.resolve_batch`: one law over many problems given as numpy arrays.
//!
//! Rows are cut into chunks of [`CHUNK`] rows, computed in parallel (rayon, with the GIL
//! released) and written straight into numpy arrays allocated once per call: each row is
//! validated into a [`ContactProblem`] (the library's checks and messages), resolved by the
//! law ([`LawId::resolve`], whose dispatch the branch predictor hides) and its outcome written
//! in place — no allocation and no intermediate record per row (the library's
//! `analysis::resolve_problems` would add a 88-byte record per row and a copy of every
//! problem). Every row is a pure function of its inputs, so the result does not depend on the
//! thread count or the chunking.

use crate::convert::{float_array, planar_law, spatial_law, threads as thread_count, value_error};
use impax::analysis::Sequence;
use impax::planar::{ContactProblem, Verdict};
use impax::spatial;
use impax::LawId;
use numpy::ndarray::ArrayViewD;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::borrow::Cow;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Rows per parallel task.
const CHUNK: usize = 4096;

/// The `status` codes of `resolve_batch`, by index.
pub const STATUSES: [&str; 5] = [
    "consistent",
    "energy-gained",
    "inconsistent-assumption",
    "breakdown",
    "invalid",
];

/// The `sequence` codes of a planar batch, by index (the library's `Sequence` ids).
pub const SEQUENCES: [&str; 6] = [
    "slip",
    "slip-stick",
    "slip-reverse",
    "stick",
    "no-slip",
    "none",
];

/// The `sequence` codes of a spatial batch, by index.
pub const SEQUENCES_3D: [&str; 8] = [
    "slip",
    "slip-stick",
    "slip-resumed",
    "stick",
    "no-slip",
    "none",
    "resumed",
    "other",
];

/// The status code of an invalid row.
pub(crate) const STATUS_INVALID: u8 = 4;
/// The status code of a breakdown.
pub(crate) const STATUS_BREAKDOWN: u8 = 3;

/// The status code of a verdict.
#[allow(unreachable_patterns)]
pub(crate) fn verdict_code(v: Verdict) -> u8 {
    match v {
        Verdict::Consistent => 0,
        Verdict::EnergyGained => 1,
        Verdict::InconsistentAssumption => 2,
        _ => 2,
    }
}

#[allow(unreachable_patterns)]
fn sequence_code(s: Sequence) -> u8 {
    match s {
        Sequence::Slip => 0,
        Sequence::SlipStick => 1,
        Sequence::SlipReverse => 2,
        Sequence::Stick => 3,
        Sequence::NoSlip => 4,
        Sequence::None => 5,
        _ => 5,
    }
}

#[allow(unreachable_patterns)]
fn sequence3_code(phases: &[impax::spatial::Phase]) -> u8 {
    use spatial::PhaseKind::*;
    match phases {
        [] => 5,
        [a] => match a.kind {
            Slip { .. } => 0,
            Stick => 3,
            NoSlip => 4,
            Resumed { .. } => 6,
            _ => 7,
        },
        [a, b, ..] => match (a.kind, b.kind) {
            (Slip { .. }, Stick) => 1,
            (Slip { .. }, Resumed { .. }) => 2,
            _ => 7,
        },
    }
}

/// A coefficient column: one number for every row, or one per row.
#[derive(Clone, Copy)]
enum Coef<'a> {
    Scalar(f64),
    Column(&'a [f64]),
}

impl Coef<'_> {
    #[inline(always)]
    fn at(&self, i: usize) -> f64 {
        match self {
            Coef::Scalar(x) => *x,
            Coef::Column(c) => c[i],
        }
    }
}

/// The output arrays of a batch (row-major), split into disjoint row ranges for the tasks.
struct Out<'a> {
    dim: usize,
    impulse: &'a mut [f64],
    velocity: &'a mut [f64],
    energy: &'a mut [f64],
    wc: &'a mut [f64],
    wr: &'a mut [f64],
    wf: &'a mut [f64],
    pc: &'a mut [f64],
    status: &'a mut [u8],
    sequence: &'a mut [u8],
    gained: &'a mut [bool],
}

impl<'a> Out<'a> {
    fn rows(&self) -> usize {
        self.energy.len()
    }

    fn split_at(self, row: usize) -> (Out<'a>, Out<'a>) {
        let d = self.dim;
        let (i0, i1) = self.impulse.split_at_mut(row * d);
        let (v0, v1) = self.velocity.split_at_mut(row * d);
        let (e0, e1) = self.energy.split_at_mut(row);
        let (c0, c1) = self.wc.split_at_mut(row);
        let (r0, r1) = self.wr.split_at_mut(row);
        let (f0, f1) = self.wf.split_at_mut(row);
        let (p0, p1) = self.pc.split_at_mut(row);
        let (s0, s1) = self.status.split_at_mut(row);
        let (q0, q1) = self.sequence.split_at_mut(row);
        let (g0, g1) = self.gained.split_at_mut(row);
        (
            Out {
                dim: d,
                impulse: i0,
                velocity: v0,
                energy: e0,
                wc: c0,
                wr: r0,
                wf: f0,
                pc: p0,
                status: s0,
                sequence: q0,
                gained: g0,
            },
            Out {
                dim: d,
                impulse: i1,
                velocity: v1,
                energy: e1,
                wc: c1,
                wr: r1,
                wf: f1,
                pc: p1,
                status: s1,
                sequence: q1,
                gained: g1,
            },
        )
    }

    /// Row `k`: every number NaN, the given status.
    #[inline]
    fn blank(&mut self, k: usize, status: u8) {
        let d = self.dim;
        self.impulse[k * d..(k + 1) * d].fill(f64::NAN);
        self.velocity[k * d..(k + 1) * d].fill(f64::NAN);
        self.energy[k] = f64::NAN;
        self.wc[k] = f64::NAN;
        self.wr[k] = f64::NAN;
        self.wf[k] = f64::NAN;
        self.pc[k] = f64::NAN;
        self.status[k] = status;
        self.sequence[k] = 5;
        self.gained[k] = false;
    }

    #[inline]
    fn planar(&mut self, k: usize, r: &impax::planar::Resolution) {
        match r {
            Ok(o) => {
                self.impulse[2 * k] = o.impulse.x;
                self.impulse[2 * k + 1] = o.impulse.y;
                self.velocity[2 * k] = o.velocity_after.x;
                self.velocity[2 * k + 1] = o.velocity_after.y;
                self.energy[k] = o.energy_change;
                self.wc[k] = o.work.compression;
                self.wr[k] = o.work.restitution;
                self.wf[k] = o.work.friction;
                self.pc[k] = o.compression_impulse.unwrap_or(f64::NAN);
                self.status[k] = verdict_code(o.verdict);
                self.sequence[k] = sequence_code(Sequence::of(&o.phases));
                self.gained[k] = o.verdict == Verdict::EnergyGained;
            }
            Err(_) => self.blank(k, STATUS_BREAKDOWN),
        }
    }

    #[inline]
    fn spatial(&mut self, k: usize, r: &impax::spatial::Resolution) {
        match r {
            Ok(o) => {
                for j in 0..3 {
                    self.impulse[3 * k + j] = o.impulse[j];
                    self.velocity[3 * k + j] = o.velocity_after[j];
                }
                self.energy[k] = o.energy_change;
                self.wc[k] = o.work.compression;
                self.wr[k] = o.work.restitution;
                self.wf[k] = o.work.friction;
                self.pc[k] = o.compression_impulse.unwrap_or(f64::NAN);
                self.status[k] = verdict_code(o.verdict);
                self.sequence[k] = sequence3_code(o.phases.as_slice());
                self.gained[k] = o.verdict == Verdict::EnergyGained;
            }
            Err(_) => self.blank(k, STATUS_BREAKDOWN),
        }
    }
}

/// The inputs of a batch, as row-major slices.
struct Input<'a> {
    w: &'a [f64],
    v: &'a [f64],
    friction: Coef<'a>,
    restitution: Coef<'a>,
    law: LawId,
    spatial: bool,
    raise: bool,
}

/// The first invalid row (its index and the library's error), if any.
type RowError = Option<(usize, impax::Error)>;

/// Rows `start..start + out.rows()`, split in halves down to [`CHUNK`] rows, in parallel.
fn run(input: &Input<'_>, out: Out<'_>, start: usize, first_error: &AtomicUsize) -> RowError {
    let n = out.rows();
    if n > CHUNK {
        let half = n.div_ceil(2 * CHUNK) * CHUNK;
        let (a, b) = out.split_at(half);
        let (ea, eb) = rayon::join(
            || run(input, a, start, first_error),
            || run(input, b, start + half, first_error),
        );
        return match (ea, eb) {
            (Some(a), _) => Some(a),
            (None, b) => b,
        };
    }
    // An earlier row already failed: this chunk's result will not be used.
    if input.raise && first_error.load(Ordering::Relaxed) < start {
        return None;
    }
    let r = if input.spatial {
        chunk_spatial(input, out, start)
    } else {
        chunk_planar(input, out, start)
    };
    if let Some((row, _)) = &r {
        first_error.fetch_min(*row, Ordering::Relaxed);
    }
    r
}

fn chunk_planar(input: &Input<'_>, mut out: Out<'_>, start: usize) -> RowError {
    for k in 0..out.rows() {
        let i = start + k;
        let (w, v) = (&input.w[3 * i..3 * i + 3], &input.v[2 * i..2 * i + 2]);
        match ContactProblem::from_entries(
            w[0],
            w[1],
            w[2],
            v[0],
            v[1],
            input.friction.at(i),
            input.restitution.at(i),
        ) {
            Ok(p) => out.planar(k, &input.law.resolve(&p)),
            Err(e) if input.raise => return Some((i, e)),
            Err(_) => out.blank(k, STATUS_INVALID),
        }
    }
    None
}

fn chunk_spatial(input: &Input<'_>, mut out: Out<'_>, start: usize) -> RowError {
    for k in 0..out.rows() {
        let i = start + k;
        let (w, v) = (&input.w[6 * i..6 * i + 6], &input.v[3 * i..3 * i + 3]);
        match spatial::ContactProblem::from_upper(
            [w[0], w[1], w[2], w[3], w[4], w[5]],
            [v[0], v[1], v[2]],
            input.friction.at(i),
            input.restitution.at(i),
        ) {
            Ok(p) => out.spatial(k, &input.law.resolve(&p)),
            Err(e) if input.raise => return Some((i, e)),
            Err(_) => out.blank(k, STATUS_INVALID),
        }
    }
    None
}

fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A contiguous row-major view of an array (a copy only if it is not contiguous).
fn contiguous<'a>(a: &'a ArrayViewD<'_, f64>) -> Cow<'a, [f64]> {
    match a.as_slice() {
        Some(s) => Cow::Borrowed(s),
        None => Cow::Owned(a.iter().copied().collect()),
    }
}

fn coef<'a>(view: &ArrayViewD<'_, f64>, s: &'a [f64]) -> Coef<'a> {
    if view.shape().is_empty() {
        Coef::Scalar(s[0])
    } else {
        Coef::Column(s)
    }
}

/// `threads=` checked as `resolve_batch` checks it (None, or an integer from 1 to 256): the
/// value, or `ValueError` / `TypeError`. For `impax.study` and `impax.dask`, which check it
/// before sending any chunk to a worker.
#[pyfunction]
#[pyo3(name = "_check_threads", signature = (threads = None))]
pub fn check_threads(threads: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    thread_count(threads)
}

/// `on_invalid=`: whether an invalid row raises (`"raise"`) or is marked (`"mark"`).
fn raises(on_invalid: &str) -> PyResult<bool> {
    match on_invalid {
        "raise" => Ok(true),
        "mark" => Ok(false),
        other => Err(value_error(format!(
            "on_invalid: expected \"raise\" or \"mark\", got {other:?}"
        ))),
    }
}

/// Resolve many impacts with one law, in parallel, on numpy arrays.
///
/// Planar: `w` of shape (N, 3) holds `W_tt, W_tn, W_nn`, `v` of shape (N, 2) holds
/// `v_t, v_n`. Spatial: `w` (N, 6) holds `W11, W12, W13, W22, W23, W33`, `v` (N, 3) holds
/// `v_t1, v_t2, v_n`. `friction` and `restitution` are numbers or arrays of shape (N,).
/// Row `i` is resolved exactly as `resolve(w[i], v[i], friction[i], restitution[i], law)`.
///
/// Returns a dict of arrays: `impulse` and `velocity_after` (N, 2|3), `energy_change`,
/// `work_compression`, `work_restitution`, `work_friction`, `compression_impulse` (N,),
/// `status` (uint8 codes into `impax.STATUSES`), `sequence` (uint8 codes into
/// `impax.SEQUENCES` or `impax.SEQUENCES_3D`), `energy_gained` (bool). Numbers are NaN where
/// the law broke down (`status == "breakdown"`) and only there (or on invalid rows).
///
/// With `contacts=K`: problems with `K` contacts at once and a multi-contact law (`lcp`,
/// `sequential`, `lzb`; with `K = 1` any contact-space law): `w` of shape (N, dK, dK) or the
/// upper triangles (N, dK (dK + 1)/2) with `d = 2` (planar) or 3 (spatial), `v` (N, dK) or
/// (N, K, d), `friction` and `restitution` numbers, (N,) or (N, K); returns `impulse` and
/// `velocity_after` (N, K, d), `energy_change` (N,) and `status` (N,), each row exactly
/// `resolve(w[i], v[i], friction[i], restitution[i], law, contacts=K)`.
///
/// An invalid row raises `ValueError("row I: <the CLI's message>")` naming the first one
/// (`on_invalid="raise"`, the default); with `on_invalid="mark"` it gets status `invalid`.
/// Complex arrays are refused (`TypeError`), as are integers too large for a float
/// (`ValueError`). The GIL is released while the rows are computed; `threads` is the number
/// of worker threads, an integer from 1 to 256 (`impax.MAX_THREADS`; default: rayon's pool,
/// one per core); any other value raises `ValueError`.
#[pyfunction]
#[pyo3(signature = (w, v, friction, restitution, law = "energetic", *, on_invalid = "raise", threads = None, contacts = None))]
#[allow(clippy::too_many_arguments)]
pub fn resolve_batch<'py>(
    py: Python<'py>,
    w: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    restitution: &Bound<'py, PyAny>,
    law: &str,
    on_invalid: &str,
    threads: Option<&Bound<'py, PyAny>>,
    contacts: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let raise = raises(on_invalid)?;
    if let Some(k) = contacts {
        return crate::batch_multi::resolve(
            py,
            w,
            v,
            friction,
            restitution,
            law,
            k,
            raise,
            threads,
        );
    }
    let threads = thread_count(threads)?;
    let w = float_array(w, "w")?;
    let v = float_array(v, "v")?;
    let friction = float_array(friction, "friction")?;
    let restitution = float_array(restitution, "restitution")?;
    let w_view = w.as_array();
    let v_view = v.as_array();
    let (n, spatial) = match w_view.shape() {
        [n, 3] => (*n, false),
        [n, 6] => (*n, true),
        s => {
            return Err(value_error(format!(
                "w: expected shape (N, 3) (planar: W_tt, W_tn, W_nn) or (N, 6) (spatial: W11, W12, W13, W22, W23, W33), got {}",
                shape_text(s)
            )))
        }
    };
    let dim = if spatial { 3 } else { 2 };
    if v_view.shape() != [n, dim] {
        return Err(value_error(format!(
            "v: expected shape ({n}, {dim}) ({}) for W of shape {}, got {}",
            if spatial {
                "v_t1, v_t2, v_n"
            } else {
                "v_t, v_n"
            },
            shape_text(w_view.shape()),
            shape_text(v_view.shape())
        )));
    }
    let law = if spatial {
        spatial_law(law)?
    } else {
        planar_law(law)?
    };
    let f_view = friction.as_array();
    let e_view = restitution.as_array();
    let coef_ok = |s: &[usize]| s.is_empty() || s == [n];
    for (name, view) in [("friction", &f_view), ("restitution", &e_view)] {
        if !coef_ok(view.shape()) {
            return Err(value_error(format!(
                "{name}: expected a number or shape ({n},), got {}",
                shape_text(view.shape())
            )));
        }
    }
    let (w_s, v_s) = (contiguous(&w_view), contiguous(&v_view));
    let (f_s, e_s) = (contiguous(&f_view), contiguous(&e_view));
    let input = Input {
        w: &w_s,
        v: &v_s,
        friction: coef(&f_view, &f_s),
        restitution: coef(&e_view, &e_s),
        law,
        spatial,
        raise,
    };

    // Outputs, allocated once; every element is written before they are returned.
    // SAFETY: the arrays are new (no other reference) and fully initialised by `run` (every
    // row is written by exactly one task: resolved, marked invalid or breakdown); when `run`
    // reports an invalid row the arrays are dropped unread.
    let impulse = unsafe { PyArray2::<f64>::new(py, [n, dim], false) };
    let velocity = unsafe { PyArray2::<f64>::new(py, [n, dim], false) };
    let col = || unsafe { PyArray1::<f64>::new(py, [n], false) };
    let (energy, wc, wr, wf, pc) = (col(), col(), col(), col(), col());
    let status = unsafe { PyArray1::<u8>::new(py, [n], false) };
    let sequence = unsafe { PyArray1::<u8>::new(py, [n], false) };
    let gained = unsafe { PyArray1::<bool>::new(py, [n], false) };
    let error = {
        // SAFETY: the slices borrow arrays created above, which nothing else references.
        let out = unsafe {
            Out {
                dim,
                impulse: impulse.as_slice_mut()?,
                velocity: velocity.as_slice_mut()?,
                energy: energy.as_slice_mut()?,
                wc: wc.as_slice_mut()?,
                wr: wr.as_slice_mut()?,
                wf: wf.as_slice_mut()?,
                pc: pc.as_slice_mut()?,
                status: status.as_slice_mut()?,
                sequence: sequence.as_slice_mut()?,
                gained: gained.as_slice_mut()?,
            }
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
        py.detach(|| {
            let first = AtomicUsize::new(usize::MAX);
            match &pool {
                Some(p) => p.install(|| run(&input, out, 0, &first)),
                None => run(&input, out, 0, &first),
            }
        })
    };
    if let Some((row, e)) = error {
        return Err(value_error(format!("row {row}: {e}")));
    }
    let d = PyDict::new(py);
    d.set_item("law", law.as_str())?;
    d.set_item("impulse", impulse)?;
    d.set_item("velocity_after", velocity)?;
    d.set_item("energy_change", energy)?;
    d.set_item("work_compression", wc)?;
    d.set_item("work_restitution", wr)?;
    d.set_item("work_friction", wf)?;
    d.set_item("compression_impulse", pc)?;
    d.set_item("status", status)?;
    d.set_item("sequence", sequence)?;
    d.set_item("energy_gained", gained)?;
    Ok(d)
}
