//! Descriptions of systems as users write them (TOML files, command-line flags, Python and
//! explorer arguments), read and checked once, here, for every front end.
//!
//! Today: the planar body scenario of `impax compare` — one striking body against a fixed
//! surface, or two free bodies — with its TOML format ([`PlanarScenario::from_toml`]), the
//! table of shapes and their parameters ([`Shape`], [`ShapeParam`], and [`ShapeScalar`] for
//! the numbers a sweep sets by name) and the one builder of a body ([`BodySpec::build`]). The
//! command line, the sweeps, the Python bindings and the explorer fill a [`BodySpec`] (or read
//! the table) rather than knowing shapes themselves: a shape added here works in all of them.
//! The spatial body scenario of `impax compare` (`space = "3d"`) likewise:
//! [`SpatialScenario`], [`Shape3`], [`BodySpec3::build`]. The built-in mechanisms likewise: [`MechanismSpec::build`] (a file with a `mechanism` key,
//! the mechanism flags, Python's `mechanism(...)`).
//!
//! ```toml
//! friction = 0.4          # μ
//! restitution = 0.7       # e
//! laws = ["whittaker", "energetic"]   # optional; default: every law
//!
//! [body]                  # the striking body A (contact at its lowest point)
//! shape = "sphere"        # sphere | disc | rod | ellipse | rigid | box
//! mass = 1.0
//! radius = 1.0            # sphere, disc
//! # length = 2.0; angle_deg = 50        (rod: angle from the surface)
//! # semi_axes = [2.0, 1.0]; angle_deg = 20   (ellipse: its a axis from the surface)
//! # inertia = 0.5; contact = [0.3, -1.0]     (rigid: contact point from the centre, (t, n))
//! # half_extents = [1.0, 0.5]; angle_deg = 20; corner = [-1, -1]
//! #     (box: half-width a, half-height b; its a side from the surface, default 0; the
//! #     corner that strikes, signs in the box's frame, default the lowest — needed when an
//! #     edge is lowest, as at angle 0)
//! speed = 1.0             # round bodies: v0, α, γ as in paper A …
//! alpha_deg = 30.0
//! spin_ratio = 0.0
//! # velocity = [0.5, -0.866]; omega = 0.0   # … or the state directly (any shape)
//!
//! [other]                 # optional: a second free body B, struck at its highest point
//! shape = "disc"
//! mass = 2.0
//! radius = 1.0
//! velocity = [0.0, 0.0]
//! omega = 0.0
//! ```
//!
//! Unknown keys are errors; every error names its field as the file spells it (`body.radius`,
//! `other.velocity`).

mod body;
mod file_lines;
mod mechanism;
mod mechanism_file;
mod planar;
mod robot;
mod shape;
mod spatial;

pub use body::{BodySpec, BuiltBody, Scale};
pub use file_lines::{field_line, file_error_message};
pub use mechanism::{
    BuiltMechanism, MechanismSpec, DEFAULT_FRICTION, DEFAULT_RESTITUTION, MAX_ANGLE_DEG,
};
pub use mechanism_file::{
    is_mechanism_file, BodyEntry, ContactEntry, InertiaEntry, JointEntry, MechanismFile, Space,
};
pub use planar::{BuiltPlanar, PlanarScenario, SEED_TOML};
pub use robot::{BuiltRobot, FreeRobot, Robot, RobotSource, RobotSpec};
pub use shape::{AngleUnit, Need, Quantity, Shape, ShapeParam, ShapeScalar};
pub use spatial::{BodySpec3, BuiltBody3, BuiltSpatial, Shape3, SpatialScenario};
