//! The picture of a simulated motion: the path in the plane with snapshots of the body at
//! its impacts (equal scales on both axes), and the energy T, V, T + V against time with the
//! impacts marked (a gain in red).
//!
//! One panel per file: the path (`path`) above, the energy (`energy`) below.

mod energy;
mod path;

use super::{err, text, DrawResult, Figure};
use crate::commands::simulate::Shape;
use impax::mechanism::builtin::BuiltIn;
use impax::simulation::Run;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The path and the energy of one run.
pub struct TrajectoryFigure<'a> {
    /// The line above the panels.
    pub title: String,
    /// The simulated mechanism.
    pub mechanism: &'a BuiltIn,
    /// Its run.
    pub run: &'a Run,
    /// What to draw for each body.
    pub shapes: &'a [Shape],
}

impl Figure for TrajectoryFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let (title, body) = root.split_vertically(36);
        title
            .draw(&Text::new(self.title.clone(), (16, 8), text(18.0)))
            .map_err(err)?;
        let (top, bottom) = body.split_vertically(body.dim_in_pixel().1 * 11 / 20);
        path::draw(&top, self.mechanism, self.run, self.shapes)?;
        energy::draw(&bottom, self.run)
    }
}
