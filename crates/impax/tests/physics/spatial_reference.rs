//! Independent reference integration of the spatial Darboux–Keller laws (`newton`,
//! `poisson`, `energetic` in 3D), compared with `LawId::resolve` on 2,000 random problems
//! and 12 jamb problems.
//!
//! The reference shares no code with the library's integrator (no Dormand–Prince, no
//! switch to `ln σ`, no invariant-ray tail, no `resumption_direction`):
//!
//! * **Slip** is integrated in the pseudo-time `τ` with `dp_n = σ dτ` (`σ = |v_t|`), in which
//!   the whole slip system is free of divisions and smooth away from `v_t = 0`:
//!   ```text
//!   dv_t/dτ = σ w_tn − μ W_tt v_t,   dv_n/dτ = σ w_nn − μ w_tn·v_t,   dp_n/dτ = σ,
//!   dp_t/dτ = −μ v_t,                dW_n/dτ = σ v_n,                dW_t/dτ = −μ σ².
//!   ```
//!   `σ → 0` is reached only as `τ → ∞`, so an approach to a halt and a swirl that passes
//!   close to the origin are both integrated in the same variable. The integrator is the
//!   classical RK4 with step doubling and Richardson extrapolation (local error estimate
//!   `(y_{h/2,h/2} − y_h)/15`, accepted value `y_{h/2,h/2} + (y_{h/2,h/2} − y_h)/15`),
//!   tolerance `1e-12` with the slip velocity controlled *relative to its own size*
//!   (largest deviation from the library ~4e-11 with this tolerance).
//! * **Halt**: once the slip is shrinking (`ŝ·g < 0`) and the impulse left to the halt,
//!   `σ/|ŝ·g|`, is below `1e-14` of the impulse scale, the rest is run straight along the
//!   last direction (error below `2 μ · 1e-14` of the impulse).
//! * **Stick** iff `|W_tt⁻¹ w_tn| ≤ μ` (2×2 inverse by hand): `dp_t/dp_n = −W_tt⁻¹ w_tn`,
//!   `dv_n/dp_n = det W / det W_tt` by cofactors in double-double arithmetic (the Schur
//!   complement `w_nn − w_tnᵀ W_tt⁻¹ w_tn` without the cancellation of the explicit form).
//! * **Resumed slip** along `ŝ = (λ'I + μW_tt)⁻¹ w_tn / |…|` with `λ' > 0` found by
//!   *bisection* on `|(λ'I + μW_tt)⁻¹ w_tn| = 1` (decreasing in `λ'`).
//! * **Events** — end of compression (`v_n = 0`), each termination (newton
//!   `v_n = −e v_n⁻`; poisson: the restitution impulse, where `v_n ≥ 0`, reaches `e` times
//!   the compression impulse, where `v_n < 0` — `p_n = (1+e) p_c` unless `v_n` falls back
//!   below zero after `p_c` (jamb), whose phases add to the compression; energetic
//!   `W_n = (1−e²) W_c`), a second compression (`v_n` back to 0 after `p_c`), and the start
//!   and end of every compression phase after the first — are located by bisection of the step
//!   length on the reference's own solution (re-stepping from the step start), and on the
//!   straight pieces by bisection of the closed-form state on its monotone intervals.
//!   The path does not depend on the law, so one integration serves all three laws.
//!
//! Problems: `W_tt = R diag(d1, d2) Rᵀ` with anisotropy up to 100 (15 % isotropic),
//! `w_tn = ρ √w_nn W_tt^{1/2} û` of every direction with `ρ ∈ [0, 1)` (10 % zero, 10 % near
//! the positive-definiteness limit `1 − ρ ∈ [1e-6, 1e-2]`), `μ` mostly relative to
//! `|W_tt⁻¹ w_tn|` (so that stick is impossible in a good fraction), `e ∈ [0, 1]`; `v_t⁻`
//! of all sizes, 5 % zero and 25 % aimed within `1e-9 … 1e-2` rad of a centripetal
//! invariant ray (found by the test's own scan), which gives halts, swirls and passes near
//! the origin. Twelve fixed problems with a second compression (jamb), found by a search
//! with the reference, are added (`JAMB`).
//!
//! Agreement required: `TOL = 1e-9` relative on every case, and every largest deviation
//! below `TARGET = 1e-10` (the accuracy the library's default tolerance is meant to give).
//! Deviations are measured as follows: impulse and compression impulse relative to
//! `|p|`, velocity relative to `|v⁻| + |W| |p|`, works and `ΔT` relative to
//! `|v⁻||p| + |W||p|²` (the size of the terms they are sums of); also the slip halt and
//! the second compression (a path that grazes the origin within 1e-8 σ0 where stick is
//! impossible may be reported as a halt by one side only: halt + resumed slip and a pass
//! are then the same path, and the path itself must agree), and stick vs resumed slip after
//! a halt with the resumed direction to 1e-7 rad. Each case kind is counted (per problem and
//! law): slip throughout, halt → stick, halt → resumed slip, swirl (turned > 10°), swirl near
//! zero (turned > 10° after σ fell below 1e-3 σ0), passed near zero (σ below 1e-3 σ0, then
//! grew tenfold without a halt), second compression, no initial slip; each must reach its
//! minimum. Counts and the largest deviations are printed
//! (`cargo test -p impax --test physics spatial_reference -- --nocapture`). Debug-build cost: most of the
//! time is the library's own integration (about 5 ms per law and problem unoptimised).

use impax::math::SplitMix64;
use impax::spatial::{ContactProblem, LawDetail, Outcome, PhaseKind};
use impax::LawId;
use std::f64::consts::{PI, TAU};

/// Agreement required between the reference and the library.
const TOL: f64 = 1e-9;
/// The accuracy target of the library's default tolerance: every largest deviation (with
/// the reference's own error of a few 1e-12 included) stays below this.
const TARGET: f64 = 1e-10;
/// Number of random problems.
const PROBLEMS: usize = 2_000;
/// Local tolerance of the reference integrator.
const RTOL: f64 = 1e-12;
/// The halt is declared when the impulse left to it is below this fraction of the scale.
const HALT_REST: f64 = 1e-14;
/// Step budget of the reference.
const MAX_STEPS: usize = 200_000;
const LAWS: [LawId; 3] = [LawId::Newton, LawId::Poisson, LawId::Energetic];

// ---------------------------------------------------------------------------------------
// Random numbers

// ---------------------------------------------------------------------------------------
// Problem data, read back through the public accessors

#[derive(Debug, Clone, Copy)]
struct Data {
    a: [[f64; 2]; 2],
    w: [f64; 2],
    wnn: f64,
    /// The slope of stick `w_nn − w_tnᵀ W_tt⁻¹ w_tn = det W / det W_tt` ([`schur`]).
    schur: f64,
    v: [f64; 3],
    mu: f64,
    e: f64,
}

impl Data {
    fn of(p: &ContactProblem) -> Self {
        let m = p.w();
        let v = p.velocity();
        Data {
            a: [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]],
            w: [m[(0, 2)], m[(1, 2)]],
            wnn: m[(2, 2)],
            schur: schur([
                m[(0, 0)],
                m[(0, 1)],
                m[(0, 2)],
                m[(1, 1)],
                m[(1, 2)],
                m[(2, 2)],
            ]),
            v: [v.x, v.y, v.z],
            mu: p.friction(),
            e: p.restitution(),
        }
    }
    fn a_times(&self, s: [f64; 2]) -> [f64; 2] {
        [
            self.a[0][0] * s[0] + self.a[0][1] * s[1],
            self.a[1][0] * s[0] + self.a[1][1] * s[1],
        ]
    }
    /// `g(ŝ) = w_tn − μ W_tt ŝ`.
    fn g(&self, s: [f64; 2]) -> [f64; 2] {
        let a = self.a_times(s);
        [self.w[0] - self.mu * a[0], self.w[1] - self.mu * a[1]]
    }
    /// `f(φ) = ŝ × g(ŝ)` and `q(φ) = ŝ·g(ŝ)`.
    fn fq(&self, phi: f64) -> (f64, f64) {
        let s = [phi.cos(), phi.sin()];
        let g = self.g(s);
        (s[0] * g[1] - s[1] * g[0], s[0] * g[0] + s[1] * g[1])
    }
    /// `W_tt⁻¹ w_tn`, by hand.
    fn att_inv_w(&self) -> [f64; 2] {
        let det = self.a[0][0] * self.a[1][1] - self.a[0][1] * self.a[1][0];
        [
            (self.a[1][1] * self.w[0] - self.a[0][1] * self.w[1]) / det,
            (-self.a[1][0] * self.w[0] + self.a[0][0] * self.w[1]) / det,
        ]
    }
    fn w_norm(&self) -> f64 {
        let mut s = self.wnn * self.wnn + 2.0 * (self.w[0] * self.w[0] + self.w[1] * self.w[1]);
        for r in &self.a {
            for x in r {
                s += x * x;
            }
        }
        s.sqrt()
    }
    fn v_norm(&self) -> f64 {
        (self.v[0] * self.v[0] + self.v[1] * self.v[1] + self.v[2] * self.v[2]).sqrt()
    }
}

/// `det W / det W_tt` by cofactors in double-double arithmetic (products of doubles exact by
/// `mul_add`, sums by two-sum): the Schur complement of `W_tt` to full double precision
/// however ill-conditioned `W` is (in double, `w_nn − w_tnᵀ W_tt⁻¹ w_tn` loses `κ` of its
/// digits: 4e-10 relative on case 614, `κ = 2e8`).
fn schur([a, b, c, d, e, f]: [f64; 6]) -> f64 {
    type D = (f64, f64);
    let sum = |x: D, y: D| -> D {
        let s = x.0 + y.0;
        let bb = s - x.0;
        let err = (x.0 - (s - bb)) + (y.0 - bb) + x.1 + y.1;
        let t = s + err;
        (t, err - (t - s))
    };
    let neg = |x: D| -> D { (-x.0, -x.1) };
    let prod = |x: f64, y: f64| -> D {
        let p = x * y;
        (p, x.mul_add(y, -p))
    };
    // x (a double-double) times y (a double).
    let scale = |x: D, y: f64| -> D {
        let p = prod(x.0, y);
        sum(p, (x.1 * y, 0.0))
    };
    // W = [[a, b, c], [b, d, e], [c, e, f]].
    let det2 = sum(prod(a, d), neg(prod(b, b)));
    let m1 = sum(prod(d, f), neg(prod(e, e)));
    let m2 = sum(prod(b, f), neg(prod(e, c)));
    let m3 = sum(prod(b, e), neg(prod(d, c)));
    let det3 = sum(sum(scale(m1, a), neg(scale(m2, b))), scale(m3, c));
    // The quotient to double precision: one correction of the leading quotient.
    let q = det3.0 / det2.0;
    let r = sum(det3, neg(sum(prod(q, det2.0), (q * det2.1, 0.0))));
    q + (r.0 + r.1) / det2.0
}

/// `(λ'I + μ W_tt)⁻¹ w_tn`.
fn shifted_solve(d: &Data, l: f64) -> [f64; 2] {
    let m = [
        [l + d.mu * d.a[0][0], d.mu * d.a[0][1]],
        [d.mu * d.a[1][0], l + d.mu * d.a[1][1]],
    ];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    [
        (m[1][1] * d.w[0] - m[0][1] * d.w[1]) / det,
        (-m[1][0] * d.w[0] + m[0][0] * d.w[1]) / det,
    ]
}

/// The resumption direction by bisection on `λ'`: `|(λ'I + μW_tt)⁻¹ w_tn|` decreases from
/// `|W_tt⁻¹ w_tn|/μ > 1` at `λ' = 0` to `≤ 1` at `λ' = |w_tn|`.
fn resumption(d: &Data) -> ([f64; 2], f64) {
    let n2 = |l: f64| {
        let x = shifted_solve(d, l);
        x[0] * x[0] + x[1] * x[1]
    };
    let (mut lo, mut hi) = (0.0f64, (d.w[0] * d.w[0] + d.w[1] * d.w[1]).sqrt());
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if n2(mid) > 1.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let x = shifted_solve(d, hi);
    let n = (x[0] * x[0] + x[1] * x[1]).sqrt();
    ([x[0] / n, x[1] / n], hi)
}

// ---------------------------------------------------------------------------------------
// The reference integration

#[derive(Debug, Clone, Copy, Default)]
struct St {
    p: f64,
    vt: [f64; 2],
    vn: f64,
    pt: [f64; 2],
    wn: f64,
    wt: f64,
}

type Y = [f64; 8];

impl St {
    fn y(&self) -> Y {
        [
            self.vt[0], self.vt[1], self.vn, self.p, self.pt[0], self.pt[1], self.wn, self.wt,
        ]
    }
    fn of(y: &Y) -> St {
        St {
            vt: [y[0], y[1]],
            vn: y[2],
            p: y[3],
            pt: [y[4], y[5]],
            wn: y[6],
            wt: y[7],
        }
    }
    fn sigma(&self) -> f64 {
        (self.vt[0] * self.vt[0] + self.vt[1] * self.vt[1]).sqrt()
    }
}

/// The slip system in `τ` (`dp_n = σ dτ`).
fn rhs(d: &Data, y: &Y) -> Y {
    let (v1, v2) = (y[0], y[1]);
    let sig = (v1 * v1 + v2 * v2).sqrt();
    let av = d.a_times([v1, v2]);
    [
        sig * d.w[0] - d.mu * av[0],
        sig * d.w[1] - d.mu * av[1],
        sig * d.wnn - d.mu * (d.w[0] * v1 + d.w[1] * v2),
        sig,
        -d.mu * v1,
        -d.mu * v2,
        y[2] * sig,
        -d.mu * sig * sig,
    ]
}

fn axpy(y: &Y, h: f64, k: &Y) -> Y {
    let mut o = *y;
    for i in 0..8 {
        o[i] += h * k[i];
    }
    o
}

fn rk4(d: &Data, y: &Y, h: f64) -> Y {
    let k1 = rhs(d, y);
    let k2 = rhs(d, &axpy(y, 0.5 * h, &k1));
    let k3 = rhs(d, &axpy(y, 0.5 * h, &k2));
    let k4 = rhs(d, &axpy(y, h, &k3));
    let mut o = *y;
    for i in 0..8 {
        o[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    o
}

/// One step-doubling RK4 step with Richardson extrapolation: (extrapolated, difference).
fn rstep(d: &Data, y: &Y, h: f64) -> (Y, Y) {
    let full = rk4(d, y, h);
    let half = rk4(d, &rk4(d, y, 0.5 * h), 0.5 * h);
    let mut diff = [0.0; 8];
    let mut out = half;
    for i in 0..8 {
        diff[i] = half[i] - full[i];
        out[i] += diff[i] / 15.0;
    }
    (out, diff)
}

/// What happened after the initial slip halted.
#[derive(Debug, Clone, Copy, PartialEq)]
enum After {
    NotHalted,
    Stick,
    Resumed(f64),
}

/// Shape of the slip path up to the halt or the end.
#[derive(Debug, Clone, Copy)]
struct Diag {
    sig0: f64,
    raw: f64,
    phi: f64,
    phi0: f64,
    max_turn: f64,
    sig_min: f64,
    below: Option<f64>,
    turn_below: f64,
    passed: bool,
}

impl Diag {
    fn new(st: &St) -> Self {
        let phi = st.vt[1].atan2(st.vt[0]);
        let sig = st.sigma();
        Diag {
            sig0: sig,
            raw: phi,
            phi,
            phi0: phi,
            max_turn: 0.0,
            sig_min: sig,
            below: None,
            turn_below: 0.0,
            passed: false,
        }
    }
    fn see(&mut self, st: &St) {
        let sig = st.sigma();
        if sig == 0.0 || self.sig0 == 0.0 {
            return;
        }
        let raw = st.vt[1].atan2(st.vt[0]);
        let mut dphi = raw - self.raw;
        while dphi > PI {
            dphi -= TAU;
        }
        while dphi < -PI {
            dphi += TAU;
        }
        self.raw = raw;
        self.phi += dphi;
        self.max_turn = self.max_turn.max((self.phi - self.phi0).abs());
        if sig < 1e-3 * self.sig0 && self.below.is_none() {
            self.below = Some(self.phi);
        }
        if let Some(b) = self.below {
            self.turn_below = self.turn_below.max((self.phi - b).abs());
        }
        if self.sig_min < 1e-3 * self.sig0 && sig > 10.0 * self.sig_min {
            self.passed = true;
        }
        self.sig_min = self.sig_min.min(sig);
    }
}

/// The reference's record of one law.
#[derive(Debug, Clone, Copy)]
struct LawEnd {
    st: St,
    pc: f64,
    wc: f64,
    second: Option<f64>,
    halt: Option<f64>,
    after: After,
    diag: Option<Diag>,
}

struct Ev<'a> {
    d: &'a Data,
    pc: Option<f64>,
    wc: f64,
    second: Option<f64>,
    /// Impulse of the compression phases after the first that have ended.
    comp: f64,
    /// Start of the current compression phase after the first.
    neg: Option<f64>,
    halt: Option<f64>,
    after: After,
    diag: Option<Diag>,
    ends: [Option<LawEnd>; 3],
}

const N_EVENTS: usize = 7;

impl Ev<'_> {
    fn term(&self, i: usize, st: &St) -> f64 {
        let d = self.d;
        match i {
            0 => st.vn + d.e * d.v[2],
            // Restitution impulse − e × compression impulse (every phase with v_n < 0).
            1 => {
                let c = self.pc.unwrap_or(f64::INFINITY)
                    + self.comp
                    + self.neg.map_or(0.0, |start| st.p - start);
                st.p - (1.0 + d.e) * c
            }
            _ => st.wn - (1.0 - d.e * d.e) * self.wc,
        }
    }
    /// Event `i` (0 compression, 1–3 the laws, 4 second compression, 5 and 6 the start of
    /// any later compression phase and the end of each): active, and its function, which
    /// crosses upward through zero at the event.
    fn value(&self, i: usize, st: &St) -> Option<f64> {
        match i {
            0 => self.pc.is_none().then_some(st.vn),
            1..=3 => {
                (self.pc.is_some() && self.ends[i - 1].is_none()).then(|| self.term(i - 1, st))
            }
            4 => (self.pc.is_some() && self.second.is_none()).then_some(-st.vn),
            5 => (self.second.is_some() && self.neg.is_none()).then_some(-st.vn),
            _ => self.neg.is_some().then_some(st.vn),
        }
    }
    fn end_law(&mut self, i: usize, st: &St) {
        self.ends[i] = Some(LawEnd {
            st: *st,
            pc: self.pc.expect("after compression"),
            wc: self.wc,
            second: self.second,
            halt: self.halt,
            after: self.after,
            diag: self.diag,
        });
    }
    fn apply(&mut self, i: usize, st: &St) {
        match i {
            0 => {
                self.pc = Some(st.p);
                self.wc = st.wn;
            }
            1..=3 => self.end_law(i - 1, st),
            4 | 5 => {
                self.second.get_or_insert(st.p);
                self.neg = Some(st.p);
            }
            _ => {
                self.comp += st.p - self.neg.take().expect("in a later compression");
            }
        }
        if self.pc.is_some() {
            for l in 0..3 {
                if self.ends[l].is_none() && self.term(l, st) >= 0.0 {
                    self.end_law(l, st);
                }
            }
        }
    }
    fn done(&self) -> bool {
        self.ends.iter().all(|e| e.is_some())
    }
    /// Events crossing between `a` and `b`.
    fn crossing(&self, a: &St, b: &St) -> [bool; N_EVENTS] {
        let mut c = [false; N_EVENTS];
        for (i, ci) in c.iter_mut().enumerate() {
            if let (Some(fa), Some(fb)) = (self.value(i, a), self.value(i, b)) {
                *ci = fa < 0.0 && fb >= 0.0;
            }
        }
        c
    }
}

/// Bisect `t ∈ (lo, hi]` with `f(lo) < 0 ≤ f(hi)` down to adjacent numbers; returns `hi`.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return hi;
        }
        if f(mid) >= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
}

/// A straight piece: slip `σ(x) ŝ = (σ0 + r x) ŝ`, friction ratio `k`, length `len`.
#[derive(Clone, Copy)]
struct Lin {
    k: [f64; 2],
    s: [f64; 2],
    sig: f64,
    r: f64,
    kn: f64,
    len: f64,
}

fn lin_at(d: &Data, a: &St, l: &Lin, x: f64) -> St {
    St {
        p: a.p + x,
        vt: [l.s[0] * (l.sig + l.r * x), l.s[1] * (l.sig + l.r * x)],
        vn: a.vn + l.kn * x,
        pt: [a.pt[0] + l.k[0] * x, a.pt[1] + l.k[1] * x],
        wn: a.wn + x * (a.vn + 0.5 * l.kn * x),
        wt: a.wt - d.mu * x * (l.sig + 0.5 * l.r * x),
    }
}

/// Run a straight piece from `st`, handling its events. Returns `false` if the piece is
/// infinite and some law never terminates on it (no separation).
fn run_piece(ev: &mut Ev, st: &mut St, l: Lin, pscale: f64) -> bool {
    let d = ev.d;
    let mut l = l;
    loop {
        if ev.done() {
            return true;
        }
        let a = *st;
        // Monotone intervals of every event function: split at the vertex of W_n.
        let mut cuts = vec![0.0];
        if l.kn != 0.0 {
            let xv = -a.vn / l.kn;
            if xv > 0.0 && xv < l.len {
                cuts.push(xv);
            }
        }
        cuts.push(l.len);
        let mut best: Option<(f64, usize)> = None;
        for i in 0..N_EVENTS {
            let f = |x: f64| ev.value(i, &lin_at(d, &a, &l, x)).unwrap_or(f64::NAN);
            if ev.value(i, &a).is_none() {
                continue;
            }
            for w in cuts.windows(2) {
                let (x0, mut x1) = (w[0], w[1]);
                if f(x0) >= 0.0 {
                    continue;
                }
                if !x1.is_finite() {
                    // Increasing on [x0, ∞)? Search by doubling.
                    let mut x = (x0 * 2.0).max(1e-3 * pscale);
                    let mut found = false;
                    for _ in 0..2100 {
                        if f(x) >= 0.0 {
                            found = true;
                            break;
                        }
                        x *= 2.0;
                        if !x.is_finite() {
                            break;
                        }
                    }
                    if !found {
                        continue;
                    }
                    x1 = x;
                }
                if f(x1) >= 0.0 {
                    let x = bisect(f, x0, x1);
                    if best.is_none_or(|(bx, _)| x < bx) {
                        best = Some((x, i));
                    }
                    break;
                }
            }
        }
        match best {
            Some((x, i)) => {
                *st = lin_at(d, &a, &l, x);
                ev.apply(i, st);
                l.sig += l.r * x;
                l.len -= x;
            }
            None => {
                if l.len.is_finite() {
                    *st = lin_at(d, &a, &l, l.len);
                    return true;
                }
                return false;
            }
        }
    }
}

/// Integrate the path of `d` to the termination of all three laws. `Err` if the reference
/// itself could not finish (step budget).
fn reference(d: &Data) -> Result<[Option<LawEnd>; 3], String> {
    let mut ev = Ev {
        d,
        pc: None,
        wc: 0.0,
        second: None,
        comp: 0.0,
        neg: None,
        halt: None,
        after: After::NotHalted,
        diag: None,
        ends: [None; 3],
    };
    let mut st = St {
        vt: [d.v[0], d.v[1]],
        vn: d.v[2],
        ..St::default()
    };
    let g_norm = (d.w[0] * d.w[0] + d.w[1] * d.w[1]).sqrt()
        + d.mu
            * (d.a[0][0] * d.a[0][0] + d.a[1][1] * d.a[1][1] + 2.0 * d.a[0][1] * d.a[0][1]).sqrt();
    let sig0 = st.sigma();
    let p0 = (1.0 + d.e) * -d.v[2] / d.wnn + sig0 / (g_norm + d.wnn);
    let wn = d.w_norm();
    if sig0 > 0.0 {
        ev.diag = Some(Diag::new(&st));
        let mut h = 1e-3 * (1.0 / (g_norm + d.wnn)).min(p0 / sig0);
        let mut steps = 0usize;
        loop {
            if ev.done() {
                return Ok(ev.ends);
            }
            let pscale = p0.max(st.p);
            // Halt: shrinking, and the impulse left is negligible.
            let sig = st.sigma();
            if sig == 0.0 {
                ev.halt = Some(st.p);
                break;
            }
            let s = [st.vt[0] / sig, st.vt[1] / sig];
            let g = d.g(s);
            let q = s[0] * g[0] + s[1] * g[1];
            if q < 0.0 && sig <= HALT_REST * -q * pscale {
                let l = Lin {
                    k: [-d.mu * s[0], -d.mu * s[1]],
                    s,
                    sig,
                    r: q,
                    kn: d.wnn - d.mu * (d.w[0] * s[0] + d.w[1] * s[1]),
                    len: sig / -q,
                };
                run_piece(&mut ev, &mut st, l, pscale);
                if ev.done() {
                    return Ok(ev.ends);
                }
                st.vt = [0.0, 0.0];
                ev.halt = Some(st.p);
                break;
            }
            steps += 1;
            if steps > MAX_STEPS {
                return Err(format!("reference: step budget exhausted at p = {}", st.p));
            }
            let y = st.y();
            let (y1, diff) = rstep(d, &y, h);
            let b = St::of(&y1);
            let vscale = d.v_norm() + wn * pscale.max(b.p);
            let sc = [
                sig.max(b.sigma()),
                sig.max(b.sigma()),
                vscale,
                pscale.max(b.p),
                pscale.max(b.p),
                pscale.max(b.p),
                vscale * pscale.max(b.p),
                vscale * pscale.max(b.p),
            ];
            let mut en = 0.0f64;
            for i in 0..8 {
                en = en.max(diff[i].abs() / 15.0 / (RTOL * sc[i]));
            }
            if en > 1.0 || en.is_nan() {
                h *= if en.is_finite() {
                    (0.9 * en.powf(-0.2)).max(0.1)
                } else {
                    0.1
                };
                continue;
            }
            let c = ev.crossing(&st, &b);
            if c.iter().any(|&x| x) {
                let mut best: Option<(f64, usize)> = None;
                for (i, &ci) in c.iter().enumerate() {
                    if !ci {
                        continue;
                    }
                    let f = |t: f64| {
                        let (yt, _) = rstep(d, &y, t * h);
                        ev.value(i, &St::of(&yt)).unwrap_or(f64::NAN)
                    };
                    let t = bisect(f, 0.0, 1.0);
                    if best.is_none_or(|(bt, _)| t < bt) {
                        best = Some((t, i));
                    }
                }
                let (t, i) = best.expect("some event");
                let (yt, _) = rstep(d, &y, t * h);
                st = St::of(&yt);
                if let Some(dg) = ev.diag.as_mut() {
                    dg.see(&st);
                }
                ev.apply(i, &st);
                continue;
            }
            st = b;
            if let Some(dg) = ev.diag.as_mut() {
                dg.see(&st);
            }
            h *= (0.9 * en.max(1e-12).powf(-0.2)).min(4.0);
        }
    }
    // Stick or resumed slip.
    let lam = d.att_inv_w();
    let lam_n = (lam[0] * lam[0] + lam[1] * lam[1]).sqrt();
    let l = if lam_n <= d.mu {
        ev.after = After::Stick;
        Lin {
            k: [-lam[0], -lam[1]],
            s: [0.0, 0.0],
            sig: 0.0,
            r: 0.0,
            kn: d.schur,
            len: f64::INFINITY,
        }
    } else {
        let (s, rate) = resumption(d);
        ev.after = After::Resumed(s[1].atan2(s[0]));
        Lin {
            k: [-d.mu * s[0], -d.mu * s[1]],
            s,
            sig: 0.0,
            r: rate,
            kn: d.wnn - d.mu * (d.w[0] * s[0] + d.w[1] * s[1]),
            len: f64::INFINITY,
        }
    };
    let pscale = p0.max(st.p);
    run_piece(&mut ev, &mut st, l, pscale);
    Ok(ev.ends)
}

// ---------------------------------------------------------------------------------------
// Case generation

/// The centripetal invariant rays of `d` by the test's own scan of `f(φ) = ŝ × g(ŝ)`.
fn centripetal_rays(d: &Data) -> Vec<f64> {
    let n = 720;
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (TAU * i as f64 / n as f64, TAU * (i + 1) as f64 / n as f64);
        let (fa, fb) = (d.fq(a).0, d.fq(b).0);
        if (fa < 0.0) != (fb < 0.0) {
            let up = fa < 0.0;
            let r = bisect(
                |x| {
                    let f = d.fq(x).0;
                    if up {
                        f
                    } else {
                        -f
                    }
                },
                a,
                b,
            );
            if d.fq(r).1 < 0.0 {
                out.push(r);
            }
        }
    }
    out
}

fn random_problem(rng: &mut SplitMix64) -> ContactProblem {
    let d1 = rng.decades(-1.0, 1.0);
    let aniso = if rng.unit() < 0.15 {
        1.0
    } else {
        rng.decades(0.0, 2.0)
    };
    let d2 = d1 * aniso;
    let th = rng.range(0.0, PI);
    let (s, c) = th.sin_cos();
    // W_tt = R diag(d1, d2) Rᵀ, W_tt^{1/2} = R diag(√d1, √d2) Rᵀ.
    let a00 = c * c * d1 + s * s * d2;
    let a01 = c * s * (d1 - d2);
    let a11 = s * s * d1 + c * c * d2;
    let (r1, r2) = (d1.sqrt(), d2.sqrt());
    let h00 = c * c * r1 + s * s * r2;
    let h01 = c * s * (r1 - r2);
    let h11 = s * s * r1 + c * c * r2;
    let wnn = rng.decades(-1.0, 1.0);
    let u = rng.unit();
    let rho = if u < 0.1 {
        0.0
    } else if u < 0.2 {
        1.0 - rng.decades(-6.0, -2.0)
    } else {
        rng.range(0.0, 0.95)
    };
    let ang = rng.range(0.0, TAU);
    let (uy, ux) = ang.sin_cos();
    let k = rho * wnn.sqrt();
    let w = [k * (h00 * ux + h01 * uy), k * (h01 * ux + h11 * uy)];
    // |W_tt⁻¹ w_tn|
    let det = a00 * a11 - a01 * a01;
    let li = [
        (a11 * w[0] - a01 * w[1]) / det,
        (-a01 * w[0] + a00 * w[1]) / det,
    ];
    let lam = (li[0] * li[0] + li[1] * li[1]).sqrt();
    let u = rng.unit();
    let mu = if u < 0.08 {
        0.0
    } else if u < 0.16 {
        2.0
    } else if u < 0.4 || lam == 0.0 {
        rng.range(0.0, 2.0)
    } else {
        (lam * rng.decades(-0.7, 0.7)).min(2.0)
    };
    let u = rng.unit();
    let e = if u < 0.1 {
        0.0
    } else if u < 0.2 {
        1.0
    } else {
        rng.unit()
    };
    let vn = -rng.decades(-1.0, 0.5);
    // (Only the slip field is read here: no Schur complement.)
    let d = Data {
        a: [[a00, a01], [a01, a11]],
        w,
        wnn,
        schur: f64::NAN,
        v: [0.0, 0.0, vn],
        mu,
        e,
    };
    let u = rng.unit();
    let vt = if u < 0.05 {
        [0.0, 0.0]
    } else if u < 0.30 {
        let rays = centripetal_rays(&d);
        let mag = -vn * rng.decades(-1.0, 1.5);
        let phi = if rays.is_empty() {
            rng.range(0.0, TAU)
        } else {
            let r = rays[(rng.unit() * rays.len() as f64) as usize % rays.len()];
            let off = rng.decades(-9.0, -2.0);
            if rng.unit() < 0.5 {
                r + off
            } else {
                r - off
            }
        };
        [mag * phi.cos(), mag * phi.sin()]
    } else {
        let mag = -vn * rng.decades(-3.0, 2.0);
        let phi = rng.range(0.0, TAU);
        [mag * phi.cos(), mag * phi.sin()]
    };
    ContactProblem::from_upper([a00, a01, w[0], a11, w[1], wnn], [vt[0], vt[1], vn], mu, e)
        .expect("valid by construction")
}

/// Problems in which `v_n` falls back to zero after the end of compression (jamb, a second
/// compression) for at least one law, found by a search with the reference over
/// `w_nn ∈ [0.01, 1]`, `ρ ∈ [0.68, 0.9999]`, `μ ∈ [0.3, 2]` (random `W` as above); `(upper
/// triangle of W, v⁻, μ, e)`.
#[rustfmt::skip]
const JAMB: [([f64; 6], [f64; 3], f64, f64); 12] = [
    ([1.1564291604083434, -0.5016036172190128, 0.08823338924369033, 3.342567048940835, -0.2748023136717309, 0.02467742153100455], [2.2869036770242928, 0.9396669445576561, -0.019340870246028725], 0.5697521181939844, 0.5052287040470193),
    ([0.16661826196580776, 0.027063160860579832, -0.0005023066028601789, 0.2910991383599021, 0.20264081783163365, 0.14354296176896192], [0.7976807588112713, -0.7428320769119697, -0.6401635712578261], 1.0723674047301115, 0.3864799281812821),
    ([12.129405136901985, 5.587037983517536, -1.7950064057080872, 3.504271236450969, -0.4609878911858632, 0.4102901440669608], [6.175508268389936, 9.242089803618239, -0.7075424570684112], 1.9259283145851933, 0.8439475529533114),
    ([16.325718554803004, -36.633295619580466, -1.7709787697250565, 100.20006726378054, 4.131410917548059, 0.1935566911143198], [1.487933156726654, -4.785821152390925, -0.1903922243091842], 0.5494121923427863, 0.09897749446413029),
    ([0.4149357720259681, 0.41032654784627454, 0.0028547434521008163, 11.647932180338069, 0.8573995712362017, 0.065294115017857], [-5.163909469207249, -0.8260182554962584, -0.03923705636563555], 1.276632930201577, 0.7921215754399715),
    ([0.31378217368107364, -0.3093620220948064, -0.2549437917410767, 0.689407858093842, 0.1669929272552694, 0.22648614631085412], [-14.84178552172543, -14.88692602555131, -0.70602180074754], 1.4815534032092845, 0.5666720040725903),
    ([0.7886824320497287, 2.9760208375366695, 0.5124135831989064, 14.797730572617434, 2.0471276001006746, 0.3778817255825857], [1.3067748052021808, -1.2618680041324808, -0.1066456971347513], 1.6517792283145536, 0.34261634446092826),
    ([0.23280445313040615, 0.091958747259067, 0.16382455744626523, 0.2785313596417337, 0.3038681363245782, 0.3563289467245894], [0.13225902523362715, -0.043632361357914304, -0.03065332305290523], 1.339508899647237, 0.7970059034994409),
    ([0.4242115082188655, 0.01550364158572882, -0.49051096910944286, 0.30067195317419537, -0.05230000780224741, 0.5801970483490396], [0.02695227199866624, -0.24670820485810177, -0.09741040114257794], 1.693696076368058, 0.83366391054773),
    ([13.163400728994432, 11.115904189561999, 0.4234410734197225, 12.676098121569472, 0.44507604421040825, 0.0159532947252051], [-3.798381364582911, -0.689762525047902, -0.06100195291670011], 1.9547915546867463, 0.2801090286745732),
    ([23.366501428489975, -13.42060750727748, -2.862229993752458, 11.50775875954415, 1.3370107558547768, 0.377083444802786], [0.678109578333684, -0.6382283896283989, -0.06698538473364064], 0.6756263239539236, 0.3552012788554596),
    ([1.7123427979035066, -4.184691626573996, 0.14403626511047102, 11.856249537811465, -0.4320429403722086, 0.017328408378864152], [-2.8104525891754504, -0.3811047826307195, -0.012192723635477964], 1.0450267837619442, 0.5314871292945529),
];

// ---------------------------------------------------------------------------------------
// Comparison

#[derive(Default, Clone, Copy)]
struct Worst {
    value: f64,
    case: usize,
}

impl Worst {
    fn see(&mut self, value: f64, case: usize) {
        if value > self.value || value.is_nan() {
            *self = Worst { value, case };
        }
    }
}

#[derive(Default)]
struct Tally {
    cases: usize,
    no_initial_slip: usize,
    slip_throughout: usize,
    halt_stick: usize,
    halt_resumed: usize,
    swirl: usize,
    swirl_near_zero: usize,
    passed_near_zero: usize,
    second_compression: usize,
    no_separation: usize,
    grazing: usize,
    worst: [Worst; 9],
    failures: Vec<String>,
}

const WORST_NAMES: [&str; 9] = [
    "impulse",
    "velocity after",
    "compression impulse",
    "W_c",
    "W_r",
    "W_t",
    "ΔT",
    "slip halt",
    "second compression",
];

fn check(case: usize, problem: &ContactProblem, t: &mut Tally) {
    let d = Data::of(problem);
    let ends = match reference(&d) {
        Ok(e) => e,
        Err(msg) => {
            t.failures.push(format!("case {case}: {msg}: {problem:?}"));
            return;
        }
    };
    for (li, law) in LAWS.iter().enumerate() {
        t.cases += 1;
        let out = law.resolve(problem);
        let r = match (ends[li], out) {
            (Some(r), Ok(o)) => (r, o),
            (None, Err(b)) if b.reason.id() == "no-separation" => {
                t.no_separation += 1;
                continue;
            }
            (r, o) => {
                t.failures.push(format!(
                    "case {case} {law}: reference {:?}, library {o:?}: {problem:?}",
                    r.map(|r| r.st)
                ));
                continue;
            }
        };
        let (r, o): (LawEnd, Outcome) = r;
        classify(&r, t);
        compare(case, *law, problem, &d, &r, &o, t);
    }
}

fn classify(r: &LawEnd, t: &mut Tally) {
    let Some(dg) = r.diag else {
        t.no_initial_slip += 1;
        return;
    };
    match (r.halt, r.after) {
        (Some(_), After::Stick) => t.halt_stick += 1,
        (Some(_), After::Resumed(_)) => t.halt_resumed += 1,
        _ => t.slip_throughout += 1,
    }
    if dg.max_turn > 10f64.to_radians() {
        t.swirl += 1;
    }
    if dg.below.is_some() && dg.turn_below > 10f64.to_radians() {
        t.swirl_near_zero += 1;
    }
    if dg.passed {
        t.passed_near_zero += 1;
    }
    if r.second.is_some() {
        t.second_compression += 1;
    }
}

#[allow(clippy::too_many_arguments)]
fn compare(
    case: usize,
    law: LawId,
    problem: &ContactProblem,
    d: &Data,
    r: &LawEnd,
    o: &Outcome,
    t: &mut Tally,
) {
    let s = &r.st;
    let p_ref = [s.pt[0], s.pt[1], s.p];
    let v_ref = [s.vt[0], s.vt[1], s.vn];
    let pn = (p_ref[0] * p_ref[0] + p_ref[1] * p_ref[1] + p_ref[2] * p_ref[2]).sqrt();
    let vscale = d.v_norm() + d.w_norm() * pn;
    let escale = d.v_norm() * pn + d.w_norm() * pn * pn;
    let dist = |a: [f64; 3], b: [f64; 3]| {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    };
    let po = [o.impulse.x, o.impulse.y, o.impulse.z];
    let vo = [o.velocity_after.x, o.velocity_after.y, o.velocity_after.z];
    let mut devs = [0.0f64; 9];
    devs[0] = dist(po, p_ref) / pn;
    devs[1] = dist(vo, v_ref) / vscale;
    devs[2] = match o.compression_impulse {
        Some(pc) => (pc - r.pc).abs() / pn,
        None => f64::INFINITY,
    };
    let w_c = r.wc;
    let w_r = s.wn - r.wc;
    devs[3] = (o.work.compression - w_c).abs() / escale;
    devs[4] = (o.work.restitution - w_r).abs() / escale;
    devs[5] = (o.work.friction - s.wt).abs() / escale;
    devs[6] = (o.energy_change - (s.wn + s.wt)).abs() / escale;
    let (halt, second) = match o.detail {
        LawDetail::DarbouxKeller {
            slip_halt,
            second_compression,
            ..
        } => (slip_halt, second_compression),
        _ => (None, None),
    };
    // A halt (or second compression) within TOL of the end may fall on either side.
    let near_end = |x: f64| (x - s.p).abs() <= TOL * pn;
    // A path that passes within 1e-8 σ0 of the origin where stick is impossible is, to
    // that order, the same as a halt followed by resumed slip: either report is right.
    let lam = d.att_inv_w();
    let grazing = r.diag.is_some_and(|g| g.sig_min <= 1e-8 * g.sig0)
        && (lam[0] * lam[0] + lam[1] * lam[1]).sqrt() > d.mu;
    devs[7] = match (halt, r.halt) {
        (Some(a), Some(b)) => (a - b).abs() / pn,
        (None, None) => 0.0,
        (Some(x), None) | (None, Some(x)) if near_end(x) => 0.0,
        (Some(_), None) | (None, Some(_)) if grazing => {
            t.grazing += 1;
            0.0
        }
        _ => f64::INFINITY,
    };
    devs[8] = match (second, r.second) {
        (Some(a), Some(b)) => (a - b).abs() / pn,
        (None, None) => 0.0,
        (Some(x), None) | (None, Some(x)) if near_end(x) => 0.0,
        _ => f64::INFINITY,
    };
    for (i, &dv) in devs.iter().enumerate() {
        t.worst[i].see(dv, case);
        if dv > TOL || dv.is_nan() {
            t.failures.push(format!(
                "case {case} {law}: {} deviates by {dv:e} (library {:?} / reference {:?}; \
                 halt {halt:?} vs {:?}, second {second:?} vs {:?}, after {:?}): {problem:?}",
                WORST_NAMES[i], o.impulse, p_ref, r.halt, r.second, r.after
            ));
        }
    }
    // The regime after the halt.
    if let (Some(_), Some(ph)) = (r.halt, o.phases.as_slice().get(1)) {
        let ok = match (ph.kind, r.after) {
            (PhaseKind::Stick, After::Stick) => true,
            (PhaseKind::Resumed { angle }, After::Resumed(b)) => {
                let dd = (angle - b).rem_euclid(TAU);
                dd.min(TAU - dd) <= 1e-7
            }
            // At the stick limit |W_tt⁻¹ w_tn| ≈ μ either regime is the same path.
            _ => {
                let l = d.att_inv_w();
                ((l[0] * l[0] + l[1] * l[1]).sqrt() - d.mu).abs() <= 1e-9 * d.mu
            }
        };
        if !ok {
            t.failures.push(format!(
                "case {case} {law}: after the halt the library has {:?}, the reference {:?}: {problem:?}",
                ph.kind, r.after
            ));
        }
    }
}

#[test]
fn darboux_keller_3d_agrees_with_an_independent_rk4_reference_on_2000_problems() {
    let mut rng = SplitMix64(0x05EA_71A1_3D3D);
    let mut problems: Vec<ContactProblem> =
        (0..PROBLEMS).map(|_| random_problem(&mut rng)).collect();
    problems.extend(
        JAMB.iter()
            .map(|&(w, v, mu, e)| ContactProblem::from_upper(w, v, mu, e).expect("valid")),
    );
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(8);
    // Interleaved, so that every thread gets its share of the expensive problems.
    let tallies: Vec<Tally> = std::thread::scope(|sc| {
        let problems = &problems;
        let hs: Vec<_> = (0..threads)
            .map(|k| {
                sc.spawn(move || {
                    let mut t = Tally::default();
                    for (i, p) in problems.iter().enumerate().skip(k).step_by(threads) {
                        check(i, p, &mut t);
                    }
                    t
                })
            })
            .collect();
        hs.into_iter()
            .map(|h| h.join().expect("no panic"))
            .collect()
    });
    let mut t = Tally::default();
    for x in tallies {
        t.cases += x.cases;
        t.no_initial_slip += x.no_initial_slip;
        t.slip_throughout += x.slip_throughout;
        t.halt_stick += x.halt_stick;
        t.halt_resumed += x.halt_resumed;
        t.swirl += x.swirl;
        t.swirl_near_zero += x.swirl_near_zero;
        t.passed_near_zero += x.passed_near_zero;
        t.second_compression += x.second_compression;
        t.no_separation += x.no_separation;
        t.grazing += x.grazing;
        for i in 0..t.worst.len() {
            if x.worst[i].value > t.worst[i].value || x.worst[i].value.is_nan() {
                t.worst[i] = x.worst[i];
            }
        }
        t.failures.extend(x.failures);
    }
    eprintln!(
        "spatial reference: {} (problem, law) pairs from {} problems ({PROBLEMS} random, {} jamb)",
        t.cases,
        problems.len(),
        JAMB.len()
    );
    eprintln!("  no initial slip (v_t⁻ = 0):       {}", t.no_initial_slip);
    eprintln!("  slip throughout (no halt):        {}", t.slip_throughout);
    eprintln!("  halt then stick:                  {}", t.halt_stick);
    eprintln!("  halt then resumed slip:           {}", t.halt_resumed);
    eprintln!("  swirl (turned > 10°):             {}", t.swirl);
    eprintln!(
        "  swirl near zero (σ < 1e-3 σ0, then turned > 10°): {}",
        t.swirl_near_zero
    );
    eprintln!(
        "  passed near zero (σ < 1e-3 σ0, then grew ×10):    {}",
        t.passed_near_zero
    );
    eprintln!(
        "  second compression:               {}",
        t.second_compression
    );
    eprintln!("  no separation (both agree):       {}", t.no_separation);
    eprintln!(
        "  grazing the origin (halt reported by one side only): {}",
        t.grazing
    );
    for (i, w) in t.worst.iter().enumerate() {
        eprintln!(
            "  largest deviation, {:<20} {:.3e} (case {})",
            WORST_NAMES[i], w.value, w.case
        );
    }
    for f in t.failures.iter().take(12) {
        eprintln!("FAIL {f}");
    }
    assert!(
        t.failures.is_empty(),
        "{} disagreements (first: {})",
        t.failures.len(),
        t.failures[0]
    );
    for (i, w) in t.worst.iter().enumerate() {
        assert!(
            w.value <= TARGET,
            "largest deviation of {} is {:.3e} (case {}), above the target {TARGET:e}",
            WORST_NAMES[i],
            w.value,
            w.case
        );
    }
    for (name, n, min) in [
        ("slip throughout", t.slip_throughout, 300),
        ("halt then stick", t.halt_stick, 300),
        ("halt then resumed slip", t.halt_resumed, 150),
        ("swirl", t.swirl, 300),
        ("swirl near zero", t.swirl_near_zero, 100),
        ("passed near zero", t.passed_near_zero, 100),
        ("no initial slip", t.no_initial_slip, 100),
        ("second compression", t.second_compression, 10),
    ] {
        assert!(n >= min, "only {n} cases of kind `{name}` (need {min})");
    }
}
