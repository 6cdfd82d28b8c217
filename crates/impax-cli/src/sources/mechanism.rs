//! Built-in mechanisms at the command line and in TOML: names, parameters, the state.
//!
//! ```toml
//! mechanism = "double-pendulum"   # double-pendulum | ring-pendulum | cart-pendulum | sphere | rod
//! friction = 0.5                  # compare only
//! restitution = 0.5               # compare only
//! laws = ["whittaker", "energetic"]
//! masses = [1.0, 1.0]             # per mechanism, see `impax compare --help`
//! lengths = [1.0, 1.0]
//! radius = 1.0
//! gravity = 9.81
//! angles_deg = [30.0, 0.0]
//! rates = [-1.0, 2.0]
//! position = [0.0]
//! ```

use crate::commands::simulate::MAX_ANGLE_DEG;
use crate::input::{CliError, CliResult};
use crate::output::fmt::Plain;
use impax::mechanism::builtin::{
    BuiltIn, CartPendulum, DoublePendulum, RingPendulum, Rod, Sphere, STANDARD_GRAVITY,
};
use serde::Deserialize;
use std::path::Path;

/// The parameters of a built-in mechanism, from flags or a TOML file (all optional; every
/// mechanism has defaults).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    pub mechanism: String,
    pub friction: Option<f64>,
    pub restitution: Option<f64>,
    pub laws: Option<Vec<String>>,
    pub masses: Option<Vec<f64>>,
    pub lengths: Option<Vec<f64>>,
    pub radius: Option<f64>,
    pub gravity: Option<f64>,
    pub angles_deg: Option<Vec<f64>>,
    pub rates: Option<Vec<f64>>,
    pub position: Option<Vec<f64>>,
}

/// A built-in mechanism and its state.
pub struct MechanismCase {
    pub mechanism: BuiltIn,
    /// Generalized coordinates (radians for angles).
    pub q: Vec<f64>,
    /// Generalized velocities (rad/s for angles).
    pub u: Vec<f64>,
    /// One line describing the case.
    pub description: String,
}

/// Whether a TOML text describes a mechanism (a top-level `mechanism` key).
pub fn is_mechanism_toml(text: &str) -> bool {
    text.parse::<toml::Table>()
        .map(|t| t.contains_key("mechanism"))
        .unwrap_or(false)
}

/// Read a mechanism TOML file.
pub fn parse_file(path: &Path, text: &str) -> CliResult<MechanismSpec> {
    toml::from_str(text).map_err(|e| {
        CliError::input(format!(
            "{}: {}",
            path.display(),
            e.message().replace('\n', " ")
        ))
    })
}

/// Flags override the file's values (a flag given replaces the whole list).
pub fn merge(spec: &mut MechanismSpec, flags: &MechanismSpec) {
    macro_rules! take {
        ($($f:ident),*) => { $( if flags.$f.is_some() { spec.$f = flags.$f.clone(); } )* };
    }
    take!(
        friction,
        restitution,
        laws,
        masses,
        lengths,
        radius,
        gravity,
        angles_deg,
        rates,
        position
    );
}

fn list(field: &str, v: &Option<Vec<f64>>, default: &[f64]) -> CliResult<Vec<f64>> {
    let v = v.clone().unwrap_or_else(|| default.to_vec());
    if v.len() != default.len() {
        return Err(CliError::input(format!(
            "{field}: needs {} value(s), got {}",
            default.len(),
            v.len()
        )));
    }
    for (i, x) in v.iter().enumerate() {
        if !x.is_finite() {
            return Err(CliError::input(format!(
                "{field}[{i}]: must be a finite number, got {}",
                Plain(*x)
            )));
        }
        if field == "angles_deg" && x.abs() > MAX_ANGLE_DEG {
            return Err(CliError::input(format!(
                "{field}[{i}]: must be between -{MAX_ANGLE_DEG} and {MAX_ANGLE_DEG} degrees, got {}",
                Plain(*x)
            )));
        }
    }
    Ok(v)
}

fn reject(name: &str, field: &str, present: bool) -> CliResult<()> {
    if present {
        Err(CliError::input(format!(
            "{field}: not a parameter of {name}"
        )))
    } else {
        Ok(())
    }
}

/// Build the mechanism and its state from a spec, with the defaults of each mechanism.
pub fn build(spec: &MechanismSpec) -> CliResult<MechanismCase> {
    let g = spec.gravity.unwrap_or(STANDARD_GRAVITY);
    let name = spec.mechanism.as_str();
    let deg = |v: Vec<f64>| v.into_iter().map(f64::to_radians).collect::<Vec<_>>();
    let case = match name {
        "double-pendulum" => {
            reject(name, "radius", spec.radius.is_some())?;
            reject(name, "position", spec.position.is_some())?;
            let m = list("masses", &spec.masses, &[1.0, 1.0])?;
            let l = list("lengths", &spec.lengths, &[1.0, 1.0])?;
            let a = list("angles_deg", &spec.angles_deg, &[30.0, 0.0])?;
            let u = list("rates", &spec.rates, &[-1.0, 2.0])?;
            let q = deg(a.clone());
            let mut dp = DoublePendulum::new(m[0], m[1], l[0], l[1], g, 0.0)?;
            dp.put_floor_at_tip([q[0], q[1]]);
            MechanismCase {
                description: format!(
                    "double pendulum (m = {}, {}; l = {}, {}; g = {g}): θ1 = {}°, θ2 = {}°, rates ({}, {}) rad/s; the tip of rod 2 strikes the floor",
                    m[0], m[1], l[0], l[1], a[0], a[1], u[0], u[1]
                ),
                mechanism: BuiltIn::DoublePendulum(dp),
                q,
                u,
            }
        }
        "ring-pendulum" | "cart-pendulum" => {
            let ring = name == "ring-pendulum";
            if !ring {
                reject(name, "radius", spec.radius.is_some())?;
            }
            let m = list("masses", &spec.masses, &[1.0, 1.0])?;
            let l = list("lengths", &spec.lengths, &[1.0])?;
            let x = list("position", &spec.position, &[0.0])?;
            let a = list("angles_deg", &spec.angles_deg, &[30.0])?;
            let u = list("rates", &spec.rates, &[0.5, 0.0])?;
            let q = vec![x[0], a[0].to_radians()];
            let (mechanism, what) = if ring {
                let r = spec.radius.unwrap_or(1.0);
                (
                    BuiltIn::RingPendulum(RingPendulum::new(m[0], r, m[1], l[0], g)?),
                    format!(
                        "ring-pendulum (ring M = {}, R = {r}; bob m = {}, l = {}; g = {g})",
                        m[0], m[1], l[0]
                    ),
                )
            } else {
                (
                    BuiltIn::CartPendulum(CartPendulum::new(m[0], m[1], l[0], g)?),
                    format!(
                        "cart-pendulum (cart M = {}; bob m = {}, l = {}; g = {g})",
                        m[0], m[1], l[0]
                    ),
                )
            };
            MechanismCase {
                description: format!(
                    "{what}: x = {}, φ = {}°, ẋ = {}, φ̇ = {} rad/s",
                    x[0], a[0], u[0], u[1]
                ),
                mechanism,
                q,
                u,
            }
        }
        "sphere" => {
            reject(name, "lengths", spec.lengths.is_some())?;
            let m = list("masses", &spec.masses, &[1.0])?;
            let r = spec.radius.unwrap_or(1.0);
            let p = list("position", &spec.position, &[0.0, r])?;
            let a = list("angles_deg", &spec.angles_deg, &[0.0])?;
            let (s, c) = 30f64.to_radians().sin_cos();
            let u = list("rates", &spec.rates, &[s, -c, 0.0])?;
            MechanismCase {
                description: format!(
                    "sphere (m = {}, r = {r}; g = {g}) at ({}, {}), θ = {}°, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                    m[0], p[0], p[1], a[0], u[0], u[1], u[2]
                ),
                mechanism: BuiltIn::Sphere(Sphere::new(m[0], r, g, 0.0)?),
                q: vec![p[0], p[1], a[0].to_radians()],
                u,
            }
        }
        "rod" => {
            reject(name, "radius", spec.radius.is_some())?;
            let m = list("masses", &spec.masses, &[1.0])?;
            let l = list("lengths", &spec.lengths, &[1.0])?;
            let a = list("angles_deg", &spec.angles_deg, &[50.0])?;
            let lift = 0.5 * l[0] * a[0].to_radians().sin().abs();
            let p = list("position", &spec.position, &[0.0, lift])?;
            let u = list("rates", &spec.rates, &[0.5, -1.0, 0.0])?;
            MechanismCase {
                description: format!(
                    "rod (m = {}, l = {}; g = {g}) at ({}, {}), θ = {}° from the floor, velocity ({}, {}), ω = {} rad/s; the floor is y = 0",
                    m[0], l[0], p[0], p[1], a[0], u[0], u[1], u[2]
                ),
                mechanism: BuiltIn::Rod(Rod::new(m[0], l[0], g, 0.0)?),
                q: vec![p[0], p[1], a[0].to_radians()],
                u,
            }
        }
        other => {
            return Err(CliError::input(format!(
                "mechanism: unknown mechanism `{other}` (known: {})",
                BuiltIn::NAMES.join(", ")
            )))
        }
    };
    Ok(case)
}

/// The spec of a classified mechanism source (a built-in's name, or a mechanism file read
/// once), with the flags merged over it.
pub fn load_source(source: &super::Source, flags: &MechanismSpec) -> CliResult<MechanismSpec> {
    let mut spec = match source {
        super::Source::BuiltInMechanism(name) => MechanismSpec {
            mechanism: name.clone(),
            ..MechanismSpec::default()
        },
        super::Source::Mechanism(file) => parse_file(Path::new(&file.name), &file.text)?,
        _ => unreachable!("a body scenario is not a mechanism source"),
    };
    merge(&mut spec, flags);
    Ok(spec)
}

/// The spec named by `source` (a built-in name or a TOML file), with the flags merged over it.
pub fn load(source: &str, flags: &MechanismSpec) -> CliResult<MechanismSpec> {
    let mut spec = if BuiltIn::NAMES.contains(&source) {
        MechanismSpec {
            mechanism: source.to_string(),
            ..MechanismSpec::default()
        }
    } else {
        let path = Path::new(source);
        let text = std::fs::read_to_string(path).map_err(|e| {
            CliError::input(format!(
                "{source}: not a built-in mechanism ({}) nor a readable file: {e}",
                BuiltIn::NAMES.join(", ")
            ))
        })?;
        parse_file(path, &text)?
    };
    merge(&mut spec, flags);
    Ok(spec)
}
