//! Invariant slip directions of the spatial Darboux–Keller equations and the direction in
//! which slip resumes after an unstable stick (theory §2, "Spatial").
//!
//! During slip the tangential contact velocity `v_t = σ ŝ`, `ŝ = (cos φ, sin φ)`, obeys
//!
//! ```text
//! dv_t/dp_n = g(ŝ) = w_tn − μ W_tt ŝ,    dσ/dp_n = ŝ·g,    dφ/dp_n = (ŝ × g)/σ.
//! ```
//!
//! The field depends on the direction only, so the rays with `ŝ × g(φ) = 0` are invariant:
//!
//! ```text
//! f(φ) = w2 cos φ − w1 sin φ − μ [W12 cos 2φ + ½ (W22 − W11) sin 2φ] = 0,
//! ```
//!
//! a trigonometric polynomial of degree 2, so at most four rays. A ray is *centripetal* when
//! `ŝ·g < 0` on it (slip along it decreases to a halt), *centrifugal* when `ŝ·g > 0`. With
//! `t = tan(φ/2)`, `f = 0` becomes the quartic
//! `(C − A) t⁴ + (2B − 4D) t³ − 6C t² + (2B + 4D) t + (A + C) = 0` (`A = w2`, `B = −w1`,
//! `C = −μ W12`, `D = −μ (W22 − W11)/2`), solved through its companion matrix and polished by
//! Newton's method on `f(φ)` itself.

use super::ContactProblem;
use crate::math::{Mat2, Vec2};
use nalgebra::Matrix4;

/// Whether slip along an invariant ray shrinks or grows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RayKind {
    /// `ŝ·g < 0`: the slip speed decreases along the ray; trajectories end here at a halt.
    Centripetal,
    /// `ŝ·g > 0`: the slip speed grows along the ray; slip resumes along such a ray.
    Centrifugal,
    /// `ŝ·g = 0` on the ray (a degenerate, neutral ray).
    Neutral,
}

impl RayKind {
    /// Stable id: `centripetal`, `centrifugal`, `neutral`.
    pub fn id(self) -> &'static str {
        match self {
            RayKind::Centripetal => "centripetal",
            RayKind::Centrifugal => "centrifugal",
            RayKind::Neutral => "neutral",
        }
    }
}

/// One invariant ray: its angle `φ ∈ [0, 2π)` in the tangent plane, its type, and the rate
/// `dσ/dp_n = ŝ·g` along it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvariantRay {
    /// Angle of the ray, radians in `[0, 2π)`.
    pub angle: f64,
    /// Centripetal or centrifugal.
    pub kind: RayKind,
    /// `ŝ·g` on the ray.
    pub rate: f64,
}

/// The invariant rays of a problem (at most four), or all directions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InvariantRays {
    /// Every direction is invariant (`f ≡ 0`, e.g. isotropic `W_tt` with `w_tn = 0`: no
    /// swirl at all).
    All,
    /// Finitely many rays, sorted by angle.
    Rays {
        /// The rays (the first `len` entries are used).
        rays: [InvariantRay; 4],
        /// How many.
        len: usize,
    },
}

impl InvariantRays {
    /// The rays as a slice (empty for [`InvariantRays::All`]).
    pub fn as_slice(&self) -> &[InvariantRay] {
        match self {
            InvariantRays::All => &[],
            InvariantRays::Rays { rays, len } => &rays[..*len],
        }
    }
}

/// `g(ŝ) = w_tn − μ W_tt ŝ`.
#[inline]
pub(crate) fn slip_rate(wtt: &Mat2, wtn: Vec2, mu: f64, s: Vec2) -> Vec2 {
    wtn - mu * (wtt * s)
}

/// The invariant rays of the problem's slip field.
pub fn invariant_rays(problem: &ContactProblem) -> InvariantRays {
    rays_of(&problem.wtt(), problem.wtn(), problem.friction())
}

/// [`invariant_rays`] of the slip field `g(ŝ) = w − μ W_tt ŝ`.
pub(crate) fn rays_of(wtt: &Mat2, w: Vec2, mu: f64) -> InvariantRays {
    let wtt = *wtt;
    let a = w.y;
    let b = -w.x;
    let c = -mu * wtt[(0, 1)];
    let d = -0.5 * mu * (wtt[(1, 1)] - wtt[(0, 0)]);
    let scale = w.norm() + mu * wtt.norm();
    let f =
        |phi: f64| a * phi.cos() + b * phi.sin() + c * (2.0 * phi).cos() + d * (2.0 * phi).sin();
    let df = |phi: f64| {
        -a * phi.sin() + b * phi.cos() - 2.0 * c * (2.0 * phi).sin() + 2.0 * d * (2.0 * phi).cos()
    };
    if a.abs() + b.abs() + c.abs() + d.abs() <= 1e-14 * scale.max(f64::MIN_POSITIVE) {
        return InvariantRays::All;
    }
    // Quartic in t = tan(φ/2), coefficients from t⁴ down to t⁰.
    let q = [c - a, 2.0 * b - 4.0 * d, -6.0 * c, 2.0 * b + 4.0 * d, a + c];
    let mut cands = [0.0f64; 5];
    let mut n = 0;
    // φ = π (t = ∞) is a root when f(π) = −A + C vanishes.
    if f(std::f64::consts::PI).abs() <= 1e-13 * scale {
        cands[n] = std::f64::consts::PI;
        n += 1;
    }
    // Degree drops while leading coefficients vanish.
    let qmax = q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut lead = 0;
    while lead < 4 && q[lead].abs() <= 1e-14 * qmax {
        lead += 1;
    }
    let deg = 4 - lead;
    let mut roots = [0.0f64; 4];
    let mut nr = 0;
    match deg {
        0 => {}
        1 => {
            roots[0] = -q[4] / q[3];
            nr = 1;
        }
        _ => {
            // Companion matrix of the monic polynomial of degree `deg` (padded to 4×4 with
            // a block that contributes no real roots of interest).
            let mut m = Matrix4::<f64>::zeros();
            for i in 0..deg {
                m[(0, i)] = -q[lead + 1 + i] / q[lead];
            }
            for i in 1..deg {
                m[(i, i - 1)] = 1.0;
            }
            let eig = m.complex_eigenvalues();
            for (i, z) in eig.iter().enumerate() {
                if i >= deg {
                    break;
                }
                if z.im.abs() <= 1e-6 * (1.0 + z.re.abs()) {
                    roots[nr] = z.re;
                    nr += 1;
                }
            }
        }
    }
    for &t in &roots[..nr] {
        if n < cands.len() {
            cands[n] = 2.0 * t.atan();
            n += 1;
        }
    }
    // Polish with Newton on f(φ), keep true roots, normalise to [0, 2π), dedupe.
    let mut rays = [InvariantRay {
        angle: 0.0,
        kind: RayKind::Neutral,
        rate: 0.0,
    }; 4];
    let mut len = 0;
    let two_pi = std::f64::consts::TAU;
    for &phi0 in &cands[..n] {
        let mut phi = phi0;
        for _ in 0..20 {
            let d1 = df(phi);
            if d1 == 0.0 {
                break;
            }
            let step = f(phi) / d1;
            phi -= step;
            if step.abs() <= 1e-16 * (1.0 + phi.abs()) {
                break;
            }
        }
        if f(phi).abs() > 1e-10 * scale {
            continue;
        }
        let phi = phi.rem_euclid(two_pi);
        let dup = rays[..len].iter().any(|r| {
            let dd = (r.angle - phi).abs();
            dd.min(two_pi - dd) < 1e-9
        });
        if dup || len == 4 {
            continue;
        }
        let s = Vec2::new(phi.cos(), phi.sin());
        let rate = s.dot(&slip_rate(&wtt, w, mu, s));
        let kind = if rate < 0.0 {
            RayKind::Centripetal
        } else if rate > 0.0 {
            RayKind::Centrifugal
        } else {
            RayKind::Neutral
        };
        rays[len] = InvariantRay {
            angle: phi,
            kind,
            rate,
        };
        len += 1;
    }
    rays[..len].sort_by(|x, y| x.angle.total_cmp(&y.angle));
    InvariantRays::Rays { rays, len }
}

/// The stick test (theory §2): the friction ratio that keeps `v_t = 0` is
/// `λ = −W_tt⁻¹ w_tn`; stick holds iff `|λ| ≤ μ`. Returns `λ`, from the factorisation
/// `W = L D Lᵀ` (order `t1, t2, n`): `λ = −(l31 − l21 l32, l32)` (backward stable, where the
/// explicit inverse of an ill-conditioned `W_tt` is not).
#[inline]
pub fn sticking_ratio(problem: &ContactProblem) -> Vec2 {
    problem.stick().0
}

/// The direction `ŝ` along which slip resumes when stick cannot hold (`|W_tt⁻¹ w_tn| > μ`),
/// and the rate `λ' = dσ/dp_n > 0`: the unique solution of `(λ' I + μ W_tt) ŝ = w_tn`,
/// `|ŝ| = 1` (theory §2).
///
/// In the eigenbasis `W_tt = Q diag(d1, d2) Qᵀ`, `w̃ = Qᵀ w_tn`, `λ'` solves the secular
/// equation `Σ w̃ᵢ² / (λ' + μ dᵢ)² = 1`, whose left side decreases strictly and convexly:
/// Newton's method from a point left of the root (`max(0, |w̃| − μ d_max)`) converges
/// monotonically.
pub fn resumption_direction(problem: &ContactProblem) -> Option<(Vec2, f64)> {
    resumption_ray(&problem.wtt(), problem.wtn(), problem.friction())
}

/// [`resumption_direction`] of the slip field `g(ŝ) = w − μ W_tt ŝ` (`W_tt` symmetric
/// positive semidefinite): the unit `ŝ` and `λ' > 0` with `(λ' I + μ W_tt) ŝ = w`, if any.
pub(crate) fn resumption_ray(wtt: &Mat2, w: Vec2, mu: f64) -> Option<(Vec2, f64)> {
    let wtt = *wtt;
    if mu == 0.0 {
        // Frictionless: g = w_tn whatever the direction; slip leaves along w_tn.
        let n = w.norm();
        return (n > 0.0).then(|| (w / n, n));
    }
    let eig = nalgebra::SymmetricEigen::new(wtt);
    let wq = eig.eigenvectors.transpose() * w;
    let d = eig.eigenvalues;
    let secular = |l: f64| {
        let a = wq.x / (l + mu * d.x);
        let b = wq.y / (l + mu * d.y);
        let f = a * a + b * b - 1.0;
        let df = -2.0 * (a * a / (l + mu * d.x) + b * b / (l + mu * d.y));
        (f, df)
    };
    let (f0, _) = secular(0.0);
    if f0.is_nan() || f0 <= 0.0 {
        return None;
    }
    // Start at the lower bound λ' ≥ |w̃| − μ d_max of the root (every term there is at
    // least w̃ᵢ²/|w̃|², so the secular function is ≥ 0): from 0 a tiny μ would make it
    // overflow.
    let mut l = (wq.norm() - mu * d.x.max(d.y)).max(0.0);
    for _ in 0..100 {
        let (f, df) = secular(l);
        let step = -f / df;
        let next = l + step;
        if next.is_nan() || next <= l || step <= 1e-16 * next {
            l = next.max(l);
            break;
        }
        l = next;
    }
    ray_at(&wtt, w, mu, l).map(|(s, _)| (s, l))
}

/// The unit direction of `(λ' I + μ W_tt)⁻¹ w` at `λ'`, polished onto the ray, and the
/// squared length of that solve (the secular function plus one): [`resumption_ray`]'s ray
/// at its root, or, at `λ' = 0`, the limit the ray tends to as a stick reaches its cone.
pub(crate) fn ray_at(wtt: &Mat2, w: Vec2, mu: f64, l: f64) -> Option<(Vec2, f64)> {
    let m = Mat2::identity() * l + mu * wtt;
    let s = m.try_inverse()? * w;
    let n2 = s.norm_squared();
    let s = s / n2.sqrt();
    // The solve loses κ(λ' I + μ W_tt) ε in the direction, much where λ' is small beside
    // μ W_tt (near the stick limit of an ill-conditioned W); the ray is a root of
    // f(φ) = ŝ × g(ŝ), which Newton's method on f (evaluated to round-off of its
    // coefficients) polishes to the last bits.
    Some((polish_ray(wtt, w, mu, s).unwrap_or(s), n2))
}

/// The root of `f(ŝ) = ŝ × (w_tn − μ W_tt ŝ)` next to the direction `s` (an accurate start),
/// by at most three Newton steps in the angle, each a rotation of the unit vector (`f` and
/// `df/dφ` from its components: an `s` with `f(s) = 0`, e.g. `(±1, 0)` of a planar problem,
/// stays exactly as it is). `None` if the steps turn by more than 1e-6 rad (`s` is not next
/// to a ray); `s` itself if they do not reduce `|f|` (it is on the ray to round-off).
pub(crate) fn polish_ray(wtt: &Mat2, w: Vec2, mu: f64, s: Vec2) -> Option<Vec2> {
    // f(s) = s × g(s) and df/dφ = s' × g(s) − μ s × W_tt s', s' = (−s_y, s_x).
    let f_df = |s: Vec2| {
        let g = slip_rate(wtt, w, mu, s);
        let sp = Vec2::new(-s.y, s.x);
        let h = wtt * sp;
        (
            s.x * g.y - s.y * g.x,
            sp.x * g.y - sp.y * g.x - mu * (s.x * h.y - s.y * h.x),
        )
    };
    let (f0, _) = f_df(s);
    let mut x = s;
    let mut turned = 0.0f64;
    for _ in 0..3 {
        let (f, df) = f_df(x);
        if f == 0.0 || df == 0.0 {
            break;
        }
        let d = -f / df;
        turned += d;
        let (sd, cd) = d.sin_cos();
        x = Vec2::new(x.x * cd - x.y * sd, x.y * cd + x.x * sd);
        x /= x.norm();
    }
    if turned.is_nan() || turned.abs() > 1e-6 {
        None
    } else if f_df(x).0.abs() < f0.abs() {
        Some(x)
    } else {
        Some(s)
    }
}
