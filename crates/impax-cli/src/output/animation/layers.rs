//! The layers of the SVG document, back to front: the title, the floor, the path traced, the
//! bodies (animated), the clock bar and the energy bar.

use super::view::View;
use crate::commands::simulate::{Case, Shape};
use std::fmt::Write;

/// The document's opening tag, its white background and the title line.
pub(super) fn title(s: &mut String, view: &View, case: &Case, duration: f64, pace: &str) {
    let (w, h) = (view.w, view.h);
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
}

/// The floor at height `floor`: grey below, a line on top.
pub(super) fn floor(s: &mut String, view: &View, floor: f64) {
    let (w, h) = (view.w, view.h);
    let fy = view.sy(floor);
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

/// The path traced by the first element (a ball's centre, a rod's end, a pendulum's tip).
pub(super) fn trace(s: &mut String, view: &View, geo: &[Vec<Vec<f64>>]) {
    let mut trace = String::new();
    for frame in geo {
        let el = frame.last().expect("an element");
        let (px, py) = if el.len() == 2 {
            (el[0], el[1])
        } else {
            (el[2], el[3])
        };
        let _ = write!(trace, "{:.2},{:.2} ", view.sx(px), view.sy(py));
    }
    let _ = writeln!(
        s,
        r##"<polyline points="{trace}" fill="none" stroke="#9ecae1" stroke-width="1.5" stroke-dasharray="4 3"/>"##
    );
}

/// The bodies, each element animated through the frames over `dur` (looping), and a
/// pendulum's pivot.
pub(super) fn bodies(
    s: &mut String,
    view: &View,
    shapes: &[Shape],
    geo: &[Vec<Vec<f64>>],
    dur: &str,
) {
    let sx = |x: f64| view.sx(x);
    let sy = |y: f64| view.sy(y);
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
    for shape in shapes {
        match *shape {
            Shape::Ball(r) => {
                let _ = writeln!(
                    s,
                    r##"<circle r="{:.2}" fill="#3182bd" stroke="#08306b" stroke-width="2">{}{}</circle>"##,
                    r * view.scale,
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
    if shapes.iter().any(|s| matches!(s, Shape::Pendulum(_))) {
        let _ = writeln!(
            s,
            r##"<circle cx="{:.2}" cy="{:.2}" r="5" fill="#000"/>"##,
            sx(0.0),
            sy(0.0)
        );
    }
}

/// The clock bar (filling in time) and the energy bar (its length following `T + V` between
/// its least and largest values), each over `dur`, looping.
pub(super) fn bars(s: &mut String, view: &View, energy: &[f64], dur: &str) {
    let h = view.h;
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
}
