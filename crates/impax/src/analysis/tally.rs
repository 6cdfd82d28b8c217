//! A reduction of many impacts into counts and extremes (a sweep's "summary" output).

use super::batch::{ImpactSummary, Sequence, Status};
use crate::planar::{BriefResolution, OutcomeBrief, Resolution, Verdict};

/// Counts by status and by phase sequence, and the range and sum of `ΔT/T0`, of one law
/// over many impacts. Tallies of consecutive chunks [`merge`](Tally::merge) in order, so a
/// sweep's tally does not depend on the number of threads.
///
/// ```
/// use impax::analysis::{ImpactSummary, Tally};
/// let mut t = Tally::default();
/// t.add(&ImpactSummary::INVALID, 1.0);
/// assert_eq!((t.total, t.invalid), (1, 1));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tally {
    /// Impacts seen.
    pub total: u64,
    /// Verdict `consistent`.
    pub consistent: u64,
    /// Verdict `energy-gained` (Kane's paradox).
    pub energy_gained: u64,
    /// Verdict `inconsistent-assumption`.
    pub inconsistent: u64,
    /// Breakdowns of the law.
    pub breakdown: u64,
    /// Invalid problems.
    pub invalid: u64,
    /// Counts by [`Sequence`], in the order of [`Sequence::ALL`].
    pub sequences: [u64; 6],
    /// Least `ΔT/T0` (`+∞` if none resolved).
    pub min_ratio: f64,
    /// Greatest `ΔT/T0` (`−∞` if none resolved).
    pub max_ratio: f64,
    /// Sum of `ΔT/T0` over the resolved impacts.
    pub sum_ratio: f64,
}

impl Default for Tally {
    fn default() -> Self {
        Self::new()
    }
}

impl Tally {
    /// An empty tally.
    pub fn new() -> Self {
        Self {
            min_ratio: f64::INFINITY,
            max_ratio: f64::NEG_INFINITY,
            total: 0,
            consistent: 0,
            energy_gained: 0,
            inconsistent: 0,
            breakdown: 0,
            invalid: 0,
            sequences: [0; 6],
            sum_ratio: 0.0,
        }
    }

    /// Count one impact; `t0` normalises `ΔT`.
    #[inline]
    pub fn add(&mut self, s: &ImpactSummary, t0: f64) {
        self.total += 1;
        match s.status {
            Status::Resolved(Verdict::Consistent) => self.consistent += 1,
            Status::Resolved(Verdict::EnergyGained) => self.energy_gained += 1,
            Status::Resolved(Verdict::InconsistentAssumption) => self.inconsistent += 1,
            Status::Breakdown => self.breakdown += 1,
            Status::Invalid => self.invalid += 1,
        }
        self.sequences[s.sequence as usize] += 1;
        if s.status.is_resolved() {
            let r = s.energy_change / t0;
            self.min_ratio = self.min_ratio.min(r);
            self.max_ratio = self.max_ratio.max(r);
            self.sum_ratio += r;
        }
    }

    /// Count one resolution straight from the law's result (the same counts as
    /// [`Tally::add`] of its [`ImpactSummary`]).
    #[inline]
    pub fn add_resolution(&mut self, r: &Resolution, t0: f64) {
        self.add_brief(&r.as_ref().map(OutcomeBrief::of).map_err(|b| *b), t0);
    }

    /// Count one impact from the brief of the law's result
    /// ([`ImpactLaw::resolve_brief`](crate::law::ImpactLaw::resolve_brief)): the same counts
    /// as [`Tally::add_resolution`] of the full result.
    #[inline]
    pub fn add_brief(&mut self, r: &BriefResolution, t0: f64) {
        self.total += 1;
        match r {
            Ok(o) => {
                match o.verdict {
                    Verdict::Consistent => self.consistent += 1,
                    Verdict::EnergyGained => self.energy_gained += 1,
                    Verdict::InconsistentAssumption => self.inconsistent += 1,
                }
                self.sequences[Sequence::of(&o.phases) as usize] += 1;
                let ratio = o.energy_change / t0;
                self.min_ratio = self.min_ratio.min(ratio);
                self.max_ratio = self.max_ratio.max(ratio);
                self.sum_ratio += ratio;
            }
            Err(_) => {
                self.breakdown += 1;
                self.sequences[Sequence::None as usize] += 1;
            }
        }
    }

    /// Add the counts of the next chunk's tally.
    pub fn merge(&mut self, o: &Tally) {
        self.total += o.total;
        self.consistent += o.consistent;
        self.energy_gained += o.energy_gained;
        self.inconsistent += o.inconsistent;
        self.breakdown += o.breakdown;
        self.invalid += o.invalid;
        for (a, b) in self.sequences.iter_mut().zip(o.sequences) {
            *a += b;
        }
        self.min_ratio = self.min_ratio.min(o.min_ratio);
        self.max_ratio = self.max_ratio.max(o.max_ratio);
        self.sum_ratio += o.sum_ratio;
    }

    /// Resolved impacts.
    pub fn resolved(&self) -> u64 {
        self.consistent + self.energy_gained + self.inconsistent
    }

    /// The count of one sequence class.
    pub fn sequence(&self, s: Sequence) -> u64 {
        self.sequences[s as usize]
    }
}
