//! Scenarios for `impax compare`: the seed's sphere, TOML files, and flag overrides.
//!
//! File format (all lengths, masses and speeds in any consistent units; angles in degrees):
//!
//! ```toml
//! friction = 0.4          # μ
//! restitution = 0.7       # e
//! laws = ["whittaker", "energetic"]   # optional; default: every law
//!
//! [body]                  # the striking body A (contact at its lowest point)
//! shape = "sphere"        # sphere | disc | rod | ellipse | rigid
//! mass = 1.0
//! radius = 1.0            # sphere, disc
//! # length = 2.0; angle_deg = 50        (rod: angle from the surface)
//! # semi_axes = [2.0, 1.0]; angle_deg = 20   (ellipse: its a axis from the surface)
//! # inertia = 0.5; contact = [0.3, -1.0]     (rigid: contact point from the centre, (t, n))
//! speed = 1.0             # round bodies: v0, α, γ as in paper A …
//! alpha_deg = 30.0
//! spin_ratio = 0.0
//! # velocity = [0.5, -0.866]; omega = 0.0   # … or the state directly (any shape)
//!
//! [other]                 # optional: a second free body B, struck at its highest point
//! shape = "disc"
//! mass = 2.0
//! radius = 1.0
//! velocity = [0.0, 0.0]
//! omega = 0.0
//! ```

use crate::cli::CompareArgs;
use crate::fmt::Plain;
use crate::input::{finite_flag, CliError, CliResult};
use impax::bodies::{self, BodyState2, PlanarImpact, RigidBody2, Side};
use impax::error::Num;
use impax::math::Vec2;
use impax::LawId;
use serde::Deserialize;
use std::path::Path;

/// The seed's case (paper A): sphere, m = r = v0 = 1, α = 30°, e = 0.7, μ = 0.4, γ = 0.
pub const SEED_TOML: &str = r#"friction = 0.4
restitution = 0.7

[body]
shape = "sphere"
mass = 1.0
radius = 1.0
speed = 1.0
alpha_deg = 30.0
spin_ratio = 0.0
"#;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileSpec {
    pub(crate) friction: f64,
    pub(crate) restitution: f64,
    pub(crate) laws: Option<Vec<String>>,
    pub(crate) body: BodySpec,
    pub(crate) other: Option<BodySpec>,
}

#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(crate) struct BodySpec {
    pub(crate) shape: String,
    pub(crate) mass: f64,
    pub(crate) radius: Option<f64>,
    pub(crate) length: Option<f64>,
    pub(crate) semi_axes: Option<[f64; 2]>,
    pub(crate) inertia: Option<f64>,
    pub(crate) contact: Option<[f64; 2]>,
    pub(crate) angle_deg: Option<f64>,
    pub(crate) speed: Option<f64>,
    pub(crate) alpha_deg: Option<f64>,
    pub(crate) spin_ratio: Option<f64>,
    pub(crate) velocity: Option<[f64; 2]>,
    pub(crate) omega: Option<f64>,
}

/// How results are normalised in the table.
#[derive(Debug, Clone, Copy)]
pub struct Scale {
    /// Velocity scale `v0` (the approach speed of a round body; else 1).
    pub speed: f64,
    /// Length scale `r` (the radius of a round body; else 1).
    pub length: f64,
    /// Whether the table shows normalised columns (`v/v0`, `ω r/v0`).
    pub normalised: bool,
}

/// A resolved scenario.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub impact: PlanarImpact,
    pub friction: f64,
    pub restitution: f64,
    pub laws: Vec<LawId>,
    pub description: String,
    pub scale: Scale,
    /// `T0`: the translational kinetic energy before the impact (= ½ m v0² for the seed);
    /// the total kinetic energy if that is zero.
    pub t0: f64,
}

fn toml_error(source: &str, text: &str, err: &toml::de::Error) -> CliError {
    let msg = err.message().replace('\n', " ");
    match err.span() {
        Some(span) => {
            let before = &text[..span.start.min(text.len())];
            let line = before.matches('\n').count() + 1;
            let col = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            CliError::input(format!("{source}:{line}:{col}: {msg}"))
        }
        None => CliError::input(format!("{source}: {msg}")),
    }
}

fn need(field: &str, shape: &str, x: Option<f64>) -> CliResult<f64> {
    x.ok_or_else(|| CliError::input(format!("{field}: required for shape `{shape}`")))
}

fn reject(field: &str, shape: &str, present: bool) -> CliResult<()> {
    if present {
        Err(CliError::input(format!(
            "{field}: not a parameter of shape `{shape}`"
        )))
    } else {
        Ok(())
    }
}

fn finite_field(field: &str, x: f64) -> CliResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(CliError::input(format!(
            "{field}: must be a finite number, got {}",
            Plain(x)
        )))
    }
}

/// Build body, state and scale from a spec. `prefix` is `body` or `other`.
pub(crate) fn build_body(
    spec: &BodySpec,
    prefix: &str,
    side: Side,
) -> CliResult<(RigidBody2, BodyState2, Scale, String)> {
    let f = |name: &str| format!("{prefix}.{name}");
    let shape = spec.shape.as_str();
    let m = finite_field(&f("mass"), spec.mass)?;
    let name_err = |e: impax::Error| CliError::input(format!("{prefix}.{e}"));
    let (body, round_radius, desc) = match shape {
        "sphere" | "disc" => {
            let r = need(&f("radius"), shape, spec.radius)?;
            reject(&f("length"), shape, spec.length.is_some())?;
            reject(&f("semi_axes"), shape, spec.semi_axes.is_some())?;
            reject(&f("inertia"), shape, spec.inertia.is_some())?;
            reject(&f("contact"), shape, spec.contact.is_some())?;
            reject(&f("angle_deg"), shape, spec.angle_deg.is_some())?;
            let b = if shape == "sphere" {
                bodies::sphere(m, r, side)
            } else {
                bodies::disc(m, r, side)
            }
            .map_err(name_err)?;
            (b, Some(r), format!("{shape} m = {m}, r = {r}"))
        }
        "rod" => {
            let l = need(&f("length"), shape, spec.length)?;
            let a = need(&f("angle_deg"), shape, spec.angle_deg)?;
            reject(&f("radius"), shape, spec.radius.is_some())?;
            reject(&f("semi_axes"), shape, spec.semi_axes.is_some())?;
            reject(&f("inertia"), shape, spec.inertia.is_some())?;
            reject(&f("contact"), shape, spec.contact.is_some())?;
            let a = finite_field(&f("angle_deg"), a)?;
            let b = bodies::rod(m, l, a.to_radians(), side).map_err(name_err)?;
            (
                b,
                None,
                format!("rod m = {m}, L = {l}, at {a}° to the surface"),
            )
        }
        "ellipse" => {
            let [sa, sb] = spec.semi_axes.ok_or_else(|| {
                CliError::input(format!("{}: required for shape `ellipse`", f("semi_axes")))
            })?;
            let a = spec.angle_deg.unwrap_or(0.0);
            reject(&f("radius"), shape, spec.radius.is_some())?;
            reject(&f("length"), shape, spec.length.is_some())?;
            reject(&f("inertia"), shape, spec.inertia.is_some())?;
            reject(&f("contact"), shape, spec.contact.is_some())?;
            let a = finite_field(&f("angle_deg"), a)?;
            let b = bodies::ellipse(m, sa, sb, a.to_radians(), side).map_err(name_err)?;
            (
                b,
                None,
                format!("ellipse m = {m}, a = {sa}, b = {sb}, at {a}°"),
            )
        }
        "rigid" => {
            let i = need(&f("inertia"), shape, spec.inertia)?;
            let [rt, rn] = spec.contact.ok_or_else(|| {
                CliError::input(format!("{}: required for shape `rigid`", f("contact")))
            })?;
            reject(&f("radius"), shape, spec.radius.is_some())?;
            reject(&f("length"), shape, spec.length.is_some())?;
            reject(&f("semi_axes"), shape, spec.semi_axes.is_some())?;
            reject(&f("angle_deg"), shape, spec.angle_deg.is_some())?;
            let b = RigidBody2::new(m, i, Vec2::new(rt, rn)).map_err(name_err)?;
            (
                b,
                None,
                format!("rigid body m = {m}, I = {i}, contact at ({rt}, {rn})"),
            )
        }
        other => {
            return Err(CliError::input(format!(
                "{}: unknown shape `{other}` (known: sphere, disc, rod, ellipse, rigid)",
                f("shape")
            )))
        }
    };
    let seed_motion = spec.speed.is_some() || spec.alpha_deg.is_some() || spec.spin_ratio.is_some();
    let direct_motion = spec.velocity.is_some() || spec.omega.is_some();
    if seed_motion && direct_motion {
        return Err(CliError::input(format!(
            "{prefix}: give either speed/alpha_deg/spin_ratio or velocity/omega, not both"
        )));
    }
    if seed_motion {
        let r = round_radius.ok_or_else(|| {
            CliError::input(format!(
                "{}: speed/alpha_deg/spin_ratio describe round bodies; give velocity and omega for shape `{shape}`",
                f("speed")
            ))
        })?;
        let v0 = finite_field(&f("speed"), spec.speed.unwrap_or(1.0))?;
        let alpha = finite_field(&f("alpha_deg"), spec.alpha_deg.unwrap_or(0.0))?;
        let gamma = finite_field(&f("spin_ratio"), spec.spin_ratio.unwrap_or(0.0))?;
        if v0 <= 0.0 {
            return Err(CliError::input(format!(
                "{}: must be > 0, got {}",
                f("speed"),
                Plain(v0)
            )));
        }
        if !(alpha > -90.0 && alpha < 90.0) {
            return Err(CliError::input(format!(
                "{}: must be in (-90, 90) for the body to approach the surface, got {}",
                f("alpha_deg"),
                Plain(alpha)
            )));
        }
        let state = bodies::spin_state(v0, alpha.to_radians(), gamma, r).map_err(name_err)?;
        let desc = format!("{desc}, v0 = {v0}, α = {alpha}°, γ = {gamma}");
        Ok((
            body,
            state,
            Scale {
                speed: v0,
                length: r,
                normalised: true,
            },
            desc,
        ))
    } else {
        let [vx, vy] = spec.velocity.unwrap_or([0.0, 0.0]);
        let vx = finite_field(&f("velocity"), vx)?;
        let vy = finite_field(&f("velocity"), vy)?;
        let omega = finite_field(&f("omega"), spec.omega.unwrap_or(0.0))?;
        let desc = format!("{desc}, v = ({vx}, {vy}), ω = {omega}");
        Ok((
            body,
            BodyState2::new(vx, vy, omega),
            Scale {
                speed: 1.0,
                length: 1.0,
                normalised: false,
            },
            desc,
        ))
    }
}

/// Parse law ids (`smith-centre` is allowed: compare has bodies).
pub fn parse_laws(ids: &[String]) -> CliResult<Vec<LawId>> {
    let mut laws = Vec::new();
    for id in ids {
        let law: LawId = id.trim().parse()?;
        if !laws.contains(&law) {
            laws.push(law);
        }
    }
    Ok(laws)
}

/// Read and parse a scenario file (or the seed's scenario).
pub(crate) fn parse_file(path: Option<&Path>) -> CliResult<FileSpec> {
    let (source, text) = match path {
        Some(path) => (path.display().to_string(), read(path)?),
        None => ("seed scenario".to_string(), SEED_TOML.to_string()),
    };
    toml::from_str(&text).map_err(|e| toml_error(&source, &text, &e))
}

/// Load the scenario of `impax compare`: the file (or the seed), then the flags.
pub fn load(args: &CompareArgs) -> CliResult<Scenario> {
    let mut spec = parse_file(args.scenario.as_deref())?;
    // Flag overrides.
    if let Some(x) = args.friction {
        spec.friction = finite_flag("friction", x)?;
    }
    if let Some(x) = args.restitution {
        spec.restitution = finite_flag("restitution", x)?;
    }
    if let Some(x) = args.mass {
        spec.body.mass = finite_flag("mass", x)?;
    }
    let round = matches!(spec.body.shape.as_str(), "sphere" | "disc");
    for (flag, value) in [
        ("radius", args.radius),
        ("speed", args.speed),
        ("alpha-deg", args.alpha_deg),
        ("spin-ratio", args.spin_ratio),
    ] {
        if let Some(x) = value {
            finite_flag(flag, x)?;
            if !round {
                return Err(CliError::input(format!(
                    "--{flag}: applies to sphere and disc scenarios, not to shape `{}`",
                    spec.body.shape
                )));
            }
        }
    }
    if args.radius.is_some() {
        spec.body.radius = args.radius;
    }
    let motion_flag = args.speed.is_some() || args.alpha_deg.is_some() || args.spin_ratio.is_some();
    if motion_flag {
        if spec.body.velocity.is_some() || spec.body.omega.is_some() {
            return Err(CliError::input(
                "--speed/--alpha-deg/--spin-ratio: the scenario gives velocity/omega directly; edit the file instead",
            ));
        }
        spec.body.speed = args.speed.or(spec.body.speed);
        spec.body.alpha_deg = args.alpha_deg.or(spec.body.alpha_deg);
        spec.body.spin_ratio = args.spin_ratio.or(spec.body.spin_ratio);
    }
    let laws = if !args.law.is_empty() {
        parse_laws(&args.law)?
    } else if let Some(ids) = &spec.laws {
        parse_laws(ids).map_err(|e| CliError::input(format!("laws: {}", e.message)))?
    } else {
        LawId::ALL.to_vec()
    };
    let (body, state, scale, mut description) = build_body(&spec.body, "body", Side::Below)?;
    body_energies(&body, &state, "body", &spec.body)?;
    let impact = match &spec.other {
        None => PlanarImpact::on_fixed_surface(body, state),
        Some(o) => {
            let (ob, os, _, od) = build_body(o, "other", Side::Above)?;
            body_energies(&ob, &os, "other", o)?;
            description = format!("{description} striking {od}");
            PlanarImpact::between(body, state, ob, os)
        }
    };
    let motion = if spec.body.velocity.is_some() || spec.body.omega.is_some() {
        "velocity"
    } else {
        "speed"
    };
    let t0 = reference_energy(&impact.energy_before(), motion)?;
    Ok(Scenario {
        impact,
        friction: spec.friction,
        restitution: spec.restitution,
        laws,
        description,
        scale,
        t0,
    })
}

fn read(path: &Path) -> CliResult<String> {
    std::fs::read_to_string(path).map_err(|e| {
        CliError::input(format!(
            "{}: cannot read scenario file: {e}",
            path.display()
        ))
    })
}

/// The energy that normalises `ΔT` in tables, sweeps and maps: the translational kinetic
/// energy before the impact (`½ m v0²` for the seed), or the total if that is zero. It must
/// lie within `[1e-290, 1e300]` so that `ΔT/T0` is a number to full precision (at
/// `v0 = 1e-300` it underflows to 0 and the ratio would be NaN): an error names `field`
/// (the flag or key that sets the velocity) otherwise.
pub fn reference_energy(before: &impax::bodies::EnergyParts, field: &str) -> impax::Result<f64> {
    let t0 = if before.translational > 0.0 {
        before.translational
    } else {
        before.total()
    };
    if (1e-290..=1e300).contains(&t0) {
        Ok(t0)
    } else {
        Err(impax::Error::Invalid {
            field: field.into(),
            reason: format!(
                "the kinetic energy before the impact, T0 = {}, must lie within [1e-290, 1e300] to normalise ΔT (ΔT/T0 is not representable otherwise); change the units",
                impax::error::Num(t0)
            ),
        })
    }
}

/// Each part of a body's kinetic energy is a number with room to spare (a `spin_ratio` or an
/// `omega` of 1e308 gave a null `energy_before`): an error names the key that sets it.
fn body_energies(
    body: &impax::bodies::RigidBody2,
    state: &impax::bodies::BodyState2,
    prefix: &str,
    spec: &BodySpec,
) -> CliResult<()> {
    let direct = spec.velocity.is_some() || spec.omega.is_some();
    let parts = [
        (
            if direct { "velocity" } else { "speed" },
            body.translational_energy(state),
        ),
        (
            if direct { "omega" } else { "spin_ratio" },
            body.rotational_energy(state),
        ),
    ];
    for (key, energy) in parts {
        if !(energy.is_finite() && energy <= 1e300) {
            return Err(CliError::input(format!(
                "{prefix}.{key}: the kinetic energy it gives, {}, is not representable with room to spare (it must be below 1e300)",
                Num(energy)
            )));
        }
    }
    Ok(())
}
