//! The path of the impact: the adaptive DOP853 integration with its error test, the first
//! event inside an accepted step located on the discrete solution, the changes of variable,
//! and the ends of the impact (as in the planar law's `path.rs`).
//!
//! An event is located on the step's seventh-order dense output: the root of the event
//! function in the step's fraction `θ` by the Illinois iteration to `4ε` in `θ` (of the
//! events inside one step, the first). The path goes on from the discrete solution there, by
//! re-stepping from the step's start to that `θ`. At the start and after every event, the
//! phases where the loaded contacts keep fixed proportions and their slips their directions
//! are taken in closed form first (`closed.rs`); the integration resumes after them with the
//! step it had, or with [`FIRST_STEP`] of the shortest compression time.

use super::closed;
use super::events;
use super::field::{eval, Eval};
use super::record::{End, Path};
use super::state::{Modes, Setup, PER, ROWS, S};
use super::variable::Var;
use super::{MAX_STEPS, RTOL};
use crate::law::BreakdownReason;
use crate::multi::lzb::common::{grow, guard, shrink};
use crate::numerics::dop853::{dop853_step, error_measure, Dense};
use crate::numerics::roots::illinois;

/// Integrate the impact to its end (module docs of [`super`]); `N = 5K`.
pub(super) fn run<const N: usize>(setup: &Setup) -> Result<End, BreakdownReason> {
    debug_assert_eq!(N, PER * setup.k);
    let k = setup.k;
    let mut y = [0.0; N];
    let mut path = Path::start(setup, &y);
    let (mut var, mut h, shortest) = start(setup);
    let mut x = 0.0;
    let root_end = 0.25 * shortest;
    let (mut attempts, mut steps) = (0usize, 0usize);
    // The phases in closed form from the start, then the integration: from its start, or
    // in τ with a first step of FIRST_STEP of the shortest compression time.
    let advanced = match closed_phases(&mut path, &mut y, &mut attempts)? {
        Closed::Ended => return Ok(path.finish(&y, steps)),
        Closed::Unchanged => false,
        Closed::Advanced => true,
    };
    let mut modes = path.modes;
    let (mut k1, mut watch, mut g_a);
    if advanced {
        (var, x, h, k1, watch, g_a) = restart(setup, &modes, &y, FIRST_STEP * shortest, root_end);
    } else {
        k1 = var.rhs::<N>(setup, &modes, x, &y);
        let ev0 = eval(setup, &modes, &y);
        watch = events::watch(setup, &modes, &y, &ev0);
        g_a = events::values(setup, &modes, &watch, &y, &ev0);
    }
    while (0..k).any(|j| modes.active(j)) {
        attempts += 1;
        if attempts > MAX_STEPS {
            return Err(BreakdownReason::TooManySteps { limit: MAX_STEPS });
        }
        // A separation ends exactly at σ = 0, a halt's variable at the log of the limit.
        let end = var.end(&modes);
        let lands = end.is_some_and(|end| x + h <= end);
        if let (true, Some(end)) = (lands, end) {
            h = end - x;
        }
        let f = |xx: f64, yy: &[f64; N]| var.rhs::<N>(setup, &modes, xx, yy);
        let st = dop853_step(&f, x, &y, &k1, h);
        let en = error_measure(&st, |i| {
            setup.atol[i] + RTOL * y[i].abs().max(st.y[i].abs())
        });
        // (NaN or a number not representable: rejected.)
        let en = if st.y.iter().all(|x| x.is_finite()) {
            en
        } else {
            f64::NAN
        };
        if en.is_nan() || en > 1.0 {
            h *= shrink(en);
            continue;
        }
        let y1 = st.y;
        let (k_end, ev_b) = var.rhs_eval::<N>(setup, &modes, x + h, &y1);
        let g_b = events::values(setup, &modes, &watch, &y1, &ev_b);
        // (In the separation and halt variables their own event is the end of the range.)
        let own = var.own_event();
        let crosses = |i: usize| g_a[i] <= 0.0 && g_b[i] > 0.0 && Some(watch.list[i]) != own;
        let crossing = (0..watch.n).any(crosses);
        if !crossing && settled(setup, &modes, &y1, &ev_b.v) {
            y = y1;
            steps += 1;
            path.end_settled(&y);
            break;
        }
        if !crossing {
            if let Some(stored) = jammed(setup, &modes, &y1, &ev_b) {
                return Err(BreakdownReason::Jammed { stored });
            }
        }
        let (theta, event) = if crossing {
            // The first event inside the step, located on the dense output, then on the
            // discrete solution: re-step from the step's start to it.
            let dense = Dense::new(&f, x, &y, &st, &k_end, h);
            let (seed, i) = first_event(setup, &modes, &watch, &g_a, &g_b, &crosses, &dense);
            let ye = if seed == 0.0 {
                y
            } else {
                dop853_step(&f, x, &y, &k1, seed * h).y
            };
            path.follow_primary(seed, &y, &ye, &|| Dense::new(&f, x, &y, &st, &k_end, h));
            y = ye;
            (seed, Some(watch.list[i]))
        } else {
            path.follow_primary(1.0, &y, &y1, &|| Dense::new(&f, x, &y, &st, &k_end, h));
            y = y1;
            (1.0, own.filter(|_| lands))
        };
        steps += 1;
        let Some(event) = event else {
            // On in the same regimes; the next variable: the start ends, a separation or a
            // halt nears, or stops nearing.
            x += h;
            k1 = k_end;
            g_a = g_b;
            h *= grow(en);
            // Slips near their halts compared with their rays (the regimes may change here,
            // at the step's end, with no event to locate).
            if var != Var::Root && path.check_halts(&ev_b, var.to_time(setup, x, h, &ev_b)) {
                modes = path.modes;
                let h_tau = guard(var.to_time(setup, x, h, &ev_b), shortest);
                (var, x, h, k1, watch, g_a) = restart(setup, &modes, &y, h_tau, root_end);
                continue;
            }
            let next = var.next(setup, &modes, x, h, &y1, &ev_b, root_end);
            if next != var {
                h = guard(var.to_time(setup, x, h, &ev_b), shortest);
                (x, h) = next.start_from_time(setup, &modes, &ev_b.v, &y, h);
                var = next;
                k1 = var.rhs::<N>(setup, &modes, x, &y);
            }
            continue;
        };
        // The event (or the own event the step landed on) changes the regimes.
        let ev_before = if theta == 1.0 {
            ev_b
        } else {
            eval(setup, &modes, &y)
        };
        path.apply(&[event], &mut y);
        if settled(setup, &path.modes, &y, &eval(setup, &path.modes, &y).v) {
            path.end_settled(&y);
            break;
        }
        if closed_phases(&mut path, &mut y, &mut attempts)? == Closed::Ended {
            break;
        }
        modes = path.modes;
        let h_tau = guard(var.to_time(setup, x, h, &ev_before), shortest);
        (var, x, h, k1, watch, g_a) = restart(setup, &modes, &y, h_tau, root_end);
    }
    Ok(path.finish(&y, steps))
}

/// The start: the variable, its first step, and the shortest time a contact alone would
/// compress in. In `u = τ^(1/m)` for a quarter of that time, or in `τ` for an integer
/// exponent; the first step a tenth of the way.
fn start(setup: &Setup) -> (Var, f64, f64) {
    let mut shortest = f64::INFINITY;
    for j in 0..setup.k {
        let vn = setup.v0[3 * j + 2];
        if vn < -setup.approach {
            let wnn = setup.w[3 * j + 2][3 * j + 2];
            shortest = shortest.min(setup.law.compression_time(setup.kappa[j], wnn, vn));
        }
    }
    let m = setup.law.m;
    if m == 1 {
        (Var::Time, 0.01 * shortest, shortest)
    } else {
        let h = 0.1 * (0.25 * shortest).powf(1.0 / f64::from(m));
        (Var::Root, h, shortest)
    }
}

/// The first step of `τ` after phases in closed form from the impact's start, as a fraction
/// of the shortest time a contact alone would compress in.
const FIRST_STEP: f64 = 0.01;

/// What the phases in closed form at a point did ([`closed_phases`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Closed {
    /// None was taken.
    Unchanged,
    /// The path moved on; contacts still carry a force.
    Advanced,
    /// The impact ended.
    Ended,
}

/// The phases in closed form from the point `y` (`closed.rs`), one after the other, each
/// with the events at its end; `attempts` counts them with the integration's steps.
fn closed_phases<const N: usize>(
    path: &mut Path,
    y: &mut [f64; N],
    attempts: &mut usize,
) -> Result<Closed, BreakdownReason> {
    let setup = path.setup;
    let mut out = Closed::Unchanged;
    while let Some(end) = closed::phase::<N>(setup, &path.modes, y) {
        *attempts += 1;
        if *attempts > MAX_STEPS {
            return Err(BreakdownReason::TooManySteps { limit: MAX_STEPS });
        }
        out = Closed::Advanced;
        for (j, dir) in end.halting.iter().enumerate() {
            if let Some(dir) = *dir {
                path.halt_along(j, dir);
            }
        }
        path.apply(&end.events[..end.n], y);
        if settled(setup, &path.modes, y, &eval(setup, &path.modes, y).v) {
            path.end_settled(y);
            return Ok(Closed::Ended);
        }
        if !(0..setup.k).any(|j| path.modes.active(j)) {
            return Ok(Closed::Ended);
        }
    }
    Ok(out)
}

/// Going on from `y` in new regimes `modes` with a step `h` of `τ`: in `τ`, or in a
/// separation's or a halt's variable if one is near. Returns the variable, where it starts
/// and its first step, the derivative there and the watched events with their values.
fn restart<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    y: &[f64; N],
    h: f64,
    root_end: f64,
) -> (Var, f64, f64, [f64; N], events::Watch, events::Values) {
    let ev = eval(setup, modes, y);
    let var = Var::Time.next(setup, modes, 0.0, h, y, &ev, root_end);
    let (x, h) = var.start_from_time(setup, modes, &ev.v, y, h);
    let k1 = var.rhs::<N>(setup, modes, x, y);
    let watch = events::watch(setup, modes, y, &ev);
    let g = events::values(setup, modes, &watch, y, &ev);
    (var, x, h, k1, watch, g)
}

/// The first of the events crossing inside a step (`crosses`), located on the step's dense
/// output: its fraction of the step and its index in the watch.
fn first_event<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    watch: &events::Watch,
    g_a: &events::Values,
    g_b: &events::Values,
    crosses: &dyn Fn(usize) -> bool,
    dense: &Dense<N>,
) -> (f64, usize) {
    let mut first: Option<(f64, usize)> = None;
    for i in (0..watch.n).filter(|&i| crosses(i)) {
        let seed = if g_a[i] == 0.0 {
            0.0
        } else {
            let g = |th: f64| {
                let z = dense.at(th);
                events::value(setup, modes, watch, i, &z, &eval(setup, modes, &z))
            };
            illinois(g, 0.0, g_a[i], 1.0, g_b[i])
        };
        if first.is_none_or(|(th, _)| seed < th) {
            first = Some((seed, i));
        }
    }
    first.expect("a crossing")
}

/// Whether the impact has settled at `y` (velocities `v`): every contact that carries a
/// force moves normally by at most the settled round-off (`|v_nj| ≤ d`,
/// [`crate::multi::lzb::SETTLED`] of the largest `|v⁻_i|`) and stores at most the energy
/// that could move it by that much alone (`Ê_j ≤ ½ d² / W_njnj`), and no other contact
/// approaches by more than `d`.
fn settled(setup: &Setup, modes: &Modes, y: &[f64], v: &[f64; ROWS]) -> bool {
    let d = setup.settled;
    (0..setup.k).all(|j| {
        let vn = v[3 * j + 2];
        if modes.active(j) {
            vn.abs() <= d
                && setup.energy(j, y[PER * j + S]) <= 0.5 * d * d / setup.w[3 * j + 2][3 * j + 2]
        } else {
            vn >= -d
        }
    })
}

/// The energy stored in the contacts if they are jammed at `y` (quantities `ev`): every
/// contact that carries a force at rest (each velocity component within the settled
/// round-off) and no velocity changing (`|dv_i/dτ|` at those contacts below `1e-9` of
/// `Σ_c |W_ic| |dp_c/dτ|`): the path is at an equilibrium holding energy, which a positive
/// definite `W` cannot have.
fn jammed(setup: &Setup, modes: &Modes, y: &[f64], ev: &Eval) -> Option<f64> {
    let d = setup.settled;
    let k = setup.k;
    let mut stored = 0.0;
    for j in (0..k).filter(|&j| modes.active(j)) {
        if (0..3).any(|a| ev.v[3 * j + a].abs() > d) {
            return None;
        }
        stored += setup.energy(j, y[PER * j + S]);
    }
    if stored.is_nan() || stored <= 0.0 {
        return None;
    }
    let mut rates = [0.0; ROWS];
    for c in 0..k {
        rates[3 * c] = ev.pt[c].x;
        rates[3 * c + 1] = ev.pt[c].y;
        rates[3 * c + 2] = ev.f[c];
    }
    for j in (0..k).filter(|&j| modes.active(j)) {
        for i in 3 * j..3 * j + 3 {
            let row = &setup.w[i];
            let (mut acc, mut scale) = (0.0, 0.0);
            for (wc, rc) in row[..3 * k].iter().zip(&rates[..3 * k]) {
                acc += wc * rc;
                scale += (wc * rc).abs();
            }
            if acc.abs() > 1e-9 * scale {
                return None;
            }
        }
    }
    Some(setup.units.work(stored))
}
