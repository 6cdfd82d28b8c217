//! The laws' impulse paths and their termination points, the legend on the side away from the
//! paths' ends, and the key to the markers.

use super::window::Window;
use super::{Chart, LawPath};
use crate::output::plot::{colour, err, text, DrawResult};
use plotters::prelude::*;

/// Draw every law's path: earlier laws wider, so that coinciding paths stay visible; a disc
/// at the termination point, a triangle at each corner (the end of a first phase).
pub(super) fn draw<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    paths: &[LawPath],
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let n = paths.len() as u32;
    for (i, path) in paths.iter().enumerate() {
        let col = colour::law(path.law);
        // From 7 px for the first law down to 2 px for the last.
        let width = 2 + 5 * (n - 1 - i as u32) / (n - 1).max(1);
        let style = col.stroke_width(width);
        chart
            .draw_series(LineSeries::new(path.points.iter().copied(), style))
            .map_err(err)?
            .label(path.law.to_string())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(3)));
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
    Ok(())
}

/// The legend, on the side away from the paths' ends, and the key to the markers.
pub(super) fn legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    paths: &[LawPath],
    win: &Window,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let Window { x0, x1, y0, y1 } = *win;
    // The legend goes on the side away from the paths' ends.
    let mean_end: f64 = paths
        .iter()
        .filter_map(|p| p.points.last().map(|e| e.0))
        .sum::<f64>();
    let side = if mean_end <= 0.5 * (x0 + x1) * paths.len() as f64 {
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
