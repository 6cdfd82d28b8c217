//! A pendulum carried by a ring rolling without slip (paper B) and by a freely sliding cart
//! (the contrast case), with their Noether symmetries.

use super::{gravity, positive};
use crate::error::Result;
use crate::mechanism::conserved::{Noether, Symmetry};
use crate::mechanism::{BodyInertia, Dual64, DualNum, Mechanism, Pose, Real};

/// Paper B's mechanism: a thin ring of mass `M` and radius `R` rolling without slip on a
/// horizontal line, carrying a pendulum (a point mass `m` on a massless arm of length `l`)
/// hinged at its centre.
///
/// Coordinates `q = (x, φ)`: the ring centre's abscissa and the pendulum's angle from the
/// downward vertical. Rolling is holonomic here: the ring's angle is `−x/R`. Lagrangian
/// (theory.md §4; `M = m` gives paper B's `(3/2) m ẋ²`):
/// `L = ½(2M + m) ẋ² + m l cos φ ẋ φ̇ + ½ m l² φ̇² + m g l cos φ`.
/// `x` is cyclic: `p_x = (2M + m) ẋ + m l φ̇ cos φ` is conserved, while the horizontal
/// momentum `P_x = (M + m) ẋ + m l φ̇ cos φ` is not (the rolling contact's friction). Small
/// oscillations: `ω² = (g/l)(2M + m)/(2M)` (`3g/(2l)` for `M = m`).
///
/// # Example: which quantities are conserved
/// The ring rolls, so the floor's friction acts on it: the horizontal momentum `P_x` is not
/// conserved, but `x` is cyclic and its integral `p_x = P_x + M ẋ` is; so are the energy (the
/// rolling contact does no work) and the boost charge `t p_x − (2M + m) x − m l sin φ`:
///
/// ```
/// use impax::mechanism::builtin::RingPendulum;
/// use impax::mechanism::conserved::{track, TrackOptions};
/// let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81)?;
/// let options = TrackOptions { duration: 2.0, intervals: 100, ..TrackOptions::default() };
/// let run = track(&ring, &[0.0, 0.5], &[0.5, 0.0], &ring.symmetries(), &[], options)?;
/// assert_eq!(run.cyclic, vec![0]); // x
/// let q = |name: &str| run.tracks.iter().find(|t| t.name == name).unwrap();
/// assert!(q("p_x").conserved(1e-9) && q("energy").conserved(1e-9) && q("boost x").conserved(1e-9));
/// assert!(!q("P_x").conserved(1e-3));
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RingPendulum {
    bodies: [BodyInertia; 2],
    radius: f64,
    length: f64,
    gravity: f64,
}

impl RingPendulum {
    /// Ring of mass `ring_mass` and radius `radius`, bob of mass `bob_mass` on an arm of
    /// length `length`, gravity `g`.
    ///
    /// # Errors
    /// A mass or length not finite and positive; gravity negative.
    pub fn new(ring_mass: f64, radius: f64, bob_mass: f64, length: f64, g: f64) -> Result<Self> {
        let ring_mass = positive("ring mass", ring_mass)?;
        let radius = positive("radius", radius)?;
        Ok(RingPendulum {
            bodies: [
                BodyInertia {
                    name: "ring",
                    mass: ring_mass,
                    inertia: ring_mass * radius * radius,
                },
                BodyInertia {
                    name: "bob",
                    mass: positive("bob mass", bob_mass)?,
                    inertia: 0.0,
                },
            ],
            radius,
            length: positive("length", length)?,
            gravity: gravity(g)?,
        })
    }

    /// The ring's radius `R`.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The pendulum's arm `l`.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Small-oscillation angular frequency squared, `ω² = (g/l)(2M + m)/(2M)`.
    pub fn small_oscillation_omega2(&self) -> f64 {
        let (ring, bob) = (self.bodies[0].mass, self.bodies[1].mass);
        self.gravity / self.length * (2.0 * ring + bob) / (2.0 * ring)
    }

    /// The Noether symmetries: translation of `x` (charge `p_x`) and the Galilean boost
    /// `x → x + ε t` with gauge `F = (2M + m) x + m l sin φ`, whose charge
    /// `t p_x − (2M + m) x − m l sin φ` is conserved although no coordinate is cyclic for it.
    pub fn symmetries(&self) -> Vec<Box<dyn Symmetry>> {
        let k = 2.0 * self.bodies[0].mass + self.bodies[1].mass;
        boost_and_translation(k, self.bodies[1].mass * self.length)
    }
}

/// Translation of `x` and the boost `x → x + εt` with gauge `F = k x + c sin φ`.
fn boost_and_translation(k: f64, c: f64) -> Vec<Box<dyn Symmetry>> {
    vec![
        Box::new(Noether::translation("translation x", 0)),
        Box::new(Noether::new(
            "boost x",
            |_q: &[Dual64], t: Dual64, xi: &mut [Dual64]| {
                xi[0] = t;
                xi[1] = Dual64::from(0.0);
            },
            move |q: &[Dual64], _t: Dual64| q[0] * k + q[1].sin() * c,
        )),
    ]
}

impl Mechanism for RingPendulum {
    fn coordinates(&self) -> &[&'static str] {
        &["x", "phi"]
    }

    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }

    fn gravity(&self) -> f64 {
        self.gravity
    }

    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        let (r, l) = (self.radius, self.length);
        let (s, c) = q[1].sin_cos();
        poses[0] = Pose::new(q[0], D::from(r), q[0] * (-1.0 / r));
        poses[1] = Pose::new(q[0] + s * l, D::from(r) - c * l, q[1]);
    }
}

/// A pendulum (point mass `m`, arm `l`) hinged on a cart of mass `M` that slides freely on a
/// horizontal line: `L = ½(M + m) ẋ² + m l cos φ ẋ φ̇ + ½ m l² φ̇² + m g l cos φ`.
/// Here the cyclic integral `p_x = (M + m) ẋ + m l φ̇ cos φ` *is* the horizontal momentum
/// (no horizontal external force), the contrast to [`RingPendulum`]. Small oscillations:
/// `ω² = (g/l)(M + m)/M`.
///
/// # Example: the cyclic integral is the momentum
/// ```
/// use impax::mechanism::builtin::CartPendulum;
/// use impax::mechanism::conserved::{track, TrackOptions};
/// let cart = CartPendulum::new(2.0, 1.0, 0.8, 9.81)?;
/// let options = TrackOptions { duration: 2.0, intervals: 100, ..TrackOptions::default() };
/// let run = track(&cart, &[0.0, 1.0], &[0.3, 0.0], &cart.symmetries(), &[], options)?;
/// let q = |name: &str| run.tracks.iter().find(|t| t.name == name).unwrap();
/// assert!(q("p_x").conserved(1e-9) && q("P_x").conserved(1e-9));
/// for (a, b) in q("p_x").values.iter().zip(&q("P_x").values) {
///     assert!((a - b).abs() < 1e-12); // p_x = P_x along the whole motion
/// }
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CartPendulum {
    bodies: [BodyInertia; 2],
    length: f64,
    gravity: f64,
}

impl CartPendulum {
    /// Cart of mass `cart_mass`, bob of mass `bob_mass` on an arm of length `length`,
    /// gravity `g`.
    ///
    /// # Errors
    /// A mass or length not finite and positive; gravity negative.
    pub fn new(cart_mass: f64, bob_mass: f64, length: f64, g: f64) -> Result<Self> {
        Ok(CartPendulum {
            bodies: [
                BodyInertia {
                    name: "cart",
                    mass: positive("cart mass", cart_mass)?,
                    inertia: 0.0,
                },
                BodyInertia {
                    name: "bob",
                    mass: positive("bob mass", bob_mass)?,
                    inertia: 0.0,
                },
            ],
            length: positive("length", length)?,
            gravity: gravity(g)?,
        })
    }

    /// The pendulum's arm `l`.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Small-oscillation angular frequency squared, `ω² = (g/l)(M + m)/M`.
    pub fn small_oscillation_omega2(&self) -> f64 {
        let (cart, bob) = (self.bodies[0].mass, self.bodies[1].mass);
        self.gravity / self.length * (cart + bob) / cart
    }

    /// Translation of `x` (charge `p_x = P_x`) and the boost `x → x + ε t` with gauge
    /// `F = (M + m) x + m l sin φ` (the centre of mass moves uniformly).
    pub fn symmetries(&self) -> Vec<Box<dyn Symmetry>> {
        let k = self.bodies[0].mass + self.bodies[1].mass;
        boost_and_translation(k, self.bodies[1].mass * self.length)
    }
}

impl Mechanism for CartPendulum {
    fn coordinates(&self) -> &[&'static str] {
        &["x", "phi"]
    }

    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }

    fn gravity(&self) -> f64 {
        self.gravity
    }

    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        let l = self.length;
        let (s, c) = q[1].sin_cos();
        poses[0] = Pose::new(q[0], D::from(0.0), D::from(0.0));
        poses[1] = Pose::new(q[0] + s * l, -(c * l), q[1]);
    }
}
