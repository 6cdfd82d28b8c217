//! Where the world goes on the page: the bounds of every frame (with the floor and a ball's
//! radius), scaled equally on both axes into the picture.

use crate::commands::simulate::Shape;

/// The picture's size and the world-to-page mapping.
pub(super) struct View {
    /// Width of the picture, pixels.
    pub(super) w: f64,
    /// Height of the picture, pixels.
    pub(super) h: f64,
    /// Margin around the world, pixels.
    margin: f64,
    /// Pixels per metre.
    pub(super) scale: f64,
    /// The world's horizontal centre, drawn at the middle of the picture.
    cx: f64,
    /// The world's lowest point, drawn above the bars.
    y0: f64,
}

impl View {
    /// The view that holds every frame of `geo` (and the floor at `floor_at`), each point
    /// padded by the largest ball's radius.
    pub(super) fn of(geo: &[Vec<Vec<f64>>], shapes: &[Shape], floor_at: Option<f64>) -> Self {
        let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut y0, mut y1) = match floor_at {
            Some(f) => (f, f),
            None => (f64::INFINITY, f64::NEG_INFINITY),
        };
        let pad = shapes
            .iter()
            .map(|s| if let Shape::Ball(r) = s { *r } else { 0.0 })
            .fold(0.0, f64::max);
        for frame in geo {
            for el in frame {
                for xy in el.chunks(2) {
                    x0 = x0.min(xy[0] - pad);
                    x1 = x1.max(xy[0] + pad);
                    y0 = y0.min(xy[1] - pad);
                    y1 = y1.max(xy[1] + pad);
                }
            }
        }
        let (w, h, margin) = (900.0, 520.0, 40.0);
        let span = ((x1 - x0) / (w - 2.0 * margin))
            .max((y1 - y0) / (h - 2.0 * margin - 40.0))
            .max(1e-9);
        View {
            w,
            h,
            margin,
            scale: 1.0 / span,
            cx: 0.5 * (x0 + x1),
            y0,
        }
    }

    /// The page's `x` of the world's `x`.
    pub(super) fn sx(&self, x: f64) -> f64 {
        self.w / 2.0 + (x - self.cx) * self.scale
    }

    /// The page's `y` of the world's `y` (downwards).
    pub(super) fn sy(&self, y: f64) -> f64 {
        self.h - self.margin - 30.0 - (y - self.y0) * self.scale
    }
}
