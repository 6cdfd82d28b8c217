//! The watched event functions along a step of the series: each is a row of the series or a
//! sum of rows, so a polynomial in the step — where one rises above zero and falls back inside
//! the step ([`Series::first_rise`]), and where one crosses zero ([`Series::locate`]).

use super::{Series, F, ORDER, VN, VT};
use crate::multi::lzb::events::{Event, Watch};
use crate::multi::lzb::field::Field;
use crate::multi::lzb::state::{Modes, Setup, Tangent, PER, S};
use crate::numerics::roots::illinois;

impl<const N: usize> Series<N> {
    /// The first fraction `θ ∈ (0, 1]` of the step where one of the watched events'
    /// functions that is at or below zero at both ends of the step (`g_a`, `g_b`) rises above
    /// it, `skip` excepted (a separation's own end); `None` if none does. A step of the
    /// series is long (a fifth of its radius of convergence), and a function can rise above
    /// zero and fall back inside it — a slip that halts and would resume the same way —
    /// where its values at the two ends show nothing: the step is shortened to this point,
    /// where the crossing is then seen and located. Each function is a polynomial in the step
    /// ([`Series::event_poly`]).
    #[allow(clippy::too_many_arguments)]
    pub(in crate::multi::lzb) fn first_rise(
        &self,
        setup: &Setup,
        modes: &Modes,
        field: &Field,
        watch: &Watch,
        g_a: &[f64],
        g_b: &[f64],
        skip: Option<Event>,
    ) -> Option<f64> {
        let (k, h) = (N / PER, self.h);
        // The tails Σ_{k≥3} |c_k| h^k of `aux`'s rows and of the deflections, once for all:
        // a function that is one row, signed, is bounded as `rise` bounds it without its
        // polynomial being formed (the same sums, to the bit).
        let (mut tail_aux, mut tail_s) = ([0.0; N], [0.0; N]);
        let mut hp = h * h * h;
        for kk in 3..=ORDER {
            if kk < ORDER {
                for (t, a) in tail_aux.iter_mut().zip(&self.aux[kk]) {
                    *t += (a * hp).abs();
                }
            }
            for (j, t) in tail_s.iter_mut().enumerate().take(k) {
                *t += (self.c[kk][PER * j + S] * hp).abs();
            }
            hp *= h;
        }
        let mut first: Option<f64> = None;
        for i in 0..watch.n {
            if g_a[i] > 0.0 || g_b[i] > 0.0 || Some(watch.list[i]) == skip {
                continue;
            }
            // (sign, row's first three coefficients, tail) of a one-row function.
            let aux_row = |sign: f64, ix: usize| {
                let r = [self.aux[0][ix], self.aux[1][ix], self.aux[2][ix]];
                Some((sign, r, tail_aux[ix]))
            };
            let single = match watch.list[i] {
                Event::CompressionEnd(j) => aux_row(1.0, VN * k + j),
                Event::Recompression(j) | Event::Join(j) => aux_row(-1.0, VN * k + j),
                Event::Halt(j) => match modes.tangent[j] {
                    Tangent::Slip(sigma) => aux_row(-sigma, VT * k + j),
                    Tangent::Stick => continue,
                },
                Event::Separation(j) => {
                    let o = PER * j + S;
                    Some((-1.0, [self.c[0][o], self.c[1][o], self.c[2][o]], tail_s[j]))
                }
                Event::StickBreak(_) => None,
            };
            if let Some((sign, r, rest)) = single {
                let q0 = (sign * r[0] - watch.offset[i]).min(g_a[i]);
                if !may_rise(q0, sign * r[1] * h, sign * r[2] * h * h, rest) {
                    continue;
                }
            }
            let Some((mut q, q2)) = self.event_poly(setup, modes, field, watch, i) else {
                continue;
            };
            // (At the start, at most the function's value there: the same point, up to the
            // round-off of its velocities formed anew.)
            q[0] = q[0].min(g_a[i]);
            let mut rise = rise(&q, self.h);
            if let Some(mut other) = q2 {
                other[0] = other[0].min(g_a[i]);
                rise = match (rise, self::rise(&other, self.h)) {
                    (Some(a), Some(b)) => Some(a.min(b)),
                    (a, b) => a.or(b),
                };
            }
            if let Some(th) = rise {
                first = Some(first.map_or(th, |f: f64| f.min(th)));
            }
        }
        first
    }

    /// Where the `i`-th watched function, at or below zero at the step's start (`ga`) and
    /// above it at its end (`gb`), crosses zero: the fraction of the step, by the Illinois
    /// iteration on its polynomial ([`Series::event_poly`]).
    pub(in crate::multi::lzb) fn locate(
        &self,
        setup: &Setup,
        modes: &Modes,
        field: &Field,
        watch: &Watch,
        i: usize,
        (ga, gb): (f64, f64),
    ) -> f64 {
        let Some((q, q2)) = self.event_poly(setup, modes, field, watch, i) else {
            return 1.0;
        };
        let h = self.h;
        let g = |th: f64| {
            let t = th * h;
            let v = horner(&q, t);
            q2.map_or(v, |o| v.max(horner(&o, t)))
        };
        illinois(g, 0.0, ga, 1.0, gb)
    }

    /// The `i`-th watched function along the step as a polynomial in `t = θ h`, its offset
    /// subtracted: the velocities and forces are linear in the series' rows (`aux`, to order
    /// `ORDER − 1`), the deflection is a row (in the start's variable `z`, `q_j = s_j/τ`: the
    /// same sign and zero), so each function is a row or a sum of rows; a stick break's
    /// `|x_j| − μ_j F_j` as its two branches `±x_j − μ_j F_j` (`x = T F`). `None` for a halt
    /// watched in stick (no function).
    pub(super) fn event_poly(
        &self,
        setup: &Setup,
        modes: &Modes,
        field: &Field,
        watch: &Watch,
        i: usize,
    ) -> Option<([f64; ORDER + 1], Option<[f64; ORDER + 1]>)> {
        let k = N / PER;
        let mut q = [0.0; ORDER + 1];
        let mut q2: Option<[f64; ORDER + 1]> = None;
        match watch.list[i] {
            Event::CompressionEnd(j) => {
                for (qk, a) in q.iter_mut().zip(&self.aux) {
                    *qk = a[VN * k + j];
                }
            }
            Event::Separation(j) => {
                for (qk, c) in q.iter_mut().zip(&self.c) {
                    *qk = -c[PER * j + S];
                }
            }
            Event::Recompression(j) | Event::Join(j) => {
                for (qk, a) in q.iter_mut().zip(&self.aux) {
                    *qk = -a[VN * k + j];
                }
            }
            Event::Halt(j) => {
                let Tangent::Slip(sigma) = modes.tangent[j] else {
                    return None;
                };
                for (qk, a) in q.iter_mut().zip(&self.aux) {
                    *qk = -sigma * a[VT * k + j];
                }
            }
            Event::StickBreak(j) => {
                let row = field.map_row(j);
                let mut other = [0.0; ORDER + 1];
                for ((qk, ok), a) in q.iter_mut().zip(other.iter_mut()).zip(&self.aux) {
                    let x: f64 = (0..k).map(|c| row[c] * a[F * k + c]).sum();
                    let mf = setup.mu[j] * a[F * k + j];
                    *qk = x - mf;
                    *ok = -x - mf;
                }
                other[0] -= watch.offset[i];
                q2 = Some(other);
            }
        }
        q[0] -= watch.offset[i];
        Some((q, q2))
    }
}

/// Whether `Q₀ + Q₁ θ + (Q₂ + rest) θ²` (`rest = Σ_{k≥3} |Q_k|`, [`rise`]'s bound of a
/// polynomial on `θ ∈ [0, 1]`) rises above zero there (not for a NaN).
#[inline]
fn may_rise(q0: f64, q1: f64, q2: f64, rest: f64) -> bool {
    let c = q2 + rest;
    let mut bound = q0.max(q0 + q1 + c);
    if c < 0.0 && q1 > 0.0 && q1 < -2.0 * c {
        bound = bound.max(q0 - q1 * q1 / (4.0 * c));
    }
    bound > 0.0
}

/// `Σ_k q_k t^k` (Horner).
#[inline]
pub(super) fn horner(q: &[f64; ORDER + 1], t: f64) -> f64 {
    q.iter().rev().fold(0.0, |v, qk| v * t + qk)
}

/// Where the polynomial `q(t) = Σ q_k t^k` (`q(0) ≤ 0`) first rises above zero on
/// `t = θ h`, `θ ∈ (0, 1]`: `None` if a bound of it is at most zero there (in `θ`, with
/// `Q_k = q_k h^k`: the largest value of `Q₀ + Q₁ θ + (Q₂ + Σ_{k≥3} |Q_k|) θ²`); else the
/// first of 16 equally spaced points where `q > 0`, or, in an interval between two of them
/// where `dq/dθ` falls through zero, its maximum (Newton's iteration on `dq/dθ`, kept
/// inside the bracket) if `q` is above zero there.
pub(super) fn rise(q: &[f64; ORDER + 1], h: f64) -> Option<f64> {
    // In θ (Q_k = q_k h^k): q ≤ Q₀ + Q₁ θ + (Q₂ + Σ_{k≥3} |Q_k|) θ² on [0, 1].
    let (q1, q2) = (q[1] * h, q[2] * h * h);
    let (mut rest, mut hp) = (0.0, h * h * h);
    for qk in &q[3..] {
        rest += (qk * hp).abs();
        hp *= h;
    }
    if !may_rise(q[0], q1, q2, rest) {
        return None;
    }
    // q, dq/dθ and d²q/dθ² at θ.
    let at = |th: f64| {
        let t = th * h;
        let (mut v, mut d, mut dd) = (q[ORDER], 0.0, 0.0);
        for qk in q[..ORDER].iter().rev() {
            dd = dd * t + d;
            d = d * t + v;
            v = v * t + qk;
        }
        (v, d * h, 2.0 * dd * h * h)
    };
    // The round-off of dq/dθ on [0, 1]: 8 ε Σ_k k |q_k h^k|.
    let slope_round_off = || {
        let (mut sum, mut hp) = (0.0, h.abs());
        for (k, qk) in q.iter().enumerate().skip(1) {
            sum += k as f64 * (qk * hp).abs();
            hp *= h.abs();
        }
        8.0 * f64::EPSILON * sum
    };
    // q and dq/dt at the samples, their Horner chains side by side (each waits on itself
    // alone).
    const SAMPLES: usize = 16;
    let t: [f64; SAMPLES] = std::array::from_fn(|m| (m + 1) as f64 / SAMPLES as f64 * h);
    let (mut vs, mut ds) = ([q[ORDER]; SAMPLES], [0.0; SAMPLES]);
    for qk in q[..ORDER].iter().rev() {
        for ((v, d), t) in vs.iter_mut().zip(&mut ds).zip(&t) {
            *d = *d * t + *v;
            *v = *v * t + qk;
        }
    }
    let (mut th0, mut d0) = (0.0, q1);
    for m in 1..=SAMPLES {
        let th1 = m as f64 / SAMPLES as f64;
        let (v1, d1) = (vs[m - 1], ds[m - 1] * h);
        if v1 > 0.0 {
            return Some(th1);
        }
        if d0 > 0.0 && d1 < 0.0 {
            if let Some(th) =
                top(&at, (th0, th1), d1, slope_round_off()).filter(|&th| at(th).0 > 0.0)
            {
                return Some(th);
            }
        }
        (th0, d0) = (th1, d1);
    }
    None
}

/// The maximum of `q` between `th0` and `th1`, where its slope falls from above zero to `d1`
/// below it (`at(θ)`: `q`, `dq/dθ`, `d²q/dθ²`): Newton's steps on `dq/dθ` kept inside the bracket
/// (halving it where one would leave it), to where `dq/dθ` is zero to its round-off `flat`.
/// `None` where the slope at `th1` is zero to round-off: the maximum is there, at or below
/// zero (a function that reaches zero at the step's end as a power, `−c (1 − θ)³`, the
/// separating contact's stick-break function where it lands, would otherwise be searched
/// for a top through its round-off).
fn top(
    at: &impl Fn(f64) -> (f64, f64, f64),
    (th0, th1): (f64, f64),
    d1: f64,
    flat: f64,
) -> Option<f64> {
    if d1 >= -flat {
        return None;
    }
    let (mut lo, mut hi) = (th0, th1);
    let mut th = 0.5 * (lo + hi);
    for _ in 0..60 {
        let (_, d, dd) = at(th);
        if d.abs() <= flat {
            break;
        }
        if d > 0.0 {
            lo = th;
        } else {
            hi = th;
        }
        let newton = th - d / dd;
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - th).abs() <= 4.0 * f64::EPSILON * th || hi - lo <= f64::EPSILON * hi {
            break;
        }
        th = next;
    }
    Some(th)
}
