//! What the event-driven loop watches on each step and how it locates an event: the gaps of
//! the open contacts and the forces and slips of the closed ones, a crossing located on the
//! discrete solution itself; and the accumulation of impacts.

use super::closed::{self, Closed, Regime};
use crate::mechanism::{dynamics, Mechanism};
use crate::numerics::roots::illinois_with_bisection;
use crate::ode::Dopri5;

/// Gap of contact `k` at the state `y = (q, u, …)`.
pub(crate) fn gap_of<M: Mechanism + ?Sized>(m: &M, k: usize, y: &[f64]) -> f64 {
    dynamics::gap(m, k, &y[..m.dof()])
}

/// What a watched quantity signals when it falls through zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Watched {
    /// An open contact's gap: it reaches its surface.
    Gap(usize),
    /// A closed contact's normal force: it opens.
    Force(usize),
    /// A sliding contact's slip (times its direction): the slip halts.
    Slip(usize),
    /// A sticking contact's friction margin `μ λ_n − |λ_t|`: it starts to slip.
    Margin(usize),
    /// The sliding regime's force coefficient (relative determinant): Painlevé.
    Singular,
}

/// The watched quantities of the closed contacts from their watch values: per closed contact
/// its normal force and its slip (sliding) or friction margin (sticking); the singular one of
/// a sliding regime whose determinant `det0` at the regime's start is not near zero.
pub(crate) fn watched(
    closed: &[Closed],
    w: &closed::Watch,
    mu: f64,
    det0: f64,
) -> Vec<(Watched, f64)> {
    let mut out = Vec::with_capacity(2 * closed.len() + 1);
    for (j, c) in closed.iter().enumerate() {
        let (lt, ln) = (w.lambda[2 * j], w.lambda[2 * j + 1]);
        out.push((Watched::Force(c.contact), ln));
        match c.regime {
            Regime::Slip(d) => out.push((Watched::Slip(c.contact), d.sign() * w.v[2 * j])),
            Regime::Stick => out.push((Watched::Margin(c.contact), mu * ln - lt.abs())),
            Regime::Frictionless => {}
        }
    }
    let slides = closed.iter().any(|c| matches!(c.regime, Regime::Slip(_)));
    if slides && det0.abs() > 1e-6 {
        out.push((Watched::Singular, w.det * det0.signum()));
    }
    out
}

/// The value of one watched quantity at `y` (NaN where it cannot be evaluated).
pub(crate) fn watched_value<M: Mechanism + ?Sized>(
    m: &M,
    mu: f64,
    closed: &[Closed],
    what: Watched,
    y: &[f64],
    det0: f64,
) -> f64 {
    if let Watched::Gap(k) = what {
        return gap_of(m, k, y);
    }
    let Ok(w) = closed::watch(m, closed, mu, y) else {
        return f64::NAN;
    };
    watched(closed, &w, mu, det0)
        .iter()
        .find(|(x, _)| *x == what)
        .map_or(f64::NAN, |x| x.1)
}

/// An accumulation of impacts: the last intervals shrink geometrically (three ratios equal to
/// 1e-4) and the rest of the series is below a thousandth of the sample interval; or the last
/// interval is below round-off of the time. Returns `(t∞, ratio)`.
pub(crate) fn accumulation(times: &[f64], sample_interval: f64) -> Option<(f64, f64)> {
    let k = times.len();
    if k < 2 {
        return None;
    }
    let last = times[k - 1];
    let dt = last - times[k - 2];
    if dt <= 64.0 * f64::EPSILON * last.abs().max(1.0) {
        return Some((last, 0.0));
    }
    if k < 5 {
        return None;
    }
    let d: Vec<f64> = (k - 4..k).map(|i| times[i] - times[i - 1]).collect();
    let r: Vec<f64> = (1..4).map(|i| d[i] / d[i - 1]).collect();
    let ratio = r[2];
    let steady = r.iter().all(|&x| x > 0.0 && x < 1.0)
        && (r[2] - r[1]).abs() <= 1e-4 * ratio
        && (r[1] - r[0]).abs() <= 1e-4 * ratio;
    let tail = dt * ratio / (1.0 - ratio);
    (steady && tail <= 1e-3 * sample_interval).then_some((last + tail, ratio))
}

/// Locate where `g` (positive before, ≤ 0 at the event) falls through zero on the discrete
/// solution (re-stepping from `(t0, y0)`), bracketed by `[a, b]` from the dense output; `None`
/// when the discrete solution does not cross (a dense-output graze).
#[allow(clippy::too_many_arguments)]
pub(crate) fn locate(
    ode: &mut Dopri5,
    f: &mut impl FnMut(f64, &[f64], &mut [f64]),
    t0: f64,
    y0: &[f64],
    t1: f64,
    y1: &[f64],
    a: f64,
    b: f64,
    trial: &mut [f64],
    g: &mut impl FnMut(&[f64]) -> f64,
) -> Option<f64> {
    let mut at = |t: f64, g: &mut dyn FnMut(&[f64]) -> f64| -> f64 {
        if t == t0 {
            return g(y0);
        }
        if t == t1 {
            return g(y1);
        }
        ode.trial_step(f, t0, y0, t - t0, trial);
        g(trial)
    };
    let (mut lo, mut hi) = (a, b);
    let mut glo = at(lo, g);
    if glo.is_nan() || glo <= 0.0 {
        lo = t0;
        glo = at(t0, g);
    }
    let mut ghi = at(hi, g);
    if ghi.is_nan() || ghi > 0.0 {
        hi = t1;
        ghi = at(t1, g);
    }
    if !(glo > 0.0 && ghi <= 0.0) {
        return None;
    }
    // g falls through zero: its negative rises through zero, to round-off of t.
    Some(illinois_with_bisection(|t| -at(t, g), lo, -glo, hi, -ghi))
}
