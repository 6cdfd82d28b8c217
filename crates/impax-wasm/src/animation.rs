//! Frames of the approach and the rebound for the page's animation.
//!
//! The impact is instantaneous: before it each body moves with its velocities before, after
//! it with the law's velocities after (held constant: no gravity in the picture). Positions
//! are in a frame whose origin is the contact point at the impact and whose floor is
//! `y = 0`. A motion that would take a body through the floor (a spinning rod's other end,
//! a second contact the picture does not resolve) is cut there: the body rests in its last
//! pose above the floor.

use serde_json::{json, Value};

/// Frames in each half of the animation (approach, rebound).
pub const FRAMES: usize = 48;

/// A body's outline in its own frame at the instant of impact (turned by the pose's angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outline {
    /// A disc or sphere of this radius.
    Circle {
        /// Radius.
        radius: f64,
    },
    /// A rod through the centre along `direction` (radians from the floor's tangent).
    Segment {
        /// Half of its length.
        half_length: f64,
        /// Its direction at the impact.
        direction: f64,
    },
    /// An ellipse with its `a` axis along `direction`.
    Ellipse {
        /// Semi-axis along `direction`.
        a: f64,
        /// The other semi-axis.
        b: f64,
        /// Direction of the `a` axis at the impact.
        direction: f64,
    },
    /// Any body: the contact point from the centre and the radius of gyration.
    Rigid {
        /// Contact point from the centre, `(t, n)`, at the impact.
        contact: [f64; 2],
        /// `√(I/m)`.
        gyration: f64,
    },
}

impl Outline {
    /// The JSON the page draws.
    pub fn to_json(self) -> Value {
        match self {
            Outline::Circle { radius } => json!({ "kind": "circle", "radius": radius }),
            Outline::Segment {
                half_length,
                direction,
            } => json!({ "kind": "segment", "half_length": half_length, "direction": direction }),
            Outline::Ellipse { a, b, direction } => {
                json!({ "kind": "ellipse", "a": a, "b": b, "direction": direction })
            }
            Outline::Rigid { contact, gyration } => {
                json!({ "kind": "rigid", "contact": contact, "gyration": gyration })
            }
        }
    }

    /// The lowest height of the outline at pose `(x, y, angle)` (`angle` added to the
    /// outline's own).
    pub fn lowest(self, [_, y, angle]: [f64; 3]) -> f64 {
        match self {
            Outline::Circle { radius } => y - radius,
            Outline::Segment {
                half_length,
                direction,
            } => y - half_length * (direction + angle).sin().abs(),
            Outline::Ellipse { a, b, direction } => {
                let (s, c) = (direction + angle).sin_cos();
                y - ((a * s).powi(2) + (b * c).powi(2)).sqrt()
            }
            Outline::Rigid { contact, .. } => {
                let (s, c) = angle.sin_cos();
                y + s * contact[0] + c * contact[1]
            }
        }
    }

    /// A length of the outline (the tolerance of the floor test scales with it).
    fn size(self) -> f64 {
        match self {
            Outline::Circle { radius } => radius,
            Outline::Segment { half_length, .. } => half_length,
            Outline::Ellipse { a, b, .. } => a.max(b),
            Outline::Rigid { contact, gyration } => contact[0].hypot(contact[1]).max(gyration),
        }
    }
}

/// Poses `[x, y, angle]` of every body, one list per frame.
pub type Frames = Vec<Vec<[f64; 3]>>;

/// The frames of one half: `pose(t)` for `t` from `−τ` to 0 (`approach`) or 0 to `τ`, cut
/// where a body would pass through the floor.
pub fn half(
    outlines: &[Outline],
    tau: f64,
    approach: bool,
    pose: impl Fn(f64) -> Vec<[f64; 3]>,
) -> Frames {
    let tol = 1e-9 * outlines.iter().map(|o| o.size()).fold(0.0, f64::max);
    let through = |p: &[[f64; 3]]| outlines.iter().zip(p).any(|(o, &q)| o.lowest(q) < -tol);
    // Walk away from the impact (t = 0, always shown); once a pose goes through the floor,
    // hold the last one above it.
    let mut out: Frames = vec![pose(0.0)];
    let mut cut = false;
    for k in 1..=FRAMES {
        let t = tau * k as f64 / FRAMES as f64;
        let p = pose(if approach { -t } else { t });
        cut = cut || through(&p);
        let next = if cut { out[k - 1].clone() } else { p };
        out.push(next);
    }
    if approach {
        out.reverse();
    }
    out
}

/// Frames as JSON (`-0` as `0`).
pub fn to_json(frames: &Frames) -> Value {
    Value::Array(
        frames
            .iter()
            .map(|f| {
                Value::Array(
                    f.iter()
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
            .collect(),
    )
}
