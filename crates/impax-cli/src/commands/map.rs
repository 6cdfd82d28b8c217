//! `impax map`: a 2-parameter sweep drawn per law — the sign of ΔT (Kane's paradox), the
//! phase sequence, or any numeric output — as PNG or SVG.
//!
//! For paper A's case (a sphere given by v0, α, γ on a fixed plane, swept over `alpha-deg`
//! and `spin-ratio`), the `whittaker` panel also shows the energy-gain boundary found by the
//! engine on the grid and the analytic threshold of paper A eq. 13, and the text report
//! compares them column by column.

use crate::cli::MapArgs;
use crate::commands::sweep::CHUNK_POINTS;
use crate::input::{CliError, CliResult};
use crate::output::plot::map::{Cells, MapAxis, MapFigure, Overlay};
use crate::output::plot::{self, Format};
use crate::pipeline::columns::{body_after, Column};
use crate::pipeline::evaluate;
use crate::pipeline::progress::Progress;
use crate::pipeline::space::{self, Setup};
use crate::pipeline::template::{Field, Param};
use impax::analysis::{run_ordered, whittaker_sphere_thresholds, Axis, Sequence, Space, Status};
use impax::planar::Verdict;
use impax::LawId;
use plotters::style::RGBColor;

/// What a map shows.
#[derive(Debug, Clone, Copy, PartialEq)]
enum What {
    Sign,
    Sequence,
    Scalar(Column),
}

/// Sign classes.
const GAINED: u8 = 0;
const LOST: u8 = 1;
const BREAKDOWN: u8 = 2;
const INVALID: u8 = 3;

fn sign_classes() -> Vec<(String, RGBColor)> {
    vec![
        (
            "ΔT > 0: energy gained (Kane's paradox)".into(),
            RGBColor(215, 48, 39),
        ),
        ("ΔT ≤ 0: energy lost".into(), RGBColor(171, 210, 230)),
        ("breakdown of the law".into(), RGBColor(80, 80, 80)),
        ("invalid point".into(), RGBColor(245, 245, 245)),
    ]
}

fn sequence_classes() -> Vec<(String, RGBColor)> {
    Sequence::ALL
        .iter()
        .map(|s| {
            let (label, c) = match s {
                Sequence::Slip => ("slip throughout", RGBColor(253, 174, 97)),
                Sequence::SlipStick => ("slip → stick", RGBColor(102, 189, 99)),
                Sequence::SlipReverse => ("slip → reversed slip", RGBColor(152, 78, 163)),
                Sequence::Stick => ("stick throughout", RGBColor(55, 126, 184)),
                Sequence::NoSlip => ("no slip, no friction", RGBColor(255, 255, 153)),
                Sequence::None => ("none (breakdown or invalid)", RGBColor(150, 150, 150)),
            };
            (label.to_string(), c)
        })
        .collect()
}

fn sign_class(status: Status) -> u8 {
    match status {
        Status::Resolved(Verdict::EnergyGained) => GAINED,
        Status::Resolved(_) => LOST,
        Status::Breakdown => BREAKDOWN,
        Status::Invalid => INVALID,
    }
}

pub fn run(args: &MapArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let what = match args.what.as_str() {
        "sign" => What::Sign,
        "sequence" => What::Sequence,
        other => match Column::parse(other) {
            Some(c) if !c.is_text() => What::Scalar(c),
            _ => {
                let numeric: Vec<&str> = Column::ALL
                    .iter()
                    .filter(|c| !c.is_text())
                    .map(|c| c.name())
                    .collect();
                return Err(CliError::input(format!(
                    "--what: unknown quantity `{other}` (known: sign, sequence, {})",
                    numeric.join(", ")
                )));
            }
        },
    };
    Format::of("out", &args.out)?;
    let size = args.size.as_deref().map(plot::parse_size).transpose()?;
    if !args.space.random.is_empty() {
        return Err(CliError::input(
            "--random: a map needs a grid: give two --grid axes (x first, then y)",
        ));
    }
    if args.space.grid.len() != 2 {
        return Err(CliError::input(format!(
            "--grid: a map needs exactly two grid axes (x first, then y), got {}",
            args.space.grid.len()
        )));
    }
    let setup = space::setup(&args.space)?;
    let Space::Grid(grid) = &setup.space else {
        return Err(CliError::input("--grid: a map needs a grid"));
    };
    // A file that cannot be written is bad input: say so before sweeping.
    std::fs::File::create(&args.out).map_err(|e| {
        CliError::input(format!("--out {}: cannot create: {e}", args.out.display()))
    })?;
    let (ax, ay) = (grid.axes()[0].clone(), grid.axes()[1].clone());
    let nl = setup.laws.len();
    let total = setup.space.len();
    let whittaker = setup.laws.iter().position(|&l| l == LawId::Whittaker);
    let seed_axes = seed_axes(&setup);

    // Sweep: one value per cell and law, plus Whittaker's gain flags for the comparison.
    let mut cat: Vec<Vec<u8>> = vec![Vec::new(); nl];
    let mut scal: Vec<Vec<f32>> = vec![Vec::new(); nl];
    let mut gain: Vec<bool> = Vec::new();
    let progress = Progress::new(total, args.space.quiet);
    let quantity = what;
    let keep = matches!(what, What::Scalar(c) if c.needs_body());
    space::with_threads(args.space.threads, || {
        let r = run_ordered(
            total,
            CHUNK_POINTS,
            |range| {
                let n = (range.end - range.start) as usize;
                let mut c = vec![Vec::with_capacity(n); nl];
                let mut s = vec![Vec::with_capacity(n); nl];
                let mut g = Vec::with_capacity(n);
                evaluate::chunk(&setup, range, keep, |_, _, point, sums| {
                    for (k, x) in sums.iter().enumerate() {
                        match quantity {
                            What::Sign => c[k].push(sign_class(x.status)),
                            What::Sequence => c[k].push(x.sequence as u8),
                            What::Scalar(col) => {
                                let body = if col.needs_body() {
                                    body_after(x, point)
                                } else {
                                    [f64::NAN; 3]
                                };
                                s[k].push(col.value(x, point, body) as f32)
                            }
                        }
                    }
                    if let Some(w) = whittaker {
                        g.push(sign_class(sums[w].status) == GAINED);
                    }
                });
                (n as u64, c, s, g)
            },
            |(n, c, s, g)| {
                for (dst, src) in cat.iter_mut().zip(c) {
                    dst.extend(src);
                }
                for (dst, src) in scal.iter_mut().zip(s) {
                    dst.extend(src);
                }
                gain.extend(g);
                progress.advance(n);
                Ok::<(), CliError>(())
            },
        );
        progress.finish("map", total, nl);
        r
    })??;

    let cells = match what {
        What::Sign => Cells::Categories {
            data: cat,
            classes: sign_classes(),
        },
        What::Sequence => Cells::Categories {
            data: cat,
            classes: sequence_classes(),
        },
        What::Scalar(col) => {
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for v in scal
                .iter()
                .flatten()
                .map(|&v| v as f64)
                .filter(|v| v.is_finite())
            {
                lo = lo.min(v);
                hi = hi.max(v);
            }
            if !lo.is_finite() {
                (lo, hi) = (0.0, 1.0);
            }
            Cells::Scalar {
                data: scal,
                label: col.label().to_string(),
                lo,
                hi,
                diverging: lo < 0.0 && hi > 0.0,
            }
        }
    };

    let mut report = String::new();
    let mut overlays = Vec::new();
    if let (Some(w), Some(axes)) = (whittaker, seed_axes) {
        let cmp = compare_threshold(&setup, &ax, &ay, axes, &gain);
        report.push_str(&cmp.report);
        overlays = cmp.overlays(w, nl);
    }
    let quantity_text = match what {
        What::Sign => "sign of ΔT (energy gained or lost)".to_string(),
        What::Sequence => "phase sequence".to_string(),
        What::Scalar(c) => c.label().to_string(),
    };
    let fixed = describe_fixed(&setup);
    let figure = MapFigure {
        title: format!("impax map — {quantity_text}"),
        subtitle: fixed,
        x: MapAxis {
            label: setup.fields[0].label(),
            start: ax.start(),
            stop: ax.stop(),
            count: ax.count(),
        },
        y: MapAxis {
            label: setup.fields[1].label(),
            start: ay.start(),
            stop: ay.stop(),
            count: ay.count(),
        },
        panels: setup.laws.iter().map(|l| l.to_string()).collect(),
        cells,
        overlays,
    };
    let size = size.unwrap_or_else(|| figure.default_size());
    plot::render("out", &args.out, size, &figure)?;
    out.extend_from_slice(
        format!(
            "impax map: wrote {} ({} × {} px): {quantity_text}, {} panels, {} × {} cells ({} × {})\n{report}",
            args.out.display(),
            size.0,
            size.1,
            nl,
            ax.count(),
            ay.count(),
            ax.name(),
            ay.name(),
        )
        .as_bytes(),
    );
    Ok(())
}

/// Which grid axis is α and which is γ, when the scenario is paper A's sphere.
#[derive(Debug, Clone, Copy)]
struct SeedAxes {
    /// Whether the first (x) axis is α (else it is γ).
    alpha_is_x: bool,
}

fn seed_axes(setup: &Setup) -> Option<SeedAxes> {
    if !setup.template.is_seed_sphere() {
        return None;
    }
    let a = Field::Body(Param::AlphaDeg);
    let g = Field::Body(Param::SpinRatio);
    match (setup.fields[0], setup.fields[1]) {
        (x, y) if x == a && y == g => Some(SeedAxes { alpha_is_x: true }),
        (x, y) if x == g && y == a => Some(SeedAxes { alpha_is_x: false }),
        _ => None,
    }
}

fn describe_fixed(setup: &Setup) -> String {
    let (f, e) = setup.template.coefficients();
    let body = if setup.template.is_seed_sphere() {
        "sphere on a fixed plane"
    } else {
        "scenario"
    };
    format!(
        "{body}, μ = {f}, e = {e}; grid {} × {}; each panel one law",
        setup.fields[0].name(),
        setup.fields[1].name()
    )
}

/// The engine's energy-gain boundary of Whittaker's rule against paper A eq. 13.
struct Comparison {
    report: String,
    /// Engine boundary, lower and upper, as runs of (α, γ).
    engine: [Vec<Vec<(f64, f64)>>; 2],
    /// Eq. 13 thresholds γ*₋, γ*₊ as runs of (α, γ).
    analytic: [Vec<Vec<(f64, f64)>>; 2],
    /// The no-slip line γ = −sin α.
    no_slip: Vec<(f64, f64)>,
    /// Paper A's printed eqs. 14–15 points at α = 30° (only for the seed's e and f).
    printed: Vec<(f64, f64)>,
    alpha_is_x: bool,
}

impl Comparison {
    fn overlays(&self, panel: usize, panels: usize) -> Vec<Overlay> {
        let xy = |runs: &[Vec<(f64, f64)>]| -> Vec<Vec<(f64, f64)>> {
            runs.iter()
                .map(|r| {
                    r.iter()
                        .map(|&(a, g)| if self.alpha_is_x { (a, g) } else { (g, a) })
                        .collect()
                })
                .collect()
        };
        let mut v = Vec::new();
        for k in 0..panels {
            v.push(Overlay {
                panel: k,
                label: "no slip before the impact: γ = −sin α".into(),
                runs: xy(std::slice::from_ref(&self.no_slip)),
                colour: RGBColor(60, 60, 60),
                width: 1,
                dashed: true,
                markers: false,
            });
        }
        v.push(Overlay {
            panel,
            label: "whittaker: energy-gain boundary found by the engine on the grid".into(),
            runs: xy(&[self.engine[0].clone(), self.engine[1].clone()].concat()),
            colour: RGBColor(0, 0, 0),
            width: 4,
            dashed: false,
            markers: false,
        });
        v.push(Overlay {
            panel,
            label: "paper A eq. 13: ΔT = 0 (analytic γ*₊, γ*₋)".into(),
            runs: xy(&[self.analytic[0].clone(), self.analytic[1].clone()].concat()),
            colour: RGBColor(255, 215, 0),
            width: 2,
            dashed: true,
            markers: false,
        });
        if !self.printed.is_empty() {
            v.push(Overlay {
                panel,
                label: "paper A eqs. 14–15 as printed: γ = ±0.20 at α = 30°".into(),
                runs: xy(std::slice::from_ref(&self.printed)),
                colour: RGBColor(30, 90, 200),
                width: 2,
                dashed: false,
                markers: true,
            });
        }
        v
    }
}

/// Split points with NaN γ into runs.
fn runs(points: impl Iterator<Item = (f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for (a, g) in points {
        if g.is_finite() {
            cur.push((a, g));
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn compare_threshold(
    setup: &Setup,
    ax: &Axis,
    ay: &Axis,
    axes: SeedAxes,
    gain: &[bool],
) -> Comparison {
    let (alpha_axis, gamma_axis) = if axes.alpha_is_x { (ax, ay) } else { (ay, ax) };
    let (f, e) = setup.template.coefficients();
    let (na, ng) = (alpha_axis.count(), gamma_axis.count());
    let ny = ay.count();
    let gained = |ia: u64, ig: u64| {
        let (ix, iy) = if axes.alpha_is_x { (ia, ig) } else { (ig, ia) };
        gain[(ix * ny + iy) as usize]
    };
    let step = if ng > 1 {
        (gamma_axis.stop() - gamma_axis.start()) / (ng - 1) as f64
    } else {
        f64::INFINITY
    };
    let (g0, g1) = (gamma_axis.start(), gamma_axis.stop());
    let mut engine = [Vec::new(), Vec::new()];
    let mut worst = [0.0f64; 2];
    let mut compared = [0u64; 2];
    let mut disagree = 0u64;
    for ia in 0..na {
        let alpha_deg = alpha_axis.value(ia);
        let t = whittaker_sphere_thresholds(alpha_deg.to_radians(), e, f);
        let cells: Vec<u64> = (0..ng).filter(|&ig| gained(ia, ig)).collect();
        // Outermost transitions: the midpoints between the first/last gaining cell and its
        // outer neighbour (none when the region reaches the edge of the grid).
        let lower = cells
            .first()
            .filter(|&&i| i > 0)
            .map(|&i| 0.5 * (gamma_axis.value(i - 1) + gamma_axis.value(i)));
        let upper = cells
            .last()
            .filter(|&&i| i + 1 < ng)
            .map(|&i| 0.5 * (gamma_axis.value(i) + gamma_axis.value(i + 1)));
        for (b, (found, exact)) in [(lower, t.lower), (upper, t.upper)].into_iter().enumerate() {
            engine[b].push((alpha_deg, found.unwrap_or(f64::NAN)));
            let inside = exact.filter(|&g| g > g0 + step && g < g1 - step);
            match (found, inside) {
                (Some(x), Some(y)) => {
                    worst[b] = worst[b].max((x - y).abs());
                    compared[b] += 1;
                }
                (None, Some(_)) => disagree += 1,
                (Some(x), None) if x > g0 + step && x < g1 - step => disagree += 1,
                _ => {}
            }
        }
    }
    // A finer analytic curve for drawing.
    let fine = 600u64.max(na);
    let curve = |b: usize| {
        runs((0..=fine).map(|i| {
            let a = alpha_axis.start()
                + (alpha_axis.stop() - alpha_axis.start()) * i as f64 / fine as f64;
            let t = whittaker_sphere_thresholds(a.to_radians(), e, f);
            let g = if b == 0 { t.lower } else { t.upper };
            (a, g.filter(|&g| g >= g0 && g <= g1).unwrap_or(f64::NAN))
        }))
    };
    let no_slip: Vec<(f64, f64)> = (0..=fine)
        .map(|i| {
            let a = alpha_axis.start()
                + (alpha_axis.stop() - alpha_axis.start()) * i as f64 / fine as f64;
            (a, -a.to_radians().sin())
        })
        .filter(|&(_, g)| g >= g0 && g <= g1)
        .collect();
    let seed_coefficients = f == 0.4 && e == 0.7;
    let printed = if seed_coefficients && alpha_axis.start() <= 30.0 && alpha_axis.stop() >= 30.0 {
        [0.20, -0.20]
            .into_iter()
            .filter(|&g| g >= g0 && g <= g1)
            .map(|g| (30.0, g))
            .collect()
    } else {
        Vec::new()
    };
    let mut report = if ng < 2 {
        "whittaker energy-gain boundary vs paper A eq. 13: not compared (the γ axis has a single value, no grid step)\n".to_string()
    } else {
        format!(
        "whittaker energy-gain boundary vs paper A eq. 13 (γ grid step {step:.6}): \
         max |engine − eq. 13| = {:.6} on the upper branch γ*₊ ({} α columns), {:.6} on the lower branch γ*₋ ({} α columns); \
         {disagree} columns where only one of them has a boundary inside the grid; \
         within half a grid step: {}\n",
        worst[1],
        compared[1],
        worst[0],
        compared[0],
        if worst[0] <= 0.5 * step * (1.0 + 1e-9) && worst[1] <= 0.5 * step * (1.0 + 1e-9) && disagree == 0 {
            "yes"
        } else {
            "NO"
        },
    )
    };
    let at30 = whittaker_sphere_thresholds(30f64.to_radians(), e, f);
    if seed_coefficients {
        report.push_str(&format!(
            "at α = 30°: eq. 13 gives γ*₊ = {:.6}, γ*₋ = {:.6}; paper A prints ±0.20 (eqs. 14–15)\n",
            at30.upper.unwrap_or(f64::NAN),
            at30.lower.unwrap_or(f64::NAN)
        ));
    }
    Comparison {
        report,
        engine: [
            runs(engine[0].iter().copied()),
            runs(engine[1].iter().copied()),
        ],
        analytic: [curve(0), curve(1)],
        no_slip,
        printed,
        alpha_is_x: axes.alpha_is_x,
    }
}
