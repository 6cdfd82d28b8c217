//! The frames of the animation: the geometry of every drawn element and the energy `T + V`,
//! at equal steps of time through the run.

use crate::commands::simulate::Shape;
use impax::mechanism::{Mechanism, Pose};
use impax::simulation::Run;

/// The motion at equal steps of time.
pub(super) struct Frames {
    /// The time the run covers (at least a millisecond).
    pub(super) duration: f64,
    /// Per frame, per drawn element, its numbers ([`geometry`]).
    pub(super) geo: Vec<Vec<Vec<f64>>>,
    /// Per frame, `T + V` of the last sample at or before it.
    pub(super) energy: Vec<f64>,
}

impl Frames {
    /// Sixty frames a second of motion, between 60 and 1200 frames.
    pub(super) fn of<M: Mechanism>(m: &M, shapes: &[Shape], run: &Run) -> Self {
        let duration = run.end_time.max(1e-3);
        let frames = ((duration * 60.0) as usize).clamp(60, 1200);
        let nb = m.bodies().len();
        let mut poses = vec![Pose::new(0.0, 0.0, 0.0); nb];
        let mut geo: Vec<Vec<Vec<f64>>> = Vec::with_capacity(frames + 1);
        let mut energy = Vec::with_capacity(frames + 1);
        let e_of = |t: f64| {
            let i = run.samples.partition_point(|x| x.t <= t).max(1) - 1;
            let s = &run.samples[i];
            s.kinetic + s.potential
        };
        for f in 0..=frames {
            let t = duration * f as f64 / frames as f64;
            m.poses(&q_at(run, t), &mut poses);
            geo.push(geometry(shapes, &poses));
            energy.push(e_of(t));
        }
        Frames {
            duration,
            geo,
            energy,
        }
    }
}

/// Geometry of every drawn element at one frame: a list of numbers per element.
fn geometry(shapes: &[Shape], poses: &[Pose<f64>]) -> Vec<Vec<f64>> {
    let mut out = Vec::new();
    for (shape, p) in shapes.iter().zip(poses) {
        match *shape {
            Shape::Ball(r) => {
                out.push(vec![p.x, p.y]);
                out.push(vec![
                    p.x,
                    p.y,
                    p.x + r * p.angle.cos(),
                    p.y + r * p.angle.sin(),
                ]);
            }
            Shape::Rod(l) => {
                let (s, c) = p.angle.sin_cos();
                out.push(vec![
                    p.x - 0.5 * l * c,
                    p.y - 0.5 * l * s,
                    p.x + 0.5 * l * c,
                    p.y + 0.5 * l * s,
                ]);
            }
            Shape::Pendulum(l) => {
                let (s, c) = p.angle.sin_cos();
                out.push(vec![
                    p.x - 0.5 * l * s,
                    p.y + 0.5 * l * c,
                    p.x + 0.5 * l * s,
                    p.y - 0.5 * l * c,
                ]);
            }
            Shape::Block(b, h) => {
                // The four edges B–C, C–D, D–A, A–B (the path traced follows the last one's end, B).
                let corners = block_corners(p, b, h);
                for i in 0..4 {
                    let (a, z) = (corners[(i + 1) % 4], corners[(i + 2) % 4]);
                    out.push(vec![a.0, a.1, z.0, z.1]);
                }
            }
        }
    }
    out
}

/// The corners of a block at pose `p`: A (−b, −h), B (b, −h), C (b, h), D (−b, h) rotated.
pub(crate) fn block_corners(p: &Pose<f64>, b: f64, h: f64) -> [(f64, f64); 4] {
    let (s, c) = p.angle.sin_cos();
    [(-b, -h), (b, -h), (b, h), (-b, h)].map(|(x, y)| (p.x + c * x - s * y, p.y + s * x + c * y))
}

/// The height of the mechanism's floor: the first contact with a fixed horizontal surface
/// (`None` when every contact is between bodies, as in a cradle).
pub(crate) fn floor<M: Mechanism>(m: &M) -> Option<f64> {
    m.contacts()
        .iter()
        .enumerate()
        .find(|(k, c)| m.surface_body(*k).is_none() && c.surface.normal.x == 0.0)
        .map(|(_, c)| c.surface.point.y)
}

/// The state's coordinates at time `t`, linearly interpolated between samples.
fn q_at(run: &Run, t: f64) -> Vec<f64> {
    let s = &run.samples;
    let i = s.partition_point(|x| x.t <= t);
    if i == 0 {
        return s[0].q.clone();
    }
    if i >= s.len() {
        return s[s.len() - 1].q.clone();
    }
    let (a, b) = (&s[i - 1], &s[i]);
    let w = if b.t > a.t {
        (t - a.t) / (b.t - a.t)
    } else {
        1.0
    };
    a.q.iter().zip(&b.q).map(|(x, y)| x + w * (y - x)).collect()
}
