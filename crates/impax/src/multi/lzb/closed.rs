//! Phases in closed form: where the contacts that carry a force load in fixed proportions,
//! the path has one degree of freedom and is known exactly, as with one contact.
//!
//! **Fixed proportions.** With the regimes fixed, the velocities change as
//! `dv/dτ = W (T F; F)` (`field.rs`). Suppose the active contacts' deflections are
//! `s_j = a_j φ(τ)` with fixed `a_j > 0` (`a_c = 1` for a reference contact `c`). Then
//! `F_j = r_j F_c` with the fixed ratios `r_j = κ_j a_j^η / κ_c`, the velocities change along
//! the fixed direction `g = W (T r; r)` per unit of the reference's normal impulse `q`, and
//!
//! ```text
//! d²s_j/dτ² = −g_nj F_c / div_j,      ds_j/dτ = −v_nj / div_j,
//! ```
//!
//! which stay `a_j` times the reference's for all `τ` if and only if, at the phase's start,
//! `−v_nj/div_j = β a_j` and `−g_nj/div_j = γ a_j` for one `β` and one `γ` (the first holds
//! then for all `τ` because the second does). This is the case of one active contact alone,
//! and of several that move as one: a rod or a block landing flat, symmetric contacts. At the
//! impact's start every `s_j` is zero and the proportions are those of the deflection rates,
//! `a_j ∝ −v_nj⁻` (the first condition holds by construction). Then, in `q` from the phase's
//! start (values there with a `0`):
//!
//! ```text
//! p(q) = p₀ + (t; r) q,  t = T r,      v(q) = v₀ + g q,
//! Ê_c(q) = Ê_c0 − (v_nc0 q + g_nc q²/2) / div_c,      s_c = the deflection of Ê_c,  s_j = a_j s_c,
//! w_tj(q) = w_tj0 + t_j (v_tj0 q + g_tj q²/2),
//! ```
//!
//! the Darboux–Keller path of one contact (theory §2): velocities linear in the impulse,
//! energies quadratic. Every event function of `events.rs` is then affine in `q`, but the
//! separation (`Ê_c(q) = 0`, all the active contacts together: a quadratic); a stick cannot
//! break (the friction it needs is a fixed fraction of its force, inside the cone where the
//! regimes were chosen) and the primary cannot change (the energies keep their ratios). The
//! phase ends at the first root, found exactly, with every event due there (to `1e-12` of
//! `q`: the contacts moving as one end their compression, or separate, together).
//!
//! The conditions are checked to round-off: each difference within `64 ε` of the size of its
//! terms (the velocities' size `|v⁻| + |W| |p|`, the rates' `|W| |(t; r)|`), so that the
//! closed form departs from the integrated path by round-off only. A phase is not taken in
//! closed form when a contact in stick needs more friction than its cone holds, when the
//! active contacts are not all in the same normal regime, or when no event would end it (the
//! integration then decides, and reports a jam if there is one).

use super::events::{self, Event};
use super::field::{Eval, Field};
use super::state::{Modes, Setup, Tangent, MAXK, PER, PN, PT, S, WT};

/// How close, relative to the size of their terms, the proportions must hold.
const PROPORTION_TOL: f64 = 64.0 * f64::EPSILON;

/// At the impact's start, a phase is taken in closed form only if it ends past this fraction
/// of the deflection where its compression would end.
const START_FRACTION: f64 = 0.25;

/// Events of one contact due at the same point as the first, relative to its `q`.
const SIMULTANEOUS: f64 = 1e-12;

/// The events at the end of a phase taken in closed form.
pub(super) struct Ending {
    /// The events due there (the first one first).
    pub events: [Event; 3 * MAXK],
    /// How many.
    pub n: usize,
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
    /// `a_j`, `r_j`, `t_j = (T r)_j`.
    a: [f64; MAXK],
    r: [f64; MAXK],
    t: [f64; MAXK],
    /// `g = W (t; r)`, the velocities' rates.
    g: [f64; 2 * MAXK],
    /// The velocities at the start.
    v: [f64; 2 * MAXK],
    /// The reference's stored energy at the start and its deflection-rate divisor.
    e0: f64,
    div: f64,
}

impl Line {
    /// The reference's stored energy at `q`: `Ê_c0 − (v_nc0 q + g_nc q²/2)/div_c`.
    fn energy(&self, q: f64) -> f64 {
        let (v, g) = (self.v[2 * self.c + 1], self.g[2 * self.c + 1]);
        (self.e0 - (v * q + 0.5 * g * q * q) / self.div).max(0.0)
    }
}

/// If the active contacts load in fixed proportions at the point `y` in the regimes
/// `modes` (module docs), move `y` to the end of that phase and return the events due
/// there; else `None`, `y` unchanged. `at`: the field of `modes` and the point's quantities
/// in it, if the caller has them.
pub(super) fn phase<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    y: &mut [f64; N],
    at: Option<(&Field, &Eval)>,
) -> Option<Ending> {
    let formed;
    let (field, ev) = match at {
        Some(at) => at,
        None => {
            let field = Field::new(setup, modes);
            formed = (field, field.eval::<N>(setup, y));
            (&formed.0, &formed.1)
        }
    };
    let line = proportions(setup, modes, field, y, &ev.v)?;
    let (q, ending) = first_events(setup, modes, y, ev, &line)?;
    let (c, k) = (line.c, setup.k);
    if line.from_rest && (0..k).all(|j| y[PER * j + PN] == 0.0) {
        // The impact's start, where the forces grow as τ^η: a phase ending early would leave
        // the integration to go on in τ next to that singular point. Taken only if it ends
        // past START_FRACTION of the deflection where its compression ends (where the
        // integration would leave its start variable).
        let gc = line.g[2 * c + 1];
        let full = if gc > 0.0 {
            line.energy(-line.v[2 * c + 1] / gc)
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
        y[o + PT] += t[j] * q;
        y[o + PN] += r[j] * q;
        y[o + S] = if j == c { sc } else { a[j] * sc };
        y[o + WT] += t[j] * (v[2 * j] * q + 0.5 * g[2 * j] * q * q);
    }
    Some(ending)
}

/// The phase from the point `y` (velocities `v`) if its active contacts keep fixed
/// proportions (module docs: the conditions).
fn proportions(
    setup: &Setup,
    modes: &Modes,
    field: &Field,
    y: &[f64],
    v: &[f64; 2 * MAXK],
) -> Option<Line> {
    let k = setup.k;
    let mut line = Line {
        active: [0; MAXK],
        n: 0,
        from_rest: true,
        c: 0,
        a: [0.0; MAXK],
        r: [0.0; MAXK],
        t: [0.0; MAXK],
        g: [0.0; 2 * MAXK],
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
            -v[2 * j + 1] / field.div(j)
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
    line.div = field.div(c);
    line.e0 = setup.energy(c, y[PER * c + S]);
    // The rates per unit of the reference's normal impulse, and the sizes of the terms.
    line.t = field.tangential(k, &line.r);
    let (t, r) = (&line.t, &line.r);
    let (mut g_size, mut v_size) = (0.0f64, 0.0f64);
    for (i, gi) in line.g.iter_mut().enumerate().take(2 * k) {
        let row = &setup.w[i];
        let (mut x, mut size, mut vs) = (0.0, 0.0, setup.v0[i].abs());
        for col in 0..k {
            x += row[2 * col] * t[col] + row[2 * col + 1] * r[col];
            size += (row[2 * col] * t[col]).abs() + (row[2 * col + 1] * r[col]).abs();
            vs += (row[2 * col] * y[PER * col + PT]).abs()
                + (row[2 * col + 1] * y[PER * col + PN]).abs();
        }
        *gi = x;
        g_size = g_size.max(size);
        v_size = v_size.max(vs);
    }
    // The proportions hold (module docs); the sticking contacts inside their cones.
    let (g, a) = (&line.g, &line.a);
    let beta = -v[2 * c + 1] / line.div;
    let gamma = -g[2 * c + 1] / line.div;
    for &j in active {
        let dj = field.div(j);
        if (v[2 * j + 1] + dj * beta * a[j]).abs() > PROPORTION_TOL * v_size
            || (g[2 * j + 1] + dj * gamma * a[j]).abs() > PROPORTION_TOL * g_size
            || (modes.tangent[j] == Tangent::Stick && t[j].abs() > setup.mu[j] * r[j])
        {
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
    let g = &line.g;
    let watch = events::watch(setup, modes, y, ev);
    let mut roots = [f64::INFINITY; 3 * MAXK];
    for (i, root) in roots.iter_mut().enumerate().take(watch.n) {
        let slope = match watch.list[i] {
            Event::CompressionEnd(j) => g[2 * j + 1],
            Event::Recompression(j) | Event::Join(j) => -g[2 * j + 1],
            Event::Halt(j) => match modes.tangent[j] {
                Tangent::Slip(sigma) => -sigma * g[2 * j],
                Tangent::Stick => 0.0,
            },
            // (The friction needed stays inside the cone: `proportions`.)
            Event::StickBreak(_) => 0.0,
            Event::Separation(_) => {
                let c = line.c;
                *root = separation(line.e0, line.v[2 * c + 1], g[2 * c + 1], line.div);
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
        events: [Event::Join(0); 3 * MAXK],
        n: 0,
    };
    for (i, &root) in roots.iter().enumerate().take(watch.n) {
        if root <= q * (1.0 + SIMULTANEOUS) {
            ending.events[ending.n] = watch.list[i];
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
