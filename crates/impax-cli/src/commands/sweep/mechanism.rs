//! `impax sweep MECHANISM`: a mechanism's impact over its state and coefficients — a built-in
//! mechanism, a mechanism file (planar or `space = "3d"`) or a URDF robot — with the fields
//! `q.NAME` and `u.NAME` (a generalized coordinate or velocity by its name), `friction` and
//! `restitution`, every law, in parallel, as CSV.
//!
//! The contact that strikes is the one chosen at the mechanism's own state (`--contact` for a
//! robot); each point moves the state and resolves that contact's impact (its `W` and `v⁻`
//! at the point's state; the floor's height does not enter them). Rows come in point order
//! and, for each point, in the order of the laws: the output is byte-identical for any
//! `--threads`.

use super::CHUNK_POINTS;
use crate::cli::SweepArgs;
use crate::input::{CliError, CliResult};
use crate::pipeline::progress::Progress;
use crate::pipeline::space;
use crate::sources::{mechanism as planar_source, robot, Source};
use impax::analysis::run_ordered;
use impax::law::Breakdown;
use impax::mechanism::builtin::BuiltIn;
use impax::mechanism::impact::MechanismImpact;
use impax::mechanism::Mechanism;
use impax::multibody::{Model, SpatialMechanismImpact};
use impax::scenario::MechanismSpec;
use impax::LawId;
use std::fmt::Write as _;
use std::io::Write;

/// A field a mechanism sweep sets.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Field {
    /// A generalized coordinate, by index.
    Q(usize),
    /// A generalized velocity, by index.
    U(usize),
    Friction,
    Restitution,
}

/// The mechanism swept: planar (a built-in or a planar file) or spatial (a robot).
enum Swept {
    Planar(BuiltIn),
    Spatial(Model),
}

/// A point of the sweep: the state and the coefficients.
#[derive(Debug, Clone)]
struct State {
    q: Vec<f64>,
    u: Vec<f64>,
    friction: f64,
    restitution: f64,
}

impl State {
    fn set(&mut self, f: Field, x: f64) {
        match f {
            Field::Q(i) => self.q[i] = x,
            Field::U(i) => self.u[i] = x,
            Field::Friction => self.friction = x,
            Field::Restitution => self.restitution = x,
        }
    }
}

/// The mechanism, the names of its coordinates and velocities, the striking contact and the
/// base state.
struct Base {
    swept: Swept,
    coordinates: Vec<String>,
    speeds: Vec<String>,
    contact: usize,
    state: State,
}

impl Base {
    fn field(&self, name: &str) -> Result<Field, String> {
        let known = || {
            let mut all: Vec<String> = self.coordinates.iter().map(|c| format!("q.{c}")).collect();
            all.extend(self.speeds.iter().map(|c| format!("u.{c}")));
            all.extend(["friction".into(), "restitution".into()]);
            all.join(", ")
        };
        let find = |list: &[String], n: &str| list.iter().position(|c| c == n);
        match name {
            "friction" => Ok(Field::Friction),
            "restitution" => Ok(Field::Restitution),
            _ => match name.split_once('.') {
                Some(("q", n)) if find(&self.coordinates, n).is_some() => {
                    Ok(Field::Q(find(&self.coordinates, n).expect("found")))
                }
                Some(("u", n)) if find(&self.speeds, n).is_some() => {
                    Ok(Field::U(find(&self.speeds, n).expect("found")))
                }
                _ => Err(format!("unknown field `{name}` (known: {})", known())),
            },
        }
    }

    fn name(&self, f: Field) -> String {
        match f {
            Field::Q(i) => format!("q.{}", self.coordinates[i]),
            Field::U(i) => format!("u.{}", self.speeds[i]),
            Field::Friction => "friction".into(),
            Field::Restitution => "restitution".into(),
        }
    }

    /// Every law's row at one point: the law, then `status`, `verdict`, `energy_change`,
    /// `energy_ratio`, `normal_impulse`, `phases` and the velocities after.
    fn rows(&self, point: &State, laws: &[LawId], values: &str, out: &mut String) {
        let blank = ",".repeat(self.speeds.len());
        let results = match &self.swept {
            Swept::Planar(m) => {
                MechanismImpact::new(m, &point.q, &point.u, self.contact).and_then(|impact| {
                    let t0 = impact.energy_before();
                    laws.iter()
                        .map(|&law| {
                            let r = impact.resolve(law, point.friction, point.restitution)?;
                            Ok(Law::of(
                                r.resolution.map(|o| {
                                    let after = r.velocities_after.unwrap_or_default();
                                    (
                                        o.verdict.id(),
                                        o.energy_change,
                                        o.impulse.y,
                                        o.phases.summary(),
                                        after,
                                    )
                                }),
                                t0,
                            ))
                        })
                        .collect::<impax::Result<Vec<_>>>()
                })
            }
            Swept::Spatial(model) => {
                SpatialMechanismImpact::new(model, &point.q, &point.u, self.contact).and_then(
                    |impact| {
                        let t0 = impact.energy_before();
                        laws.iter()
                            .map(|&law| {
                                let r = impact.resolve(law, point.friction, point.restitution)?;
                                Ok(Law::of(
                                    r.resolution.map(|o| {
                                        let after = r.velocities_after.unwrap_or_default();
                                        (
                                            o.verdict.id(),
                                            o.energy_change,
                                            o.impulse.z,
                                            o.phases.summary(),
                                            after,
                                        )
                                    }),
                                    t0,
                                ))
                            })
                            .collect::<impax::Result<Vec<_>>>()
                    },
                )
            }
        };
        let results = match results {
            Ok(r) => r,
            Err(e) => {
                let reason = e.to_string().replace('"', "'");
                for law in laws {
                    let _ = writeln!(out, "{values},{law},invalid,,,,,\"{reason}\"{blank}");
                }
                return;
            }
        };
        for (law, r) in laws.iter().zip(results) {
            match r {
                Law::Resolved {
                    verdict,
                    de,
                    ratio,
                    pn,
                    phases,
                    after,
                } => {
                    let _ = write!(
                        out,
                        "{values},{law},ok,{verdict},{de},{ratio},{pn},{phases}"
                    );
                    for x in after {
                        let _ = write!(out, ",{x}");
                    }
                    out.push('\n');
                }
                Law::Broken(id) => {
                    let _ = writeln!(out, "{values},{law},breakdown,{id},,,,{blank}");
                }
            }
        }
    }
}

/// One law's result at a point, whatever the mechanism's dimension.
enum Law {
    Resolved {
        verdict: &'static str,
        de: f64,
        ratio: f64,
        pn: f64,
        phases: String,
        after: Vec<f64>,
    },
    /// The breakdown's id.
    Broken(&'static str),
}

impl Law {
    /// From `(verdict, ΔT, p_n, phases, u⁺)` or a breakdown, with the energy before `t0`.
    fn of(r: Result<(&'static str, f64, f64, String, Vec<f64>), Breakdown>, t0: f64) -> Self {
        match r {
            Ok((verdict, de, pn, phases, after)) => Law::Resolved {
                verdict,
                de,
                ratio: (t0 + de) / t0,
                pn,
                phases,
                after,
            },
            Err(b) => Law::Broken(b.reason.id()),
        }
    }
}

/// The mechanism named by `source`, at its state, with the flags of the sweep (`--law`).
fn base(source: &Source, args: &SweepArgs) -> CliResult<(Base, Vec<LawId>)> {
    match source {
        Source::Robot(file) => {
            let case = robot::load(file, &args.mechanism, None, None, &args.space.law)?;
            let built = case.spec.build()?;
            let base = Base {
                coordinates: built.model.coordinates().to_vec(),
                speeds: built.model.speeds().to_vec(),
                contact: built.contact,
                state: State {
                    q: built.q,
                    u: built.u,
                    friction: case.friction,
                    restitution: case.restitution,
                },
                swept: Swept::Spatial(built.model),
            };
            Ok((base, case.laws))
        }
        _ => {
            let flags = &args.mechanism;
            let spec = planar_source::load_source(
                source,
                &MechanismSpec {
                    masses: flags.masses.clone(),
                    lengths: flags.lengths.clone(),
                    gravity: flags.gravity,
                    angles: flags.angles_deg.clone(),
                    rates: flags.rates.clone(),
                    position: flags.position.clone(),
                    q: flags.q.clone(),
                    u: flags.u.clone(),
                    ..MechanismSpec::default()
                },
            )?;
            for (flag, given) in [
                ("contact", !flags.contact.is_empty()),
                ("floating-base", flags.floating_base),
                ("floor", flags.floor.is_some()),
            ] {
                if given {
                    return Err(CliError::input(format!(
                        "--{flag}: for a robot (URDF) or a 3D mechanism file"
                    )));
                }
            }
            let case = planar_source::build(&spec)?;
            let impact = MechanismImpact::striking(&case.mechanism, &case.q, &case.u)
                .map_err(|e| CliError::input(format!("the mechanism's own state: {e}")))?;
            let contact = impact.contact();
            let laws = if !args.space.law.is_empty() {
                crate::sources::scenario::parse_laws(&args.space.law)?
            } else if let Some(ids) = &spec.laws {
                crate::sources::scenario::parse_laws(ids)?
            } else {
                LawId::CONTACT_SPACE.to_vec()
            };
            let names: Vec<String> = case
                .mechanism
                .coordinates()
                .iter()
                .map(|c| c.to_string())
                .collect();
            let base = Base {
                coordinates: names.clone(),
                speeds: names,
                contact,
                state: State {
                    q: case.q,
                    u: case.u,
                    friction: spec.friction.unwrap_or(0.5),
                    restitution: spec.restitution.unwrap_or(0.5),
                },
                swept: Swept::Planar(case.mechanism),
            };
            Ok((base, laws))
        }
    }
}

/// Run the sweep of a mechanism (CSV only).
pub fn run(source: &Source, args: &SweepArgs) -> CliResult<()> {
    if args.format != "csv" || !args.columns.is_empty() {
        return Err(CliError::input(
            "--format/--columns: a mechanism's sweep is CSV with its own columns (status, verdict, energy_change, energy_ratio, normal_impulse, phases, u_after.NAME…)",
        ));
    }
    space::thread_count(args.space.threads)?;
    let (mut base, laws) = base(source, args)?;
    let lookup = |name: &str| base.field(name);
    let names = |f: Field| base.name(f);
    let mut fixed = Vec::new();
    let (fields, points) = space::points(
        &args.space,
        lookup,
        names,
        |f: Field, lo, hi| match f {
            Field::Friction if lo < 0.0 => Err(format!("friction must be ≥ 0, got {lo}")),
            Field::Restitution if lo < 0.0 || hi > 1.0 => {
                Err(format!("restitution must be in [0, 1], got {lo} to {hi}"))
            }
            _ => Ok(()),
        },
        |f, x| fixed.push((f, x)),
    )?;
    for (f, x) in fixed {
        base.state.set(f, x);
    }
    space::confirm(&args.space, &points, laws.len())?;
    let mut w: Box<dyn Write + Send> = match &args.out {
        Some(path) => Box::new(std::io::BufWriter::new(
            std::fs::File::create(path).map_err(|e| {
                CliError::input(format!("--out {}: cannot create: {e}", path.display()))
            })?,
        )),
        None => Box::new(std::io::BufWriter::new(std::io::stdout())),
    };
    let mut header: Vec<String> = fields.iter().map(|&f| base.name(f)).collect();
    header.extend(
        [
            "law",
            "status",
            "verdict",
            "energy_change",
            "energy_ratio",
            "normal_impulse",
            "phases",
        ]
        .map(String::from),
    );
    header.extend(base.speeds.iter().map(|s| format!("u_after.{s}")));
    let io = |e: std::io::Error| CliError::failure(format!("cannot write the output: {e}"));
    w.write_all((header.join(",") + "\n").as_bytes())
        .map_err(io)?;
    let total = points.len();
    let progress = Progress::new(total, args.space.quiet);
    let result = space::with_threads(args.space.threads, || {
        run_ordered(
            total,
            CHUNK_POINTS,
            |range| {
                let n = range.end - range.start;
                let mut out = String::new();
                let mut point = base.state.clone();
                points.for_each_in(range, |_, values| {
                    for (&f, &x) in fields.iter().zip(values) {
                        point.set(f, x);
                    }
                    let shown: Vec<String> = values.iter().map(|x| x.to_string()).collect();
                    base.rows(&point, &laws, &shown.join(","), &mut out);
                });
                (n, out)
            },
            |(n, out): (u64, String)| {
                w.write_all(out.as_bytes()).map_err(io)?;
                progress.advance(n);
                Ok::<(), CliError>(())
            },
        )
    })?;
    result?;
    w.flush().map_err(io)?;
    progress.finish("sweep", total, laws.len());
    Ok(())
}
