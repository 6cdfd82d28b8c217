//! The bodies' motion after the impact, one law's velocities after at a time, for the page's
//! animations: poses `[x, y, θ]` of every body at [`FRAMES`] + 1 equal steps of one window of
//! time shared by the laws (so that the laws' pictures run side by side at the same pace).
//!
//! * **On the floor** (rod, block): the core's event-driven simulation
//!   ([`impax::simulation::simulate`]) from the configuration at the impact with the law's
//!   velocities after, under gravity, with the contacts left touching at zero normal velocity
//!   closed (a block rocking on about its other corner, a rod sliding on the floor), until the
//!   next impact (not resolved: `max_impacts = 0`), rest, or [`HORIZON`].
//! * **On a table** (cradle, ball–ball–wall): free motion at the velocities after (no gravity
//!   in the plane), until two balls meet again or a ball reaches the wall.
//!
//! After its end a law's bodies hold their last pose. The window is the latest end among the
//! laws on the floor (the rebound of the slowest law, [`REST_WINDOW`] when every law leaves
//! the bodies at rest at once) and `4 r / v_max` on a table.

use super::system::{Layout, Outline, System};
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::{dynamics, Mechanism};
use impax::ode::Tolerances;
use impax::simulation::{simulate, SimulationOptions, StopReason};
use impax::LawId;
use serde_json::{json, Value};

/// Frames of a law's motion after the first (the poses at the impact).
pub const FRAMES: usize = 120;

/// The longest motion simulated after the impact, seconds.
pub const HORIZON: f64 = 3.0;

/// The integration's tolerances: a picture's (the run's events are still located to
/// round-off).
pub const TOLERANCES: Tolerances = Tolerances {
    relative: 1e-9,
    absolute: 1e-12,
};

/// The window when every law leaves the bodies at rest at once, seconds.
pub const REST_WINDOW: f64 = 0.25;

/// A law's motion after the impact.
#[derive(Debug, Clone)]
pub struct Motion {
    /// Times and configurations, from the impact (`t = 0`) to the end.
    samples: Vec<(f64, Vec<f64>)>,
    /// When the motion ends (the bodies hold their pose after).
    pub end_time: f64,
    /// How it ends: `next-impact`, `rest`, `moving` (still moving at [`HORIZON`]), `meets`
    /// (two balls meet again), `wall` (a ball reaches the wall), or the simulation's stop
    /// id (`painleve`, `unsupported-contact`, …), or `error`.
    pub end: &'static str,
    /// The end in words.
    pub text: String,
}

impl Motion {
    /// The configuration at `t` (linear between samples; held after the end).
    fn at(&self, t: f64) -> Vec<f64> {
        let s = &self.samples;
        let k = s.partition_point(|(ts, _)| *ts <= t);
        if k == 0 {
            return s[0].1.clone();
        }
        if k >= s.len() {
            return s[s.len() - 1].1.clone();
        }
        let ((t0, q0), (t1, q1)) = (&s[k - 1], &s[k]);
        let f = if t1 > t0 { (t - t0) / (t1 - t0) } else { 1.0 };
        q0.iter().zip(q1).map(|(a, b)| a + f * (b - a)).collect()
    }

    /// The poses over `[0, window]` as JSON, with the end.
    pub fn to_json(&self, window: f64) -> Value {
        let frames: Vec<Value> = (0..=FRAMES)
            .map(|k| {
                let q = self.at(window * k as f64 / FRAMES as f64);
                Value::Array(
                    q.chunks(3)
                        .map(|p| {
                            json!([
                                crate::report::num(p[0]),
                                crate::report::num(p[1]),
                                crate::report::num(p[2])
                            ])
                        })
                        .collect(),
                )
            })
            .collect();
        json!({
            "poses": frames,
            "end": { "id": self.end, "time": crate::report::num(self.end_time), "text": self.text },
        })
    }
}

/// The motion after the impact with the velocities after `u` of `law`.
pub fn after(system: &System, law: LawId, u: &[f64]) -> Motion {
    match (&system.mechanism, system.layout) {
        (Some(m), _) => on_floor(m, system, law, u),
        (None, layout) => on_table(system, layout, u),
    }
}

/// The window shared by the laws' motions, `afters` their velocities after.
pub fn window(system: &System, motions: &[Motion], afters: &[&[f64]]) -> f64 {
    if system.layout == Layout::Floor {
        let last = motions.iter().map(|m| m.end_time).fold(0.0, f64::max);
        return if last > 0.0 { last } else { REST_WINDOW };
    }
    let before = system.scenario.impact.velocities_before();
    let fastest = afters.iter().fold(speed(before), |m, u| m.max(speed(u)));
    4.0 * radius(system) / fastest.max(f64::MIN_POSITIVE)
}

/// The largest speed of a body's centre.
fn speed(u: &[f64]) -> f64 {
    u.chunks(3).map(|v| v[0].hypot(v[1])).fold(0.0, f64::max)
}

/// The balls' radius (0 for other bodies).
fn radius(system: &System) -> f64 {
    match system.outlines.first() {
        Some(Outline::Ball { radius }) => *radius,
        _ => 0.0,
    }
}

fn on_floor(m: &BuiltIn, system: &System, law: LawId, u: &[f64]) -> Motion {
    let mut options = SimulationOptions::new(law, system.friction, system.restitution, HORIZON);
    options.max_impacts = 0;
    options.sample_interval = HORIZON / 3000.0;
    options.tolerances = TOLERANCES;
    let q0 = &system.q;
    let run = match simulate(m, q0, u, &options) {
        Ok(run) => run,
        Err(e) => {
            return Motion {
                samples: vec![(0.0, q0.clone())],
                end_time: 0.0,
                end: "error",
                text: format!("the motion after could not be simulated: {e}"),
            }
        }
    };
    let samples: Vec<(f64, Vec<f64>)> = run.samples.iter().map(|s| (s.t, s.q.clone())).collect();
    let t = run.end_time;
    let last = samples.last().map_or(q0.clone(), |s| s.1.clone());
    let (end, text) = match &run.stop {
        StopReason::ImpactLimit => {
            let struck = striking(m, &last, run.samples.last().map_or(u, |s| &s.u));
            (
                "next-impact",
                format!("{struck} strikes the floor at t = {t:.3} s"),
            )
        }
        StopReason::Rest => ("rest", format!("at rest on the floor from t = {t:.3} s")),
        StopReason::TimeLimit => ("moving", format!("still moving at t = {t:.1} s")),
        other => (
            other.id(),
            format!("the simulation stops at t = {t:.3} s ({})", other.id()),
        ),
    };
    Motion {
        samples,
        end_time: t,
        end,
        text,
    }
}

/// The contact that strikes at `q` with velocities `u`: the touching one approaching fastest.
fn striking(m: &BuiltIn, q: &[f64], u: &[f64]) -> &'static str {
    let contacts = m.contacts();
    (0..contacts.len())
        .filter(|&k| dynamics::gap(m, k, q).abs() <= dynamics::touching_tolerance(m, k, q))
        .min_by(|&a, &b| dynamics::gap_rate(m, a, q, u).total_cmp(&dynamics::gap_rate(m, b, q, u)))
        .map_or("a contact", |k| contacts[k].name)
}

/// Free motion of balls on a table until two meet again or one reaches the wall.
fn on_table(system: &System, layout: Layout, u: &[f64]) -> Motion {
    let q0 = &system.q;
    let balls = q0.len() / 3;
    let r = radius(system);
    // Relative velocities below round-off of the impact's speeds are not an approach.
    let tol = 1e-9 * speed(system.scenario.impact.velocities_before()).max(speed(u));
    let mut end = (f64::INFINITY, "moving", String::new());
    for i in 0..balls {
        for j in i + 1..balls {
            let d = [q0[3 * j] - q0[3 * i], q0[3 * j + 1] - q0[3 * i + 1]];
            let w = [u[3 * j] - u[3 * i], u[3 * j + 1] - u[3 * i + 1]];
            if let Some(t) = meeting(d, w, 2.0 * r, tol) {
                if t < end.0 {
                    end = (
                        t,
                        "meets",
                        format!("balls {} and {} meet again", i + 1, j + 1),
                    );
                }
            }
        }
    }
    if layout == Layout::Wall && u[0] < -tol {
        let t = ((q0[0] - r) / -u[0]).max(0.0);
        if t < end.0 {
            end = (t, "wall", "ball 1 reaches the wall again".into());
        }
    }
    let (t_end, id, what) = end;
    // Two samples: the impact and the end (or far beyond any window): the motion is linear.
    let t1 = if t_end.is_finite() { t_end } else { 1e300 };
    let q1 = q0.iter().zip(u).map(|(q, v)| q + v * t1).collect();
    let text = if t_end.is_finite() {
        format!("{what} at t = {t_end:.3} s")
    } else {
        "the balls move apart".into()
    };
    Motion {
        samples: vec![(0.0, q0.clone()), (t1, q1)],
        end_time: t_end,
        end: id,
        text,
    }
}

/// The first time `t ≥ 0` at which `|d + w t|` falls to `reach`, approaching faster than
/// `tol` along `d` (`None` if never).
fn meeting(d: [f64; 2], w: [f64; 2], reach: f64, tol: f64) -> Option<f64> {
    let a = w[0] * w[0] + w[1] * w[1];
    let b = d[0] * w[0] + d[1] * w[1];
    if a == 0.0 || b >= -tol * d[0].hypot(d[1]) {
        return None;
    }
    let c = d[0] * d[0] + d[1] * d[1] - reach * reach;
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    // The smaller root of a t² + 2 b t + c = 0 (b < 0), written without cancellation.
    let t = c / (-b + disc.sqrt());
    Some(t.max(0.0))
}
