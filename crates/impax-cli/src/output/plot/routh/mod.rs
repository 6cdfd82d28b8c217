//! Routh's impulse-space diagram of one impact (Routh 1905; Stronge 2000, ch. 5): the
//! impulse `p = (p_t, p_n)` on body A, with the line of sticking (`v_t = 0`), the line of
//! maximum compression (`v_n = 0`), the line of Newton's restitution (`v_n = −e v_n⁻`), the
//! friction cone `|p_t| = μ p_n`, and each law's impulse path and termination point.
//!
//! The figure also carries the energy bars of every law ([`super::energy`]). The diagram is
//! drawn in stages: its window in impulse space (`window`), the reference lines (`lines`),
//! the laws' paths and the legend (`paths`).

mod lines;
mod paths;
mod window;

use super::energy::{self, EnergyRow};
use super::map::tick;
use super::{err, text, DrawResult, Figure};
use impax::planar::{ContactProblem, Outcome};
use impax::LawId;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use window::Window;

/// The diagram's chart: `(p_t, p_n)` on linear axes.
type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// One law's impulse path: a polyline from the origin to its termination point.
#[derive(Debug, Clone)]
pub struct LawPath {
    pub law: LawId,
    /// `(p_t, p_n)` vertices, starting at the origin.
    pub points: Vec<(f64, f64)>,
}

impl LawPath {
    /// The path of an outcome ([`Outcome::impulse_path`], shared with the explorer page).
    pub fn of(problem: &ContactProblem, o: &Outcome) -> Self {
        let points = o.impulse_path(problem).iter().map(|v| (v.x, v.y)).collect();
        Self { law: o.law, points }
    }
}

/// Routh's diagram and the energy bars of one impact.
#[derive(Debug, Clone)]
pub struct RouthFigure {
    pub title: String,
    pub subtitle: String,
    pub problem: ContactProblem,
    pub paths: Vec<LawPath>,
    pub energy: Vec<EnergyRow>,
}

impl RouthFigure {
    pub const DEFAULT_SIZE: (u32, u32) = (1500, 900);
}

impl Figure for RouthFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let (w, _) = root.dim_in_pixel();
        let (head, rest) = root.split_vertically(64);
        head.draw(&Text::new(self.title.clone(), (16, 8), text(22.0)))
            .map_err(err)?;
        head.draw(&Text::new(
            self.subtitle.clone(),
            (16, 38),
            text(15.0).color(&RGBColor(70, 70, 70)),
        ))
        .map_err(err)?;
        let (left, right) = rest.split_horizontally((w as f64 * 0.55) as u32);
        self.draw_routh(&left)?;
        let (top, bottom) = right.split_vertically(right.dim_in_pixel().1 / 2);
        energy::draw_bars(&top, &self.energy, energy::Split::Work)?;
        energy::draw_bars(&bottom, &self.energy, energy::Split::Parts)
    }
}

impl RouthFigure {
    /// Routh's diagram on `area`: the window, the axes, the reference lines, the laws' paths
    /// and the legend.
    fn draw_routh<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let win = Window::of(self);
        let Window { x0, x1, y0, y1 } = win;
        let mut chart = ChartBuilder::on(area)
            .caption("Routh's diagram: impulse on body A", text(18.0))
            .margin(10)
            .x_label_area_size(46)
            .y_label_area_size(64)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(215, 215, 215))
            .x_desc("tangential impulse p_t (mass × velocity)")
            .y_desc("normal impulse p_n (mass × velocity)")
            .x_label_formatter(&|x| tick(*x))
            .y_label_formatter(&|x| tick(*x))
            .label_style(text(13.0))
            .axis_desc_style(text(14.0))
            .draw()
            .map_err(err)?;
        lines::draw(&mut chart, &self.problem, &win)?;
        paths::draw(&mut chart, &self.paths)?;
        paths::legend(&mut chart, &self.paths, &win)
    }
}
