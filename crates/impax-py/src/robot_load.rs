//! Reading a mechanism of one's own for `impax.mechanism(...)`: what the argument is (a
//! path or the text of a mechanism file or a URDF robot, or a built-in's name) and the
//! [`Mechanism`] read from it — a planar file built once by `impax::scenario::MechanismSpec`,
//! a spatial file or a URDF robot read once by `impax::scenario::RobotSpec::load`.

use crate::convert::{lib, value_error};
use crate::robots::{Defaults, Kind, Mechanism, Planar, Spatial};
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::Mechanism as _;
use impax::multibody;
use impax::scenario::{
    is_mechanism_file, MechanismFile, MechanismSpec, RobotSource, RobotSpec, Space,
};
use impax::LawId;
use pyo3::prelude::*;
use std::sync::{Arc, Mutex};

/// Where a mechanism comes from: the text of a file and its name.
pub struct Source {
    pub text: String,
    pub urdf: bool,
    /// The path it was read from (empty for text).
    pub path: String,
    /// The file's stem (empty for text).
    pub stem: String,
}

/// Whether `source` names a mechanism of one's own (a path or the text of a file) rather
/// than a built-in: text (several lines, or XML), an existing file, or a name ending in
/// `.toml`, `.urdf` or `.xml` or holding a path separator (which must then be readable).
pub fn source(obj: &Bound<'_, PyAny>) -> PyResult<Option<Source>> {
    let py = obj.py();
    let path_like = py.import("os")?.getattr("PathLike")?;
    let text: String = if obj.is_instance(&path_like)? {
        py.import("os")?.call_method1("fspath", (obj,))?.extract()?
    } else {
        match obj.extract() {
            Ok(text) => text,
            Err(_) => {
                return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                    "mechanism: expected a built-in's name, a path or the text of a mechanism file or URDF robot, got an object of type {}",
                    obj.get_type().name()?
                )))
            }
        }
    };
    let head = text.trim_start();
    if text.contains('\n') || head.starts_with('<') {
        let urdf = head.starts_with('<');
        return Ok(Some(Source {
            text,
            urdf,
            path: String::new(),
            stem: String::new(),
        }));
    }
    if BuiltIn::NAMES.contains(&text.as_str()) {
        return Ok(None);
    }
    let path = std::path::Path::new(&text);
    let lower = text.to_ascii_lowercase();
    let file_like = [".toml", ".urdf", ".xml"]
        .iter()
        .any(|x| lower.ends_with(x))
        || text.contains(std::path::MAIN_SEPARATOR)
        || text.contains('/');
    if !(path.is_file() || file_like) {
        return Ok(None);
    }
    let contents = std::fs::read_to_string(path)
        .map_err(|e| value_error(format!("mechanism: cannot read `{text}`: {e}")))?;
    let head = contents.trim_start();
    Ok(Some(Source {
        urdf: lower.ends_with(".urdf")
            || lower.ends_with(".xml")
            || head.starts_with("<?xml")
            || head.starts_with("<robot"),
        text: contents,
        path: text.clone(),
        stem: path
            .file_stem()
            .map_or(String::new(), |s| s.to_string_lossy().into_owned()),
    }))
}

/// The options of `mechanism(...)` for a mechanism of one's own.
pub struct Options {
    pub floating_base: bool,
    pub contact: Option<String>,
    pub floor: Option<f64>,
    pub gravity: Option<f64>,
    pub friction: Option<f64>,
    pub restitution: Option<f64>,
}

/// Read a mechanism of one's own.
pub fn load(py: Python<'_>, source: Source, options: Options) -> PyResult<Mechanism> {
    let (robot_source, file) = if source.urdf {
        (RobotSource::Urdf(source.text), None)
    } else {
        if !is_mechanism_file(&source.text) {
            return Err(value_error(if source.text.contains("mechanism") {
                "mechanism: this TOML describes a built-in mechanism (its `mechanism` key): call impax.mechanism(NAME, ...) with its parameters".to_string()
            } else {
                "mechanism: not a mechanism file (no [[body]] or [[joint]] tables) nor a URDF robot"
                    .to_string()
            }));
        }
        let file = MechanismFile::parse(&source.text).map_err(|e| {
            let what = if source.path.is_empty() {
                "mechanism"
            } else {
                &source.path
            };
            value_error(format!("{what}: {e}"))
        })?;
        (RobotSource::File(Box::new(file.clone())), Some(file))
    };
    let file_laws = file.as_ref().and_then(|f| f.laws.clone());
    let coefficient = |given: Option<f64>, of_file: Option<f64>| given.or(of_file).unwrap_or(0.5);
    let friction = coefficient(options.friction, file.as_ref().and_then(|f| f.friction));
    let restitution = coefficient(
        options.restitution,
        file.as_ref().and_then(|f| f.restitution),
    );
    let (name, kind, description) = match file {
        Some(file) if file.space == Space::Planar => planar(source.stem, file, &options)?,
        _ => spatial(source.stem, robot_source, &options)?,
    };
    let mut m = Mechanism {
        name,
        kind,
        defaults: Defaults {
            contact: None,
            friction,
            restitution,
            laws: Vec::new(),
        },
        description,
    };
    m.defaults.laws = match file_laws {
        Some(ids) => m.laws(Some(ids.into_pyobject(py)?.as_any()))?,
        None => match m.kind {
            Kind::Planar(_) => LawId::CONTACT_SPACE.to_vec(),
            Kind::Spatial(_) => LawId::SPATIAL.to_vec(),
        },
    };
    if let Some(c) = options.contact {
        check_contact(&m, &c)?;
        m.defaults.contact = Some(c);
    }
    Ok(m)
}

/// Check `mechanism(..., contact=...)`: a file's contact, a URDF robot's link (its model is
/// built and kept).
fn check_contact(m: &Mechanism, contact: &str) -> PyResult<()> {
    let names: Vec<String> = match &m.kind {
        Kind::Spatial(s) if s.robot.is_urdf() => return s.model(Some(contact)).map(|_| ()),
        Kind::Planar(p) => p
            .mechanism
            .contacts()
            .iter()
            .map(|c| c.name.to_string())
            .collect(),
        Kind::Spatial(s) => s
            .robot
            .contact_names()
            .iter()
            .map(|c| c.to_string())
            .collect(),
    };
    if names.iter().any(|n| n == contact) {
        return Ok(());
    }
    Err(value_error(format!(
        "contact: `{contact}` is not a contact of `{}` (its contacts: {})",
        m.name,
        names.join(", ")
    )))
}

/// A planar mechanism file: its name, the linkage and the description.
fn planar(stem: String, mut file: MechanismFile, o: &Options) -> PyResult<(String, Kind, String)> {
    if o.floating_base {
        return Err(value_error(
            "floating_base: a mechanism file gives its base a `free` joint itself",
        ));
    }
    if let Some(h) = o.floor {
        if !h.is_finite() {
            return Err(value_error(impax::Error::NotFinite {
                field: "floor".into(),
                value: h,
            }));
        }
        file.set_floor(h);
    }
    let floor_given = file.floor_given();
    let name = file.name.clone().unwrap_or(if stem.is_empty() {
        "mechanism".into()
    } else {
        stem
    });
    let built = lib(MechanismSpec {
        mechanism: name.clone(),
        gravity: o.gravity,
        file: Some(file.clone()),
        ..MechanismSpec::default()
    }
    .build())?;
    let description = built
        .description
        .split(": q = ")
        .next()
        .unwrap_or_default()
        .to_string();
    let kind = Kind::Planar(Planar {
        mechanism: built.mechanism,
        file,
        gravity: o.gravity,
        floor_given,
        q: built.q,
        u: built.u,
    });
    Ok((name, kind, description))
}

/// A spatial mechanism file or a URDF robot: its name, the robot and the description.
fn spatial(stem: String, source: RobotSource, o: &Options) -> PyResult<(String, Kind, String)> {
    let urdf = matches!(source, RobotSource::Urdf(_));
    let spec = RobotSpec {
        floating_base: o.floating_base,
        floor: o.floor,
        gravity: o.gravity,
        ..RobotSpec::new(if urdf { "" } else { &stem }, source)
    };
    let robot = lib(spec.load())?;
    let model = robot.model();
    let base = match model.joints().first() {
        Some(j) if j.kind == multibody::JointKind::Free => "floating base",
        _ => "fixed base",
    };
    let mut description = format!(
        "{} ({}, {} bodies, {} coordinates, {} speeds; g = {})",
        robot.name(),
        base,
        model.bodies().len(),
        model.nq(),
        model.nv(),
        model.gravity()
    );
    if !robot.mimic_joints().is_empty() {
        description.push_str(&format!(
            "; mimic joints kept independent: {}",
            robot.mimic_joints().join(", ")
        ));
    }
    let file_model = if urdf || model.contacts().is_empty() {
        None
    } else {
        Some(Arc::new(lib(robot.struck_by(None))?))
    };
    let name = robot.name().to_string();
    let kind = Kind::Spatial(Spatial {
        robot,
        file_model,
        models: Mutex::new(Vec::new()),
    });
    Ok((name, kind, description))
}
