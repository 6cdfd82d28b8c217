//! The built-in scenarios from their parameters: the parameters each accepts, its defaults,
//! its initial state and the shapes drawn, and the run's options.

use super::{Case, Shape, SimSpec, NAMES};
use crate::input::{CliError, CliResult};
use crate::output::fmt::Plain;
use impax::mechanism::builtin::STANDARD_GRAVITY;
use impax::mechanism::Mechanism;
use impax::scenario::{MechanismFile, MechanismSpec, MAX_ANGLE_DEG};
use impax::simulation::scenarios::{self, Initial};
use impax::simulation::SimulationOptions;
use impax::LawId;

/// Check an angle in degrees: finite and at most [`MAX_ANGLE_DEG`] in magnitude.
fn angle(field: &str, deg: f64) -> CliResult<f64> {
    if deg.abs() <= MAX_ANGLE_DEG {
        Ok(deg)
    } else {
        Err(CliError::input(format!(
            "{field}: must be between -{MAX_ANGLE_DEG} and {MAX_ANGLE_DEG} degrees, got {}",
            Plain(deg)
        )))
    }
}

fn pair(field: &str, v: &Option<Vec<f64>>, default: [f64; 2]) -> CliResult<[f64; 2]> {
    match v {
        None => Ok(default),
        Some(v) if v.len() == 2 => Ok([v[0], v[1]]),
        Some(v) => Err(CliError::input(format!(
            "{field}: needs 2 values, got {}",
            v.len()
        ))),
    }
}

/// A scenario's initial state, the shapes drawn for its bodies, and its description.
type Built = (Initial, Vec<Shape>, String);

/// Build the scenario, refusing parameters it does not have.
pub fn build(spec: &SimSpec) -> CliResult<Case> {
    let name = spec.simulation.as_str();
    let allowed = if spec.file.is_some() {
        &["q", "u"][..]
    } else {
        parameters(name)?
    };
    refuse_others(spec, name, allowed)?;
    let g = spec.gravity.unwrap_or(STANDARD_GRAVITY);
    let (law_default, mu_default, e_default, until_default) = match name {
        "bouncing-ball" => ("energetic", 0.3, 0.8, 5.0),
        "rocking-block" => ("energetic", 1.0, 0.0, 6.0),
        "cradle" => ("energetic", 0.0, 1.0, 2.0),
        _ => ("energetic", 0.5, 0.5, 3.0),
    };
    let law: LawId = spec.law.as_deref().unwrap_or(law_default).trim().parse()?;
    let friction = spec.friction.unwrap_or(mu_default);
    let restitution = spec.restitution.unwrap_or(e_default);
    let until = spec.until.unwrap_or(until_default);
    let (initial, shapes, description) = match (&spec.file, name) {
        (Some(file), _) => mechanism_file(spec, file, g)?,
        (None, "bouncing-ball") => bouncing_ball(spec, g)?,
        (None, "rod-drop") => rod_drop(spec, g)?,
        (None, "rocking-block") => rocking_block(spec, g)?,
        (None, "cradle") => cradle(spec)?,
        _ => double_pendulum_drop(spec, g)?,
    };
    let options = run_options(law, friction, restitution, until, spec.samples)?;
    Ok(Case {
        name: name.into(),
        description,
        initial,
        options,
        shapes,
    })
}

/// The options of a run: its law and coefficients, `until` (in (0, 1e5] s) and `samples`
/// sample intervals (1 to 10⁶, default 1000).
pub(super) fn run_options(
    law: LawId,
    friction: f64,
    restitution: f64,
    until: f64,
    samples: Option<usize>,
) -> CliResult<SimulationOptions> {
    let samples = samples.unwrap_or(1000);
    if samples == 0 || samples > 1_000_000 {
        return Err(CliError::input(format!(
            "samples: must be between 1 and 10⁶, got {samples}"
        )));
    }
    if !(until.is_finite() && until > 0.0 && until <= 1e5) {
        return Err(CliError::input(format!(
            "until: must be positive and at most 1e5 s, got {}",
            Plain(until)
        )));
    }
    let mut options = SimulationOptions::new(law, friction, restitution, until);
    options.sample_interval = until / samples as f64;
    Ok(options)
}

/// The parameters of the scenario `name` (besides law, friction, restitution, until, samples
/// and gravity); an unknown name is an error.
fn parameters(name: &str) -> CliResult<&'static [&'static str]> {
    Ok(match name {
        "bouncing-ball" => &[
            "mass",
            "radius",
            "height",
            "speed",
            "alpha_deg",
            "spin_ratio",
            "disc",
        ],
        "rod-drop" => &["mass", "length", "angle_deg", "height"],
        "double-pendulum-drop" => &["masses", "lengths", "angles_deg", "rates", "floor"],
        "rocking-block" => &["mass", "half_width", "half_height", "angle_deg", "omega"],
        "cradle" => &["balls", "mass", "radius", "v0", "gap"],
        other => {
            return Err(CliError::input(format!(
                "simulation: unknown scenario `{other}` (known: {})",
                NAMES.join(", ")
            )))
        }
    })
}

/// Refuse a parameter given that the scenario `name` does not have (`allowed`).
fn refuse_others(spec: &SimSpec, name: &str, allowed: &[&str]) -> CliResult<()> {
    let given = [
        ("mass", spec.mass.is_some()),
        ("radius", spec.radius.is_some()),
        ("height", spec.height.is_some()),
        ("speed", spec.speed.is_some()),
        ("alpha_deg", spec.alpha_deg.is_some()),
        ("spin_ratio", spec.spin_ratio.is_some()),
        ("disc", spec.disc.is_some()),
        ("length", spec.length.is_some()),
        ("angle_deg", spec.angle_deg.is_some()),
        ("masses", spec.masses.is_some()),
        ("lengths", spec.lengths.is_some()),
        ("angles_deg", spec.angles_deg.is_some()),
        ("rates", spec.rates.is_some()),
        ("floor", spec.floor.is_some()),
        ("half_width", spec.half_width.is_some()),
        ("half_height", spec.half_height.is_some()),
        ("omega", spec.omega.is_some()),
        ("balls", spec.balls.is_some()),
        ("v0", spec.v0.is_some()),
        ("gap", spec.gap.is_some()),
        ("q", spec.q.is_some()),
        ("u", spec.u.is_some()),
        // The cradle's balls move on a horizontal table: gravity acts across it.
        ("gravity", name == "cradle" && spec.gravity.is_some()),
    ];
    for (field, present) in given {
        if present && (!allowed.contains(&field) || field == "gravity") {
            return Err(CliError::input(format!(
                "{}: not a parameter of {name} (its parameters: {})",
                field.replace('_', "-"),
                allowed.join(", ").replace('_', "-")
            )));
        }
    }
    Ok(())
}

/// `bouncing-ball`: a ball (or disc) thrown at the floor with spin.
fn bouncing_ball(spec: &SimSpec, g: f64) -> CliResult<Built> {
    let (m, r) = (spec.mass.unwrap_or(1.0), spec.radius.unwrap_or(0.1));
    let (h, v0) = (spec.height.unwrap_or(1.0), spec.speed.unwrap_or(2.0));
    let (a, gamma) = (
        angle("alpha-deg", spec.alpha_deg.unwrap_or(30.0))?,
        spec.spin_ratio.unwrap_or(0.0),
    );
    let disc = spec.disc.unwrap_or(false);
    let init = scenarios::bouncing_ball(m, r, h, v0, a.to_radians(), gamma, g, disc)?;
    Ok((
        init,
        vec![Shape::Ball(r)],
        format!(
            "bouncing {} (m = {}, r = {}) from {} above the floor, v0 = {} at α = {}° from the vertical, spin ratio γ = {}",
            if disc { "disc" } else { "ball" },
            Plain(m),
            Plain(r),
            Plain(h),
            Plain(v0),
            Plain(a),
            Plain(gamma)
        ),
    ))
}

/// `rod-drop`: a rod dropped from rest at an angle to the floor.
fn rod_drop(spec: &SimSpec, g: f64) -> CliResult<Built> {
    let (m, l) = (spec.mass.unwrap_or(1.0), spec.length.unwrap_or(1.0));
    let a = angle("angle-deg", spec.angle_deg.unwrap_or(30.0))?;
    let h = spec.height.unwrap_or(0.5);
    let init = scenarios::rod_drop(m, l, a.to_radians(), h, g)?;
    Ok((
        init,
        vec![Shape::Rod(l)],
        format!(
            "rod (m = {m}, l = {l}) dropped from rest at {a}° to the floor, lower end {h} above it"
        ),
    ))
}

/// `rocking-block`: a block tilted onto a corner.
fn rocking_block(spec: &SimSpec, g: f64) -> CliResult<Built> {
    let m = spec.mass.unwrap_or(1.0);
    let (b, h) = (
        spec.half_width.unwrap_or(0.2),
        spec.half_height.unwrap_or(0.6),
    );
    let a = angle("angle-deg", spec.angle_deg.unwrap_or(10.0))?;
    let w = spec.omega.unwrap_or(0.0);
    let init = scenarios::rocking_block(m, b, h, a.to_radians(), w, g)?;
    Ok((
        init,
        vec![Shape::Block(b, h)],
        format!(
            "block (m = {m}, half-width {b}, half-height {h}) tilted {a}° onto a corner, turning at {w} rad/s about it"
        ),
    ))
}

/// `cradle`: Newton's cradle, balls in a row on a table.
fn cradle(spec: &SimSpec) -> CliResult<Built> {
    let n = spec.balls.unwrap_or(3);
    let (m, r) = (spec.mass.unwrap_or(1.0), spec.radius.unwrap_or(0.5));
    let (v0, gap) = (spec.v0.unwrap_or(1.0), spec.gap.unwrap_or(0.0));
    let init = scenarios::cradle(n, m, r, v0, gap)?;
    Ok((
        init,
        vec![Shape::Ball(r); n],
        format!(
            "Newton's cradle: {n} balls (m = {}, r = {}) {} on a frictionless table, the first at v0 = {}",
            Plain(m),
            Plain(r),
            if gap == 0.0 { "touching in a row".to_string() } else { format!("in a row {} apart", Plain(gap)) },
            Plain(v0)
        ),
    ))
}

/// `double-pendulum-drop`: a double pendulum released above a floor.
fn double_pendulum_drop(spec: &SimSpec, g: f64) -> CliResult<Built> {
    let m = pair("masses", &spec.masses, [1.0, 1.0])?;
    let l = pair("lengths", &spec.lengths, [1.0, 1.0])?;
    let a = pair("angles_deg", &spec.angles_deg, [90.0, 90.0])?;
    for x in a {
        angle("angles-deg", x)?;
    }
    let u = pair("rates", &spec.rates, [0.0, 0.0])?;
    let floor = spec.floor.unwrap_or(-1.5);
    let init = scenarios::double_pendulum_drop(
        m[0],
        m[1],
        l[0],
        l[1],
        g,
        floor,
        [a[0].to_radians(), a[1].to_radians()],
        u,
    )?;
    Ok((
        init,
        vec![Shape::Pendulum(l[0]), Shape::Pendulum(l[1])],
        format!(
            "double pendulum (m = {}, {}; l = {}, {}) released at θ = ({}°, {}°), rates ({}, {}) rad/s, floor y = {}",
            Plain(m[0]), Plain(m[1]), Plain(l[0]), Plain(l[1]), Plain(a[0]), Plain(a[1]), Plain(u[0]), Plain(u[1]), Plain(floor)
        ),
    ))
}

/// A planar mechanism file at its state (`q`, `u` from the flags or the file), each body drawn
/// as a dot at its centre of mass.
fn mechanism_file(spec: &SimSpec, file: &MechanismFile, g: f64) -> CliResult<Built> {
    let built = MechanismSpec {
        mechanism: spec.simulation.clone(),
        gravity: Some(g),
        q: spec.q.clone(),
        u: spec.u.clone(),
        file: Some(file.clone()),
        ..MechanismSpec::default()
    }
    .build()?;
    let shapes = vec![Shape::Ball(0.0); built.mechanism.bodies().len()];
    Ok((
        Initial {
            mechanism: built.mechanism,
            q: built.q,
            u: built.u,
        },
        shapes,
        built.description,
    ))
}
