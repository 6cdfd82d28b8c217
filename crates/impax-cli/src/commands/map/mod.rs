//! `impax map`: a 2-parameter sweep drawn per law — the sign of ΔT (Kane's paradox), the
//! phase sequence, or any numeric output — as PNG or SVG.
//!
//! For paper A's case (a sphere given by v0, α, γ on a fixed plane, swept over `alpha-deg`
//! and `spin-ratio`), the `whittaker` panel also shows the energy-gain boundary found by the
//! engine on the grid and the analytic threshold of paper A eq. 13, and the text report
//! compares them column by column.
//!
//! The command by stages: the quantity and the grid checked, the sweep (`sweep`), the cells
//! and their classes (`cells`), the comparison with eq. 13 for paper A's case
//! (`threshold`), then the figure and the report.

mod cells;
mod sweep;
mod threshold;

use crate::cli::MapArgs;
use crate::input::{CliError, CliResult};
use crate::output::plot::map::{MapAxis, MapFigure};
use crate::output::plot::{self, Format};
use crate::pipeline::columns::Column;
use crate::pipeline::space::{self, Setup};
use impax::analysis::{Axis, Space};
use impax::LawId;
use threshold::{compare_threshold, seed_axes};

/// What a map shows.
#[derive(Debug, Clone, Copy, PartialEq)]
enum What {
    Sign,
    Sequence,
    Scalar(Column),
}

impl What {
    /// The quantity of `--what`: `sign`, `sequence` or a numeric column.
    fn parse(what: &str) -> CliResult<What> {
        Ok(match what {
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
        })
    }
}

/// `impax map`: sweep the grid, draw the maps, report what was written (and the comparison
/// with eq. 13 for paper A's case).
pub fn run(args: &MapArgs, out: &mut Vec<u8>) -> CliResult<()> {
    let what = What::parse(&args.what)?;
    Format::of("out", &args.out)?;
    let size = args.size.as_deref().map(plot::parse_size).transpose()?;
    let (setup, ax, ay) = grid(args)?;
    let nl = setup.laws.len();
    let whittaker = setup.laws.iter().position(|&l| l == LawId::Whittaker);
    let seed_axes = seed_axes(&setup);
    let swept = sweep::sweep(args, &setup, what, whittaker)?;
    let gain = swept.gain;
    let cells = cells::cells(what, swept.cat, swept.scal);

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

/// The setup of the sweep and its two grid axes, `x` then `y`; the output file created (a
/// file that cannot be written is bad input: said before sweeping).
fn grid(args: &MapArgs) -> CliResult<(Setup, Axis, Axis)> {
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
    Ok((setup, ax, ay))
}

/// The subtitle: the body, the coefficients and the grid.
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
