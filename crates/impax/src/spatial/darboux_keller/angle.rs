//! The slip stage in the angle variable (theory §2, "Spatial"): the direction equation solved
//! by a change of variable, everything else a quadrature on Chebyshev panels.
//!
//! During slip `dφ/dp_n = f(φ)/σ` keeps the sign of `f = ŝ × g` (`g = w_tn − μ W_tt ŝ`), so
//! the direction turns monotonically from the invariant ray behind it toward the one ahead
//! (the roots of `f`, which has zero mean over the circle and so at least two) and reaches
//! neither at a finite impulse unless the slip halts there. With `θ` the angle turned in the
//! sense of `f`, `δ_b = θ − θ_b` and `δ_a = θ_a − θ` the distances to the two rays and
//! `D = δ_a + δ_b < 2π`, the variable
//!
//! ```text
//! x = ln(sin(δ_b/2)/sin(δ_a/2)),   dθ/dx = 2 sin(δ_a/2) sin(δ_b/2)/sin(D/2),
//! ρ = (dθ/dx)/|f|,
//! du/dx = q ρ,  dp_n/dx = σ ρ,  dp_t/dx = −μ ŝ σ ρ,  dv_n/dx = (w_nn − μ w_tn·ŝ) σ ρ,
//! dW_t/dx = −μ σ² ρ,  dW_n/dx = v_n σ ρ
//! ```
//!
//! (`u = ln σ`, `q = ŝ·g`) maps the sector onto the whole real line. It is rational in
//! `e^x`: the half-angle vector `h = e_b' + e^x e_a'` (`e'` the unit vectors at half the
//! rays' angles) points at `θ/2`, so `ŝ = (h_x² − h_y², 2 h_x h_y)/|h|²` and
//! `dθ/dx = 2 e^x sin(D/2)/|h|²` (`e^{−x}` and `h e^{−x}` for `x > 0`): no sine or cosine,
//! and nine exponentials for a panel's seventeen nodes (they are symmetric about its
//! middle). Near either ray `|f| ≈ |f'| δ`, so `ρ` stays bounded and
//! `σ ∝ e^{κ x}`: every integrand is smooth on the scale of one unit of `x` — a swing of
//! the direction through a near-zero pass, the approach to a halt, a slip leaving a ray or
//! growing along one, a nearly frozen slip alike. The only nonlinear equation (the
//! direction's) is solved by the map itself; `u`, then `p_n`, `v_n`, `p_t`, `W_t` and `W_n`
//! are integrals on 17-node Chebyshev–Lobatto panels ([`crate::numerics::chebyshev`]), whose
//! length follows the size of the last Chebyshev coefficients of the integrands; the
//! cumulative ones (at every node) only where an event can read them. Events are located on
//! the panel's interpolants. The two rays are found by scans outward from the slip's
//! direction ([`Sector`]).
//!
//! Near a ray `r`, `f` is evaluated from its expansion about the ray with `f(r) = 0` imposed
//! (a change of the data by the round-off of the root, ~1e-16):
//!
//! ```text
//! f(r + ε) = sin ε [Q + 2 S cos ε − R sin ε (2 cos ε + 1)/(1 + cos ε)],
//! Q = B cos r − A sin r,  R = C cos 2r + D sin 2r,  S = D cos 2r − C sin 2r,
//! ```
//!
//! so `ρ` keeps full relative accuracy however close the direction gets to the ray.

// Tests of the form `!(x > 0.0)` are meant: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{
    after_event, event_value, first_event, linear_piece, norm_of, poisson_ends_first, series_tail,
    Events, Linear, Point, Scales, SlipEnd, TailSeries, Termination,
};
use crate::law::BreakdownReason;
use crate::math::{Mat2, Vec2, Vec3};
use crate::numerics::chebyshev::{dot, lobatto, M, N};
use crate::numerics::roots::{newton_crossing, newton_in_bracket};
use crate::spatial::outcome::Phase3Kind;
use crate::spatial::ray_series::Field;
use std::f64::consts::TAU;

/// The two invariant rays around a direction `φ0` that is on none: the nearest roots of `f`
/// below and above it (`below < φ0 < above`, unwrapped), found by scans outward from `φ0`
/// that cannot miss a root (a bound on `|f''|` excludes roots between samples of `f` and
/// `f'`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Sector {
    pub below: f64,
    pub above: f64,
}

/// The roots found by one scan.
#[derive(Debug, Clone, Copy)]
struct Roots {
    phi: [f64; 4],
    len: usize,
    /// Subdivisions left to the scan.
    budget: u32,
}

/// Samples of the scan per turn.
const GRID: usize = 32;

/// `f` and `f'` at the direction `(c, s)` (double angles by the product formulas).
#[inline]
fn f_df_at((a, b, cc, d): (f64, f64, f64, f64), c: f64, s: f64) -> (f64, f64) {
    let (c2, s2) = (c * c - s * s, 2.0 * c * s);
    (
        a * c + b * s + cc * c2 + d * s2,
        -a * s + b * c - 2.0 * cc * s2 + 2.0 * d * c2,
    )
}

impl Sector {
    /// The sector of `phi0`, or `None` if `f ≡ 0` (every direction invariant), `f(φ0) = 0`
    /// or a near-tangency of two roots is not resolved.
    pub(super) fn find(field: &Field, phi0: f64) -> Option<Sector> {
        let (a, b, c, d) = field.f_coefficients();
        let scale = a.abs() + b.abs() + c.abs() + d.abs();
        if !(scale > 0.0) || !scale.is_finite() {
            return None;
        }
        // f scaled to unit size (no underflow in the tests below).
        let k = (a / scale, b / scale, c / scale, d / scale);
        let (a, b, c, d) = k;
        // |f''| ≤ |A| + |B| + 4 (|C| + |D|).
        let bound = a.abs() + b.abs() + 4.0 * (c.abs() + d.abs());
        let (s0, c0) = phi0.sin_cos();
        let (f0, df0) = f_df_at(k, c0, s0);
        if f0 == 0.0 {
            return None;
        }
        let start = (phi0, f0, df0);
        Some(Sector {
            below: Self::nearest(k, bound, start, (c0, s0), -1.0)?,
            above: Self::nearest(k, bound, start, (c0, s0), 1.0)?,
        })
    }

    /// The nearest root from `start` in the sense `dir`, sampling every `2π/GRID` (the
    /// samples by rotation, the subdivisions by `sin_cos`).
    fn nearest(
        k: (f64, f64, f64, f64),
        bound: f64,
        start: (f64, f64, f64),
        (mut c, mut s): (f64, f64),
        dir: f64,
    ) -> Option<f64> {
        let h = TAU / GRID as f64;
        let (sh, ch) = (dir * h).sin_cos();
        let mut roots = Roots {
            phi: [0.0; 4],
            len: 0,
            budget: 64,
        };
        let mut prev = start;
        for j in 1..=GRID {
            (c, s) = (c * ch - s * sh, s * ch + c * sh);
            let (fx, dfx) = f_df_at(k, c, s);
            let next = (start.0 + dir * j as f64 * h, fx, dfx);
            if dir > 0.0 {
                roots.scan(k, prev, next, bound, 1.0, 0);
            } else {
                roots.scan(k, next, prev, bound, 1.0, 0);
            }
            if roots.budget == 0 {
                // An unresolved near-tangency: the sector is not known for certain.
                return None;
            }
            if roots.len > 0 {
                let found = roots.phi[..roots.len].iter();
                return Some(if dir > 0.0 {
                    found.fold(f64::INFINITY, |m, &r| m.min(r))
                } else {
                    found.fold(f64::NEG_INFINITY, |m, &r| m.max(r))
                });
            }
            prev = next;
        }
        None
    }
}

impl Roots {
    fn push(&mut self, phi: f64) {
        let dup = self.phi[..self.len]
            .iter()
            .any(|&r| (r - phi).abs() < 1e-12);
        if !dup && self.len < 4 {
            self.phi[self.len] = phi;
            self.len += 1;
        }
    }

    /// Roots in `[a, b)` given `(φ, f, f')` at both ends.
    fn scan(
        &mut self,
        k: (f64, f64, f64, f64),
        (xa, fa, da): (f64, f64, f64),
        (xb, fb, db): (f64, f64, f64),
        bound: f64,
        scale: f64,
        depth: u32,
    ) {
        if fa == 0.0 {
            self.push(xa);
            return;
        }
        if fb != 0.0 && (fa < 0.0) != (fb < 0.0) {
            self.push(polish(k, (xa, fa, da), (xb, fb, db)));
            return;
        }
        // Same sign at both ends: f stays away from zero within r_a of a and r_b of b
        // (f(a + t) ≥ |f_a| ± f'_a t − bound t²/2, oriented to the sign of f).
        let sgn = fa.signum();
        let (fa, da, fb, db) = (sgn * fa, sgn * da, sgn * fb, sgn * db);
        let width = xb - xa;
        // f ≥ min(f_a, f_b) − bound width²/8 on the interval.
        if fa.min(fb) > 0.125 * bound * width * width {
            return;
        }
        let reach = |f: f64, slope: f64| (slope + (slope * slope + 2.0 * bound * f).sqrt()) / bound;
        if reach(fa, da) + reach(fb.max(0.0), -db) >= width {
            return;
        }
        if depth >= 40 || width < 1e-12 {
            // A tangency (double root) to the resolution of the scan.
            if fa.min(fb) <= 1e-13 * scale {
                self.push(if fa <= fb { xa } else { xb });
            }
            return;
        }
        if self.budget == 0 {
            return;
        }
        self.budget -= 1;
        let xm = 0.5 * (xa + xb);
        let (sm, cm) = xm.sin_cos();
        let (fm, dm) = f_df_at(k, cm, sm);
        let mid = (xm, fm, dm);
        self.scan(k, (xa, sgn * fa, sgn * da), mid, bound, scale, depth + 1);
        self.scan(k, mid, (xb, sgn * fb, sgn * db), bound, scale, depth + 1);
    }
}

/// The root of `f` between `a` and `b` (`f` of opposite signs there): from a Newton step
/// off the end with the smaller `|f|` (or the secant point), [`newton_in_bracket`].
fn polish(
    k: (f64, f64, f64, f64),
    (a, fa, da): (f64, f64, f64),
    (b, fb, db): (f64, f64, f64),
) -> f64 {
    // Start: Newton from the end with the smaller |f|, or the secant point.
    let mut x = if fa.abs() < fb.abs() && da != 0.0 {
        a - fa / da
    } else if db != 0.0 {
        b - fb / db
    } else {
        a - fa * (b - a) / (fb - fa)
    };
    if !(x > a.min(b) && x < a.max(b)) {
        x = a - fa * (b - a) / (fb - fa);
    }
    newton_in_bracket(
        |x| {
            let (s, c) = x.sin_cos();
            f_df_at(k, c, s)
        },
        a,
        fa,
        b,
        x,
    )
}

/// One invariant ray with the coefficients of `f`'s expansion about it.
#[derive(Debug, Clone, Copy)]
struct Ray {
    phi: f64,
    dir: Vec2,
    q: f64,
    r: f64,
    s: f64,
}

impl Ray {
    fn new(field: &Field, phi: f64) -> Ray {
        let (a, b, c, d) = field.f_coefficients();
        let (sr, cr) = phi.sin_cos();
        let (s2, c2) = (2.0 * sr * cr, cr * cr - sr * sr);
        Ray {
            phi,
            dir: Vec2::new(cr, sr),
            q: b * cr - a * sr,
            r: c * c2 + d * s2,
            s: d * c2 - c * s2,
        }
    }
}

/// The sector between the ray behind and the ray ahead, and its map onto the real line.
struct Fan {
    sgn: f64,
    /// `cos(D/2)`, `sin(D/2)`.
    cd: f64,
    sd: f64,
    ahead: Ray,
    behind: Ray,
}

/// The integrand data at one value of `x`.
#[derive(Debug, Clone, Copy)]
struct Node {
    s: Vec2,
    q: f64,
    rho: f64,
}

/// [`half_vectors_with`] with its own exponential.
#[cfg(test)]
fn half_vectors(cd: f64, sd: f64, x: f64) -> (f64, f64, f64, f64, f64) {
    half_vectors_with(cd, sd, x, (-x.abs()).exp())
}

/// The half-angle vector `h = (h_x, h_y)` of the map at `x` given `t = e^{−|x|}`, with the
/// sine and cosine of `δ_a/2` times `|h|` and `t`: `(cos(δ_b/2), sin(δ_b/2)) = h/|h|`.
#[inline]
fn half_vectors_with(cd: f64, sd: f64, x: f64, t: f64) -> (f64, f64, f64, f64, f64) {
    if x <= 0.0 {
        (1.0 + t * cd, t * sd, sd, cd + t, t)
    } else {
        (t + cd, sd, t * sd, 1.0 + t * cd, t)
    }
}

/// `e^{s x_j}` at the panel's nodes `x_j = x_c + L t_j` (`x_c` its middle, `L` half its
/// width, `s` the sign that makes `e^{s x_c} = e^{−|x_c|}`) from nine exponentials instead
/// of seventeen: the nodes are symmetric about the middle (`t_{N−j} = −t_j`), so with
/// `a_j = e^{L t_j}` (`j < N/2`), `e^{s x_j} = e^{−|x_c|} a_j^{±1}`. That is `e^{−|x_j|}` where
/// `x_j` is on the side of `x_c`, its reciprocal where it is not ([`e_abs`]). (Entry 0 is
/// not filled: the first node is the last panel's end.)
fn node_exponentials(xc: f64, l: f64, t: &[f64; M]) -> [f64; M] {
    let ec = (-xc.abs()).exp();
    let mut out = [0.0; M];
    for j in 0..N / 2 {
        let a = (l * t[j]).exp();
        (out[j], out[N - j]) = if xc <= 0.0 {
            (ec * a, ec / a)
        } else {
            (ec / a, ec * a)
        };
    }
    out[N / 2] = ec;
    out
}

/// `e^{−|x|}` from `p = e^{s x}` of [`node_exponentials`] (`x_c` the panel's middle).
#[inline]
fn e_abs(x: f64, xc: f64, p: f64) -> f64 {
    if (x <= 0.0) == (xc <= 0.0) {
        p
    } else {
        1.0 / p
    }
}

impl Fan {
    /// `δ_a` at `x`.
    #[cfg(test)]
    fn delta_ahead(&self, x: f64) -> f64 {
        let (_, _, sa, ca, _) = half_vectors(self.cd, self.sd, x);
        2.0 * sa.atan2(ca)
    }

    /// Whether `δ_a ≤ δ` at `x` (given `e = e^{−|x|}`), from `t = tan(δ/2)`: the half-angle
    /// vector of `δ_a/2` is in the first quadrant with `sin ≤ t cos` (no arctangent).
    #[inline]
    fn ahead_within(&self, x: f64, e: f64, t: f64) -> bool {
        let (_, _, sa, ca, _) = half_vectors_with(self.cd, self.sd, x, e);
        ca > 0.0 && sa <= t * ca
    }

    /// The direction, `q` and `ρ` at `x`; `None` where `f` does not have the sign of the
    /// sector (round-off at the very ends).
    #[inline]
    fn node(&self, field: &Field, x: f64) -> Option<Node> {
        self.node_with(field, x, (-x.abs()).exp())
    }

    /// [`Fan::node`] given `e^{−|x|}`.
    #[inline]
    fn node_with(&self, field: &Field, x: f64, e: f64) -> Option<Node> {
        let (hx, hy, sa, ca, t) = half_vectors_with(self.cd, self.sd, x, e);
        let inv = 1.0 / (hx * hx + hy * hy);
        // The offset ε from the nearer ray, by its sine and cosine (double half-angles).
        let (se, ce, ray) = if x <= 0.0 {
            (
                self.sgn * 2.0 * hx * hy * inv,
                1.0 - 2.0 * hy * hy * inv,
                &self.behind,
            )
        } else {
            (
                -self.sgn * 2.0 * sa * ca * inv,
                1.0 - 2.0 * sa * sa * inv,
                &self.ahead,
            )
        };
        let s = Vec2::new(
            ray.dir.x * ce - ray.dir.y * se,
            ray.dir.y * ce + ray.dir.x * se,
        );
        // |ε| ≤ 1: the expansion about the ray.
        let f = if ce >= 0.5403 {
            se * (ray.q + 2.0 * ray.s * ce - ray.r * se * (2.0 * ce + 1.0) / (1.0 + ce))
        } else {
            field.f_at(s.x, s.y)
        };
        let fa = self.sgn * f;
        if !(fa > 0.0) {
            return None;
        }
        Some(Node {
            s,
            q: field.q_at(s.x, s.y),
            // dθ/dx = 2 e^{−|x|} sin(D/2)/|h|².
            rho: 2.0 * t * self.sd * inv / fa,
        })
    }
}

/// The cumulative integrals of `dp_n`, `dW_n` and `dW_t/(−μ)` at a panel's nodes.
type Dense = ([f64; M], [f64; M], [f64; M]);

/// How the stage in the angle variable ended.
pub(super) enum Exit {
    /// The slip stage ended (terminated or halted).
    End(SlipEnd),
    /// The variable does not apply here (the slip is on a ray to round-off, or `f` lost its
    /// sign): go on with the other variables from `pt`.
    Handoff,
    /// The rays are not known for certain (an unresolved near-tangency of two, or `f ≡ 0`):
    /// nothing was done, and the variable is not to be tried again.
    Unavailable,
}

/// Everything the stage reads.
pub(super) struct Context<'a> {
    pub wtt: &'a Mat2,
    pub wtn: Vec2,
    pub wnn: f64,
    pub mu: f64,
    pub field: &'a Field,
    pub sc: Scales,
    pub max_steps: u32,
    /// The coefficient of restitution.
    pub e: f64,
    /// The normal velocity before the impact.
    pub vn0: f64,
    /// Whether the observer does anything (else `p_n` inside a panel only where an event
    /// reads it).
    pub observing: bool,
}

/// `tan(0.15)`: the series about the ray ahead is tried within 0.3 rad of it.
const TAN_0_15: f64 = 0.151_135_218_058_295_08;

/// The order in `h` assumed when an accepted panel's successor is sized: lower than the
/// panel's `N`, because the singularities that limit a panel (complex roots of `f`, the
/// map's poles at `Im x = ±(π − D/2)`) lie behind it as the panels move on, so the tail grows
/// more slowly than `h^N` (over 4,000 random problems, 11 is best among 9–16: 1.8 % fewer
/// instructions than 16, the 120° swirl and a near-zero swing 0.5 % and 2.3 % fewer).
const GROWTH_ORDER: f64 = 11.0;

/// The factor on a rejected panel's width for its error estimate `err > 1` (the tail falls
/// as `h^N`), within `[0.2, 0.9]`; `0.25` if the estimate is not finite.
fn reject_factor(err: f64) -> f64 {
    if err.is_finite() {
        (0.9 * err.powf(-1.0 / N as f64)).clamp(0.2, 0.9)
    } else {
        0.25
    }
}

/// Run the slip from `pt` in the angle variable to its end, or hand it back.
/// `straight` ends the slip in closed form once its direction is on a centripetal ray to the
/// last bit of the result (`None` while it is not).
pub(super) fn run(
    cx: &Context,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    observe: &mut impl FnMut(f64, Vec3),
    straight: &mut impl FnMut(&mut Point, &mut Events) -> Option<Result<SlipEnd, BreakdownReason>>,
) -> Result<Exit, BreakdownReason> {
    let field = cx.field;
    let sigma0 = norm_of(pt.vt);
    if !(sigma0 > 0.0 && sigma0.is_finite()) {
        return Ok(Exit::Handoff);
    }
    let phi0 = pt.vt.y.atan2(pt.vt.x);
    let (f0, _) = field.f_df(phi0);
    let (a, b, c, d) = field.f_coefficients();
    if !(f0.abs() > 1e-14 * (a.abs() + b.abs() + c.abs() + d.abs())) {
        return Ok(Exit::Handoff);
    }
    let Some(sector) = Sector::find(field, phi0) else {
        return Ok(Exit::Unavailable);
    };
    let sgn = f0.signum();
    let (ra, rb) = if sgn > 0.0 {
        (sector.above, sector.below)
    } else {
        (sector.below, sector.above)
    };
    let (da0, db0) = (sgn * (ra - phi0), sgn * (phi0 - rb));
    if !(da0 > 1e-12 && db0 > 1e-12) {
        return Ok(Exit::Handoff);
    }
    let (sd, cd) = (0.5 * (da0 + db0)).sin_cos();
    if !(sd > 1e-3) {
        // The sector is the whole circle but for a double root.
        return Ok(Exit::Handoff);
    }
    let fan = Fan {
        sgn,
        cd,
        sd,
        ahead: Ray::new(field, ra),
        behind: Ray::new(field, rb),
    };
    let qa = field.q_at(fan.ahead.dir.x, fan.ahead.dir.y);
    let lb = lobatto();
    let rtol = cx.sc.rtol;
    let mut x = (0.5 * db0).sin().ln() - (0.5 * da0).sin().ln();
    let Some(mut n0) = fan.node(field, x) else {
        return Ok(Exit::Handoff);
    };
    let mut u0 = sigma0.ln();
    // The first panel: 1.2 wide, or less where σ changes by more than e² over it
    // (`|d ln σ/dx| = |q ρ|`; as a starting step from the derivative, Hairer–Nørsett–Wanner
    // §II.4); tried on 4,000 random problems, 2 is best on average.
    let mut h = 1.2f64.min(2.0 / (n0.q * n0.rho).abs().max(f64::MIN_POSITIVE));
    let mut series = TailSeries::with_ray(fan.ahead.phi, fan.ahead.dir);
    loop {
        if *steps >= cx.max_steps {
            return Err(BreakdownReason::NoSeparation);
        }
        let base = *pt;
        // The panel reaches at most a few times the normal impulse to the next event (`v_n`
        // to 0, then to about `e |v_n⁻|`, at the rate `k_n = w_nn − μ w_tn·ŝ`), so that
        // the events are located on interpolants of their own scale.
        let kn = cx.wnn - cx.mu * cx.wtn.dot(&n0.s);
        if kn > 0.0 {
            let to_event = (base.vn.abs().max(cx.e * cx.vn0.abs())) / kn;
            let rate = norm_of(base.vt) * n0.rho;
            if to_event > 0.0 && rate > 0.0 {
                h = h.min(4.0 * to_event / rate);
            }
        }
        if !(h > 1e-12 * (1.0 + x.abs())) {
            // The direction barely turns before the next event: the normal impulse is the
            // better variable.
            return Ok(Exit::Handoff);
        }
        let half = 0.5 * h;
        let mut nodes = [n0; M];
        let mut ok = true;
        let xc = x + half;
        let ex = node_exponentials(xc, half, &lb.t);
        for (j, nd) in nodes.iter_mut().enumerate().skip(1) {
            let xj = x + half * (1.0 + lb.t[j]);
            match fan.node_with(field, xj, e_abs(xj, xc, ex[j])) {
                Some(n) => *nd = n,
                None => {
                    ok = false;
                    break;
                }
            }
        }
        if !ok {
            h *= 0.25;
            if h < 1e-6 {
                return Ok(Exit::Handoff);
            }
            continue;
        }
        let du: [f64; M] = std::array::from_fn(|j| nodes[j].q * nodes[j].rho);
        // The error test on `u` first (part of the test below): a panel that fails it is
        // rejected before `σ` and the quadratures are formed.
        let err_u = half * lb.tail(&du) / rtol;
        if !(err_u <= 1.0) {
            h *= reject_factor(err_u);
            if h < 1e-6 {
                return Ok(Exit::Handoff);
            }
            continue;
        }
        let cu = lb.cumulative(&du);
        let sig: [f64; M] = std::array::from_fn(|j| {
            if j == 0 {
                norm_of(base.vt)
            } else {
                (u0 + half * cu[j]).exp()
            }
        });
        let dp: [f64; M] = std::array::from_fn(|j| sig[j] * nodes[j].rho);
        let d1: [f64; M] = std::array::from_fn(|j| nodes[j].s.x * dp[j]);
        let d2: [f64; M] = std::array::from_fn(|j| nodes[j].s.y * dp[j]);
        let dw: [f64; M] = std::array::from_fn(|j| sig[j] * dp[j]);
        // dv_n = (w_nn − μ w_tn·ŝ) dp_n.
        let dv: [f64; M] =
            std::array::from_fn(|j| (cx.wnn - cx.mu * cx.wtn.dot(&nodes[j].s)) * dp[j]);
        let cv = lb.cumulative(&dv);
        let vn: [f64; M] = std::array::from_fn(|j| {
            if j == 0 {
                base.vn
            } else {
                base.vn + half * cv[j]
            }
        });
        let dn: [f64; M] = std::array::from_fn(|j| vn[j] * dp[j]);
        // The error test: the last Chebyshev coefficients of each integrand against the
        // tolerance on `u` (absolute: relative on σ; tested above) and relative on every
        // other quantity (its value at the start plus the size of its increment over the
        // panel). (`k` is the factor of the integral in the quantity.)
        let (tails, sizes) = lb.tails_and_sizes([&dp, &d1, &d2, &dw, &dn]);
        let rel = |i: usize, at: f64, k: f64| {
            k * half * tails[i] / (rtol * (at.abs() + k * h * sizes[i]))
        };
        let err = err_u
            .max(rel(0, base.p, 1.0))
            .max(rel(1, base.pt.x, cx.mu))
            .max(rel(2, base.pt.y, cx.mu))
            .max(rel(3, base.wt, cx.mu))
            .max(rel(4, base.wn, 1.0));
        if !(err <= 1.0) {
            h *= reject_factor(err);
            if h < 1e-6 {
                return Ok(Exit::Handoff);
            }
            continue;
        }
        // `p_n` and the works at every node (`dense`) only where something reads them: the
        // observer, the termination once compression has ended (Poisson's reads `p_n`, the
        // energetic one `W_n`), or an event inside the panel; else at the panel's end only.
        // The tangential impulse inside the panel only at an event.
        let all_dense = || (lb.cumulative(&dp), lb.cumulative(&dn), lb.cumulative(&dw));
        let mut dense = (cx.observing
            || (ev.pc.is_some() && !matches!(ev.term, Termination::Newton)))
        .then(all_dense);
        let end_p = base.p + half * lb.integral(&dp);
        let end_pt = base.pt - cx.mu * half * Vec2::new(lb.integral(&d1), lb.integral(&d2));
        let (end_n, end_w) = (
            base.wn + half * lb.integral(&dn),
            base.wt - cx.mu * half * lb.integral(&dw),
        );
        // The state at node `j` (the tangential impulse only at the end; `p_n` and the works
        // at the end, or where they are known).
        let point = |j: usize, dense: &Option<Dense>| {
            let (p, wn, wt) = match dense {
                Some((cp, cn, cw)) => (
                    base.p + half * cp[j],
                    base.wn + half * cn[j],
                    base.wt - cx.mu * half * cw[j],
                ),
                None if j == N => (end_p, end_n, end_w),
                None => (f64::NAN, f64::NAN, f64::NAN),
            };
            Point {
                p,
                vt: sig[j] * nodes[j].s,
                vn: vn[j],
                pt: if j == N {
                    end_pt
                } else {
                    Vec2::new(f64::NAN, f64::NAN)
                },
                wn,
                wt,
            }
        };
        // What the event functions read at `t` (p_n, v_n, W_n) on the interpolants.
        let light = |l: &[f64; M], (cp, cn, _): &Dense| -> Point {
            Point {
                p: base.p + half * dot(l, cp),
                vt: Vec2::zeros(),
                vn: base.vn + half * dot(l, &cv),
                pt: base.pt,
                wn: base.wn + half * dot(l, cn),
                wt: f64::NAN,
            }
        };
        // The events on the panel's interpolants, node interval by node interval; the slip
        // itself does not change at an event, so the panel goes on past any that does not
        // end the law.
        let mut prev = base;
        #[allow(clippy::needless_range_loop)] // j indexes the node arrays and the nodes t_j
        for j in 1..M {
            let mut bj = point(j, &dense);
            let mut lo = lb.t[j - 1];
            while let Some((mut kind, ga, gb)) = first_event(ev, &prev, &bj) {
                let w = *dense.get_or_insert_with(all_dense);
                bj = point(j, &dense);
                // The event function's rate: its integrand's interpolant (v_n for the end
                // of compression, a second compression and Newton's termination).
                let at_crossing = |kind: u8, ga: f64, gb: f64| {
                    let (rate, sign) = match (kind, ev.term) {
                        (1, Termination::Energetic) => (&dn, 1.0),
                        (1, Termination::Poisson) => (&dp, 1.0),
                        (2, _) => (&dv, -1.0),
                        _ => (&dv, 1.0),
                    };
                    if ga >= 0.0 {
                        // (A later compression that began at v_n = 0 exactly ends at once.)
                        return lo;
                    }
                    newton_crossing(
                        |t| {
                            let l = lb.basis(t);
                            (
                                event_value(ev, kind, &light(&l, &w)),
                                sign * half * dot(&l, rate),
                            )
                        },
                        lo,
                        ga,
                        lb.t[j],
                        gb,
                    )
                };
                let mut t = at_crossing(kind, ga, gb);
                if poisson_ends_first(ev, kind, &light(&lb.basis(t), &w)) {
                    kind = 1;
                    t = at_crossing(kind, ev.terminal(&prev), ev.terminal(&bj));
                }
                // The whole state at the event.
                let l = lb.basis(t);
                let (c1, c2) = (lb.cumulative(&d1), lb.cumulative(&d2));
                let mut e = light(&l, &w);
                e.pt = base.pt - cx.mu * half * Vec2::new(dot(&l, &c1), dot(&l, &c2));
                e.wt = base.wt - cx.mu * half * dot(&l, &w.2);
                let ue = u0 + half * dot(&l, &cu);
                let ne = fan.node(field, x + half * (1.0 + t)).unwrap_or(nodes[j]);
                e.vt = ue.exp() * ne.s;
                *pt = e;
                *steps += 1;
                observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                if let Some(end) = after_event(kind, pt, ev, pt.vt.y.atan2(pt.vt.x)) {
                    return Ok(Exit::End(end));
                }
                prev = *pt;
                lo = t;
            }
            observe(bj.p, Vec3::new(bj.vt.x, bj.vt.y, bj.vn));
            prev = bj;
        }
        *pt = prev;
        *steps += 1;
        x += h;
        u0 += half * cu[N];
        n0 = nodes[N];
        h *= (0.9 * err.max(1e-30).powf(-1.0 / GROWTH_ORDER)).min(4.0);
        // δ_a at the panel's end against the series' reach (0.3 rad, tan 0.15) and, on a
        // centrifugal ray, against the last bit (δ with tan(δ/2) = δ/2).
        let e_end = e_abs(x, xc, ex[N]);
        let within = |t: f64| fan.ahead_within(x, e_end, t);
        if qa < 0.0 {
            if let Some(end) = straight(pt, ev) {
                let end = end?;
                observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                return Ok(Exit::End(end));
            }
            if within(TAN_0_15) {
                let g = cx.wtn - cx.mu * (cx.wtt * (pt.vt / norm_of(pt.vt)));
                if let Some(ser) = series.get(field, cx.wnn, g, pt.vt) {
                    let sc = cx.sc;
                    if let Some(end) = series_tail(ser, cx.wtn, cx.wnn, cx.mu, sc, pt, ev, observe)
                    {
                        return Ok(Exit::End(end));
                    }
                }
            }
        } else if within(0.5 * f64::EPSILON * f64::EPSILON / (64.0 * (1.0 + cx.mu))) {
            // On the ray ahead to the last bit of the result: the rest is a straight run
            // along it.
            let s = fan.ahead.dir;
            let sigma = norm_of(pt.vt);
            let piece = Linear {
                kind: Phase3Kind::Stick,
                ratio: -cx.mu * s,
                slope: cx.wnn - cx.mu * cx.wtn.dot(&s),
                dir: s,
                sigma,
                dsigma: qa,
                length: f64::INFINITY,
            };
            let phi = pt.vt.y.atan2(pt.vt.x);
            return if linear_piece(&piece, pt, ev, cx.mu)? {
                observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                Ok(Exit::End(SlipEnd::Terminated { phi }))
            } else {
                Err(BreakdownReason::NoSeparation)
            };
        }
        if x > 600.0 {
            return Ok(Exit::Handoff);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::SplitMix64;
    use crate::spatial::{invariant_rays, ContactProblem3};

    fn random_field(g: &mut SplitMix64) -> (ContactProblem3, Field) {
        let (a, c) = (g.decades(-1.0, 1.0), g.decades(-1.0, 1.0));
        let b = g.range(-0.9, 0.9) * (a * c).sqrt();
        let (w1, w2) = (g.range(-1.0, 1.0), g.range(-1.0, 1.0));
        let mu = g.decades(-1.5, 0.5);
        // w_nn above the Schur complement's bound w_tᵀ W_tt⁻¹ w_t.
        let wnn = 1.0 + (c * w1 * w1 - 2.0 * b * w1 * w2 + a * w2 * w2) / (a * c - b * b);
        let p = ContactProblem3::from_upper([a, b, w1, c, w2, wnn], [0.1, 0.2, -1.0], mu, 0.5)
            .expect("SPD by construction");
        let field = Field::new(&p.wtt(), p.wtn(), mu);
        (p, field)
    }

    /// The scans find the nearest rays below and above a direction, the same as the
    /// companion matrix of the quartic in `tan(φ/2)` (`invariant_rays`, an independent
    /// method) gives, and each is a root of `f` to round-off.
    #[test]
    fn the_sector_scan_finds_the_rays_of_the_companion_matrix() {
        let mut g = SplitMix64(0x9e37_79b9_7f4a_7c15);
        let mut compared = 0;
        for _ in 0..5000 {
            let (p, field) = random_field(&mut g);
            let (a, b, c, d) = field.f_coefficients();
            let scale = a.abs() + b.abs() + c.abs() + d.abs();
            let phi0 = g.range(-10.0, 10.0);
            let (s0, c0) = phi0.sin_cos();
            if field.f_at(c0, s0).abs() < 1e-6 * scale {
                continue;
            }
            let sector = Sector::find(&field, phi0).expect("f is not identically zero");
            assert!(sector.below < phi0 && phi0 < sector.above);
            assert!(sector.above - sector.below <= TAU + 1e-12);
            for r in [sector.below, sector.above] {
                let (s, co) = r.sin_cos();
                assert!(field.f_at(co, s).abs() <= 1e-14 * scale, "f({r}) not zero");
            }
            let rays = invariant_rays(&p);
            let reference: Vec<f64> = rays.as_slice().iter().map(|x| x.angle).collect();
            // Near-tangencies (two roots closer than 1e-6) are left to the scan alone.
            let close = reference.windows(2).any(|w| (w[1] - w[0]).abs() < 1e-6);
            if close {
                continue;
            }
            // The nearest reference rays above and below φ0.
            let above = reference
                .iter()
                .map(|&r| phi0 + (r - phi0).rem_euclid(TAU))
                .fold(f64::INFINITY, f64::min);
            let below = reference
                .iter()
                .map(|&r| phi0 - (phi0 - r).rem_euclid(TAU))
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                (sector.above - above).abs() < 1e-12,
                "{sector:?} vs {above} for {p:?}"
            );
            assert!(
                (sector.below - below).abs() < 1e-12,
                "{sector:?} vs {below} for {p:?}"
            );
            compared += 1;
        }
        assert!(compared > 4500, "{compared} compared");
    }

    /// `f` from its expansion about a ray equals `f` evaluated directly, to round-off of the
    /// size of `f`'s coefficients, across the whole range it is used on (`|ε| ≤ 1`).
    #[test]
    fn the_expansion_about_a_ray_is_f() {
        let mut g = SplitMix64(0x2545_f491_4f6c_dd1d);
        for _ in 0..500 {
            let (p, field) = random_field(&mut g);
            let (a, b, c, d) = field.f_coefficients();
            let scale = a.abs() + b.abs() + c.abs() + d.abs();
            for r in invariant_rays(&p).as_slice().iter().map(|x| x.angle) {
                let ray = Ray::new(&field, r);
                for k in 0..40 {
                    let eps = g.range(-1.0, 1.0) * 10f64.powi(-(k % 8));
                    let (se, ce) = eps.sin_cos();
                    let expanded = se
                        * (ray.q + 2.0 * ray.s * ce - ray.r * se * (2.0 * ce + 1.0) / (1.0 + ce));
                    let (s, co) = (r + eps).sin_cos();
                    let direct = field.f_at(co, s);
                    assert!(
                        (expanded - direct).abs() <= 1e-14 * scale,
                        "ε {eps}: {expanded} vs {direct}"
                    );
                }
            }
        }
    }

    /// The nodes' exponentials from the symmetric products are `e^{−|x_j|}` to a few ulp, on
    /// panels left of, right of and across `x = 0`.
    #[test]
    fn node_exponentials_are_the_exponentials_of_the_nodes() {
        let lb = lobatto();
        for &(x, h) in &[
            (-7.3, 1.1),
            (-0.4, 0.9),
            (-0.6, 0.6),
            (0.0, 1.2),
            (2.5, 4.0),
            (-3.0, 5.5),
        ] {
            let half = 0.5 * h;
            let xc = x + half;
            let ex = node_exponentials(xc, half, &lb.t);
            for (j, (&tj, &p)) in lb.t.iter().zip(&ex).enumerate().skip(1) {
                let xj = x + half * (1.0 + tj);
                let got = e_abs(xj, xc, p);
                let want = (-xj.abs()).exp();
                assert!(
                    (got - want).abs() <= 4.0 * f64::EPSILON * want,
                    "x {x} h {h} node {j}: {got} vs {want}"
                );
            }
        }
    }

    /// The half-angle map against the angle it stands for: `ŝ(x)` is the direction at
    /// `θ_b + sgn·2 atan2(e^x sin(D/2), 1 + e^x cos(D/2))`, `δ_a` is `D` less the angle
    /// turned, and `ρ |f| = dθ/dx` agrees with a central difference of that angle.
    #[test]
    fn the_half_angle_map_is_the_angle_it_stands_for() {
        let mut g = SplitMix64(0x6a09_e667_f3bc_c909);
        let mut checked = 0;
        for _ in 0..300 {
            let (_, field) = random_field(&mut g);
            let phi0 = g.range(-3.0, 3.0);
            let (s0, c0) = phi0.sin_cos();
            let f0 = field.f_at(c0, s0);
            let (a, b, c, d) = field.f_coefficients();
            if f0.abs() < 1e-3 * (a.abs() + b.abs() + c.abs() + d.abs()) {
                continue;
            }
            let Some(sector) = Sector::find(&field, phi0) else {
                continue;
            };
            let sgn = f0.signum();
            let (ra, rb) = if sgn > 0.0 {
                (sector.above, sector.below)
            } else {
                (sector.below, sector.above)
            };
            let big_d = sector.above - sector.below;
            if big_d > 6.0 {
                continue;
            }
            let (sd, cd) = (0.5 * big_d).sin_cos();
            let fan = Fan {
                sgn,
                cd,
                sd,
                ahead: Ray::new(&field, ra),
                behind: Ray::new(&field, rb),
            };
            let turned = |x: f64| 2.0 * (x.exp() * sd).atan2(1.0 + x.exp() * cd);
            for x in [-30.0, -4.0, -0.7, 0.0, 0.3, 2.5, 9.0] {
                let Some(n) = fan.node(&field, x) else {
                    continue;
                };
                let theta = rb + sgn * turned(x);
                assert!((n.s.x - theta.cos()).abs() < 1e-14 && (n.s.y - theta.sin()).abs() < 1e-14);
                assert!((n.s.norm() - 1.0).abs() < 1e-15);
                let da = fan.delta_ahead(x);
                assert!((da - (big_d - turned(x))).abs() < 1e-13 * big_d.max(1.0) + 1e-15);
                if x.abs() < 5.0 {
                    let e = 1e-5;
                    let rate = (turned(x + e) - turned(x - e)) / (2.0 * e);
                    let f = field.f_at(n.s.x, n.s.y).abs();
                    assert!(((n.rho * f) - rate).abs() < 1e-8 * rate, "x {x}");
                }
                checked += 1;
            }
        }
        assert!(checked > 1000, "{checked} checked");
    }
}
