//! Phases in closed form: where the contacts that carry a force load in fixed proportions
//! and every slip keeps its direction, the path has one degree of freedom and is known
//! exactly, as with one contact (the planar law's `closed.rs`, with each contact's tangent a
//! 2-vector).
//!
//! **Fixed proportions.** Suppose the active contacts' deflections are `s_j = a_j φ(τ)` with
//! fixed `a_j > 0` (`a_c = 1` for a reference contact `c`, the largest force). Then
//! `F_j = r_j F_c` with the fixed ratios `r_j = κ_j a_j^η / κ_c`, and if the tangential
//! impulse rates are a fixed multiple of the forces too, `dp_tj/dτ = t_j F_c`, the
//! velocities change along the fixed direction `g = W (t; r)` per unit of the reference's
//! normal impulse `q`. The tangential rates are fixed multiples where
//!
//! * a slip along a fixed direction `d` (the last bit of a halting slip, the first of one
//!   leaving rest): `t_j = −μ_j r_j d`;
//! * a slip along its own direction `ŝ_j`, if `ŝ_j` does not turn: `g_tj ∥ ŝ_j`, so that
//!   `v_tj(q) = v_tj0 + g_tj q` stays on the line of `ŝ_j` (a symmetric body's corners
//!   slipping round the vertical); then `t_j = −μ_j r_j ŝ_j` up to its halt, where
//!   `v_tj0 + g_tj q = 0`, a straight-line halt (the integrated path's last bit along the
//!   same fixed direction, `mod.rs`);
//! * stick: the stick set's solve is linear in the other rates (`field.rs`), so `t_S` is
//!   the solve's answer for the forces `r`, inside the cone if `|t_j| ≤ μ_j r_j` — and then
//!   for the whole phase, the ratio being fixed.
//!
//! With the deflection-rate divisor `div_j` (1 in compression, `e_j²` in expansion),
//!
//! ```text
//! d²s_j/dτ² = −g_nj F_c / div_j,      ds_j/dτ = −v_nj / div_j,
//! ```
//!
//! which stay `a_j` times the reference's for all `τ` if and only if, at the phase's start,
//! `−v_nj/div_j = β a_j` and `−g_nj/div_j = γ a_j` for one `β` and one `γ`. At the impact's
//! start every `s_j` is zero and the proportions are those of the deflection rates,
//! `a_j ∝ −v_nj⁻`. Then, in `q` from the phase's start (values there with a `0`):
//!
//! ```text
//! p(q) = p₀ + (t; r) q,      v(q) = v₀ + g q,
//! Ê_c(q) = Ê_c0 − (v_nc0 q + g_nc q²/2) / div_c,      s_j = a_j s_c,
//! w_tj(q) = w_tj0 + t_j · (v_tj0 q + g_tj q²/2),
//! ```
//!
//! the Darboux–Keller path of one contact. The event functions of `events.rs` are then
//! affine in `q` — but the separation (`Ê_c(q) = 0`, all the active contacts together: a
//! quadratic) and a fixed slip growing past its limit (`|v_tj(q)|` reaching it: a
//! quadratic); a slip along its own direction is taken to its halt (`|v_tj| = 0`, affine),
//! where it goes on as the integrated path would from its last bit; a stick cannot break and
//! the primary cannot change (the energies keep their ratios). The phase ends at the first
//! root, found exactly, with every event due there (to `1e-12` of `q`: the contacts moving
//! as one end their compression, halt, or separate together).
//!
//! The conditions are checked to round-off: each difference within `64 ε` of the size of
//! its terms (the velocities' size `|v⁻| + |W| |p|`, the rates' `|W| |(t; r)|`), so that
//! the closed form departs from the integrated path by round-off only. A phase is not taken
//! in closed form when a contact in stick needs more friction than its cone holds, a slip's
//! direction turns, the active contacts are not all in the same normal regime, or no event
//! would end it (the integration then decides, and reports a jam if there is one).

use super::events::{self, Event, PER_CONTACT};
use super::field::{eval, slip, tangential_rates, Eval};
use super::state::{Modes, Normal, Setup, Tangent, MAXK, PER, PN, PT1, PT2, ROWS, S, WT};
use crate::math::Vec2;

/// How close, relative to the size of their terms, the proportions must hold.
const PROPORTION_TOL: f64 = 64.0 * f64::EPSILON;

/// At the impact's start, a phase is taken in closed form only if it ends past this fraction
/// of the deflection where its compression would end.
const START_FRACTION: f64 = 0.25;

/// Events due at the same point as the first, relative to its `q`.
const SIMULTANEOUS: f64 = 1e-12;

/// The events at the end of a phase taken in closed form.
pub(super) struct Ending {
    /// The events due there (the first one first).
    pub events: [Event; PER_CONTACT * MAXK],
    /// How many.
    pub n: usize,
    /// The slips along their own directions that halt there (a [`Event::Halt`] each), with
    /// the direction they halt along.
    pub halting: [Option<Vec2>; MAXK],
}

/// A phase in fixed proportions from its start (module docs): the reference contact, the
/// proportions and the rates per unit of the reference's normal impulse `q`.
struct Line {
    /// The active contacts (the first `n`).
    active: [usize; MAXK],
    n: usize,
    /// Whether every active contact's deflection is zero (the proportions are then those of
    /// the deflection rates).
    from_rest: bool,
    /// The reference contact: the largest force.
    c: usize,
    /// `a_j`, `r_j`, `t_j`.
    a: [f64; MAXK],
    r: [f64; MAXK],
    t: [Vec2; MAXK],
    /// `g = W (t; r)`, the velocities' rates.
    g: [f64; ROWS],
    /// The velocities at the start.
    v: [f64; ROWS],
    /// The reference's stored energy at the start and its deflection-rate divisor.
    e0: f64,
    div: f64,
}

impl Line {
    /// The reference's stored energy at `q`: `Ê_c0 − (v_nc0 q + g_nc q²/2)/div_c`.
    fn energy(&self, q: f64) -> f64 {
        let (v, g) = (self.v[3 * self.c + 2], self.g[3 * self.c + 2]);
        (self.e0 - (v * q + 0.5 * g * q * q) / self.div).max(0.0)
    }
}

/// Contact `j`'s divisor of its deflection rate: 1 in compression, `e_j²` in expansion.
fn div(setup: &Setup, modes: &Modes, j: usize) -> f64 {
    match modes.normal[j] {
        Normal::Expansion => setup.e[j] * setup.e[j],
        _ => 1.0,
    }
}

/// If the active contacts load in fixed proportions at the point `y` in the regimes
/// `modes` (module docs), move `y` to the end of that phase and return the events due
/// there; else `None`, `y` unchanged.
pub(super) fn phase<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    y: &mut [f64; N],
) -> Option<Ending> {
    let (v, v_size) = velocities(setup, y);
    let line = proportions(setup, modes, y, &v, v_size)?;
    let ev = eval(setup, modes, y);
    let (q, ending) = first_events(setup, modes, y, &ev, &line)?;
    let (c, k) = (line.c, setup.k);
    if line.from_rest && (0..k).all(|j| y[PER * j + PN] == 0.0) {
        // The impact's start, where the forces grow as τ^η: a phase ending early would leave
        // the integration to go on in τ next to that singular point. Taken only if it ends
        // past START_FRACTION of the deflection where its compression ends (where the
        // integration would leave its start variable).
        let gc = line.g[3 * c + 2];
        let full = if gc > 0.0 {
            line.energy(-line.v[3 * c + 2] / gc)
        } else {
            f64::INFINITY
        };
        if line.energy(q) < START_FRACTION.powf(setup.law.eta + 1.0) * full {
            return None;
        }
    }
    // Move to the end of the phase.
    let separates = ending.events[..ending.n]
        .iter()
        .any(|e| matches!(e, Event::Separation(_)));
    let energy = if separates { 0.0 } else { line.energy(q) };
    let sc = if energy > 0.0 {
        setup.law.deflection(setup.kappa[c], energy)
    } else {
        0.0
    };
    let (a, r, t, g, v) = (&line.a, &line.r, &line.t, &line.g, &line.v);
    for &j in &line.active[..line.n] {
        let o = PER * j;
        y[o + PT1] += t[j].x * q;
        y[o + PT2] += t[j].y * q;
        y[o + PN] += r[j] * q;
        y[o + S] = if j == c { sc } else { a[j] * sc };
        let (v0, g0) = (slip(v, j), slip(g, j));
        y[o + WT] += t[j].dot(&(v0 * q + g0 * (0.5 * q * q)));
    }
    Some(ending)
}

/// The velocities `v⁻ + W p` at the point `y` and their size, the largest
/// `|v⁻_i| + Σ_c |W_ic p_c|`.
fn velocities(setup: &Setup, y: &[f64]) -> ([f64; ROWS], f64) {
    let k = setup.k;
    let mut p = [0.0; ROWS];
    for c in 0..k {
        p[3 * c] = y[PER * c + PT1];
        p[3 * c + 1] = y[PER * c + PT2];
        p[3 * c + 2] = y[PER * c + PN];
    }
    let mut v = [0.0; ROWS];
    let mut size = 0.0f64;
    for ((vi, row), v0) in v.iter_mut().zip(&setup.w[..3 * k]).zip(&setup.v0[..3 * k]) {
        let (mut x, mut s) = (*v0, v0.abs());
        for (w, pc) in row[..3 * k].iter().zip(&p[..3 * k]) {
            x += w * pc;
            s += (w * pc).abs();
        }
        *vi = x;
        size = size.max(s);
    }
    (v, size)
}

/// The phase from the point `y` (velocities `v`, of size `v_size`) if its active contacts keep fixed
/// proportions and their slips their directions (module docs: the conditions).
fn proportions(
    setup: &Setup,
    modes: &Modes,
    y: &[f64],
    v: &[f64; ROWS],
    v_size: f64,
) -> Option<Line> {
    let k = setup.k;
    let mut line = Line {
        active: [0; MAXK],
        n: 0,
        from_rest: true,
        c: 0,
        a: [0.0; MAXK],
        r: [0.0; MAXK],
        t: [Vec2::zeros(); MAXK],
        g: [0.0; ROWS],
        v: *v,
        e0: 0.0,
        div: 1.0,
    };
    for j in (0..k).filter(|&j| modes.active(j)) {
        line.active[line.n] = j;
        line.n += 1;
        line.from_rest &= y[PER * j + S] == 0.0;
    }
    let active = &line.active[..line.n];
    let first = *active.first()?;
    if active
        .iter()
        .any(|&j| modes.normal[j] != modes.normal[first])
    {
        return None;
    }
    // The proportions of the deflections: the deflections, or from rest their rates.
    let (a, r) = (&mut line.a, &mut line.r);
    for &j in active {
        a[j] = if line.from_rest {
            -v[3 * j + 2] / div(setup, modes, j)
        } else {
            y[PER * j + S]
        };
        r[j] = setup.force(j, a[j]);
        if !(a[j] > 0.0 && a[j].is_finite()) {
            return None;
        }
    }
    let c = active
        .iter()
        .copied()
        .fold(first, |b, j| if r[j] > r[b] { j } else { b });
    let (rc, ac) = (r[c], a[c]);
    if !(rc > 0.0 && rc.is_finite()) {
        return None;
    }
    for &j in active {
        r[j] /= rc;
        a[j] /= ac;
    }
    line.c = c;
    line.div = div(setup, modes, c);
    line.e0 = setup.energy(c, y[PER * c + S]);
    // The deflection rates in proportion (module docs), checked before the rates are formed
    // (most points fail here).
    let beta = -v[3 * c + 2] / line.div;
    for &j in active {
        let dj = div(setup, modes, j);
        if (v[3 * j + 2] + dj * beta * line.a[j]).abs() > PROPORTION_TOL * v_size {
            return None;
        }
    }
    // The rates per unit of the reference's normal impulse (slips along their directions
    // at the start), and the size of their terms.
    line.t = tangential_rates(setup, modes, &line.r, v);
    let (t, r) = (&line.t, &line.r);
    let mut rates = [0.0; ROWS];
    for col in 0..k {
        rates[3 * col] = t[col].x;
        rates[3 * col + 1] = t[col].y;
        rates[3 * col + 2] = r[col];
    }
    let mut g_size = 0.0f64;
    for (row, gi) in setup.w[..3 * k].iter().zip(line.g.iter_mut()) {
        let (mut x, mut size) = (0.0, 0.0);
        for (w, rc) in row[..3 * k].iter().zip(&rates[..3 * k]) {
            x += w * rc;
            size += (w * rc).abs();
        }
        *gi = x;
        g_size = g_size.max(size);
    }
    // The rates in proportion; the sticking contacts inside their cones; the slips along
    // their own directions on straight lines.
    let (g, a) = (&line.g, &line.a);
    let gamma = -g[3 * c + 2] / line.div;
    for &j in active {
        let dj = div(setup, modes, j);
        if (g[3 * j + 2] + dj * gamma * a[j]).abs() > PROPORTION_TOL * g_size {
            return None;
        }
        if setup.mu[j] == 0.0 {
            continue;
        }
        let holds = match modes.tangent[j] {
            Tangent::Stick => t[j].norm() <= setup.mu[j] * r[j],
            Tangent::Fixed { .. } => true,
            Tangent::Slip => {
                let (vt, gt) = (slip(v, j), slip(g, j));
                let sigma = vt.norm();
                sigma > modes.limit[j]
                    && (vt.x * gt.y - vt.y * gt.x).abs() <= PROPORTION_TOL * g_size * sigma
            }
        };
        if !holds {
            return None;
        }
    }
    Some(line)
}

/// The first root along `line` of the event functions watched at the point `y` (quantities
/// `ev`), and every event due there; `None` if no event ends the phase.
fn first_events(
    setup: &Setup,
    modes: &Modes,
    y: &[f64],
    ev: &Eval,
    line: &Line,
) -> Option<(f64, Ending)> {
    let (g, v) = (&line.g, &line.v);
    let watch = events::watch(setup, modes, y, ev);
    let mut roots = [f64::INFINITY; PER_CONTACT * MAXK];
    for (i, root) in roots.iter_mut().enumerate().take(watch.n) {
        let slope = match watch.list[i] {
            Event::CompressionEnd(j) => g[3 * j + 2],
            Event::Recompression(j) | Event::Join(j) => -g[3 * j + 2],
            Event::Halt(j) => match modes.tangent[j] {
                Tangent::Fixed { dir, .. } => -dir.dot(&slip(g, j)),
                _ => 0.0,
            },
            Event::NearHalt(j) => {
                // Taken to the halt itself, `|v_tj| = 0` (the slip on a straight line).
                let vt = slip(v, j);
                let sigma = vt.norm();
                let rate = vt.dot(&slip(g, j)) / sigma;
                if rate < 0.0 {
                    *root = sigma / -rate;
                }
                continue;
            }
            Event::Live(j) => {
                *root = live(slip(v, j), slip(g, j), modes.limit[j] + watch.offset[i]);
                continue;
            }
            // (The friction needed stays inside the cone: `proportions`.)
            Event::StickBreak(_) => 0.0,
            Event::Separation(_) => {
                let c = line.c;
                *root = separation(line.e0, v[3 * c + 2], g[3 * c + 2], line.div);
                continue;
            }
        };
        let start = events::value(setup, modes, &watch, i, y, ev);
        if slope > 0.0 {
            *root = (-start / slope).max(0.0);
        }
    }
    let q = roots[..watch.n]
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min);
    if !(q > 0.0 && q.is_finite()) {
        return None;
    }
    let mut ending = Ending {
        events: [Event::Join(0); PER_CONTACT * MAXK],
        n: 0,
        halting: [None; MAXK],
    };
    for (i, &root) in roots.iter().enumerate().take(watch.n) {
        if root <= q * (1.0 + SIMULTANEOUS) {
            let mut event = watch.list[i];
            if let Event::NearHalt(j) = event {
                let vt = slip(v, j);
                ending.halting[j] = Some(vt / vt.norm());
                event = Event::Halt(j);
            }
            ending.events[ending.n] = event;
            ending.n += 1;
        }
    }
    Some((q, ending))
}

/// The first `q > 0` where `Ê(q) = e0 − (v q + g q²/2)/div` reaches zero (infinite if
/// none): the smaller positive root of `g q² + 2 v q − 2 e0 div`, in the form without
/// cancellation.
fn separation(e0: f64, v: f64, g: f64, div: f64) -> f64 {
    let c = 2.0 * e0 * div;
    let disc = v * v + g * c;
    if disc.is_nan() || disc < 0.0 {
        return f64::INFINITY;
    }
    let den = v + disc.sqrt();
    if den > 0.0 {
        c / den
    } else if g > 0.0 {
        (disc.sqrt() - v) / g
    } else {
        f64::INFINITY
    }
}

/// The first `q > 0` where a slip `v0 + g q` starting within `limit` grows past it
/// (infinite if never): the positive root of `|g|² q² + 2 (v0·g) q + |v0|² − limit²`.
fn live(v0: Vec2, g: Vec2, limit: f64) -> f64 {
    let (a, b, c) = (
        g.norm_squared(),
        v0.dot(&g),
        v0.norm_squared() - limit * limit,
    );
    let disc = b * b - a * c;
    if a.is_nan() || a <= 0.0 || disc.is_nan() || disc < 0.0 || c > 0.0 {
        return f64::INFINITY;
    }
    if b > 0.0 {
        -c / (b + disc.sqrt())
    } else {
        (disc.sqrt() - b) / a
    }
}
