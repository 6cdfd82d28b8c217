//! A uniform rigid rectangle moving in the plane above a floor, its four corners the contacts:
//! the rocking block of Housner (1963).

use super::{gravity, positive};
use crate::error::Result;
use crate::mechanism::{BodyInertia, Contact, Mechanism, Pose, Real, Surface};

/// A uniform rectangle of mass `m`, half-width `b` and half-height `h`
/// (`I = m (b² + h²)/3`), moving in the plane above the floor `y = floor`, with
/// `q = (x, y, θ)`: its centre and its angle (counter-clockwise; `θ = 0` stands upright, the
/// width along `x`). Its four corners are the contacts, at `(∓b, ∓h)` in the block's frame:
/// contact 0, `corner A`, `(−b, −h)` (bottom left), contact 1, `corner B`, `(b, −h)` (bottom
/// right), contact 2, `corner C`, `(b, h)`, contact 3, `corner D`, `(−b, h)`.
///
/// Tilted by `θ > 0` the block stands on corner A; turning back (`θ̇ < 0`) it strikes with
/// corner B. Housner's ratio for a plastic impact at B without slip (angular momentum about B
/// conserved): `ω⁺/ω⁻ = 1 − (3/2) sin²α`, `α = atan(b/h)` ([`Block::housner_ratio`]).
///
/// ```
/// use impax::mechanism::builtin::Block;
/// use impax::mechanism::{dynamics, Mechanism};
/// let block = Block::new(1.0, 0.2, 0.6, 9.81, 0.0)?;
/// // Upright on the floor: both bottom corners touch it.
/// let q = [0.0, 0.6, 0.0];
/// for corner in [0, 1] {
///     assert!(dynamics::gap(&block, corner, &q).abs() < 1e-15);
/// }
/// assert!((block.housner_ratio() - 0.85).abs() < 1e-15); // sin²α = 0.04/0.4
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    bodies: [BodyInertia; 1],
    half_width: f64,
    half_height: f64,
    gravity: f64,
    contacts: [Contact; 4],
}

/// The corners in the block's frame, in the order of the contacts.
const CORNERS: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

impl Block {
    /// A uniform rectangle.
    ///
    /// # Errors
    /// Mass, half-width or half-height not finite and positive; gravity negative; a
    /// non-finite floor.
    pub fn new(mass: f64, half_width: f64, half_height: f64, g: f64, floor: f64) -> Result<Self> {
        let mass = positive("mass", mass)?;
        let b = positive("half-width", half_width)?;
        let h = positive("half-height", half_height)?;
        crate::error::finite("floor", floor)?;
        let corner = |name| Contact {
            name,
            body: 0,
            surface: Surface::floor(floor),
        };
        Ok(Block {
            bodies: [BodyInertia {
                name: "block",
                mass,
                inertia: mass * (b * b + h * h) / 3.0,
            }],
            half_width: b,
            half_height: h,
            gravity: gravity(g)?,
            contacts: [
                corner("corner A"),
                corner("corner B"),
                corner("corner C"),
                corner("corner D"),
            ],
        })
    }

    /// `(b, h)`.
    pub fn half_sizes(&self) -> [f64; 2] {
        [self.half_width, self.half_height]
    }

    /// Housner's ratio `ω⁺/ω⁻ = 1 − (3/2) sin²α`, `α = atan(b/h)`.
    pub fn housner_ratio(&self) -> f64 {
        let (b, h) = (self.half_width, self.half_height);
        1.0 - 1.5 * b * b / (b * b + h * h)
    }
}

impl Mechanism for Block {
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
        let (s, c) = q[2].sin_cos();
        let [sx, sy] = CORNERS[k];
        let (px, py) = (sx * self.half_width, sy * self.half_height);
        [q[0] + c * px - s * py, q[1] + s * px + c * py]
    }
}
