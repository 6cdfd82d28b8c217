//! A planar mechanism described as data: rigid bodies joined into a tree by joints, with
//! contact points — the mechanisms of files ([`crate::scenario::MechanismFile`]) and of any
//! front end, without writing Rust.
//!
//! Each body has a frame (origin and angle in the plane) in which its centre of mass and its
//! contact points are given. A joint places its child's frame from its parent's (or from the
//! world's): the joint's point is `at` in the parent's frame and `child_at` in the child's,
//! and the joint's coordinates move one relative to the other (`R(θ)` the rotation by `θ`):
//!
//! | type | coordinates | child frame |
//! |---|---|---|
//! | `revolute` | `θ` (the joint's name) | angle `θ_p + θ`, origin `J − R(θ_c) child_at` |
//! | `prismatic` | `s` | angle `θ_p`, the joint point moved by `s R(θ_p) a` (`a` the unit axis) |
//! | `fixed` | — | angle `θ_p`, origin `J − R(θ_c) child_at` |
//! | `free` | `NAME.x`, `NAME.y`, `NAME.theta` | the joint point moved by `R(θ_p) (x, y)`, angle `θ_p + θ` |
//! | `rolling` | `s` | a disc or ring of radius `r` rolling without slip on the line through `J` along `R(θ_p) a`: centre `J + s t + r n` (`n` the line's left normal), angle `θ_p − s/r` |
//!
//! with `J = o_p + R(θ_p) at` the joint's point in the world. The generalized coordinates are
//! the joints' in their order, named after the joints; angles are relative to the parent
//! (a double pendulum's second coordinate is the angle between its rods). Everything else —
//! mass matrix, equations of motion, contact Jacobians, conserved quantities — follows by
//! automatic differentiation of these poses ([`crate::mechanism`]).
//!
//! ```
//! use impax::mechanism::linkage::{Joint, JointKind, Linkage, LinkBody, LinkContact};
//! use impax::mechanism::{builtin::DoublePendulum, dynamics, Mechanism};
//! use impax::math::Vec2;
//! // Kane & Levinson's double pendulum, rods of unit length and mass hanging from the origin.
//! let rod = |name: &str| LinkBody::new(name, 1.0, 1.0 / 12.0, Vec2::zeros());
//! let hinge = |name: &str, parent: Option<usize>, child, at| Joint {
//!     name: name.into(), kind: JointKind::Revolute, parent, child,
//!     at, child_at: Vec2::new(0.0, 0.5),
//! };
//! let linkage = Linkage::new(
//!     "double pendulum",
//!     vec![rod("rod 1"), rod("rod 2")],
//!     vec![hinge("theta1", None, 0, Vec2::zeros()), hinge("theta2", Some(0), 1, Vec2::new(0.0, -0.5))],
//!     vec![LinkContact::on_floor("tip", 1, Vec2::new(0.0, -0.5))],
//!     9.81,
//! )?;
//! // The same mass matrix as the built-in at absolute angles (30°, 0): q = (30°, −30°).
//! let a = 30f64.to_radians();
//! let m = dynamics::mass_matrix(&linkage, &[a, -a]);
//! let b = dynamics::mass_matrix(&DoublePendulum::unit_at([a, 0.0]), &[a, 0.0]);
//! // Relative angles: θ₂(abs) = q₁ + q₂, so M = Tᵀ M_abs T with T = [[1, 0], [1, 1]].
//! let t = nalgebra::DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 1.0, 1.0]);
//! assert!((m - t.transpose() * b * t).abs().max() < 1e-14);
//! # Ok::<(), impax::Error>(())
//! ```

use super::{BodyInertia, Contact, Mechanism, Pose, Real, Surface};
use crate::error::{Error, Result};
use crate::math::Vec2;
use std::collections::HashSet;
use std::sync::{Mutex, OnceLock};

/// A body of a linkage: its name, mass, central moment of inertia and centre of mass in its
/// own frame.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkBody {
    /// The body's name (unique in the linkage).
    pub name: String,
    /// Mass `m > 0`.
    pub mass: f64,
    /// Moment of inertia about the centre of mass, `I ≥ 0`.
    pub inertia: f64,
    /// The centre of mass in the body's frame.
    pub com: Vec2,
}

impl LinkBody {
    /// A body from its parts.
    pub fn new(name: &str, mass: f64, inertia: f64, com: Vec2) -> Self {
        LinkBody {
            name: name.into(),
            mass,
            inertia,
            com,
        }
    }
}

/// How a joint moves its child relative to its parent (module docs: the table).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointKind {
    /// A hinge: one angle.
    Revolute,
    /// A slider along the unit `axis` of the parent's frame: one displacement.
    Prismatic {
        /// The direction of the slide in the parent's frame (normalised).
        axis: Vec2,
    },
    /// Welded: no coordinate.
    Fixed,
    /// Free in the plane: `x`, `y` (in the parent's frame) and the angle.
    Free,
    /// A disc or ring of radius `radius` rolling without slip on the line through the joint's
    /// point along `axis` (the parent's frame): one coordinate, the distance rolled.
    Rolling {
        /// The direction of the line in the parent's frame (normalised).
        axis: Vec2,
        /// The radius `r > 0` of the disc.
        radius: f64,
    },
}

impl JointKind {
    /// The number of coordinates of the joint.
    pub fn dof(self) -> usize {
        match self {
            JointKind::Fixed => 0,
            JointKind::Free => 3,
            _ => 1,
        }
    }
}

/// A joint of a linkage: it places the frame of `child` from the frame of `parent` (the world
/// when `None`).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// The joint's name: the name of its coordinate (`NAME.x`, `NAME.y`, `NAME.theta` for a
    /// free joint).
    pub name: String,
    /// How it moves.
    pub kind: JointKind,
    /// The parent body (index into the bodies), `None` for the world.
    pub parent: Option<usize>,
    /// The child body.
    pub child: usize,
    /// The joint's point in the parent's frame.
    pub at: Vec2,
    /// The same point in the child's frame.
    pub child_at: Vec2,
}

/// A contact point of a linkage: a point of a body (with the radius of a round foot) that can
/// strike the floor.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkContact {
    /// The contact's name.
    pub name: String,
    /// The body (index into the bodies).
    pub body: usize,
    /// The point in the body's frame (the centre of a round foot).
    pub point: Vec2,
    /// The radius of a round foot (`0` for a point): the contact is the foot's lowest point.
    pub radius: f64,
    /// The height of the floor, or `None`: the floor through the lowest of the contacts
    /// without a height at the state the linkage is placed at ([`Linkage::place_floor`]).
    pub height: Option<f64>,
}

impl LinkContact {
    /// A point contact of `body` at `point` against the floor placed by the state.
    pub fn on_floor(name: &str, body: usize, point: Vec2) -> Self {
        LinkContact {
            name: name.into(),
            body,
            point,
            radius: 0.0,
            height: None,
        }
    }
}

/// A planar mechanism of bodies, joints and contact points (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Linkage {
    name: String,
    coordinates: Vec<&'static str>,
    bodies: Vec<BodyInertia>,
    coms: Vec<Vec2>,
    joints: Vec<Joint>,
    links: Vec<LinkContact>,
    contacts: Vec<Contact>,
    gravity: f64,
}

/// The `&'static` name the [`Mechanism`] trait hands out: each distinct name is stored once
/// for the life of the program (reading the same file again reuses it).
fn intern(name: &str) -> &'static str {
    static NAMES: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    let mut names = NAMES
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|e| e.into_inner());
    if let Some(&s) = names.get(name) {
        return s;
    }
    let s: &'static str = Box::leak(name.to_owned().into_boxed_str());
    names.insert(s);
    s
}

fn invalid(field: String, reason: impl Into<String>) -> Error {
    Error::Invalid {
        field,
        reason: reason.into(),
    }
}

fn finite2(field: &str, v: Vec2) -> Result<()> {
    crate::error::finite(&format!("{field}[0]"), v.x)?;
    crate::error::finite(&format!("{field}[1]"), v.y)?;
    Ok(())
}

impl Linkage {
    /// A linkage from its parts, checked: every body placed by exactly one joint whose parent
    /// is the world or a body placed by an earlier joint; masses positive, inertias
    /// non-negative, axes non-zero, rolling radii positive, every number finite; names unique.
    /// The floors of contacts without a height are at `y = 0` until
    /// [`Linkage::place_floor`] puts them through the state's lowest contact.
    ///
    /// # Errors
    /// [`Error::Invalid`] (or a finiteness or range error) naming the field, e.g.
    /// `joint[theta2].parent`, `body[rod 1].mass`, `contact[tip].body`.
    pub fn new(
        name: &str,
        bodies: Vec<LinkBody>,
        joints: Vec<Joint>,
        contacts: Vec<LinkContact>,
        gravity: f64,
    ) -> Result<Self> {
        let gravity = super::builtin::gravity(gravity)?;
        let mut inertias = Vec::with_capacity(bodies.len());
        let mut names = HashSet::new();
        for b in &bodies {
            let field = |f: &str| format!("body[{}].{f}", b.name);
            if b.name.is_empty() || !names.insert(b.name.as_str()) {
                return Err(invalid(
                    "body.name".into(),
                    format!("`{}`: every body needs a name of its own", b.name),
                ));
            }
            super::builtin::positive(&field("mass"), b.mass)?;
            crate::error::finite(&field("inertia"), b.inertia)?;
            if b.inertia < 0.0 {
                return Err(invalid(field("inertia"), "must be ≥ 0"));
            }
            finite2(&field("com"), b.com)?;
            inertias.push(BodyInertia {
                name: intern(&b.name),
                mass: b.mass,
                inertia: b.inertia,
            });
        }
        let joints = Self::checked_joints(&bodies, joints)?;
        let mut coordinates = Vec::new();
        for j in &joints {
            match j.kind {
                JointKind::Fixed => {}
                JointKind::Free => {
                    for c in ["x", "y", "theta"] {
                        coordinates.push(intern(&format!("{}.{c}", j.name)));
                    }
                }
                _ => coordinates.push(intern(&j.name)),
            }
        }
        let mut seen = HashSet::new();
        if let Some(c) = coordinates.iter().find(|c| !seen.insert(**c)) {
            return Err(invalid(
                "joint.name".into(),
                format!("`{c}` names two coordinates"),
            ));
        }
        for c in &contacts {
            let field = |f: &str| format!("contact[{}].{f}", c.name);
            if c.body >= bodies.len() {
                return Err(invalid(field("body"), "not a body of the mechanism"));
            }
            finite2(&field("point"), c.point)?;
            crate::error::finite(&field("radius"), c.radius)?;
            if c.radius < 0.0 {
                return Err(invalid(field("radius"), "must be ≥ 0"));
            }
            if let Some(h) = c.height {
                crate::error::finite(&field("height"), h)?;
            }
        }
        let mut linkage = Linkage {
            name: name.into(),
            coordinates,
            bodies: inertias,
            coms: bodies.iter().map(|b| b.com).collect(),
            joints,
            contacts: Vec::new(),
            links: contacts,
            gravity,
        };
        linkage.contacts = linkage
            .links
            .iter()
            .map(|c| Contact {
                name: intern(&c.name),
                body: c.body,
                surface: Surface::floor(c.height.unwrap_or(0.0)),
            })
            .collect();
        Ok(linkage)
    }

    /// The joints checked (module docs, [`Linkage::new`]) with their axes normalised.
    fn checked_joints(bodies: &[LinkBody], mut joints: Vec<Joint>) -> Result<Vec<Joint>> {
        let mut placed = vec![false; bodies.len()];
        for j in &mut joints {
            let field = |f: &str| format!("joint[{}].{f}", j.name);
            if j.child >= bodies.len() {
                return Err(invalid(field("child"), "not a body of the mechanism"));
            }
            if placed[j.child] {
                return Err(invalid(
                    field("child"),
                    format!(
                        "`{}` is already placed by another joint",
                        bodies[j.child].name
                    ),
                ));
            }
            if let Some(p) = j.parent {
                if p >= bodies.len() || !placed[p] {
                    return Err(invalid(
                        field("parent"),
                        "must be `world` or a body placed by an earlier joint (list the joints \
                         from the world outwards)",
                    ));
                }
            }
            finite2(&field("at"), j.at)?;
            finite2(&field("child_at"), j.child_at)?;
            match &mut j.kind {
                JointKind::Prismatic { axis } | JointKind::Rolling { axis, .. } => {
                    finite2(&field("axis"), *axis)?;
                    let n = axis.norm();
                    if n == 0.0 {
                        return Err(invalid(field("axis"), "must not be zero"));
                    }
                    *axis /= n;
                }
                _ => {}
            }
            if let JointKind::Rolling { radius, .. } = j.kind {
                super::builtin::positive(&field("radius"), radius)?;
            }
            placed[j.child] = true;
        }
        if let Some(b) = placed.iter().position(|p| !p) {
            return Err(invalid(
                format!("body[{}]", bodies[b].name),
                "no joint places it (give it a `free` joint to the world, or a `fixed` one)",
            ));
        }
        Ok(joints)
    }

    /// The mechanism's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The joints, in order.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// Put the floor of every contact without a given height through the lowest of those
    /// contacts at `q` (each contact's point at `q`, less its foot's radius): the floor the
    /// mechanism strikes at that state.
    ///
    /// # Errors
    /// `q` of the wrong length or not finite, naming `q`.
    pub fn place_floor(&mut self, q: &[f64]) -> Result<()> {
        if q.len() != self.dof() {
            return Err(invalid(
                "q".into(),
                format!(
                    "needs {} value(s) ({}), got {}",
                    self.dof(),
                    self.coordinates.join(", "),
                    q.len()
                ),
            ));
        }
        for (i, &x) in q.iter().enumerate() {
            crate::error::finite(&format!("q[{i}]"), x)?;
        }
        let lowest = (0..self.links.len())
            .filter(|&k| self.links[k].height.is_none())
            .map(|k| self.contact_point(k, q)[1])
            .fold(f64::INFINITY, f64::min);
        for (c, link) in self.contacts.iter_mut().zip(&self.links) {
            if link.height.is_none() {
                c.surface = Surface::floor(lowest);
            }
        }
        Ok(())
    }

    /// The frame (origin, angle) of every body at `q`.
    fn frames<D: Real>(&self, q: &[D], frames: &mut [(D, D, D)]) {
        let rot = |a: D, v: Vec2| {
            let (s, c) = a.sin_cos();
            (c * v.x - s * v.y, s * v.x + c * v.y)
        };
        let mut i = 0;
        for j in &self.joints {
            let (px, py, pa) = j
                .parent
                .map_or((D::zero(), D::zero(), D::zero()), |p| frames[p]);
            let (ax, ay) = rot(pa, j.at);
            let (mut jx, mut jy) = (px + ax, py + ay);
            let angle = match j.kind {
                JointKind::Revolute => pa + q[i],
                JointKind::Fixed => pa,
                JointKind::Prismatic { axis } => {
                    let (tx, ty) = rot(pa, axis);
                    jx += tx * q[i];
                    jy += ty * q[i];
                    pa
                }
                JointKind::Free => {
                    let (s, c) = pa.sin_cos();
                    jx += c * q[i] - s * q[i + 1];
                    jy += s * q[i] + c * q[i + 1];
                    pa + q[i + 2]
                }
                JointKind::Rolling { axis, radius } => {
                    let (tx, ty) = rot(pa, axis);
                    // The centre: rolled along the line, one radius off it (left normal).
                    jx += tx * q[i] - ty * radius;
                    jy += ty * q[i] + tx * radius;
                    pa - q[i] / radius
                }
            };
            i += j.kind.dof();
            let (cx, cy) = rot(angle, j.child_at);
            frames[j.child] = (jx - cx, jy - cy, angle);
        }
    }

    /// A point given in body `b`'s frame, in the world, at the frames `frames`.
    fn world<D: Real>(frames: &[(D, D, D)], b: usize, p: Vec2) -> [D; 2] {
        let (ox, oy, a) = frames[b];
        let (s, c) = a.sin_cos();
        [ox + c * p.x - s * p.y, oy + s * p.x + c * p.y]
    }
}

impl Mechanism for Linkage {
    fn coordinates(&self) -> &[&'static str] {
        &self.coordinates
    }

    fn bodies(&self) -> &[BodyInertia] {
        &self.bodies
    }

    fn gravity(&self) -> f64 {
        self.gravity
    }

    fn poses<D: Real>(&self, q: &[D], poses: &mut [Pose<D>]) {
        let mut frames = vec![(D::zero(), D::zero(), D::zero()); self.bodies.len()];
        self.frames(q, &mut frames);
        for (b, pose) in poses.iter_mut().enumerate() {
            let [x, y] = Self::world(&frames, b, self.coms[b]);
            *pose = Pose::new(x, y, frames[b].2);
        }
    }

    fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    fn contact_point<D: Real>(&self, k: usize, q: &[D]) -> [D; 2] {
        let mut frames = vec![(D::zero(), D::zero(), D::zero()); self.bodies.len()];
        self.frames(q, &mut frames);
        let c = &self.links[k];
        let [x, y] = Self::world(&frames, c.body, c.point);
        // A round foot touches the floor at its lowest point.
        [x, y - c.radius]
    }
}
