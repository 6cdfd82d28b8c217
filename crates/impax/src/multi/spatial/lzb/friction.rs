//! Coulomb's law at every contact with the circular cone: the stick set's solve, the
//! direction of a slip that leaves rest or halts, and the choice of the tangential regimes
//! where contacts are at rest.
//!
//! **Stick.** The sticking contacts `S` keep `v_t = 0`: their tangential impulse rates
//! (two per contact) solve `W_SS^tt x_S = −r_S` (`field.rs`) in the least-norm sense,
//! `x_S = −(W_SS^tt)⁺ r_S`, the pseudo-inverse of the `2|S| × 2|S|` block from its
//! eigenvalues (those within [`crate::multi::RANK_TOL`] of the largest zero, as the planar
//! law's Jacobi rotations do). Stick holds while `|x_j| ≤ μ_j F_j` up to the
//! round-off [`super::STICK_ROUND_OFF`] of the force scale (a symmetric body's contacts
//! separate a hair apart, their forces a hair from zero and unequal: round-off must not
//! break their stick there).
//!
//! **The slip field of a contact.** With every other contact's regime as it is, the rate of
//! change of contact `j`'s tangential velocity is affine in its slip direction `d`:
//! `a_j(d) = c_j − μ_j F_j M_j d`, with `M_j` the Schur complement of the stick set in `W`'s
//! tangential block (symmetric positive semidefinite); `c_j` and `M_j` are read off the
//! right-hand side itself (three evaluations; exact, the map being linear). This is the
//! one-contact field `w_tn − μ W_tt ŝ` of the spatial Darboux–Keller law with `w_tn → c_j/F_j`
//! and `W_tt → M_j`, so that
//!
//! * a slip that **leaves rest** does so along the unique centrifugal invariant ray,
//!   `(λ I + μ_j F_j M_j) d = c_j`, `λ > 0`
//!   ([`crate::spatial::resumption_direction`]'s secular equation; where a stick breaks the
//!   root is `λ ≈ 0`, and a hair below it the ray's limit `M⁻¹ c/(μ F)` is taken);
//!   several contacts leaving rest together have coupled rays (`a_j(d) = λ_j d_j` for
//!   each), found by Gauss–Seidel sweeps over the contacts, each solving its own ray given
//!   the others';
//! * a slip that **halts** ends on a centripetal invariant ray, `d × a_j(d) = 0`,
//!   `d·a_j(d) < 0`: the first one its direction turns towards.
//!
//! **Choice.** Where contacts with friction are at rest — at the start, when slips halt,
//! when a stick breaks, when a contact joins at rest — every assignment of `stick` and
//! `slip` to them is tried, most sticks first, the slipping ones along their rays, and the
//! first consistent one is taken: each sticking contact inside its cone (`|x_j| ≤ μ_j F_j`),
//! each slip leaving rest along its ray with `λ_j ≥ 0` (to round-off). A contact whose stick
//! just broke must slip. If no assignment is consistent (not observed), the least
//! inconsistent one is taken.

use super::field::{cone_excess, rate_scale, slip_rate, tangential_rates};
use super::state::{Modes, Setup, StickSet, Tangent, MAXK, ROWS};
use crate::math::{Mat2, Vec2};
use crate::multi::RANK_TOL;
use crate::spatial::invariant::{ray_at, rays_of, resumption_ray, InvariantRays, RayKind};
use nalgebra::{DMatrix, SymmetricEigen};
use std::f64::consts::TAU;

/// Gauss–Seidel sweeps for the rays of several contacts leaving rest together.
const SWEEPS: usize = 60;

/// The stick set of the contacts `idx` (increasing): `(W_SS^tt)⁺` from the block's
/// eigenvalues (those within [`RANK_TOL`] of the largest zero).
pub(super) fn stick_set(setup: &Setup, idx: &[usize]) -> StickSet {
    let n = idx.len();
    let mut set = StickSet::EMPTY;
    set.n = n;
    set.idx[..n].copy_from_slice(idx);
    if n == 0 {
        return set;
    }
    let m = 2 * n;
    let row = |p: usize| 3 * idx[p / 2] + p % 2;
    let a = DMatrix::from_fn(m, m, |p, q| setup.w[row(p)][row(q)]);
    let eig = SymmetricEigen::new(a);
    let dmax = eig.eigenvalues.iter().fold(0.0f64, |x, d| x.max(d.abs()));
    for (e, &d) in eig.eigenvalues.iter().enumerate() {
        if d > RANK_TOL * dmax {
            let col = eig.eigenvectors.column(e);
            for p in 0..m {
                for q in 0..m {
                    set.pinv[p][q] += col[p] * col[q] / d;
                }
            }
        }
    }
    set
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

/// The slip fields of the contacts `r` (module docs): `a_i(d) = c[i] + Σ_k b[i][k] d_k`
/// for `d_k` the fixed slip direction of `r[k]`, every other contact as in `modes`.
struct Affine {
    c: [Vec2; MAXK],
    b: [[Mat2; MAXK]; MAXK],
}

fn affine(setup: &Setup, modes: &Modes, f: &[f64; MAXK], v: &[f64; ROWS], r: &[usize]) -> Affine {
    let mut m = *modes;
    for &j in r {
        m.tangent[j] = Tangent::Fixed {
            dir: Vec2::zeros(),
            leaving: true,
        };
    }
    rebuild(setup, &mut m);
    let at = |m: &Modes| {
        let pt = tangential_rates(setup, m, f, v);
        let mut a = [Vec2::zeros(); MAXK];
        for (ai, &j) in a.iter_mut().zip(r) {
            *ai = slip_rate(setup, j, f, &pt);
        }
        a
    };
    let c = at(&m);
    let mut b = [[Mat2::zeros(); MAXK]; MAXK];
    for (kk, &k) in r.iter().enumerate() {
        for ax in 0..2 {
            let mut dir = Vec2::zeros();
            dir[ax] = 1.0;
            m.tangent[k] = Tangent::Fixed { dir, leaving: true };
            let a = at(&m);
            for i in 0..r.len() {
                b[i][kk].set_column(ax, &(a[i] - c[i]));
            }
        }
        m.tangent[k] = Tangent::Fixed {
            dir: Vec2::zeros(),
            leaving: true,
        };
    }
    Affine { c, b }
}

/// The unit direction `d` of a slip leaving rest in the field `c + b d`, `b = −μF M`:
/// `(λ I − b) d = c`, `λ > 0`; `muf = μ F`. `None` if there is none (the contact would
/// rather stick).
fn leave_alone(b: &Mat2, c: Vec2, muf: f64) -> Option<Vec2> {
    if muf > 0.0 {
        let m = (b + b.transpose()) * (-0.5 / muf);
        let w = c / muf;
        resumption_ray(&m, w, 1.0)
            .map(|(d, _)| d)
            .or_else(|| at_the_limit(&m, w))
    } else {
        let n = c.norm();
        (n > 0.0).then(|| c / n)
    }
}

/// A stick at its limit to round-off leaves along the ray's limit `λ → 0⁺`, `M⁻¹ w` (unit
/// to within [`LIMIT_BAND`]): where a stick breaks — located to the integration's tolerance,
/// a hair inside the cone or outside — the secular equation's root is `λ ≈ 0` and may fall
/// a hair below it, where [`resumption_ray`] finds none. `None` for a singular `M` or a
/// stick inside the band.
fn at_the_limit(m: &Mat2, w: Vec2) -> Option<Vec2> {
    let (s, n2) = ray_at(m, w, 1.0, 0.0)?;
    (n2.is_finite() && n2 > 0.0 && n2 >= 1.0 - LIMIT_BAND).then_some(s)
}

/// How far inside the cone (`1 − |M⁻¹ w|²`) a stick still counts as at its limit for
/// [`at_the_limit`]: a stick break located to the integration's tolerance (`1e-12`) is within
/// about `1e-10` of it.
const LIMIT_BAND: f64 = 1e-9;

/// The directions of the contacts `r` leaving rest together (module docs), `None` if
/// some contact has none or the sweeps do not settle.
fn leaving_directions(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    r: &[usize],
) -> Option<[Vec2; MAXK]> {
    let n = r.len();
    let af = affine(setup, modes, f, v, r);
    let mut d = [Vec2::zeros(); MAXK];
    for _ in 0..SWEEPS {
        let mut change = 0.0f64;
        for i in 0..n {
            let mut c = af.c[i];
            for (kk, dk) in d.iter().enumerate().take(n) {
                if kk != i {
                    c += af.b[i][kk] * dk;
                }
            }
            let di = leave_alone(&af.b[i][i], c, setup.mu[r[i]] * f[r[i]])?;
            change = change.max((di - d[i]).norm());
            d[i] = di;
        }
        if n == 1 || change <= 1e-14 {
            return Some(d);
        }
    }
    None
}

/// The direction a halting slip of contact `j` ends along: the centripetal invariant ray of
/// its slip field `c + B d` (every other contact as in `modes`; the one-contact law's rays,
/// [`crate::spatial::invariant_rays`], of the field with `w_tn → c`, `μ W_tt → −B`) within
/// `10⁻⁶` rad of its direction `s0` if there is one (the slip is on it to round-off: a
/// symmetric body's), else the one `s0` turns towards — the first root of
/// `f(φ) = ŝ × a(ŝ)` from `s0` in the sense of `f(s0)` — each polished by Newton's method on
/// the angle; `s0` itself where every direction is invariant; `None` if that root is not
/// centripetal.
pub(super) fn halting_ray(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    j: usize,
    s0: Vec2,
    hint: Option<f64>,
) -> Option<Vec2> {
    let af = affine(setup, modes, f, v, &[j]);
    let (c, b) = (af.c[0], af.b[0][0]);
    let m = (b + b.transpose()) * -0.5;
    let field = |s: Vec2| c - m * s;
    let cross = |s: Vec2| {
        let a = field(s);
        s.x * a.y - s.y * a.x
    };
    let phi0 = s0.y.atan2(s0.x);
    // The root next to the ray found last (it drifts a little between two looks), or next
    // to the direction if that is on a ray to 10⁻⁶: Newton's method alone.
    let next_to = hint.or((cross(s0).abs() <= 1e-6 * field(s0).norm()).then_some(phi0));
    if let Some(start) = next_to {
        let phi = polish(start, &field, &cross, &m);
        let s = Vec2::new(phi.cos(), phi.sin());
        let turned = (phi - start).sin().atan2((phi - start).cos()).abs();
        if turned <= 0.1 && cross(s).abs() <= 1e-12 * field(s).norm() && s.dot(&field(s)) < 0.0 {
            return Some(s);
        }
    }
    let rays = match rays_of(&m, c, 1.0) {
        InvariantRays::All => return Some(s0),
        InvariantRays::Rays { rays, len } => (rays, len),
    };
    let f0 = cross(s0);
    // (The angle either way and the angle ahead to the nearest ray, each with its angle.)
    let mut nearest: Option<(f64, f64)> = None;
    let mut best: Option<(f64, f64)> = None;
    for r in rays.0[..rays.1]
        .iter()
        .filter(|r| r.kind == RayKind::Centripetal)
    {
        // The angle from s0 to the ray either way, and in the sense the direction turns.
        let d = (r.angle - phi0).rem_euclid(TAU);
        let either = d.min(TAU - d);
        let ahead = if f0 >= 0.0 { d } else { TAU - d };
        if nearest.is_none_or(|(a, _)| either < a) {
            nearest = Some((either, r.angle));
        }
        if best.is_none_or(|(a, _)| ahead < a) {
            best = Some((ahead, r.angle));
        }
    }
    let start = match (nearest, best) {
        (Some((either, angle)), _) if either <= 1e-6 => angle,
        (_, Some((_, angle))) => angle,
        _ => return None,
    };
    let phi = polish(start, &field, &cross, &m);
    let s = Vec2::new(phi.cos(), phi.sin());
    (s.dot(&field(s)) < 0.0).then_some(s)
}

/// A root of `cross(φ) = ŝ × field(ŝ)` (`field(s) = c − M s`) from the angle `phi`, by at
/// most eight Newton steps.
fn polish(
    mut phi: f64,
    field: &impl Fn(Vec2) -> Vec2,
    cross: &impl Fn(Vec2) -> f64,
    m: &Mat2,
) -> f64 {
    for _ in 0..8 {
        let (sn, cs) = phi.sin_cos();
        let s = Vec2::new(cs, sn);
        let sp = Vec2::new(-sn, cs);
        let a = field(s);
        let ms = m * sp;
        let dg = sp.x * a.y - sp.y * a.x - (s.x * ms.y - s.y * ms.x);
        if dg == 0.0 || !dg.is_finite() {
            break;
        }
        let step = -cross(s) / dg;
        phi += step;
        if step.abs() <= 1e-16 {
            break;
        }
    }
    phi
}

/// What a contact at rest may do: stick (or else only slip).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Allowed {
    pub stick: bool,
}

impl Allowed {
    pub(super) const ANY: Allowed = Allowed { stick: true };
    pub(super) const SLIP: Allowed = Allowed { stick: false };
}

/// Choose the tangential regimes of the contacts `rest` (with friction, carrying or about to
/// carry a force, at rest), each restricted by `allowed`, given the effective normal forces
/// `f` (the forces, or at the start of the impact their limiting ratios) and the velocities
/// `v`. The other active contacts keep their regimes. Sets `modes.tangent` of `rest` and
/// rebuilds the stick set.
pub(super) fn choose(
    setup: &Setup,
    modes: &mut Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    rest: &[usize],
    allowed: &[Allowed],
) {
    let z = rest.len();
    let fscale = f[..setup.k].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut best = (f64::INFINITY, (1u32 << z) - 1);
    for releases in 0..=z as u32 {
        for code in 0..1u32 << z {
            if code.count_ones() != releases
                || (0..z).any(|i| code & (1 << i) == 0 && !allowed[i].stick)
            {
                continue;
            }
            if !assign(setup, modes, f, v, rest, code) {
                continue;
            }
            let bad = violation(setup, modes, f, v, rest, fscale);
            if bad == 0.0 {
                return;
            }
            if bad < best.0 {
                best = (bad, code);
            }
        }
    }
    if !assign(setup, modes, f, v, rest, best.1) {
        // (Not observed.) The slipping ones along their accelerations without friction.
        let slipping: Vec<usize> = (0..z)
            .filter(|i| best.1 & (1 << i) != 0)
            .map(|i| rest[i])
            .collect();
        let af = affine(setup, modes, f, v, &slipping);
        for (i, &j) in slipping.iter().enumerate() {
            let n = af.c[i].norm();
            let dir = if n > 0.0 {
                af.c[i] / n
            } else {
                Vec2::new(1.0, 0.0)
            };
            modes.tangent[j] = Tangent::Fixed { dir, leaving: true };
            modes.limit[j] = setup.near;
        }
    }
}

/// Set the regimes of the contacts `rest` from the bits of `code` (0 stick, 1 slip leaving
/// rest along its ray); `false` if the rays are not found.
fn assign(
    setup: &Setup,
    modes: &mut Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    rest: &[usize],
    code: u32,
) -> bool {
    let mut slipping = [0usize; MAXK];
    let mut n = 0;
    for (i, &j) in rest.iter().enumerate() {
        modes.tangent[j] = if code & (1 << i) == 0 {
            Tangent::Stick
        } else {
            slipping[n] = j;
            n += 1;
            Tangent::Fixed {
                dir: Vec2::zeros(),
                leaving: true,
            }
        };
    }
    rebuild(setup, modes);
    if n == 0 {
        return true;
    }
    let Some(d) = leaving_directions(setup, modes, f, v, &slipping[..n]) else {
        return false;
    };
    for (&j, dir) in slipping[..n].iter().zip(d) {
        modes.tangent[j] = Tangent::Fixed { dir, leaving: true };
        modes.limit[j] = setup.near;
    }
    true
}

/// How far the regimes of `rest` are from consistent, relative to the force scale (0 when
/// consistent): a sticking contact's friction beyond its cone, a slip leaving rest off its
/// acceleration or against it.
fn violation(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
    v: &[f64; ROWS],
    rest: &[usize],
    fscale: f64,
) -> f64 {
    let pt = tangential_rates(setup, modes, f, v);
    let mut bad = 0.0f64;
    for &j in rest {
        match modes.tangent[j] {
            Tangent::Stick => {
                let over = cone_excess(setup, j, &pt, f);
                if over > 0.0 {
                    bad = bad.max(over / fscale.max(f64::MIN_POSITIVE) + 1e-300);
                }
            }
            Tangent::Fixed { dir, .. } => {
                let a = slip_rate(setup, j, f, &pt);
                let scale = rate_scale(setup, j, f, &pt).max(f64::MIN_POSITIVE);
                let against = -dir.dot(&a) - 1e-10 * scale;
                let off = (dir.x * a.y - dir.y * a.x).abs() - 1e-8 * scale;
                let worst = against.max(off);
                if worst > 0.0 {
                    bad = bad.max(worst / scale + 1e-300);
                }
            }
            Tangent::Slip => {}
        }
    }
    bad
}
