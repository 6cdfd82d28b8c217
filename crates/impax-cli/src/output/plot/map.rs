//! Maps of a 2-parameter sweep: one panel per law, the cells drawn as one raster image per
//! panel (a few kilobytes in SVG whatever the grid size), with axes and units, a legend for
//! categories or a colour bar for a scalar, and line overlays (boundaries, thresholds).

use super::{colour, err, text, DrawResult, Figure};
use plotters::coord::Shift;
use plotters::element::BitMapElement;
use plotters::prelude::*;

/// One axis of the map: the grid's values and a label with units.
#[derive(Debug, Clone)]
pub struct MapAxis {
    pub label: String,
    pub start: f64,
    pub stop: f64,
    pub count: u64,
}

impl MapAxis {
    fn nearest(&self, x: f64) -> usize {
        if self.count <= 1 {
            return 0;
        }
        let t = (x - self.start) / (self.stop - self.start) * (self.count - 1) as f64;
        (t.round().max(0.0) as usize).min(self.count as usize - 1)
    }
    /// The drawn range (a single value is widened so that the axis has a length).
    fn range(&self) -> (f64, f64) {
        if self.stop > self.start {
            (self.start, self.stop)
        } else {
            (self.start - 0.5, self.start + 0.5)
        }
    }
}

/// The cells of every panel: `data[k][ix * ny + iy]` for law (panel) `k`.
#[derive(Debug, Clone)]
pub enum Cells {
    /// Categories: a class index per cell and `(label, colour)` per class.
    Categories {
        data: Vec<Vec<u8>>,
        classes: Vec<(String, RGBColor)>,
    },
    /// A scalar per cell (NaN: no value), coloured on `[lo, hi]`.
    Scalar {
        data: Vec<Vec<f32>>,
        label: String,
        lo: f64,
        hi: f64,
        diverging: bool,
    },
}

/// A line drawn over a panel.
#[derive(Debug, Clone)]
pub struct Overlay {
    /// Panel index.
    pub panel: usize,
    /// Legend text (shown once per distinct label).
    pub label: String,
    /// Polylines (each a run of points).
    pub runs: Vec<Vec<(f64, f64)>>,
    pub colour: RGBColor,
    pub width: u32,
    pub dashed: bool,
    /// Draw the points as markers rather than lines.
    pub markers: bool,
}

/// A map figure.
#[derive(Debug, Clone)]
pub struct MapFigure {
    pub title: String,
    pub subtitle: String,
    pub x: MapAxis,
    pub y: MapAxis,
    pub panels: Vec<String>,
    pub cells: Cells,
    pub overlays: Vec<Overlay>,
}

impl MapFigure {
    /// Panel grid `(columns, rows)`.
    pub fn layout(&self) -> (usize, usize) {
        let n = self.panels.len().max(1);
        let cols = match n {
            1 => 1,
            2 | 4 => 2,
            3 | 5 | 6 | 9 => 3,
            _ => 4,
        };
        (cols, n.div_ceil(cols))
    }

    /// A size that gives each panel about 440 × 380 pixels.
    pub fn default_size(&self) -> (u32, u32) {
        let (c, r) = self.layout();
        let w = 60 + 440 * c as u32 + LEGEND_WIDTH;
        let mut h = 80 + 380 * r as u32;
        // A colour bar needs height beside the overlays' legend.
        if matches!(self.cells, Cells::Scalar { .. }) && !self.overlays.is_empty() {
            h = h.max(680);
        }
        if c == 1 {
            (w + 300, h.max(720))
        } else {
            (w, h)
        }
    }

    fn colour_of(&self, panel: usize, idx: usize) -> RGBColor {
        match &self.cells {
            Cells::Categories { data, classes } => {
                let k = data[panel][idx] as usize;
                classes.get(k).map_or(colour::NO_VALUE, |c| c.1)
            }
            Cells::Scalar {
                data,
                lo,
                hi,
                diverging,
                ..
            } => {
                let v = data[panel][idx] as f64;
                if !v.is_finite() {
                    return colour::NO_VALUE;
                }
                scalar_colour(v, *lo, *hi, *diverging)
            }
        }
    }
}

const LEGEND_WIDTH: u32 = 250;

/// Colour of a value on `[lo, hi]`; a diverging map puts white at zero.
pub fn scalar_colour(v: f64, lo: f64, hi: f64, diverging: bool) -> RGBColor {
    if diverging {
        let m = lo.abs().max(hi.abs()).max(f64::MIN_POSITIVE);
        colour::diverging(0.5 + 0.5 * v / m)
    } else {
        let span = hi - lo;
        colour::viridis(if span > 0.0 { (v - lo) / span } else { 0.5 })
    }
}

/// Tick label: few digits, no trailing noise.
pub fn tick(v: f64) -> String {
    // Axis key points computed as sums land a few ulps off zero.
    if v.abs() < 1e-10 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e5).contains(&a) {
        return format!("{v:.1e}");
    }
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

impl Figure for MapFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let (w, _h) = root.dim_in_pixel();
        let (title_area, rest) = root.split_vertically(64);
        title_area
            .draw(&Text::new(
                self.title.clone(),
                (16, 8),
                text(22.0).color(&BLACK),
            ))
            .map_err(err)?;
        title_area
            .draw(&Text::new(
                self.subtitle.clone(),
                (16, 38),
                text(15.0).color(&RGBColor(70, 70, 70)),
            ))
            .map_err(err)?;
        let (panels_area, legend_area) = rest.split_horizontally(w.saturating_sub(LEGEND_WIDTH));
        let (cols, rows) = self.layout();
        let areas = panels_area.split_evenly((rows, cols));
        for (k, name) in self.panels.iter().enumerate() {
            self.draw_panel(&areas[k], k, name)?;
        }
        self.draw_legend(&legend_area)
    }
}

impl MapFigure {
    fn draw_panel<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: usize,
        name: &str,
    ) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let (x0, x1) = self.x.range();
        let (y0, y1) = self.y.range();
        let mut chart = ChartBuilder::on(area)
            .caption(name, text(18.0))
            .margin(8)
            .margin_right(18)
            .x_label_area_size(46)
            .y_label_area_size(62)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(self.x.label.clone())
            .y_desc(self.y.label.clone())
            .x_labels(7)
            .y_labels(7)
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .label_style(text(13.0))
            .axis_desc_style(text(14.0))
            .draw()
            .map_err(err)?;
        // The raster: one pixel per plotting-area pixel, the nearest grid cell's colour.
        let (px, py) = chart.plotting_area().get_pixel_range();
        let (pw, ph) = (
            (px.end - px.start).max(1) as u32,
            (py.end - py.start).max(1) as u32,
        );
        let ny = self.y.count as usize;
        let mut buf = vec![0u8; (pw * ph * 3) as usize];
        for j in 0..ph {
            let y = y1 - (j as f64 + 0.5) / ph as f64 * (y1 - y0);
            let iy = self.y.nearest(y);
            for i in 0..pw {
                let x = x0 + (i as f64 + 0.5) / pw as f64 * (x1 - x0);
                let ix = self.x.nearest(x);
                let c = self.colour_of(k, ix * ny + iy);
                let o = ((j * pw + i) * 3) as usize;
                buf[o] = c.0;
                buf[o + 1] = c.1;
                buf[o + 2] = c.2;
            }
        }
        let image = BitMapElement::with_owned_buffer((x0, y1), (pw, ph), buf)
            .ok_or("raster buffer too small")?;
        chart.draw_series(std::iter::once(image)).map_err(err)?;
        for o in self.overlays.iter().filter(|o| o.panel == k) {
            let style = ShapeStyle::from(&o.colour).stroke_width(o.width);
            for run in &o.runs {
                if o.markers {
                    chart
                        .draw_series(
                            run.iter()
                                .map(|&p| Circle::new(p, o.width as i32 + 3, o.colour.filled())),
                        )
                        .map_err(err)?;
                    chart
                        .draw_series(
                            run.iter().map(|&p| {
                                Circle::new(p, o.width as i32 + 3, WHITE.stroke_width(1))
                            }),
                        )
                        .map_err(err)?;
                } else if o.dashed {
                    chart
                        .draw_series(DashedLineSeries::new(run.iter().copied(), 9, 6, style))
                        .map_err(err)?;
                } else {
                    chart
                        .draw_series(LineSeries::new(run.iter().copied(), style))
                        .map_err(err)?;
                }
            }
        }
        // A frame around the plotting area.
        chart
            .plotting_area()
            .draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK.stroke_width(1)))
            .map_err(err)?;
        Ok(())
    }

    fn draw_legend<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult
    where
        DB::ErrorType: 'static,
    {
        let x = 10;
        let (_, h) = area.dim_in_pixel();
        // The overlays' legend (distinct labels), measured first.
        let mut items: Vec<(&Overlay, Vec<String>)> = Vec::new();
        for o in &self.overlays {
            if !items.iter().any(|(i, _)| i.label == o.label) {
                items.push((o, wrap(&o.label, 28)));
            }
        }
        let overlay_height: i32 = items.iter().map(|(_, l)| 16 * l.len() as i32 + 12).sum();
        let mut y = 40;
        match &self.cells {
            Cells::Categories { classes, .. } => {
                for (label, c) in classes {
                    area.draw(&Rectangle::new([(x, y), (x + 22, y + 16)], c.filled()))
                        .map_err(err)?;
                    area.draw(&Rectangle::new(
                        [(x, y), (x + 22, y + 16)],
                        BLACK.stroke_width(1),
                    ))
                    .map_err(err)?;
                    let lines = wrap(label, 26);
                    for (i, line) in lines.iter().enumerate() {
                        area.draw(&Text::new(
                            line.clone(),
                            (x + 30, y + 17 * i as i32),
                            text(14.0),
                        ))
                        .map_err(err)?;
                    }
                    y += 17 * lines.len() as i32 + 10;
                }
                y += 14;
            }
            Cells::Scalar {
                label,
                lo,
                hi,
                diverging,
                ..
            } => {
                for (i, line) in wrap(label, 28).iter().enumerate() {
                    area.draw(&Text::new(
                        line.clone(),
                        (x, 20 + 17 * i as i32),
                        text(14.0),
                    ))
                    .map_err(err)?;
                }
                let top = 70;
                let bottom = (h as i32 - 70 - overlay_height).max(top + 160);
                let (clo, chi) = if *diverging {
                    let m = lo.abs().max(hi.abs());
                    (-m, m)
                } else {
                    (*lo, *hi)
                };
                let bar = (x + 10, x + 40);
                for py in top..bottom {
                    let t = 1.0 - (py - top) as f64 / (bottom - top) as f64;
                    let c = scalar_colour(clo + t * (chi - clo), *lo, *hi, *diverging);
                    area.draw(&Rectangle::new([(bar.0, py), (bar.1, py + 1)], c.filled()))
                        .map_err(err)?;
                }
                area.draw(&Rectangle::new(
                    [(bar.0, top), (bar.1, bottom)],
                    BLACK.stroke_width(1),
                ))
                .map_err(err)?;
                let to_py = |v: f64| {
                    bottom
                        - ((bottom - top) as f64 * (v - clo) / (chi - clo).max(f64::MIN_POSITIVE))
                            .round() as i32
                };
                for v in nice_ticks(clo, chi, ((bottom - top) / 28).clamp(2, 12) as usize) {
                    let py = to_py(v);
                    area.draw(&PathElement::new(
                        vec![(bar.1, py), (bar.1 + 6, py)],
                        BLACK.stroke_width(1),
                    ))
                    .map_err(err)?;
                    area.draw(&Text::new(tick(v), (bar.1 + 10, py - 7), text(13.0)))
                        .map_err(err)?;
                }
                y = bottom + 16;
                area.draw(&Rectangle::new(
                    [(x, y), (x + 22, y + 16)],
                    colour::NO_VALUE.filled(),
                ))
                .map_err(err)?;
                area.draw(&Text::new(
                    "no value (breakdown/invalid)".to_string(),
                    (x + 30, y),
                    text(12.0),
                ))
                .map_err(err)?;
                y += 36;
            }
        }
        for (o, lines) in items {
            let style = ShapeStyle::from(&o.colour).stroke_width(o.width);
            if o.markers {
                area.draw(&Circle::new(
                    (x + 11, y + 8),
                    o.width as i32 + 3,
                    o.colour.filled(),
                ))
                .map_err(err)?;
            } else if o.dashed {
                for s in 0..3 {
                    let a = x + s * 9;
                    area.draw(&PathElement::new(vec![(a, y + 8), (a + 5, y + 8)], style))
                        .map_err(err)?;
                }
            } else {
                area.draw(&PathElement::new(vec![(x, y + 8), (x + 22, y + 8)], style))
                    .map_err(err)?;
            }
            for (i, line) in lines.iter().enumerate() {
                area.draw(&Text::new(
                    line.clone(),
                    (x + 30, y + 16 * i as i32),
                    text(13.0),
                ))
                .map_err(err)?;
            }
            y += 16 * lines.len() as i32 + 12;
        }
        Ok(())
    }
}

/// Round tick values (1, 2 or 5 times a power of ten apart) in `[lo, hi]`, about `n`.
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return vec![lo];
    }
    let raw = span / n.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Wrap text at spaces to lines of at most `width` characters.
pub fn wrap(s: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in s.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}
