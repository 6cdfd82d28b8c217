//! Newton's cradle: equal balls in a row on a frictionless horizontal table, meeting each
//! other along the row.

use super::positive;
use crate::error::{Error, Result};
use crate::math::Vec2;
use crate::mechanism::{BodyInertia, Contact, Mechanism, Pose, Real, Surface};

/// The most balls of a [`Cradle`].
pub const MAX_BALLS: usize = 20;

const NAMES: [&str; MAX_BALLS - 1] = [
    "balls 1–2",
    "balls 2–3",
    "balls 3–4",
    "balls 4–5",
    "balls 5–6",
    "balls 6–7",
    "balls 7–8",
    "balls 8–9",
    "balls 9–10",
    "balls 10–11",
    "balls 11–12",
    "balls 12–13",
    "balls 13–14",
    "balls 14–15",
    "balls 15–16",
    "balls 16–17",
    "balls 17–18",
    "balls 18–19",
    "balls 19–20",
];

const BALLS: [&str; MAX_BALLS] = [
    "ball 1", "ball 2", "ball 3", "ball 4", "ball 5", "ball 6", "ball 7", "ball 8", "ball 9",
    "ball 10", "ball 11", "ball 12", "ball 13", "ball 14", "ball 15", "ball 16", "ball 17",
    "ball 18", "ball 19", "ball 20",
];

/// `N` equal solid spheres (mass `m`, radius `r`, `I = 2 m r²/5`) moving on a horizontal
/// table (the plane of motion; gravity acts across it and does no work), in a row along `x`.
/// Coordinates `q = (x₁, y₁, θ₁, …, x_N, y_N, θ_N)`. Contact `j` (from 0), `balls j+1–j+2`,
/// is between ball `j + 1` (its point `(x_{j+1} − r, y_{j+1})`) and ball `j` (the surface, its
/// point `(x_j + r, y_j)`), normal `x̂`, tangent `−ŷ`: the gap is `x_{j+1} − x_j − 2r` and the
/// contact velocity is ball `j + 1`'s point relative to ball `j`'s (the contact rows of
/// [`crate::multi::scenarios::Cradle`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Cradle {
    bodies: Vec<BodyInertia>,
    radius: f64,
    coordinates: Vec<&'static str>,
    contacts: Vec<Contact>,
}

impl Cradle {
    /// `balls` equal balls.
    ///
    /// # Errors
    /// `balls` not from 2 to [`MAX_BALLS`]; mass or radius not finite and positive.
    pub fn new(balls: usize, mass: f64, radius: f64) -> Result<Self> {
        if !(2..=MAX_BALLS).contains(&balls) {
            return Err(Error::Invalid {
                field: "balls".into(),
                reason: format!("must be from 2 to {MAX_BALLS}, got {balls}"),
            });
        }
        let mass = positive("mass", mass)?;
        let radius = positive("radius", radius)?;
        const COORDS: [&str; 3 * MAX_BALLS] = coordinate_names();
        Ok(Cradle {
            bodies: (0..balls)
                .map(|i| BodyInertia {
                    name: BALLS[i],
                    mass,
                    inertia: 0.4 * mass * radius * radius,
                })
                .collect(),
            radius,
            coordinates: COORDS[..3 * balls].to_vec(),
            contacts: (0..balls - 1)
                .map(|j| Contact {
                    name: NAMES[j],
                    body: j + 1,
                    surface: Surface {
                        point: Vec2::zeros(),
                        normal: Vec2::new(1.0, 0.0),
                    },
                })
                .collect(),
        })
    }

    /// The number of balls.
    pub fn balls(&self) -> usize {
        self.bodies.len()
    }

    /// The balls' radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// `x1, y1, theta1, …, x20, y20, theta20`.
const fn coordinate_names() -> [&'static str; 3 * MAX_BALLS] {
    const X: [&str; MAX_BALLS] = [
        "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x13", "x14",
        "x15", "x16", "x17", "x18", "x19", "x20",
    ];
    const Y: [&str; MAX_BALLS] = [
        "y1", "y2", "y3", "y4", "y5", "y6", "y7", "y8", "y9", "y10", "y11", "y12", "y13", "y14",
        "y15", "y16", "y17", "y18", "y19", "y20",
    ];
    const T: [&str; MAX_BALLS] = [
        "theta1", "theta2", "theta3", "theta4", "theta5", "theta6", "theta7", "theta8", "theta9",
        "theta10", "theta11", "theta12", "theta13", "theta14", "theta15", "theta16", "theta17",
        "theta18", "theta19", "theta20",
    ];
    let mut out = [""; 3 * MAX_BALLS];
    let mut i = 0;
    while i < MAX_BALLS {
        out[3 * i] = X[i];
        out[3 * i + 1] = Y[i];
        out[3 * i + 2] = T[i];
        i += 1;
    }
    out
}

impl Mechanism for Cradle {
    fn coordinates(&self) -> &[&'static str] {
        &self.coordinates
    }
    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }
    fn gravity(&self) -> f64 {
        0.0
    }
    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        for (i, p) in poses.iter_mut().enumerate() {
            *p = Pose::new(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
        }
    }
    fn contacts(&self) -> &[Contact] {
        &self.contacts
    }
    fn contact_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        let i = k + 1;
        [q[3 * i] - self.radius, q[3 * i + 1]]
    }
    fn surface_body(&self, k: usize) -> Option<usize> {
        Some(k)
    }
    fn surface_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        [q[3 * k] + self.radius, q[3 * k + 1]]
    }
}
