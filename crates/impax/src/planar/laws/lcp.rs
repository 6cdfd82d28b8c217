//! `lcp`: the velocity-level complementarity impact — the rule physics engines converge to.
//!
//! Anitescu & Potra 1997 (*Formulating dynamic multi-rigid-body contact problems with friction
//! as solvable linear complementarity problems*, Nonlinear Dynamics 14), Stewart & Trinkle
//! 1996, and the fixed point of the sequential-impulse / projected Gauss–Seidel iterations of
//! Box2D, Chipmunk (pymunk) and Bullet: one impulse `p`, the velocity after `v⁺ = v⁻ + W p`,
//!
//! ```text
//! normal:   p_n ≥ 0,  v_n⁺ + e v_n⁻ ≥ 0,  p_n (v_n⁺ + e v_n⁻) = 0   (Newton's target)
//! friction: |p_t| ≤ μ p_n;  v_t⁺ = 0 if |p_t| < μ p_n,  else p_t = −μ p_n sign(v_t⁺)
//! ```
//!
//! (Coulomb's law with maximal dissipation on the *final* velocity). With approach
//! (`v_n⁻ < 0`), `p_n = 0` would leave `v_n⁺ = v_n⁻ < 0`, so `p_n > 0` and `v_n⁺ = −e v_n⁻`
//! exactly. The law enumerates the three candidates (theory §3, "others worth knowing"),
//! with `N = −(1+e) v_n⁻ > 0` and `W = [[a, b], [b, c]]`:
//!
//! ```text
//! stick:   W p = (−v_t⁻, N)                 valid iff p_n ≥ 0 and |p_t| ≤ μ p_n
//! slip +:  p = p_n (−μ, 1), p_n = N/(c − μ b)   valid iff c − μ b > 0 and v_t⁺ ≥ 0
//! slip −:  p = p_n (+μ, 1), p_n = N/(c + μ b)   valid iff c + μ b > 0 and v_t⁺ ≤ 0
//! ```
//!
//! and returns the consistent one.
//!
//! **Existence and uniqueness (planar, `W` positive definite).** On Newton's line
//! `b p_t + c p_n = N` write `p_n(p_t) = (N − b p_t)/c`; then
//! `v_t⁺ = v* + s p_t` with `s = (ac − b²)/c > 0` and `v* = v_t⁻ + b N / c`. The cone
//! condition `|p_t| ≤ μ p_n(p_t)` is a closed interval `C` of `p_t` that contains `0`
//! (`p_n(0) = N/c > 0`), possibly unbounded on one side. The friction conditions say
//! exactly `−v_t⁺ ∈ N_C(p_t)` (the normal cone of `C`: `{0}` inside, `[0, ∞)` at the upper
//! end where `p_t = +μ p_n`, `(−∞, 0]` at the lower end where `p_t = −μ p_n`), which is the
//! optimality condition of the strictly convex problem `min_{p_t ∈ C} ½ s p_t² + v* p_t`.
//! A strictly convex function has exactly one minimiser on a non-empty closed interval, so the
//! planar LCP always has exactly one solution: the sticking impulse `p*_t = −v*/s` clamped
//! to `C`. Two candidates pass only on the boundary between them (stick with
//! `|p_t| = μ p_n` and slip with `v_t⁺ = 0`), where they are the same impulse. `p_n ≥ 0`
//! holds on `C` (`p_n ≥ |p_t|/μ`; `C = {0}` when `μ = 0`).
//!
//! **Identity with [`brach`](super::brach).** Brach's rule is the sticking impulse with
//! Newton's restitution, its ratio capped to `±μ` along its own sign: that is the same
//! clamp of `p*_t` to `C`. So in the plane `lcp` ≡ `brach` (tested on random problems);
//! they differ in 3D, where the engine's friction opposes the final slip and Brach's is
//! along the sticking impulse.
//!
//! Because the friction acts against the final slip and Newton's target fixes `v_n⁺`, the
//! rule equals Darboux–Keller `newton` whenever the slip does not reverse during the impact,
//! and can gain energy when it does (a uniform rod at 50° to the floor, μ = 0.8, e = 1,
//! translating at (0.5, −1): `T⁺/T⁻ ≈ 1.18`). The work split is reported along the straight
//! path `p = p_n (p_t/p_n, 1)` (an engine has no path in impulse space), as for the other
//! algebraic laws.
//!
//! **`lcp-poisson` is not provided.** Anitescu & Potra 1997 and Stewart & Trinkle 1996
//! formulate restitution at the velocity level (Newton's target, or a two-stage
//! compression/decompression scheme that depends on the time-stepping), and the engines
//! measured here use Newton's target; the literature has no single, standard Poisson
//! (kinetic) version of the velocity-level LCP, so none is offered under a stable id.
//!
//! ```
//! use impax::planar::{ContactProblem, laws::{ImpactLaw, Lcp}};
//! // Uniform rod (m = 1, l = 1) at 50° to the floor, lower end striking, v = (0.5, −1), ω = 0.
//! let (s, c) = 50f64.to_radians().sin_cos();
//! let (rt, rn) = (-0.5 * c, -0.5 * s); // centre → contact point
//! let i = 1.0 / 12.0;
//! let p = ContactProblem::from_entries(1.0 + rn * rn / i, -rt * rn / i, 1.0 + rt * rt / i,
//!                                      0.5, -1.0, 0.8, 1.0).unwrap();
//! let out = Lcp.resolve(&p).unwrap();
//! assert!((out.velocity_after.y - 1.0).abs() < 1e-12); // Newton's target
//! assert!(out.energy_change > 0.0);                   // the engine rule gains energy here
//! ```

use super::{checked, finish_line, ImpactLaw};
use crate::law::LawId;
use crate::planar::{
    ContactProblem, LawDetail, Outcome, PhaseKind, Resolution, SlipDirection, Verdict,
};

/// The engine rule (velocity-level LCP). See the [module docs](self).
#[derive(Debug, Clone, Copy, Default)]
pub struct Lcp;

/// One candidate of the enumeration: the friction ratio `p_t/p_n`, the normal impulse, and
/// how far it is from satisfying its own conditions (`0` when it satisfies them exactly).
#[derive(Debug, Clone, Copy)]
struct Candidate {
    kind: PhaseKind,
    ratio: f64,
    pn: f64,
    violation: f64,
}

impl Lcp {
    /// The three candidates `[stick, slip+, slip−]` (a candidate that does not exist, e.g.
    /// a non-positive denominator, has an infinite violation); with `μ = 0` only the
    /// frictionless impulse.
    fn candidates(problem: &ContactProblem) -> [Candidate; 3] {
        let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
        let v = problem.velocity();
        let mu = problem.friction();
        let n = -(1.0 + problem.restitution()) * v.y;
        let det = a * c - b * b;
        // Stick: W p = (−v_t, N).
        let pt = (-c * v.x - b * n) / det;
        let pn = (b * v.x + a * n) / det;
        let scale = pt.abs().max(pn.abs()).max(f64::MIN_POSITIVE);
        let stick = if pn > 0.0 {
            Candidate {
                kind: PhaseKind::Stick,
                ratio: pt / pn,
                pn,
                violation: (pt.abs() - mu * pn).max(0.0) / scale,
            }
        } else {
            Candidate {
                kind: PhaseKind::Stick,
                ratio: 0.0,
                pn,
                violation: if pt == 0.0 && pn == 0.0 {
                    0.0
                } else {
                    f64::INFINITY
                },
            }
        };
        // Slip with p_t = k p_n: `k = −μ` needs v_t⁺ ≥ 0, `k = +μ` needs v_t⁺ ≤ 0.
        let slip = |k: f64, dir: f64| {
            let den = c + k * b;
            let pn = n / den;
            let kind = if mu > 0.0 {
                PhaseKind::Slip(SlipDirection::of(dir))
            } else {
                PhaseKind::Slip(SlipDirection::of(v.x + b * pn))
            };
            if !(den > 0.0 && pn.is_finite()) {
                return Candidate {
                    kind,
                    ratio: k,
                    pn: f64::NAN,
                    violation: f64::INFINITY,
                };
            }
            let vt = v.x + (a * k + b) * pn;
            let vscale = v.x.abs().max(v.y.abs()).max(f64::MIN_POSITIVE);
            Candidate {
                kind,
                ratio: k,
                pn,
                violation: (-dir * vt).max(0.0) / vscale,
            }
        };
        if mu == 0.0 {
            // Frictionless: one candidate, p = (0, N/c), whatever the slip after.
            let none = Candidate {
                violation: f64::INFINITY,
                ..stick
            };
            let free = Candidate {
                violation: 0.0,
                ..slip(0.0, 1.0)
            };
            return [free, none, none];
        }
        [stick, slip(-mu, 1.0), slip(mu, -1.0)]
    }

    /// How many of the three candidates satisfy their conditions exactly (in floating
    /// point): `1`, or `2` on the boundary between stick and slip where both are the same
    /// impulse; `0` only when round-off puts the solution a hair outside every candidate's
    /// test (the least-violating candidate is then returned).
    pub fn consistent_candidates(problem: &ContactProblem) -> usize {
        Self::candidates(problem)
            .iter()
            .filter(|c| c.violation == 0.0)
            .count()
    }
}

impl ImpactLaw for Lcp {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        LawId::Lcp
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, _, _| {
            let cands = Self::candidates(problem);
            let consistent = cands.iter().filter(|c| c.violation == 0.0).count();
            // The first consistent candidate (stick first: on the boundary it leaves v_t⁺ = 0
            // exactly); else the one nearest to consistency (round-off).
            let best = cands
                .iter()
                .copied()
                .min_by(|x, y| x.violation.total_cmp(&y.violation))
                .expect("three candidates");
            let out = finish_line(
                problem,
                LawId::Lcp,
                best.kind,
                best.ratio,
                best.pn,
                LawDetail::Lcp {
                    ratio: best.ratio,
                    consistent_candidates: consistent,
                },
                None,
            );
            checked(tidy(out, best.kind))
        })
    }
}

/// Stick leaves `v_t⁺ = 0` by definition: keep it exact rather than its round-off.
fn tidy(mut out: Outcome, kind: PhaseKind) -> Outcome {
    if kind == PhaseKind::Stick {
        out.velocity_after.x = 0.0;
    }
    debug_assert!(out.verdict != Verdict::InconsistentAssumption);
    out
}
