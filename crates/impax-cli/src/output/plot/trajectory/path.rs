//! The upper panel: the path in the plane — the centres of mass and the first contact point —
//! with snapshots of the bodies at the start and at their first impacts, on equal scales.

use super::super::map::tick;
use super::super::{err, text, DrawResult};
use crate::commands::simulate::Shape;
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::{Mechanism, Pose};
use impax::simulation::Run;
use plotters::coord::Shift;
use plotters::prelude::*;

/// What the panel draws of a run.
struct Traced {
    /// The centre of mass of each body, per sample.
    paths: Vec<Vec<(f64, f64)>>,
    /// The first contact point, per sample (empty without contacts).
    tip: Vec<(f64, f64)>,
    /// The bodies' outlines at the start and at the first 12 impacts.
    snaps: Vec<Vec<Vec<(f64, f64)>>>,
}

impl Traced {
    fn of(m: &BuiltIn, run: &Run, shapes: &[Shape]) -> Self {
        let mut poses = vec![Pose::new(0.0, 0.0, 0.0); m.bodies().len()];
        let mut paths: Vec<Vec<(f64, f64)>> = vec![Vec::new(); m.bodies().len()];
        let mut tip: Vec<(f64, f64)> = Vec::new();
        for s in &run.samples {
            m.poses(&s.q, &mut poses);
            for (p, pose) in paths.iter_mut().zip(&poses) {
                p.push((pose.x, pose.y));
            }
            if !m.contacts().is_empty() {
                let c = m.contact_point(0, &s.q);
                tip.push((c[0], c[1]));
            }
        }
        let mut snaps: Vec<Vec<Vec<(f64, f64)>>> = Vec::new();
        m.poses(&run.samples[0].q, &mut poses);
        snaps.push(outlines(shapes, &poses));
        for imp in run.impacts.iter().take(12) {
            m.poses(&imp.q, &mut poses);
            snaps.push(outlines(shapes, &poses));
        }
        Traced { paths, tip, snaps }
    }
}

/// The world's window `(cx, cy, xr, yr)` (centre and half-ranges) that holds every point
/// drawn and the floor, widened to the panel's aspect so that both axes have one scale.
fn window(traced: &Traced, floor_at: Option<f64>, (pw, ph): (u32, u32)) -> (f64, f64, f64, f64) {
    let Traced { paths, tip, snaps } = traced;
    let all = paths
        .iter()
        .flatten()
        .chain(tip)
        .chain(snaps.iter().flatten().flatten());
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut y0, mut y1) = match floor_at {
        Some(f) => (f, f),
        None => (f64::INFINITY, f64::NEG_INFINITY),
    };
    for &(x, y) in all {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    // Equal scales: widen the shorter range to the panel's aspect.
    let (aw, ah) = (pw as f64 - 100.0, ph as f64 - 70.0);
    let (dx, dy) = ((x1 - x0).max(1e-9), (y1 - y0).max(1e-9));
    let k = (dx / aw).max(dy / ah) * 1.08;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (xr, yr) = (0.5 * k * aw, 0.5 * k * ah);
    (cx, cy, xr, yr)
}

/// Draw the panel on `area`.
pub(super) fn draw<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    m: &BuiltIn,
    run: &Run,
    shapes: &[Shape],
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let traced = Traced::of(m, run, shapes);
    let floor_at = crate::output::animation::floor(m);
    let floor = floor_at.unwrap_or(0.0);
    let (cx, cy, xr, yr) = window(&traced, floor_at, area.dim_in_pixel());
    let Traced { paths, tip, snaps } = &traced;
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d((cx - xr)..(cx + xr), (cy - yr)..(cy + yr))
        .map_err(err)?;
    chart
        .configure_mesh()
        .light_line_style(RGBColor(240, 240, 240))
        .bold_line_style(RGBColor(222, 222, 222))
        .x_desc("x (m)")
        .y_desc("y (m)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(text(12.0))
        .axis_desc_style(text(13.0))
        .draw()
        .map_err(err)?;
    if floor_at.is_some() {
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(cx - xr, cy - yr), (cx + xr, floor)],
                RGBColor(225, 225, 225).filled(),
            )))
            .map_err(err)?;
        chart
            .draw_series(LineSeries::new(
                vec![(cx - xr, floor), (cx + xr, floor)],
                BLACK.stroke_width(2),
            ))
            .map_err(err)?;
    }
    for (i, snap) in snaps.iter().enumerate() {
        let shade = if i == 0 {
            RGBColor(120, 120, 120)
        } else {
            RGBColor(49, 130, 189)
        };
        for outline in snap {
            chart
                .draw_series(LineSeries::new(outline.clone(), shade.stroke_width(2)))
                .map_err(err)?;
        }
    }
    for (i, p) in paths.iter().enumerate() {
        let drawn = chart
            .draw_series(LineSeries::new(
                p.clone(),
                RGBColor(8, 48, 107).stroke_width(1),
            ))
            .map_err(err)?;
        if i == 0 {
            drawn
                .label(if paths.len() > 1 {
                    "centres of mass"
                } else {
                    "centre of mass"
                })
                .legend(|(x, y)| {
                    PathElement::new(
                        vec![(x, y), (x + 18, y)],
                        RGBColor(8, 48, 107).stroke_width(2),
                    )
                });
        }
    }
    if !tip.is_empty() {
        chart
            .draw_series(LineSeries::new(
                tip.clone(),
                RGBColor(230, 85, 13).stroke_width(1),
            ))
            .map_err(err)?
            .label("contact point")
            .legend(|(x, y)| {
                PathElement::new(
                    vec![(x, y), (x + 18, y)],
                    RGBColor(230, 85, 13).stroke_width(2),
                )
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

/// Outline segments (or a circle) of each body at `q`.
fn outlines(shapes: &[Shape], poses: &[Pose<f64>]) -> Vec<Vec<(f64, f64)>> {
    shapes
        .iter()
        .zip(poses)
        .map(|(shape, p)| match *shape {
            Shape::Ball(r) => {
                let mut pts: Vec<(f64, f64)> = (0..=48)
                    .map(|i| {
                        let a = std::f64::consts::TAU * i as f64 / 48.0;
                        (p.x + r * a.cos(), p.y + r * a.sin())
                    })
                    .collect();
                pts.push((p.x, p.y));
                pts.push((p.x + r * p.angle.cos(), p.y + r * p.angle.sin()));
                pts
            }
            Shape::Rod(l) => {
                let (s, c) = p.angle.sin_cos();
                vec![
                    (p.x - 0.5 * l * c, p.y - 0.5 * l * s),
                    (p.x + 0.5 * l * c, p.y + 0.5 * l * s),
                ]
            }
            Shape::Pendulum(l) => {
                let (s, c) = p.angle.sin_cos();
                vec![
                    (p.x - 0.5 * l * s, p.y + 0.5 * l * c),
                    (p.x + 0.5 * l * s, p.y - 0.5 * l * c),
                ]
            }
            Shape::Block(b, h) => {
                let c = crate::output::animation::block_corners(p, b, h);
                vec![c[0], c[1], c[2], c[3], c[0]]
            }
        })
        .collect()
}
