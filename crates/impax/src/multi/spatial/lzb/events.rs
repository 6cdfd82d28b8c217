//! The events of the path, each the zero crossing of a function of the point that increases
//! through it (a crossing inside a step: `g ≤ 0` at its start, `g > 0` at its end):
//!
//! | event | regime | function |
//! |---|---|---|
//! | end of compression | compression | `v_nj` |
//! | separation | expansion | `−s_j` (the stored energy back to zero) |
//! | recompression | expansion | `−v_nj − a` (approaching again while loaded) |
//! | joining | off | `−v_nj − a`: a contact starts approaching |
//! | slip at its floor | slip along `v_t` | `σ_l − |v_tj|`: it goes on along a fixed direction (`σ_l = 2 σ_f`) |
//! | slip halt | slip along a fixed `d` | `−d·v_tj` |
//! | slip live | slip along a fixed `d` | `|v_tj| − σ_l`: it follows its own direction again |
//! | stick break | stick | `|x_j| − μ_j F_j − ε`: the friction needed leaves the circular cone |
//!
//! (`a` is the approach round-off, [`crate::multi::lzb::APPROACH_ROUND_OFF`] of the largest
//! `|v⁻_i|`; `σ_l` the contact's limit, [`Modes::limit`]; `ε` the stick's round-off,
//! [`super::STICK_ROUND_OFF`] of the force scale.) As in the planar law, a velocity that
//! starts a regime is zero only to the round-off of the event located there: each function
//! is offset by its value
//! where the regime starts when that is above zero, and a velocity event that starts within
//! `a` of zero by `a` more, so that every function starts below zero and its crossing is
//! seen.
//!
//! What each event changes is the path's business (`record.rs`).

use super::field::{cone_excess, slip, Eval};
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
    /// A slip along its own direction falls to its limit ([`Modes::limit`]).
    NearHalt(usize),
    /// A slip along a fixed direction halts.
    Halt(usize),
    /// A slip along a fixed direction grows past its limit.
    Live(usize),
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
            | Event::NearHalt(j)
            | Event::Halt(j)
            | Event::Live(j)
            | Event::StickBreak(j) => j,
        }
    }
}

/// The most events watched per contact (expansion: two; a fixed slip: two).
pub(super) const PER_CONTACT: usize = 4;

/// The events that can happen in the current regimes, with the offsets of their functions.
#[derive(Debug, Clone, Copy)]
pub(super) struct Watch {
    /// The events.
    pub list: [Event; PER_CONTACT * MAXK],
    /// Subtracted from each event's raw function ([`raw`]).
    pub offset: [f64; PER_CONTACT * MAXK],
    /// How many.
    pub n: usize,
}

/// The watched functions' values at a point.
pub(super) type Values = [f64; PER_CONTACT * MAXK];

/// The events to watch in `modes` from the point `y` (quantities `ev`) where the regimes
/// start (module docs: the offsets).
pub(super) fn watch(setup: &Setup, modes: &Modes, y: &[f64], ev: &Eval) -> Watch {
    let mut w = Watch {
        list: [Event::Join(0); PER_CONTACT * MAXK],
        offset: [0.0; PER_CONTACT * MAXK],
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
        if setup.mu[j] == 0.0 {
            continue;
        }
        match modes.tangent[j] {
            Tangent::Stick => push(Event::StickBreak(j), 0.0),
            Tangent::Slip => push(Event::NearHalt(j), 0.0),
            Tangent::Fixed { .. } => {
                push(Event::Halt(j), a);
                push(Event::Live(j), 0.0);
            }
        }
    }
    w
}

/// The raw function of `event` at the point `y` (with its quantities `ev`): the watched one
/// is this minus the watch's offset.
#[inline]
pub(super) fn raw(setup: &Setup, modes: &Modes, event: Event, y: &[f64], ev: &Eval) -> f64 {
    match event {
        Event::CompressionEnd(j) => ev.v[3 * j + 2],
        Event::Separation(j) => -y[PER * j + S],
        Event::Recompression(j) | Event::Join(j) => -ev.v[3 * j + 2],
        Event::NearHalt(j) => modes.limit[j] - slip(&ev.v, j).norm(),
        Event::Halt(j) => match modes.tangent[j] {
            Tangent::Fixed { dir, .. } => -dir.dot(&slip(&ev.v, j)),
            _ => 0.0,
        },
        Event::Live(j) => slip(&ev.v, j).norm() - modes.limit[j],
        Event::StickBreak(j) => cone_excess(setup, j, &ev.pt, &ev.f),
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
pub(super) fn values(setup: &Setup, modes: &Modes, watch: &Watch, y: &[f64], ev: &Eval) -> Values {
    let mut g = [0.0; PER_CONTACT * MAXK];
    for (i, gi) in g.iter_mut().enumerate().take(watch.n) {
        *gi = value(setup, modes, watch, i, y, ev);
    }
    g
}
