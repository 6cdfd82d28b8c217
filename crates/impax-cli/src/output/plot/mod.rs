//! Pictures: maps of sweeps, Routh's impulse-space diagram, energy bars; PNG or SVG by the
//! extension of the output file. Text is drawn with an embedded font ([`font`]), so plots
//! render the same on a machine without system fonts.

pub mod colour;
pub mod conserved;
pub mod energy;
pub mod font;
pub mod map;
pub mod routh;
pub mod trajectory;

use crate::input::{CliError, CliResult};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// The picture format, from the file extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Png,
    Svg,
}

impl Format {
    /// `.png` or `.svg` (case-insensitive); anything else is bad input naming `flag`.
    pub fn of(flag: &str, path: &Path) -> CliResult<Self> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("png") => Ok(Format::Png),
            Some("svg") => Ok(Format::Svg),
            _ => Err(CliError::input(format!(
                "--{flag} {}: the file name must end in .png or .svg",
                path.display()
            ))),
        }
    }
}

/// Drawing errors as text.
pub type DrawResult = Result<(), String>;

/// Convert a plotters error to text.
pub fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// Something drawn on a drawing area of any backend.
pub trait Figure {
    /// Draw on `root` (already filled white).
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static;
}

/// Render a figure to `path` (format from the extension) at `size` pixels.
pub fn render(flag: &str, path: &Path, size: (u32, u32), figure: &impl Figure) -> CliResult<()> {
    let format = Format::of(flag, path)?;
    // Fail early, as bad input, if the file cannot be created.
    std::fs::File::create(path)
        .map_err(|e| CliError::input(format!("--{flag} {}: cannot create: {e}", path.display())))?;
    font::register();
    let failed = |e: String| CliError::failure(format!("drawing {}: {e}", path.display()));
    match format {
        Format::Png => {
            let root = BitMapBackend::new(path, size).into_drawing_area();
            root.fill(&WHITE).map_err(err).map_err(failed)?;
            figure.draw(&root).map_err(failed)?;
            root.present().map_err(err).map_err(failed)
        }
        Format::Svg => {
            let root = SVGBackend::new(path, size).into_drawing_area();
            root.fill(&WHITE).map_err(err).map_err(failed)?;
            figure.draw(&root).map_err(failed)?;
            root.present().map_err(err).map_err(failed)
        }
    }
}

/// A font of the embedded family at `size` pixels.
pub fn text(size: f64) -> TextStyle<'static> {
    (font::FAMILY, size).into_font().into()
}

/// Parse `WIDTHxHEIGHT`.
pub fn parse_size(text: &str) -> CliResult<(u32, u32)> {
    let bad = || {
        CliError::input(format!(
            "--size {text}: expected WIDTHxHEIGHT in pixels, each 200 to 10000 (e.g. 1600x900)"
        ))
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if !(200..=10_000).contains(&w) || !(200..=10_000).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}
