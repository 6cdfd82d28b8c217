//! An animated SVG of a simulated motion (SMIL `<animate>` of each body's geometry, in real
//! time or slowed to at least four seconds, looping), with the floor, the path traced, a clock bar and an energy bar.

use crate::commands::simulate::{Case, Shape};
use impax::mechanism::{Mechanism, Pose};
use impax::simulation::Run;
use std::fmt::Write;

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

/// The animated SVG document.
pub fn svg(case: &Case, run: &Run) -> String {
    let m = &case.initial.mechanism;
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
        geo.push(geometry(&case.shapes, &poses));
        energy.push(e_of(t));
    }
    // World bounds (with the floor and the pivot of a pendulum).
    let floor_at = floor(m);
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut y0, mut y1) = match floor_at {
        Some(f) => (f, f),
        None => (f64::INFINITY, f64::NEG_INFINITY),
    };
    let pad = case
        .shapes
        .iter()
        .map(|s| if let Shape::Ball(r) = s { *r } else { 0.0 })
        .fold(0.0, f64::max);
    for frame in &geo {
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
    let scale = 1.0 / span;
    let cx = 0.5 * (x0 + x1);
    let sx = |x: f64| w / 2.0 + (x - cx) * scale;
    let sy = |y: f64| h - margin - 30.0 - (y - y0) * scale;
    // Short motions are slowed down to at least four seconds of playback.
    let playback = duration.max(4.0);
    let dur = format!("{playback:.4}s");
    let pace = if playback > duration {
        format!("slowed ×{:.1}", playback / duration)
    } else {
        "real time".to_string()
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, sans-serif">"##
    );
    let _ = writeln!(s, r##"<rect width="{w}" height="{h}" fill="#ffffff"/>"##);
    let _ = writeln!(
        s,
        r##"<text x="16" y="24" font-size="16">{} — {} (μ = {}, e = {}), {:.2} s of motion, {pace}</text>"##,
        case.name, case.options.law, case.options.friction, case.options.restitution, duration
    );
    // Floor.
    if let Some(floor) = floor_at {
        let fy = sy(floor);
        let _ = writeln!(
            s,
            r##"<rect x="0" y="{fy:.2}" width="{w}" height="{:.2}" fill="#d9d9d9"/>"##,
            h - fy
        );
        let _ = writeln!(
            s,
            r##"<line x1="0" y1="{fy:.2}" x2="{w}" y2="{fy:.2}" stroke="#444" stroke-width="2"/>"##
        );
    }
    // The path traced by the first element (a ball's centre, a rod's end, a pendulum's tip).
    let mut trace = String::new();
    for frame in &geo {
        let el = frame.last().expect("an element");
        let (px, py) = if el.len() == 2 {
            (el[0], el[1])
        } else {
            (el[2], el[3])
        };
        let _ = write!(trace, "{:.2},{:.2} ", sx(px), sy(py));
    }
    let _ = writeln!(
        s,
        r##"<polyline points="{trace}" fill="none" stroke="#9ecae1" stroke-width="1.5" stroke-dasharray="4 3"/>"##
    );
    let values = |k: usize, j: usize, f: &dyn Fn(f64) -> f64| {
        geo.iter()
            .map(|fr| format!("{:.2}", f(fr[k][j])))
            .collect::<Vec<_>>()
            .join(";")
    };
    let anim = |attr: &str, v: String| {
        format!(
            r##"<animate attributeName="{attr}" dur="{dur}" repeatCount="indefinite" calcMode="linear" values="{v}"/>"##
        )
    };
    let mut k = 0;
    for shape in &case.shapes {
        match *shape {
            Shape::Ball(r) => {
                let _ = writeln!(
                    s,
                    r##"<circle r="{:.2}" fill="#3182bd" stroke="#08306b" stroke-width="2">{}{}</circle>"##,
                    r * scale,
                    anim("cx", values(k, 0, &sx)),
                    anim("cy", values(k, 1, &sy))
                );
                k += 1;
                let _ = writeln!(
                    s,
                    r##"<line stroke="#ffffff" stroke-width="3">{}{}{}{}</line>"##,
                    anim("x1", values(k, 0, &sx)),
                    anim("y1", values(k, 1, &sy)),
                    anim("x2", values(k, 2, &sx)),
                    anim("y2", values(k, 3, &sy))
                );
                k += 1;
            }
            Shape::Block(..) => {
                for _ in 0..4 {
                    let _ = writeln!(
                        s,
                        r##"<line stroke="#08306b" stroke-width="4" stroke-linecap="round">{}{}{}{}</line>"##,
                        anim("x1", values(k, 0, &sx)),
                        anim("y1", values(k, 1, &sy)),
                        anim("x2", values(k, 2, &sx)),
                        anim("y2", values(k, 3, &sy))
                    );
                    k += 1;
                }
            }
            Shape::Rod(_) | Shape::Pendulum(_) => {
                let _ = writeln!(
                    s,
                    r##"<line stroke="#08306b" stroke-width="7" stroke-linecap="round">{}{}{}{}</line>"##,
                    anim("x1", values(k, 0, &sx)),
                    anim("y1", values(k, 1, &sy)),
                    anim("x2", values(k, 2, &sx)),
                    anim("y2", values(k, 3, &sy))
                );
                k += 1;
            }
        }
    }
    if case.shapes.iter().any(|s| matches!(s, Shape::Pendulum(_))) {
        let _ = writeln!(
            s,
            r##"<circle cx="{:.2}" cy="{:.2}" r="5" fill="#000"/>"##,
            sx(0.0),
            sy(0.0)
        );
    }
    // Clock bar and energy bar.
    let _ = writeln!(
        s,
        r##"<text x="16" y="{:.0}" font-size="13">time</text>"##,
        h - 14.0
    );
    let _ = writeln!(
        s,
        r##"<rect x="60" y="{:.0}" width="300" height="10" fill="none" stroke="#888"/>"##,
        h - 24.0
    );
    let _ = writeln!(
        s,
        r##"<rect x="60" y="{:.0}" height="10" fill="#636363"><animate attributeName="width" dur="{dur}" repeatCount="indefinite" values="0;300"/></rect>"##,
        h - 24.0
    );
    let (emin, emax) = energy
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &e| {
            (a.min(e), b.max(e))
        });
    let e_span = (emax - emin).max(1e-12 * emax.abs().max(1.0));
    let ew: Vec<String> = energy
        .iter()
        .map(|e| format!("{:.2}", 20.0 + 280.0 * (e - emin) / e_span))
        .collect();
    let _ = writeln!(
        s,
        r##"<text x="420" y="{:.0}" font-size="13">energy T + V</text>"##,
        h - 14.0
    );
    let _ = writeln!(
        s,
        r##"<rect x="520" y="{:.0}" width="300" height="10" fill="none" stroke="#888"/>"##,
        h - 24.0
    );
    let _ = writeln!(
        s,
        r##"<rect x="520" y="{:.0}" height="10" fill="#e6550d"><animate attributeName="width" dur="{dur}" repeatCount="indefinite" calcMode="linear" values="{}"/></rect>"##,
        h - 24.0,
        ew.join(";")
    );
    s.push_str("</svg>\n");
    s
}
