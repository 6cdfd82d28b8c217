//! The parameters of a simulation: from a built-in's name or a TOML file, the flags given on
//! the command line taking precedence.

use super::NAMES;
use crate::cli::SimulateArgs;
use crate::input::{CliError, CliResult};
use impax::scenario::{is_mechanism_file, MechanismFile};
use serde::Deserialize;

/// Every parameter of every scenario (flags or TOML); each scenario accepts some.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimSpec {
    pub simulation: String,
    pub law: Option<String>,
    pub friction: Option<f64>,
    pub restitution: Option<f64>,
    pub until: Option<f64>,
    pub samples: Option<usize>,
    pub gravity: Option<f64>,
    pub mass: Option<f64>,
    pub radius: Option<f64>,
    pub height: Option<f64>,
    pub speed: Option<f64>,
    pub alpha_deg: Option<f64>,
    pub spin_ratio: Option<f64>,
    pub disc: Option<bool>,
    pub length: Option<f64>,
    pub angle_deg: Option<f64>,
    pub masses: Option<Vec<f64>>,
    pub lengths: Option<Vec<f64>>,
    pub angles_deg: Option<Vec<f64>>,
    pub rates: Option<Vec<f64>>,
    pub floor: Option<f64>,
    pub half_width: Option<f64>,
    pub half_height: Option<f64>,
    pub omega: Option<f64>,
    pub balls: Option<usize>,
    pub v0: Option<f64>,
    pub gap: Option<f64>,
    pub q: Option<Vec<f64>>,
    pub u: Option<Vec<f64>>,
    /// A mechanism file to simulate (then `simulation` is its name). Not a key.
    #[serde(skip)]
    pub file: Option<MechanismFile>,
}

/// The parameters given as flags.
pub(super) fn flags(args: &SimulateArgs) -> SimSpec {
    SimSpec {
        simulation: String::new(),
        law: args.law.clone(),
        friction: args.friction,
        restitution: args.restitution,
        until: args.until,
        samples: args.samples,
        gravity: args.gravity,
        mass: args.mass,
        radius: args.radius,
        height: args.height,
        speed: args.speed,
        alpha_deg: args.alpha_deg,
        spin_ratio: args.spin_ratio,
        disc: args.disc.then_some(true),
        length: args.length,
        angle_deg: args.angle_deg,
        masses: args.masses.clone(),
        lengths: args.lengths.clone(),
        angles_deg: args.angles_deg.clone(),
        rates: args.rates.clone(),
        floor: args.floor,
        half_width: args.half_width,
        half_height: args.half_height,
        omega: args.omega,
        balls: args.balls,
        v0: args.v0,
        gap: args.gap,
        q: args.q.clone(),
        u: args.u.clone(),
        file: None,
    }
}

/// Take every parameter that `over` gives.
fn merge(spec: &mut SimSpec, over: &SimSpec) {
    macro_rules! take {
        ($($f:ident),*) => { $( if over.$f.is_some() { spec.$f = over.$f.clone(); } )* };
    }
    take!(
        law,
        friction,
        restitution,
        until,
        samples,
        gravity,
        mass,
        radius,
        height,
        speed,
        alpha_deg,
        spin_ratio,
        disc,
        length,
        angle_deg,
        masses,
        lengths,
        angles_deg,
        rates,
        floor,
        half_width,
        half_height,
        omega,
        balls,
        v0,
        gap,
        q,
        u
    );
}

/// The parameters of `source` (a built-in's name or a TOML file), `over` taking precedence.
pub(super) fn load(source: &str, over: &SimSpec) -> CliResult<SimSpec> {
    let mut spec = if NAMES.contains(&source) {
        SimSpec {
            simulation: source.into(),
            ..SimSpec::default()
        }
    } else {
        let text = std::fs::read_to_string(source).map_err(|e| {
            CliError::input(format!(
                "{source}: not a built-in scenario ({}) nor a readable file: {e}",
                NAMES.join(", ")
            ))
        })?;
        if is_mechanism_file(&text) {
            mechanism_file(source, &text)?
        } else {
            toml::from_str(&text).map_err(|e| {
                CliError::input(format!("{source}: {}", e.message().replace('\n', " ")))
            })?
        }
    };
    merge(&mut spec, over);
    Ok(spec)
}

/// A mechanism file to simulate: its name, friction, restitution and its one law (if it names
/// exactly one).
fn mechanism_file(source: &str, text: &str) -> CliResult<SimSpec> {
    // A `space = "3d"` file is a robot's (`super::robot`): it does not come here.
    let file = MechanismFile::parse(text).map_err(|e| CliError::input(format!("{source}: {e}")))?;
    let name = file.name.clone().unwrap_or_else(|| {
        std::path::Path::new(source)
            .file_stem()
            .map_or("mechanism".into(), |s| s.to_string_lossy().into_owned())
    });
    Ok(SimSpec {
        simulation: name,
        law: file
            .laws
            .as_ref()
            .filter(|l| l.len() == 1)
            .map(|l| l[0].clone()),
        friction: file.friction,
        restitution: file.restitution,
        gravity: file.gravity,
        file: Some(file),
        ..SimSpec::default()
    })
}
