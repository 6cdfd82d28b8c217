//! Coulomb's law at every contact: the stick set's solve and the choice of the tangential
//! regimes where a contact's slip is zero.
//!
//! **Stick.** The sticking contacts `S` keep `v_t = 0`: their tangential impulse rates `x_S`
//! solve `W_SS^tt x_S = −r_S` (`field.rs`), in the least-norm sense, `x_S = −(W_SS^tt)⁺ r_S`:
//! with redundant contacts (a rod lying flat: both ends share one tangential velocity)
//! `W_SS^tt` is singular, the system is consistent (`r_S` is in the range of `W_SS^tt` when
//! `W = J M⁻¹ Jᵀ`) and only the least-norm split is chosen (as `lcp` does). The
//! pseudo-inverse is computed once per stick set, by Jacobi's rotations on the small
//! symmetric block, eigenvalues within [`crate::multi::RANK_TOL`] of the largest counted as
//! zero (`common.rs`). Stick holds while `|x_j| ≤ μ_j F_j`.
//!
//! **Choice.** Where contacts with friction have zero slip — at the start, when a slip
//! halts, when a stick breaks, when a contact joins at rest — every assignment of
//! `stick`, `slip+`, `slip−` to them is tried, most sticks first, and the first consistent one
//! is taken: each sticking contact inside its cone (`|x_j| ≤ μ_j F_j`), each slipping one
//! accelerating in its direction (`σ_j dv_tj/dτ ≥ 0`, to round-off). A contact whose stick
//! just broke must slip; a contact whose slip just halted sticks or reverses (as in the
//! one-contact law). Past six contacts at rest at once, the first six (the contacts of the
//! event first) are enumerated and the others take the regime the all-stick solve gives them
//! (stick inside the cone, else slip against the friction needed). If no assignment is
//! consistent (not observed), the least inconsistent one is taken.

use super::common::pseudo_inverse;
use super::field::{tangential_acceleration, tangential_rates};
use super::state::{Modes, Setup, StickSet, Tangent, MAXK};

/// The most contacts whose regimes are chosen by enumeration (`3^6 = 729` assignments);
/// beyond, each contact past the sixth takes its regime from the all-stick solve: stick if
/// that solve keeps it inside its cone, else slip against the friction it would need (seven
/// contacts at rest at once: the eight-ball cradle with friction, whose seven contacts all
/// stick).
const ENUMERATED: usize = 6;

/// The stick set of the contacts `idx` (increasing): `(W_SS^tt)⁺` by Jacobi's rotations.
pub(super) fn stick_set(setup: &Setup, idx: &[usize]) -> StickSet {
    let n = idx.len();
    let mut set = StickSet::EMPTY;
    set.n = n;
    set.idx[..n].copy_from_slice(idx);
    if n == 0 {
        return set;
    }
    let mut a = [[0.0; MAXK]; MAXK];
    for p in 0..n {
        for q in 0..n {
            a[p][q] = setup.w[2 * idx[p]][2 * idx[q]];
        }
    }
    set.pinv = pseudo_inverse(a, n);
    set
}

/// What a contact at rest may do: stick, slip in `+t`, slip in `−t`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Allowed {
    pub stick: bool,
    pub positive: bool,
    pub negative: bool,
}

impl Allowed {
    pub(super) const ANY: Allowed = Allowed {
        stick: true,
        positive: true,
        negative: true,
    };
}

/// Choose the tangential regimes of the contacts `rest` (with friction, carrying or about to
/// carry a force, zero slip), each restricted by `allowed`, given the effective normal forces
/// `f` (the forces, or at the start of the impact their limiting ratios). The other active
/// contacts keep their regimes. Sets `modes.tangent` of `rest` and rebuilds the stick set.
pub(super) fn choose(
    setup: &Setup,
    modes: &mut Modes,
    f: &[f64; MAXK],
    rest: &[usize],
    allowed: &[Allowed],
) {
    let k = setup.k;
    let z = rest.len().min(ENUMERATED);
    if rest.len() > z {
        tail(setup, modes, f, rest, allowed, z);
    }
    let fscale = f[..k].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut best = (f64::INFINITY, 0usize);
    let total = 3usize.pow(z as u32);
    for releases in 0..=z {
        for code in 0..total {
            let mut c = code;
            let mut count = 0;
            let mut ok = true;
            for al in allowed.iter().take(z) {
                let d = c % 3;
                c /= 3;
                count += usize::from(d != 0);
                ok &= match d {
                    0 => al.stick,
                    1 => al.positive,
                    _ => al.negative,
                };
            }
            if !ok || count != releases {
                continue;
            }
            assign(modes, rest, z, code);
            rebuild(setup, modes);
            let bad = violation(setup, modes, f, rest, fscale);
            if bad == 0.0 {
                return;
            }
            if bad < best.0 {
                best = (bad, code);
            }
        }
    }
    assign(modes, rest, z, best.1);
    rebuild(setup, modes);
}

/// The regimes of the contacts of `rest` past the first `z` (those not enumerated), from the
/// solve with every contact of `rest` in stick: a contact that may stick and needs no more
/// friction than its cone holds (`|x_j| ≤ μ_j F_j`) sticks, any other slips against the
/// friction it would need (the direction its tangential velocity would take), or the way it
/// is allowed to. The enumeration of the first `z` then checks these contacts too.
fn tail(
    setup: &Setup,
    modes: &mut Modes,
    f: &[f64; MAXK],
    rest: &[usize],
    allowed: &[Allowed],
    z: usize,
) {
    for &j in rest {
        modes.tangent[j] = Tangent::Stick;
    }
    rebuild(setup, modes);
    let x = tangential_rates(setup, modes, f);
    for (&j, al) in rest.iter().zip(allowed).skip(z) {
        if al.stick && x[j].abs() <= setup.mu[j] * f[j] {
            continue;
        }
        let against = if x[j] > 0.0 { -1.0 } else { 1.0 };
        let sigma = match (al.positive, al.negative) {
            (true, false) => 1.0,
            (false, true) => -1.0,
            _ => against,
        };
        modes.tangent[j] = Tangent::Slip(sigma);
    }
}

/// Set the regimes of the first `z` contacts of `rest` from the base-3 digits of `code`
/// (0 stick, 1 slip+, 2 slip−).
fn assign(modes: &mut Modes, rest: &[usize], z: usize, mut code: usize) {
    for &j in &rest[..z] {
        modes.tangent[j] = match code % 3 {
            0 => Tangent::Stick,
            1 => Tangent::Slip(1.0),
            _ => Tangent::Slip(-1.0),
        };
        code /= 3;
    }
}

/// Rebuild the stick set from the active contacts in stick.
pub(super) fn rebuild(setup: &Setup, modes: &mut Modes) {
    let mut idx = [0usize; MAXK];
    let mut n = 0;
    for j in 0..setup.k {
        if modes.active(j) && modes.tangent[j] == Tangent::Stick {
            idx[n] = j;
            n += 1;
        }
    }
    let same = n == modes.stick.n && idx[..n] == modes.stick.idx[..n];
    if !same {
        modes.stick = stick_set(setup, &idx[..n]);
    }
}

/// How far the regimes of `rest` are from consistent, relative to the force scale (0 when
/// consistent): a sticking contact's friction beyond its cone, a slipping one's tangential
/// acceleration against its direction.
fn violation(setup: &Setup, modes: &Modes, f: &[f64; MAXK], rest: &[usize], fscale: f64) -> f64 {
    let pt = tangential_rates(setup, modes, f);
    let acc = tangential_acceleration(setup, f, &pt);
    // The round-off of an acceleration: |W| times the rates.
    let k = setup.k;
    let mut ascale = 0.0f64;
    for j in 0..k {
        let row = &setup.w[2 * j];
        let mut x = 0.0;
        for c in 0..k {
            x += (row[2 * c] * pt[c]).abs() + (row[2 * c + 1] * f[c]).abs();
        }
        ascale = ascale.max(x);
    }
    let mut bad = 0.0f64;
    for &j in rest {
        match modes.tangent[j] {
            Tangent::Stick => {
                let over = pt[j].abs() - setup.mu[j] * f[j];
                if over > 0.0 {
                    bad = bad.max(over / fscale.max(f64::MIN_POSITIVE) + 1e-300);
                }
            }
            Tangent::Slip(sigma) => {
                let against = -sigma * acc[j] - 1e-10 * ascale;
                if against > 0.0 {
                    bad = bad.max(against / ascale.max(f64::MIN_POSITIVE) + 1e-300);
                }
            }
        }
    }
    bad
}
