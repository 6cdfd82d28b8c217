//! Where a system comes from: a body scenario file (or the seed's), a `space = "3d"` body
//! file, a built-in mechanism or a mechanism file — decided once, by [`Source::classify`],
//! from the argument and the file's keys; each subcommand then reads what it was given.

pub mod mechanism;
pub mod robot;
pub mod scenario;

use crate::input::{CliError, CliResult};
use std::path::Path;

/// A file read once: its name for messages and its text.
#[derive(Debug, Clone)]
pub struct File {
    /// The path as given.
    pub name: String,
    /// Its contents.
    pub text: String,
}

/// What a scenario argument names.
#[derive(Debug, Clone)]
pub enum Source {
    /// A planar body scenario file.
    Planar(File),
    /// A `space = "3d"` body scenario file.
    Spatial(File),
    /// A built-in mechanism, by name (`double-pendulum`, …).
    BuiltInMechanism(String),
    /// A planar mechanism file: a built-in's parameters (a top-level `mechanism` key) or a
    /// mechanism of one's own (`[[body]]`, `[[joint]]`).
    Mechanism(File),
    /// A spatial mechanism of one's own: a URDF robot or a `space = "3d"` mechanism file.
    Robot(File),
}

impl Source {
    /// Classify `arg`: one of `built_ins` (the mechanisms the subcommand knows by name, unless
    /// a file has that name), else a file, read once and told apart by its keys (`mechanism`;
    /// `space = "3d"`; otherwise a planar body scenario).
    /// `unreadable` words the error of a file that cannot be read (each subcommand says what
    /// else the argument could have been).
    pub fn classify(
        arg: &str,
        built_ins: &[&str],
        unreadable: impl FnOnce(std::io::Error) -> CliError,
    ) -> CliResult<Self> {
        if built_ins.contains(&arg) && !Path::new(arg).is_file() {
            return Ok(Source::BuiltInMechanism(arg.to_string()));
        }
        let text = std::fs::read_to_string(arg).map_err(unreadable)?;
        let file = File {
            name: arg.to_string(),
            text,
        };
        Ok(if robot::is_robot(&file.name, &file.text) {
            Source::Robot(file)
        } else if mechanism::is_mechanism_toml(&file.text) {
            Source::Mechanism(file)
        } else if crate::commands::compare::spatial::is_spatial(&file.text) {
            Source::Spatial(file)
        } else {
            Source::Planar(file)
        })
    }
}
