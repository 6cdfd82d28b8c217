//! Free planar bodies as mechanisms (`q = (x, y, θ)`), the checks of the automatic
//! mass matrix against `diag(m, m, I)` and of mechanism impacts against [`crate::bodies`].

use super::{gravity, positive};
use crate::error::Result;
use crate::mechanism::{BodyInertia, Contact, Mechanism, Pose, Real, Surface};

/// A sphere (or, with `inertia_factor = 1/2`, a disc) of mass `m`, radius `r`, central
/// inertia `k m r²` (`k = 2/5` for a sphere), moving in the plane above the floor `y = floor`;
/// its lowest point `(x, y − r)` is the contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Sphere {
    bodies: [BodyInertia; 1],
    radius: f64,
    gravity: f64,
    contacts: [Contact; 1],
}

impl Sphere {
    /// A solid sphere (`I = 2/5 m r²`).
    ///
    /// # Errors
    /// Mass or radius not finite and positive; gravity negative; non-finite floor.
    pub fn new(mass: f64, radius: f64, g: f64, floor: f64) -> Result<Self> {
        let mass = positive("mass", mass)?;
        let radius = positive("radius", radius)?;
        crate::error::finite("floor", floor)?;
        Ok(Sphere {
            bodies: [BodyInertia {
                name: "sphere",
                mass,
                inertia: 0.4 * mass * radius * radius,
            }],
            radius,
            gravity: gravity(g)?,
            contacts: [Contact {
                name: "lowest point",
                body: 0,
                surface: Surface::floor(floor),
            }],
        })
    }
}

impl Mechanism for Sphere {
    fn coordinates(&self) -> &[&'static str] {
        &["x", "y", "theta"]
    }
    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }
    fn gravity(&self) -> f64 {
        self.gravity
    }
    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        poses[0] = Pose::new(q[0], q[1], q[2]);
    }
    fn contacts(&self) -> &[Contact] {
        &self.contacts
    }
    fn contact_point<D: Real>(&self, _k: usize, q: &[D]) -> [D; 2] {
        [q[0], q[1] - self.radius]
    }
}

/// A uniform rod of mass `m` and length `l` (`I = m l²/12`) moving in the plane above the
/// floor `y = floor`; `θ` is its angle from the floor, and its lower end the contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Rod {
    bodies: [BodyInertia; 1],
    length: f64,
    gravity: f64,
    contacts: [Contact; 1],
}

impl Rod {
    /// A uniform rod.
    ///
    /// # Errors
    /// Mass or length not finite and positive; gravity negative; non-finite floor.
    pub fn new(mass: f64, length: f64, g: f64, floor: f64) -> Result<Self> {
        let mass = positive("mass", mass)?;
        let length = positive("length", length)?;
        crate::error::finite("floor", floor)?;
        Ok(Rod {
            bodies: [BodyInertia {
                name: "rod",
                mass,
                inertia: mass * length * length / 12.0,
            }],
            length,
            gravity: gravity(g)?,
            contacts: [Contact {
                name: "lower end",
                body: 0,
                surface: Surface::floor(floor),
            }],
        })
    }
}

impl Mechanism for Rod {
    fn coordinates(&self) -> &[&'static str] {
        &["x", "y", "theta"]
    }
    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }
    fn gravity(&self) -> f64 {
        self.gravity
    }
    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        poses[0] = Pose::new(q[0], q[1], q[2]);
    }
    fn contacts(&self) -> &[Contact] {
        &self.contacts
    }
    fn contact_point<D: Real>(&self, _k: usize, q: &[D]) -> [D; 2] {
        // The lower of the two ends.
        let (s, c) = q[2].sin_cos();
        let half = if s.re() >= 0.0 {
            -0.5 * self.length
        } else {
            0.5 * self.length
        };
        [q[0] + c * half, q[1] + s * half]
    }
}
