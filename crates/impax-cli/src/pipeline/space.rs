//! The points of `impax sweep` / `impax map`: `--grid`, `--random`, `--set` and `--law`
//! parsed and checked against the scenario, with the size confirmation.

use crate::cli::SpaceArgs;
use crate::input::{CliError, CliResult};
use crate::pipeline::template::{Field, Template};
use crate::sources::scenario::parse_laws;
use impax::analysis::{Axis, Grid, RandomSamples, SampleRange, Space};
use impax::LawId;

/// Sweeps of more impacts (points × laws) than this need `--yes`.
pub const CONFIRM_ABOVE: u64 = 10_000_000;

/// The most worker threads `--threads` accepts (each thread costs a stack and a share of the
/// machine; more threads than cores only add switching).
pub const MAX_THREADS: i64 = 256;

/// A checked sweep: the scenario, the swept fields (in the order of the point values), the
/// points and the laws.
#[derive(Debug, Clone)]
pub struct Setup {
    pub template: Template,
    pub fields: Vec<Field>,
    pub space: Space,
    pub laws: Vec<LawId>,
}

fn split_assignment<'a>(flag: &str, text: &'a str, form: &str) -> CliResult<(&'a str, &'a str)> {
    text.split_once('=')
        .map(|(n, v)| (n.trim(), v.trim()))
        .filter(|(n, _)| !n.is_empty())
        .ok_or_else(|| CliError::input(format!("--{flag} {text}: expected {form}")))
}

fn number(flag: &str, text: &str, part: &str) -> CliResult<f64> {
    let x: f64 = part
        .trim()
        .parse()
        .map_err(|_| CliError::input(format!("--{flag} {text}: `{part}` is not a number")))?;
    if !x.is_finite() {
        return Err(CliError::input(format!(
            "--{flag} {text}: `{part}` is not a finite number"
        )));
    }
    Ok(x)
}

/// Parse and check the points of a sweep of a body scenario.
pub fn setup(args: &SpaceArgs) -> CliResult<Setup> {
    thread_count(args.threads)?;
    let mut template = Template::load(args.scenario.as_deref())?;
    let laws = if args.law.is_empty() {
        template.laws.clone()
    } else {
        parse_laws(&args.law)?
    };
    let lookup = template.clone();
    let (fields, space) = points(
        args,
        |name| lookup.field(name),
        |f: Field| f.name(),
        |f: Field, lo, hi| f.check_range(lo, hi),
        |f, x| template.set(f, x),
    )?;
    let setup = Setup {
        template,
        fields,
        space,
        laws,
    };
    confirm(args, &setup.space, setup.laws.len())?;
    Ok(setup)
}

/// The swept fields and the points of `--grid` or `--random`, with `--set` applied through
/// `set`: the parsing and checks every kind of sweep shares. `lookup` finds a field by name,
/// `name` names it back, `check` refuses a range it cannot take.
pub fn points<F: Copy + PartialEq>(
    args: &SpaceArgs,
    lookup: impl Fn(&str) -> Result<F, String>,
    name: impl Fn(F) -> String,
    check: impl Fn(F, f64, f64) -> Result<(), String>,
    mut set: impl FnMut(F, f64),
) -> CliResult<(Vec<F>, Space)> {
    let field = |flag: &str, text: &str, n: &str| {
        lookup(n).map_err(|e| CliError::input(format!("--{flag} {text}: {e}")))
    };
    let check_range = |f: F, flag: &str, text: &str, lo: f64, hi: f64| {
        check(f, lo, hi).map_err(|e| CliError::input(format!("--{flag} {text}: {e}")))
    };
    let mut fixed = Vec::new();
    for text in &args.set {
        let (n, value) = split_assignment("set", text, "NAME=VALUE")?;
        let f = field("set", text, n)?;
        let x = number("set", text, value)?;
        check_range(f, "set", text, x, x)?;
        set(f, x);
        fixed.push((f, text));
    }
    let mut fields: Vec<F> = Vec::new();
    let twice = |fields: &[F], f: F, flag: &str, text: &str| {
        if fields.contains(&f) {
            Err(CliError::input(format!(
                "--{flag} {text}: field `{}` is swept twice",
                name(f)
            )))
        } else {
            Ok(())
        }
    };
    let space =
        match (args.grid.is_empty(), args.random.is_empty()) {
            (false, false) => {
                return Err(CliError::input(
                    "--grid and --random: give one kind of points, not both",
                ))
            }
            (true, true) => return Err(CliError::input(
                "no points: give --grid NAME=START:STOP:COUNT (or --random NAME=LO:HI --samples N)",
            )),
            (false, true) => {
                if args.samples.is_some() || args.seed.is_some() {
                    return Err(CliError::input(
                        "--samples/--seed: apply to --random points, not to --grid",
                    ));
                }
                let mut axes = Vec::new();
                for text in &args.grid {
                    let form = "NAME=START:STOP:COUNT (e.g. alpha-deg=0:90:91)";
                    let (n, spec) = split_assignment("grid", text, form)?;
                    let parts: Vec<&str> = spec.split(':').collect();
                    if parts.len() != 3 {
                        return Err(CliError::input(format!("--grid {text}: expected {form}")));
                    }
                    let f = field("grid", text, n)?;
                    let start = number("grid", text, parts[0])?;
                    let stop = number("grid", text, parts[1])?;
                    let count: u64 = parts[2].trim().parse().map_err(|_| {
                        CliError::input(format!(
                            "--grid {text}: COUNT `{}` is not a whole number",
                            parts[2]
                        ))
                    })?;
                    let axis = Axis::new(&name(f), start, stop, count)
                        .map_err(|e| CliError::input(format!("--grid {text}: {e}")))?;
                    check_range(f, "grid", text, start, stop)?;
                    twice(&fields, f, "grid", text)?;
                    fields.push(f);
                    axes.push(axis);
                }
                Space::Grid(Grid::new(axes).map_err(|e| CliError::input(format!("--grid: {e}")))?)
            }
            (true, false) => {
                let samples = args.samples.ok_or_else(|| {
                    CliError::input("--random: give the number of points with --samples N")
                })?;
                let mut ranges = Vec::new();
                for text in &args.random {
                    let (n, spec) = split_assignment("random", text, "NAME=LO:HI")?;
                    let parts: Vec<&str> = spec.split(':').collect();
                    if parts.len() != 2 {
                        return Err(CliError::input(format!(
                            "--random {text}: expected NAME=LO:HI"
                        )));
                    }
                    let f = field("random", text, n)?;
                    let lo = number("random", text, parts[0])?;
                    let hi = number("random", text, parts[1])?;
                    let r = SampleRange::new(&name(f), lo, hi)
                        .map_err(|e| CliError::input(format!("--random {text}: {e}")))?;
                    check_range(f, "random", text, lo, hi)?;
                    twice(&fields, f, "random", text)?;
                    fields.push(f);
                    ranges.push(r);
                }
                Space::Random(
                    RandomSamples::new(ranges, samples, args.seed.unwrap_or(0))
                        .map_err(|e| CliError::input(format!("--samples: {e}")))?,
                )
            }
        };
    // A swept field takes every value of its axis: a `--set` of it would be silently ignored.
    if let Some((f, text)) = fixed.iter().find(|(f, _)| fields.contains(f)) {
        return Err(CliError::input(format!(
            "--set {text}: field `{}` is also swept by --{}; give it either a fixed value or a range, not both",
            name(*f),
            kind(args)
        )));
    }
    Ok((fields, space))
}

/// `grid` or `random`: the kind of points asked for.
fn kind(args: &SpaceArgs) -> &'static str {
    if args.grid.is_empty() {
        "random"
    } else {
        "grid"
    }
}

/// Refuse a sweep of more than [`CONFIRM_ABOVE`] impacts without `--yes`, and one whose count
/// overflows.
pub fn confirm(args: &SpaceArgs, space: &Space, laws: usize) -> CliResult<()> {
    let Some(impacts) = space.len().checked_mul(laws as u64) else {
        return Err(CliError::input(format!(
            "--{}: {} points × {laws} laws overflows: more than 2⁶⁴ − 1 impacts, far beyond any sweep (more than 10⁷ impacts already need --yes)",
            kind(args),
            space.len(),
        )));
    };
    if impacts > CONFIRM_ABOVE && !args.yes {
        return Err(CliError::input(format!(
            "{} points × {laws} laws = {impacts} impacts is more than {CONFIRM_ABOVE}: pass --yes to run it",
            space.len(),
        )));
    }
    Ok(())
}

/// The checked `--threads`: between 1 and [`MAX_THREADS`], or None for rayon's default.
pub fn thread_count(threads: Option<i64>) -> CliResult<Option<usize>> {
    match threads {
        None => Ok(None),
        Some(n) if (1..=MAX_THREADS).contains(&n) => Ok(Some(n as usize)),
        Some(n) => Err(CliError::input(format!(
            "--threads: must be between 1 and {MAX_THREADS}, got {n}"
        ))),
    }
}

/// Run `f` in a pool of `threads` threads (default: rayon's, one per core); `threads` is
/// checked by [`thread_count`].
pub fn with_threads<T: Send>(threads: Option<i64>, f: impl FnOnce() -> T + Send) -> CliResult<T> {
    match thread_count(threads)? {
        None => Ok(f()),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| CliError::failure(format!("cannot start {n} threads: {e}")))?;
            Ok(pool.install(f))
        }
    }
}
