//! Energy bars per law: `ΔT/T0` split into normal work and friction work
//! (`ΔT = W_n + W_t`, theory §1), or into the body's translational and rotational parts
//! (paper A §5). Horizontal bars, one row per law; a breakdown is written as such.

use super::map::tick;
use super::{err, text, DrawResult};
use impax::LawId;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The energy numbers of one law, normalised by `T0` (`None`: the law broke down).
#[derive(Debug, Clone)]
pub struct EnergyRow {
    pub law: LawId,
    /// `(W_n, W_t, ΔT, ΔT_translational, ΔT_rotational)` / T0.
    pub values: Option<[f64; 5]>,
}

/// Which split to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Split {
    /// Normal work and friction work.
    Work,
    /// Translational and rotational parts.
    Parts,
}

/// Draw one bar chart of `rows` on `area`.
pub fn draw_bars<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    rows: &[EnergyRow],
    split: Split,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let (caption, parts): (&str, [(&str, RGBColor, usize); 3]) = match split {
        Split::Work => (
            "ΔT / T0 = normal work + friction work",
            [
                ("normal work W_n / T0", RGBColor(31, 119, 180), 0),
                ("friction work W_t / T0", RGBColor(255, 127, 14), 1),
                ("ΔT / T0", RGBColor(40, 40, 40), 2),
            ],
        ),
        Split::Parts => (
            "ΔT / T0 = translational + rotational (paper A §5)",
            [
                ("translational ΔT₁ / T0", RGBColor(44, 160, 44), 3),
                ("rotational ΔT₂ / T0", RGBColor(148, 103, 189), 4),
                ("ΔT / T0", RGBColor(40, 40, 40), 2),
            ],
        ),
    };
    let mut lo = 0.0f64;
    let mut hi = 0.0f64;
    for r in rows.iter().filter_map(|r| r.values) {
        for (_, _, k) in parts {
            lo = lo.min(r[k]);
            hi = hi.max(r[k]);
        }
    }
    let span = (hi - lo).max(1e-12);
    let (x0, x1) = (lo - 0.08 * span, hi + 0.08 * span);
    let n = rows.len().max(1) as f64;
    // The legend: one line above the chart, where it hides no bar.
    let (strip, area) = area.split_vertically(56);
    let mut lx = 110;
    for (name, col, _) in parts {
        strip
            .draw(&Rectangle::new([(lx, 36), (lx + 16, 48)], col.filled()))
            .map_err(err)?;
        strip
            .draw(&Text::new(name.to_string(), (lx + 22, 35), text(13.0)))
            .map_err(err)?;
        lx += 40 + 8 * name.chars().count() as i32;
    }
    strip
        .draw(&Text::new(caption.to_string(), (110, 6), text(16.0)))
        .map_err(err)?;
    let mut chart = ChartBuilder::on(&area)
        .margin(10)
        .margin_right(24)
        .x_label_area_size(40)
        .y_label_area_size(100)
        .build_cartesian_2d(x0..x1, -0.5..n - 0.5)
        .map_err(err)?;
    let names: Vec<String> = rows.iter().map(|r| r.law.to_string()).collect();
    let label = move |y: &f64| {
        let i = y.round();
        if (y - i).abs() < 1e-6 && i >= 0.0 && (i as usize) < names.len() {
            // Row 0 at the top.
            names[names.len() - 1 - i as usize].clone()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_y_mesh()
        .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(220, 220, 220))
        .y_labels(rows.len() * 2 + 1)
        .y_label_formatter(&label)
        .x_label_formatter(&|x| tick(*x))
        .x_desc("energy / T0 (T0: translational kinetic energy before)")
        .label_style(text(13.0))
        .axis_desc_style(text(13.0))
        .draw()
        .map_err(err)?;
    let h = 0.26;
    for (i, r) in rows.iter().enumerate() {
        let yc = n - 1.0 - i as f64;
        match r.values {
            Some(v) => {
                for (j, (_, col, k)) in parts.iter().enumerate() {
                    let top = yc + 0.39 - j as f64 * h;
                    chart
                        .draw_series(std::iter::once(Rectangle::new(
                            [(0.0, top), (v[*k], top - h + 0.03)],
                            col.filled(),
                        )))
                        .map_err(err)?;
                }
            }
            None => {
                chart
                    .draw_series(std::iter::once(Text::new(
                        "breakdown (no result)".to_string(),
                        (x0 + 0.02 * (x1 - x0), yc + 0.15),
                        text(13.0),
                    )))
                    .map_err(err)?;
            }
        }
    }
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(0.0, -0.5), (0.0, n - 0.5)],
            BLACK.stroke_width(1),
        )))
        .map_err(err)?;
    Ok(())
}
