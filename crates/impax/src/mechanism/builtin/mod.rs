//! Built-in mechanisms, each with its parameters checked at construction.
//!
//! | mechanism | coordinates | contact |
//! |---|---|---|
//! | [`DoublePendulum`] | θ₁, θ₂ (absolute, from the downward vertical) | tip of rod 2, elbow on a floor |
//! | [`RingPendulum`] | x (ring centre), φ (pendulum from the downward vertical) | — (rolls) |
//! | [`CartPendulum`] | x (cart), φ | — |
//! | [`Sphere`] | x, y, θ | lowest point on a floor |
//! | [`Rod`] | x, y, θ (from the floor) | end A, end B on a floor |
//! | [`Block`] | x, y, θ | its four corners on a floor |
//! | [`Cradle`] | x, y, θ of each ball | ball against ball along the row |

mod block;
pub mod cradle;
mod double_pendulum;
mod free;
mod pendulums;

pub use block::Block;
pub use cradle::Cradle;
pub use double_pendulum::DoublePendulum;
pub use free::{Rod, Sphere};
pub use pendulums::{CartPendulum, RingPendulum};

use crate::error::{Error, Result};

/// Standard gravity, m/s² (the default of every built-in).
pub const STANDARD_GRAVITY: f64 = 9.81;

/// A parameter that must be finite and positive.
pub(crate) fn positive(field: &str, x: f64) -> Result<f64> {
    crate::error::finite(field, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value: x,
            reason: "must be positive".into(),
        })
    }
}

/// Gravity: finite and ≥ 0.
pub(crate) fn gravity(x: f64) -> Result<f64> {
    crate::error::finite("gravity", x)?;
    if x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: "gravity".into(),
            value: x,
            reason: "must be ≥ 0 (it acts along −y)".into(),
        })
    }
}

use super::conserved::Symmetry;
use super::{BodyInertia, Contact, Mechanism, Pose, Real, RoundOnFloor};

/// Any built-in mechanism, selectable by its stable name (CLI, TOML, bindings).
#[derive(Debug, Clone, PartialEq)]
pub enum BuiltIn {
    /// `double-pendulum`.
    DoublePendulum(DoublePendulum),
    /// `ring-pendulum`.
    RingPendulum(RingPendulum),
    /// `cart-pendulum`.
    CartPendulum(CartPendulum),
    /// `sphere`.
    Sphere(Sphere),
    /// `rod`.
    Rod(Rod),
    /// `block` (simulation only).
    Block(Block),
    /// `cradle` (simulation only).
    Cradle(Cradle),
    /// A mechanism of one's own (bodies, joints, contacts: a mechanism file).
    Linkage(super::linkage::Linkage),
}

macro_rules! each {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            BuiltIn::DoublePendulum($m) => $e,
            BuiltIn::RingPendulum($m) => $e,
            BuiltIn::CartPendulum($m) => $e,
            BuiltIn::Sphere($m) => $e,
            BuiltIn::Rod($m) => $e,
            BuiltIn::Block($m) => $e,
            BuiltIn::Cradle($m) => $e,
            BuiltIn::Linkage($m) => $e,
        }
    };
}

impl BuiltIn {
    /// The stable names of the mechanisms the mechanism commands build (`impax conserved`,
    /// `impax audit`), in the order of the enum; [`BuiltIn::Block`] and [`BuiltIn::Cradle`]
    /// (`block`, `cradle`) are the simulation's.
    pub const NAMES: [&'static str; 5] = [
        "double-pendulum",
        "ring-pendulum",
        "cart-pendulum",
        "sphere",
        "rod",
    ];

    /// The stable name.
    pub fn name(&self) -> &'static str {
        match self {
            BuiltIn::DoublePendulum(_) => Self::NAMES[0],
            BuiltIn::RingPendulum(_) => Self::NAMES[1],
            BuiltIn::CartPendulum(_) => Self::NAMES[2],
            BuiltIn::Sphere(_) => Self::NAMES[3],
            BuiltIn::Rod(_) => Self::NAMES[4],
            BuiltIn::Block(_) => "block",
            BuiltIn::Cradle(_) => "cradle",
            BuiltIn::Linkage(_) => "linkage",
        }
    }

    /// The Noether symmetries known for this mechanism (translations of its cyclic
    /// coordinates and the Galilean boost where the centre of mass moves freely or rolls).
    pub fn symmetries(&self) -> Vec<Box<dyn Symmetry>> {
        use super::conserved::Noether;
        match self {
            BuiltIn::RingPendulum(m) => m.symmetries(),
            BuiltIn::CartPendulum(m) => m.symmetries(),
            BuiltIn::Sphere(_) | BuiltIn::Rod(_) | BuiltIn::Block(_) => {
                vec![Box::new(Noether::translation("translation x", 0))]
            }
            BuiltIn::DoublePendulum(_) | BuiltIn::Cradle(_) | BuiltIn::Linkage(_) => Vec::new(),
        }
    }
}

impl BuiltIn {
    /// Put the floor where the mechanism strikes it at `q`: through the double pendulum's tip,
    /// through a mechanism file's lowest contact without a height; the other built-ins keep
    /// their floor `y = 0`.
    ///
    /// # Errors
    /// `q` of the wrong length or not finite (naming `q`).
    pub fn place_floor(&mut self, q: &[f64]) -> Result<()> {
        match self {
            BuiltIn::DoublePendulum(m) => {
                let q: [f64; 2] = q.try_into().map_err(|_| Error::Invalid {
                    field: "q".into(),
                    reason: format!("needs 2 value(s) (theta1, theta2), got {}", q.len()),
                })?;
                m.put_floor_at_tip(q);
                Ok(())
            }
            BuiltIn::Linkage(m) => m.place_floor(q),
            _ => Ok(()),
        }
    }
}

impl Mechanism for BuiltIn {
    fn coordinates(&self) -> &[&'static str] {
        each!(self, m => m.coordinates())
    }
    fn bodies(&self) -> &[BodyInertia] {
        each!(self, m => m.bodies())
    }
    fn gravity(&self) -> f64 {
        each!(self, m => m.gravity())
    }
    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        each!(self, m => m.poses(q, poses))
    }
    fn potential<D: Real>(&self, q: &[D]) -> D {
        each!(self, m => m.potential(q))
    }
    fn contacts(&self) -> &[Contact] {
        each!(self, m => m.contacts())
    }
    fn contact_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        each!(self, m => m.contact_point(k, q))
    }
    fn round_on_floor(&self) -> Option<RoundOnFloor> {
        each!(self, m => m.round_on_floor())
    }
    fn surface_body(&self, k: usize) -> Option<usize> {
        each!(self, m => m.surface_body(k))
    }
    fn surface_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        each!(self, m => m.surface_point(k, q))
    }
}
