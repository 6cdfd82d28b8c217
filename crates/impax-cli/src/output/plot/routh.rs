//! Routh's impulse-space diagram of one impact (Routh 1905; Stronge 2000, ch. 5): the
//! impulse `p = (p_t, p_n)` on body A, with the line of sticking (`v_t = 0`), the line of
//! maximum compression (`v_n = 0`), the line of Newton's restitution (`v_n = −e v_n⁻`), the
//! friction cone `|p_t| = μ p_n`, and each law's impulse path and termination point.
//!
//! The figure also carries the energy bars of every law ([`super::energy`]).

use super::energy::{self, EnergyRow};
use super::map::tick;
use super::{colour, err, text, DrawResult, Figure};
use impax::planar::{ContactProblem, Outcome};
use impax::LawId;
use plotters::coord::Shift;
use plotters::prelude::*;

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
    fn draw_routh<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let p = &self.problem;
        let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
        let v = p.velocity();
        let (mu, e) = (p.friction(), p.restitution());
        // Extent: every path point, the origin, and the Newton line's normal impulse.
        let pn_newton = -(1.0 + e) * v.y / c;
        let mut pt = (0.0f64, 0.0f64);
        let mut pn_max = pn_newton.max(0.0);
        for path in &self.paths {
            for &(x, y) in &path.points {
                pt = (pt.0.min(x), pt.1.max(x));
                pn_max = pn_max.max(y);
            }
        }
        let stick_at = |pn: f64| -(v.x + b * pn) / a;
        for pn in [0.0, pn_max] {
            let x = stick_at(pn);
            if x.is_finite() {
                pt = (pt.0.min(x), pt.1.max(x));
            }
        }
        let span = (pt.1 - pt.0).max(0.2 * pn_max).max(1e-12);
        let (x0, x1) = (pt.0 - 0.12 * span, pt.1 + 0.12 * span);
        // Headroom above the paths for the legend.
        let (y0, y1) = (-0.04 * pn_max.max(1e-12), 1.5 * pn_max.max(1e-12));
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
        // Straight reference lines, clipped to the chart by sampling.
        let grey = RGBColor(150, 150, 150);
        let cone: Vec<(f64, f64)> = [(-mu * y1, y1), (0.0, 0.0), (mu * y1, y1)].to_vec();
        chart
            .draw_series(DashedLineSeries::new(cone, 6, 5, grey.stroke_width(1)))
            .map_err(err)?
            .label(format!("friction cone |p_t| = μ p_n (μ = {mu})"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(1))
            });
        // Straight lines `ux + vy = w` clipped to the chart (two end points: no jaggies).
        let clip = |u: f64, v: f64, w: f64| -> Vec<(f64, f64)> {
            let mut pts = Vec::new();
            if v != 0.0 {
                for x in [x0, x1] {
                    let y = (w - u * x) / v;
                    if (y0..=y1).contains(&y) {
                        pts.push((x, y));
                    }
                }
            }
            if u != 0.0 {
                for y in [y0, y1] {
                    let x = (w - v * y) / u;
                    if (x0..=x1).contains(&x) {
                        pts.push((x, y));
                    }
                }
            }
            pts.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.total_cmp(&q.1)));
            pts.dedup();
            if pts.len() > 2 {
                let last = pts[pts.len() - 1];
                pts.truncate(1);
                pts.push(last);
            }
            pts
        };
        let stick_colour = RGBColor(0, 150, 136);
        chart
            .draw_series(LineSeries::new(
                clip(a, b, -v.x), // v_t = v_t⁻ + a p_t + b p_n = 0
                stick_colour.stroke_width(2),
            ))
            .map_err(err)?
            .label("line of sticking: v_t = 0")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], stick_colour.stroke_width(2))
            });
        let comp_colour = RGBColor(90, 90, 90);
        chart
            // v_n = v_n⁻ + b p_t + c p_n = 0
            .draw_series(LineSeries::new(
                clip(b, c, -v.y),
                comp_colour.stroke_width(2),
            ))
            .map_err(err)?
            .label("line of maximum compression: v_n = 0")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], comp_colour.stroke_width(2))
            });
        chart
            // v_n = −e v_n⁻
            .draw_series(DashedLineSeries::new(
                clip(b, c, -(1.0 + e) * v.y),
                8,
                5,
                comp_colour.stroke_width(1),
            ))
            .map_err(err)?
            .label(format!("Newton's restitution: v_n = −e v_n⁻ (e = {e})"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], comp_colour.stroke_width(1))
            });
        // Paths: earlier laws drawn wider, so that coinciding paths stay visible.
        let n = self.paths.len() as u32;
        for (i, path) in self.paths.iter().enumerate() {
            let col = colour::law(path.law);
            // From 7 px for the first law down to 2 px for the last.
            let width = 2 + 5 * (n - 1 - i as u32) / (n - 1).max(1);
            let style = col.stroke_width(width);
            chart
                .draw_series(LineSeries::new(path.points.iter().copied(), style))
                .map_err(err)?
                .label(path.law.to_string())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(3))
                });
            if let Some(&end) = path.points.last() {
                chart
                    .draw_series(std::iter::once(Circle::new(end, 6, col.filled())))
                    .map_err(err)?;
                chart
                    .draw_series(std::iter::once(Circle::new(end, 6, BLACK.stroke_width(1))))
                    .map_err(err)?;
            }
            for &mid in path.points.iter().skip(1).rev().skip(1) {
                chart
                    .draw_series(std::iter::once(TriangleMarker::new(mid, 6, col.filled())))
                    .map_err(err)?;
            }
        }
        // The legend goes on the side away from the paths' ends.
        let mean_end: f64 = self
            .paths
            .iter()
            .filter_map(|p| p.points.last().map(|e| e.0))
            .sum::<f64>();
        let side = if mean_end <= 0.5 * (x0 + x1) * self.paths.len() as f64 {
            SeriesLabelPosition::UpperRight
        } else {
            SeriesLabelPosition::UpperLeft
        };
        chart
            .configure_series_labels()
            .position(side)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font(text(13.0))
            .draw()
            .map_err(err)?;
        chart
            .plotting_area()
            .draw(&Text::new(
                "● termination point   ▲ end of the first phase (slip halts / friction switched)"
                    .to_string(),
                (x0 + 0.02 * (x1 - x0), y0 + 0.05 * (y1 - y0)),
                text(12.0),
            ))
            .map_err(err)?;
        Ok(())
    }
}
