//! An animated SVG of a simulated motion (SMIL `<animate>` of each body's geometry, in real
//! time or slowed to at least four seconds, looping), with the floor, the path traced, a clock bar and an energy bar.
//!
//! The document is made in stages: the frames of the motion (`frames`), the view that holds
//! them (`view`), and the layers drawn back to front (`layers`).

mod frames;
mod layers;
mod view;

pub(crate) use frames::{block_corners, floor};

use crate::commands::simulate::Case;
use frames::Frames;
use impax::simulation::Run;
use view::View;

/// The animated SVG document.
pub fn svg(case: &Case, run: &Run) -> String {
    let m = &case.initial.mechanism;
    let frames = Frames::of(m, &case.shapes, run);
    let duration = frames.duration;
    // World bounds (with the floor and the pivot of a pendulum).
    let floor_at = floor(m);
    let view = View::of(&frames.geo, &case.shapes, floor_at);
    // Short motions are slowed down to at least four seconds of playback.
    let playback = duration.max(4.0);
    let dur = format!("{playback:.4}s");
    let pace = if playback > duration {
        format!("slowed ×{:.1}", playback / duration)
    } else {
        "real time".to_string()
    };
    let mut s = String::new();
    layers::title(&mut s, &view, case, duration, &pace);
    if let Some(floor) = floor_at {
        layers::floor(&mut s, &view, floor);
    }
    layers::trace(&mut s, &view, &frames.geo);
    layers::bodies(&mut s, &view, &case.shapes, &frames.geo, &dur);
    layers::bars(&mut s, &view, &frames.energy, &dur);
    s.push_str("</svg>\n");
    s
}
