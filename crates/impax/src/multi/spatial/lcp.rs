//! `lcp` in 3D with `K` contacts: the velocity-level complementarity impact at every contact
//! at once with the exact circular friction cone (no polyhedral approximation).
//!
//! The conditions are the planar law's ([`crate::multi::lcp`]; Anitescu & Potra 1997,
//! Stewart & Trinkle 1996) with each tangential velocity a 2-vector and the cone circular
//! (the one-contact spatial law is [`crate::spatial::laws::lcp`]): with Newton's target
//! `b_j = max(−e_j v_nj⁻, 0)`,
//!
//! ```text
//! 0 ≤ p_nj ⊥ v_nj⁺ − b_j ≥ 0,     |p_tj| ≤ μ_j p_nj,
//! v_tj⁺ = 0 (stick)   or   p_tj = −μ_j p_nj v_tj⁺/|v_tj⁺| (slip: maximal dissipation).
//! ```
//!
//! **Enumeration of the contacts' modes** — off, stick, slip (frictionless: off, or an impulse
//! along the normal) — `3^K` combinations, [`MAX_CONTACTS`] `= 4` (81). Off and stick give
//! linear equations; a slip contact along the direction `ŝ_j = (cos θ_j, sin θ_j)` has the
//! impulse `p_nj (−μ_j ŝ_j, 1)` and the equations `v_nj⁺ = b_j` and
//!
//! ```text
//! r_j(θ) = ŝ_j × v_tj⁺ = 0,   with  σ_j = ŝ_j · v_tj⁺ ≥ 0,
//! ```
//!
//! so for given slip angles the impulses solve a linear system (least-norm, for a singular
//! `W`: a box lying on four corners), and the angles of the slip contacts are the roots of
//! `r(θ)` — found by Newton's method (Jacobian by differences, step halving) from several
//! starts per combination: each slip contact's direction before the impact and its opposite
//! (all combinations), the directions its slip would take if it were frictionless, and with
//! one slip contact twelve more angles round the circle; when no combination yields a solution,
//! a second pass adds a sweep of each slip angle in turn and a grid of directions (36, 64 or 81
//! starts for 2, 3 or 4 slip contacts: Newton's method from the quick starts can converge in
//! one order of the contacts and not in another). Each root found is then checked
//! against **every** condition (impulse signs and cones, `v_n⁺ = b`, stick `v_t⁺ = 0`, slip
//! `r = 0` and `σ ≥ 0`, off `v_n⁺ ≥ b`) to [`VELOCITY_ROUND_OFF`] of the velocity scale
//! and reported as the conditions give it (`v_nj⁺ = b_j`, stick `v_tj⁺ = 0`, slip
//! `v_tj⁺ = σ_j ŝ_j`, `p_tj = −μ_j p_nj ŝ_j`); the roots themselves meet `r = 0` to
//! round-off (about `1e-15` of the velocity scale; where Newton's steps stall on the round-off
//! of ill-conditioned equations, within `1e-11` of it).
//!
//! Solutions whose velocities after agree to `1e-8` of the scale are merged (the smaller
//! impulse kept); the result is the solution of least kinetic energy after, every solution
//! found in the detail, [`Inconsistency::MultipleSolutions`] when there are several. Unlike
//! the planar enumeration, the search for the slip angles is not proven exhaustive: a
//! solution is never reported that does not satisfy the conditions, but with several slip
//! contacts a further solution could be missed; if none is found the law breaks down with
//! `no-solution`.
//!
//! With one contact this agrees with [`crate::spatial::laws::lcp`] (tested).

use super::outcome::{assemble, ContactPhase, ContactPhaseKind, ContactResult, LcpSolution};
use super::outcome::{velocity_scale, MultiDetail};
use super::{MultiProblem, MultiResolution};
use crate::law::{Breakdown, BreakdownReason, Inconsistency, LawId, WorkSplit};
use crate::math::Vec3;
use crate::multi::VELOCITY_ROUND_OFF;
use crate::spatial::PhaseKind;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::{PI, TAU};

/// The most contacts `lcp` enumerates in 3D (`3^4 = 81` combinations of modes).
pub const MAX_CONTACTS: usize = 4;

/// Singular values below this fraction of the largest are zero (rank deficiency).
const PIVOT_TOL: f64 = 1e-11;

/// Two solutions whose velocities after differ by less than this fraction of the velocity
/// scale are the same solution.
const SAME: f64 = 1e-8;

/// Newton's iterations on the slip angles of one start.
const NEWTON_STEPS: usize = 60;

/// The slip residual, relative to the velocity scale, at which Newton's method stops
/// improving and its angles are taken as a root: the round-off of the linear solves, which
/// grows with the condition of the contacts' equations (residuals of 1e-13 to 2e-13 are met on
/// random four-contact problems, and one contact order reached 1e-13 where another did not).
/// Every condition is then checked to [`VELOCITY_ROUND_OFF`].
const STALLED_ROOT: f64 = 1e-11;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Off,
    Stick,
    Slip,
    /// Frictionless contact with an impulse: `p_t = 0`.
    Free,
}

/// The problem in the canonical units.
struct Setup<'a> {
    k: usize,
    w: &'a DMatrix<f64>,
    v: &'a DVector<f64>,
    b: Vec<f64>,
    mu: Vec<f64>,
}

/// The linear solve of one combination of modes at given slip angles.
struct Solved {
    p: DVector<f64>,
    v: DVector<f64>,
}

/// A solution found, in the canonical units.
#[derive(Debug, Clone)]
struct Candidate {
    modes: Vec<Mode>,
    theta: Vec<f64>,
    p: DVector<f64>,
    v: DVector<f64>,
    vscale: f64,
    norm: f64,
}

/// `lcp` on `K` spatial contacts: the solution of least kinetic energy after, every solution
/// found in the detail. Breakdowns: [`BreakdownReason::TooManyContacts`],
/// [`BreakdownReason::NoSolution`], [`BreakdownReason::Overflow`].
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lcp;
    let k = problem.contacts();
    crate::multi::within(law, k, MAX_CONTACTS)?;
    let (_, w, v) = problem.canonical();
    let s = Setup {
        k,
        w,
        v,
        b: (0..k)
            .map(|j| (-problem.restitution(j) * v[3 * j + 2]).max(0.0))
            .collect(),
        mu: (0..k).map(|j| problem.friction(j)).collect(),
    };
    let mut found = enumerate(&s, false);
    if found.is_empty() {
        found = enumerate(&s, true);
    }
    if found.is_empty() {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::NoSolution,
        });
    }
    let mut all: Vec<LcpSolution> = found.iter().map(|c| tidy(&s, c)).collect();
    all.sort_by(|a, b| a.energy_change.total_cmp(&b.energy_change));
    let best = all[0].clone();
    let contacts: Vec<ContactResult> = (0..k)
        .map(|j| {
            let (p, va) = (best.impulses[j], best.velocities_after[j]);
            let vb = Vec3::new(v[3 * j], v[3 * j + 1], v[3 * j + 2]);
            ContactResult {
                impulse: p,
                velocity_after: va,
                phases: vec![ContactPhase {
                    kind: best.regimes[j],
                    ends_at: p.z,
                }],
                work: straight_work(vb, va, p),
            }
        })
        .collect();
    let inconsistency =
        (all.len() > 1).then_some(Inconsistency::MultipleSolutions { count: all.len() });
    let out = assemble(
        problem,
        law,
        contacts,
        MultiDetail::Lcp { solutions: all },
        inconsistency,
    );
    let finite = out.is_finite();
    crate::multi::finite_or_overflow(law, out, finite)
}

/// The work of one contact along the straight path `s p`, `0 ≤ s ≤ 1` (as the planar law).
fn straight_work(before: Vec3, after: Vec3, p: Vec3) -> WorkSplit {
    let normal = 0.5 * p.z * (before.z + after.z);
    let compression = if before.z >= 0.0 || p.z == 0.0 {
        0.0
    } else if after.z >= 0.0 {
        let sc = -before.z / (after.z - before.z);
        0.5 * p.z * sc * before.z
    } else {
        normal
    };
    WorkSplit {
        compression,
        restitution: normal - compression,
        friction: 0.5 * (p.x * (before.x + after.x) + p.y * (before.y + after.y)),
    }
}

/// Every combination of modes, each solved; the distinct solutions in enumeration order.
/// `thorough`: also start the slip angles from a sweep over the slip contacts in turn
/// ([`sweep`]), when the quick starts found nothing.
fn enumerate(s: &Setup, thorough: bool) -> Vec<Candidate> {
    let k = s.k;
    let choices = |j: usize| -> &'static [Mode] {
        if s.mu[j] > 0.0 {
            &[Mode::Off, Mode::Stick, Mode::Slip]
        } else {
            &[Mode::Off, Mode::Free]
        }
    };
    let mut digits = vec![0usize; k];
    let mut found: Vec<Candidate> = Vec::new();
    loop {
        let modes: Vec<Mode> = (0..k).map(|j| choices(j)[digits[j]]).collect();
        if modes.iter().any(|m| *m != Mode::Off) {
            for c in solve_mode(s, &modes, thorough) {
                merge(&mut found, c);
            }
        }
        let mut j = 0;
        loop {
            if j == k {
                return found;
            }
            digits[j] += 1;
            if digits[j] < choices(j).len() {
                break;
            }
            digits[j] = 0;
            j += 1;
        }
    }
}

/// Keep `c` unless a solution with the same velocities is known (then the smaller impulse).
fn merge(found: &mut Vec<Candidate>, c: Candidate) {
    for e in found.iter_mut() {
        let tol = SAME * e.vscale.max(c.vscale);
        if (&e.v - &c.v).amax() <= tol {
            if c.norm < e.norm * (1.0 - SAME) {
                *e = c;
            }
            return;
        }
    }
    found.push(c);
}

/// The impulses and velocities of `modes` with the slip contacts at the angles `theta` (one
/// per contact; read for slip contacts only): the least-norm solution of the equations.
fn linear(s: &Setup, modes: &[Mode], theta: &[f64]) -> Solved {
    let k = s.k;
    let n = 3 * k;
    // Columns: the impulse directions of the unknowns; rows: the equations.
    let mut cols: Vec<DVector<f64>> = Vec::new();
    let mut rows: Vec<(usize, f64)> = Vec::new();
    for j in 0..k {
        match modes[j] {
            Mode::Off => {}
            Mode::Stick => {
                for c in 0..3 {
                    let mut d = DVector::zeros(n);
                    d[3 * j + c] = 1.0;
                    cols.push(d);
                }
                rows.extend([(3 * j, 0.0), (3 * j + 1, 0.0), (3 * j + 2, s.b[j])]);
            }
            Mode::Slip | Mode::Free => {
                let mu = if modes[j] == Mode::Slip { s.mu[j] } else { 0.0 };
                let (sn, cs) = theta[j].sin_cos();
                let h = 1f64.hypot(mu);
                let mut d = DVector::zeros(n);
                d[3 * j] = -mu * cs / h;
                d[3 * j + 1] = -mu * sn / h;
                d[3 * j + 2] = 1.0 / h;
                cols.push(d);
                rows.push((3 * j + 2, s.b[j]));
            }
        }
    }
    let m = cols.len();
    let a = DMatrix::from_fn(rows.len(), m, |r, c| {
        let i = rows[r].0;
        (0..n).map(|q| s.w[(i, q)] * cols[c][q]).sum::<f64>()
    });
    let r = DVector::from_fn(rows.len(), |r, _| rows[r].1 - s.v[rows[r].0]);
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    let y = svd
        .solve(&r, PIVOT_TOL * smax.max(f64::MIN_POSITIVE))
        .unwrap_or_else(|_| DVector::zeros(m));
    let mut p = DVector::zeros(n);
    for (c, d) in cols.iter().enumerate() {
        p += d * y[c];
    }
    let v = s.v + s.w * &p;
    Solved { p, v }
}

/// The slip residuals `ŝ_j × v_tj⁺` of the slip contacts, in order.
fn residual(s: &Setup, modes: &[Mode], theta: &[f64], sol: &Solved) -> Vec<f64> {
    (0..s.k)
        .filter(|&j| modes[j] == Mode::Slip)
        .map(|j| {
            let (sn, cs) = theta[j].sin_cos();
            cs * sol.v[3 * j + 1] - sn * sol.v[3 * j]
        })
        .collect()
}

/// The solutions of one combination of modes (several starts for the slip angles).
fn solve_mode(s: &Setup, modes: &[Mode], thorough: bool) -> Vec<Candidate> {
    let k = s.k;
    let slips: Vec<usize> = (0..k).filter(|&j| modes[j] == Mode::Slip).collect();
    let angle_of = |v: &DVector<f64>, j: usize| {
        let (x, y) = (v[3 * j], v[3 * j + 1]);
        if x == 0.0 && y == 0.0 {
            0.0
        } else {
            y.atan2(x)
        }
    };
    if slips.is_empty() {
        return check(s, modes, &vec![0.0; k]).into_iter().collect();
    }
    let mut starts: Vec<Vec<f64>> = Vec::new();
    let before: Vec<f64> = (0..k).map(|j| angle_of(s.v, j)).collect();
    for mask in 0..(1usize << slips.len()) {
        let mut t = before.clone();
        for (bit, &j) in slips.iter().enumerate() {
            if mask & (1 << bit) != 0 {
                t[j] += PI;
            }
        }
        starts.push(t);
    }
    // The directions the slips would take without friction at the slip contacts.
    let free: Vec<Mode> = modes
        .iter()
        .map(|m| if *m == Mode::Slip { Mode::Free } else { *m })
        .collect();
    let sol = linear(s, &free, &before);
    starts.push((0..k).map(|j| angle_of(&sol.v, j)).collect());
    // Each slip contact's direction if it were alone (its own block, its own velocity).
    let mut alone = before.clone();
    for &j in &slips {
        let block = impax_block(s, j);
        let vj = Vec3::new(s.v[3 * j], s.v[3 * j + 1], s.v[3 * j + 2]);
        if let Ok(one) = crate::spatial::ContactProblem::new(block, vj, s.mu[j], 0.0) {
            for sol in crate::spatial::laws::lcp::solutions(&one) {
                if let PhaseKind::Slip { to, .. } = sol.kind {
                    alone[j] = to;
                    break;
                }
            }
        }
    }
    starts.push(alone);
    if thorough {
        starts.push(sweep(s, modes, &slips, before.clone()));
        if slips.len() > 1 {
            // A grid of directions round the circle at every slip contact (6, 4 or 3 a
            // contact for 2, 3 or 4 slip contacts: 36, 64 or 81 starts).
            let g = [6usize, 6, 6, 4, 3][slips.len()];
            for index in 0..g.pow(slips.len() as u32) {
                let mut t = before.clone();
                let mut rest = index;
                for &j in &slips {
                    t[j] = before[j] + TAU * (rest % g) as f64 / g as f64 + PI / g as f64;
                    rest /= g;
                }
                starts.push(t);
            }
        }
    }
    if slips.len() == 1 {
        for i in 0..12 {
            let mut t = before.clone();
            t[slips[0]] = TAU * (i as f64 + 0.5) / 12.0;
            starts.push(t);
        }
    }
    let mut out: Vec<Candidate> = Vec::new();
    for start in starts {
        if let Some(theta) = newton(s, modes, &slips, start) {
            if let Some(c) = check(s, modes, &theta) {
                merge(&mut out, c);
            }
        }
    }
    out
}

/// Contact `j`'s own block of `W`.
fn impax_block(s: &Setup, j: usize) -> crate::math::Mat3 {
    crate::math::Mat3::from_fn(|r, c| s.w[(3 * j + r, 3 * j + c)])
}

/// Slip angles from sweeps over the slip contacts in turn: each angle set to the root of its
/// own residual (the others held) nearest to its current value, found by sampling the
/// circle and bisecting the sign changes where the slip is consistent (`σ > 0`).
fn sweep(s: &Setup, modes: &[Mode], slips: &[usize], mut theta: Vec<f64>) -> Vec<f64> {
    const SAMPLES: usize = 24;
    let at = |theta: &[f64], j: usize, t: f64| {
        let mut th = theta.to_vec();
        th[j] = t;
        let sol = linear(s, modes, &th);
        let (sn, cs) = t.sin_cos();
        let (vt1, vt2) = (sol.v[3 * j], sol.v[3 * j + 1]);
        (cs * vt2 - sn * vt1, cs * vt1 + sn * vt2)
    };
    for _ in 0..8 {
        let mut moved = 0.0f64;
        for &j in slips {
            let grid: Vec<f64> = (0..=SAMPLES)
                .map(|i| theta[j] - PI + TAU * i as f64 / SAMPLES as f64)
                .collect();
            let values: Vec<(f64, f64)> = grid.iter().map(|&t| at(&theta, j, t)).collect();
            let mut best: Option<f64> = None;
            for i in 0..SAMPLES {
                let (r0, r1) = (values[i].0, values[i + 1].0);
                if r0 == 0.0 || r0.signum() != r1.signum() {
                    let (mut lo, mut hi, mut rlo) = (grid[i], grid[i + 1], r0);
                    for _ in 0..50 {
                        let mid = 0.5 * (lo + hi);
                        let (rm, _) = at(&theta, j, mid);
                        if rm.signum() == rlo.signum() && rm != 0.0 {
                            lo = mid;
                            rlo = rm;
                        } else {
                            hi = mid;
                        }
                    }
                    let root = 0.5 * (lo + hi);
                    if at(&theta, j, root).1 > 0.0
                        && best.is_none_or(|b| (root - theta[j]).abs() < (b - theta[j]).abs())
                    {
                        best = Some(root);
                    }
                }
            }
            if let Some(root) = best {
                moved = moved.max((root - theta[j]).abs());
                theta[j] = root;
            }
        }
        if moved < 1e-13 {
            break;
        }
    }
    theta
}

/// Newton's method on the slip angles from `theta`; the angles if the residual falls to
/// round-off.
fn newton(s: &Setup, modes: &[Mode], slips: &[usize], mut theta: Vec<f64>) -> Option<Vec<f64>> {
    let m = slips.len();
    let norm = |r: &[f64]| r.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let mut sol = linear(s, modes, &theta);
    let mut r = residual(s, modes, &theta, &sol);
    for _ in 0..NEWTON_STEPS {
        let scale = velocity_scale(s.w, s.v, &sol.p);
        if norm(&r) <= 4.0 * f64::EPSILON * scale {
            return Some(theta);
        }
        let h = 1e-7;
        let mut jac = DMatrix::zeros(m, m);
        for (c, &j) in slips.iter().enumerate() {
            let mut t = theta.clone();
            t[j] += h;
            let rt = residual(s, modes, &t, &linear(s, modes, &t));
            for row in 0..m {
                jac[(row, c)] = (rt[row] - r[row]) / h;
            }
        }
        let step = jac
            .svd(true, true)
            .solve(&DVector::from_iterator(m, r.iter().map(|x| -x)), 1e-14)
            .ok()?;
        let mut lambda = 1.0;
        let mut improved = false;
        for _ in 0..12 {
            let mut t = theta.clone();
            for (c, &j) in slips.iter().enumerate() {
                t[j] += lambda * step[c].clamp(-1.0, 1.0);
            }
            let st = linear(s, modes, &t);
            let rt = residual(s, modes, &t, &st);
            if norm(&rt) < norm(&r) {
                theta = t;
                sol = st;
                r = rt;
                improved = true;
                break;
            }
            lambda *= 0.5;
        }
        if !improved {
            let scale = velocity_scale(s.w, s.v, &sol.p);
            return (norm(&r) <= STALLED_ROOT * scale).then_some(theta);
        }
    }
    let scale = velocity_scale(s.w, s.v, &sol.p);
    (norm(&r) <= STALLED_ROOT * scale).then_some(theta)
}

/// Solve `modes` at `theta` and check every condition; the candidate if they all hold.
fn check(s: &Setup, modes: &[Mode], theta: &[f64]) -> Option<Candidate> {
    let k = s.k;
    let sol = linear(s, modes, theta);
    let (p, v) = (&sol.p, &sol.v);
    let pscale = p.amax().max(f64::MIN_POSITIVE);
    let vscale = velocity_scale(s.w, s.v, p);
    let (tp, tv) = (VELOCITY_ROUND_OFF * pscale, VELOCITY_ROUND_OFF * vscale);
    for j in 0..k {
        let (pt, pn) = ((p[3 * j]).hypot(p[3 * j + 1]), p[3 * j + 2]);
        let (vt1, vt2, vn) = (v[3 * j], v[3 * j + 1], v[3 * j + 2]);
        let ok = match modes[j] {
            Mode::Off => vn >= s.b[j] - tv,
            // (The cone conditions as distances from the cone: a slip impulse is
            // `p_n (−μ d, 1)`, reversed when `p_n < 0` however large `μ` is.)
            Mode::Stick => {
                pn >= -tp
                    && (pt - s.mu[j] * pn) / 1f64.hypot(s.mu[j]) <= tp
                    && vt1.abs() <= tv
                    && vt2.abs() <= tv
                    && (vn - s.b[j]).abs() <= tv
            }
            Mode::Slip => {
                let (sn, cs) = theta[j].sin_cos();
                pn * 1f64.hypot(s.mu[j]) >= -tp
                    && (vn - s.b[j]).abs() <= tv
                    && cs * vt1 + sn * vt2 >= -tv
                    && (cs * vt2 - sn * vt1).abs() <= tv
            }
            Mode::Free => pn >= -tp && (vn - s.b[j]).abs() <= tv,
        };
        if !ok {
            return None;
        }
    }
    Some(Candidate {
        modes: modes.to_vec(),
        theta: theta.to_vec(),
        norm: p.norm(),
        p: sol.p,
        v: sol.v,
        vscale,
    })
}

/// The solution as reported: impulses inside their cones, velocities as the conditions give
/// them, `ΔT`.
fn tidy(s: &Setup, c: &Candidate) -> LcpSolution {
    let k = s.k;
    let mut regimes = Vec::with_capacity(k);
    let mut impulses = Vec::with_capacity(k);
    let mut velocities = Vec::with_capacity(k);
    let mut energy = 0.0;
    for j in 0..k {
        let mu = s.mu[j];
        let vb = Vec3::new(s.v[3 * j], s.v[3 * j + 1], s.v[3 * j + 2]);
        let pn = c.p[3 * j + 2].max(0.0);
        let (regime, p, va) = match c.modes[j] {
            Mode::Off => (
                ContactPhaseKind::Off,
                Vec3::zeros(),
                Vec3::new(c.v[3 * j], c.v[3 * j + 1], c.v[3 * j + 2]),
            ),
            Mode::Stick => {
                let (mut pt1, mut pt2) = (c.p[3 * j], c.p[3 * j + 1]);
                let pt = pt1.hypot(pt2);
                if pt > mu * pn {
                    let f = mu * pn / pt;
                    pt1 *= f;
                    pt2 *= f;
                }
                (
                    ContactPhaseKind::Impact(PhaseKind::Stick),
                    Vec3::new(pt1, pt2, pn),
                    Vec3::new(0.0, 0.0, s.b[j]),
                )
            }
            Mode::Slip => {
                let (sn, cs) = c.theta[j].sin_cos();
                let sigma = (cs * c.v[3 * j] + sn * c.v[3 * j + 1]).max(0.0);
                let angle = sn.atan2(cs);
                (
                    ContactPhaseKind::Impact(PhaseKind::Slip {
                        from: angle,
                        to: angle,
                    }),
                    Vec3::new(-mu * pn * cs, -mu * pn * sn, pn),
                    Vec3::new(sigma * cs, sigma * sn, s.b[j]),
                )
            }
            Mode::Free => {
                let (vt1, vt2) = (c.v[3 * j], c.v[3 * j + 1]);
                let kind = if vt1 == 0.0 && vt2 == 0.0 {
                    PhaseKind::NoSlip
                } else {
                    let a = vt2.atan2(vt1);
                    PhaseKind::Slip { from: a, to: a }
                };
                (
                    ContactPhaseKind::Impact(kind),
                    Vec3::new(0.0, 0.0, pn),
                    Vec3::new(vt1, vt2, s.b[j]),
                )
            }
        };
        energy += 0.5 * (vb + va).dot(&p);
        regimes.push(regime);
        impulses.push(p);
        velocities.push(va);
    }
    LcpSolution {
        regimes,
        impulses,
        velocities_after: velocities,
        energy_change: energy,
    }
}
