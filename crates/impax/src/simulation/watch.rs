//! Where the gaps of the open contacts are watched inside a step (planar and 3D runs alike):
//! at the step's regular watch times, and at more wherever a contact could reach its surface
//! and leave it again unseen between two of them.
//!
//! A gap is watched for a fall from positive to zero at discrete times; a contact that dips
//! through its surface and comes back between two of them is missed, and the motion goes on
//! through the surface (a short rod spinning at thousands of radians a second: one flight
//! step can hold several turns), and one that falls through between two of them may have
//! touched first earlier in that part. A part between two watch times is looked into when a
//! contact reaches its surface inside it, or could at its point's speed relative to the
//! surface (`min(φ_a, φ_b) ≤ 2 Δt max |ċ − ṡ|`), and then
//!
//! * while the bodies carrying it turn by more than [`TURN`] over the part (`|ω| Δt`, the
//!   larger of the two ends), it is cut into equal parts that each turn by less;
//! * then the cubic through the gaps and their rates at the two ends (Hermite) is looked at:
//!   where it dips below the contact's touching tolerance, the gap is watched at the cubic's
//!   least value too, and each side looked into again, [`DEPTH`] times at most.
//!
//! Both tests are local: a contact far from its surface, or one sliding along it without
//! approaching (a gap and rate of round-off), adds no time.

use crate::mechanism::dynamics;
use crate::mechanism::{Mechanism, Pose};
use num_dual::Dual64;

/// The most a body carrying a watched contact turns between two watch times, radians, near
/// its surface.
const TURN: f64 = 0.5;

/// How many times a part is looked into again, at most (each time a cut at the cubic's least
/// value, or into equal parts).
const DEPTH: u32 = 8;

/// The most equal parts one part is cut into.
const MAX_PARTS: f64 = 1024.0;

/// The open contacts' gaps and their rates of change at one time.
pub(crate) struct Probe {
    /// The time.
    pub t: f64,
    /// `φ_k`.
    pub gap: Vec<f64>,
    /// `φ̇_k`.
    pub rate: Vec<f64>,
    /// `|ċ − ṡ|`, the contact point's speed relative to its surface's point.
    pub speed: Vec<f64>,
    /// The largest `|ω|` of the bodies carrying the contact.
    pub spin: Vec<f64>,
    /// The touching tolerance.
    pub tol: Vec<f64>,
}

impl Probe {
    /// An empty probe at `t`, for the caller to fill contact by contact.
    pub(crate) fn at(t: f64, contacts: usize) -> Probe {
        Probe {
            t,
            gap: Vec::with_capacity(contacts),
            rate: Vec::with_capacity(contacts),
            speed: Vec::with_capacity(contacts),
            spin: Vec::with_capacity(contacts),
            tol: Vec::with_capacity(contacts),
        }
    }

    /// The planar mechanism's open contacts `open` at the state `y` (`q` its first `n`, `u`
    /// the next `n`): one dual-number pass of the poses and the contact points seeded
    /// `q + εu`.
    pub(crate) fn planar<M: Mechanism + ?Sized>(
        m: &M,
        open: &[usize],
        n: usize,
        t: f64,
        y: &[f64],
    ) -> Probe {
        let qd: Vec<Dual64> = (0..n).map(|i| Dual64::new(y[i], y[n + i])).collect();
        let zero = Dual64::from(0.0);
        let mut poses = vec![Pose::new(zero, zero, zero); m.bodies().len()];
        m.poses(&qd, &mut poses);
        let mut p = Probe::at(t, open.len());
        for &k in open {
            let nrm = m.contacts()[k].surface.normal;
            let c = m.contact_point(k, &qd);
            let s = m.surface_point(k, &qd);
            let (dx, dy) = (c[0] - s[0], c[1] - s[1]);
            p.gap.push(dx.re * nrm.x + dy.re * nrm.y);
            p.rate.push(dx.eps * nrm.x + dy.eps * nrm.y);
            p.speed.push(dx.eps.hypot(dy.eps));
            let body = poses[m.contacts()[k].body];
            let mut spin = body.angle.eps.abs();
            if let Some(other) = m.surface_body(k) {
                spin = spin.max(poses[other].angle.eps.abs());
            }
            p.spin.push(spin);
            p.tol.push(dynamics::touching_tolerance_of(
                [c[0].re, c[1].re],
                [s[0].re, s[1].re],
                [body.x.re, body.y.re],
            ));
        }
        p
    }
}

/// The times at which to watch the gaps in a step and the gaps there (the probe's contacts,
/// in its order).
pub(crate) type Watch = Vec<(f64, Vec<f64>)>;

/// The probes at which to watch the gaps in a step from `(t0, y0)`: the regular watch times
/// `times` (ascending, the step's end last; states `states`) and more inside the parts
/// between them ([`look_into`]), up to the end of the first part in which a gap falls
/// through zero. `interpolate` gives the state at any time of the step (its dense output),
/// `probe` the probe of a state.
pub(crate) fn watch_times(
    interpolate: impl Fn(f64, &mut [f64]),
    mut probe: impl FnMut(f64, &[f64]) -> Probe,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    states: &[Vec<f64>],
) -> Watch {
    let mut buf = vec![0.0; y0.len()];
    let mut at = |t: f64, known: Option<&[f64]>| match known {
        Some(y) => probe(t, y),
        None => {
            interpolate(t, &mut buf);
            probe(t, &buf)
        }
    };
    let mut out = Vec::with_capacity(times.len());
    let mut a = at(t0, Some(y0));
    for (&tj, yj) in times.iter().zip(states) {
        let b = at(tj, Some(yj));
        let crossed = look_into(&mut at, &a, &b, 0, &mut out);
        out.push((b.t, b.gap.clone()));
        if crossed {
            break;
        }
        a = b;
    }
    out
}

/// The part from `a` to `b`: the times and states to watch strictly inside it, in order,
/// pushed to `out`. True if a gap is found falling through zero in it (the parts after it
/// cannot hold the first event).
fn look_into(
    probe: &mut impl FnMut(f64, Option<&[f64]>) -> Probe,
    a: &Probe,
    b: &Probe,
    depth: u32,
    out: &mut Watch,
) -> bool {
    let dt = b.t - a.t;
    // Contact i reaches its surface inside the part (it may do so more than once: the first
    // time is wanted), or could at its speed.
    let near = |i: usize| {
        let (ga, gb) = (a.gap[i], b.gap[i]);
        (ga > 0.0 && gb <= 0.0)
            || (gb > 0.0 && ga.max(0.0).min(gb) <= 2.0 * dt * a.speed[i].max(b.speed[i]))
    };
    let crossed = (0..a.gap.len()).any(|i| a.gap[i] > 0.0 && b.gap[i] <= 0.0);
    let any_near = (0..a.gap.len()).any(near);
    let spin = (0..a.gap.len())
        .filter(|&i| near(i))
        .fold(0.0f64, |s, i| s.max(a.spin[i].max(b.spin[i]) * dt));
    if !any_near || depth >= DEPTH {
        return crossed;
    }
    if spin > TURN {
        // Turning fast: equal parts that each turn by less.
        let parts = (spin / TURN).ceil().min(MAX_PARTS) as usize;
        let mut prev: Option<Probe> = None;
        for j in 1..=parts {
            let next = (j < parts).then(|| probe(a.t + dt * j as f64 / parts as f64, None));
            let from = prev.as_ref().unwrap_or(a);
            let found = look_into(probe, from, next.as_ref().unwrap_or(b), depth + 1, out);
            if let Some(p) = &next {
                out.push((p.t, p.gap.clone()));
            }
            if found {
                return true;
            }
            if next.is_some() {
                prev = next;
            }
        }
        return crossed;
    }
    // The cubic through the gaps and rates at the ends: where it dips below the touching
    // tolerance, its least value.
    let mut cut: Option<f64> = None;
    for i in (0..a.gap.len()).filter(|&i| near(i)) {
        let (ga, gb) = (a.gap[i], b.gap[i]);
        if let Some((s, h)) = cubic_least(ga, a.rate[i] * dt, gb, b.rate[i] * dt) {
            if h < -a.tol[i] {
                cut = Some(cut.map_or(s, |c: f64| c.min(s)));
            }
        }
    }
    let Some(s) = cut else {
        return crossed;
    };
    let mid = probe(a.t + s * dt, None);
    if !(mid.t > a.t && mid.t < b.t) {
        return crossed;
    }
    let found = look_into(probe, a, &mid, depth + 1, out);
    out.push((mid.t, mid.gap.clone()));
    found || look_into(probe, &mid, b, depth + 1, out) || crossed
}

/// The least value of the cubic Hermite interpolant on `s ∈ (0, 1)` with values `g0`, `g1`
/// and derivatives `d0`, `d1` (per unit `s`) at the ends, and where: `None` if it has no
/// interior minimum.
fn cubic_least(g0: f64, d0: f64, g1: f64, d1: f64) -> Option<(f64, f64)> {
    // h(s) = g0 + d0 s + c2 s² + c3 s³.
    let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let c3 = 2.0 * (g0 - g1) + d0 + d1;
    let h = |s: f64| g0 + s * (d0 + s * (c2 + s * c3));
    // h'(s) = d0 + 2 c2 s + 3 c3 s².
    let (a, b, c) = (3.0 * c3, 2.0 * c2, d0);
    let mut roots = [f64::NAN; 2];
    if a.abs() <= 1e-14 * (b.abs() + c.abs()) {
        if b != 0.0 {
            roots[0] = -c / b;
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            let r = disc.sqrt();
            let qq = -0.5 * (b + b.signum() * r);
            roots = [qq / a, if qq != 0.0 { c / qq } else { f64::NAN }];
        }
    }
    roots
        .into_iter()
        .filter(|&s| s > 0.0 && s < 1.0)
        // A minimum: h'' = 2 c2 + 6 c3 s > 0.
        .filter(|&s| 2.0 * c2 + 6.0 * c3 * s > 0.0)
        .map(|s| (s, h(s)))
        .min_by(|x, y| x.1.total_cmp(&y.1))
}
