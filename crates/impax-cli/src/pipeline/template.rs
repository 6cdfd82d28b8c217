//! A scenario as numbers, with its fields set by name: what `impax sweep` and `impax map`
//! vary from point to point.
//!
//! The scenario file (or the seed's) is validated once, as `impax compare` would; then every
//! point sets a few numeric fields and rebuilds the contact problem without allocation.
//!
//! Field names (kebab case; `_` is accepted for `-`; `other.` prefixes the second body). The
//! shape's numbers are the core's ([`impax::scenario::ShapeScalar`], named there in snake
//! case); today:
//!
//! | field | applies to | domain |
//! |---|---|---|
//! | `friction`, `restitution` | every scenario | `μ ≥ 0`, `e ∈ [0, 1]` |
//! | `mass` | every body | `> 0` |
//! | `radius` | sphere, disc | `> 0` |
//! | `length`, `angle-deg` | rod | `> 0`; `(0, 180)` degrees |
//! | `semi-axis-a`, `semi-axis-b`, `angle-deg` | ellipse | `> 0`; degrees |
//! | `inertia`, `contact-t`, `contact-n` | rigid | `> 0`; any |
//! | `half-extent-a`, `half-extent-b`, `angle-deg` | box | `> 0`; degrees |
//! | `speed`, `alpha-deg`, `spin-ratio` | round bodies given by v0, α, γ | `> 0`; `[−90, 90]` degrees; any |
//! | `vx`, `vy`, `omega` | bodies given by their velocity | any |

use crate::input::{CliError, CliResult};
use crate::sources::scenario::{build_body, parse_file, parse_laws, BodySpec};
use crate::sources::Source;
use impax::planar::bodies::{self, BodyImpact, BodyState, RigidBody, Side};
use impax::planar::{ContactProblem, InverseInertia};
use impax::scenario::{Shape, ShapeScalar};
use impax::LawId;
use std::borrow::Cow;
use std::path::Path;

/// One numeric parameter of a body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    Mass,
    /// A number of the body's shape (`radius`, `semi-axis-a`, …: the core's table of shapes,
    /// [`ShapeScalar`]).
    Shape(ShapeScalar),
    Speed,
    AlphaDeg,
    SpinRatio,
    Vx,
    Vy,
    Omega,
}

impl Param {
    /// Every parameter, in the order field lists show them.
    fn all() -> impl Iterator<Item = Param> {
        std::iter::once(Param::Mass)
            .chain(ShapeScalar::ALL.into_iter().map(Param::Shape))
            .chain([
                Param::Speed,
                Param::AlphaDeg,
                Param::SpinRatio,
                Param::Vx,
                Param::Vy,
                Param::Omega,
            ])
    }

    /// The name in kebab case, e.g. `semi-axis-a`.
    fn name(self) -> Cow<'static, str> {
        match self {
            Param::Mass => "mass".into(),
            Param::Shape(s) => s.name().replace('_', "-").into(),
            Param::Speed => "speed".into(),
            Param::AlphaDeg => "alpha-deg".into(),
            Param::SpinRatio => "spin-ratio".into(),
            Param::Vx => "vx".into(),
            Param::Vy => "vy".into(),
            Param::Omega => "omega".into(),
        }
    }

    /// Axis label with units.
    fn label(self) -> &'static str {
        match self {
            Param::Mass => "mass m",
            Param::Shape(s) => s.label(),
            Param::Speed => "approach speed v0",
            Param::AlphaDeg => "approach angle α from the normal (deg)",
            Param::SpinRatio => "spin ratio γ = ω0 r / v0 (–)",
            Param::Vx => "velocity v_x",
            Param::Vy => "velocity v_y",
            Param::Omega => "angular velocity ω (rad per time unit)",
        }
    }

    /// The allowed closed interval of values (open ends are checked by the body builders).
    fn domain(self) -> (f64, f64, &'static str) {
        let positive = (f64::MIN_POSITIVE, f64::INFINITY, "must be > 0");
        match self {
            Param::Mass | Param::Speed => positive,
            Param::Shape(s) if s.positive() => positive,
            Param::AlphaDeg => (-90.0, 90.0, "must be in [-90, 90] degrees"),
            _ => (f64::NEG_INFINITY, f64::INFINITY, ""),
        }
    }
}

/// A scenario field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    Friction,
    Restitution,
    /// A parameter of the striking body A.
    Body(Param),
    /// A parameter of the struck body B.
    Other(Param),
}

impl Field {
    /// The canonical name, e.g. `alpha-deg`, `other.mass`.
    pub fn name(self) -> String {
        match self {
            Field::Friction => "friction".into(),
            Field::Restitution => "restitution".into(),
            Field::Body(p) => p.name().into_owned(),
            Field::Other(p) => format!("other.{}", p.name()),
        }
    }

    /// An axis label with units.
    pub fn label(self) -> String {
        match self {
            Field::Friction => "friction coefficient μ (–)".into(),
            Field::Restitution => "coefficient of restitution e (–)".into(),
            Field::Body(p) => p.label().into(),
            Field::Other(p) => format!("body B: {}", p.label()),
        }
    }

    /// Check that every value of `[lo, hi]` is in the field's domain.
    pub fn check_range(self, lo: f64, hi: f64) -> Result<(), String> {
        let (min, max, why) = match self {
            Field::Friction => (0.0, f64::INFINITY, "the friction coefficient must be ≥ 0"),
            Field::Restitution => (0.0, 1.0, "the coefficient of restitution must be in [0, 1]"),
            Field::Body(p) | Field::Other(p) => p.domain(),
        };
        if lo < min || hi > max {
            Err(format!("{}: {why}", self.name()))
        } else {
            Ok(())
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Motion {
    Seed {
        speed: f64,
        alpha_deg: f64,
        spin_ratio: f64,
    },
    Direct {
        vx: f64,
        vy: f64,
        omega: f64,
    },
}

impl Motion {
    /// The field that sets the body's velocity, for errors.
    fn field(&self) -> &'static str {
        match self {
            Motion::Seed { .. } => "speed",
            Motion::Direct { .. } => "velocity",
        }
    }
}

/// A body as its description (the core's [`BodySpec`], its shape parsed) and its motion as
/// numbers.
#[derive(Debug, Clone, PartialEq)]
struct BodyParams {
    spec: BodySpec,
    shape: Shape,
    side: Side,
    motion: Motion,
}

impl BodyParams {
    /// From a spec already validated by [`build_body`].
    fn of(spec: &BodySpec, side: Side) -> CliResult<Self> {
        let shape = spec.parse_shape("")?;
        let seed = spec.speed.is_some() || spec.alpha.is_some() || spec.spin_ratio.is_some();
        let motion = if seed {
            Motion::Seed {
                speed: spec.speed.unwrap_or(1.0),
                alpha_deg: spec.alpha.unwrap_or(0.0),
                spin_ratio: spec.spin_ratio.unwrap_or(0.0),
            }
        } else {
            let [vx, vy] = spec.velocity.unwrap_or([0.0, 0.0]);
            Motion::Direct {
                vx,
                vy,
                omega: spec.omega.unwrap_or(0.0),
            }
        };
        Ok(Self {
            spec: spec.clone(),
            shape,
            side,
            motion,
        })
    }

    /// Whether the parameter describes this body (shape and kind of motion).
    fn has(&self, p: Param) -> bool {
        let seed = matches!(self.motion, Motion::Seed { .. });
        match p {
            Param::Mass => true,
            Param::Shape(s) => self.shape.has_scalar(s),
            Param::Speed | Param::AlphaDeg | Param::SpinRatio => seed,
            Param::Vx | Param::Vy | Param::Omega => !seed,
        }
    }

    /// Set a parameter ([`BodyParams::has`] is checked when a field is resolved by name).
    fn set(&mut self, p: Param, value: f64) {
        match (p, &mut self.motion) {
            (Param::Mass, _) => self.spec.mass = value,
            (Param::Shape(s), _) => self.spec.set_scalar(s, value),
            (Param::Speed, Motion::Seed { speed, .. }) => *speed = value,
            (Param::AlphaDeg, Motion::Seed { alpha_deg, .. }) => *alpha_deg = value,
            (Param::SpinRatio, Motion::Seed { spin_ratio, .. }) => *spin_ratio = value,
            (Param::Vx, Motion::Direct { vx, .. }) => *vx = value,
            (Param::Vy, Motion::Direct { vy, .. }) => *vy = value,
            (Param::Omega, Motion::Direct { omega, .. }) => *omega = value,
            _ => {}
        }
    }

    /// Whether setting the parameter changes the body (not only its state).
    fn shapes_body(p: Param) -> bool {
        matches!(p, Param::Mass | Param::Shape(_))
    }

    /// The body (the core's builder; errors name the field without a section, no
    /// allocation unless it fails).
    fn body(&self) -> impax::Result<RigidBody> {
        self.spec.rigid_body("", self.side)
    }

    /// The state before the impact: for v0, α, γ exactly [`bodies::spin_state`] (paper A
    /// eq. 1), inlined (the radius was validated with the body).
    /// `trig` remembers `(α in degrees, sin α, cos α)` of the last call: a grid whose α
    /// varies slowly computes each sine and cosine once.
    #[inline(always)]
    fn state(&self, trig: &mut (f64, f64, f64)) -> impax::Result<BodyState> {
        match self.motion {
            Motion::Seed {
                speed,
                alpha_deg,
                spin_ratio,
            } => {
                if !(speed > 0.0 && speed.is_finite()) {
                    return Err(impax::Error::OutOfRange {
                        field: "speed".into(),
                        value: speed,
                        reason: "must be > 0".into(),
                    });
                }
                if !alpha_deg.is_finite() || !spin_ratio.is_finite() {
                    // The library names the field.
                    let alpha = alpha_deg.to_radians();
                    return bodies::spin_state(speed, alpha, spin_ratio, self.radius());
                }
                if trig.0.to_bits() != alpha_deg.to_bits() {
                    let alpha = alpha_deg.to_radians();
                    *trig = (alpha_deg, alpha.sin(), alpha.cos());
                }
                Ok(BodyState::new(
                    speed * trig.1,
                    -speed * trig.2,
                    spin_ratio * speed / self.radius(),
                ))
            }
            Motion::Direct { vx, vy, omega } => Ok(BodyState::new(vx, vy, omega)),
        }
    }

    /// The radius of a round body given by v0, α, γ (validated with the body).
    #[inline(always)]
    fn radius(&self) -> f64 {
        self.spec.radius.unwrap_or(f64::NAN)
    }
}

/// The bodies and `W` of the current body parameters (rebuilt when one of them is set).
#[derive(Debug, Clone, Copy)]
struct Built {
    body: RigidBody,
    other: Option<RigidBody>,
    w: InverseInertia,
}

/// A scenario whose numeric fields can be set by name.
#[derive(Debug, Clone)]
pub struct Template {
    friction: f64,
    restitution: f64,
    body: BodyParams,
    other: Option<BodyParams>,
    /// The laws of the file (`laws = [...]`), or every law.
    pub laws: Vec<LawId>,
    built: Option<Built>,
    /// Memo of the last `(α deg, sin α, cos α)` of body A and of body B.
    trig: [(f64, f64, f64); 2],
}

impl Template {
    /// Load and validate a scenario file (default: the seed's sphere).
    pub fn load(path: Option<&Path>) -> CliResult<Self> {
        let file = match path {
            None => None,
            Some(p) => {
                let unreadable =
                    |e| CliError::input(format!("{}: cannot read scenario file: {e}", p.display()));
                match Source::classify(&p.to_string_lossy(), &[], unreadable)? {
                    Source::Planar(file) => Some(file),
                    Source::Spatial(_) => {
                        return Err(CliError::input(format!(
                            "{}: sweeps and maps are planar: a `space = \"3d\"` scenario cannot be swept yet",
                            p.display()
                        )))
                    }
                    Source::Mechanism(_) | Source::BuiltInMechanism(_) | Source::Robot(_) => {
                        return Err(CliError::input(format!(
                            "{}: sweeps and maps take body scenarios: a mechanism cannot be swept yet",
                            p.display()
                        )))
                    }
                }
            }
        };
        let spec = parse_file(file.as_ref())?;
        build_body(&spec.body, "body", Side::Below)?;
        if let Some(o) = &spec.other {
            build_body(o, "other", Side::Above)?;
        }
        let laws = match &spec.laws {
            Some(ids) => {
                parse_laws(ids).map_err(|e| CliError::input(format!("laws: {}", e.message)))?
            }
            None => LawId::ALL.to_vec(),
        };
        Ok(Self {
            friction: spec.friction,
            restitution: spec.restitution,
            body: BodyParams::of(&spec.body, Side::Below)?,
            other: spec
                .other
                .as_ref()
                .map(|o| BodyParams::of(o, Side::Above))
                .transpose()?,
            laws,
            built: None,
            trig: [(f64::NAN, 0.0, 0.0); 2],
        })
    }

    /// Resolve a field name (`alpha-deg`, `alpha_deg`, `other.mass`, …) for this scenario.
    pub fn field(&self, name: &str) -> Result<Field, String> {
        let canon = name.trim().replace('_', "-");
        match canon.as_str() {
            "friction" => return Ok(Field::Friction),
            "restitution" => return Ok(Field::Restitution),
            _ => {}
        }
        let (target, pname) = match canon.strip_prefix("other.") {
            Some(rest) => (true, rest),
            None => (false, canon.as_str()),
        };
        let known = || {
            let mut names = vec![Cow::from("friction"), "restitution".into()];
            names.extend(Param::all().map(Param::name));
            names.join(", ")
        };
        let param = Param::all().find(|p| p.name() == pname).ok_or_else(|| {
            format!(
                "unknown field `{name}` (known: {}; prefix `other.` for body B)",
                known()
            )
        })?;
        let body = if target {
            self.other
                .as_ref()
                .ok_or_else(|| format!("field `{name}`: the scenario has no [other] body"))?
        } else {
            &self.body
        };
        if !body.has(param) {
            let what = match param {
                Param::Speed | Param::AlphaDeg | Param::SpinRatio => {
                    "the scenario gives the body's velocity/omega, not speed/alpha_deg/spin_ratio"
                        .to_string()
                }
                Param::Vx | Param::Vy | Param::Omega => {
                    "the scenario gives the body's speed/alpha_deg/spin_ratio, not velocity/omega"
                        .to_string()
                }
                _ => format!("not a parameter of shape `{}`", body.shape),
            };
            return Err(format!("field `{name}`: {what}"));
        }
        Ok(if target {
            Field::Other(param)
        } else {
            Field::Body(param)
        })
    }

    /// Set a field (resolved by [`Template::field`] for this scenario).
    #[inline]
    pub fn set(&mut self, field: Field, value: f64) {
        match field {
            Field::Friction => self.friction = value,
            Field::Restitution => self.restitution = value,
            Field::Body(p) => {
                self.body.set(p, value);
                if BodyParams::shapes_body(p) {
                    self.built = None;
                }
            }
            Field::Other(p) => {
                if let Some(o) = self.other.as_mut() {
                    o.set(p, value);
                }
                if BodyParams::shapes_body(p) {
                    self.built = None;
                }
            }
        }
    }

    /// Build the current point and append its contact problem, its energy scale `T0` (the
    /// translational kinetic energy before, else the total, as `impax compare`) and, if
    /// asked, the impact to the caller's buffers (nothing is appended on error). No
    /// allocation unless the point is invalid; the bodies and `W` are kept until a body
    /// parameter is set. The result is bit for bit what `impax compare` builds.
    #[inline]
    pub fn point_into(
        &mut self,
        problems: &mut Vec<ContactProblem>,
        t0s: &mut Vec<f64>,
        impacts: Option<&mut Vec<BodyImpact>>,
    ) -> impax::Result<()> {
        if self.built.is_none() {
            let body = self.body.body()?;
            let other = self.other.as_ref().map(BodyParams::body).transpose()?;
            let mut w = body.inverse_inertia();
            if let Some(o) = &other {
                w += o.inverse_inertia();
            }
            let w = InverseInertia::new(w)?;
            self.built = Some(Built { body, other, w });
        }
        let Some(built) = self.built.as_ref() else {
            unreachable!("built above")
        };
        let state = self.body.state(&mut self.trig[0])?;
        if let (None, None) = (&self.other, &impacts) {
            // One body and no impact kept: the same numbers as `BodyImpact`'s
            // `contact_velocity` and `energy_before`, without building it.
            let body = &built.body;
            let problem = ContactProblem::with_inertia(
                &built.w,
                body.contact_velocity(&state),
                self.friction,
                self.restitution,
            )?;
            let t0 = crate::sources::scenario::reference_energy(
                &impax::planar::bodies::EnergyParts {
                    translational: body.translational_energy(&state),
                    rotational: body.rotational_energy(&state),
                },
                self.body.motion.field(),
            )?;
            problems.push(problem);
            t0s.push(t0);
            return Ok(());
        }
        let impact = match (&self.other, &built.other) {
            (Some(o), Some(ob)) => {
                BodyImpact::between(built.body, state, *ob, o.state(&mut self.trig[1])?)
            }
            _ => BodyImpact::on_fixed_surface(built.body, state),
        };
        let problem = ContactProblem::with_inertia(
            &built.w,
            impact.contact_velocity(),
            self.friction,
            self.restitution,
        )?;
        let t0 = crate::sources::scenario::reference_energy(
            &impact.energy_before(),
            self.body.motion.field(),
        )?;
        problems.push(problem);
        t0s.push(t0);
        if let Some(v) = impacts {
            v.push(impact);
        }
        Ok(())
    }

    /// Whether this is paper A's case: one sphere given by v0, α, γ against a fixed plane
    /// (so that the eq. 13 threshold applies).
    pub fn is_seed_sphere(&self) -> bool {
        self.other.is_none()
            && self.body.shape == Shape::Sphere
            && matches!(self.body.motion, Motion::Seed { .. })
    }

    /// Friction and restitution.
    pub fn coefficients(&self) -> (f64, f64) {
        (self.friction, self.restitution)
    }
}
