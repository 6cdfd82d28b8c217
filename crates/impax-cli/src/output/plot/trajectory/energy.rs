//! The lower panel: the energy T, V and T + V against time, with the impacts marked (a gain
//! in red).

use super::super::map::tick;
use super::super::{err, text, DrawResult};
use impax::simulation::Run;
use plotters::coord::Shift;
use plotters::prelude::*;

/// One energy curve: name, colour, width, and the value of a sample.
type EnergySeries = (
    &'static str,
    RGBColor,
    u32,
    fn(&impax::simulation::Sample) -> f64,
);

/// Draw the panel on `area`.
pub(super) fn draw<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, run: &Run) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let t_end = run.end_time.max(1e-9);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in &run.samples {
        for v in [s.kinetic, s.potential, s.kinetic + s.potential] {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    let pad = 0.06 * (hi - lo).max(1e-9);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..t_end, (lo - pad)..(hi + pad))
        .map_err(err)?;
    chart
        .configure_mesh()
        .light_line_style(RGBColor(240, 240, 240))
        .bold_line_style(RGBColor(222, 222, 222))
        .x_desc("time t (s)")
        .y_desc("energy (J)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(text(12.0))
        .axis_desc_style(text(13.0))
        .draw()
        .map_err(err)?;
    for imp in &run.impacts {
        let colour = if imp.energy_change > 0.0 {
            RGBColor(214, 39, 40)
        } else {
            RGBColor(200, 200, 200)
        };
        chart
            .draw_series(LineSeries::new(
                vec![(imp.time, lo - pad), (imp.time, hi + pad)],
                colour.stroke_width(1),
            ))
            .map_err(err)?;
    }
    let series: [EnergySeries; 3] = [
        ("kinetic T", RGBColor(49, 130, 189), 1, |s| s.kinetic),
        ("potential V", RGBColor(116, 196, 118), 1, |s| s.potential),
        ("total T + V", RGBColor(0, 0, 0), 3, |s| {
            s.kinetic + s.potential
        }),
    ];
    for (name, colour, width, f) in series {
        chart
            .draw_series(LineSeries::new(
                run.samples.iter().map(|s| (s.t, f(s))),
                colour.stroke_width(width),
            ))
            .map_err(err)?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(3))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(RGBColor(180, 180, 180))
        .label_font(text(12.0))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(err)?;
    Ok(())
}
