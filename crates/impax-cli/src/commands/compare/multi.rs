//! `impax compare NAME` for the built-in systems struck at several contacts (`rod-flat`,
//! `rocking-block`, `cradle`, `ball-ball-wall`, and in 3D `box-flat`;
//! `impax::multi::scenarios`): every multi-contact law side by side with the generalized
//! velocities after and the energy ratio.

use crate::cli::{CompareArgs, MultiFlags};
use crate::input::{CliError, CliResult};
use crate::output::fmt::{signed, Plain, Table};
use crate::output::json::{self, num};
use crate::sources::scenario::parse_laws;
use impax::law::{Breakdown, Inconsistency, Verdict};
use impax::multi::scenarios::{BallBallWall, BoxFlat, Cradle, RockingBlock, RodFlat, NAMES};
use impax::multi::spatial as multi3;
use impax::multi::{lcp, MultiProblem, MultiScenario};
use impax::LawId;
use serde_json::{json, Value};

/// The built-ins' names (for [`crate::sources::Source::classify`]'s callers).
pub const BUILT_INS: [&str; 5] = NAMES;

/// The flags of `lzb`'s force law, which every built-in takes.
const FORCE_LAW: [&str; 2] = ["stiffness", "exponent"];

/// The flags each built-in takes (besides `--friction`, `--restitution`, `--law`, `--json`
/// and [`FORCE_LAW`]).
fn accepted(name: &str) -> &'static [&'static str] {
    match name {
        "rod-flat" => &["mass", "length", "vx", "vy", "omega"],
        "rocking-block" => &["mass", "half-width", "half-height", "omega"],
        "cradle" => &["balls", "mass", "radius", "v0"],
        "box-flat" => &["mass", "half-extents", "vx", "vy", "vz", "omega"],
        _ => &["mass", "radius", "v0", "angle-deg"],
    }
}

/// Build the built-in `name` from the flags (defaults for those not given).
pub fn build(name: &str, args: &CompareArgs) -> CliResult<MultiScenario> {
    for (flag, given) in [
        ("alpha-deg", args.alpha_deg.is_some()),
        ("spin-ratio", args.spin_ratio.is_some()),
        ("speed", args.speed.is_some()),
        ("plot", args.plot.is_some()),
    ] {
        if given {
            return Err(CliError::input(format!(
                "--{flag}: not a parameter of `{name}` (it takes --{})",
                accepted(name).join(", --")
            )));
        }
    }
    if let Some(flag) = args.mechanism.first_given() {
        return Err(CliError::input(format!(
            "--{flag}: not a parameter of `{name}` (it takes --{})",
            accepted(name).join(", --")
        )));
    }
    built_in(name, args.mass, args.radius, &args.multi)
}

/// Build the built-in `name` from its parameters (`--mass`, `--radius` and the multi-contact
/// flags; defaults for those not given), refusing a flag it does not take.
pub fn built_in(
    name: &str,
    mass: Option<f64>,
    radius: Option<f64>,
    f: &MultiFlags,
) -> CliResult<MultiScenario> {
    let mut given = f.given();
    if mass.is_some() {
        given.push("mass");
    }
    if radius.is_some() {
        given.push("radius");
    }
    if let Some(flag) = given
        .iter()
        .find(|f| !accepted(name).contains(f) && !FORCE_LAW.contains(f))
    {
        return Err(CliError::input(format!(
            "--{flag}: not a parameter of `{name}` (it takes --{})",
            accepted(name).join(", --")
        )));
    }
    let scenario = match name {
        "rod-flat" => {
            let d = RodFlat::default();
            RodFlat {
                mass: mass.unwrap_or(d.mass),
                length: f.length.unwrap_or(d.length),
                vx: f.vx.unwrap_or(d.vx),
                vy: f.vy.unwrap_or(d.vy),
                omega: f.omega.unwrap_or(d.omega),
            }
            .build()?
        }
        "rocking-block" => {
            let d = RockingBlock::default();
            RockingBlock {
                mass: mass.unwrap_or(d.mass),
                half_width: f.half_width.unwrap_or(d.half_width),
                half_height: f.half_height.unwrap_or(d.half_height),
                omega: f.omega.unwrap_or(d.omega),
            }
            .build()?
        }
        "cradle" => {
            let d = Cradle::default();
            Cradle {
                balls: f.balls.unwrap_or(d.balls),
                mass: mass.unwrap_or(d.mass),
                radius: radius.unwrap_or(d.radius),
                v0: f.v0.unwrap_or(d.v0),
            }
            .build()?
        }
        "box-flat" => {
            let d = BoxFlat::default();
            let half_extents = match &f.half_extents {
                None => d.half_extents,
                Some(h) => <[f64; 3]>::try_from(h.as_slice()).map_err(|_| {
                    CliError::input(format!(
                        "--half-extents: expected 3 numbers A,B,C, got {}",
                        h.len()
                    ))
                })?,
            };
            BoxFlat {
                mass: mass.unwrap_or(d.mass),
                half_extents,
                velocity: [
                    f.vx.unwrap_or(d.velocity[0]),
                    f.vy.unwrap_or(d.velocity[1]),
                    f.vz.unwrap_or(d.velocity[2]),
                ],
                spin: f.omega.unwrap_or(d.spin),
            }
            .build()?
        }
        _ => {
            let d = BallBallWall::default();
            BallBallWall {
                mass: mass.unwrap_or(d.mass),
                radius: radius.unwrap_or(d.radius),
                v0: f.v0.unwrap_or(d.v0),
                angle_deg: f.angle_deg.unwrap_or(d.angle_deg),
            }
            .build()?
        }
    };
    Ok(scenario)
}

/// The laws: `--law`, or every multi-contact law that takes this many contacts.
pub fn laws(ids: &[String], contacts: usize) -> CliResult<Vec<LawId>> {
    Ok(if ids.is_empty() {
        LawId::MULTI_CONTACT
            .into_iter()
            .filter(|l| *l != LawId::Lcp || contacts <= lcp::MAX_CONTACTS)
            .collect()
    } else {
        parse_laws(ids)?
    })
}

/// The built-in's contact-space problem with μ and e (the scenario's unless given) and
/// `lzb`'s force law from `--stiffness` and `--exponent`.
pub fn problem(
    name: &str,
    sc: &MultiScenario,
    friction: Option<f64>,
    restitution: Option<f64>,
    f: &MultiFlags,
) -> CliResult<MultiProblem> {
    let friction = friction.unwrap_or(sc.friction);
    let restitution = restitution.unwrap_or(sc.restitution);
    let mut problem = sc
        .impact
        .problem(&[friction], &[restitution])
        .map_err(|e| match e {
            impax::Error::NotApproaching { .. } => {
                let v = sc.impact.contact_velocities();
                CliError::input(format!(
                    "vy, omega: no end of the rod comes down (normal velocities {} and {}): `{name}` strikes only while an end approaches the floor",
                    short(v[1]),
                    short(v[3])
                ))
            }
            other => other.into(),
        })?;
    if let Some(kappa) = &f.stiffness {
        problem = problem.with_stiffness(kappa)?;
    }
    if let Some(eta) = f.exponent {
        problem = problem.with_exponent(eta)?;
    }
    Ok(problem)
}

pub fn run(name: &str, args: &CompareArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let sc = build(name, args)?;
    let (view, rows) = resolve_all(
        name,
        &sc,
        args.friction,
        args.restitution,
        &args.multi,
        &args.law,
    )?;
    let text = if args.json {
        serde_json::to_string_pretty(&document(&sc, &view, &rows)).map_err(CliError::failure)?
            + "\n"
    } else {
        table(&sc, &view, &rows)
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}

/// What the tables and documents show of one law's result, planar or spatial.
pub struct LawRow {
    /// The law.
    pub law: LawId,
    /// Its numbers, or why it broke down.
    pub result: Result<RowNumbers, Breakdown>,
    /// The entry of `impax resolve --contacts K --json`.
    pub entry: Value,
    /// `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻`.
    pub energy_change_from_velocities: Option<f64>,
}

/// The numbers of a law that applied.
pub struct RowNumbers {
    /// The generalized velocities after.
    pub velocities_after: Vec<f64>,
    /// Each contact's normal impulse.
    pub normal_impulses: Vec<f64>,
    /// Each contact's phases in words.
    pub phases: Vec<String>,
    /// `ΔT`.
    pub energy_change: f64,
    /// The verdict.
    pub verdict: Verdict,
    /// A contradicted assumption.
    pub inconsistency: Option<Inconsistency>,
}

/// What the header shows of the contact-space problem.
pub struct ProblemView {
    /// `1 end A (0, -1), 2 …`.
    pub contacts: String,
    /// `(v_t, v_n)` or `(v_t1, v_t2, v_n)`.
    pub frame: &'static str,
    /// The size of `W` (`dK`) and its rank.
    pub size: usize,
    /// The rank of `W`.
    pub rank: usize,
    /// The first contact's μ and e.
    pub friction: f64,
    /// The first contact's e.
    pub restitution: f64,
    /// `lzb`'s force law when not the default.
    pub force_law: String,
    /// The problem as JSON.
    pub json: Value,
}

/// Every law (`--law`, or those that take the built-in's contacts) on the built-in, planar or
/// spatial.
pub fn resolve_all(
    name: &str,
    sc: &MultiScenario,
    friction: Option<f64>,
    restitution: Option<f64>,
    f: &MultiFlags,
    law_ids: &[String],
) -> CliResult<(ProblemView, Vec<LawRow>)> {
    let names = sc.impact.contacts();
    if sc.impact.is_spatial() {
        let mut p = sc
            .impact
            .spatial_problem(
                &[friction.unwrap_or(sc.friction)],
                &[restitution.unwrap_or(sc.restitution)],
            )
            .map_err(|e| match e {
                impax::Error::NotApproaching { value, .. } => CliError::input(format!(
                    "vz: the box does not come down (its corners' normal velocity is {}): `{name}` strikes only while it lands",
                    short(value)
                )),
                other => other.into(),
            })?;
        if let Some(kappa) = &f.stiffness {
            p = p.with_stiffness(kappa)?;
        }
        if let Some(eta) = f.exponent {
            p = p.with_exponent(eta)?;
        }
        let k = p.contacts();
        let laws = if law_ids.is_empty() {
            [LawId::Lcp, LawId::Sequential, LawId::Lzb]
                .into_iter()
                .filter(|l| *l != LawId::Lcp || k <= multi3::lcp::MAX_CONTACTS)
                .collect()
        } else {
            parse_laws(law_ids)?
        };
        let mut rows = Vec::new();
        for law in laws {
            let r = sc.impact.resolve(law, &p)?;
            rows.push(LawRow {
                law,
                entry: json::multi3_entry(&r.resolution),
                energy_change_from_velocities: r.energy_change_from_velocities,
                result: r.resolution.map(|o| RowNumbers {
                    velocities_after: r.velocities_after.unwrap_or_default(),
                    normal_impulses: o.contacts.iter().map(|c| c.impulse.z).collect(),
                    phases: o.contacts.iter().map(|c| c.phase_summary()).collect(),
                    energy_change: o.energy_change,
                    verdict: o.verdict,
                    inconsistency: o.inconsistency,
                }),
            });
        }
        let view = ProblemView {
            contacts: (0..k)
                .map(|j| {
                    let c = p.contact_velocity(j);
                    format!(
                        "{} {} ({}, {}, {})",
                        j + 1,
                        names[j],
                        short(c.x),
                        short(c.y),
                        short(c.z)
                    )
                })
                .collect::<Vec<_>>()
                .join(", "),
            frame: "(v_t1, v_t2, v_n)",
            size: 3 * k,
            rank: p.rank(),
            friction: p.friction(0),
            restitution: p.restitution(0),
            force_law: String::new(),
            json: json::multi3_problem(&p),
        };
        return Ok((view, rows));
    }
    let p = problem(name, sc, friction, restitution, f)?;
    let k = p.contacts();
    let mut rows = Vec::new();
    for law in laws(law_ids, k)? {
        let r = sc.impact.resolve(law, &p)?;
        rows.push(LawRow {
            law,
            entry: json::multi_entry(&r.resolution),
            energy_change_from_velocities: r.energy_change_from_velocities,
            result: r.resolution.map(|o| RowNumbers {
                velocities_after: r.velocities_after.unwrap_or_default(),
                normal_impulses: o.contacts.iter().map(|c| c.impulse.y).collect(),
                phases: o.contacts.iter().map(|c| c.phase_summary()).collect(),
                energy_change: o.energy_change,
                verdict: o.verdict,
                inconsistency: o.inconsistency,
            }),
        });
    }
    let view = ProblemView {
        contacts: (0..k)
            .map(|j| {
                let c = p.contact_velocity(j);
                format!("{} {} ({}, {})", j + 1, names[j], short(c.x), short(c.y))
            })
            .collect::<Vec<_>>()
            .join(", "),
        frame: "(v_t, v_n)",
        size: 2 * k,
        rank: p.rank(),
        friction: p.friction(0),
        restitution: p.restitution(0),
        force_law: crate::commands::resolve::force_law(&p),
        json: json::multi_problem(&p),
    };
    Ok((view, rows))
}

/// The JSON document: `scenario`, `description`, `coordinates`, `u_before`, `contact_names`,
/// `problem`, `energy_before`, `results` (each `impax resolve --contacts`'s entry plus
/// `velocities_after`, `energy_after`, `energy_ratio`, `energy_change_from_velocities`).
pub fn document(sc: &MultiScenario, view: &ProblemView, rows: &[LawRow]) -> Value {
    let t0 = sc.impact.energy_before();
    let entries: Vec<Value> = rows
        .iter()
        .map(|r| {
            let mut e = r.entry.clone();
            let m = e.as_object_mut().expect("an object");
            match &r.result {
                Ok(o) => {
                    m.insert(
                        "velocities_after".into(),
                        json!(o
                            .velocities_after
                            .iter()
                            .map(|&x| num(x))
                            .collect::<Vec<_>>()),
                    );
                    m.insert("energy_after".into(), num(t0 + o.energy_change));
                    m.insert("energy_ratio".into(), num((t0 + o.energy_change) / t0));
                    m.insert(
                        "energy_change_from_velocities".into(),
                        r.energy_change_from_velocities.map_or(Value::Null, num),
                    );
                }
                Err(_) => {
                    for k in [
                        "velocities_after",
                        "energy_after",
                        "energy_ratio",
                        "energy_change_from_velocities",
                    ] {
                        m.insert(k.into(), Value::Null);
                    }
                }
            }
            e
        })
        .collect();
    json!({
        "scenario": sc.name,
        "description": sc.description,
        "coordinates": sc.impact.coordinates(),
        "u_before": sc.impact.velocities_before().iter().map(|&x| num(x)).collect::<Vec<_>>(),
        "contact_names": sc.impact.contacts(),
        "problem": view.json,
        "energy_before": t0,
        "results": entries,
    })
}

/// The coordinates worth a column: those moving before, or after under some law (a cradle's
/// vertical velocities and spins stay zero).
pub fn shown(sc: &MultiScenario, rows: &[LawRow]) -> Vec<usize> {
    let before = sc.impact.velocities_before();
    let scale = before.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    (0..before.len())
        .filter(|&i| {
            before[i] != 0.0
                || rows.iter().any(|r| {
                    r.result
                        .as_ref()
                        .is_ok_and(|o| o.velocities_after[i].abs() > 1e-12 * scale)
                })
        })
        .collect()
}

/// Six significant digits, without trailing zeros (`-0.5`, `0.266667`).
fn short(x: f64) -> String {
    let s = format!("{:.6e}", x);
    let v: f64 = s.parse().expect("a number");
    Plain(v).to_string()
}

fn table(sc: &MultiScenario, view: &ProblemView, rows: &[LawRow]) -> String {
    let coords = sc.impact.coordinates();
    let k = sc.impact.contacts().len();
    let t0 = sc.impact.energy_before();
    let cols_shown = shown(sc, rows);
    let mut columns: Vec<(String, bool)> = vec![("law".into(), false)];
    for &i in &cols_shown {
        columns.push((format!("{}+", coords[i]), true));
    }
    for j in 1..=k {
        columns.push((format!("p_n{j}"), true));
    }
    columns.extend([
        ("ΔT".into(), true),
        ("T+/T-".into(), true),
        ("verdict".into(), false),
    ]);
    let cols: Vec<(&str, bool)> = columns.iter().map(|(s, r)| (s.as_str(), *r)).collect();
    let mut t = Table::new(&cols);
    let mut notes = Vec::new();
    for r in rows {
        let law = r.law;
        match &r.result {
            Ok(o) => {
                let mut row = vec![law.to_string()];
                row.extend(cols_shown.iter().map(|&i| signed(o.velocities_after[i], 5)));
                row.extend(o.normal_impulses.iter().map(|&x| signed(x, 5)));
                row.extend([
                    signed(o.energy_change, 5),
                    format!("{:.5}", (t0 + o.energy_change) / t0),
                    o.verdict.id().to_string(),
                ]);
                t.row(row);
                if let Some(i) = o.inconsistency {
                    notes.push(format!("{law}: {i}"));
                }
            }
            Err(b) => {
                let mut row = vec![law.to_string()];
                row.extend(std::iter::repeat_n(
                    "—".to_string(),
                    cols_shown.len() + k + 2,
                ));
                row.push("breakdown".into());
                t.row(row);
                notes.push(format!("{law}: breakdown: {}", b.reason));
            }
        }
    }
    let mut text = format!(
        "impax compare — {}; μ = {}, e = {}{}\ncontacts (v⁻ = {}): {}; W {n} × {n} of rank {}; T⁻ = {}\n\n",
        sc.description,
        Plain(view.friction),
        Plain(view.restitution),
        view.force_law,
        view.frame,
        view.contacts,
        view.rank,
        short(t0),
        n = view.size,
    );
    text.push_str(&t.render());
    let hidden = coords.len() - cols_shown.len();
    text.push_str(&format!(
        "\n{}: generalized velocities after{}; p_nj: contact j's normal impulse; ΔT = T⁺ − T⁻\n",
        cols_shown
            .iter()
            .map(|&i| format!("{}+", coords[i]))
            .collect::<Vec<_>>()
            .join(", "),
        if hidden == 1 {
            " (the other one is 0 before and after)".to_string()
        } else if hidden > 1 {
            format!(" (the other {hidden} are 0 before and after)")
        } else {
            String::new()
        }
    ));
    text.push_str(&crate::output::fmt::notes(&notes));
    text
}
