//! The quantities of `impax conserved` against time: each as its change since t = 0 relative
//! to its magnitude, so conserved ones lie on zero and the others visibly move.

use super::map::tick;
use super::{err, text, DrawResult, Figure};
use impax::mechanism::conserved::{Track, Tracking};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The figure: one line per quantity.
pub struct ConservedFigure<'a> {
    pub title: String,
    pub tracking: &'a Tracking,
    pub tolerance: f64,
}

const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

impl Figure for ConservedFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let (title, body) = root.split_vertically(34);
        title
            .draw(&Text::new(self.title.clone(), (16, 8), text(18.0)))
            .map_err(err)?;
        let (upper, lower) = body.split_vertically(body.dim_in_pixel().1 / 2);
        let tracks: Vec<(usize, &Track)> = self.tracking.tracks.iter().enumerate().collect();
        let (kept, moved): (Vec<_>, Vec<_>) = tracks
            .into_iter()
            .partition(|(_, t)| t.conserved(self.tolerance));
        panel(
            &upper,
            self.tracking,
            &moved,
            "not conserved: (Q(t) − Q(0)) / magnitude",
        )?;
        panel(
            &lower,
            self.tracking,
            &kept,
            "conserved: (Q(t) − Q(0)) / magnitude (round-off scale)",
        )?;
        Ok(())
    }
}

/// One panel: the relative change of the given quantities against time, legend on the right.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    tr: &Tracking,
    tracks: &[(usize, &Track)],
    y_desc: &str,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let t_end = *tr.times.last().unwrap_or(&1.0);
    let rel = |t: &Track, v: f64| {
        if t.magnitude > 0.0 {
            (v - t.initial()) / t.magnitude
        } else {
            0.0
        }
    };
    let mut hi = 0.0f64;
    for (_, t) in tracks {
        for &v in &t.values {
            hi = hi.max(rel(t, v).abs());
        }
    }
    let hi = if hi > 0.0 { 1.1 * hi } else { 1e-15 };
    let width = area.dim_in_pixel().0;
    let (area, legend) = area.split_horizontally(width.saturating_sub(220));
    for (k, (i, t)) in tracks.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let y = 24 + 22 * k as i32;
        legend
            .draw(&PathElement::new(
                vec![(8, y), (30, y)],
                colour.stroke_width(3),
            ))
            .map_err(err)?;
        legend
            .draw(&Text::new(t.name.clone(), (38, y - 8), text(13.0)))
            .map_err(err)?;
    }
    let mut chart = ChartBuilder::on(&area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..t_end, -hi..hi)
        .map_err(err)?;
    chart
        .configure_mesh()
        .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(220, 220, 220))
        .x_desc("time t (s)")
        .y_desc(y_desc)
        .x_label_formatter(&|x| tick(*x))
        .y_label_formatter(&|y| {
            if y.abs() < 1e-6 * hi {
                "0".to_string()
            } else if hi < 1e-3 {
                format!("{y:.1e}")
            } else {
                tick(*y)
            }
        })
        .label_style(text(12.0))
        .axis_desc_style(text(12.0))
        .draw()
        .map_err(err)?;
    for (i, t) in tracks {
        let colour = PALETTE[i % PALETTE.len()];
        chart
            .draw_series(LineSeries::new(
                tr.times
                    .iter()
                    .zip(&t.values)
                    .map(|(&x, &v)| (x, rel(t, v))),
                colour.stroke_width(2),
            ))
            .map_err(err)?;
    }
    if tracks.is_empty() {
        chart
            .draw_series(std::iter::once(Text::new(
                "(none)".to_string(),
                (0.45 * t_end, 0.0),
                text(14.0),
            )))
            .map_err(err)?;
    }
    Ok(())
}
