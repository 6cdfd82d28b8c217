//! `impax sweep`: scenario fields over a grid or random samples, every law, in parallel,
//! streamed as CSV (or reduced to a summary) with constant memory.
//!
//! Rows come in point order (the first `--grid` axis slowest), and for each point in the
//! order of the laws; chunks are computed in parallel and written in order, so the output is
//! byte-identical for any `--threads`.

mod mechanism;

use crate::cli::SweepArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::Table;
use crate::pipeline::columns::Column;
use crate::pipeline::csv_rows::{chunk_bytes, Rows, RowsSetup};
use crate::pipeline::evaluate::{self, ChunkNotes};
use crate::pipeline::progress::Progress;
use crate::pipeline::space::{self, Setup};
use crate::sources::Source;
use impax::analysis::{run_ordered, run_ordered_waves, Sequence, Tally};
use impax::mechanism::builtin::BuiltIn;
use std::io::Write;
use std::sync::Mutex;

/// Points per chunk: large enough to amortise the scheduling, small enough for progress.
pub const CHUNK_POINTS: u64 = 8192;

/// Chunks per wave and per thread of `--format summary` (see
/// [`impax::analysis::run_ordered_waves`]): 64 chunk tallies per thread are a few hundred
/// kilobytes, and a thread idles at most one chunk in 64 at the end of a wave.
const SUMMARY_CHUNKS_PER_THREAD: usize = 64;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Csv,
    Summary,
    /// Parquet (cargo feature `parquet`).
    Parquet,
}

/// Run the sweep, writing straight to stdout or `--out` (not through `main`'s buffer).
pub fn run(args: &SweepArgs) -> CliResult<()> {
    if let Some(path) = &args.space.scenario {
        let unreadable = |e| {
            CliError::input(format!(
                "{}: cannot read scenario file: {e}",
                path.display()
            ))
        };
        let name = path.to_string_lossy();
        let source = Source::classify(&name, &BuiltIn::NAMES, unreadable)?;
        if matches!(
            source,
            Source::Robot(_) | Source::Mechanism(_) | Source::BuiltInMechanism(_)
        ) {
            return mechanism::run(&source, args);
        }
    }
    if let Some(flag) = args.mechanism.first_given() {
        return Err(CliError::input(format!(
            "--{flag}: only for a mechanism or a robot; sweep a body scenario's fields with --grid, --random and --set"
        )));
    }
    let format = match args.format.as_str() {
        "csv" => Format::Csv,
        "summary" => Format::Summary,
        "parquet" => {
            if !cfg!(feature = "parquet") {
                return Err(CliError::input(
                    "--format parquet: this impax was built without Parquet support (build with `cargo build --release --features parquet`)",
                ));
            }
            if args.out.is_none() {
                return Err(CliError::input(
                    "--format parquet: give the file with --out FILE.parquet",
                ));
            }
            Format::Parquet
        }
        other => {
            return Err(CliError::input(format!(
                "--format: unknown format `{other}` (known: csv, summary, parquet)"
            )))
        }
    };
    let columns = if args.columns.is_empty() {
        Column::ALL.to_vec()
    } else {
        if format == Format::Summary {
            return Err(CliError::input(
                "--columns: applies to --format csv and parquet",
            ));
        }
        let mut cols = Vec::new();
        for name in &args.columns {
            let c = Column::parse(name).ok_or_else(|| {
                CliError::input(format!(
                    "--columns: unknown column `{name}` (known: {})",
                    Column::names()
                ))
            })?;
            if !cols.contains(&c) {
                cols.push(c);
            }
        }
        cols
    };
    let setup = space::setup(&args.space)?;
    if format == Format::Parquet {
        return parquet(args, &setup, &columns);
    }
    let mut writer: Box<dyn Write + Send> = match &args.out {
        Some(path) => Box::new(std::io::BufWriter::with_capacity(
            1 << 20,
            std::fs::File::create(path).map_err(|e| {
                CliError::input(format!("--out {}: cannot create: {e}", path.display()))
            })?,
        )),
        None => Box::new(std::io::BufWriter::with_capacity(
            1 << 20,
            std::io::stdout(),
        )),
    };
    let quiet = args.space.quiet;
    let result = space::with_threads(args.space.threads, || match format {
        Format::Csv => csv(&setup, &columns, &mut writer, quiet),
        Format::Summary => summary(&setup, &mut writer, quiet),
        Format::Parquet => unreachable!("written above"),
    })?;
    let flushed = result.and_then(|()| writer.flush().map_err(io_error));
    match flushed {
        // A closed pipe (`impax sweep … | head`) ends the sweep quietly.
        Err(e) if e.message == BROKEN_PIPE => Ok(()),
        other => other,
    }
}

#[cfg(feature = "parquet")]
fn parquet(args: &SweepArgs, setup: &Setup, columns: &[Column]) -> CliResult<()> {
    let path = args.out.as_deref().expect("checked with the format");
    let quiet = args.space.quiet;
    space::with_threads(args.space.threads, || {
        let progress = Progress::new(setup.space.len(), quiet);
        let notes = crate::pipeline::parquet_out::write(setup, columns, path, &progress)?;
        progress.finish("sweep", setup.space.len(), setup.laws.len());
        note_invalid(setup, &notes, quiet);
        Ok(())
    })?
}

#[cfg(not(feature = "parquet"))]
fn parquet(_: &SweepArgs, _: &Setup, _: &[Column]) -> CliResult<()> {
    unreachable!("rejected when the format is parsed")
}

const BROKEN_PIPE: &str = "broken pipe";

fn io_error(e: std::io::Error) -> CliError {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        CliError::failure(BROKEN_PIPE)
    } else {
        CliError::failure(format!("cannot write the output: {e}"))
    }
}

/// Print the first invalid point (if any) on stderr.
fn note_invalid(setup: &Setup, notes: &ChunkNotes, quiet: bool) {
    if quiet || notes.invalid == 0 {
        return;
    }
    if let Some(first) = &notes.first_invalid {
        let mut vals = vec![0.0; setup.fields.len()];
        setup
            .space
            .for_each_in(first.index..first.index + 1, |_, v| vals.copy_from_slice(v));
        let at: Vec<String> = setup
            .fields
            .iter()
            .zip(&vals)
            .map(|(f, v)| format!("{}={v}", f.name()))
            .collect();
        eprintln!(
            "impax: note: {} of {} points are invalid (status `invalid`); the first, at {}: {}",
            notes.invalid,
            setup.space.len(),
            at.join(", "),
            first.reason
        );
    }
}

fn merge_notes(total: &mut ChunkNotes, chunk: ChunkNotes) {
    total.invalid += chunk.invalid;
    if total.first_invalid.is_none() {
        total.first_invalid = chunk.first_invalid;
    }
}

fn csv(
    setup: &Setup,
    columns: &[Column],
    w: &mut Box<dyn Write + Send>,
    quiet: bool,
) -> CliResult<()> {
    let mut header: Vec<String> = setup.fields.iter().map(|f| f.name()).collect();
    header.push("law".into());
    header.extend(columns.iter().map(|c| c.name().to_string()));
    w.write_all((header.join(",") + "\n").as_bytes())
        .map_err(io_error)?;
    let needs_body = columns.iter().any(|c| c.needs_body());
    let law_names: Vec<&str> = setup.laws.iter().map(|l| l.as_str()).collect();
    let rows_setup = RowsSetup::new(&law_names, &setup.space);
    let d = setup.fields.len();
    // Zeroed (untouched pages stay unmapped) and never outgrown: a row takes at most 25 bytes
    // a cell, about 18 on average.
    let row_bytes = chunk_bytes(
        CHUNK_POINTS as usize,
        law_names.len(),
        d + 1 + columns.len(),
    );
    let total = setup.space.len();
    let progress = Progress::new(total, quiet);
    let mut notes = ChunkNotes::default();
    // Row buffers go back to a pool once written: a fresh megabyte per chunk would cost a
    // page fault per 4 KiB.
    let pool: Mutex<Vec<Vec<u8>>> = Mutex::new(Vec::new());
    run_ordered(
        total,
        CHUNK_POINTS,
        |range| {
            let n = range.end - range.start;
            let buf = pool
                .lock()
                .ok()
                .and_then(|mut p| p.pop())
                .unwrap_or_else(|| vec![0; row_bytes]);
            let mut rows = Rows::new(&rows_setup, &setup.space, d, columns, range.start, buf);
            let notes = evaluate::chunk(setup, range, needs_body, |_, vals, point, sums| {
                rows.point(vals, point, sums)
            });
            let (buf, len) = rows.finish();
            (n, buf, len, notes)
        },
        |(n, buf, len, chunk_notes)| {
            w.write_all(&buf[..len]).map_err(io_error)?;
            if let Ok(mut p) = pool.lock() {
                p.push(buf);
            }
            merge_notes(&mut notes, chunk_notes);
            progress.advance(n);
            Ok::<(), CliError>(())
        },
    )?;
    progress.finish("sweep", total, setup.laws.len());
    note_invalid(setup, &notes, quiet);
    Ok(())
}

fn summary(setup: &Setup, w: &mut Box<dyn Write + Send>, quiet: bool) -> CliResult<()> {
    let nl = setup.laws.len();
    let total = setup.space.len();
    let progress = Progress::new(total, quiet);
    let mut tallies = vec![Tally::new(); nl];
    let mut notes = ChunkNotes::default();
    // A chunk's tally is a few hundred bytes: long waves keep both cores busy.
    run_ordered_waves(
        total,
        CHUNK_POINTS,
        SUMMARY_CHUNKS_PER_THREAD,
        |range| {
            let n = range.end - range.start;
            let (t, notes) = evaluate::tally(setup, range);
            (n, t, notes)
        },
        |(n, t, chunk_notes): (u64, Vec<Tally>, ChunkNotes)| {
            for (a, b) in tallies.iter_mut().zip(&t) {
                a.merge(b);
            }
            merge_notes(&mut notes, chunk_notes);
            progress.advance(n);
            Ok::<(), CliError>(())
        },
    )?;
    progress.finish("sweep", total, nl);
    note_invalid(setup, &notes, quiet);
    let mut cols = vec![
        ("law", false),
        ("impacts", true),
        ("consistent", true),
        ("energy-gained", true),
        ("inconsistent", true),
        ("breakdown", true),
        ("invalid", true),
    ];
    let seq: Vec<Sequence> = Sequence::ALL
        .iter()
        .copied()
        .filter(|s| *s != Sequence::None)
        .collect();
    cols.extend(seq.iter().map(|s| (s.id(), true)));
    cols.extend([
        ("min ΔT/T0", true),
        ("mean ΔT/T0", true),
        ("max ΔT/T0", true),
    ]);
    let mut table = Table::new(&cols);
    for (law, t) in setup.laws.iter().zip(&tallies) {
        let resolved = t.resolved();
        let f = |x: f64| {
            if resolved > 0 {
                format!("{x:+.6}")
            } else {
                "—".into()
            }
        };
        let mut row = vec![
            law.to_string(),
            t.total.to_string(),
            t.consistent.to_string(),
            t.energy_gained.to_string(),
            t.inconsistent.to_string(),
            t.breakdown.to_string(),
            t.invalid.to_string(),
        ];
        row.extend(seq.iter().map(|s| t.sequence(*s).to_string()));
        row.extend([
            f(t.min_ratio),
            f(t.sum_ratio / resolved.max(1) as f64),
            f(t.max_ratio),
        ]);
        table.row(row);
    }
    let names: Vec<String> = setup.fields.iter().map(|f| f.name()).collect();
    let text = format!(
        "impax sweep — {} points over {} × {} laws\n\n{}",
        total,
        names.join(", "),
        nl,
        table.render()
    );
    w.write_all(text.as_bytes()).map_err(io_error)
}
