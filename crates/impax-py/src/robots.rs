//! Mechanisms of one's own: `impax.mechanism(path_or_text, ...)` for a mechanism file (planar
//! or `space = "3d"`) or a URDF robot — a [`Mechanism`] read once and evaluated at any state:
//! names of its coordinates, speeds and contacts, `M(q)`, a contact's Jacobian, its
//! contact-space problem, and its impacts (one state, every law: the command line's
//! `impax compare --json` document, [`crate::robot_impact::record`]; many states, one law:
//! numpy arrays, [`crate::robot_batch`]). Reading it: [`crate::robot_load`].
//!
//! The descriptions, their checks and every number are the core's: a planar file is built by
//! `impax::scenario::MechanismSpec` into a linkage (`impax::mechanism::linkage`), struck by
//! `MechanismImpact::named`; a spatial one or a URDF robot is read once by
//! `impax::scenario::RobotSpec::load` into an `impax::scenario::Robot`, whose model struck at
//! a contact (`Robot::struck_by`) is kept per contact, and reduced by
//! `SpatialMechanismImpact`.

use crate::convert::{arg, float_array, json_to_py, lib, value_error};
use crate::robot_impact::{self, Struck};
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::impact::MechanismImpact as LibMechanismImpact;
use impax::mechanism::{dynamics, Mechanism as _};
use impax::multibody::{self, Model, Workspace};
use impax::scenario::{MechanismFile, Robot};
use impax::LawId;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use std::sync::{Arc, Mutex};

/// A contact-space problem as two arrays: `W` and `v⁻`.
type ProblemArrays<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<f64>>);

/// How many models struck at a named contact a URDF robot keeps (the oldest is dropped).
const MODELS_KEPT: usize = 32;

/// A planar mechanism file, built.
pub struct Planar {
    /// The linkage (its floors where the file or `floor=` puts them).
    pub mechanism: BuiltIn,
    /// The file (its floors as `floor=` puts them), for `impact`'s record.
    pub file: MechanismFile,
    /// `mechanism(..., gravity=...)`.
    pub gravity: Option<f64>,
    /// Whether the floor is given (else it passes through the lowest contact at each state).
    pub floor_given: bool,
    /// The file's state.
    pub q: Vec<f64>,
    pub u: Vec<f64>,
}

/// A spatial mechanism file or a URDF robot, read.
pub struct Spatial {
    pub robot: Robot,
    /// A file's model with its contacts (none when it has none).
    pub file_model: Option<Arc<Model>>,
    /// A URDF robot's models struck at the contacts named so far.
    pub models: Mutex<Vec<(String, Arc<Model>)>>,
}

/// What a mechanism is.
pub enum Kind {
    Planar(Planar),
    Spatial(Spatial),
}

/// The defaults of the impacts: the file's (or `mechanism(...)`'s) coefficients and laws.
pub struct Defaults {
    /// The contact of `mechanism(..., contact=...)`, for calls that name none.
    pub contact: Option<String>,
    pub friction: f64,
    pub restitution: f64,
    pub laws: Vec<LawId>,
}

/// A mechanism of one's own (a mechanism file or a URDF robot), read once.
#[pyclass(frozen, name = "Mechanism", module = "impax._impax")]
pub struct Mechanism {
    pub name: String,
    pub kind: Kind,
    pub defaults: Defaults,
    pub description: String,
}

impl Spatial {
    /// The model struck at `contact` ([`Robot::struck_by`]): a file's own, a URDF robot's
    /// with that one contact (kept for the next call).
    pub fn model(&self, contact: Option<&str>) -> PyResult<Arc<Model>> {
        if !self.robot.is_urdf() {
            return match &self.file_model {
                Some(m) => Ok(m.clone()),
                None => Err(value_error(format!(
                    "contact: `{}` has no contact point to strike",
                    self.robot.name()
                ))),
            };
        }
        let key = contact.unwrap_or_default();
        if let Some((_, m)) = self.lock().iter().find(|(k, _)| k == key) {
            return Ok(m.clone());
        }
        let model = Arc::new(lib(self.robot.struck_by(contact))?);
        let mut models = self.lock();
        if models.len() >= MODELS_KEPT {
            models.remove(0);
        }
        models.push((key.to_string(), model.clone()));
        Ok(model)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Vec<(String, Arc<Model>)>> {
        self.models.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// `q` or `u`: a sequence or a 1-D array of real numbers.
fn state(obj: &Bound<'_, PyAny>, field: &str) -> PyResult<Vec<f64>> {
    let a = float_array(obj, field)?;
    let view = a.as_array();
    if view.ndim() != 1 {
        return Err(value_error(format!(
            "{field}: expected a sequence of numbers (one dimension), got an array of shape {:?}",
            view.shape()
        )));
    }
    Ok(view.iter().copied().collect())
}

fn q_arg(obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    state(obj, "q")
}

fn u_arg(obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    state(obj, "u")
}

/// A numpy vector.
fn vector<'py>(py: Python<'py>, v: &[f64]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, v)
}

/// A numpy matrix from a column-major nalgebra matrix.
pub fn matrix<'py>(
    py: Python<'py>,
    rows: usize,
    cols: usize,
    at: impl Fn(usize, usize) -> f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let data: Vec<Vec<f64>> = (0..rows)
        .map(|i| (0..cols).map(|j| at(i, j)).collect())
        .collect();
    Ok(PyArray2::from_vec2(py, &data)?)
}

impl Mechanism {
    /// `(nq, nv, d)`: the numbers of coordinates and speeds, and the contact space's
    /// dimension.
    pub fn dimensions(&self) -> (usize, usize, usize) {
        match &self.kind {
            Kind::Planar(p) => (p.mechanism.dof(), p.mechanism.dof(), 2),
            Kind::Spatial(s) => (s.robot.model().nq(), s.robot.model().nv(), 3),
        }
    }

    /// The contact of a call: the one given, else `mechanism(..., contact=...)`'s.
    pub fn contact<'a>(&'a self, contact: Option<&'a str>) -> Option<&'a str> {
        contact.or(self.defaults.contact.as_deref())
    }

    /// The coordinates' names.
    fn coordinate_names(&self) -> Vec<String> {
        match &self.kind {
            Kind::Planar(p) => p
                .mechanism
                .coordinates()
                .iter()
                .map(|s| s.to_string())
                .collect(),
            Kind::Spatial(s) => s.robot.model().coordinates().to_vec(),
        }
    }

    /// The laws of `laws=`: None (the defaults), one id, or a sequence of ids.
    pub fn laws(&self, laws: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<LawId>> {
        let ids: Vec<String> = match laws.filter(|l| !l.is_none()) {
            None => return Ok(self.defaults.laws.clone()),
            Some(l) if l.is_instance_of::<PyString>() => vec![l.extract()?],
            Some(l) => l.extract().map_err(|_| {
                value_error("laws: expected a law id or a sequence of law ids (impax.LAWS)")
            })?,
        };
        let spatial = matches!(self.kind, Kind::Spatial(_));
        let mut out = Vec::new();
        for id in &ids {
            let l = if spatial {
                crate::convert::spatial_law(id.trim())?
            } else {
                crate::convert::planar_law(id.trim())?
            };
            if !out.contains(&l) {
                out.push(l);
            }
        }
        Ok(out)
    }

    /// The coefficients of a call: given, else the defaults.
    pub fn coefficients(&self, friction: Option<f64>, restitution: Option<f64>) -> (f64, f64) {
        (
            friction.unwrap_or(self.defaults.friction),
            restitution.unwrap_or(self.defaults.restitution),
        )
    }

    /// `f(struck)` with the mechanism at `(q, u)` struck at `contact` (see
    /// [`robot_impact::strike`]).
    fn with_struck<R>(
        &self,
        q: &[f64],
        u: &[f64],
        contact: Option<&str>,
        f: impl FnOnce(&Struck<'_>) -> impax::Result<R>,
    ) -> PyResult<R> {
        let mut ws = None;
        let model = match &self.kind {
            Kind::Spatial(s) => Some(s.model(contact)?),
            Kind::Planar(_) => None,
        };
        lib(robot_impact::strike(
            self,
            model.as_deref(),
            &mut ws,
            q,
            u,
            contact,
            f,
        ))
    }
}

#[pymethods]
impl Mechanism {
    /// The mechanism's name (the file's `name`, the URDF robot's, else the file's stem).
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// `"2d"` (a planar mechanism file) or `"3d"` (a spatial file or a URDF robot).
    #[getter]
    fn space(&self) -> &'static str {
        match self.kind {
            Kind::Planar(_) => "2d",
            Kind::Spatial(_) => "3d",
        }
    }

    /// The names of the entries of `q`, in order, as a list (a floating base's
    /// `x, y, z, qw, qx, qy, qz` first).
    #[getter]
    fn coordinates<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.coordinate_names())
    }

    /// The names of the entries of `u` (a floating base's `vx, vy, vz, wx, wy, wz`: the base
    /// origin's velocity and the angular velocity, in the world frame).
    #[getter]
    fn speeds<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        match &self.kind {
            Kind::Planar(_) => PyTuple::new(py, self.coordinate_names()),
            Kind::Spatial(s) => PyTuple::new(py, s.robot.model().speeds()),
        }
    }

    /// What `contact=` may name: a file's contacts; a URDF robot's links (each `"LINK"`, the
    /// origin of its frame, or `"LINK:x,y,z"`, a point in it).
    #[getter]
    fn contacts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        match &self.kind {
            Kind::Planar(p) => PyTuple::new(py, p.mechanism.contacts().iter().map(|c| c.name)),
            Kind::Spatial(s) => PyTuple::new(py, s.robot.contact_names()),
        }
    }

    /// URDF joints with a `<mimic>` tag, kept as independent coordinates (as Pinocchio's URDF
    /// reader does by default).
    #[getter]
    fn mimic_joints<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        match &self.kind {
            Kind::Planar(_) => PyTuple::new(py, Vec::<String>::new()),
            Kind::Spatial(s) => PyTuple::new(py, s.robot.mimic_joints()),
        }
    }

    /// One line describing the mechanism.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// A default configuration: every joint at zero, a floating base at the origin with the
    /// identity quaternion `(1, 0, 0, 0)`.
    fn neutral<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        match &self.kind {
            Kind::Planar(p) => vector(py, &vec![0.0; p.mechanism.dof()]),
            Kind::Spatial(s) => vector(py, &s.robot.model().neutral()),
        }
    }

    /// The state a mechanism file gives (`q`, `u`; default: zero, a neutral configuration),
    /// as two arrays.
    fn default_state<'py>(
        &self,
        py: Python<'py>,
    ) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
        match &self.kind {
            Kind::Planar(p) => (vector(py, &p.q), vector(py, &p.u)),
            Kind::Spatial(s) => {
                let (q, u) = s.robot.default_state();
                (vector(py, &q), vector(py, &u))
            }
        }
    }

    /// The mass matrix `M(q)` (`nv × nv`), `T = ½ uᵀ M u`.
    fn mass_matrix<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = q_arg)] q: Vec<f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let m = match &self.kind {
            Kind::Planar(p) => {
                lib(dynamics::check_state(&p.mechanism, &q, None))?;
                dynamics::mass_matrix(&p.mechanism, &q)
            }
            Kind::Spatial(s) => lib(multibody::mass_matrix(s.robot.model(), &q))?,
        };
        matrix(py, m.nrows(), m.ncols(), |i, j| m[(i, j)])
    }

    /// The contact's Jacobian at `q` in its contact frame (rows `t, n` in 2D; `t1, t2, n` in
    /// 3D — for the floor `t1 = x`, `t2 = y`, `n = z` of the world): `v = J u` is the contact
    /// point's velocity. `contact`: a file's contact (default: the one that strikes at `q`,
    /// the lowest), or a URDF robot's `"LINK"` / `"LINK:x,y,z"` (required).
    #[pyo3(signature = (q, contact = None))]
    fn contact_jacobian<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = q_arg)] q: Vec<f64>,
        contact: Option<&str>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let contact = self.contact(contact);
        match &self.kind {
            Kind::Planar(p) => {
                let zeros = vec![0.0; p.mechanism.dof()];
                let mech = lib(robot_impact::placed(p, &q))?;
                let impact = lib(LibMechanismImpact::named(&*mech, &q, &zeros, contact))?;
                let j = impact.jacobian();
                matrix(py, j.nrows(), j.ncols(), |r, c| j[(r, c)])
            }
            Kind::Spatial(s) => {
                let model = s.model(contact)?;
                let mut ws = Workspace::new(&model);
                lib(ws.update(&model, &q))?;
                let k = lib(s
                    .robot
                    .striking_contact(&model, contact, ws.configuration()))?;
                let j = lib(multibody::contact_jacobian(&model, &ws, k))?;
                matrix(py, 3, j.ncols(), |r, c| j[(r, c)])
            }
        }
    }

    /// The contact-space problem at `(q, u)`: `(W, v)` with `W = J M⁻¹ Jᵀ` (2×2 or 3×3) and
    /// `v = J u` (the contact velocity before), as arrays. With `friction` and `restitution`
    /// the problem is also checked as `impact` checks it (an approaching contact,
    /// coefficients in range), so that `impax.resolve(W, v, friction, restitution, law)`
    /// gives `impact`'s contact-space numbers.
    #[pyo3(signature = (q, u, contact = None, friction = None, restitution = None))]
    fn contact_problem<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = q_arg)] q: Vec<f64>,
        #[pyo3(from_py_with = u_arg)] u: Vec<f64>,
        contact: Option<&str>,
        #[pyo3(from_py_with = arg::friction)] friction: Option<f64>,
        #[pyo3(from_py_with = arg::restitution)] restitution: Option<f64>,
    ) -> PyResult<ProblemArrays<'py>> {
        let contact = self.contact(contact);
        let (w, v) = self.with_struck(&q, &u, contact, |s| {
            if friction.is_some() || restitution.is_some() {
                let (f, e) = self.coefficients(friction, restitution);
                s.check_problem(f, e)?;
            }
            Ok(s.reduced())
        })?;
        let d = v.len();
        Ok((matrix(py, d, d, |i, j| w[i * d + j])?, vector(py, &v)))
    }

    /// The gap of the contact at `q` above the floor (0 when the floor passes through the
    /// striking contact: no `floor=`, no height in the file).
    #[pyo3(signature = (q, contact = None))]
    fn gap(
        &self,
        #[pyo3(from_py_with = q_arg)] q: Vec<f64>,
        contact: Option<&str>,
    ) -> PyResult<f64> {
        let contact = self.contact(contact);
        match &self.kind {
            Kind::Planar(p) => {
                let zeros = vec![0.0; p.mechanism.dof()];
                let mech = lib(robot_impact::placed(p, &q))?;
                Ok(lib(LibMechanismImpact::named(&*mech, &q, &zeros, contact))?.gap())
            }
            Kind::Spatial(s) => lib(robot_impact::spatial_gap(&s.robot, &q, contact)),
        }
    }

    /// Resolve the impact at `(q, u)` of `contact` with each law of `laws` (one id or a list;
    /// default: the file's `laws`, else every spatial law in 3D and every contact-space law
    /// in 2D). Returns the record `impax compare FILE --q Q --u U --json` prints (a dict,
    /// written by the same function of the core): `mechanism`, `scenario`, `coordinates`,
    /// `q` (quaternions normalised), `u_before`, `contact`, `gap`, `problem` (`w`, `v`,
    /// `friction`, `restitution`), `energy_before` and `results`, one dict per law with
    /// `velocities_after` (`u⁺ = u⁻ + M⁻¹ Jᵀ p`), `impulse`, `energy_change`,
    /// `energy_after`, `energy_ratio`, `energy_change_from_velocities`, `phases`, `verdict`,
    /// …; in 3D also `speeds` and `mimic_joints`. `friction`, `restitution`: default the
    /// file's, else those given to `mechanism(...)`, else 0.5.
    #[pyo3(signature = (q, u, contact = None, friction = None, restitution = None, laws = None))]
    #[allow(clippy::too_many_arguments)]
    fn impact<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = q_arg)] q: Vec<f64>,
        #[pyo3(from_py_with = u_arg)] u: Vec<f64>,
        contact: Option<&str>,
        #[pyo3(from_py_with = arg::friction)] friction: Option<f64>,
        #[pyo3(from_py_with = arg::restitution)] restitution: Option<f64>,
        laws: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let laws = self.laws(laws)?;
        let contact = self.contact(contact);
        let (f, e) = self.coefficients(friction, restitution);
        let doc = lib(robot_impact::record(self, &q, &u, contact, f, e, &laws))?;
        json_to_py(py, &doc)
    }

    /// Resolve the impacts of many states with one law, in parallel (rayon, the GIL
    /// released): `q` of shape (N, nq), `u` (N, nv); `contact`, `friction`, `restitution` as
    /// for `impact` (one for every row). Row `i` equals `impact(q[i], u[i], ...)` with
    /// `laws=[law]`. Returns a dict of arrays: `velocities_after` (N, nv), `impulse` and
    /// `velocity_after` (the contact velocity after; N, 2 or 3), `energy_before`,
    /// `energy_change` (N,), `status` (uint8 codes into `impax.STATUSES`); numbers are NaN
    /// where the law broke down or the row is invalid. An invalid row raises
    /// `ValueError("row I: ...")` (`on_invalid="raise"`) or gets the status `invalid`
    /// (`"mark"`); `threads` as for `resolve_batch`.
    #[pyo3(signature = (q, u, contact = None, friction = None, restitution = None, law = "energetic", *, on_invalid = "raise", threads = None))]
    #[allow(clippy::too_many_arguments)]
    fn impact_batch<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        u: &Bound<'py, PyAny>,
        contact: Option<&str>,
        #[pyo3(from_py_with = arg::friction)] friction: Option<f64>,
        #[pyo3(from_py_with = arg::restitution)] restitution: Option<f64>,
        law: &str,
        on_invalid: &str,
        threads: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let law = match self.laws(Some(PyString::new(py, law).as_any()))?[..] {
            [l] => l,
            _ => return Err(value_error("law: expected one law id")),
        };
        let (f, e) = self.coefficients(friction, restitution);
        let contact = self.contact(contact);
        crate::robot_batch::run(py, self, q, u, contact, f, e, law, on_invalid, threads)
    }

    fn __repr__(&self) -> String {
        format!("Mechanism({})", self.description)
    }
}
