//! Spatial mechanisms of one's own at the command line — a URDF robot or a `space = "3d"`
//! mechanism file — with the flags (`--contact`, `--floating-base`, `--floor`, `--q`, `--u`,
//! `--friction`, `--restitution`, `--law`); the description and its builder are the core's
//! ([`impax::scenario::RobotSpec`]).

use super::File;
use crate::cli::MechanismFlags;
use crate::input::{CliError, CliResult};
use crate::sources::scenario::parse_laws;
use impax::scenario::{
    is_mechanism_file, MechanismFile, RobotSource, RobotSpec, Space, DEFAULT_FRICTION,
    DEFAULT_RESTITUTION,
};
use impax::LawId;
use std::path::Path;

/// Whether a file is a URDF robot (named `.urdf`, or XML with a `<robot` element) or a
/// `space = "3d"` mechanism file.
pub fn is_robot(name: &str, text: &str) -> bool {
    let head = text.trim_start();
    name.to_ascii_lowercase().ends_with(".urdf")
        || ((head.starts_with("<?xml") || head.starts_with("<robot")) && text.contains("<robot"))
        || (is_mechanism_file(text)
            && MechanismFile::parse(text).is_ok_and(|f| f.space == Space::Spatial))
}

/// What a robot's file and the flags give: the spec, and the file's coefficients and laws
/// (a URDF has none).
pub struct RobotCase {
    /// The robot, its state and its contact.
    pub spec: RobotSpec,
    /// Coulomb friction of the impact (`--friction`, the file's, or 0.5).
    pub friction: f64,
    /// Restitution (`--restitution`, the file's, or 0.5).
    pub restitution: f64,
    /// The laws (`--law`, the file's, or every spatial law).
    pub laws: Vec<LawId>,
}

/// The flags that only the planar built-ins take.
fn refuse_planar_flags(flags: &MechanismFlags) -> CliResult<()> {
    for (flag, given) in [
        ("angles-deg", flags.angles_deg.is_some()),
        ("rates", flags.rates.is_some()),
        ("masses", flags.masses.is_some()),
        ("lengths", flags.lengths.is_some()),
        ("position", flags.position.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: a parameter of the planar built-ins; a robot's state is --q and --u"
            )));
        }
    }
    Ok(())
}

/// Read a robot source with its flags.
pub fn load(
    file: &File,
    flags: &MechanismFlags,
    friction: Option<f64>,
    restitution: Option<f64>,
    law_flags: &[String],
) -> CliResult<RobotCase> {
    refuse_planar_flags(flags)?;
    let path = Path::new(&file.name);
    let stem = path
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let (source, file_friction, file_restitution, file_laws) = if is_mechanism_file(&file.text) {
        let m = MechanismFile::parse(&file.text)
            .map_err(|e| CliError::input(format!("{}: {e}", file.name)))?;
        let (f, r, l) = (m.friction, m.restitution, m.laws.clone());
        (RobotSource::File(Box::new(m)), f, r, l)
    } else {
        (RobotSource::Urdf(file.text.clone()), None, None, None)
    };
    let spec = RobotSpec {
        floating_base: flags.floating_base,
        contact: flags.contact.first().cloned(),
        more_contacts: flags.contact.iter().skip(1).cloned().collect(),
        floor: flags.floor,
        gravity: flags.gravity,
        q: flags.q.clone(),
        u: flags.u.clone(),
        ..RobotSpec::new(
            if matches!(source, RobotSource::Urdf(_)) {
                ""
            } else {
                &stem
            },
            source,
        )
    };
    let laws = if !law_flags.is_empty() {
        parse_laws(law_flags)?
    } else if let Some(ids) = &file_laws {
        parse_laws(ids)?
    } else {
        LawId::SPATIAL.to_vec()
    };
    if let Some(l) = laws.iter().find(|l| !l.is_spatial()) {
        return Err(CliError::input(format!(
            "law: `{l}` is defined for planar impacts only (spatial laws: {})",
            LawId::SPATIAL.map(|l| l.as_str()).join(", ")
        )));
    }
    Ok(RobotCase {
        spec,
        friction: friction.or(file_friction).unwrap_or(DEFAULT_FRICTION),
        restitution: restitution
            .or(file_restitution)
            .unwrap_or(DEFAULT_RESTITUTION),
        laws,
    })
}
