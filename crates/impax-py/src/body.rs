//! The planar bodies of Python: a striking body with its impact ([`BodyImpact`]) and a struck
//! free body ([`Body`], the `other=` of a striking body). The functions that build them are in
//! [`crate::shapes`].

use crate::convert::mat2;
use crate::outcome::{Context, Outcome, Raw};
use impax::planar::bodies::{self, BodyState, RigidBody};
use impax::planar::ContactProblem;
use impax::scenario::BuiltBody;
use impax::LawId;
use numpy::PyArray2;
use pyo3::prelude::*;

/// A planar body (with its state before the impact) striking a fixed surface, with the
/// coefficients of the contact: the input of `compare` and of `resolve`.
#[pyclass(frozen, module = "impax._impax")]
pub struct BodyImpact {
    impact: bodies::BodyImpact,
    problem: ContactProblem,
    t0: f64,
    description: String,
}

impl BodyImpact {
    /// Body A as the core built it, against the fixed surface or against `other`.
    pub(crate) fn new(
        built: BuiltBody,
        other: Option<&Body>,
        friction: f64,
        restitution: f64,
    ) -> PyResult<Self> {
        let BuiltBody {
            body,
            state,
            description,
            ..
        } = built;
        let (impact, description) = match other {
            None => (bodies::BodyImpact::on_fixed_surface(body, state), description),
            Some(o) => (
                bodies::BodyImpact::between(body, state, o.body, o.state),
                format!("{description} striking {}", o.description),
            ),
        };
        let problem = crate::convert::lib(impact.problem(friction, restitution))?;
        let before = impact.energy_before();
        let t0 = if before.translational > 0.0 {
            before.translational
        } else {
            before.total()
        };
        Ok(Self {
            impact,
            problem,
            t0,
            description,
        })
    }

    pub(crate) fn outcome(&self, law: LawId) -> Outcome {
        let r = self.impact.resolve(law, &self.problem);
        let (raw, body_after, other_after, split) = match r {
            Ok(b) => (
                Ok(b.outcome),
                Some(b.body_after),
                b.other_after,
                Some(b.energy_change),
            ),
            Err(e) => (Err(e), None, None, None),
        };
        Outcome {
            law,
            raw: Raw::Planar(raw),
            approach_energy: self.problem.approach_energy(),
            context: Context::Body {
                body_after,
                other_after,
                two_bodies: self.impact.other.is_some(),
                split,
                t0: self.t0,
                energy_before: self.impact.energy_before().total(),
            },
            problem3: None,
        }
    }
}

#[pymethods]
impl BodyImpact {
    /// The contact-space inverse inertia `W = [[1/m + r_n²/I, −r_t r_n/I], [·, 1/m + r_t²/I]]`.
    #[getter]
    fn w<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        mat2(py, self.problem.w())
    }

    /// The contact velocity before, `(v_t, v_n) = (v_x − ω r_n, v_y + ω r_t)`.
    #[getter]
    fn v(&self) -> (f64, f64) {
        let v = self.problem.velocity();
        (v.x, v.y)
    }

    /// Coulomb friction coefficient μ.
    #[getter]
    fn friction(&self) -> f64 {
        self.problem.friction()
    }

    /// Coefficient of restitution e.
    #[getter]
    fn restitution(&self) -> f64 {
        self.problem.restitution()
    }

    /// Kinetic energy before the impact, `½ m |v|² + ½ I ω²`.
    #[getter]
    fn energy_before(&self) -> f64 {
        self.impact.energy_before().total()
    }

    /// The normalisation `T0` of `energy_change_ratio`: the translational kinetic energy
    /// before (`½ m v0²` in the seed's case), or the total if that is zero.
    #[getter]
    fn t0(&self) -> f64 {
        self.t0
    }

    /// One line describing the body and its state.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// Resolve the impact with one law (any law, including `smith-centre`).
    #[pyo3(signature = (law = "energetic"))]
    fn resolve(&self, law: &str) -> PyResult<Outcome> {
        Ok(self.outcome(crate::convert::law(law)?))
    }

    fn __repr__(&self) -> String {
        format!("BodyImpact({})", self.description)
    }
}

/// A struck body B: a free planar body met at its highest point (`Side::Above`), with its
/// state; the `other=` of a body constructor (two free bodies: `W = W_A + W_B`, the relative
/// contact velocity `v_A − v_B`, impulse `p` on A and `−p` on B).
#[pyclass(frozen, module = "impax._impax")]
pub struct Body {
    body: RigidBody,
    state: BodyState,
    description: String,
}

#[pymethods]
impl Body {
    /// One line describing the body and its state.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// The body's contact-space inverse inertia `W_B` at its contact point.
    #[getter]
    fn w<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        mat2(py, self.body.inverse_inertia())
    }

    fn __repr__(&self) -> String {
        format!("Body({})", self.description)
    }
}

impl Body {
    /// The struck body as the core built it.
    pub(crate) fn new(built: BuiltBody) -> Self {
        Self {
            body: built.body,
            state: built.state,
            description: built.description,
        }
    }
}
