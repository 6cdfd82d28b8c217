//! The events of the path, each the zero crossing of a function of the point that increases
//! through it (a crossing inside a step: `g ≤ 0` at its start, `g > 0` at its end):
//!
//! | event | regime | function |
//! |---|---|---|
//! | end of compression | compression | `v_nj` |
//! | separation | expansion | `−s_j` (the stored energy back to zero) |
//! | recompression | expansion | `−v_nj − a` (approaching again while loaded) |
//! | joining | off | `−v_nj − a`: a contact starts approaching |
//! | slip halt | slip `σ ≠ 0` | `−σ v_tj − a` |
//! | stick break | stick | `|x_j| − μ_j F_j` (the friction needed leaves the cone) |
//!
//! (`a` is the approach round-off, [`super::APPROACH_ROUND_OFF`] of the largest `|v⁻_i|`.)
//! A velocity that starts a regime is zero only to the round-off of the event located there,
//! of either sign (a slip resumed after a halt, an expansion after a compression): each
//! function is offset by its value where the regime starts when that is above zero, and a
//! velocity event that starts within `a` of zero by `a` more, so that every function starts
//! below zero and its crossing is seen (a slip resumed in the wrong direction by `1e-12` would
//! otherwise never end, and its friction would do positive work). Only the events of regimes
//! started at rest are so offset, and located late by `a` at most; a slip that started
//! sliding halts exactly at `v_t = 0`.
//!
//! What each event changes is the path's business (`path.rs`).

use super::field::Eval;
use super::state::{Modes, Normal, Setup, Tangent, MAXK, PER, S};

/// An event of contact `j`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Event {
    /// `v_nj` reaches 0 in compression.
    CompressionEnd(usize),
    /// `s_j` (the stored energy) reaches 0 in expansion.
    Separation(usize),
    /// `v_nj` falls below 0 in expansion.
    Recompression(usize),
    /// An off contact starts approaching.
    Join(usize),
    /// A slip halts.
    Halt(usize),
    /// A stick breaks.
    StickBreak(usize),
}

impl Event {
    /// The contact.
    pub(super) fn contact(self) -> usize {
        match self {
            Event::CompressionEnd(j)
            | Event::Separation(j)
            | Event::Recompression(j)
            | Event::Join(j)
            | Event::Halt(j)
            | Event::StickBreak(j) => j,
        }
    }
}

/// The events that can happen in the current regimes, with the offsets of their functions.
#[derive(Debug, Clone, Copy)]
pub(super) struct Watch {
    /// The events.
    pub list: [Event; 3 * MAXK],
    /// Subtracted from each event's raw function ([`raw`]).
    pub offset: [f64; 3 * MAXK],
    /// How many.
    pub n: usize,
}

/// The events to watch in `modes` from the point `y` (quantities `ev`) where the regimes
/// start (module docs: the offsets).
pub(super) fn watch(setup: &Setup, modes: &Modes, y: &[f64], ev: &Eval) -> Watch {
    let mut w = Watch {
        list: [Event::Join(0); 3 * MAXK],
        offset: [0.0; 3 * MAXK],
        n: 0,
    };
    let mut push = |e: Event, margin: f64| {
        let start = raw(setup, modes, e, y, ev);
        w.list[w.n] = e;
        w.offset[w.n] = if start > -margin {
            start.max(0.0) + margin
        } else {
            0.0
        };
        w.n += 1;
    };
    let a = setup.approach;
    for j in 0..setup.k {
        match modes.normal[j] {
            Normal::Off => {
                push(Event::Join(j), a);
                continue;
            }
            Normal::Compression => push(Event::CompressionEnd(j), 0.0),
            Normal::Expansion => {
                push(Event::Separation(j), 0.0);
                push(Event::Recompression(j), a);
            }
        }
        match modes.tangent[j] {
            Tangent::Stick => push(Event::StickBreak(j), 0.0),
            Tangent::Slip(sigma) if sigma != 0.0 => push(Event::Halt(j), a),
            Tangent::Slip(_) => {}
        }
    }
    w
}

/// The raw function of `event` at the point `y` (with its quantities `ev`): the watched one
/// is this minus the watch's offset.
#[inline]
pub(super) fn raw(setup: &Setup, modes: &Modes, event: Event, y: &[f64], ev: &Eval) -> f64 {
    match event {
        Event::CompressionEnd(j) => ev.v[2 * j + 1],
        Event::Separation(j) => -y[PER * j + S],
        Event::Recompression(j) | Event::Join(j) => -ev.v[2 * j + 1],
        Event::Halt(j) => match modes.tangent[j] {
            Tangent::Slip(sigma) => -sigma * ev.v[2 * j],
            Tangent::Stick => 0.0,
        },
        Event::StickBreak(j) => ev.pt[j].abs() - setup.mu[j] * ev.f[j],
    }
}

/// The watched function of the `i`-th event of `watch` at the point.
#[inline]
pub(super) fn value(
    setup: &Setup,
    modes: &Modes,
    watch: &Watch,
    i: usize,
    y: &[f64],
    ev: &Eval,
) -> f64 {
    raw(setup, modes, watch.list[i], y, ev) - watch.offset[i]
}

/// Every watched function at the point.
#[inline]
pub(super) fn values(
    setup: &Setup,
    modes: &Modes,
    watch: &Watch,
    y: &[f64],
    ev: &Eval,
) -> [f64; 3 * MAXK] {
    let mut g = [0.0; 3 * MAXK];
    for (i, gi) in g.iter_mut().enumerate().take(watch.n) {
        *gi = value(setup, modes, watch, i, y, ev);
    }
    g
}
