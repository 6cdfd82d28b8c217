//! The diagram's window in impulse space: every path point, the origin, the Newton line's
//! normal impulse and the line of sticking's ends, with room above for the legend; and the
//! straight lines of the diagram clipped to it.

use super::RouthFigure;

/// The window `[x0, x1] × [y0, y1]` in `(p_t, p_n)`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Window {
    pub(super) x0: f64,
    pub(super) x1: f64,
    pub(super) y0: f64,
    pub(super) y1: f64,
}

impl Window {
    /// The window of a figure's problem and paths.
    pub(super) fn of(figure: &RouthFigure) -> Self {
        let p = &figure.problem;
        let (a, b, c) = (p.wtt(), p.wtn(), p.wnn());
        let v = p.velocity();
        let e = p.restitution();
        // Extent: every path point, the origin, and the Newton line's normal impulse.
        let pn_newton = -(1.0 + e) * v.y / c;
        let mut pt = (0.0f64, 0.0f64);
        let mut pn_max = pn_newton.max(0.0);
        for path in &figure.paths {
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
        Window { x0, x1, y0, y1 }
    }

    /// The straight line `u x + v y = w` clipped to the window (two end points: no jaggies).
    pub(super) fn clip(&self, u: f64, v: f64, w: f64) -> Vec<(f64, f64)> {
        let Window { x0, x1, y0, y1 } = *self;
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
    }
}
