//! The page's requests: a body striking a fixed floor, or a built-in mechanism, with friction
//! and restitution; checked and turned into the library's impact.
//!
//! A body request (angles in degrees, as at the command line):
//!
//! ```json
//! {"friction": 0.4, "restitution": 0.7,
//!  "body": {"shape": "sphere", "mass": 1, "radius": 1,
//!           "speed": 1, "alpha_deg": 30, "spin_ratio": 0}}
//! ```
//!
//! The body is the core's description (`impax::scenario::BodySpec`, as a scenario file's
//! `[body]` table): `shape` is one of [`SHAPES`] — `sphere` or `disc` (`radius`), `rod`
//! (`length`, `angle_deg` from the surface), `ellipse` (`semi_axes`, `angle_deg` of its `a`
//! axis), `rigid` (`inertia`, `contact` = the contact point from the centre, `(t, n)`), … — and
//! the core checks and builds it. The motion is that of paper A for every shape (`speed`,
//! `alpha_deg` and `spin_ratio` are required, `velocity` and `omega` refused): the centre approaches at `speed` v0 at `alpha_deg` α from the normal,
//! `v = v0 (sin α, −cos α)`, spinning at `ω = γ v0 / ρ` where `γ` is `spin_ratio` and `ρ` the
//! distance from the centre to the contact point (the radius of a round body, so that the
//! slip before impact is `v0 (sin α + γ)`, paper A eq. 6).
//!
//! A mechanism request (`double-pendulum`, Kane & Levinson's; the floor through the tip of
//! rod 2 at the given angles):
//!
//! ```json
//! {"friction": 0.5, "restitution": 0.5,
//!  "mechanism": {"name": "double-pendulum", "masses": [1, 1], "lengths": [1, 1],
//!                "angles_deg": [30, 0], "rates": [-1, 2]}}
//! ```

use impax::mechanism::builtin::{DoublePendulum, STANDARD_GRAVITY};
use impax::mechanism::impact::MechanismImpact;
use impax::planar::bodies::{self, BodyImpact, BodyState, Side};
use impax::planar::ContactProblem;
use impax::scenario::{AngleUnit, BodySpec, Shape, ShapeScalar};
use serde::Deserialize;

/// The body shapes a request may name: the core's ([`Shape::NAMES`]).
pub const SHAPES: &[&str] = &Shape::NAMES;

/// Each shape's numbers as the core's table names them (see [`crate::info_json`]): the page
/// builds the sliders of a shape it has no preset for, and every request's body, from them.
pub fn shape_parameters() -> serde_json::Value {
    let mut shapes = serde_json::Map::new();
    for shape in Shape::ALL {
        let scalars: Vec<serde_json::Value> = ShapeScalar::ALL
            .into_iter()
            .filter(|&s| shape.has_scalar(s))
            .map(|s| {
                let (p, i) = s.param();
                serde_json::json!({
                    "name": s.name(),
                    "key": p.key(AngleUnit::Degrees),
                    "index": if p.count() == 1 { None } else { Some(i) },
                    "label": s.label(),
                    "quantity": s.quantity().name(),
                })
            })
            .collect();
        shapes.insert(shape.name().into(), scalars.into());
    }
    shapes.into()
}

/// The parameters of a body request a map may sweep.
pub const BODY_PARAMETERS: [&str; 5] = [
    "alpha_deg",
    "spin_ratio",
    "friction",
    "restitution",
    "angle_deg",
];

/// The parameters of a mechanism request a map may sweep.
pub const MECHANISM_PARAMETERS: [&str; 6] = [
    "angle1_deg",
    "angle2_deg",
    "rate1",
    "rate2",
    "friction",
    "restitution",
];

/// One impact to resolve with every law.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Request {
    /// Coulomb friction μ ≥ 0.
    pub friction: f64,
    /// Restitution e ∈ [0, 1].
    pub restitution: f64,
    /// A body striking a fixed floor (exactly one of `body`, `mechanism`).
    #[serde(default)]
    pub body: Option<BodySpec>,
    /// A built-in mechanism (exactly one of `body`, `mechanism`).
    #[serde(default)]
    pub mechanism: Option<MechanismSpec>,
}

/// A built-in mechanism and its state before the impact.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// `double-pendulum`.
    pub name: String,
    /// Masses of rods 1 and 2.
    pub masses: [f64; 2],
    /// Lengths of rods 1 and 2.
    pub lengths: [f64; 2],
    /// θ₁, θ₂ from the downward vertical, degrees.
    pub angles_deg: [f64; 2],
    /// θ̇₁, θ̇₂, rad/s.
    pub rates: [f64; 2],
}

/// A checked body case.
#[derive(Debug, Clone)]
pub struct BodyCase {
    /// The impact on the fixed floor.
    pub impact: BodyImpact,
    /// The body as requested.
    pub spec: BodySpec,
    /// Its shape.
    pub shape: Shape,
    /// Approach speed v0 > 0 of the centre.
    pub speed: f64,
    /// Approach angle α from the normal, degrees, in (−90, 90).
    pub alpha_deg: f64,
    /// Spin ratio γ = ω ρ / v0.
    pub spin_ratio: f64,
    /// ρ: distance from the centre to the contact point (the spin's length scale).
    pub length_scale: f64,
    /// One line describing the case.
    pub description: String,
}

/// A checked mechanism case.
#[derive(Debug, Clone)]
pub struct MechanismCase {
    /// The pendulum, its floor through the tip.
    pub pendulum: DoublePendulum,
    /// Coordinates (radians).
    pub q: [f64; 2],
    /// Rates (rad/s).
    pub u: [f64; 2],
    /// The mechanism as requested.
    pub spec: MechanismSpec,
    /// One line describing the case.
    pub description: String,
}

/// Either kind of case.
#[derive(Debug, Clone)]
pub enum Case {
    /// A body on a fixed floor.
    Body(BodyCase),
    /// A mechanism.
    Mechanism(MechanismCase),
}

fn finite(field: &str, x: f64) -> Result<f64, String> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("{field}: must be a finite number, got {x}"))
    }
}

/// A motion number the explorer requires.
fn need(field: &str, x: Option<f64>) -> Result<f64, String> {
    finite(
        field,
        x.ok_or_else(|| format!("{field}: required (the explorer gives the motion as speed, alpha_deg and spin_ratio)"))?,
    )
}

fn text(e: impax::Error) -> String {
    e.to_string()
}

impl Request {
    /// Check the request and build its case.
    ///
    /// # Errors
    /// One line naming the field: a missing or non-finite number, a value out of range, an
    /// unknown shape or mechanism, a state that does not approach the floor.
    pub fn case(&self) -> Result<Case, String> {
        finite("friction", self.friction)?;
        finite("restitution", self.restitution)?;
        match (&self.body, &self.mechanism) {
            (Some(b), None) => body_case(b).map(Case::Body),
            (None, Some(m)) => mechanism_case(m).map(Case::Mechanism),
            _ => Err("request: give exactly one of `body` and `mechanism`".into()),
        }
    }
}

fn body_case(spec: &BodySpec) -> Result<BodyCase, String> {
    // The shape, its parameters and its description are the core's.
    let body = spec.rigid_body("", Side::Below).map_err(text)?;
    let shape = spec.parse_shape("").map_err(text)?;
    let desc = spec.shape_description();
    for (key, given) in [
        ("velocity", spec.velocity.is_some()),
        ("omega", spec.omega.is_some()),
    ] {
        if given {
            return Err(format!(
                "{key}: the explorer gives the motion as speed, alpha_deg and spin_ratio"
            ));
        }
    }
    let v0 = need("speed", spec.speed)?;
    let alpha = need("alpha_deg", spec.alpha)?;
    let gamma = need("spin_ratio", spec.spin_ratio)?;
    if v0 <= 0.0 {
        return Err(format!("speed: must be > 0, got {v0}"));
    }
    if !(alpha > -90.0 && alpha < 90.0) {
        return Err(format!(
            "alpha_deg: must be in (-90, 90) for the body to approach the surface, got {alpha}"
        ));
    }
    let rho = body.contact().norm();
    if rho <= 0.0 {
        return Err("contact: the contact point must not be the centre of mass".into());
    }
    let state = bodies::spin_state(v0, alpha.to_radians(), gamma, rho).map_err(text)?;
    Ok(BodyCase {
        impact: BodyImpact::on_fixed_surface(body, state),
        spec: spec.clone(),
        shape,
        speed: v0,
        alpha_deg: alpha,
        spin_ratio: gamma,
        length_scale: rho,
        description: format!("{desc}, v0 = {v0}, α = {alpha}°, γ = {gamma}"),
    })
}

fn mechanism_case(spec: &MechanismSpec) -> Result<MechanismCase, String> {
    if spec.name != "double-pendulum" {
        return Err(format!(
            "mechanism: unknown mechanism `{}` (known: double-pendulum)",
            spec.name
        ));
    }
    for (i, x) in spec.angles_deg.iter().enumerate() {
        finite(&format!("angles_deg[{i}]"), *x)?;
    }
    for (i, x) in spec.rates.iter().enumerate() {
        finite(&format!("rates[{i}]"), *x)?;
    }
    let [m1, m2] = spec.masses;
    let [l1, l2] = spec.lengths;
    let mut pendulum = DoublePendulum::new(m1, m2, l1, l2, STANDARD_GRAVITY, 0.0).map_err(text)?;
    let q = spec.angles_deg.map(f64::to_radians);
    pendulum.put_floor_at_tip(q);
    let [a1, a2] = spec.angles_deg;
    let [u1, u2] = spec.rates;
    Ok(MechanismCase {
        pendulum,
        q,
        u: spec.rates,
        spec: spec.clone(),
        description: format!(
            "double pendulum m = ({m1}, {m2}), l = ({l1}, {l2}), θ = ({a1}°, {a2}°), θ̇ = ({u1}, {u2}) rad/s"
        ),
    })
}

impl BodyCase {
    /// The contact-space problem.
    ///
    /// # Errors
    /// Friction or restitution out of range.
    pub fn problem(&self, friction: f64, restitution: f64) -> Result<ContactProblem, String> {
        self.impact.problem(friction, restitution).map_err(text)
    }

    /// `T0`: the translational kinetic energy before the impact (`½ m v0²`, as paper A
    /// normalises; the CLI's `t0`).
    pub fn t0(&self) -> f64 {
        let before = self.impact.energy_before();
        if before.translational > 0.0 {
            before.translational
        } else {
            before.total()
        }
    }

    /// The body's state before the impact.
    pub fn state(&self) -> BodyState {
        self.impact.body.1
    }
}

impl MechanismCase {
    /// The mechanism's impact at its state.
    ///
    /// # Errors
    /// A singular configuration.
    pub fn impact(&self) -> Result<MechanismImpact<'_, DoublePendulum>, String> {
        MechanismImpact::new(&self.pendulum, &self.q, &self.u, 0).map_err(text)
    }
}
