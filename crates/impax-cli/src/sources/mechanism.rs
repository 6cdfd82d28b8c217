//! Built-in mechanisms at the command line and in TOML: the file, the flags merged over it;
//! the description and its builder are the core's ([`impax::scenario::MechanismSpec`]).
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

use crate::input::{CliError, CliResult};
use impax::mechanism::builtin::BuiltIn;
use impax::scenario::{is_mechanism_file, MechanismFile};
use std::path::Path;

/// The parameters of a built-in mechanism, from flags or a TOML file: the core's description
/// (every field optional; every mechanism has defaults), built by the core.
pub use impax::scenario::MechanismSpec;

/// A built-in mechanism and its state, as the core builds it.
pub use impax::scenario::BuiltMechanism as MechanismCase;

/// Whether a TOML text describes a mechanism: a built-in's parameters (a top-level
/// `mechanism` key) or a mechanism of one's own (`[[body]]` and `[[joint]]` tables).
pub fn is_mechanism_toml(text: &str) -> bool {
    text.parse::<toml::Table>()
        .map(|t| t.contains_key("mechanism"))
        .unwrap_or(false)
        || is_mechanism_file(text)
}

/// Read a mechanism TOML file: a built-in's parameters, or a mechanism file (bodies, joints,
/// contacts), whose name is its `name` or else the file's stem.
pub fn parse_file(path: &Path, text: &str) -> CliResult<MechanismSpec> {
    if is_mechanism_file(text) {
        let file = MechanismFile::parse(text)
            .map_err(|e| CliError::input(format!("{}: {e}", path.display())))?;
        let name = file.name.clone().unwrap_or_else(|| {
            path.file_stem()
                .map_or("mechanism".into(), |s| s.to_string_lossy().into_owned())
        });
        return Ok(MechanismSpec {
            mechanism: name,
            friction: file.friction,
            restitution: file.restitution,
            laws: file.laws.clone(),
            file: Some(file),
            ..MechanismSpec::default()
        });
    }
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
        angles,
        rates,
        position,
        q,
        u
    );
}

/// Build the mechanism and its state from a spec, with the defaults of each mechanism
/// ([`MechanismSpec::build`]).
pub fn build(spec: &MechanismSpec) -> CliResult<MechanismCase> {
    Ok(spec.build()?)
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
