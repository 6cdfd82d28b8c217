//! Command-line definitions (clap derive).

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Rigid-body impact with friction: every classical impact law, exact, side by side.
#[derive(Debug, Parser)]
#[command(name = "impax", version, about, arg_required_else_help = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Every impact law side by side on one body or mechanism impact (default: the seed's
    /// sphere of Liu 2012: α = 30°, e = 0.7, μ = 0.4, γ = 0; or a built-in mechanism such as
    /// `double-pendulum`).
    Compare(Box<CompareArgs>),
    /// Resolve a contact-space problem (W, v⁻, μ, e) directly: planar (W of 3 numbers, v⁻
    /// of 2), spatial (W of 6, v⁻ of 3), or planar with several contacts (--contacts K).
    Resolve(ResolveArgs),
    /// Reproduce a source paper's numbered results beside impax's values.
    Paper(PaperArgs),
    /// Sweep scenario fields over a grid or random samples: one CSV row per point and law
    /// (or a summary), in parallel, streamed with constant memory.
    Sweep(SweepArgs),
    /// Integrate a mechanism's free motion and report which quantities are conserved
    /// (generalized momenta, cyclic coordinates, energy, momentum, angular momentum, Noether
    /// charges).
    Conserved(ConservedArgs),
    /// Simulate a motion with impacts and contacts that stay closed (event-driven):
    /// `bouncing-ball`, `rod-drop`, `double-pendulum-drop`, `rocking-block`, `cradle`, or a
    /// TOML scenario; impacts table, JSON, CSV, plot, animation.
    Simulate(Box<SimulateArgs>),
    /// Draw a 2-parameter sweep as maps, one panel per law: the energy-gain region (sign of
    /// ΔT), the phase sequence, or any numeric output as a heatmap (PNG or SVG).
    Map(MapArgs),
    /// Audit an impact as a physics engine computes it: the exact laws beside `lcp` (the rule
    /// sequential-impulse engines converge to) and `whittaker`, each engine-style rule's
    /// deviation from `energetic`, and a verdict in words. Built-in scenarios: `sphere`
    /// (μ = 0.4, e = 0.7), `rod` (50°, v = (0.5, −1), μ = 0.8, e = 1), `double-pendulum`
    /// (μ = e = 0.5); or a TOML scenario (a body, a mechanism, or a `space = "3d"` body).
    /// The systems struck at several contacts (`rod-flat`, `rocking-block`, `cradle`,
    /// `ball-ball-wall`, `box-flat`): `lcp` and `sequential` against `lzb`.
    Audit(AuditArgs),
    /// The interactive explorer in the browser: serve the page (the impax core compiled to
    /// WebAssembly) on 127.0.0.1 and print its URL, or write its static files with --out.
    Explore(ExploreArgs),
}

#[derive(Debug, Args)]
pub struct ExploreArgs {
    /// TCP port on 127.0.0.1 (0: any free port).
    #[arg(long, default_value_t = 8717)]
    pub port: u16,
    /// Write the page's static files to DIR (created if needed) instead of serving them.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// The points of a sweep and the scenario they vary (shared by `sweep` and `map`).
#[derive(Debug, Args)]
pub struct SpaceArgs {
    /// A TOML scenario file (the book: docs/src/scenarios.md); default: the seed's sphere.
    pub scenario: Option<PathBuf>,
    /// A grid axis: COUNT values of field NAME from START to STOP inclusive (repeatable; the
    /// first axis varies slowest). E.g. `--grid alpha-deg=0:90:901`.
    #[arg(long, value_name = "NAME=START:STOP:COUNT", allow_hyphen_values = true)]
    pub grid: Vec<String>,
    /// A random parameter: field NAME uniform in [LO, HI) (repeatable; with --samples).
    #[arg(long, value_name = "NAME=LO:HI", allow_hyphen_values = true)]
    pub random: Vec<String>,
    /// Number of random points (with --random).
    #[arg(long)]
    pub samples: Option<u64>,
    /// Seed of the random points (with --random; default 0).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Fix a field at a value for every point (repeatable), e.g. `--set friction=0.3`.
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
    /// Laws, comma separated (default: the file's `laws`, else every law).
    #[arg(long, value_delimiter = ',')]
    pub law: Vec<String>,
    /// Worker threads, 1 to 256 (default: one per core).
    #[arg(long, allow_hyphen_values = true)]
    pub threads: Option<i64>,
    /// Confirm a sweep of more than 10⁷ impacts (points × laws).
    #[arg(long)]
    pub yes: bool,
    /// No progress bar and no throughput line on stderr.
    #[arg(long)]
    pub quiet: bool,
}

#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub space: SpaceArgs,
    /// Output: `csv` (one row per point and law, with a header row), `summary` (counts by
    /// verdict and phase sequence and the range of ΔT/T0, per law), or `parquet` (the CSV's
    /// columns; needs --out and an impax built with the `parquet` feature).
    #[arg(long, default_value = "csv")]
    pub format: String,
    /// CSV/Parquet output columns after the swept fields and `law`, comma separated
    /// (default: all; the book: docs/src/sweeps.md).
    #[arg(long, value_delimiter = ',')]
    pub columns: Vec<String>,
    /// Write to FILE instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// A mechanism or robot swept over its state (`q.NAME`, `u.NAME`, `friction`,
    /// `restitution`): its base state and contact.
    #[command(flatten)]
    pub mechanism: MechanismFlags,
}

#[derive(Debug, Args)]
pub struct MapArgs {
    #[command(flatten)]
    pub space: SpaceArgs,
    /// What to draw: `sign` (energy gained or not: Kane's paradox), `sequence` (phase
    /// sequence), or a numeric CSV column of `impax sweep` (e.g. `energy_ratio`).
    #[arg(long, default_value = "sign")]
    pub what: String,
    /// The picture: FILE.png or FILE.svg.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// Picture size in pixels, WIDTHxHEIGHT (default: from the number of panels).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
}

#[derive(Debug, Args)]
pub struct CompareArgs {
    /// A TOML scenario file (the book: docs/src/scenarios.md), a built-in mechanism:
    /// `double-pendulum` (θ1, θ2 from the downward vertical; the tip of rod 2 strikes the
    /// floor), `ring-pendulum`, `cart-pendulum`, or a built-in system struck at several
    /// contacts: `rod-flat`, `rocking-block`, `cradle`, `ball-ball-wall`; default: the seed's
    /// sphere.
    pub scenario: Option<PathBuf>,
    /// Angle of the approach velocity from the normal, degrees (round bodies).
    #[arg(long, allow_hyphen_values = true)]
    pub alpha_deg: Option<f64>,
    /// Coefficient of restitution e ∈ [0, 1].
    #[arg(long, allow_hyphen_values = true)]
    pub restitution: Option<f64>,
    /// Coulomb friction coefficient μ ≥ 0.
    #[arg(long, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Spin ratio γ = ω0 r / v0 (round bodies); the slip before impact is v0 (sin α + γ).
    #[arg(long, allow_hyphen_values = true)]
    pub spin_ratio: Option<f64>,
    /// Mass of the (first) body.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Radius of the (first, round) body.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// Approach speed v0 of the (first, round) body.
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<f64>,
    /// Laws to show, comma separated (default: all).
    #[arg(long, value_delimiter = ',')]
    pub law: Vec<String>,
    #[command(flatten)]
    pub mechanism: MechanismFlags,
    #[command(flatten)]
    pub multi: MultiFlags,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Also draw Routh's impulse-space diagram and the energy bars of every law to FILE
    /// (.png or .svg).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
}

/// The parameters of the built-in systems struck at several contacts (`rod-flat`,
/// `rocking-block`, `cradle`, `ball-ball-wall`; each has defaults). `--mass` and `--radius`
/// apply to them too.
#[derive(Debug, Args, Clone, Default)]
pub struct MultiFlags {
    /// rod-flat: the rod's length (default 1).
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<f64>,
    /// rod-flat, box-flat: the centre's horizontal velocity (default 0).
    #[arg(long, allow_hyphen_values = true)]
    pub vx: Option<f64>,
    /// rod-flat: the centre's vertical velocity (default −1); box-flat: horizontal (default 0).
    #[arg(long, allow_hyphen_values = true)]
    pub vy: Option<f64>,
    /// box-flat: the centre's vertical velocity (default −1).
    #[arg(long, allow_hyphen_values = true)]
    pub vz: Option<f64>,
    /// box-flat: the half-extents a, b, c along x, y, z (default 0.5,0.3,0.2).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "A,B,C"
    )]
    pub half_extents: Option<Vec<f64>>,
    /// rod-flat: the angular velocity (default 0); rocking-block: the angular velocity about
    /// corner A, negative (default −1); box-flat: the spin about the vertical (default 2).
    #[arg(long, allow_hyphen_values = true)]
    pub omega: Option<f64>,
    /// rocking-block: the half-width b (default 0.2).
    #[arg(long, allow_hyphen_values = true)]
    pub half_width: Option<f64>,
    /// rocking-block: the half-height h (default 0.6).
    #[arg(long, allow_hyphen_values = true)]
    pub half_height: Option<f64>,
    /// cradle: the number of balls (default 3).
    #[arg(long)]
    pub balls: Option<usize>,
    /// cradle: the first ball's velocity; ball-ball-wall: ball 2's speed (default 1).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// ball-ball-wall: the angle of the line of centres from the wall's normal, degrees
    /// (default 30).
    #[arg(long, allow_hyphen_values = true)]
    pub angle_deg: Option<f64>,
    /// Every built-in, for `lzb`: the contacts' stiffnesses κ_j > 0 (F_j = κ_j δ_j^η), one
    /// for every contact or one per contact, comma separated (only ratios matter; default 1).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_delimiter = ',',
        value_name = "K,.."
    )]
    pub stiffness: Option<Vec<f64>>,
    /// Every built-in, for `lzb`: the exponent η > 0 of the force law (default 1.5, Hertz).
    #[arg(long, allow_hyphen_values = true)]
    pub exponent: Option<f64>,
}

impl MultiFlags {
    /// The flags given, by name without `--`.
    pub fn given(&self) -> Vec<&'static str> {
        [
            ("length", self.length.is_some()),
            ("vx", self.vx.is_some()),
            ("vy", self.vy.is_some()),
            ("vz", self.vz.is_some()),
            ("half-extents", self.half_extents.is_some()),
            ("omega", self.omega.is_some()),
            ("half-width", self.half_width.is_some()),
            ("half-height", self.half_height.is_some()),
            ("balls", self.balls.is_some()),
            ("v0", self.v0.is_some()),
            ("angle-deg", self.angle_deg.is_some()),
            ("stiffness", self.stiffness.is_some()),
            ("exponent", self.exponent.is_some()),
        ]
        .into_iter()
        .filter_map(|(flag, given)| given.then_some(flag))
        .collect()
    }
}

/// The parameters and state of a built-in mechanism (each has defaults).
#[derive(Debug, Args, Clone, Default)]
pub struct MechanismFlags {
    /// Mechanism: the angle coordinates in degrees (double-pendulum: θ1,θ2 from the downward
    /// vertical; ring/cart-pendulum: φ; sphere, rod: θ).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "DEG,.."
    )]
    pub angles_deg: Option<Vec<f64>>,
    /// Mechanism: the generalized velocities in coordinate order (rad/s for angles), e.g.
    /// `-1,2` for the double pendulum, `ẋ,φ̇` for the ring- and cart-pendulum.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "U,.."
    )]
    pub rates: Option<Vec<f64>>,
    /// Mechanism: the masses (double-pendulum: m1,m2; ring-pendulum: ring,bob;
    /// cart-pendulum: cart,bob; sphere, rod: m).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "M,.."
    )]
    pub masses: Option<Vec<f64>>,
    /// Mechanism: the lengths (double-pendulum: l1,l2; ring/cart-pendulum: the arm l; rod: l).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "L,.."
    )]
    pub lengths: Option<Vec<f64>>,
    /// Mechanism: gravitational acceleration g along −y (default 9.81).
    #[arg(long, allow_hyphen_values = true)]
    pub gravity: Option<f64>,
    /// Mechanism: the position coordinates (ring/cart-pendulum: x; sphere, rod: x,y).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "X,.."
    )]
    pub position: Option<Vec<f64>>,
    /// Mechanism: every generalized coordinate, in SI units (radians, metres), in the order of
    /// the mechanism's `coordinates` (a mechanism file's or a robot's state; replaces
    /// --angles-deg and --position for a built-in).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "Q,.."
    )]
    pub q: Option<Vec<f64>>,
    /// Mechanism: every generalized velocity (rad/s, m/s), in the order of `coordinates`
    /// (replaces --rates).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "U,.."
    )]
    pub u: Option<Vec<f64>>,
    /// Robot (URDF): a contact point, `LINK` or `LINK:x,y,z` (a point in the link's frame);
    /// repeat it for several (the lowest at the state strikes; `simulate` watches them all);
    /// a 3D mechanism file: the name of its striking contact (default: the lowest).
    #[arg(long, value_name = "LINK[:x,y,z]")]
    pub contact: Vec<String>,
    /// Robot (URDF): a floating base, put first: q = (x, y, z, qw, qx, qy, qz, joints…),
    /// u = (the base origin's velocity, its angular velocity — world frame, joints…).
    #[arg(long)]
    pub floating_base: bool,
    /// Robot or 3D mechanism file: the floor's height z (default: through the striking
    /// contact at the state).
    #[arg(long, allow_hyphen_values = true, value_name = "Z")]
    pub floor: Option<f64>,
}

impl MechanismFlags {
    /// The first mechanism flag given on the command line (its name without `--`), if any:
    /// body scenarios refuse them.
    pub fn first_given(&self) -> Option<&'static str> {
        [
            ("angles-deg", self.angles_deg.is_some()),
            ("rates", self.rates.is_some()),
            ("masses", self.masses.is_some()),
            ("lengths", self.lengths.is_some()),
            ("gravity", self.gravity.is_some()),
            ("position", self.position.is_some()),
            ("q", self.q.is_some()),
            ("u", self.u.is_some()),
            ("contact", !self.contact.is_empty()),
            ("floating-base", self.floating_base),
            ("floor", self.floor.is_some()),
        ]
        .into_iter()
        .find_map(|(flag, given)| given.then_some(flag))
    }
}

#[derive(Debug, Args)]
pub struct ConservedArgs {
    /// A built-in mechanism (`ring-pendulum`, `cart-pendulum`, `double-pendulum`, `sphere`,
    /// `rod`), a TOML file with a `mechanism` key, a mechanism file (planar or
    /// `space = "3d"`) or a URDF robot (`--floating-base`, `--q`, `--u`, `--gravity`).
    pub mechanism: String,
    #[command(flatten)]
    pub params: MechanismFlags,
    /// Ring-pendulum, sphere: the radius R.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// Duration of the motion, seconds.
    #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
    pub duration: f64,
    /// Number of sample intervals along the motion.
    #[arg(long, default_value_t = 1000)]
    pub samples: usize,
    /// A fixed point for the angular momentum, X,Y (a robot or 3D file: X,Y,Z; repeatable;
    /// default the origin).
    #[arg(long, value_name = "X,Y[,Z]", allow_hyphen_values = true)]
    pub about: Vec<String>,
    /// A quantity is conserved when its largest deviation is at most this fraction of the
    /// magnitude of its terms.
    #[arg(long, default_value_t = 1e-8)]
    pub tolerance: f64,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Also draw every quantity's relative change against time to FILE (.png or .svg).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// A built-in scenario (`bouncing-ball`, `rod-drop`, `double-pendulum-drop`,
    /// `rocking-block`, `cradle`), a TOML file with a `simulation` key, a mechanism file
    /// (`[[body]]`, `[[joint]]`, `[[contact]]`; planar or `space = "3d"`) or a URDF robot
    /// (`--contact` for each foot, `--floating-base`).
    pub scenario: String,
    /// The impact law (default `energetic`).
    #[arg(long)]
    pub law: Option<String>,
    /// Coulomb friction μ ≥ 0 (impacts and sliding).
    #[arg(long, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Coefficient of restitution e ∈ [0, 1].
    #[arg(long, allow_hyphen_values = true)]
    pub restitution: Option<f64>,
    /// End time, seconds.
    #[arg(long, allow_hyphen_values = true)]
    pub until: Option<f64>,
    /// Number of sample intervals of the trajectory output (default 1000).
    #[arg(long)]
    pub samples: Option<usize>,
    /// Gravitational acceleration along −y (a robot or 3D file: along −z; default 9.81).
    #[arg(long, allow_hyphen_values = true)]
    pub gravity: Option<f64>,
    /// Robot (URDF): a contact point watched for impacts with the floor, `LINK` or
    /// `LINK:x,y,z` (a point in the link's frame); repeat it for every foot.
    #[arg(long, value_name = "LINK[:x,y,z]")]
    pub contact: Vec<String>,
    /// Robot (URDF): a floating base, put first: q = (x, y, z, qw, qx, qy, qz, joints…),
    /// u = (the base origin's velocity, its angular velocity — world frame, joints…).
    #[arg(long)]
    pub floating_base: bool,
    /// bouncing-ball, rod-drop, rocking-block, cradle: the mass (of each ball).
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// bouncing-ball, cradle: the radius.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// bouncing-ball, rod-drop: the height of the lowest point above the floor.
    #[arg(long, allow_hyphen_values = true)]
    pub height: Option<f64>,
    /// bouncing-ball: the initial speed v0.
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<f64>,
    /// bouncing-ball: the angle α of the initial velocity from the downward vertical, degrees.
    #[arg(long, allow_hyphen_values = true)]
    pub alpha_deg: Option<f64>,
    /// bouncing-ball: the spin ratio γ = ω r / v0 (the slip at contact is v0 (sin α + γ)).
    #[arg(long, allow_hyphen_values = true)]
    pub spin_ratio: Option<f64>,
    /// bouncing-ball: a disc (I = m r²/2) instead of a sphere.
    #[arg(long)]
    pub disc: bool,
    /// rod-drop: the rod's length.
    #[arg(long, allow_hyphen_values = true)]
    pub length: Option<f64>,
    /// rod-drop: the rod's angle from the floor; rocking-block: the initial tilt
    /// (counter-clockwise, onto corner A), degrees.
    #[arg(long, allow_hyphen_values = true)]
    pub angle_deg: Option<f64>,
    /// rocking-block: the half-width b.
    #[arg(long, allow_hyphen_values = true)]
    pub half_width: Option<f64>,
    /// rocking-block: the half-height h.
    #[arg(long, allow_hyphen_values = true)]
    pub half_height: Option<f64>,
    /// rocking-block: the initial angular velocity about the corner it stands on, rad/s.
    #[arg(long, allow_hyphen_values = true)]
    pub omega: Option<f64>,
    /// cradle: the number of balls.
    #[arg(long)]
    pub balls: Option<usize>,
    /// cradle: the first ball's velocity towards the others.
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// cradle: the gap between neighbouring balls (0: touching).
    #[arg(long, allow_hyphen_values = true)]
    pub gap: Option<f64>,
    /// A mechanism file or robot: the initial generalized coordinates (SI: radians, metres),
    /// every one in the order of its coordinates (default: the file's `q`; a robot's neutral
    /// state).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "Q,.."
    )]
    pub q: Option<Vec<f64>>,
    /// A mechanism file or robot: the initial generalized velocities (default: the file's
    /// `u`, else zero).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_name = "U,.."
    )]
    pub u: Option<Vec<f64>>,
    /// double-pendulum-drop: the masses m1,m2.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub masses: Option<Vec<f64>>,
    /// double-pendulum-drop: the lengths l1,l2.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub lengths: Option<Vec<f64>>,
    /// double-pendulum-drop: the release angles θ1,θ2 from the downward vertical, degrees.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub angles_deg: Option<Vec<f64>>,
    /// double-pendulum-drop: the release rates, rad/s.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub rates: Option<Vec<f64>>,
    /// double-pendulum-drop: the floor's height (the pivot is at the origin); a robot or 3D
    /// file: the floor's height z (default: the file's, else through the lowest contact).
    #[arg(long, allow_hyphen_values = true)]
    pub floor: Option<f64>,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Write the sampled trajectory to FILE as CSV.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Draw the path and the energy curve to FILE (.png or .svg).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Write an animation of the motion to FILE.svg (animated SVG, real time, looping).
    #[arg(long, value_name = "FILE")]
    pub animate: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct AuditArgs {
    /// `sphere`, `rod`, `double-pendulum`, or a TOML scenario file (a body, as `impax compare`
    /// reads it, planar or with `space = "3d"`, or a mechanism with a `mechanism` key); or a
    /// system struck at several contacts: `rod-flat`, `rocking-block`, `cradle`,
    /// `ball-ball-wall`.
    pub scenario: String,
    /// Several-contact built-ins: the mass (of each ball).
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Coulomb friction coefficient μ ≥ 0 (overrides the scenario's).
    #[arg(long, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Coefficient of restitution e ∈ [0, 1] (overrides the scenario's).
    #[arg(long, allow_hyphen_values = true)]
    pub restitution: Option<f64>,
    /// Sphere: the radius; cradle, ball-ball-wall: the balls' radius.
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    #[command(flatten)]
    pub mechanism: MechanismFlags,
    #[command(flatten)]
    pub multi: MultiFlags,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct ResolveArgs {
    /// Several contacts at once: K contacts (planar), W of 2K × 2K given by its upper
    /// triangle, v⁻ of 2K numbers, friction and restitution one per contact or one for all;
    /// laws `lcp`, `sequential` and `lzb` (with K = 1 every contact-space law).
    #[arg(long, value_name = "K")]
    pub contacts: Option<usize>,
    /// Contact-space inverse inertia W (symmetric positive definite): planar WTT,WTN,WNN, or
    /// spatial W11,W12,W13,W22,W23,W33 (the upper triangle row by row; tangents first,
    /// normal last). With --contacts K: the upper triangle of the 2K × 2K W row by row, rows
    /// and columns t1, n1, t2, n2, … (positive semidefinite).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "WTT,WTN,WNN | W11,...,W33"
    )]
    pub w: String,
    /// Pre-impact contact velocity (normal component < 0: approach): planar VT,VN, or
    /// spatial V1,V2,VN. With --contacts K: VT1,VN1,…,VTK,VNK (at least one approaching).
    #[arg(long, allow_hyphen_values = true, value_name = "VT,VN | V1,V2,VN")]
    pub v: String,
    /// Coulomb friction coefficient μ ≥ 0 (with --contacts K: one for every contact, or K
    /// comma separated).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_delimiter = ',',
        required = true
    )]
    pub friction: Vec<f64>,
    /// Coefficient of restitution e ∈ [0, 1] (with --contacts K: one for every contact, or K
    /// comma separated).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_delimiter = ',',
        required = true
    )]
    pub restitution: Vec<f64>,
    /// With --contacts K, for `lzb`: the contacts' stiffnesses κ_j > 0 of the force law
    /// F_j = κ_j δ_j^η, one for every contact or K comma separated (only their ratios
    /// matter; default 1).
    #[arg(long, allow_hyphen_values = true, value_delimiter = ',')]
    pub stiffness: Vec<f64>,
    /// With --contacts K, for `lzb`: the exponent η > 0 of the force law F = κ δ^η
    /// (default 1.5, Hertz; 1 for a linear spring).
    #[arg(long, allow_hyphen_values = true)]
    pub exponent: Option<f64>,
    /// Laws, comma separated (default: every contact-space law; with --contacts, `lcp`,
    /// `sequential` and `lzb`).
    #[arg(long, value_delimiter = ',')]
    pub law: Vec<String>,
    /// Print JSON: one entry for one law, else an object with `results`.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct PaperArgs {
    /// Which paper: `liu2012` (Liu Yanzhu, On Kane's paradox of frictional impact, 2012).
    pub paper: String,
    /// Print JSON instead of the table.
    #[arg(long)]
    pub json: bool,
}
