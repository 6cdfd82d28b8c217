//! The events along the path (theory §2, "Spatial"): the end of compression (`v_n = 0`), the
//! termination of the law (`newton` `v_n = −e v_n⁻`; `poisson` `P_r = e P_c`, see
//! [`Termination::Poisson`]; `energetic` `W_n = (1 − e²) W_c`), a second compression (jamb:
//! `v_n` back to zero after compression ended) and, for `poisson`, the end of every later
//! compression phase. Each is the zero crossing of a function of the [`Point`] that increases
//! through it ([`Events::value`]); which comes first between two points ([`Events::first`])
//! and what it changes ([`Events::record`]) are decided here, for every stage alike. Where
//! each is located is the stage's business: exactly on the straight pieces (`linear`), by
//! re-stepping the integrator (`step`), on a panel's interpolants (`angle`) or on the series
//! (`tail`).

use super::state::{Point, SlipEnd};
use super::Termination;

/// An event of the path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Event {
    /// The end of the first compression, `v_n = 0`.
    CompressionEnd,
    /// The termination of the law.
    LawEnd,
    /// `v_n` falls back to zero after the first compression ended (a jamb; for `poisson`,
    /// every such return begins a later compression phase).
    Recompression,
    /// The end of a later compression phase (`poisson`), `v_n = 0` again.
    RecompressionEnd,
}

/// The law's termination and the events met so far.
#[derive(Clone, Copy)]
pub(super) struct Events {
    /// The termination rule.
    pub term: Termination,
    /// The coefficient of restitution.
    pub e: f64,
    /// Newton: the normal velocity at the end, `−e v_n⁻`.
    pub target: f64,
    /// The normal impulse at the end of the first compression, once reached.
    pub pc: Option<f64>,
    /// The normal work at the end of the first compression.
    pub wc: f64,
    /// Where a second compression began.
    pub second: Option<f64>,
    /// Poisson: the normal impulse of the compression phases after the first (`v_n < 0`
    /// again after a jamb) that have ended.
    pub recompressed: f64,
    /// Poisson: where the current compression phase after the first began, while in one.
    pub again: Option<f64>,
}

impl Events {
    /// No event yet, for the termination `term` with restitution `e` of an impact that
    /// approaches at the normal velocity `vn0 < 0`.
    pub(super) fn new(term: Termination, e: f64, vn0: f64) -> Events {
        Events {
            term,
            e,
            target: -e * vn0,
            pc: None,
            wc: 0.0,
            second: None,
            recompressed: 0.0,
            again: None,
        }
    }

    /// The termination function, increasing through zero at the end (only after `p_c`).
    ///
    /// Poisson's: the restitution impulse (where `v_n ≥ 0`) reaches `e` times the
    /// compression impulse (where `v_n < 0`), `p − C ≥ e C`, i.e. `p − (1+e) C` with
    /// `C = p_c + recompressed` the compression impulse so far; constant (and negative)
    /// during a later compression phase, which adds to `C` when it ends.
    #[inline]
    pub(super) fn terminal(&self, pt: &Point) -> f64 {
        match self.term {
            Termination::Newton => pt.vn - self.target,
            Termination::Poisson => {
                let c = self.pc.unwrap_or(f64::INFINITY) + self.recompressed;
                self.again.unwrap_or(pt.p) - (1.0 + self.e) * c
            }
            Termination::Energetic => pt.wn - (1.0 - self.e * self.e) * self.wc,
        }
    }

    /// Whether every compression phase is tracked (Poisson: its termination counts them).
    #[inline]
    pub(super) fn counts_compression(&self) -> bool {
        self.term == Termination::Poisson
    }

    /// The function of `event` at `c`, increasing through zero at the event.
    #[inline]
    pub(super) fn value(&self, event: Event, c: &Point) -> f64 {
        match event {
            Event::CompressionEnd | Event::RecompressionEnd => c.vn,
            Event::LawEnd => self.terminal(c),
            Event::Recompression => -c.vn,
        }
    }

    /// The first event between two points (`a` before, `b` after a step), with its function
    /// at both (`< 0` at `a`, `≥ 0` at `b`).
    ///
    /// Where a later compression begins inside the step, Poisson's termination function is
    /// evaluated at `b` as if it had not (it stops growing there): the recompression is
    /// returned, and the caller relocates the termination if it lies before
    /// ([`Events::poisson_ends_first`]).
    #[inline]
    pub(super) fn first(&self, a: &Point, b: &Point) -> Option<(Event, f64, f64)> {
        if self.pc.is_none() {
            if b.vn >= 0.0 && a.vn < 0.0 {
                return Some((Event::CompressionEnd, a.vn, b.vn));
            }
            return None;
        }
        if self.again.is_some() {
            // In a later compression phase: its end (from a located start at v_n = 0 exactly,
            // an end inside the step is at its start).
            let ends = (a.vn < 0.0 && b.vn >= 0.0) || (a.vn == 0.0 && b.vn > 0.0);
            return ends.then_some((Event::RecompressionEnd, a.vn, b.vn));
        }
        let (ga, gb) = (self.terminal(a), self.terminal(b));
        let term = ga < 0.0 && gb >= 0.0;
        let second =
            (self.second.is_none() || self.counts_compression()) && a.vn > 0.0 && b.vn <= 0.0;
        match (term, second) {
            (true, true) if self.counts_compression() => Some((Event::Recompression, -a.vn, -b.vn)),
            (true, _) => Some((Event::LawEnd, ga, gb)),
            (false, true) => Some((Event::Recompression, -a.vn, -b.vn)),
            _ => None,
        }
    }

    /// Whether Poisson's termination lies before a recompression located at `c` in the same
    /// step: its function, still growing with `p_n`, is already `≥ 0` there.
    #[inline]
    pub(super) fn poisson_ends_first(&self, event: Event, c: &Point) -> bool {
        event == Event::Recompression && self.counts_compression() && self.terminal(c) >= 0.0
    }

    /// Record `event` at `pt` (the slip direction there is `phi`); returns the end of the
    /// slip stage if the law terminated.
    pub(super) fn record(&mut self, event: Event, pt: &mut Point, phi: f64) -> Option<SlipEnd> {
        match event {
            Event::CompressionEnd => {
                pt.vn = 0.0;
                self.pc = Some(pt.p);
                self.wc = pt.wn;
                (self.terminal(pt) >= 0.0).then_some(SlipEnd::Terminated { phi })
            }
            Event::LawEnd => Some(SlipEnd::Terminated { phi }),
            Event::Recompression => {
                self.second.get_or_insert(pt.p);
                if self.counts_compression() {
                    self.again = Some(pt.p);
                }
                None
            }
            Event::RecompressionEnd => {
                // A later compression phase ended: its impulse adds to the compression.
                if let Some(start) = self.again.take() {
                    self.recompressed += pt.p - start;
                }
                (self.terminal(pt) >= 0.0).then_some(SlipEnd::Terminated { phi })
            }
        }
    }
}
