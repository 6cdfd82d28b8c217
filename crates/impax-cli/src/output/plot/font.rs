//! The embedded font: DejaVu Sans 2.37 (Bitstream Vera licence, `assets/fonts/`), registered
//! with plotters' `ab_glyph` text renderer under [`FAMILY`]. Plots never read system fonts.

use plotters::style::{register_font, FontStyle};
use std::sync::Once;

/// The family name every plot uses.
pub const FAMILY: &str = "sans-serif";

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// Register the font (once per process).
pub fn register() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for style in [
            FontStyle::Normal,
            FontStyle::Bold,
            FontStyle::Italic,
            FontStyle::Oblique,
        ] {
            // The bytes are a valid TrueType font (checked by the plot tests).
            let _ = register_font(FAMILY, style, FONT);
        }
    });
}
