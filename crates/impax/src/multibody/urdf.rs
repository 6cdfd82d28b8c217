//! The URDF reader: a robot description (ROS's Unified Robot Description Format, XML) into a
//! [`Model`].
//!
//! * Origins `<origin xyz rpy>` with `R = Rz(yaw) Ry(pitch) Rx(roll)` (theory §7); a link's
//!   `<inertial>` origin is its centre-of-mass frame, whose own rotation turns the inertia
//!   tensor into the link frame, `I_link = R I Rᵀ`.
//! * `revolute` and `continuous` joints become [`JointKind::Revolute`], `prismatic`
//!   [`JointKind::Prismatic`] (axis normalised, a zero axis refused); the child link frame is
//!   the joint frame.
//! * `fixed` joints are merged: the child link's mass, centre of mass and inertia join its
//!   parent body's (the parallel-axis theorem: `m = Σ m_i`, `c = Σ m_i c_i / m`,
//!   `I = Σ (I_i + m_i (|d_i|² 1 − d_i d_iᵀ))`, `d_i = c_i − c`); the merged link's frame stays
//!   addressable by name ([`UrdfRobot::link`]), for contact points too.
//! * `floating`, `planar` (and the non-standard `spherical`) joints are refused.
//! * A `<mimic>` joint stays an independent coordinate, listed in
//!   [`UrdfRobot::mimic_joints`] for the caller to report (Pinocchio's reader does the same
//!   by default).
//! * A link without `<inertial>` has no mass. The mass matrix at the neutral configuration
//!   must be positive definite; otherwise the error names the coordinate that moves no mass.
//! * The base is fixed to the world, or, with [`UrdfOptions::floating_base`], hangs from it by
//!   a free joint `root_joint` placed first (`q = (x, y, z, qw, qx, qy, qz, …)`).
//!
//! Meshes are never loaded: only links, joints and inertias are read. Errors name the
//! element, e.g. `urdf: joint "FL_KFE": unknown parent link "x"`.

use super::joint::{rpy_rotation, unit_axis, Joint, JointKind, Placement};
use super::model::{check_inertia, Body, ContactPoint, Model};
use super::workspace::Workspace;
use crate::error::{Error, Result};
use crate::math::{Mat3, Vec3};
use std::collections::HashMap;

/// A contact point named by its link: `LINK` (the link frame's origin) or `LINK:x,y,z` (a
/// point in that link's frame), with an optional round-foot radius.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSpec {
    /// The contact's name (the spec as written).
    pub name: String,
    /// The link.
    pub link: String,
    /// The point in the link's frame.
    pub point: Vec3,
    /// Round-foot radius `r ≥ 0`.
    pub radius: f64,
}

impl ContactSpec {
    /// The origin of `link`'s frame, named by the link.
    pub fn new(link: &str) -> Self {
        ContactSpec {
            name: link.to_string(),
            link: link.to_string(),
            point: Vec3::zeros(),
            radius: 0.0,
        }
    }

    /// The same contact with a round foot of radius `r` (its gap and contact point are `r`
    /// lower).
    pub fn with_radius(mut self, r: f64) -> Self {
        self.radius = r;
        self
    }

    /// Parse `LINK` or `LINK:x,y,z`.
    ///
    /// ```
    /// use impax::multibody::ContactSpec;
    /// let c = ContactSpec::parse("FL_FOOT:0,0,-0.01")?;
    /// assert_eq!((c.link.as_str(), c.point.z), ("FL_FOOT", -0.01));
    /// assert_eq!(ContactSpec::parse("FL_FOOT:1,2").unwrap_err().field(), "contact");
    /// # Ok::<(), impax::Error>(())
    /// ```
    ///
    /// # Errors
    /// An empty link name; a point that is not three finite numbers.
    pub fn parse(spec: &str) -> Result<Self> {
        let bad = |reason: String| Error::Invalid {
            field: "contact".into(),
            reason: format!("\"{spec}\": {reason}"),
        };
        let (link, point) = match spec.rsplit_once(':') {
            None => (spec, Vec3::zeros()),
            Some((link, xyz)) => {
                let v: Vec<f64> = xyz
                    .split(',')
                    .map(|x| x.trim().parse::<f64>())
                    .collect::<std::result::Result<_, _>>()
                    .map_err(|e| bad(format!("the point must be three numbers x,y,z ({e})")))?;
                if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
                    return Err(bad(format!(
                        "the point must be three finite numbers x,y,z, got {}",
                        v.len()
                    )));
                }
                (link, Vec3::new(v[0], v[1], v[2]))
            }
        };
        if link.trim().is_empty() {
            return Err(bad("no link name (LINK or LINK:x,y,z)".into()));
        }
        Ok(ContactSpec {
            name: spec.to_string(),
            link: link.trim().to_string(),
            point,
            radius: 0.0,
        })
    }
}

impl std::str::FromStr for ContactSpec {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        ContactSpec::parse(s)
    }
}

/// Options of [`read_urdf`].
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct UrdfOptions {
    /// Put a free joint `root_joint` first, the root link its child (default: the root link
    /// is fixed to the world).
    pub floating_base: bool,
    /// The contact points, in the order of [`Model::contacts`].
    pub contacts: Vec<ContactSpec>,
}

impl UrdfOptions {
    /// A floating base (or not).
    pub fn floating_base(mut self, floating: bool) -> Self {
        self.floating_base = floating;
        self
    }

    /// One more contact point.
    pub fn contact(mut self, spec: ContactSpec) -> Self {
        self.contacts.push(spec);
        self
    }
}

/// A joint that the URDF says mimics another (`q_joint = multiplier q_mimicked + offset`),
/// kept as an independent coordinate.
#[derive(Debug, Clone, PartialEq)]
pub struct MimicJoint {
    /// The mimicking joint.
    pub joint: String,
    /// The joint it follows.
    pub mimicked: String,
    /// Its multiplier (default 1).
    pub multiplier: f64,
    /// Its offset (default 0).
    pub offset: f64,
}

/// Where a URDF link's frame is: in the frame of the body it belongs to (its own, or the
/// body it was merged into through fixed joints).
#[derive(Debug, Clone, PartialEq)]
pub struct LinkFrame {
    /// The link's name.
    pub link: String,
    /// The body's index.
    pub body: usize,
    /// The link frame in the body frame.
    pub placement: Placement,
}

/// A model read from URDF, with what the reader has to tell.
#[derive(Debug, Clone, PartialEq)]
pub struct UrdfRobot {
    /// The robot's name.
    pub name: String,
    /// The model.
    pub model: Model,
    /// The joints that mimic another, kept independent.
    pub mimic_joints: Vec<MimicJoint>,
    /// Every link's frame, merged links included.
    pub links: Vec<LinkFrame>,
}

impl UrdfRobot {
    /// The frame of the link named `name`.
    pub fn link(&self, name: &str) -> Option<&LinkFrame> {
        self.links.iter().find(|l| l.link == name)
    }

    /// The contact point `spec` (a point of a link, merged links included) placed in its
    /// body, as [`read_urdf`] places the contacts of its options — for a contact named after
    /// the robot is read (add it with [`Model::with_contacts`]).
    ///
    /// ```
    /// use impax::multibody::{read_urdf, ContactSpec, UrdfOptions};
    /// let text = r#"<robot name="leg">
    ///   <link name="thigh"><inertial><mass value="1"/>
    ///     <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
    ///   <link name="foot"/>
    ///   <joint name="ankle" type="fixed"><parent link="thigh"/><child link="foot"/>
    ///     <origin xyz="0 0 -0.3"/></joint>
    /// </robot>"#;
    /// let robot = read_urdf(text, &UrdfOptions::default())?;
    /// // The foot was merged into the thigh: its point 1 cm below is 0.31 m below the thigh's origin.
    /// let c = robot.contact_point(&ContactSpec::parse("foot:0,0,-0.01")?)?;
    /// assert_eq!((c.body, c.point.z), (0, -0.31));
    /// assert_eq!(robot.contact_point(&ContactSpec::new("toe")).unwrap_err().field(), "contact[toe]");
    /// # Ok::<(), impax::Error>(())
    /// ```
    ///
    /// # Errors
    /// An unknown link (field `contact[NAME]`).
    pub fn contact_point(&self, spec: &ContactSpec) -> Result<ContactPoint> {
        link_contact(&self.links, spec)
    }
}

/// The contact point `spec` on the link frames `links` ([`UrdfRobot::contact_point`]).
pub(crate) fn link_contact(links: &[LinkFrame], spec: &ContactSpec) -> Result<ContactPoint> {
    let l = links
        .iter()
        .find(|l| l.link == spec.link)
        .ok_or_else(|| Error::Invalid {
            field: format!("contact[{}]", spec.name),
            reason: format!("unknown link \"{}\"", spec.link),
        })?;
    Ok(ContactPoint::new(
        &spec.name,
        l.body,
        l.placement.transform_point(&spec.point),
        spec.radius,
    ))
}

/// The error of the URDF element `what`.
fn urdf_error(what: String, reason: String) -> Error {
    Error::Invalid {
        field: "urdf".into(),
        reason: format!("{what}: {reason}"),
    }
}

/// One link's inertial data in its body's frame: mass, centre of mass, central inertia.
type Part = (f64, Vec3, Mat3);

/// Read a model from URDF text.
///
/// ```
/// use impax::multibody::{read_urdf, UrdfOptions};
/// let text = r#"<robot name="arm">
///   <link name="base"/>
///   <link name="rod"><inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
///     <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.01"/></inertial></link>
///   <joint name="pin" type="continuous"><parent link="base"/><child link="rod"/>
///     <axis xyz="0 2 0"/></joint>
/// </robot>"#;
/// let robot = read_urdf(text, &UrdfOptions::default())?;
/// assert_eq!(robot.model.coordinates(), ["pin"]);
/// let m = impax::multibody::mass_matrix(&robot.model, &[0.0])?;
/// assert!((m[(0, 0)] - (0.1 + 2.0 * 0.25)).abs() < 1e-15); // I_yy + m d²
/// # Ok::<(), impax::Error>(())
/// ```
///
/// # Errors
/// Malformed XML; a repeated link; a joint naming an unknown link, a link that is the child
/// of two joints, no root link or several, links not connected to the root (a closed loop);
/// a floating or planar joint; a zero axis; a mimic of an unknown joint; a link's mass
/// negative or its inertia not positive semidefinite; a contact on an unknown link; a mass
/// matrix that is singular at the neutral configuration (naming the coordinate).
pub fn read_urdf(text: &str, options: &UrdfOptions) -> Result<UrdfRobot> {
    let robot = urdf_rs::read_from_string(text)
        .map_err(|e| urdf_error("the XML".into(), format!("cannot be read: {e}")))?;
    let tree = Tree::new(&robot)?;
    let mut b = Builder::default();
    let root = tree.root;
    b.bodies.push(robot.links[root].name.clone());
    b.parts.push(vec![]);
    b.frames.insert(root, (0, Placement::identity()));
    let kind = if options.floating_base {
        JointKind::Free
    } else {
        JointKind::Fixed
    };
    b.joints.push(Joint::new(
        "root_joint",
        kind,
        None,
        0,
        Placement::identity(),
    ));
    b.add_inertial(root, &robot.links[root])?;
    for &j in &tree.order {
        b.add_joint(&robot, &tree, j)?;
    }
    let mimic_joints = mimics(&robot)?;
    let bodies = b.bodies()?;
    let links = b.frames.iter().map(|(&l, &(body, placement))| LinkFrame {
        link: robot.links[l].name.clone(),
        body,
        placement,
    });
    let mut links: Vec<LinkFrame> = links.collect();
    links.sort_by(|a, c| a.link.cmp(&c.link));
    let contacts = options
        .contacts
        .iter()
        .map(|spec| link_contact(&links, spec))
        .collect::<Result<Vec<_>>>()?;
    let model = Model::new(bodies, b.joints, contacts)?;
    check_masses(&model)?;
    Ok(UrdfRobot {
        name: robot.name.clone(),
        model,
        mimic_joints,
        links,
    })
}

/// The mass matrix at the neutral configuration must be positive definite.
fn check_masses(model: &Model) -> Result<()> {
    let mut ws = Workspace::new(model);
    super::crba(model, &mut ws);
    super::factor(model, &mut ws).map_err(|e| {
        urdf_error(
            "the mass matrix at the neutral configuration".into(),
            format!("{e} (give the link an <inertial>, or make its joint fixed)"),
        )
    })
}

/// The mimic joints.
fn mimics(robot: &urdf_rs::Robot) -> Result<Vec<MimicJoint>> {
    let mut out = vec![];
    for j in &robot.joints {
        if let Some(m) = &j.mimic {
            if !robot.joints.iter().any(|k| k.name == m.joint) {
                return Err(urdf_error(
                    format!("joint \"{}\"", j.name),
                    format!("mimics an unknown joint \"{}\"", m.joint),
                ));
            }
            out.push(MimicJoint {
                joint: j.name.clone(),
                mimicked: m.joint.clone(),
                multiplier: m.multiplier.unwrap_or(1.0),
                offset: m.offset.unwrap_or(0.0),
            });
        }
    }
    Ok(out)
}

/// The URDF's tree: its root link and its joints in depth-first order (children in the
/// order of the file).
struct Tree {
    root: usize,
    order: Vec<usize>,
    link: HashMap<String, usize>,
}

impl Tree {
    fn new(robot: &urdf_rs::Robot) -> Result<Tree> {
        if robot.links.is_empty() {
            return Err(urdf_error(
                "the links".into(),
                "the robot has no <link> (an empty description, e.g. a xacro file not expanded)"
                    .into(),
            ));
        }
        let mut link = HashMap::new();
        for (i, l) in robot.links.iter().enumerate() {
            if link.insert(l.name.clone(), i).is_some() {
                return Err(urdf_error(
                    format!("link \"{}\"", l.name),
                    "is defined twice".into(),
                ));
            }
        }
        let mut parent_joint: Vec<Option<usize>> = vec![None; robot.links.len()];
        let mut children: Vec<Vec<usize>> = vec![vec![]; robot.links.len()];
        for (j, joint) in robot.joints.iter().enumerate() {
            let what = || format!("joint \"{}\"", joint.name);
            let find = |role: &str, name: &str| {
                link.get(name)
                    .copied()
                    .ok_or_else(|| urdf_error(what(), format!("unknown {role} link \"{name}\"")))
            };
            let p = find("parent", &joint.parent.link)?;
            let c = find("child", &joint.child.link)?;
            if let Some(k) = parent_joint[c] {
                return Err(urdf_error(
                    what(),
                    format!(
                        "link \"{}\" is already the child of joint \"{}\" (a closed loop is not a tree)",
                        joint.child.link, robot.joints[k].name
                    ),
                ));
            }
            parent_joint[c] = Some(j);
            children[p].push(j);
        }
        let roots: Vec<usize> = (0..robot.links.len())
            .filter(|&l| parent_joint[l].is_none())
            .collect();
        let root = match roots.as_slice() {
            [r] => *r,
            [] => {
                return Err(urdf_error(
                    "the links".into(),
                    "no root link: every link is some joint's child (a closed loop)".into(),
                ))
            }
            _ => {
                let names: Vec<&str> = roots
                    .iter()
                    .map(|&r| robot.links[r].name.as_str())
                    .collect();
                return Err(urdf_error(
                    "the links".into(),
                    format!(
                        "several root links ({}): the tree must be connected",
                        names.join(", ")
                    ),
                ));
            }
        };
        let mut order = vec![];
        let mut stack: Vec<usize> = children[root].iter().rev().copied().collect();
        while let Some(j) = stack.pop() {
            order.push(j);
            let c = link[&robot.joints[j].child.link];
            stack.extend(children[c].iter().rev());
        }
        if order.len() != robot.joints.len() {
            let lost = robot
                .joints
                .iter()
                .enumerate()
                .find(|(j, _)| !order.contains(j));
            let name = lost.map_or("", |(_, j)| j.name.as_str());
            return Err(urdf_error(
                format!("joint \"{name}\""),
                "is not connected to the root link (a closed loop)".into(),
            ));
        }
        Ok(Tree { root, order, link })
    }
}

/// The bodies, joints, inertial parts and link frames as the tree is walked.
#[derive(Default)]
struct Builder {
    bodies: Vec<String>,
    parts: Vec<Vec<Part>>,
    joints: Vec<Joint>,
    /// Each visited link's body and frame in it.
    frames: HashMap<usize, (usize, Placement)>,
}

impl Builder {
    /// Add a link's inertial data to the body it belongs to.
    fn add_inertial(&mut self, l: usize, link: &urdf_rs::Link) -> Result<()> {
        let what = || format!("link \"{}\"", link.name);
        let (body, x) = self.frames[&l];
        let inertial = &link.inertial;
        let m = inertial.mass.value;
        if !(m.is_finite() && m >= 0.0) {
            return Err(urdf_error(
                what(),
                format!("the mass must be a finite number ≥ 0, got {m}"),
            ));
        }
        let i = &inertial.inertia;
        let local = Mat3::new(
            i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz,
        );
        if local.iter().any(|x| !x.is_finite()) {
            return Err(urdf_error(what(), "the inertia must be finite".into()));
        }
        check_inertia("inertia", &local).map_err(|e| urdf_error(what(), e.to_string()))?;
        let o = &inertial.origin;
        let r_com = rpy_rotation(*o.rpy);
        let com_link = Vec3::new(o.xyz[0], o.xyz[1], o.xyz[2]);
        if com_link.iter().chain(r_com.iter()).any(|x| !x.is_finite()) {
            return Err(urdf_error(
                what(),
                "the inertial origin must be finite".into(),
            ));
        }
        let rot = x.rotation * r_com;
        self.parts[body].push((
            m,
            x.transform_point(&com_link),
            rot * local * rot.transpose(),
        ));
        Ok(())
    }

    /// Add joint `j` of the URDF: a new body, or a fixed joint merged into its parent body.
    fn add_joint(&mut self, robot: &urdf_rs::Robot, tree: &Tree, j: usize) -> Result<()> {
        let joint = &robot.joints[j];
        let what = || format!("joint \"{}\"", joint.name);
        let (p, c) = (tree.link[&joint.parent.link], tree.link[&joint.child.link]);
        let (body, x_parent) = self.frames[&p];
        let o = &joint.origin;
        let origin = Placement::from_xyz_rpy(*o.xyz, *o.rpy);
        if origin
            .rotation
            .iter()
            .chain(origin.translation.iter())
            .any(|x| !x.is_finite())
        {
            return Err(urdf_error(what(), "the origin must be finite".into()));
        }
        let placement = x_parent.compose(&origin);
        let axis = Vec3::new(joint.axis.xyz[0], joint.axis.xyz[1], joint.axis.xyz[2]);
        let axis = || unit_axis("axis", &axis).map_err(|e| urdf_error(what(), e.to_string()));
        use urdf_rs::JointType as T;
        let kind = match joint.joint_type {
            T::Fixed => None,
            T::Revolute | T::Continuous => Some(JointKind::Revolute { axis: axis()? }),
            T::Prismatic => Some(JointKind::Prismatic { axis: axis()? }),
            T::Floating | T::Planar | T::Spherical => {
                let t = format!("{:?}", joint.joint_type).to_lowercase();
                return Err(urdf_error(what(), format!("a {t} joint is not supported (only revolute, continuous, prismatic and fixed; a floating base is the option floating_base)")));
            }
        };
        match kind {
            None => {
                self.frames.insert(c, (body, placement));
            }
            Some(kind) => {
                let nb = self.bodies.len();
                self.bodies.push(joint.child.link.clone());
                self.parts.push(vec![]);
                self.joints
                    .push(Joint::new(&joint.name, kind, Some(body), nb, placement));
                self.frames.insert(c, (nb, Placement::identity()));
            }
        }
        self.add_inertial(c, &robot.links[c])
    }

    /// Every body with its parts combined by the parallel-axis theorem.
    fn bodies(&self) -> Result<Vec<Body>> {
        Ok(self
            .bodies
            .iter()
            .zip(&self.parts)
            .map(|(name, parts)| {
                let (m, com, inertia) = combine(parts);
                Body::new(name, m, com, inertia)
            })
            .collect())
    }
}

/// Masses, centres of mass and central inertias combined (parallel-axis theorem); a body
/// without mass has its centre of mass at its origin.
fn combine(parts: &[Part]) -> Part {
    let m: f64 = parts.iter().map(|p| p.0).sum();
    let com = if m > 0.0 {
        parts.iter().map(|p| p.1 * p.0).sum::<Vec3>() / m
    } else {
        Vec3::zeros()
    };
    let mut inertia = Mat3::zeros();
    for (mi, ci, ii) in parts {
        let d = ci - com;
        inertia += ii + (Mat3::identity() * d.norm_squared() - d * d.transpose()) * *mi;
    }
    (m, com, (inertia + inertia.transpose()) * 0.5)
}
