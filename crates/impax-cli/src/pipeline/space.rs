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

impl Setup {
    /// Points × laws, or None if the product overflows `u64`.
    pub fn impacts(&self) -> Option<u64> {
        self.space.len().checked_mul(self.laws.len() as u64)
    }
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

fn field(template: &Template, flag: &str, text: &str, name: &str) -> CliResult<Field> {
    template
        .field(name)
        .map_err(|e| CliError::input(format!("--{flag} {text}: {e}")))
}

fn check_range(f: Field, flag: &str, text: &str, lo: f64, hi: f64) -> CliResult<()> {
    f.check_range(lo, hi)
        .map_err(|e| CliError::input(format!("--{flag} {text}: {e}")))
}

/// Parse and check the points of a sweep.
pub fn setup(args: &SpaceArgs) -> CliResult<Setup> {
    thread_count(args.threads)?;
    let mut template = Template::load(args.scenario.as_deref())?;
    let laws = if args.law.is_empty() {
        template.laws.clone()
    } else {
        parse_laws(&args.law)?
    };
    let mut set = Vec::new();
    for text in &args.set {
        let (name, value) = split_assignment("set", text, "NAME=VALUE")?;
        let f = field(&template, "set", text, name)?;
        let x = number("set", text, value)?;
        check_range(f, "set", text, x, x)?;
        template.set(f, x);
        set.push((f, text));
    }
    let mut fields = Vec::new();
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
                    let (name, spec) = split_assignment(
                        "grid",
                        text,
                        "NAME=START:STOP:COUNT (e.g. alpha-deg=0:90:91)",
                    )?;
                    let parts: Vec<&str> = spec.split(':').collect();
                    if parts.len() != 3 {
                        return Err(CliError::input(format!(
                        "--grid {text}: expected NAME=START:STOP:COUNT (e.g. alpha-deg=0:90:91)"
                    )));
                    }
                    let f = field(&template, "grid", text, name)?;
                    let start = number("grid", text, parts[0])?;
                    let stop = number("grid", text, parts[1])?;
                    let count: u64 = parts[2].trim().parse().map_err(|_| {
                        CliError::input(format!(
                            "--grid {text}: COUNT `{}` is not a whole number",
                            parts[2]
                        ))
                    })?;
                    let axis = Axis::new(&f.name(), start, stop, count)
                        .map_err(|e| CliError::input(format!("--grid {text}: {e}")))?;
                    check_range(f, "grid", text, start, stop)?;
                    if fields.contains(&f) {
                        return Err(CliError::input(format!(
                            "--grid {text}: field `{}` is swept twice",
                            f.name()
                        )));
                    }
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
                    let (name, spec) = split_assignment("random", text, "NAME=LO:HI")?;
                    let parts: Vec<&str> = spec.split(':').collect();
                    if parts.len() != 2 {
                        return Err(CliError::input(format!(
                            "--random {text}: expected NAME=LO:HI"
                        )));
                    }
                    let f = field(&template, "random", text, name)?;
                    let lo = number("random", text, parts[0])?;
                    let hi = number("random", text, parts[1])?;
                    let r = SampleRange::new(&f.name(), lo, hi)
                        .map_err(|e| CliError::input(format!("--random {text}: {e}")))?;
                    check_range(f, "random", text, lo, hi)?;
                    if fields.contains(&f) {
                        return Err(CliError::input(format!(
                            "--random {text}: field `{}` is swept twice",
                            f.name()
                        )));
                    }
                    fields.push(f);
                    ranges.push(r);
                }
                Space::Random(
                    RandomSamples::new(ranges, samples, args.seed.unwrap_or(0))
                        .map_err(|e| CliError::input(format!("--samples: {e}")))?,
                )
            }
        };
    let kind = if args.grid.is_empty() {
        "random"
    } else {
        "grid"
    };
    // A swept field takes every value of its axis: a `--set` of it would be silently ignored.
    if let Some((f, text)) = set.iter().find(|(f, _)| fields.contains(f)) {
        return Err(CliError::input(format!(
            "--set {text}: field `{}` is also swept by --{kind}; give it either a fixed value or a range, not both",
            f.name()
        )));
    }
    let setup = Setup {
        template,
        fields,
        space,
        laws,
    };
    let Some(impacts) = setup.impacts() else {
        return Err(CliError::input(format!(
            "--{kind}: {} points × {} laws overflows: more than 2⁶⁴ − 1 impacts, far beyond any sweep (more than 10⁷ impacts already need --yes)",
            setup.space.len(),
            setup.laws.len()
        )));
    };
    if impacts > CONFIRM_ABOVE && !args.yes {
        return Err(CliError::input(format!(
            "{} points × {} laws = {impacts} impacts is more than {CONFIRM_ABOVE}: pass --yes to run it",
            setup.space.len(),
            setup.laws.len()
        )));
    }
    Ok(setup)
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
