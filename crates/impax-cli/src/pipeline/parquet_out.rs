//! `impax sweep --format parquet` (cargo feature `parquet`): the CSV's columns as a Parquet
//! file, written a row group at a time, so memory is bounded by one row group whatever the
//! number of points.
//!
//! Schema: the swept fields as required `DOUBLE`; `law`, `status`, `sequence` as required
//! UTF-8 strings; every numeric output column as optional `DOUBLE` (null where the CSV cell
//! is empty). Uncompressed (the crate is built without codecs, to stay light).

use crate::commands::sweep::CHUNK_POINTS;
use crate::input::{CliError, CliResult};
use crate::pipeline::columns::{body_after, Column};
use crate::pipeline::evaluate::{self, ChunkNotes};
use crate::pipeline::progress::Progress;
use crate::pipeline::space::Setup;
use impax::analysis::run_ordered;
use parquet::basic::{LogicalType, Repetition, Type as PhysicalType};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;
use std::fs::File;
use std::sync::Arc;

/// Rows per row group (about 10 MB of buffered columns at most).
const ROW_GROUP_ROWS: usize = 65_536;

/// Buffered columns of the rows not yet written.
#[derive(Default)]
struct Rows {
    fields: Vec<Vec<f64>>,
    text: [Vec<&'static str>; 3],
    numbers: Vec<Vec<f64>>,
}

impl Rows {
    fn new(fields: usize, numbers: usize) -> Self {
        Self {
            fields: vec![Vec::new(); fields],
            text: Default::default(),
            numbers: vec![Vec::new(); numbers],
        }
    }
    fn len(&self) -> usize {
        self.text[0].len()
    }
    fn append(&mut self, other: &mut Rows) {
        for (a, b) in self.fields.iter_mut().zip(&mut other.fields) {
            a.append(b);
        }
        for (a, b) in self.text.iter_mut().zip(&mut other.text) {
            a.append(b);
        }
        for (a, b) in self.numbers.iter_mut().zip(&mut other.numbers) {
            a.append(b);
        }
    }
    fn clear(&mut self) {
        self.fields.iter_mut().for_each(Vec::clear);
        self.text.iter_mut().for_each(Vec::clear);
        self.numbers.iter_mut().for_each(Vec::clear);
    }
}

fn schema(setup: &Setup, numeric: &[Column]) -> parquet::errors::Result<Type> {
    let mut fields = Vec::new();
    for f in &setup.fields {
        fields.push(Arc::new(
            Type::primitive_type_builder(&f.name(), PhysicalType::DOUBLE)
                .with_repetition(Repetition::REQUIRED)
                .build()?,
        ));
    }
    for name in ["law", "status", "sequence"] {
        fields.push(Arc::new(
            Type::primitive_type_builder(name, PhysicalType::BYTE_ARRAY)
                .with_repetition(Repetition::REQUIRED)
                .with_logical_type(Some(LogicalType::String))
                .build()?,
        ));
    }
    for c in numeric {
        fields.push(Arc::new(
            Type::primitive_type_builder(c.name(), PhysicalType::DOUBLE)
                .with_repetition(Repetition::OPTIONAL)
                .build()?,
        ));
    }
    Type::group_type_builder("impax_sweep")
        .with_fields(fields)
        .build()
}

fn write_group(w: &mut SerializedFileWriter<File>, rows: &Rows) -> parquet::errors::Result<()> {
    let mut g = w.next_row_group()?;
    for col in &rows.fields {
        let mut c = g.next_column()?.expect("schema column");
        c.typed::<DoubleType>().write_batch(col, None, None)?;
        c.close()?;
    }
    for col in &rows.text {
        let mut c = g.next_column()?.expect("schema column");
        let values: Vec<ByteArray> = col.iter().map(|s| ByteArray::from(*s)).collect();
        c.typed::<ByteArrayType>()
            .write_batch(&values, None, None)?;
        c.close()?;
    }
    for col in &rows.numbers {
        let mut c = g.next_column()?.expect("schema column");
        let present: Vec<f64> = col.iter().copied().filter(|x| x.is_finite()).collect();
        let levels: Vec<i16> = col.iter().map(|x| i16::from(x.is_finite())).collect();
        c.typed::<DoubleType>()
            .write_batch(&present, Some(&levels), None)?;
        c.close()?;
    }
    g.close()?;
    Ok(())
}

/// Write the sweep to `path` as Parquet; returns the notes of invalid points.
pub fn write(
    setup: &Setup,
    columns: &[Column],
    path: &std::path::Path,
    progress: &Progress,
) -> CliResult<ChunkNotes> {
    let numeric: Vec<Column> = columns.iter().copied().filter(|c| !c.is_text()).collect();
    let failed = |e: parquet::errors::ParquetError| {
        CliError::failure(format!("writing {}: {e}", path.display()))
    };
    let file = File::create(path)
        .map_err(|e| CliError::input(format!("--out {}: cannot create: {e}", path.display())))?;
    let props = Arc::new(WriterProperties::builder().build());
    let mut writer = SerializedFileWriter::new(
        file,
        Arc::new(schema(setup, &numeric).map_err(failed)?),
        props,
    )
    .map_err(failed)?;
    let needs_body = numeric.iter().any(|c| c.needs_body());
    let d = setup.fields.len();
    let mut pending = Rows::new(d, numeric.len());
    let mut notes = ChunkNotes::default();
    run_ordered(
        setup.space.len(),
        CHUNK_POINTS,
        |range| {
            let n = range.end - range.start;
            let mut rows = Rows::new(d, numeric.len());
            let chunk_notes = evaluate::chunk(setup, range, needs_body, |_, vals, point, sums| {
                for (s, law) in sums.iter().zip(&setup.laws) {
                    for (col, &v) in rows.fields.iter_mut().zip(vals) {
                        col.push(v);
                    }
                    rows.text[0].push(law.as_str());
                    rows.text[1].push(s.status.id());
                    rows.text[2].push(s.sequence.id());
                    let body = if needs_body {
                        body_after(s, point)
                    } else {
                        [f64::NAN; 3]
                    };
                    for (col, c) in rows.numbers.iter_mut().zip(&numeric) {
                        col.push(c.value(s, point, body));
                    }
                }
            });
            (n, rows, chunk_notes)
        },
        |(n, mut rows, chunk_notes)| {
            pending.append(&mut rows);
            if pending.len() >= ROW_GROUP_ROWS {
                write_group(&mut writer, &pending).map_err(failed)?;
                pending.clear();
            }
            let ChunkNotes {
                invalid,
                first_invalid,
            } = chunk_notes;
            notes.invalid += invalid;
            if notes.first_invalid.is_none() {
                notes.first_invalid = first_invalid;
            }
            progress.advance(n);
            Ok::<(), CliError>(())
        },
    )?;
    if pending.len() > 0 {
        write_group(&mut writer, &pending).map_err(failed)?;
    }
    writer.close().map_err(failed)?;
    Ok(notes)
}
