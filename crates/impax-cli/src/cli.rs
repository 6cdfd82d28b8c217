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
    /// Every impact law side by side on one body impact (default: the seed's sphere of
    /// Liu 2012: α = 30°, e = 0.7, μ = 0.4, γ = 0).
    Compare(CompareArgs),
    /// Resolve a planar contact-space problem (W, v⁻, μ, e) directly.
    Resolve(ResolveArgs),
    /// Reproduce a source paper's numbered results beside impax's values.
    Paper(PaperArgs),
}

#[derive(Debug, Args)]
pub struct CompareArgs {
    /// A TOML scenario file (see README: "Scenario files"); default: the seed's sphere.
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
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Args)]
pub struct ResolveArgs {
    /// Contact-space inverse inertia W as WTT,WTN,WNN (symmetric positive definite).
    #[arg(long, allow_hyphen_values = true, value_name = "WTT,WTN,WNN")]
    pub w: String,
    /// Pre-impact contact velocity as VT,VN (VN < 0: approach).
    #[arg(long, allow_hyphen_values = true, value_name = "VT,VN")]
    pub v: String,
    /// Coulomb friction coefficient μ ≥ 0.
    #[arg(long, allow_hyphen_values = true)]
    pub friction: f64,
    /// Coefficient of restitution e ∈ [0, 1].
    #[arg(long, allow_hyphen_values = true)]
    pub restitution: f64,
    /// Laws, comma separated (default: every contact-space law).
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
