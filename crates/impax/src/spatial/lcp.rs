//! `lcp` in 3D: the velocity-level complementarity impact with the circular friction cone.
//!
//! The conditions are the planar law's ([`crate::planar::laws::lcp`]; Anitescu & Potra 1997,
//! Stewart & Trinkle 1996, here with the circular cone rather than a polyhedral one) with the
//! tangential velocity a 2-vector: with `W = [[A, w], [wᵀ, c]]` (`A = W_tt`, `w = w_tn`,
//! `c = w_nn`), `u = v_t⁻`, `N = −(1+e) v_n⁻ > 0`,
//!
//! ```text
//! v_n⁺ = −e v_n⁻ (p_n > 0);   |p_t| ≤ μ p_n;
//! v_t⁺ = 0 (stick)   or   p_t = −μ p_n v_t⁺/|v_t⁺| (slip: maximal dissipation on v_t⁺).
//! ```
//!
//! **Stick**: `W p = (−u, N)`, valid iff `p_n ≥ 0` and `|p_t| ≤ μ p_n`.
//!
//! **Slip** along `ŝ = (cos θ, sin θ)`: `p_t = −μ p_n ŝ`, the normal row gives
//! `p_n = N / D(θ)` with `D(θ) = c − μ w·ŝ` (needs `D > 0`), and
//! `v_t⁺(θ) = u + p_n (w − μ A ŝ)`. The direction is consistent iff `v_t⁺ = σ ŝ` with
//! `σ > 0`, i.e. iff `θ` is a root of
//!
//! ```text
//! F(θ) = D(θ) ŝ × u + N ŝ × (w − μ A ŝ)        (= D ŝ × v_t⁺)
//! ```
//!
//! with `D(θ) > 0` and `σ = ŝ·v_t⁺ > 0`. `F` is a trigonometric polynomial of degree 2
//! (`ŝ × Aŝ = A_12 cos 2θ + ½ (A_22 − A_11) sin 2θ`), so it has at most four roots on the
//! circle. They are found exactly: `F` is sampled at 256 angles, each sign change is bisected
//! to the last bit, and each interval without a sign change in which `F'` changes sign is
//! searched for a pair of close roots (bisection on `F'` to the extremum, then on `F` on
//! each side).
//!
//! Unlike the plane, where the conditions are the optimality conditions of a strictly convex
//! problem and have exactly one solution, the spatial conditions are not (eliminating `p_n`
//! tilts the cone) and an anisotropic `W` with tangential–normal coupling can give up to
//! three solutions (stick and two slips, or three slips). All are returned by [`solutions`];
//! [`resolve`] reports the one of least kinetic energy after and flags
//! [`Inconsistency::MultipleSolutions`]. When `w_tn = 0` the problem is again convex and the
//! solution unique. A planar problem embedded in 3D has its solutions at `θ ∈ {0, π}` (or
//! stick) and agrees with the planar law.

use super::laws::{assemble, straight};
use super::outcome::{Detail3, Phase3Kind, Resolution3};
use super::ContactProblem3;
use crate::law::LawId;
use crate::math::{cross2, Vec2, Vec3};
use crate::planar::{Breakdown, BreakdownReason, Inconsistency};
use std::f64::consts::TAU;

/// One solution of the spatial complementarity conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LcpSolution3 {
    /// `Stick`, or `Slip { from: θ, to: θ }` with `θ` the direction of the final slip.
    pub kind: Phase3Kind,
    /// Impulse on body A, `(p_t1, p_t2, p_n)`.
    pub impulse: Vec3,
    /// Contact velocity after, `v⁻ + W p` (tangential part exactly zero for stick).
    pub velocity_after: Vec3,
    /// `ΔT = ½ (v⁻ + v⁺)·p`.
    pub energy_change: f64,
}

/// Number of sample angles of the root search.
const SAMPLES: usize = 256;

/// The pieces of `F(θ)` and of the slip candidate at `θ`.
struct Slip<'a> {
    problem: &'a ContactProblem3,
    n: f64,
}

impl Slip<'_> {
    fn dir(theta: f64) -> Vec2 {
        let (s, c) = theta.sin_cos();
        Vec2::new(c, s)
    }
    /// `D(θ) = c − μ w·ŝ`.
    fn denominator(&self, s: Vec2) -> f64 {
        self.problem.wnn() - self.problem.friction() * self.problem.wtn().dot(&s)
    }
    /// `F(θ) = D ŝ × u + N ŝ × (w − μ A ŝ)`.
    fn f(&self, theta: f64) -> f64 {
        let p = self.problem;
        let s = Self::dir(theta);
        let g = p.wtn() - p.friction() * (p.wtt() * s);
        self.denominator(s) * cross2(s, p.velocity().xy()) + self.n * cross2(s, g)
    }
    /// `F'(θ)`, by differentiating each factor (`dŝ/dθ = ŝ⊥ = (−sin θ, cos θ)`).
    fn df(&self, theta: f64) -> f64 {
        let p = self.problem;
        let s = Self::dir(theta);
        let sp = Vec2::new(-s.y, s.x);
        let mu = p.friction();
        let u = p.velocity().xy();
        let g = p.wtn() - mu * (p.wtt() * s);
        let dg = -mu * (p.wtt() * sp);
        let dd = -mu * p.wtn().dot(&sp);
        dd * cross2(s, u)
            + self.denominator(s) * cross2(sp, u)
            + self.n * (cross2(sp, g) + cross2(s, dg))
    }
    /// The slip candidate at `θ`, if `D > 0` and `σ > 0`.
    fn candidate(&self, theta: f64) -> Option<LcpSolution3> {
        let p = self.problem;
        let s = Self::dir(theta);
        let d = self.denominator(s);
        if d <= 0.0 {
            return None;
        }
        let pn = self.n / d;
        let impulse = Vec3::new(-p.friction() * pn * s.x, -p.friction() * pn * s.y, pn);
        let velocity_after = p.velocity_after(impulse);
        if velocity_after.xy().dot(&s) <= 0.0 || !pn.is_finite() {
            return None;
        }
        Some(LcpSolution3 {
            kind: Phase3Kind::Slip {
                from: theta,
                to: theta,
            },
            impulse,
            velocity_after,
            energy_change: 0.5 * (p.velocity() + velocity_after).dot(&impulse),
        })
    }
}

/// Bisect `f` on `[a, b]` (opposite signs at the ends, or a zero at one) to the last bit.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let mut fa = f(a);
    if fa == 0.0 {
        return a;
    }
    if f(b) == 0.0 {
        return b;
    }
    loop {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            return m;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
}

/// Every root of `F` on `[0, 2π)` (at most four), ascending.
fn slip_angles(slip: &Slip<'_>) -> Vec<f64> {
    let h = TAU / SAMPLES as f64;
    let theta = |k: usize| if k == SAMPLES { TAU } else { k as f64 * h };
    let f: Vec<f64> = (0..=SAMPLES).map(|k| slip.f(theta(k))).collect();
    let scale = f.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut roots = Vec::new();
    if scale == 0.0 {
        // F ≡ 0: every direction is parallel to its slip velocity (no coupling, isotropic
        // A, no initial slip); then v_t⁺ = −μ p_n A ŝ opposes ŝ and no slip is consistent.
        return roots;
    }
    for k in 0..SAMPLES {
        let (a, b) = (theta(k), theta(k + 1));
        let (fa, fb) = (f[k], f[k + 1]);
        if fa == 0.0 {
            roots.push(a);
            continue;
        }
        if fb == 0.0 {
            continue; // counted at the next interval's start (or at θ = 0)
        }
        if (fa < 0.0) != (fb < 0.0) {
            roots.push(bisect(|t| slip.f(t), a, b));
            continue;
        }
        // No sign change: a pair of close roots needs an extremum of F inside whose value
        // has the other sign.
        let (da, db) = (slip.df(a), slip.df(b));
        if (da < 0.0) != (db < 0.0) && da != 0.0 && db != 0.0 {
            let m = bisect(|t| slip.df(t), a, b);
            let fm = slip.f(m);
            if fm == 0.0 {
                roots.push(m);
            } else if (fm < 0.0) != (fa < 0.0) {
                roots.push(bisect(|t| slip.f(t), a, m));
                roots.push(bisect(|t| slip.f(t), m, b));
            }
        }
    }
    roots
}

/// The sticking candidate: `W p = (−u, N)`, if `p_n ≥ 0` and `|p_t| ≤ μ p_n`.
fn stick(problem: &ContactProblem3, n: f64) -> Option<LcpSolution3> {
    let v = problem.velocity();
    let p = problem.w().cholesky()?.solve(&Vec3::new(-v.x, -v.y, n));
    if !(p.z >= 0.0 && p.xy().norm() <= problem.friction() * p.z) {
        return None;
    }
    let mut velocity_after = problem.velocity_after(p);
    velocity_after.x = 0.0;
    velocity_after.y = 0.0;
    Some(LcpSolution3 {
        kind: Phase3Kind::Stick,
        impulse: p,
        velocity_after,
        energy_change: 0.5 * (v + velocity_after).dot(&p),
    })
}

/// Every solution of the spatial complementarity conditions, in increasing kinetic energy
/// after (least first). Distinct solutions only: a slip whose impulse equals the sticking
/// impulse to 1e-10 (the stick/slip boundary, `σ → 0`) is not repeated.
///
/// ```
/// use impax::spatial::{ContactProblem3, lcp};
/// // A sphere (W = diag(7/2, 7/2, 1)): one solution.
/// let p = ContactProblem3::from_upper([3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [0.5, 0.2, -1.0], 0.3, 0.5)
///     .unwrap();
/// assert_eq!(lcp::solutions(&p).len(), 1);
/// ```
pub fn solutions(problem: &ContactProblem3) -> Vec<LcpSolution3> {
    let n = -(1.0 + problem.restitution()) * problem.velocity().z;
    let mut all: Vec<LcpSolution3> = stick(problem, n).into_iter().collect();
    if problem.friction() == 0.0 {
        // Frictionless: p = (0, 0, N/c) whatever the slip.
        let impulse = Vec3::new(0.0, 0.0, n / problem.wnn());
        let velocity_after = problem.velocity_after(impulse);
        let t = velocity_after.xy();
        let a = t.y.atan2(t.x);
        return vec![LcpSolution3 {
            kind: Phase3Kind::Slip { from: a, to: a },
            impulse,
            velocity_after,
            energy_change: 0.5 * (problem.velocity() + velocity_after).dot(&impulse),
        }];
    }
    let slip = Slip { problem, n };
    for theta in slip_angles(&slip) {
        if let Some(c) = slip.candidate(theta) {
            let scale = c.impulse.norm();
            if all
                .iter()
                .all(|o| (o.impulse - c.impulse).norm() > 1e-10 * scale)
            {
                let theta = if theta > std::f64::consts::PI {
                    theta - TAU
                } else {
                    theta
                };
                all.push(LcpSolution3 {
                    kind: Phase3Kind::Slip {
                        from: theta,
                        to: theta,
                    },
                    ..c
                });
            }
        }
    }
    all.sort_by(|a, b| a.energy_change.total_cmp(&b.energy_change));
    all
}

/// `lcp` in 3D: the solution of least kinetic energy after; several solutions are flagged
/// with [`Inconsistency::MultipleSolutions`], none (not observed) is a
/// [`BreakdownReason::NoSolution`].
pub fn resolve(problem: &ContactProblem3) -> Resolution3 {
    let law = LawId::Lcp;
    let all = solutions(problem);
    let Some(best) = all.first() else {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::NoSolution,
        });
    };
    let pn = best.impulse.z;
    let k = best.impulse.xy() / pn;
    let mut end = straight(problem, law, best.kind, k, pn);
    end.impulse = best.impulse;
    end.velocity = best.velocity_after;
    let inconsistency =
        (all.len() > 1).then_some(Inconsistency::MultipleSolutions { count: all.len() });
    Ok(assemble(
        problem,
        law,
        &end,
        Detail3::Lcp {
            solutions: all.len(),
        },
        inconsistency,
    ))
}
