//! The rows of `impax sweep`'s CSV, assembled from fixed-size cells.
//!
//! Every cell is the text of one value followed by its comma, kept in a 32-byte array with
//! its length: a row is a run of fixed 32-byte copies into the chunk's buffer (the next cell
//! overwrites the tail of the previous one), and the comma after the last cell becomes the
//! newline. Numbers keep the shortest round-trip form (zmij); a number is formatted only when
//! its bits differ from the last value of the same column (per law), so the columns that do
//! not change along the fast axis of a grid are formatted once per run of equal values, and
//! the fast axis of a grid is formatted once per sweep ([`AxisTable`]). The bytes are the
//! same as formatting every number anew.

use crate::pipeline::columns::{body_after, Column};
use crate::pipeline::evaluate::PointView;
use impax::analysis::{ImpactSummary, Sequence, Space, Status};

/// Bytes of a cell: the longest shortest-form `f64` (24 bytes, e.g.
/// `-2.2250738585072014e-308`) or the longest id (`inconsistent-assumption`, 23), its comma,
/// and the length in the last byte.
const CELL: usize = 32;
/// Where a cell keeps its length.
const LEN: usize = CELL - 1;
/// The most bytes a cell takes in a row: 24 of zmij's longest number (its buffer's size) and
/// the comma.
const WIDEST: usize = 25;

/// A buffer large enough for the rows of `points` points (`laws` rows each, of `cells`
/// cells: fields, law and columns): rows never outgrow it, and the pages past the rows
/// written are never touched.
pub fn chunk_bytes(points: usize, laws: usize, cells: usize) -> usize {
    points * laws * cells * WIDEST + CELL
}

/// One cell: text and comma in `text[..text[LEN]]`, made from the value with bits `bits`.
#[derive(Clone, Copy)]
struct Cell {
    text: [u8; CELL],
    bits: u64,
}

impl Cell {
    /// The empty cell of a missing value (NaN, infinite): its comma alone.
    fn empty(bits: u64) -> Self {
        let mut text = [0; CELL];
        text[0] = b',';
        text[LEN] = 1;
        Cell { text, bits }
    }

    /// A cell of text (an id).
    fn text(s: &str) -> Self {
        let n = s.len();
        assert!(n < LEN, "cell text `{s}` is too long");
        let mut text = [0; CELL];
        text[..n].copy_from_slice(s.as_bytes());
        text[n] = b',';
        text[LEN] = n as u8 + 1;
        Cell { text, bits: 0 }
    }

    /// The cell of a number: its shortest round-trip form, or empty if it is not finite.
    fn number(x: f64, fmt: &mut zmij::Buffer) -> Self {
        let mut cell = Cell::empty(x.to_bits());
        let mut scratch = [0; CELL];
        cell.format(x, fmt, &mut scratch);
        cell
    }

    /// Remember the cell of `x` and write it to `out` too (at least [`CELL`] bytes).
    ///
    /// The text goes from zmij's buffer to both places in registers: reading back bytes
    /// stored piecewise a moment ago would stall the loads (no store forwarding), so a cell
    /// is read again only rows later.
    #[inline(always)]
    fn format(&mut self, x: f64, fmt: &mut zmij::Buffer, out: &mut [u8]) -> usize {
        self.bits = x.to_bits();
        if !x.is_finite() {
            out[0] = b',';
            self.text[0] = b',';
            self.text[LEN] = 1;
            return 1;
        }
        let s = fmt.format_finite(x).as_bytes();
        let n = s.len();
        let out = &mut out[..CELL];
        if n >= 16 {
            copy_ends::<16>(s, out, &mut self.text);
        } else if n >= 8 {
            copy_ends::<8>(s, out, &mut self.text);
        } else if n >= 4 {
            copy_ends::<4>(s, out, &mut self.text);
        } else if n >= 2 {
            copy_ends::<2>(s, out, &mut self.text);
        } else if n == 1 {
            out[0] = s[0];
            self.text[0] = s[0];
        }
        out[n] = b',';
        self.text[n] = b',';
        self.text[LEN] = n as u8 + 1;
        n + 1
    }
}

/// Copy `src` (`K ≤ src.len() ≤ 2K`) to the front of `a` and of `b` with two overlapping
/// `K`-byte pieces (no call to `memcpy` for a few bytes).
#[inline(always)]
fn copy_ends<const K: usize>(src: &[u8], a: &mut [u8], b: &mut [u8]) {
    let n = src.len();
    let head: [u8; K] = src[..K].try_into().expect("K bytes");
    let tail: [u8; K] = src[n - K..].try_into().expect("K bytes");
    a[..K].copy_from_slice(&head);
    a[n - K..n].copy_from_slice(&tail);
    b[..K].copy_from_slice(&head);
    b[n - K..n].copy_from_slice(&tail);
}

/// The largest fast axis whose cells are made once per sweep: 2¹⁸ values, 10 MiB.
const TABLE_MAX: u64 = 1 << 18;

/// The cells of the fastest axis of a grid, made once per sweep (when the axis has at most
/// [`TABLE_MAX`] values and the grid has other axes: each value then repeats).
pub struct AxisTable {
    cells: Vec<Cell>,
}

impl AxisTable {
    /// The table of `space`'s fastest axis, if it is worth one.
    pub fn new(space: &Space) -> Option<Self> {
        let Space::Grid(grid) = space else {
            return None;
        };
        let axis = grid.axes().last()?;
        let n = axis.count();
        if n > TABLE_MAX || grid.len() <= n {
            return None;
        }
        let mut fmt = zmij::Buffer::new();
        // The grid walks an axis back to its start after its last value (see
        // `Grid::for_each_changed_in`); any other value comes from `Axis::value`. Each cell
        // keeps the bits it was made from and is used only for those bits.
        let cells = (0..n)
            .map(|i| {
                let x = if i == 0 { axis.start() } else { axis.value(i) };
                Cell::number(x, &mut fmt)
            })
            .collect();
        Some(AxisTable { cells })
    }
}

/// Builds the rows of one chunk.
pub struct Rows<'a> {
    columns: &'a [Column],
    needs_body: bool,
    laws: &'a [Cell],
    table: Option<&'a AxisTable>,
    /// Position on the fast axis of the next point (with a table).
    fast: usize,
    /// The cells of the point's fields.
    fields: Vec<Cell>,
    /// Law `k`'s cell of column `c` at `k * columns.len() + c`.
    numbers: Vec<Cell>,
    statuses: Vec<(Status, Cell)>,
    sequences: Vec<(Sequence, Cell)>,
    fmt: zmij::Buffer,
    /// The chunk's text is `buf[..pos]`; `buf` stays at least a row of cells longer.
    buf: Vec<u8>,
    pos: usize,
    /// Bytes of the cells of one point (every law's row).
    point_max: usize,
}

/// The per-sweep parts of [`Rows`]: the law cells and the fast-axis table.
pub struct RowsSetup {
    laws: Vec<Cell>,
    table: Option<AxisTable>,
}

impl RowsSetup {
    /// For the laws' ids, in order, and the points of `space`.
    pub fn new(law_ids: &[&str], space: &Space) -> Self {
        RowsSetup {
            laws: law_ids.iter().map(|l| Cell::text(l)).collect(),
            table: AxisTable::new(space),
        }
    }
}

impl<'a> Rows<'a> {
    /// Rows of `d` fields, the setup's laws and `columns`, for the points from `first` on,
    /// written into `buf` (cleared).
    pub fn new(
        setup: &'a RowsSetup,
        space: &Space,
        d: usize,
        columns: &'a [Column],
        first: u64,
        mut buf: Vec<u8>,
    ) -> Self {
        let nl = setup.laws.len();
        let fast = match (&setup.table, space) {
            (Some(t), Space::Grid(_)) => (first % t.cells.len() as u64) as usize,
            _ => 0,
        };
        let point_max = chunk_bytes(1, nl, d + 1 + columns.len());
        if buf.len() < point_max {
            buf.resize(point_max, 0);
        }
        let nan = f64::NAN.to_bits();
        Rows {
            columns,
            needs_body: columns.iter().any(|c| c.needs_body()),
            laws: &setup.laws,
            table: setup.table.as_ref(),
            fast,
            fields: vec![Cell::empty(nan); d],
            numbers: vec![Cell::empty(nan); nl * columns.len()],
            statuses: vec![(Status::Invalid, Cell::text(Status::Invalid.id())); nl],
            sequences: vec![(Sequence::None, Cell::text(Sequence::None.id())); nl],
            fmt: zmij::Buffer::new(),
            buf,
            pos: 0,
            point_max,
        }
    }

    /// Append a cell (room checked by the caller: `pos + CELL <= buf.len()`).
    #[inline(always)]
    fn put(buf: &mut [u8], pos: &mut usize, cell: &Cell) {
        buf[*pos..*pos + CELL].copy_from_slice(&cell.text);
        *pos += cell.text[LEN] as usize;
    }

    /// Append the cell of `x`: the remembered one if it was made from the same bits, else a
    /// new one (remembered).
    #[inline(always)]
    fn put_number(
        buf: &mut [u8],
        pos: &mut usize,
        memo: &mut Cell,
        x: f64,
        fmt: &mut zmij::Buffer,
    ) {
        if memo.bits == x.to_bits() {
            Self::put(buf, pos, memo);
        } else {
            *pos += memo.format(x, fmt, &mut buf[*pos..]);
        }
    }

    /// Append one row per law of a point: `vals` are its fields, `sums[k]` law `k`'s record.
    #[inline]
    pub fn point(&mut self, vals: &[f64], point: Option<PointView<'_>>, sums: &[ImpactSummary]) {
        if self.pos + self.point_max > self.buf.len() {
            let len = (2 * self.buf.len()).max(self.pos + self.point_max);
            self.buf.resize(len, 0);
        }
        let fmt = &mut self.fmt;
        let d = vals.len();
        // The fast axis's cell from the table, if it is the one of this value.
        let fast = self.table.and_then(|table| {
            let cell = &table.cells[self.fast];
            self.fast += 1;
            if self.fast == table.cells.len() {
                self.fast = 0;
            }
            (cell.bits == vals[d - 1].to_bits()).then_some(cell)
        });
        let slow = if fast.is_some() { d - 1 } else { d };
        let nc = self.columns.len();
        let buf = &mut self.buf[..];
        let mut pos = self.pos;
        for (k, s) in sums.iter().enumerate() {
            for (memo, &x) in self.fields[..slow].iter_mut().zip(vals) {
                Self::put_number(buf, &mut pos, memo, x, fmt);
            }
            if let Some(cell) = fast {
                Self::put(buf, &mut pos, cell);
            }
            Self::put(buf, &mut pos, &self.laws[k]);
            let body = if self.needs_body {
                body_after(s, point)
            } else {
                [f64::NAN; 3]
            };
            let numbers = &mut self.numbers[k * nc..(k + 1) * nc];
            for (&c, memo) in self.columns.iter().zip(numbers) {
                match c {
                    Column::Status => {
                        let (status, cell) = &mut self.statuses[k];
                        if *status != s.status {
                            *status = s.status;
                            *cell = Cell::text(s.status.id());
                        }
                        Self::put(buf, &mut pos, cell);
                    }
                    Column::Sequence => {
                        let (sequence, cell) = &mut self.sequences[k];
                        if *sequence != s.sequence {
                            *sequence = s.sequence;
                            *cell = Cell::text(s.sequence.id());
                        }
                        Self::put(buf, &mut pos, cell);
                    }
                    _ => Self::put_number(buf, &mut pos, memo, c.value(s, point, body), fmt),
                }
            }
            buf[pos - 1] = b'\n';
        }
        self.pos = pos;
    }

    /// The chunk's rows, and the buffer they are in (to reuse for another chunk).
    pub fn finish(self) -> (Vec<u8>, usize) {
        (self.buf, self.pos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_is_the_shortest_form_and_its_comma() {
        let mut fmt = zmij::Buffer::new();
        for x in [
            0.0,
            -0.0,
            1.0,
            -3.0,
            0.1,
            1e-7,
            -2.2250738585072014e-308,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            123456789012345680.0,
            0.2966666666666667,
        ] {
            let c = Cell::number(x, &mut fmt);
            let n = c.text[LEN] as usize;
            let expected = format!("{},", zmij::Buffer::new().format_finite(x));
            assert_eq!(&c.text[..n], expected.as_bytes(), "{x}");
            assert_eq!(c.bits, x.to_bits());
        }
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let c = Cell::number(x, &mut fmt);
            assert_eq!(&c.text[..c.text[LEN] as usize], b",");
        }
    }

    #[test]
    fn a_cell_is_written_and_remembered_alike() {
        let mut fmt = zmij::Buffer::new();
        for x in [
            1.0,
            0.25,
            1234.5,
            0.1234567,
            1e-7,
            -0.015387836189607302,
            f64::NAN,
        ] {
            let mut memo = Cell::empty(0);
            let mut out = [b'x'; CELL];
            let n = memo.format(x, &mut fmt, &mut out);
            let expected = Cell::number(x, &mut fmt);
            assert_eq!(n, expected.text[LEN] as usize);
            assert_eq!(&out[..n], &expected.text[..n], "{x}");
            assert_eq!(&memo.text[..n], &expected.text[..n], "{x}");
            assert_eq!(memo.text[LEN], expected.text[LEN]);
            assert_eq!(memo.bits, x.to_bits());
        }
    }

    /// A row as formatted without any cache: every number anew.
    fn naive(vals: &[f64], law: &str, s: &ImpactSummary, columns: &[Column]) -> String {
        let num = |x: f64| {
            if x.is_finite() {
                zmij::Buffer::new().format_finite(x).to_string()
            } else {
                String::new()
            }
        };
        let mut cells: Vec<String> = vals.iter().map(|&x| num(x)).collect();
        cells.push(law.into());
        for &c in columns {
            cells.push(match c {
                Column::Status => s.status.id().into(),
                Column::Sequence => s.sequence.id().into(),
                _ => num(c.value(s, None, [f64::NAN; 3])),
            });
        }
        cells.join(",") + "\n"
    }

    #[test]
    fn rows_equal_numbers_formatted_anew() {
        use impax::analysis::{Axis, Grid};
        use impax::math::Vec2;
        use impax::planar::{Verdict, WorkSplit};
        // The fast axis repeats (table), the slow one changes rarely, a third field comes
        // from outside the table's axis; numbers repeat, change sign (0.0 and -0.0 differ),
        // go missing and come back, for two laws that alternate.
        let grid = Grid::new(vec![
            Axis::new("a", 0.0, 1.0, 3).unwrap(),
            Axis::new("b", -1.0, 1.0, 5).unwrap(),
        ])
        .unwrap();
        let space = Space::Grid(grid.clone());
        let setup = RowsSetup::new(&["energetic", "newton"], &space);
        assert!(setup.table.is_some());
        let columns = Column::ALL;
        let first = 2;
        let mut rows = Rows::new(&setup, &space, 2, &columns, first, Vec::new());
        let mut expected = String::new();
        let pick = [
            0.0,
            -0.0,
            0.1,
            0.1,
            f64::NAN,
            1e-7,
            1e-7,
            -2.5,
            f64::INFINITY,
            0.3,
        ];
        let mut points = Vec::new();
        grid.for_each_in(first..grid.len(), |_, v| points.push(v.to_vec()));
        for (i, vals) in points.iter().enumerate() {
            let sums: Vec<ImpactSummary> = (0..2)
                .map(|k| {
                    let x = |j: usize| pick[(i / (1 + j % 3) + j + k) % pick.len()];
                    ImpactSummary {
                        status: if x(0).is_finite() {
                            Status::Resolved(Verdict::Consistent)
                        } else {
                            Status::Breakdown
                        },
                        sequence: if i % 4 < 2 {
                            Sequence::Slip
                        } else {
                            Sequence::SlipStick
                        },
                        impulse: Vec2::new(x(1), x(2)),
                        velocity_after: Vec2::new(x(3), x(4)),
                        energy_change: x(5),
                        work: WorkSplit {
                            compression: x(6),
                            restitution: x(7),
                            friction: x(8),
                        },
                        compression_impulse: x(9),
                    }
                })
                .collect();
            rows.point(vals, None, &sums);
            for (s, law) in sums.iter().zip(["energetic", "newton"]) {
                expected += &naive(vals, law, s, &columns);
            }
        }
        let (buf, len) = rows.finish();
        assert_eq!(std::str::from_utf8(&buf[..len]).unwrap(), expected);
    }
}
