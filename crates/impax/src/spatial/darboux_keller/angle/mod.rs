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
//! (`u = ln σ`, `q = ŝ·g`) maps the sector onto the whole real line ([`map`]), where near
//! either ray `|f| ≈ |f'| δ`, so `ρ` stays bounded and `σ ∝ e^{κ x}`: every integrand is
//! smooth on the scale of one unit of `x` — a swing of the direction through a near-zero
//! pass, the approach to a halt, a slip leaving a ray or growing along one, a nearly frozen
//! slip alike. The only nonlinear equation (the direction's) is solved by the map itself;
//! `u`, then `p_n`, `v_n`, `p_t`, `W_t` and `W_n` are integrals on 17-node Chebyshev–Lobatto
//! panels ([`crate::numerics::chebyshev`]), whose length follows the size of the last
//! Chebyshev coefficients of the integrands; the cumulative ones (at every node) only where
//! an event can read them. Events are located on the panel's interpolants. The two rays are
//! found by scans outward from the slip's direction ([`Sector`]).

// Tests of the form `!(x > 0.0)` are meant: a NaN must fail them.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod map;

use self::map::{e_abs, node_exponentials, Fan, Node, Ray};
use super::events::{Event, Events};
use super::field::{Field, Sector};
use super::linear::Linear;
use super::slip::Slip;
use super::state::{Point, SlipEnd};
use super::tail::TailSeries;
use super::Termination;
use crate::law::BreakdownReason;
use crate::math::{norm_of, Vec2, Vec3};
use crate::numerics::chebyshev::{dot, lobatto, M, N};
use crate::numerics::roots::newton_crossing;
use crate::spatial::outcome::PhaseKind;

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

/// The sweep of a sector by panels: the map, the rate of the slip on the ray ahead, and the
/// start of the next panel.
struct Sweep {
    fan: Fan,
    /// `q = ŝ·g` on the ray ahead.
    qa: f64,
    /// The start of the next panel.
    x: f64,
    /// The node at `x`.
    n0: Node,
    /// `u = ln σ` at `x`.
    u0: f64,
    /// The width of the next panel.
    h: f64,
}

impl Sweep {
    /// The sweep from the slip at `pt`, or how the stage ends at once where the variable
    /// does not apply.
    fn start(field: &Field, pt: &Point) -> Result<Sweep, Exit> {
        let sigma0 = norm_of(pt.vt);
        if !(sigma0 > 0.0 && sigma0.is_finite()) {
            return Err(Exit::Handoff);
        }
        let phi0 = pt.vt.y.atan2(pt.vt.x);
        let (f0, _) = field.f_df(phi0);
        let (a, b, c, d) = field.f_coefficients();
        if !(f0.abs() > 1e-14 * (a.abs() + b.abs() + c.abs() + d.abs())) {
            return Err(Exit::Handoff);
        }
        let Some(sector) = Sector::find(field, phi0) else {
            return Err(Exit::Unavailable);
        };
        let sgn = f0.signum();
        let (ra, rb) = if sgn > 0.0 {
            (sector.above, sector.below)
        } else {
            (sector.below, sector.above)
        };
        let (da0, db0) = (sgn * (ra - phi0), sgn * (phi0 - rb));
        if !(da0 > 1e-12 && db0 > 1e-12) {
            return Err(Exit::Handoff);
        }
        let (sd, cd) = (0.5 * (da0 + db0)).sin_cos();
        if !(sd > 1e-3) {
            // The sector is the whole circle but for a double root.
            return Err(Exit::Handoff);
        }
        let fan = Fan {
            sgn,
            cd,
            sd,
            ahead: Ray::new(field, ra),
            behind: Ray::new(field, rb),
        };
        let qa = field.q_at(fan.ahead.dir.x, fan.ahead.dir.y);
        let x = (0.5 * db0).sin().ln() - (0.5 * da0).sin().ln();
        let Some(n0) = fan.node(field, x) else {
            return Err(Exit::Handoff);
        };
        // The first panel: 1.2 wide, or less where σ changes by more than e² over it
        // (`|d ln σ/dx| = |q ρ|`; as a starting step from the derivative, Hairer–Nørsett–Wanner
        // §II.4); tried on 4,000 random problems, 2 is best on average.
        let h = 1.2f64.min(2.0 / (n0.q * n0.rho).abs().max(f64::MIN_POSITIVE));
        Ok(Sweep {
            fan,
            qa,
            x,
            n0,
            u0: sigma0.ln(),
            h,
        })
    }

    /// After a panel that ended at `x` (`e_end = e^{−|x|}`): the end of the slip in closed
    /// form where the direction is close enough to the ray ahead — on a centripetal ray the
    /// straight tail or the series about it, on a centrifugal one (to the last bit) the run
    /// along it; a handoff far out on the line; `None` to go on.
    fn after_panel(
        &self,
        slip: &Slip,
        e_end: f64,
        series: &mut TailSeries,
        pt: &mut Point,
        ev: &mut Events,
        observe: &mut impl FnMut(f64, Vec3),
    ) -> Result<Option<Exit>, BreakdownReason> {
        let (fan, x, qa) = (&self.fan, self.x, self.qa);
        // δ_a at the panel's end against the series' reach (0.3 rad, tan 0.15) and, on a
        // centrifugal ray, against the last bit (δ with tan(δ/2) = δ/2).
        let within = |t: f64| fan.ahead_within(x, e_end, t);
        if qa < 0.0 {
            if let Some((s, q)) = slip.straight_tail(pt.vt) {
                let end = slip.run_tail(pt, ev, s, q)?;
                observe(pt.p, pt.velocity());
                return Ok(Some(Exit::End(end)));
            }
            if within(TAN_0_15) {
                let g = slip.wtn - slip.mu * (slip.wtt * (pt.vt / norm_of(pt.vt)));
                if let Some(ser) = series.get(&slip.field, slip.wnn, g, pt.vt) {
                    if let Some(end) = slip.series_tail(ser, pt, ev, observe) {
                        return Ok(Some(Exit::End(end)));
                    }
                }
            }
        } else if within(0.5 * f64::EPSILON * f64::EPSILON / (64.0 * (1.0 + slip.mu))) {
            // On the ray ahead to the last bit of the result: the rest is a straight run
            // along it.
            let s = fan.ahead.dir;
            let sigma = norm_of(pt.vt);
            let piece = Linear {
                kind: PhaseKind::Stick,
                ratio: -slip.mu * s,
                slope: slip.wnn - slip.mu * slip.wtn.dot(&s),
                dir: s,
                sigma,
                dsigma: qa,
                length: f64::INFINITY,
            };
            let phi = pt.vt.y.atan2(pt.vt.x);
            return if piece.run(pt, ev, slip.mu)? {
                observe(pt.p, pt.velocity());
                Ok(Some(Exit::End(SlipEnd::Terminated { phi })))
            } else {
                Err(BreakdownReason::NoSeparation)
            };
        }
        Ok((x > 600.0).then_some(Exit::Handoff))
    }
}

/// One panel `[x, x + h]` of the sweep: its nodes, the integrands at them and the integrals
/// the events and the next panel read. (A workspace filled in place, panel after panel: the
/// arrays are not moved.)
struct Panel {
    /// The point at the panel's start.
    base: Point,
    /// The panel's start `x`, its middle `x_c` and half its width.
    x: f64,
    xc: f64,
    half: f64,
    /// `u = ln σ` at `x`.
    u0: f64,
    /// `e^{s x_j}` at the nodes ([`node_exponentials`]).
    ex: [f64; M],
    nodes: [Node; M],
    /// The slip speed at the nodes, and the cumulative integral of `du/dx`.
    sig: [f64; M],
    cu: [f64; M],
    /// The integrands `dp_n/dx`, `ŝ dp_n/dx`, `σ dp_n/dx`, `dv_n/dx`, `v_n dp_n/dx`.
    dp: [f64; M],
    d1: [f64; M],
    d2: [f64; M],
    dw: [f64; M],
    dv: [f64; M],
    dn: [f64; M],
    /// The cumulative integral of `dv_n/dx`, and `v_n` at the nodes.
    cv: [f64; M],
    vn: [f64; M],
    /// The error estimate (at most 1 once the panel is accepted).
    err: f64,
}

impl Panel {
    /// A workspace for the panels of the sweep from `pt` (the node `n0` at its start).
    fn new(pt: Point, n0: Node) -> Panel {
        Panel {
            base: pt,
            x: 0.0,
            xc: 0.0,
            half: 0.0,
            u0: 0.0,
            ex: [0.0; M],
            nodes: [n0; M],
            sig: [0.0; M],
            cu: [0.0; M],
            dp: [0.0; M],
            d1: [0.0; M],
            d2: [0.0; M],
            dw: [0.0; M],
            dv: [0.0; M],
            dn: [0.0; M],
            cv: [0.0; M],
            vn: [0.0; M],
            err: f64::NAN,
        }
    }

    /// The next panel of `sw` from the point `base` at its start: `Ok` if it passes the
    /// error test, otherwise the factor on the width to try again with.
    fn build(&mut self, slip: &Slip, sw: &Sweep, base: Point) -> Result<(), f64> {
        let (lb, rtol, field) = (lobatto(), slip.sc.rtol, &slip.field);
        let (x, h, u0, fan) = (sw.x, sw.h, sw.u0, &sw.fan);
        let half = 0.5 * h;
        (self.base, self.x, self.half, self.u0) = (base, x, half, u0);
        self.nodes[0] = sw.n0;
        let xc = x + half;
        self.xc = xc;
        self.ex = node_exponentials(xc, half, &lb.t);
        for (j, nd) in self.nodes.iter_mut().enumerate().skip(1) {
            let xj = x + half * (1.0 + lb.t[j]);
            *nd = fan
                .node_with(field, xj, e_abs(xj, xc, self.ex[j]))
                .ok_or(0.25)?;
        }
        let nodes = &self.nodes;
        let du: [f64; M] = std::array::from_fn(|j| nodes[j].q * nodes[j].rho);
        // The error test on `u` first (part of the test below): a panel that fails it is
        // rejected before `σ` and the quadratures are formed.
        let err_u = half * lb.tail(&du) / rtol;
        if !(err_u <= 1.0) {
            return Err(reject_factor(err_u));
        }
        let cu = lb.cumulative(&du);
        self.sig = std::array::from_fn(|j| {
            if j == 0 {
                norm_of(base.vt)
            } else {
                (u0 + half * cu[j]).exp()
            }
        });
        self.cu = cu;
        let (sig, nodes) = (&self.sig, &self.nodes);
        self.dp = std::array::from_fn(|j| sig[j] * nodes[j].rho);
        let dp = &self.dp;
        self.d1 = std::array::from_fn(|j| nodes[j].s.x * dp[j]);
        self.d2 = std::array::from_fn(|j| nodes[j].s.y * dp[j]);
        self.dw = std::array::from_fn(|j| sig[j] * dp[j]);
        // dv_n = (w_nn − μ w_tn·ŝ) dp_n.
        self.dv = std::array::from_fn(|j| (slip.wnn - slip.mu * slip.wtn.dot(&nodes[j].s)) * dp[j]);
        self.cv = lb.cumulative(&self.dv);
        let cv = &self.cv;
        self.vn = std::array::from_fn(|j| {
            if j == 0 {
                base.vn
            } else {
                base.vn + half * cv[j]
            }
        });
        let vn = &self.vn;
        self.dn = std::array::from_fn(|j| vn[j] * dp[j]);
        // The error test: the last Chebyshev coefficients of each integrand against the
        // tolerance on `u` (absolute: relative on σ; tested above) and relative on every
        // other quantity (its value at the start plus the size of its increment over the
        // panel). (`k` is the factor of the integral in the quantity.)
        let (tails, sizes) = lb.tails_and_sizes([&self.dp, &self.d1, &self.d2, &self.dw, &self.dn]);
        let rel = |i: usize, at: f64, k: f64| {
            k * half * tails[i] / (rtol * (at.abs() + k * h * sizes[i]))
        };
        let err = err_u
            .max(rel(0, base.p, 1.0))
            .max(rel(1, base.pt.x, slip.mu))
            .max(rel(2, base.pt.y, slip.mu))
            .max(rel(3, base.wt, slip.mu))
            .max(rel(4, base.wn, 1.0));
        self.err = err;
        if !(err <= 1.0) {
            return Err(reject_factor(err));
        }
        Ok(())
    }

    /// Walk the panel node by node: every event on the panel's interpolants located
    /// ([`newton_crossing`]) and recorded, `observe` at each node and event. Returns the end
    /// of the slip if the law terminated at an event (`pt` the event); else `pt` is the
    /// panel's end. (The slip itself does not change at an event, so the panel goes on past
    /// any that does not end the law.)
    fn walk(
        &self,
        slip: &Slip,
        fan: &Fan,
        pt: &mut Point,
        ev: &mut Events,
        steps: &mut u32,
        observe: &mut impl FnMut(f64, Vec3),
    ) -> Option<SlipEnd> {
        let (lb, mu, field) = (lobatto(), slip.mu, &slip.field);
        let (base, half, x, u0) = (self.base, self.half, self.x, self.u0);
        let (nodes, sig, vn, cv) = (&self.nodes, &self.sig, &self.vn, &self.cv);
        // `p_n` and the works at every node (`dense`) only where something reads them: the
        // observer, the termination once compression has ended (Poisson's reads `p_n`, the
        // energetic one `W_n`), or an event inside the panel; else at the panel's end only.
        // The tangential impulse inside the panel only at an event.
        let all_dense = || {
            (
                lb.cumulative(&self.dp),
                lb.cumulative(&self.dn),
                lb.cumulative(&self.dw),
            )
        };
        let mut dense = (slip.observing
            || (ev.pc.is_some() && !matches!(ev.term, Termination::Newton)))
        .then(all_dense);
        let end_p = base.p + half * lb.integral(&self.dp);
        let end_pt = base.pt - mu * half * Vec2::new(lb.integral(&self.d1), lb.integral(&self.d2));
        let (end_n, end_w) = (
            base.wn + half * lb.integral(&self.dn),
            base.wt - mu * half * lb.integral(&self.dw),
        );
        // The state at node `j` (the tangential impulse only at the end; `p_n` and the works
        // at the end, or where they are known).
        let point = |j: usize, dense: &Option<Dense>| {
            let (p, wn, wt) = match dense {
                Some((cp, cn, cw)) => (
                    base.p + half * cp[j],
                    base.wn + half * cn[j],
                    base.wt - mu * half * cw[j],
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
                vn: base.vn + half * dot(l, cv),
                pt: base.pt,
                wn: base.wn + half * dot(l, cn),
                wt: f64::NAN,
            }
        };
        let mut prev = base;
        #[allow(clippy::needless_range_loop)] // j indexes the node arrays and the nodes t_j
        for j in 1..M {
            let mut bj = point(j, &dense);
            let mut lo = lb.t[j - 1];
            while let Some((mut kind, ga, gb)) = ev.first(&prev, &bj) {
                let w = *dense.get_or_insert_with(all_dense);
                bj = point(j, &dense);
                // The event function's rate: its integrand's interpolant (v_n for the end
                // of compression, a second compression and Newton's termination).
                let at_crossing = |kind: Event, ga: f64, gb: f64| {
                    let (rate, sign) = match (kind, ev.term) {
                        (Event::LawEnd, Termination::Energetic) => (&self.dn, 1.0),
                        (Event::LawEnd, Termination::Poisson) => (&self.dp, 1.0),
                        (Event::Recompression, _) => (&self.dv, -1.0),
                        _ => (&self.dv, 1.0),
                    };
                    if ga >= 0.0 {
                        // (A later compression that began at v_n = 0 exactly ends at once.)
                        return lo;
                    }
                    newton_crossing(
                        |t| {
                            let l = lb.basis(t);
                            (ev.value(kind, &light(&l, &w)), sign * half * dot(&l, rate))
                        },
                        lo,
                        ga,
                        lb.t[j],
                        gb,
                    )
                };
                let mut t = at_crossing(kind, ga, gb);
                if ev.poisson_ends_first(kind, &light(&lb.basis(t), &w)) {
                    kind = Event::LawEnd;
                    t = at_crossing(kind, ev.terminal(&prev), ev.terminal(&bj));
                }
                // The whole state at the event.
                let l = lb.basis(t);
                let (c1, c2) = (lb.cumulative(&self.d1), lb.cumulative(&self.d2));
                let mut e = light(&l, &w);
                e.pt = base.pt - mu * half * Vec2::new(dot(&l, &c1), dot(&l, &c2));
                e.wt = base.wt - mu * half * dot(&l, &w.2);
                let ue = u0 + half * dot(&l, &self.cu);
                let ne = fan.node(field, x + half * (1.0 + t)).unwrap_or(nodes[j]);
                e.vt = ue.exp() * ne.s;
                *pt = e;
                *steps += 1;
                observe(pt.p, pt.velocity());
                if let Some(end) = ev.record(kind, pt, pt.vt.y.atan2(pt.vt.x)) {
                    return Some(end);
                }
                prev = *pt;
                lo = t;
            }
            observe(bj.p, bj.velocity());
            prev = bj;
        }
        *pt = prev;
        None
    }
}

/// Run the slip from `pt` in the angle variable to its end, or hand it back: panel by panel
/// across the sector, each sized by its error test and the distance to the next event.
pub(super) fn run(
    slip: &Slip,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Exit, BreakdownReason> {
    let mut sw = match Sweep::start(&slip.field, pt) {
        Ok(sw) => sw,
        Err(exit) => return Ok(exit),
    };
    let mut series = TailSeries::with_ray(sw.fan.ahead.phi, sw.fan.ahead.dir);
    let mut panel = Panel::new(*pt, sw.n0);
    loop {
        if *steps >= slip.max_steps {
            return Err(BreakdownReason::NoSeparation);
        }
        let base = *pt;
        // The panel reaches at most a few times the normal impulse to the next event (`v_n`
        // to 0, then to about `e |v_n⁻|`, at the rate `k_n = w_nn − μ w_tn·ŝ`), so that
        // the events are located on interpolants of their own scale.
        let kn = slip.wnn - slip.mu * slip.wtn.dot(&sw.n0.s);
        if kn > 0.0 {
            let to_event = (base.vn.abs().max(slip.e * slip.vn0.abs())) / kn;
            let rate = norm_of(base.vt) * sw.n0.rho;
            if to_event > 0.0 && rate > 0.0 {
                sw.h = sw.h.min(4.0 * to_event / rate);
            }
        }
        if !(sw.h > 1e-12 * (1.0 + sw.x.abs())) {
            // The direction barely turns before the next event: the normal impulse is the
            // better variable.
            return Ok(Exit::Handoff);
        }
        if let Err(factor) = panel.build(slip, &sw, base) {
            sw.h *= factor;
            if sw.h < 1e-6 {
                return Ok(Exit::Handoff);
            }
            continue;
        }
        if let Some(end) = panel.walk(slip, &sw.fan, pt, ev, steps, observe) {
            return Ok(Exit::End(end));
        }
        *steps += 1;
        sw.x += sw.h;
        sw.u0 += panel.half * panel.cu[N];
        sw.n0 = panel.nodes[N];
        sw.h *= (0.9 * panel.err.max(1e-30).powf(-1.0 / GROWTH_ORDER)).min(4.0);
        let e_end = e_abs(sw.x, panel.xc, panel.ex[N]);
        if let Some(exit) = sw.after_panel(slip, e_end, &mut series, pt, ev, observe)? {
            return Ok(exit);
        }
    }
}
