//! `impax.Outcome`: the result of one law on one impact, as a small read-only object.
//!
//! It holds the library's record (no copy into Python objects until an attribute is read),
//! so that a loop over `impax.resolve` pays only for what it reads. `to_dict()` gives the
//! entry of the CLI's `--json` output for the same impact, key for key.

use impax::planar::bodies::{BodyState, EnergyParts};
use impax::math::{Vec2, Vec3};
use impax::planar::{Breakdown, Inconsistency, LawDetail, Outcome as Planar, SmithReading};
use impax::spatial::{self, invariant_rays, InvariantRays};
use impax::LawId;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

/// The library's result: planar or spatial, an outcome or a breakdown.
pub enum Raw {
    /// A planar law's resolution.
    Planar(Result<Planar, Breakdown>),
    /// A spatial law's resolution.
    Spatial(Result<spatial::Outcome, Breakdown>),
}

/// What the impact acted on, beyond contact space.
pub enum Context {
    /// Contact space only (`impax.resolve`, CLI `impax resolve --json`).
    Contact,
    /// A planar body (or two) — `impax compare --json` of a body scenario.
    Body {
        /// Body A after (none on a breakdown).
        body_after: Option<BodyState>,
        /// Body B after, when there is a body B.
        other_after: Option<BodyState>,
        /// Whether there is a body B.
        two_bodies: bool,
        /// `ΔT` split into translational and rotational parts (paper A §5).
        split: Option<EnergyParts>,
        /// The normalisation `T0`.
        t0: f64,
        /// Kinetic energy of the bodies before, `Σ ½ m |v|² + ½ I ω²`.
        energy_before: f64,
    },
    /// A mechanism — `impax compare MECHANISM --json`.
    Mechanism {
        /// Generalized velocities after (none on a breakdown).
        velocities_after: Option<Vec<f64>>,
        /// `½ u⁻ᵀ M u⁻`.
        energy_before: f64,
        /// `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻`.
        energy_change_from_velocities: Option<f64>,
    },
}

/// The result of one impact law on one impact.
///
/// Attributes are `None` where the law broke down (`verdict == "breakdown"`, with the reason
/// in `breakdown`): a breakdown never carries numbers.
#[pyclass(frozen, module = "impax._impax")]
pub struct Outcome {
    pub law: LawId,
    pub raw: Raw,
    pub approach_energy: f64,
    pub context: Context,
    /// The spatial contact-space problem (`impax.resolve` with a 3×3 `W`), for what is
    /// computed only when read: the hodograph, the invariant rays, the LCP's solutions.
    pub problem3: Option<spatial::ContactProblem>,
}

/// The common numbers of a planar or spatial outcome.
struct Common<'a> {
    dim: usize,
    impulse: [f64; 3],
    velocity: [f64; 3],
    compression_impulse: Option<f64>,
    work: impax::planar::WorkSplit,
    energy_change: f64,
    verdict: &'static str,
    inconsistency: Option<&'a Inconsistency>,
}

fn v2(v: Vec2) -> [f64; 3] {
    [v.x, v.y, 0.0]
}
fn v3(v: Vec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// A detail number as the CLI's JSON gives it: `None` when not finite (e.g. Brach's ratio
/// of a sticking impulse with no normal part is infinite).
fn fin(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// JSON numbers print `-0` as `0`; keep the same value here.
fn num(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

impl Outcome {
    /// The hodograph of a Darboux–Keller law on a spatial contact problem that resolved.
    fn hodograph_points(&self) -> Option<Vec<[f64; 4]>> {
        match (&self.problem3, &self.raw) {
            (Some(p), Raw::Spatial(Ok(_))) if self.law.is_darboux_keller() => {
                impax::spatial::laws::hodograph(p, self.law, &impax::law::Options::default()).ok()
            }
            _ => None,
        }
    }

    fn common(&self) -> Option<Common<'_>> {
        match &self.raw {
            Raw::Planar(Ok(o)) => Some(Common {
                dim: 2,
                impulse: v2(o.impulse),
                velocity: v2(o.velocity_after),
                compression_impulse: o.compression_impulse,
                work: o.work,
                energy_change: o.energy_change,
                verdict: o.verdict.id(),
                inconsistency: o.inconsistency.as_ref(),
            }),
            Raw::Spatial(Ok(o)) => Some(Common {
                dim: 3,
                impulse: v3(o.impulse),
                velocity: v3(o.velocity_after),
                compression_impulse: o.compression_impulse,
                work: o.work,
                energy_change: o.energy_change,
                verdict: o.verdict.id(),
                inconsistency: o.inconsistency.as_ref(),
            }),
            _ => None,
        }
    }

    fn breakdown_of(&self) -> Option<&Breakdown> {
        match &self.raw {
            Raw::Planar(Err(b)) | Raw::Spatial(Err(b)) => Some(b),
            _ => None,
        }
    }

    fn dim(&self) -> usize {
        match self.raw {
            Raw::Planar(_) => 2,
            Raw::Spatial(_) => 3,
        }
    }

    /// A contact-frame vector as a dict: `{t, n}` or `{t1, t2, n}`.
    fn frame_dict<'py>(&self, py: Python<'py>, v: [f64; 3]) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        if self.dim() == 2 {
            d.set_item("t", num(v[0]))?;
            d.set_item("n", num(v[1]))?;
        } else {
            d.set_item("t1", num(v[0]))?;
            d.set_item("t2", num(v[1]))?;
            d.set_item("n", num(v[2]))?;
        }
        Ok(d)
    }

    fn work_dict<'py>(py: Python<'py>, c: &Common<'_>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("compression", num(c.work.compression))?;
        d.set_item("restitution", num(c.work.restitution))?;
        d.set_item("friction", num(c.work.friction))?;
        Ok(d)
    }

    fn phases_list<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        match &self.raw {
            Raw::Planar(Ok(o)) => {
                for p in o.phases.as_slice() {
                    let d = PyDict::new(py);
                    d.set_item("kind", p.kind.label())?;
                    d.set_item("ends_at", num(p.ends_at))?;
                    list.append(d)?;
                }
            }
            Raw::Spatial(Ok(o)) => {
                for p in o.phases.as_slice() {
                    let d = PyDict::new(py);
                    d.set_item("kind", p.kind.label())?;
                    d.set_item("ends_at", num(p.ends_at))?;
                    #[allow(unreachable_patterns)]
                    match p.kind {
                        spatial::PhaseKind::Slip { from, to } => {
                            d.set_item("from_deg", from.to_degrees())?;
                            d.set_item("to_deg", to.to_degrees())?;
                        }
                        spatial::PhaseKind::Resumed { angle } => {
                            d.set_item("angle_deg", angle.to_degrees())?;
                        }
                        _ => {}
                    }
                    list.append(d)?;
                }
            }
            _ => {}
        }
        Ok(list)
    }

    fn detail_obj<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let d = PyDict::new(py);
        match &self.raw {
            #[allow(unreachable_patterns)]
            Raw::Planar(Ok(o)) => match o.detail {
                LawDetail::None => return Ok(None),
                LawDetail::TwoPhase { switch_impulse } => {
                    d.set_item("switch_impulse", switch_impulse.and_then(fin))?;
                }
                LawDetail::Smith {
                    eta,
                    roots,
                    reading,
                } => {
                    d.set_item("eta", fin(eta))?;
                    d.set_item("roots", roots)?;
                    d.set_item(
                        "reading",
                        match reading {
                            SmithReading::SlipVelocity => "slip-velocity",
                            SmithReading::CentreVelocity => "centre-velocity",
                        },
                    )?;
                }
                LawDetail::Brach { ratio, capped } => {
                    d.set_item("ratio", ratio.and_then(fin))?;
                    d.set_item("capped", capped)?;
                }
                LawDetail::DarbouxKeller { slip_halt } => {
                    d.set_item("slip_halt", slip_halt.and_then(fin))?;
                }
                LawDetail::Lcp {
                    ratio,
                    consistent_candidates,
                } => {
                    d.set_item("ratio", fin(ratio))?;
                    d.set_item("consistent_candidates", consistent_candidates)?;
                }
                _ => return Ok(None),
            },
            #[allow(unreachable_patterns)]
            Raw::Spatial(Ok(o)) => match o.detail {
                spatial::LawDetail::None => return Ok(None),
                spatial::LawDetail::Brach { ratio, capped } => {
                    d.set_item("ratio", ratio.and_then(fin))?;
                    d.set_item("capped", capped)?;
                }
                spatial::LawDetail::Lcp { solutions } => {
                    d.set_item("solutions", solutions)?;
                }
                spatial::LawDetail::DarbouxKeller {
                    slip_halt,
                    second_compression,
                    steps,
                } => {
                    d.set_item("slip_halt", slip_halt.and_then(fin))?;
                    d.set_item("second_compression", second_compression.and_then(fin))?;
                    d.set_item("steps", steps)?;
                }
                _ => return Ok(None),
            },
            _ => return Ok(None),
        }
        Ok(Some(d))
    }

    fn state_dict<'py>(py: Python<'py>, s: &BodyState) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("vx", num(s.velocity.x))?;
        d.set_item("vy", num(s.velocity.y))?;
        d.set_item("omega", num(s.omega))?;
        Ok(d)
    }

    fn tuple<'py>(py: Python<'py>, v: &[f64]) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, v.iter().copied())
    }
}

#[pymethods]
impl Outcome {
    /// The law's stable id, e.g. `"energetic"`.
    #[getter]
    fn law(&self) -> &'static str {
        self.law.as_str()
    }

    /// `"consistent"`, `"energy-gained"` (Kane's paradox), `"inconsistent-assumption"`, or
    /// `"breakdown"` (the law gives no admissible result; see `breakdown`).
    #[getter]
    fn verdict(&self) -> &'static str {
        self.common().map_or("breakdown", |c| c.verdict)
    }

    /// Whether the kinetic energy rose (`verdict == "energy-gained"`).
    #[getter]
    fn energy_gained(&self) -> bool {
        self.verdict() == "energy-gained"
    }

    /// `None`, or `{"id", "message"}` when the law broke down (e.g. Whittaker's negative
    /// normal impulse: `p_n = −(1+e) v_n⁻ / (W_nn − μ s₀ W_tn)` with a denominator ≤ 0).
    #[getter]
    fn breakdown<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match self.breakdown_of() {
            None => Ok(None),
            Some(b) => {
                let d = PyDict::new(py);
                d.set_item("id", b.reason.id())?;
                d.set_item("message", b.reason.to_string())?;
                Ok(Some(d))
            }
        }
    }

    /// Impulse on body A in the contact frame: `(p_t, p_n)` or `(p_t1, p_t2, p_n)`.
    #[getter]
    fn impulse<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyTuple>>> {
        self.common()
            .map(|c| Self::tuple(py, &c.impulse[..c.dim]))
            .transpose()
    }

    /// Contact velocity after: `v⁺ = v⁻ + W p`.
    #[getter]
    fn velocity_after<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyTuple>>> {
        self.common()
            .map(|c| Self::tuple(py, &c.velocity[..c.dim]))
            .transpose()
    }

    /// `ΔT = v⁻·p + ½ pᵀ W p` (exact for any impulse; theory §1).
    #[getter]
    fn energy_change(&self) -> Option<f64> {
        self.common().map(|c| c.energy_change)
    }

    /// The approach energy `½ v⁻ᵀ W⁻¹ v⁻`: the most energy any impulse can remove (the
    /// kinetic energy of the relative contact motion).
    #[getter]
    fn approach_energy(&self) -> f64 {
        self.approach_energy
    }

    /// Normal impulse `p_c` at the end of compression (`v_n = 0`), or `None`.
    #[getter]
    fn compression_impulse(&self) -> Option<f64> {
        self.common().and_then(|c| c.compression_impulse)
    }

    /// `{"compression", "restitution", "friction"}`: normal work in compression and
    /// restitution, friction work; they sum to `ΔT`.
    #[getter]
    fn work<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.common().map(|c| Self::work_dict(py, &c)).transpose()
    }

    /// The phases: a list of `{"kind", "ends_at"}` (`kind`: `slip+`, `slip-`, `stick`,
    /// `no-slip`; in 3D `slip`, `stick`, `resumed-slip`, `no-slip` with angles in degrees).
    #[getter]
    fn phases<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        self.phases_list(py)
    }

    /// `None`, or `{"id", "message"}`: the law's own assumption that its result contradicts
    /// (`slip-reversed`, `reversal-did-not-happen`).
    #[getter]
    fn inconsistency<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match self.common().and_then(|c| c.inconsistency) {
            None => Ok(None),
            Some(i) => {
                let d = PyDict::new(py);
                d.set_item("id", i.id())?;
                d.set_item("message", i.to_string())?;
                Ok(Some(d))
            }
        }
    }

    /// Law-specific numbers (two-phase `switch_impulse`; smith `eta`, `roots`, `reading`;
    /// brach `ratio`, `capped`; newton/poisson/energetic `slip_halt`), or `None`.
    #[getter]
    fn detail<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.detail_obj(py)
    }

    /// Body A after the impact, `{"vx", "vy", "omega"}` (bodies only).
    #[getter]
    fn body_velocity_after<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.context {
            Context::Body {
                body_after: Some(s),
                ..
            } => Ok(Some(Self::state_dict(py, s)?)),
            _ => Ok(None),
        }
    }

    /// Body B after the impact (two free bodies only).
    #[getter]
    fn other_body_velocity_after<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.context {
            Context::Body {
                other_after: Some(s),
                ..
            } => Ok(Some(Self::state_dict(py, s)?)),
            _ => Ok(None),
        }
    }

    /// `ΔT` split into `{"translational", "rotational"}` parts (paper A §5; bodies only).
    #[getter]
    fn energy_split<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        match &self.context {
            Context::Body { split: Some(s), .. } => {
                let d = PyDict::new(py);
                d.set_item("translational", num(s.translational))?;
                d.set_item("rotational", num(s.rotational))?;
                Ok(Some(d))
            }
            _ => Ok(None),
        }
    }

    /// Kinetic energy before the impact: of the bodies (`½ m |v|² + ½ I ω²`) or of the
    /// mechanism (`½ u⁻ᵀ M u⁻`); `None` in contact space, where only `approach_energy` is
    /// defined.
    #[getter]
    fn energy_before(&self) -> Option<f64> {
        match &self.context {
            Context::Contact => None,
            Context::Body { energy_before, .. } | Context::Mechanism { energy_before, .. } => {
                Some(*energy_before)
            }
        }
    }

    /// `ΔT / T0` with `T0` the translational kinetic energy before (bodies only).
    #[getter]
    fn energy_change_ratio(&self) -> Option<f64> {
        match (&self.context, self.common()) {
            (Context::Body { t0, .. }, Some(c)) => Some(c.energy_change / t0),
            _ => None,
        }
    }

    /// Generalized velocities after, `u⁺ = u⁻ + M⁻¹ Jᵀ p` (mechanisms only).
    #[getter]
    fn velocities_after<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyTuple>>> {
        match &self.context {
            Context::Mechanism {
                velocities_after: Some(u),
                ..
            } => Ok(Some(Self::tuple(py, u)?)),
            _ => Ok(None),
        }
    }

    /// Kinetic energy after, `T⁻ + ΔT` (mechanisms only).
    #[getter]
    fn energy_after(&self) -> Option<f64> {
        match (&self.context, self.common()) {
            (Context::Mechanism { energy_before, .. }, Some(c)) => {
                Some(energy_before + c.energy_change)
            }
            _ => None,
        }
    }

    /// `T⁺ / T⁻` (mechanisms only).
    #[getter]
    fn energy_ratio(&self) -> Option<f64> {
        match (&self.context, self.common()) {
            (Context::Mechanism { energy_before, .. }, Some(c)) => {
                Some((energy_before + c.energy_change) / energy_before)
            }
            _ => None,
        }
    }

    /// `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻`, which equals `energy_change` up to round-off (mechanisms).
    #[getter]
    fn energy_change_from_velocities(&self) -> Option<f64> {
        match &self.context {
            Context::Mechanism {
                energy_change_from_velocities,
                ..
            } => *energy_change_from_velocities,
            _ => None,
        }
    }

    /// The slip's hodograph `(p_n, v_t1, v_t2, v_n)` at every accepted point of the
    /// integration (`newton`, `poisson`, `energetic` on a spatial contact problem; `None`
    /// otherwise or on a breakdown). Computed when read (it integrates the impact again).
    #[getter]
    fn hodograph<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        match self.hodograph_points() {
            Some(pts) => Ok(Some(PyList::new(
                py,
                pts.iter()
                    .map(|q| PyTuple::new(py, q.iter().map(|&x| num(x))))
                    .collect::<PyResult<Vec<_>>>()?,
            )?)),
            None => Ok(None),
        }
    }

    /// The spatial problem's invariant rays: a list of `{"angle_deg", "kind", "rate"}`
    /// (`kind` `centripetal` or `centrifugal`, `rate = ŝ·g`), or `"all"` when every
    /// direction is invariant (isotropic `W_tt`, `w_tn = 0`); `None` for other records.
    #[getter]
    fn invariant_rays<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(p) = &self.problem3 else {
            return Ok(None);
        };
        let rays = invariant_rays(p);
        if let InvariantRays::All = rays {
            return Ok(Some(PyString::new(py, "all").into_any()));
        }
        let list = PyList::empty(py);
        for r in rays.as_slice() {
            let d = PyDict::new(py);
            d.set_item("angle_deg", r.angle.to_degrees())?;
            d.set_item("kind", r.kind.id())?;
            d.set_item("rate", r.rate)?;
            list.append(d)?;
        }
        Ok(Some(list.into_any()))
    }

    /// Every solution of the spatial LCP, least kinetic energy after first (`lcp` on a
    /// spatial contact problem; `None` otherwise): `kind` (`stick` or `slip`),
    /// `slip_angle_deg` (slip only), `impulse`, `velocity_after`, `energy_change`.
    #[getter]
    fn all_solutions<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyList>>> {
        let Some(p) = self.problem3.filter(|_| self.law == LawId::Lcp) else {
            return Ok(None);
        };
        let list = PyList::empty(py);
        for sol in impax::spatial::laws::lcp::solutions(&p) {
            let d = PyDict::new(py);
            d.set_item("kind", sol.kind.label())?;
            d.set_item("impulse", self.frame_dict(py, v3(sol.impulse))?)?;
            d.set_item(
                "velocity_after",
                self.frame_dict(py, v3(sol.velocity_after))?,
            )?;
            d.set_item("energy_change", num(sol.energy_change))?;
            if let spatial::PhaseKind::Slip { to, .. } = sol.kind {
                d.set_item("slip_angle_deg", to.to_degrees())?;
            }
            list.append(d)?;
        }
        Ok(Some(list))
    }

    /// The record as the CLI's JSON entry: `impax resolve --json` for a contact-space
    /// problem (a spatial one with `hodograph`, `invariant_rays` and, for `lcp`,
    /// `all_solutions`), an entry of `results` of `impax compare --json` for a body or a
    /// mechanism.
    pub fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let velocity_key = match self.context {
            Context::Contact => "velocity_after",
            _ => "contact_velocity_after",
        };
        d.set_item("law", self.law.as_str())?;
        match self.common() {
            Some(c) => {
                d.set_item("verdict", c.verdict)?;
                d.set_item("impulse", self.frame_dict(py, c.impulse)?)?;
                d.set_item(velocity_key, self.frame_dict(py, c.velocity)?)?;
                d.set_item("compression_impulse", c.compression_impulse.map(num))?;
                d.set_item("work", Self::work_dict(py, &c)?)?;
                d.set_item("energy_change", num(c.energy_change))?;
                d.set_item("phases", self.phases_list(py)?)?;
                d.set_item("inconsistency", self.inconsistency(py)?)?;
                d.set_item("detail", self.detail_obj(py)?)?;
            }
            None => {
                d.set_item("verdict", "breakdown")?;
                d.set_item("breakdown", self.breakdown(py)?)?;
                for k in [
                    "impulse",
                    velocity_key,
                    "compression_impulse",
                    "work",
                    "energy_change",
                    "inconsistency",
                    "detail",
                ] {
                    d.set_item(k, py.None())?;
                }
                d.set_item("phases", PyList::empty(py))?;
            }
        }
        if self.problem3.is_some() {
            let pts = self
                .hodograph_points()
                .map(|pts| PyList::new(py, pts.iter().map(|q| q.map(num).to_vec())));
            d.set_item("hodograph", pts.transpose()?)?;
            if self.common().is_some() {
                if let Some(all) = self.all_solutions(py)? {
                    d.set_item("all_solutions", all)?;
                }
            }
            d.set_item("invariant_rays", self.invariant_rays(py)?)?;
        }
        match &self.context {
            Context::Contact => {}
            Context::Body { two_bodies, .. } => {
                d.set_item("body_velocity_after", self.body_velocity_after(py)?)?;
                if *two_bodies && self.common().is_some() {
                    d.set_item(
                        "other_body_velocity_after",
                        self.other_body_velocity_after(py)?,
                    )?;
                }
                d.set_item("energy_change_ratio", self.energy_change_ratio().map(num))?;
                d.set_item("energy_split", self.energy_split(py)?)?;
            }
            Context::Mechanism { .. } => {
                let u = match &self.context {
                    Context::Mechanism {
                        velocities_after: Some(u),
                        ..
                    } => Some(PyList::new(py, u.iter().map(|&x| num(x)))?),
                    _ => None,
                };
                d.set_item("velocities_after", u)?;
                d.set_item("energy_after", self.energy_after().map(num))?;
                d.set_item("energy_ratio", self.energy_ratio().map(num))?;
                d.set_item(
                    "energy_change_from_velocities",
                    self.energy_change_from_velocities().map(num),
                )?;
            }
        }
        Ok(d)
    }

    fn __repr__(&self) -> String {
        match self.common() {
            Some(c) => {
                let p: Vec<String> = c.impulse[..c.dim]
                    .iter()
                    .map(|x| format!("{x:.6}"))
                    .collect();
                format!(
                    "Outcome(law={:?}, verdict={:?}, impulse=({}), energy_change={:.6})",
                    self.law.as_str(),
                    c.verdict,
                    p.join(", "),
                    c.energy_change
                )
            }
            None => format!(
                "Outcome(law={:?}, verdict=\"breakdown\", breakdown={:?})",
                self.law.as_str(),
                self.breakdown_of().map(|b| b.reason.to_string())
            ),
        }
    }
}
