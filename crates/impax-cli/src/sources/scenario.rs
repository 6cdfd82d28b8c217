//! Scenarios for `impax compare`: the seed's sphere, TOML files (read by
//! [`impax::scenario::PlanarScenario`], whose docs give the format), and flag overrides.

use crate::cli::CompareArgs;
use crate::input::{finite_flag, CliError, CliResult};
use impax::planar::bodies::{BodyImpact, BodyState, RigidBody, Side};
use impax::LawId;

pub use impax::scenario::{BodySpec, Scale};
use impax::scenario::{PlanarScenario, SEED_TOML};

/// A resolved scenario.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub impact: BodyImpact,
    pub friction: f64,
    pub restitution: f64,
    pub laws: Vec<LawId>,
    pub description: String,
    pub scale: Scale,
    /// `T0`: the translational kinetic energy before the impact (= ½ m v0² for the seed);
    /// the total kinetic energy if that is zero.
    pub t0: f64,
}

/// Build body, state and scale from a spec. `prefix` is `body` or `other`.
pub(crate) fn build_body(
    spec: &BodySpec,
    prefix: &str,
    side: Side,
) -> CliResult<(RigidBody, BodyState, Scale, String)> {
    let b = spec.build(prefix, side)?;
    Ok((b.body, b.state, b.scale, b.description))
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
pub(crate) fn parse_file(file: Option<&super::File>) -> CliResult<PlanarScenario> {
    let (source, text) = match file {
        Some(f) => (f.name.as_str(), f.text.as_str()),
        None => ("seed scenario", SEED_TOML),
    };
    PlanarScenario::from_toml(text).map_err(|e| match e {
        impax::Error::Syntax { at: Some(_), .. } => CliError::input(format!("{source}:{e}")),
        e => CliError::input(format!("{source}: {e}")),
    })
}

/// Load the scenario of `impax compare`: the file (or the seed), then the flags.
pub fn load(args: &CompareArgs, file: Option<&super::File>) -> CliResult<Scenario> {
    let mut spec = parse_file(file)?;
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
    let round = impax::scenario::Shape::from_name(&spec.body.shape).is_some_and(|s| s.is_round());
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
        spec.body.alpha = args.alpha_deg.or(spec.body.alpha);
        spec.body.spin_ratio = args.spin_ratio.or(spec.body.spin_ratio);
    }
    let laws = if !args.law.is_empty() {
        parse_laws(&args.law)?
    } else if let Some(ids) = &spec.laws {
        parse_laws(ids).map_err(|e| CliError::input(format!("laws: {}", e.message)))?
    } else {
        LawId::ALL.to_vec()
    };
    let built = spec.build()?;
    let (impact, scale, description) = (built.impact, built.body.scale, built.description());
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

/// The energy that normalises `ΔT` in tables, sweeps and maps: the translational kinetic
/// energy before the impact (`½ m v0²` for the seed), or the total if that is zero. It must
/// lie within `[1e-290, 1e300]` so that `ΔT/T0` is a number to full precision (at
/// `v0 = 1e-300` it underflows to 0 and the ratio would be NaN): an error names `field`
/// (the flag or key that sets the velocity) otherwise.
pub fn reference_energy(
    before: &impax::planar::bodies::EnergyParts,
    field: &str,
) -> impax::Result<f64> {
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
