//! The diagram's reference lines: the friction cone `|p_t| = μ p_n`, the line of sticking
//! (`v_t = 0`), the line of maximum compression (`v_n = 0`) and Newton's restitution
//! (`v_n = −e v_n⁻`).

use super::window::Window;
use super::Chart;
use crate::output::plot::{err, DrawResult};
use impax::planar::ContactProblem;
use plotters::prelude::*;

/// Draw the reference lines of problem `p` in the window `win`, each with its legend entry.
pub(super) fn draw<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    p: &ContactProblem,
    win: &Window,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
    let v = p.velocity();
    let (mu, e) = (p.friction(), p.restitution());
    let y1 = win.y1;
    // Straight reference lines, clipped to the chart by sampling.
    let grey = RGBColor(150, 150, 150);
    let cone: Vec<(f64, f64)> = [(-mu * y1, y1), (0.0, 0.0), (mu * y1, y1)].to_vec();
    chart
        .draw_series(DashedLineSeries::new(cone, 6, 5, grey.stroke_width(1)))
        .map_err(err)?
        .label(format!("friction cone |p_t| = μ p_n (μ = {mu})"))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(1)));
    let stick_colour = RGBColor(0, 150, 136);
    chart
        .draw_series(LineSeries::new(
            win.clip(a, b, -v.x), // v_t = v_t⁻ + a p_t + b p_n = 0
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
            win.clip(b, c, -v.y),
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
            win.clip(b, c, -(1.0 + e) * v.y),
            8,
            5,
            comp_colour.stroke_width(1),
        ))
        .map_err(err)?
        .label(format!("Newton's restitution: v_n = −e v_n⁻ (e = {e})"))
        .legend(move |(x, y)| {
            PathElement::new(vec![(x, y), (x + 20, y)], comp_colour.stroke_width(1))
        });
    Ok(())
}
