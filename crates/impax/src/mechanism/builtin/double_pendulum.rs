//! Kane & Levinson's double pendulum: two uniform rods, the upper one pinned, the tip of the
//! lower one striking a horizontal floor (Kane & Levinson, *Dynamics: Theory and
//! Applications*, 1985; paper A's origin of the paradox).

use super::{gravity, positive, STANDARD_GRAVITY};
use crate::error::Result;
use crate::mechanism::{BodyInertia, Contact, Mechanism, Pose, Real, Surface};

/// Two uniform rods hinged in a chain, the upper rod pinned at the origin.
///
/// Coordinates `q = (θ₁, θ₂)`: the absolute angles of rod 1 and rod 2 from the downward
/// vertical (counter-clockwise). Rod `i` has mass `m_i`, length `l_i`, central inertia
/// `m_i l_i²/12`. Centres: `r₁ = (l₁/2)(sin θ₁, −cos θ₁)`,
/// `r₂ = l₁ (sin θ₁, −cos θ₁) + (l₂/2)(sin θ₂, −cos θ₂)`; the tip
/// `c = l₁ (sin θ₁, −cos θ₁) + l₂ (sin θ₂, −cos θ₂)` strikes the floor `y = floor`
/// (contact 0, `tip of rod 2`). The elbow, the joint `l₁ (sin θ₁, −cos θ₁)` of the two rods,
/// can meet the floor too (contact 1, `elbow`): a simulation watches both.
///
/// Mass matrix (the hand-derived check of the automatic one):
/// `M = [[(m₁/3 + m₂) l₁², m₂ l₁ l₂ cos(θ₁−θ₂)/2], [·, m₂ l₂²/3]]`.
///
/// # Example: Kane's paradox
/// Unit rods at θ = (30°, 0) swinging at u = (−1, 2) rad/s strike the floor with μ = e = 0.5.
/// The tip slips forward and friction would have to stop it; Whittaker's rule (Coulomb on
/// the total impulses) keeps the friction against the initial slip after the slip has
/// reversed and returns more kinetic energy than the pendulum had, while the Darboux–Keller
/// integration halts the slip and dissipates:
///
/// ```
/// use impax::mechanism::builtin::DoublePendulum;
/// use impax::mechanism::impact::MechanismImpact;
/// use impax::LawId;
/// let q = [30f64.to_radians(), 0.0];
/// let pendulum = DoublePendulum::unit_at(q); // floor through the tip
/// let impact = MechanismImpact::new(&pendulum, &q, &[-1.0, 2.0], 0)?;
/// let t0 = impact.energy_before();
/// let w = impact.resolve(LawId::Whittaker, 0.5, 0.5)?;
/// let e = impact.resolve(LawId::Energetic, 0.5, 0.5)?;
/// let ratio = |o: &impax::mechanism::impact::MechanismOutcome| {
///     1.0 + o.energy_change_from_velocities.unwrap() / t0
/// };
/// assert!(ratio(&w) > 1.26 && ratio(&w) < 1.261); // T⁺/T⁻ = 1.26087: energy gained
/// assert!(ratio(&e) < 0.16);                      // slip halts, the tip sticks
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DoublePendulum {
    bodies: [BodyInertia; 2],
    lengths: [f64; 2],
    gravity: f64,
    contacts: [Contact; 2],
}

impl DoublePendulum {
    /// Rods of masses `m1`, `m2` and lengths `l1`, `l2` under gravity `g`, the floor at height
    /// `floor` (the pin is at the origin).
    ///
    /// # Errors
    /// A mass or length not finite and positive, gravity negative, a non-finite floor.
    pub fn new(m1: f64, m2: f64, l1: f64, l2: f64, g: f64, floor: f64) -> Result<Self> {
        let (m1, m2) = (positive("mass 1", m1)?, positive("mass 2", m2)?);
        let (l1, l2) = (positive("length 1", l1)?, positive("length 2", l2)?);
        crate::error::finite("floor", floor)?;
        Ok(DoublePendulum {
            bodies: [
                BodyInertia {
                    name: "rod 1",
                    mass: m1,
                    inertia: m1 * l1 * l1 / 12.0,
                },
                BodyInertia {
                    name: "rod 2",
                    mass: m2,
                    inertia: m2 * l2 * l2 / 12.0,
                },
            ],
            lengths: [l1, l2],
            gravity: gravity(g)?,
            contacts: [
                Contact {
                    name: "tip of rod 2",
                    body: 1,
                    surface: Surface::floor(floor),
                },
                Contact {
                    name: "elbow",
                    body: 0,
                    surface: Surface::floor(floor),
                },
            ],
        })
    }

    /// Unit rods and masses, standard gravity, the floor through the tip at `q` (so that `q`
    /// is a configuration of contact).
    pub fn unit_at(q: [f64; 2]) -> Self {
        let mut p = Self::new(1.0, 1.0, 1.0, 1.0, STANDARD_GRAVITY, 0.0).expect("valid");
        p.put_floor_at_tip(q);
        p
    }

    /// Move the floor (of both contacts) to the height of the tip at `q`.
    pub fn put_floor_at_tip(&mut self, q: [f64; 2]) {
        let tip = self.contact_point(0, &q);
        for c in &mut self.contacts {
            c.surface = Surface::floor(tip[1]);
        }
    }

    /// Rod lengths `(l₁, l₂)`.
    pub fn lengths(&self) -> [f64; 2] {
        self.lengths
    }
}

impl Mechanism for DoublePendulum {
    fn coordinates(&self) -> &[&'static str] {
        &["theta1", "theta2"]
    }

    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }

    fn gravity(&self) -> f64 {
        self.gravity
    }

    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        let [l1, l2] = self.lengths;
        let (s1, c1) = q[0].sin_cos();
        let (s2, c2) = q[1].sin_cos();
        poses[0] = Pose::new(s1 * (0.5 * l1), -c1 * (0.5 * l1), q[0]);
        poses[1] = Pose::new(
            s1 * l1 + s2 * (0.5 * l2),
            -(c1 * l1) - c2 * (0.5 * l2),
            q[1],
        );
    }

    fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    fn contact_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        let [l1, l2] = self.lengths;
        let (s1, c1) = q[0].sin_cos();
        if k == 1 {
            return [s1 * l1, -(c1 * l1)];
        }
        let (s2, c2) = q[1].sin_cos();
        [s1 * l1 + s2 * l2, -(c1 * l1) - c2 * l2]
    }
}
