//! The model: rigid bodies, the joints of their kinematic tree, the contact points, gravity
//! and the floor; validated once, with what the algorithms need precomputed (coordinate
//! offsets, each body's supporting degrees of freedom).

use super::joint::{unit_axis, Joint, JointKind, Placement};
use crate::error::{Error, Num, Result};
use crate::math::{Mat3, Vec3};

/// One rigid body of a [`Model`].
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Its name (a URDF link's), unique in the model.
    pub name: String,
    /// Mass `m ≥ 0` (zero for a massless link; the mass matrix must still be positive
    /// definite).
    pub mass: f64,
    /// Centre of mass in the body frame.
    pub com: Vec3,
    /// Inertia tensor about the centre of mass, in the body frame (symmetric positive
    /// semidefinite).
    pub inertia: Mat3,
}

impl Body {
    /// A body from its mass, centre of mass and central inertia.
    pub fn new(name: &str, mass: f64, com: Vec3, inertia: Mat3) -> Self {
        Body {
            name: name.to_string(),
            mass,
            com,
            inertia,
        }
    }
}

/// A contact point of a body with the floor `z = h` (contact frame `t1 = x`, `t2 = y`,
/// `n = z` of the world).
///
/// A round foot of radius `r` centred at `point` touches the floor at `point − r n`: its gap
/// is `z(point) − r − h`, and the impact acts on the body's material point there.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPoint {
    /// A name for messages, e.g. the foot's link name.
    pub name: String,
    /// The body it belongs to.
    pub body: usize,
    /// The point (the foot's centre for a round foot) in the body frame.
    pub point: Vec3,
    /// Radius `r ≥ 0` of a round foot (0 for a point).
    pub radius: f64,
}

impl ContactPoint {
    /// A contact point of radius `radius` at `point` of body `body`.
    pub fn new(name: &str, body: usize, point: Vec3, radius: f64) -> Self {
        ContactPoint {
            name: name.to_string(),
            body,
            point,
            radius,
        }
    }
}

/// Standard gravity, `9.81 m/s²`.
pub const STANDARD_GRAVITY: f64 = 9.81;

/// A kinematic tree of rigid bodies in 3D with its contact points, under gravity `g` along
/// `−z`, above the floor `z = h`.
///
/// Coordinates: the joints' in their order, `q` (`nq` numbers: a free joint's seven,
/// quaternion included) and the speeds `u` (`nv` numbers). [`Model::coordinates`] names the
/// entries of `q` and [`Model::speeds`] those of `u` (Kane's generalized speeds; for a free
/// joint `u ≠ q̇`, see [`JointKind::Free`]).
///
/// ```
/// use impax::multibody::{Body, Joint, JointKind, Model, Placement};
/// use impax::math::{Mat3, Vec3};
/// // A pendulum: a unit point mass on a massless rod of length 1, pinned about y.
/// let bob = Body::new("bob", 1.0, Vec3::new(0.0, 0.0, -1.0), Mat3::zeros());
/// let pin = Joint::revolute("pin", Vec3::y(), None, 0, Placement::identity());
/// let model = Model::new(vec![bob], vec![pin], vec![])?;
/// assert_eq!((model.nq(), model.nv()), (1, 1));
/// assert_eq!(model.coordinates(), ["pin"]);
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    pub(crate) bodies: Vec<Body>,
    pub(crate) joints: Vec<Joint>,
    pub(crate) contacts: Vec<ContactPoint>,
    pub(crate) gravity: f64,
    pub(crate) floor: f64,
    pub(crate) data: Derived,
}

/// What the algorithms precompute from the tree.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Derived {
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    /// First entry of each joint in `q` and in `u`.
    pub(crate) q_offset: Vec<usize>,
    pub(crate) v_offset: Vec<usize>,
    /// The joint of which each body is the child.
    pub(crate) body_joint: Vec<usize>,
    /// Each body's parent body (`None`: the world).
    pub(crate) body_parent: Vec<Option<usize>>,
    /// The speeds that move each body (its joint's and its ancestors'), ascending.
    pub(crate) support: Vec<Vec<usize>>,
    /// The joint of each speed.
    pub(crate) dof_joint: Vec<usize>,
    /// Each speed's ancestors `λ(k), λ(λ(k)), …` (descending), `λ(k)` the speed before it
    /// among those supporting its body.
    pub(crate) dof_ancestors: Vec<Vec<usize>>,
    /// `child_placement⁻¹` of each joint.
    pub(crate) child_inverse: Vec<Placement>,
    pub(crate) coordinates: Vec<String>,
    pub(crate) speeds: Vec<String>,
    /// The model's length scale: its largest offset, centre of mass, contact point or radius
    /// of gyration (for the round-off check of a floating base far from the origin).
    pub(crate) size: f64,
}

impl Model {
    /// Validate and build a model, gravity [`STANDARD_GRAVITY`] along `−z`, the floor `z = 0`.
    ///
    /// # Errors
    /// Each names its field (`body[2].mass`, `joint[hip].parent`, `contact[foot].radius`):
    /// no body; a non-finite number; a negative mass; an inertia not symmetric or not
    /// positive semidefinite; a repeated name; a zero axis (a non-unit one is normalised); a
    /// placement whose rotation is not one; a body that is the child of no joint or of two
    /// (a closed loop); a joint whose parent is not the child of an earlier joint (the joints
    /// must be in tree order); a free joint not hanging from the world; a contact on an
    /// unknown body or with a negative radius.
    pub fn new(bodies: Vec<Body>, joints: Vec<Joint>, contacts: Vec<ContactPoint>) -> Result<Self> {
        if bodies.is_empty() {
            return Err(Error::Invalid {
                field: "bodies".into(),
                reason: "a model needs at least one body".into(),
            });
        }
        for (i, b) in bodies.iter().enumerate() {
            check_body(i, b)?;
        }
        unique_names("body", bodies.iter().map(|b| b.name.as_str()))?;
        unique_names("joint", joints.iter().map(|j| j.name.as_str()))?;
        unique_names("contact", contacts.iter().map(|c| c.name.as_str()))?;
        let joints = joints
            .iter()
            .enumerate()
            .map(|(j, joint)| check_joint(j, joint, bodies.len()))
            .collect::<Result<Vec<_>>>()?;
        let (body_joint, body_parent) = tree(&bodies, &joints)?;
        for c in &contacts {
            check_contact(c, &bodies)?;
        }
        let data = derive(&bodies, &joints, &contacts, body_joint, body_parent)?;
        Ok(Model {
            bodies,
            joints,
            contacts,
            gravity: STANDARD_GRAVITY,
            floor: 0.0,
            data,
        })
    }

    /// The same model under gravity `g ≥ 0` along `−z`.
    pub fn with_gravity(mut self, g: f64) -> Result<Self> {
        crate::error::finite("gravity", g)?;
        if g < 0.0 {
            return Err(Error::OutOfRange {
                field: "gravity".into(),
                value: g,
                reason: "must be ≥ 0 (it acts along −z)".into(),
            });
        }
        self.gravity = g;
        Ok(self)
    }

    /// The same model with the floor at `z = h`.
    pub fn with_floor(mut self, h: f64) -> Result<Self> {
        self.floor = crate::error::finite("floor", h)?;
        Ok(self)
    }

    /// The same model with these contact points instead of its own (validated as in
    /// [`Model::new`]).
    pub fn with_contacts(self, contacts: Vec<ContactPoint>) -> Result<Self> {
        let (g, h) = (self.gravity, self.floor);
        Model::new(self.bodies, self.joints, contacts)?
            .with_gravity(g)?
            .with_floor(h)
    }

    /// Number of configuration coordinates `nq`.
    pub fn nq(&self) -> usize {
        self.data.nq
    }

    /// Number of speeds (degrees of freedom) `nv`.
    pub fn nv(&self) -> usize {
        self.data.nv
    }

    /// Names of the entries of `q`: a revolute or prismatic joint's name; `x, y, z, qw, qx,
    /// qy, qz` for the free joint (prefixed `joint.` when the model has several).
    pub fn coordinates(&self) -> &[String] {
        &self.data.coordinates
    }

    /// Names of the entries of `u`: a revolute or prismatic joint's name; `vx, vy, vz, wx, wy,
    /// wz` for the free joint (prefixed `joint.` when the model has several).
    pub fn speeds(&self) -> &[String] {
        &self.data.speeds
    }

    /// The bodies.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// The joints (with normalised axes and rotations).
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The contact points.
    pub fn contacts(&self) -> &[ContactPoint] {
        &self.contacts
    }

    /// Gravity `g`, along `−z`.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The floor height `h` (the plane `z = h`).
    pub fn floor(&self) -> f64 {
        self.floor
    }

    /// The index of the body named `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// The index of the contact named `name`.
    pub fn contact_index(&self, name: &str) -> Option<usize> {
        self.contacts.iter().position(|c| c.name == name)
    }

    /// The first entries of joint `j` in `q` and in `u`.
    pub fn joint_offsets(&self, j: usize) -> (usize, usize) {
        (self.data.q_offset[j], self.data.v_offset[j])
    }

    /// The speeds that move body `b`: its joint's and its ancestors', ascending.
    pub fn support(&self, b: usize) -> &[usize] {
        &self.data.support[b]
    }

    /// The neutral configuration: every joint at zero, free joints at the origin with the
    /// identity quaternion `(1, 0, 0, 0)`.
    pub fn neutral(&self) -> Vec<f64> {
        let mut q = vec![0.0; self.nq()];
        for (j, joint) in self.joints.iter().enumerate() {
            if joint.kind == JointKind::Free {
                q[self.data.q_offset[j] + 3] = 1.0;
            }
        }
        q
    }

    /// Check a state and return `q` with each free joint's quaternion normalised.
    ///
    /// # Errors
    /// Wrong lengths; a non-finite entry (named by its coordinate); a quaternion whose norm is
    /// not within `10⁻⁶` of 1 (it is normalised within that); a floating base so far from
    /// the origin (beyond `4·10⁷` times the model's size) that round-off of its position eats
    /// the robot's geometry.
    pub fn check_state(&self, q: &[f64], u: Option<&[f64]>) -> Result<Vec<f64>> {
        let mut out = Vec::with_capacity(q.len());
        self.check_configuration_into(q, &mut out)?;
        if let Some(u) = u {
            self.check_speeds(u)?;
        }
        Ok(out)
    }

    /// As [`Model::check_state`] for `q` alone, writing the checked configuration into `out`
    /// (no allocation once `out` has room).
    pub(crate) fn check_configuration_into(&self, q: &[f64], out: &mut Vec<f64>) -> Result<()> {
        check_vector("q", q, &self.data.coordinates)?;
        out.clear();
        out.extend_from_slice(q);
        for (j, joint) in self.joints.iter().enumerate() {
            if joint.kind == JointKind::Free {
                self.check_free(j, &mut out[self.data.q_offset[j]..][..7])?;
            }
        }
        Ok(())
    }

    /// Check speeds `u` (or any vector of `nv` generalized forces): their length, and that
    /// they are finite; `field` is `u` in errors.
    ///
    /// # Errors
    /// A wrong length or a non-finite entry (named by its speed).
    pub fn check_speeds(&self, u: &[f64]) -> Result<()> {
        check_vector("u", u, &self.data.speeds)
    }

    /// Normalise a free joint's quaternion (norm checked) and check its position's scale.
    fn check_free(&self, j: usize, q: &mut [f64]) -> Result<()> {
        const FAR: f64 = 4e7;
        let o = self.data.q_offset[j];
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        if (norm - 1.0).abs() > 1e-6 {
            return Err(Error::OutOfRange {
                field: format!(
                    "q[{}..{}] ({})",
                    o + 3,
                    o + 7,
                    self.data.coordinates[o + 3..o + 7].join(", ")
                ),
                value: norm,
                reason: "the norm of the quaternion must be 1 (to 1e-6)".into(),
            });
        }
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        let far = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
        if far > FAR * self.data.size {
            return Err(Error::Invalid {
                field: "q".into(),
                reason: format!(
                    "the joint {} is {} from the origin, {} times the model's size {}: so far out its geometry is lost to round-off (at most {} times); move the origin",
                    self.joints[j].name,
                    Num(far),
                    Num(far / self.data.size),
                    Num(self.data.size),
                    Num(FAR)
                ),
            });
        }
        Ok(())
    }
}

/// A vector's length and finiteness, its entries named in errors.
pub(crate) fn check_vector(field: &str, v: &[f64], names: &[String]) -> Result<()> {
    if v.len() != names.len() {
        return Err(Error::Invalid {
            field: field.into(),
            reason: format!(
                "needs {} numbers ({}), got {}",
                names.len(),
                names.join(", "),
                v.len()
            ),
        });
    }
    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
        return Err(Error::NotFinite {
            field: format!("{field}[{i}] ({})", names[i]),
            value: v[i],
        });
    }
    Ok(())
}

/// `x` if it is finite, else the error naming `field()` — formatted only then (a model is
/// checked each time a contact is put on it: no text per number on the way).
fn finite_or(x: f64, field: impl FnOnce() -> String) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        crate::error::finite(&field(), x)
    }
}

/// Check one body: finite numbers, `m ≥ 0`, inertia symmetric positive semidefinite.
fn check_body(i: usize, b: &Body) -> Result<()> {
    let field = |f: &str| format!("body[{i}].{f}");
    finite_or(b.mass, || field("mass"))?;
    if b.mass < 0.0 {
        return Err(Error::OutOfRange {
            field: field("mass"),
            value: b.mass,
            reason: format!(
                "must be positive, or zero for a massless link (body \"{}\")",
                b.name
            ),
        });
    }
    for (k, x) in b.com.iter().enumerate() {
        finite_or(*x, || format!("{}[{k}]", field("com")))?;
    }
    for (k, x) in b.inertia.iter().enumerate() {
        finite_or(*x, || format!("{}[{}][{}]", field("inertia"), k % 3, k / 3))?;
    }
    check_inertia(&field("inertia"), &b.inertia)
}

/// An inertia tensor must be symmetric (to `1e-12` of its largest entry) and positive
/// semidefinite (its eigenvalues not below `−1e-12` of its largest entry).
pub(crate) fn check_inertia(field: &str, inertia: &Mat3) -> Result<()> {
    let scale = inertia.amax();
    for (r, c) in [(0, 1), (0, 2), (1, 2)] {
        if (inertia[(r, c)] - inertia[(c, r)]).abs() > 1e-12 * scale {
            return Err(Error::NotSymmetric {
                field: field.into(),
                upper: inertia[(r, c)],
                lower: inertia[(c, r)],
            });
        }
    }
    let smallest = inertia.symmetric_eigenvalues().min();
    if smallest < -1e-12 * scale {
        return Err(Error::Invalid {
            field: field.into(),
            reason: format!(
                "must be positive semidefinite: its smallest eigenvalue is {}",
                Num(smallest)
            ),
        });
    }
    Ok(())
}

/// Names must be unique within their kind.
fn unique_names<'a>(kind: &str, names: impl Iterator<Item = &'a str>) -> Result<()> {
    let names: Vec<&str> = names.collect();
    for (i, n) in names.iter().enumerate() {
        if let Some(j) = names[..i].iter().position(|m| m == n) {
            return Err(Error::Invalid {
                field: format!("{kind}[{i}].name"),
                reason: format!("\"{n}\" is already the name of {kind}[{j}]"),
            });
        }
    }
    Ok(())
}

/// The field prefix of a joint: `joint[name]`, or `joint[index]` when it has no name.
pub(crate) fn joint_field(j: usize, joint: &Joint) -> String {
    if joint.name.is_empty() {
        format!("joint[{j}]")
    } else {
        format!("joint[{}]", joint.name)
    }
}

/// Check a joint's own data and return it with its axis normalised and its rotations
/// re-orthonormalised.
fn check_joint(j: usize, joint: &Joint, nb: usize) -> Result<Joint> {
    let prefix = joint_field(j, joint);
    let field = |f: &str| format!("{prefix}.{f}");
    let mut out = joint.clone();
    out.kind = match joint.kind {
        JointKind::Revolute { axis } => JointKind::Revolute {
            axis: unit_axis(&field("axis"), &axis)?,
        },
        JointKind::Prismatic { axis } => JointKind::Prismatic {
            axis: unit_axis(&field("axis"), &axis)?,
        },
        k => k,
    };
    out.placement = joint.placement.check(&field("placement"))?;
    out.child_placement = joint.child_placement.check(&field("child_placement"))?;
    for (f, b) in [("child", Some(joint.child)), ("parent", joint.parent)] {
        if let Some(b) = b.filter(|&b| b >= nb) {
            return Err(Error::Invalid {
                field: field(f),
                reason: format!("unknown body {b}: the model has {nb} bodies"),
            });
        }
    }
    if joint.kind == JointKind::Free && joint.parent.is_some() {
        return Err(Error::Invalid {
            field: field("parent"),
            reason: "a free joint (a floating base) must hang from the world (parent None)".into(),
        });
    }
    Ok(out)
}

/// Each body's joint and parent, checking that the joints form a tree in tree order.
type Tree = (Vec<usize>, Vec<Option<usize>>);
fn tree(bodies: &[Body], joints: &[Joint]) -> Result<Tree> {
    let mut body_joint: Vec<Option<usize>> = vec![None; bodies.len()];
    for (j, joint) in joints.iter().enumerate() {
        let field = |f: &str| format!("{}.{f}", joint_field(j, joint));
        if let Some(p) = joint.parent {
            if p == joint.child {
                return Err(Error::Invalid {
                    field: field("parent"),
                    reason: format!("body {p} cannot be its own parent (a loop)"),
                });
            }
            if body_joint[p].is_none() {
                let later = joints[j + 1..].iter().any(|k| k.child == p);
                return Err(Error::Invalid {
                    field: field("parent"),
                    reason: if later {
                        format!("body {p} (\"{}\") is the child of a later joint: the joints must be in tree order, a parent's joint first", bodies[p].name)
                    } else {
                        format!(
                            "body {p} (\"{}\") is the child of no joint: it is not in the tree",
                            bodies[p].name
                        )
                    },
                });
            }
        }
        if let Some(k) = body_joint[joint.child] {
            return Err(Error::Invalid {
                field: field("child"),
                reason: format!(
                    "body {} (\"{}\") is already the child of {}: each body has one parent joint (a closed loop is not a tree)",
                    joint.child,
                    bodies[joint.child].name,
                    joint_field(k, &joints[k])
                ),
            });
        }
        body_joint[joint.child] = Some(j);
    }
    let mut out = Vec::with_capacity(bodies.len());
    for (b, j) in body_joint.iter().enumerate() {
        let Some(j) = j else {
            return Err(Error::Invalid {
                field: format!("body[{b}]"),
                reason: format!(
                    "\"{}\" is the child of no joint (attach it to the world with a fixed joint)",
                    bodies[b].name
                ),
            });
        };
        out.push(*j);
    }
    let parents = out.iter().map(|&j| joints[j].parent).collect();
    Ok((out, parents))
}

/// Check a contact point.
fn check_contact(c: &ContactPoint, bodies: &[Body]) -> Result<()> {
    let field = |f: &str| format!("contact[{}].{f}", c.name);
    if c.body >= bodies.len() {
        return Err(Error::Invalid {
            field: field("body"),
            reason: format!(
                "unknown body {}: the model has {} bodies",
                c.body,
                bodies.len()
            ),
        });
    }
    for (k, x) in c.point.iter().enumerate() {
        finite_or(*x, || format!("{}[{k}]", field("point")))?;
    }
    finite_or(c.radius, || field("radius"))?;
    if c.radius < 0.0 {
        return Err(Error::OutOfRange {
            field: field("radius"),
            value: c.radius,
            reason: "must be ≥ 0 (0 for a point)".into(),
        });
    }
    Ok(())
}

/// Offsets, supports, names and the length scale.
fn derive(
    bodies: &[Body],
    joints: &[Joint],
    contacts: &[ContactPoint],
    body_joint: Vec<usize>,
    body_parent: Vec<Option<usize>>,
) -> Result<Derived> {
    let (mut nq, mut nv) = (0, 0);
    let (mut q_offset, mut v_offset, mut dof_joint) = (vec![], vec![], vec![]);
    let (mut coordinates, mut speeds) = (vec![], vec![]);
    let free = joints.iter().filter(|j| j.kind == JointKind::Free).count();
    for (j, joint) in joints.iter().enumerate() {
        q_offset.push(nq);
        v_offset.push(nv);
        nq += joint.kind.nq();
        nv += joint.kind.nv();
        dof_joint.extend(std::iter::repeat_n(j, joint.kind.nv()));
        if joint.kind == JointKind::Free {
            let name = |n: &str| {
                if free > 1 {
                    format!("{}.{n}", joint.name)
                } else {
                    n.to_string()
                }
            };
            coordinates.extend(["x", "y", "z", "qw", "qx", "qy", "qz"].map(name));
            speeds.extend(["vx", "vy", "vz", "wx", "wy", "wz"].map(name));
        } else if joint.kind.nv() == 1 {
            coordinates.push(joint.name.clone());
            speeds.push(joint.name.clone());
        }
    }
    unique_names("coordinate", coordinates.iter().map(String::as_str))?;
    let mut support: Vec<Vec<usize>> = vec![vec![]; bodies.len()];
    // (Tree order: a body's parent comes from an earlier joint, so its support is known.)
    for joint in joints {
        let j = body_joint[joint.child];
        let mut s = joint.parent.map_or(vec![], |p| support[p].clone());
        s.extend(v_offset[j]..v_offset[j] + joint.kind.nv());
        support[joint.child] = s;
    }
    let mut dof_ancestors = vec![vec![]; nv];
    for s in &support {
        for (i, &k) in s.iter().enumerate() {
            dof_ancestors[k] = s[..i].iter().rev().copied().collect();
        }
    }
    let mut size = f64::MIN_POSITIVE;
    for j in joints {
        size = size
            .max(j.placement.translation.norm())
            .max(j.child_placement.translation.norm());
    }
    for b in bodies {
        size = size.max(b.com.norm());
        if b.mass > 0.0 {
            size = size.max((b.inertia.trace() / b.mass).sqrt());
        }
    }
    for c in contacts {
        size = size.max(c.point.norm() + c.radius);
    }
    Ok(Derived {
        nq,
        nv,
        q_offset,
        v_offset,
        child_inverse: joints.iter().map(|j| j.child_placement.inverse()).collect(),
        body_joint,
        body_parent,
        support,
        dof_joint,
        dof_ancestors,
        coordinates,
        speeds,
        size,
    })
}
