//! Text formatting: numbers and aligned tables.

/// Fixed-point with sign, `-0` shown as `0`; scientific (`+2.000000e200`) from 10⁹ on, where
/// fixed point would print hundreds of digits.
pub fn signed(x: f64, decimals: usize) -> String {
    if x.is_finite() && x.abs() >= 1e9 {
        return format!("{:+.*e}", decimals, x);
    }
    let s = format!("{:+.*}", decimals, x);
    let zero = format!("{:+.*}", decimals, 0.0);
    let neg_zero = format!("-{}", &zero[1..]);
    if s == neg_zero {
        zero
    } else {
        s
    }
}

/// Fixed-point without a sign for quantities of one kind such as the energies of a run, in the
/// style their largest, `scale`, needs: scientific (`2.000000e200`, `1.234560e-30`) when
/// `scale` is outside `[1e-4, 1e9)`, where fixed point would print hundreds of digits or only
/// zeros; fixed point otherwise (a round-off `±3e-16` beside `7.36` shows as `0.000000`).
pub fn magnitude(x: f64, scale: f64, decimals: usize) -> String {
    if scale.is_finite() && scale != 0.0 && !(1e-4..1e9).contains(&scale.abs()) {
        format!("{:.*e}", decimals, x)
    } else {
        // (A round-off below zero shows as 0, not −0.)
        let s = format!("{:.*}", decimals, x);
        match s.strip_prefix('-') {
            Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
            _ => s,
        }
    }
}

// An input number as given (shortest round trip), in scientific form outside `[1e-6, 1e9)`
// so that `1e200` is not printed with two hundred digits: the library's `impax::error::Num`,
// which its error messages use too.
pub use impax::error::Num as Plain;

/// A plain table with left-aligned text columns and right-aligned numeric columns.
pub struct Table {
    header: Vec<String>,
    right: Vec<bool>,
    rows: Vec<Vec<String>>,
}

impl Table {
    pub fn new(columns: &[(&str, bool)]) -> Self {
        Self {
            header: columns.iter().map(|c| c.0.to_string()).collect(),
            right: columns.iter().map(|c| c.1).collect(),
            rows: Vec::new(),
        }
    }

    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }

    /// The row of a law that broke down: its id, `—` in the other columns but the last,
    /// `verdict` in the last.
    pub fn breakdown_row(&mut self, law: impl std::fmt::Display, verdict: &str) {
        let mut row = vec![law.to_string()];
        row.extend(std::iter::repeat_n("—".to_string(), self.header.len() - 2));
        row.push(verdict.into());
        self.rows.push(row);
    }

    pub fn render(&self) -> String {
        let n = self.header.len();
        let width = |i: usize| {
            std::iter::once(&self.header[i])
                .chain(self.rows.iter().map(|r| &r[i]))
                .map(|s| s.chars().count())
                .max()
                .unwrap_or(0)
        };
        let widths: Vec<usize> = (0..n).map(width).collect();
        let line = |cells: &[String]| {
            let mut s = String::new();
            for (i, c) in cells.iter().enumerate() {
                let pad = widths[i].saturating_sub(c.chars().count());
                let last = i + 1 == n;
                if self.right[i] {
                    s.push_str(&" ".repeat(pad));
                    s.push_str(c);
                } else {
                    s.push_str(c);
                    if !last {
                        s.push_str(&" ".repeat(pad));
                    }
                }
                if !last {
                    s.push_str("  ");
                }
            }
            s.trim_end().to_string() + "\n"
        };
        let mut out = line(&self.header);
        let total: usize = widths.iter().sum::<usize>() + 2 * (n - 1);
        out.push_str(&"-".repeat(total));
        out.push('\n');
        for r in &self.rows {
            out.push_str(&line(r));
        }
        out
    }
}

/// The `note — …` lines under a table.
pub fn notes(list: &[String]) -> String {
    list.iter().map(|n| format!("note — {n}\n")).collect()
}
