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
//! with `D(θ) > 0` and `σ = ŝ·v_t⁺ > 0`. At a root `p_n` is also `−(ŝ × u)/(ŝ × g)`
//! (`g = w − μ A ŝ`; `v_t⁺` has no component across `ŝ`); the expression with the smaller
//! estimated round-off is used — for a grazing impact on a strongly coupled `W`, `D` is a
//! small difference of large terms and `N/D` can be off by percents. The solution is
//! reported with `v_n⁺ = −e v_n⁻` and `v_t⁺ = σ ŝ` exactly (`v⁻ + W p` meets them to the
//! round-off of its terms). `F` is a trigonometric polynomial of degree 2
//! (`ŝ × Aŝ = A_12 cos 2θ + ½ (A_22 − A_11) sin 2θ`), so it has at most four roots on the
//! circle. They are found to the last bit: `F` (in the coefficient form below) is sampled at
//! 256 angles, each sign change is refined by safeguarded Newton steps inside the bracket,
//! and each interval without a sign change in which `F'` changes sign is searched for a pair
//! of close roots (the extremum of `F` first, then each side).
//!
//! Unlike the plane, where the conditions are the optimality conditions of a strictly convex
//! problem and have exactly one solution, the spatial conditions are not (eliminating `p_n`
//! tilts the cone) and an anisotropic `W` with tangential–normal coupling can give up to
//! three solutions (stick and two slips, or three slips). All are returned by [`solutions`];
//! [`Lcp`] reports the one of least kinetic energy after and flags
//! [`Inconsistency::MultipleSolutions`]. When `w_tn = 0` the problem is again convex and the
//! solution unique. A planar problem embedded in 3D has its solutions at `θ ∈ {0, π}` (or
//! stick) and agrees with the planar law.

use super::{assemble, straight};
use crate::law::{Breakdown, BreakdownReason, ImpactLaw, Inconsistency, LawId, Options};
use crate::math::{cross2, norm3_of, norm_of, Vec2, Vec3};
use crate::numerics::roots::newton_bisection;
use crate::spatial::{ContactProblem, LawDetail, Outcome, PhaseKind, Resolution};
use std::f64::consts::TAU;

/// One solution of the spatial complementarity conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LcpSolution {
    /// `Stick`, or `Slip { from: θ, to: θ }` with `θ` the direction of the final slip.
    pub kind: PhaseKind,
    /// Impulse on body A, `(p_t1, p_t2, p_n)`.
    pub impulse: Vec3,
    /// Contact velocity after: `v⁻ + W p` to the round-off of its terms, reported as the
    /// conditions give it — `v_n⁺ = −e v_n⁻`, and `v_t⁺ = 0` (stick) or `σ ŝ` along the
    /// slip direction `ŝ` with `σ = ŝ·(v⁻ + W p)_t > 0` (slip).
    pub velocity_after: Vec3,
    /// `ΔT = ½ (v⁻ + v⁺)·p`.
    pub energy_change: f64,
}

/// Number of sample angles of the root search.
const SAMPLES: usize = 256;

/// `F(θ) = a0 + a1 cos θ + b1 sin θ + a2 cos 2θ + b2 sin 2θ`, its coefficients from the
/// problem (module docs): with `C = w_nn`, `u = v_t⁻`, `w = w_tn`,
///
/// ```text
/// a0 = −½ μ (w × u)              a1 = C u_2 + N w_2            b1 = −(C u_1 + N w_1)
/// a2 = −½ μ (w_1 u_2 + w_2 u_1) − μ N A_12
/// b2 = −½ μ (w_2 u_2 − w_1 u_1) − ½ μ N (A_22 − A_11)
/// ```
#[derive(Debug, Clone, Copy)]
struct Trig2 {
    a0: f64,
    a1: f64,
    b1: f64,
    a2: f64,
    b2: f64,
}

impl Trig2 {
    fn of(problem: &ContactProblem, n: f64) -> Self {
        let mu = problem.friction();
        let c = problem.wnn();
        let u = problem.velocity().xy();
        let w = problem.wtn();
        let a = problem.wtt();
        Self {
            a0: -0.5 * mu * cross2(w, u),
            a1: c * u.y + n * w.y,
            b1: -(c * u.x + n * w.x),
            a2: -0.5 * mu * (w.x * u.y + w.y * u.x) - mu * n * a[(0, 1)],
            b2: -0.5 * mu * (w.y * u.y - w.x * u.x) - 0.5 * mu * n * (a[(1, 1)] - a[(0, 0)]),
        }
    }
    /// `(F, F')` at an angle given by its cosine and sine.
    #[inline]
    fn at(&self, c: f64, s: f64) -> (f64, f64) {
        let (c2, s2) = (c * c - s * s, 2.0 * s * c);
        (
            self.a0 + self.a1 * c + self.b1 * s + self.a2 * c2 + self.b2 * s2,
            -self.a1 * s + self.b1 * c - 2.0 * self.a2 * s2 + 2.0 * self.b2 * c2,
        )
    }
    #[inline]
    fn eval(&self, theta: f64) -> (f64, f64) {
        let (s, c) = theta.sin_cos();
        self.at(c, s)
    }
    fn scale(&self) -> f64 {
        self.a0.abs() + self.a1.abs() + self.b1.abs() + self.a2.abs() + self.b2.abs()
    }
}

/// `(cos, sin)` of the sample angles `2π k / SAMPLES`, `k = 0..=SAMPLES`.
fn sample_table() -> &'static [(f64, f64)] {
    static TABLE: std::sync::OnceLock<Vec<(f64, f64)>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=SAMPLES)
            .map(|k| {
                let (s, c) = (TAU * k as f64 / SAMPLES as f64).sin_cos();
                (c, s)
            })
            .collect()
    })
}

/// Every root of `F` on `[0, 2π)` (at most four), ascending.
fn slip_angles(trig: &Trig2) -> Vec<f64> {
    let h = TAU / SAMPLES as f64;
    let theta = |k: usize| if k == SAMPLES { TAU } else { k as f64 * h };
    let table = sample_table();
    let mut roots = Vec::new();
    if trig.scale() == 0.0 {
        // F ≡ 0: every direction is parallel to its slip velocity (no coupling, isotropic
        // A, no initial slip); then v_t⁺ = −μ p_n A ŝ opposes ŝ and no slip is consistent.
        return roots;
    }
    let g = |t: f64| trig.eval(t);
    let mut prev = trig.at(table[0].0, table[0].1);
    for k in 0..SAMPLES {
        let next = trig.at(table[k + 1].0, table[k + 1].1);
        let (a, b) = (theta(k), theta(k + 1));
        let ((fa, da), (fb, db)) = (prev, next);
        prev = next;
        if fa == 0.0 {
            roots.push(a);
            continue;
        }
        if fb == 0.0 {
            continue; // counted at the next interval's start (or at θ = 0)
        }
        if (fa < 0.0) != (fb < 0.0) {
            roots.push(newton_bisection(g, a, b));
            continue;
        }
        // No sign change: a pair of close roots needs an extremum of F inside whose value
        // has the other sign.
        if (da < 0.0) != (db < 0.0) && da != 0.0 && db != 0.0 {
            let m = newton_bisection(
                |t| {
                    let (s, c) = t.sin_cos();
                    let (c2, s2) = (c * c - s * s, 2.0 * s * c);
                    (
                        trig.at(c, s).1,
                        -trig.a1 * c - trig.b1 * s - 4.0 * trig.a2 * c2 - 4.0 * trig.b2 * s2,
                    )
                },
                a,
                b,
            );
            let fm = g(m).0;
            if fm == 0.0 {
                roots.push(m);
            } else if (fm < 0.0) != (fa < 0.0) {
                roots.push(newton_bisection(g, a, m));
                roots.push(newton_bisection(g, m, b));
            }
        }
    }
    roots
}

/// The slip candidate at a root `θ` of `F` (direction `ŝ = (cos θ, sin θ)`), if its normal
/// impulse is positive (at a root, `p_n > 0` iff `D(θ) = w_nn − μ w_tn·ŝ > 0`) and
/// `σ = ŝ·v_t⁺ > 0`: `p = p_n (−μ ŝ, 1)`.
///
/// At a root the normal impulse has two expressions: `p_n = N / D` from the normal row and
/// `p_n = −(ŝ × u)/(ŝ × g)` (`g = w − μ A ŝ`) from the tangential row across `ŝ` (the slip
/// velocity has no component across its own direction). Each is a quotient of sums whose
/// round-off, and whose change over the round-off of `θ` itself, can be large beside the
/// value: `D` is a small difference of large terms for a grazing impact on a strongly
/// coupled `W` (`D = 5e-9` beside `w_nn = 2e5`, where `N/D` was 6 % off and the true
/// solution was rejected with `σ < 0`), and `ŝ × u = ŝ × g = 0` for a slip along `u` on
/// an invariant ray. The one of smaller estimated relative error is used.
fn slip_candidate(problem: &ContactProblem, n: f64, theta: f64) -> Option<LcpSolution> {
    let (sn, cs) = theta.sin_cos();
    let s = Vec2::new(cs, sn);
    let sp = Vec2::new(-sn, cs);
    let mu = problem.friction();
    let (c, w, a) = (problem.wnn(), problem.wtn(), problem.wtt());
    let u = problem.velocity().xy();
    let eps = f64::EPSILON;
    // The round-off of θ (in [0, 2π]).
    let dtheta = 4.0 * eps * theta.abs().max(1.0);
    // Normal row: D and dD/dθ = −μ w·ŝ'.
    let d = c - mu * w.dot(&s);
    let d_err = eps * (c.abs() + mu * (w.x * s.x).abs() + mu * (w.y * s.y).abs())
        + mu * w.dot(&sp).abs() * dtheta;
    // Tangential row across ŝ: ŝ × u and f = ŝ × g, with d/dθ (ŝ × u) = ŝ' × u and
    // df/dθ = ŝ' × g − μ ŝ × A ŝ'.
    let as_ = a * s;
    let g = w - mu * as_;
    let cu = cross2(s, u);
    let f = cross2(s, g);
    let df = cross2(sp, g) - mu * cross2(s, a * sp);
    let cu_err = eps * (u.x.abs() + u.y.abs()) + cross2(sp, u).abs() * dtheta;
    let f_err =
        eps * (w.x.abs() + w.y.abs() + mu * (as_.x.abs() + as_.y.abs())) + df.abs() * dtheta;
    let rel_normal = d_err / d.abs();
    let rel_across = cu_err / cu.abs() + f_err / f.abs();
    let pn = if rel_across < rel_normal {
        -cu / f
    } else {
        n / d
    };
    if pn.is_nan() || pn <= 0.0 || pn.is_infinite() {
        return None;
    }
    let impulse = Vec3::new(-mu * pn * s.x, -mu * pn * s.y, pn);
    let sigma = problem.velocity_after(impulse).xy().dot(&s);
    if sigma.is_nan() || sigma <= 0.0 {
        return None;
    }
    // The conditions hold exactly for what is reported: v_t⁺ = σ ŝ against p_t = −μ p_n ŝ,
    // and v_n⁺ = −e v_n⁻ (v⁻ + W p meets them to the round-off of its terms).
    let velocity_after = Vec3::new(sigma * s.x, sigma * s.y, newton_target(problem));
    Some(LcpSolution {
        kind: PhaseKind::Slip {
            from: theta,
            to: theta,
        },
        impulse,
        velocity_after,
        energy_change: 0.5 * (problem.velocity() + velocity_after).dot(&impulse),
    })
}

/// `v_n⁺ = −e v_n⁻`, which every solution meets exactly (`p_n > 0`): reported as such
/// rather than as `v_n⁻ + (W p)_n`, whose round-off (of the size of `|W||p|`) can be large
/// beside it for a grazing impact.
#[inline]
fn newton_target(problem: &ContactProblem) -> f64 {
    -problem.restitution() * problem.velocity().z
}

/// The sticking candidate: `W p = (−u, N)`, if `p_n ≥ 0` and `|p_t| ≤ μ p_n`.
fn stick(problem: &ContactProblem, n: f64) -> Option<LcpSolution> {
    let v = problem.velocity();
    let p = problem.w().cholesky()?.solve(&Vec3::new(-v.x, -v.y, n));
    if !(p.z >= 0.0 && norm_of(p.xy()) <= problem.friction() * p.z) {
        return None;
    }
    let velocity_after = Vec3::new(0.0, 0.0, newton_target(problem));
    Some(LcpSolution {
        kind: PhaseKind::Stick,
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
/// use impax::spatial::{laws::lcp, ContactProblem};
/// // A sphere (W = diag(7/2, 7/2, 1)): one solution.
/// let p = ContactProblem::from_upper([3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [0.5, 0.2, -1.0], 0.3, 0.5)
///     .unwrap();
/// assert_eq!(lcp::solutions(&p).len(), 1);
/// ```
pub fn solutions(problem: &ContactProblem) -> Vec<LcpSolution> {
    // In the problem's canonical units (powers of two, exact; the same as `resolve`'s), the
    // solutions scaled back.
    let Some((scaled, u)) = problem.canonical_units() else {
        return solutions_in_units(problem);
    };
    solutions_in_units(&scaled)
        .into_iter()
        .map(|s| LcpSolution {
            impulse: s.impulse.map(|x| u.impulse(x)),
            velocity_after: s.velocity_after.map(|x| u.velocity(x)),
            energy_change: u.work(s.energy_change),
            ..s
        })
        .collect()
}

/// [`solutions`] in the units of `problem` as given.
fn solutions_in_units(problem: &ContactProblem) -> Vec<LcpSolution> {
    let n = -(1.0 + problem.restitution()) * problem.velocity().z;
    let mut all: Vec<LcpSolution> = stick(problem, n).into_iter().collect();
    if problem.friction() == 0.0 {
        // Frictionless: p = (0, 0, N/c) whatever the slip.
        let impulse = Vec3::new(0.0, 0.0, n / problem.wnn());
        let mut velocity_after = problem.velocity_after(impulse);
        velocity_after.z = newton_target(problem);
        let t = velocity_after.xy();
        let a = t.y.atan2(t.x);
        return vec![LcpSolution {
            kind: PhaseKind::Slip { from: a, to: a },
            impulse,
            velocity_after,
            energy_change: 0.5 * (problem.velocity() + velocity_after).dot(&impulse),
        }];
    }
    for theta in slip_angles(&Trig2::of(problem, n)) {
        if let Some(c) = slip_candidate(problem, n, theta) {
            let scale = norm3_of(c.impulse);
            if all
                .iter()
                .all(|o| norm3_of(o.impulse - c.impulse) > 1e-10 * scale)
            {
                let theta = if theta > std::f64::consts::PI {
                    theta - TAU
                } else {
                    theta
                };
                all.push(LcpSolution {
                    kind: PhaseKind::Slip {
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

/// `lcp` in 3D (the module docs): the solution of least kinetic energy after; several
/// solutions are flagged with [`Inconsistency::MultipleSolutions`], none (not observed) is a
/// [`BreakdownReason::NoSolution`]. [`ImpactLaw::resolve`] works in the problem's canonical
/// units and scales back ([`super::resolve`]); every solution is in [`solutions`].
#[derive(Debug, Clone, Copy, Default)]
pub struct Lcp;

impl ImpactLaw for Lcp {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Lcp
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Lcp, problem, &Options::default())
    }
}

/// [`Lcp`] in the units of `problem` as given.
pub(super) fn in_units(problem: &ContactProblem) -> Resolution {
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
        LawDetail::Lcp {
            solutions: all.len(),
        },
        inconsistency,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coefficient form equals `F(θ) = D ŝ × u + N ŝ × (w − μ A ŝ)` written directly,
    /// and its derivative a central difference.
    #[test]
    fn coefficient_form_matches_the_definition() {
        let p =
            ContactProblem::from_upper([2.0, 0.6, 0.3, 1.0, -0.2, 1.5], [0.3, 0.8, -1.0], 0.8, 0.7)
                .unwrap();
        let n = -(1.0 + p.restitution()) * p.velocity().z;
        let trig = Trig2::of(&p, n);
        for k in 0..97 {
            let theta = 0.3 + TAU * k as f64 / 97.0;
            let s = Vec2::new(theta.cos(), theta.sin());
            let d = p.wnn() - p.friction() * p.wtn().dot(&s);
            let g = p.wtn() - p.friction() * (p.wtt() * s);
            let direct = d * cross2(s, p.velocity().xy()) + n * cross2(s, g);
            let (f, df) = trig.eval(theta);
            assert!((f - direct).abs() < 1e-14 * trig.scale(), "{f} vs {direct}");
            let h = 1e-6;
            let fd = (trig.eval(theta + h).0 - trig.eval(theta - h).0) / (2.0 * h);
            assert!((df - fd).abs() < 1e-8 * trig.scale(), "{df} vs {fd}");
        }
    }
}
