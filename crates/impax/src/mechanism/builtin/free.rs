//! Free planar bodies as mechanisms (`q = (x, y, θ)`), the checks of the automatic
//! mass matrix against `diag(m, m, I)` and of mechanism impacts against [`crate::planar::bodies`].

use super::{gravity, positive};
use crate::error::Result;
use crate::mechanism::{BodyInertia, Contact, Mechanism, Pose, Real, RoundOnFloor, Surface};

/// A sphere (or, with `inertia_factor = 1/2`, a disc) of mass `m`, radius `r`, central
/// inertia `k m r²` (`k = 2/5` for a sphere), moving in the plane above the floor `y = floor`;
/// its lowest point `(x, y − r)` is the contact.
///
/// # Example: the same impact as the body solver
/// The automatic mass matrix is `diag(m, m, 2/5 m r²)`, and the contact-space `W` is the
/// sphere's `diag(1/m + r²/I, 1/m) = diag(7/2, 1)` for `m = r = 1`:
///
/// ```
/// use impax::mechanism::builtin::Sphere;
/// use impax::mechanism::impact::MechanismImpact;
/// let sphere = Sphere::new(1.0, 1.0, 9.81, 0.0)?;
/// let a = 30f64.to_radians();
/// let impact = MechanismImpact::new(&sphere, &[0.0, 1.0, 0.0], &[a.sin(), -a.cos(), 0.0], 0)?;
/// let w = impact.inverse_inertia();
/// assert!((w[(0, 0)] - 3.5).abs() < 1e-15 && w[(0, 1)] == 0.0 && (w[(1, 1)] - 1.0).abs() < 1e-15);
/// # Ok::<(), impax::Error>(())
/// ```
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
        Self::round("sphere", 0.4, mass, radius, g, floor)
    }

    /// A uniform disc (`I = 1/2 m r²`) rolling in its plane.
    ///
    /// # Errors
    /// As [`Sphere::new`].
    pub fn disc(mass: f64, radius: f64, g: f64, floor: f64) -> Result<Self> {
        Self::round("disc", 0.5, mass, radius, g, floor)
    }

    fn round(
        name: &'static str,
        k: f64,
        mass: f64,
        radius: f64,
        g: f64,
        floor: f64,
    ) -> Result<Self> {
        let mass = positive("mass", mass)?;
        let radius = positive("radius", radius)?;
        crate::error::finite("floor", floor)?;
        Ok(Sphere {
            bodies: [BodyInertia {
                name,
                mass,
                inertia: k * mass * radius * radius,
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
    fn round_on_floor(&self) -> Option<RoundOnFloor> {
        Some(RoundOnFloor {
            mass: self.bodies[0].mass,
            inertia: self.bodies[0].inertia,
            radius: self.radius,
            floor: self.contacts[0].surface.point.y,
        })
    }
}

/// A uniform rod of mass `m` and length `l` (`I = m l²/12`) moving in the plane above the
/// floor `y = floor`; `θ` is its angle from the floor. Both ends can strike the floor: contact
/// 0, `end A`, is the material point `(−l/2, 0)` of the rod's frame (the lower end when
/// `0 < θ < π`), contact 1, `end B`, the point `(+l/2, 0)`.
///
/// # Example: a rod striking with its end
/// A unit rod at 50° to the floor translating at (0.5, −1): the end's contact-space `W` has
/// the coupling `W_tn = −(l²/4) sin θ cos θ / I` of a lever, so friction and the normal
/// impulse interact:
///
/// ```
/// use impax::mechanism::builtin::Rod;
/// use impax::mechanism::impact::MechanismImpact;
/// let rod = Rod::new(1.0, 1.0, 9.81, 0.0)?;
/// let th = 50f64.to_radians();
/// let q = [0.0, 0.5 * th.sin(), th]; // lower end on the floor
/// let impact = MechanismImpact::new(&rod, &q, &[0.5, -1.0, 0.0], 0)?;
/// let w = impact.inverse_inertia();
/// let wtn = -0.25 * th.sin() * th.cos() * 12.0;
/// assert!((w[(0, 1)] - wtn).abs() < 1e-14);
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Rod {
    bodies: [BodyInertia; 1],
    length: f64,
    gravity: f64,
    contacts: [Contact; 2],
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
            contacts: [
                Contact {
                    name: "end A",
                    body: 0,
                    surface: Surface::floor(floor),
                },
                Contact {
                    name: "end B",
                    body: 0,
                    surface: Surface::floor(floor),
                },
            ],
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
    fn contact_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        // End A at −l/2 along the rod's axis, end B at +l/2.
        let (s, c) = q[2].sin_cos();
        let half = if k == 0 {
            -0.5 * self.length
        } else {
            0.5 * self.length
        };
        [q[0] + c * half, q[1] + s * half]
    }
}
