//! Parameter spaces of a sweep: a regular grid (one linear axis per parameter) or
//! deterministic random samples. Both map a point index `0 ≤ i < len` to parameter values
//! as a pure function of `i`, so any chunking of the index range — and so any number of
//! threads — yields the same points in the same order.

use crate::error::{Error, Num, Result};

/// One swept parameter on a regular grid: `count` values from `start` to `stop` inclusive.
///
/// The `i`-th value is `(start (n − i) + stop i) / n` with `n = count − 1`: both ends are
/// exact, and a grid whose ends and step are "round" in decimal (`0:90:901`) gives the
/// correctly rounded decimal values (`30.0`, `0.1`, …).
///
/// ```
/// use impax::analysis::Axis;
/// let a = Axis::new("alpha-deg", 0.0, 90.0, 901).unwrap();
/// assert_eq!(a.value(300), 30.0);
/// assert_eq!(a.value(1), 0.1);
/// assert_eq!(a.value(900), 90.0);
/// assert!(Axis::new("alpha-deg", 90.0, 0.0, 10).is_err()); // reversed
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    name: String,
    start: f64,
    stop: f64,
    count: u64,
}

impl Axis {
    /// Validate and build an axis.
    ///
    /// Errors (each names the axis): a non-finite end; `count = 0` (empty); `start > stop`
    /// (reversed); `start = stop` with `count > 1`, or `start ≠ stop` with `count = 1`
    /// (ambiguous).
    pub fn new(name: &str, start: f64, stop: f64, count: u64) -> Result<Self> {
        let invalid = |reason: String| Error::Invalid {
            field: name.to_string(),
            reason,
        };
        if !start.is_finite() || !stop.is_finite() {
            return Err(invalid(format!(
                "grid ends must be finite numbers, got {}:{}",
                Num(start),
                Num(stop)
            )));
        }
        if count == 0 {
            return Err(invalid("empty grid: COUNT must be at least 1".into()));
        }
        if start > stop {
            return Err(invalid(format!(
                "reversed grid: START = {} > STOP = {} (write START:STOP with START < STOP)",
                Num(start),
                Num(stop)
            )));
        }
        if count == 1 && start != stop {
            return Err(invalid(format!(
                "a grid of 1 point needs START = STOP, got {}:{}",
                Num(start),
                Num(stop)
            )));
        }
        if count > 1 && start == stop {
            return Err(invalid(format!(
                "a grid of {count} points needs START < STOP, got {}:{}",
                Num(start),
                Num(stop)
            )));
        }
        Ok(Self {
            name: name.to_string(),
            start,
            stop,
            count,
        })
    }

    /// The parameter's name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// First value.
    pub fn start(&self) -> f64 {
        self.start
    }
    /// Last value.
    pub fn stop(&self) -> f64 {
        self.stop
    }
    /// Number of values.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// The `i`-th value (`i < count`), exact at both ends.
    #[inline]
    pub fn value(&self, i: u64) -> f64 {
        if self.count == 1 {
            return self.start;
        }
        self.value_over(i, (self.count - 1) as f64)
    }

    /// [`Axis::value`] with `n = count − 1 > 0` given as `f64` (converted once per axis).
    #[inline(always)]
    fn value_over(&self, i: u64, n: f64) -> f64 {
        let i = i as f64;
        let v = (self.start * (n - i) + self.stop * i) / n;
        if v.is_finite() {
            return v;
        }
        // The products overflow for ends near f64::MAX: weigh first, then keep the value
        // between the ends (the weights' rounding could step just past one).
        let (lo, hi) = (self.start.min(self.stop), self.start.max(self.stop));
        (self.start * ((n - i) / n) + self.stop * (i / n)).clamp(lo, hi)
    }

    /// Index of the grid value nearest to `x` (clamped to the axis).
    pub fn nearest(&self, x: f64) -> u64 {
        if self.count == 1 || x <= self.start {
            return 0;
        }
        if x >= self.stop {
            return self.count - 1;
        }
        let t = (x - self.start) / (self.stop - self.start) * (self.count - 1) as f64;
        (t.round() as u64).min(self.count - 1)
    }
}

/// A regular grid: the Cartesian product of its axes. The first axis varies slowest, the
/// last fastest (row-major), so a 2-axis grid lists `(x0, y0), (x0, y1), …`.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    axes: Vec<Axis>,
    len: u64,
}

impl Grid {
    /// A grid over the axes. Errors if there is no axis, if two axes share a name, or if the
    /// number of points overflows `u64`.
    pub fn new(axes: Vec<Axis>) -> Result<Self> {
        if axes.is_empty() {
            return Err(Error::Invalid {
                field: "grid".into(),
                reason: "no axis".into(),
            });
        }
        check_unique(axes.iter().map(|a| a.name()))?;
        let mut len: u64 = 1;
        for a in &axes {
            len = len.checked_mul(a.count).ok_or_else(|| Error::Invalid {
                field: "grid".into(),
                reason: "the number of points overflows 2⁶⁴".into(),
            })?;
        }
        Ok(Self { axes, len })
    }

    /// The axes, slowest first.
    pub fn axes(&self) -> &[Axis] {
        &self.axes
    }

    /// Number of points.
    pub fn len(&self) -> u64 {
        self.len
    }

    /// Always false (a grid has at least one point).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The per-axis indices of point `index`.
    pub fn indices(&self, mut index: u64, out: &mut [u64]) {
        for (k, a) in self.axes.iter().enumerate().rev() {
            out[k] = index % a.count;
            index /= a.count;
        }
    }

    /// Call `f(index, values)` for every point with index in `range`, in order. The values
    /// are advanced like an odometer (one division per call, not per point).
    pub fn for_each_in(&self, range: std::ops::Range<u64>, mut f: impl FnMut(u64, &[f64])) {
        self.for_each_changed_in(range, |i, v, _| f(i, v));
    }

    /// As [`Grid::for_each_in`], and tell `f(index, values, changed)` the first axis whose
    /// value may differ from the previous call's (`0` on the first call): `values[..changed]`
    /// are the previous call's, so a caller can skip setting them again.
    ///
    /// ```
    /// use impax::analysis::{Axis, Grid};
    /// let g = Grid::new(vec![
    ///     Axis::new("a", 0.0, 1.0, 2).unwrap(),
    ///     Axis::new("b", 0.0, 2.0, 3).unwrap(),
    /// ])
    /// .unwrap();
    /// let mut changed = Vec::new();
    /// g.for_each_changed_in(1..5, |_, _, k| changed.push(k));
    /// assert_eq!(changed, [0, 1, 0, 1]); // (0, 1), (0, 2), (1, 0), (1, 1)
    /// ```
    pub fn for_each_changed_in(
        &self,
        range: std::ops::Range<u64>,
        mut f: impl FnMut(u64, &[f64], usize),
    ) {
        let d = self.axes.len();
        let mut idx = vec![0u64; d];
        let mut vals = vec![0f64; d];
        if range.start >= range.end {
            return;
        }
        self.indices(range.start, &mut idx);
        for k in 0..d {
            vals[k] = self.axes[k].value(idx[k]);
        }
        // `count − 1` of each axis as f64 (an axis advanced past its start has count > 1).
        let last: Vec<f64> = self.axes.iter().map(|a| (a.count - 1) as f64).collect();
        let mut changed = 0;
        for i in range {
            f(i, &vals, changed);
            // Advance the odometer.
            let mut k = d;
            while k > 0 {
                k -= 1;
                idx[k] += 1;
                if idx[k] < self.axes[k].count {
                    vals[k] = self.axes[k].value_over(idx[k], last[k]);
                    break;
                }
                idx[k] = 0;
                vals[k] = self.axes[k].start;
            }
            changed = k;
        }
    }
}

/// One parameter sampled uniformly in `[lo, hi)`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleRange {
    name: String,
    lo: f64,
    hi: f64,
}

impl SampleRange {
    /// Validate (`lo < hi`, finite) and build.
    pub fn new(name: &str, lo: f64, hi: f64) -> Result<Self> {
        if !lo.is_finite() || !hi.is_finite() {
            return Err(Error::Invalid {
                field: name.into(),
                reason: format!(
                    "range ends must be finite numbers, got {}:{}",
                    Num(lo),
                    Num(hi)
                ),
            });
        }
        if lo >= hi {
            return Err(Error::Invalid {
                field: name.into(),
                reason: format!(
                    "empty or reversed range {}:{} (write LO:HI with LO < HI)",
                    Num(lo),
                    Num(hi)
                ),
            });
        }
        Ok(Self {
            name: name.into(),
            lo,
            hi,
        })
    }
    /// The parameter's name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// Lower end.
    pub fn lo(&self) -> f64 {
        self.lo
    }
    /// Upper end.
    pub fn hi(&self) -> f64 {
        self.hi
    }
}

/// `samples` random points, parameter `j` of point `i` drawn from a counter-based generator
/// (SplitMix64 of `(seed, i, j)`): the same seed gives the same points in any order.
///
/// ```
/// use impax::analysis::{RandomSamples, SampleRange};
/// let r = RandomSamples::new(vec![SampleRange::new("friction", 0.0, 1.0).unwrap()], 10, 7).unwrap();
/// let mut a = [0.0];
/// let mut b = [0.0];
/// r.point(3, &mut a);
/// r.point(3, &mut b);
/// assert_eq!(a, b);
/// assert!((0.0..1.0).contains(&a[0]));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RandomSamples {
    ranges: Vec<SampleRange>,
    samples: u64,
    seed: u64,
}

impl RandomSamples {
    /// Validate (at least one range, distinct names, `samples ≥ 1`) and build.
    pub fn new(ranges: Vec<SampleRange>, samples: u64, seed: u64) -> Result<Self> {
        if ranges.is_empty() {
            return Err(Error::Invalid {
                field: "random".into(),
                reason: "no range".into(),
            });
        }
        check_unique(ranges.iter().map(|r| r.name()))?;
        if samples == 0 {
            return Err(Error::Invalid {
                field: "samples".into(),
                reason: "must be at least 1".into(),
            });
        }
        Ok(Self {
            ranges,
            samples,
            seed,
        })
    }
    /// The ranges.
    pub fn ranges(&self) -> &[SampleRange] {
        &self.ranges
    }
    /// Number of points.
    pub fn len(&self) -> u64 {
        self.samples
    }
    /// Always false.
    pub fn is_empty(&self) -> bool {
        self.samples == 0
    }
    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The values of point `index`.
    #[inline]
    pub fn point(&self, index: u64, out: &mut [f64]) {
        let d = self.ranges.len() as u64;
        for (j, r) in self.ranges.iter().enumerate() {
            let z = splitmix64(
                self.seed
                    .wrapping_add(index.wrapping_mul(d).wrapping_add(j as u64))
                    .wrapping_mul(crate::math::GOLDEN_GAMMA),
            );
            let u = (z >> 11) as f64 / (1u64 << 53) as f64;
            let x = r.lo + (r.hi - r.lo) * u;
            // Keep the half-open range under rounding.
            out[j] = if x < r.hi { x } else { r.lo };
        }
    }
}

/// SplitMix64 of one word: its output for the state `z` (a hash of `z`).
#[inline]
fn splitmix64(z: u64) -> u64 {
    crate::math::mix64(z.wrapping_add(crate::math::GOLDEN_GAMMA))
}

fn check_unique<'a>(names: impl Iterator<Item = &'a str>) -> Result<()> {
    let names: Vec<&str> = names.collect();
    for (i, n) in names.iter().enumerate() {
        if names[..i].contains(n) {
            return Err(Error::Invalid {
                field: (*n).to_string(),
                reason: "swept twice".into(),
            });
        }
    }
    Ok(())
}

/// The points of a sweep: a grid or random samples.
#[derive(Debug, Clone, PartialEq)]
pub enum Space {
    /// A regular grid.
    Grid(Grid),
    /// Random samples.
    Random(RandomSamples),
}

impl Space {
    /// Number of points.
    pub fn len(&self) -> u64 {
        match self {
            Space::Grid(g) => g.len(),
            Space::Random(r) => r.len(),
        }
    }
    /// Always false.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The parameter names, in the order of the values passed to callbacks.
    pub fn names(&self) -> Vec<&str> {
        match self {
            Space::Grid(g) => g.axes().iter().map(Axis::name).collect(),
            Space::Random(r) => r.ranges().iter().map(SampleRange::name).collect(),
        }
    }
    /// Call `f(index, values)` for every point with index in `range`, in order.
    pub fn for_each_in(&self, range: std::ops::Range<u64>, mut f: impl FnMut(u64, &[f64])) {
        self.for_each_changed_in(range, |i, v, _| f(i, v));
    }

    /// As [`Space::for_each_in`], and tell `f(index, values, changed)` the first value that
    /// may differ from the previous call's ([`Grid::for_each_changed_in`]; always `0` for
    /// random samples).
    pub fn for_each_changed_in(
        &self,
        range: std::ops::Range<u64>,
        mut f: impl FnMut(u64, &[f64], usize),
    ) {
        match self {
            Space::Grid(g) => g.for_each_changed_in(range, f),
            Space::Random(r) => {
                let mut vals = vec![0.0; r.ranges().len()];
                for i in range {
                    r.point(i, &mut vals);
                    f(i, &vals, 0);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odometer_matches_direct_indexing() {
        let g = Grid::new(vec![
            Axis::new("a", 0.0, 1.0, 3).unwrap(),
            Axis::new("b", -1.0, 1.0, 5).unwrap(),
            Axis::new("c", 2.0, 2.0, 1).unwrap(),
        ])
        .unwrap();
        assert_eq!(g.len(), 15);
        let mut seen = Vec::new();
        g.for_each_in(4..13, |i, v| seen.push((i, v.to_vec())));
        assert_eq!(seen.len(), 9);
        let mut idx = [0u64; 3];
        for (i, v) in seen {
            g.indices(i, &mut idx);
            let want: Vec<f64> = (0..3).map(|k| g.axes()[k].value(idx[k])).collect();
            assert_eq!(v, want);
        }
    }

    #[test]
    fn axes_near_the_largest_float_stay_finite_and_ordered() {
        let a = Axis::new("x", -f64::MAX, f64::MAX, 5).unwrap();
        let v: Vec<f64> = (0..5).map(|i| a.value(i)).collect();
        assert_eq!((v[0], v[4]), (-f64::MAX, f64::MAX));
        assert_eq!(v[2], 0.0);
        assert!(v.windows(2).all(|w| w[0] < w[1]), "{v:?}");
        let b = Axis::new("x", -1.0, 1e308, 3).unwrap();
        assert_eq!([b.value(0), b.value(1), b.value(2)], [-1.0, 5e307, 1e308]);
    }

    #[test]
    fn bad_axes_are_errors() {
        assert!(Axis::new("x", 0.0, 1.0, 0).is_err());
        assert!(Axis::new("x", 1.0, 0.0, 3).is_err());
        assert!(Axis::new("x", 1.0, 1.0, 3).is_err());
        assert!(Axis::new("x", 0.0, 1.0, 1).is_err());
        assert!(Axis::new("x", f64::NAN, 1.0, 3).is_err());
        let big = Axis::new("x", 0.0, 1.0, u64::MAX / 2).unwrap();
        assert!(Grid::new(vec![big.clone(), Axis::new("y", 0.0, 1.0, 3).unwrap()]).is_err());
        assert!(Grid::new(vec![big.clone(), big]).is_err());
    }
}
