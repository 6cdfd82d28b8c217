//! The Darboux–Keller / Routh impulse path in closed form (planar).
//!
//! With the normal impulse as independent variable (Keller 1986; Routh 1905; Stronge 2000;
//! theory §2), the contact velocity obeys `dv/dp_n = W (k, 1)` with friction ratio
//!
//! * slip, `ŝ = sign(v_t)`: `k = −μ ŝ`;
//! * stick (`v_t = 0`): `k = λ = −W_tn / W_tt`, admissible iff `|W_tn| ≤ μ W_tt`.
//!
//! Planar, `v(p_n)` is piecewise linear:
//!
//! 1. slip in `s0 = sign(v_t⁻)` with slopes `(b − μ s0 a, c − μ s0 b)`; it halts at
//!    `p_s = −v_t⁻ / (b − μ s0 a)` when that is positive;
//! 2. then stick (slopes `(0, (ac − b²)/a)`) if `|b| ≤ μ a`, otherwise slip resumes at once in
//!    `s1 = sign(b)` (reversal) with slopes `(b − μ s1 a, c − μ s1 b)` and never halts again.
//!
//! (`a = W_tt, b = W_tn, c = W_nn`.) The last segment always has `dv_n/dp_n > 0`, so the
//! compression ends; the termination rules [`newton`](super::newton),
//! [`poisson`](super::poisson) and [`energetic`](super::energetic) pick the end on this path.

use super::energy_and_verdict;
use crate::math::Vec2;
use crate::planar::path::PathSummary;
use crate::planar::{ContactProblem, OutcomeBrief, PhaseKind, Phases, SlipDirection};

/// One straight piece of the Darboux–Keller path: friction ratio, `dv/dp_n`, regime.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Regime.
    pub kind: PhaseKind,
    /// Friction ratio `k = dp_t/dp_n`.
    pub ratio: f64,
    /// `dv/dp_n = W (k, 1)`.
    pub slope: Vec2,
}

/// The unbounded planar Darboux–Keller path: the initial slip on `[0, p_s]`, then stick or
/// reversed slip on `[p_s, ∞)` (`p_s = 0` without initial slip; `p_s = ∞` if the slip never
/// halts). Everything is evaluated in closed form; no allocation, no loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DarbouxKellerPath {
    v0: Vec2,
    first: Piece,
    halt: f64,
    /// Velocity at the halt (`v_t = 0` exactly) and tangential impulse there.
    v_halt: Vec2,
    pt_halt: f64,
    second: Piece,
    /// Normal work up to the halt.
    work_halt: f64,
    /// Friction work up to the halt.
    friction_halt: f64,
}

impl DarbouxKellerPath {
    /// Build the path of a problem (theory §2, "Planar closed form").
    #[inline]
    pub fn new(problem: &ContactProblem) -> Self {
        let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
        let mu = problem.friction();
        let v0 = problem.velocity();
        let piece = |kind, ratio: f64| Piece {
            kind,
            ratio,
            slope: Vec2::new(a * ratio + b, b * ratio + c),
        };
        // v_t = 0 at the start of the second piece: stick if the cone holds it, else slip
        // resumes at once along sign(b).
        let second = if b.abs() <= mu * a {
            piece(PhaseKind::Stick, -b / a)
        } else {
            let s1 = SlipDirection::of(b);
            piece(PhaseKind::Slip(s1), -mu * s1.sign())
        };
        let dir = SlipDirection::of(v0.x);
        let first = piece(PhaseKind::Slip(dir), -mu * dir.sign());
        let halt = if dir == SlipDirection::None {
            0.0
        } else if dir.sign() * first.slope.x < 0.0 {
            -v0.x / first.slope.x
        } else {
            f64::INFINITY
        };
        let (v_halt, pt_halt, work_halt, friction_halt) = if halt.is_finite() {
            (
                Vec2::new(0.0, v0.y + first.slope.y * halt),
                first.ratio * halt,
                halt * (v0.y + 0.5 * first.slope.y * halt),
                first.ratio * halt * (v0.x + 0.5 * first.slope.x * halt),
            )
        } else {
            (Vec2::zeros(), 0.0, 0.0, 0.0)
        };
        Self {
            v0,
            first,
            halt,
            v_halt,
            pt_halt,
            second,
            work_halt,
            friction_halt,
        }
    }

    /// The normal impulse at which the initial slip halts, if it does (`> 0`).
    #[inline]
    pub fn slip_halt(&self) -> Option<f64> {
        (self.halt > 0.0 && self.halt.is_finite()).then_some(self.halt)
    }

    /// First `p_n` with `v_n(p_n) = target`, `target ≥ v_n⁻`. The second piece, and the
    /// first when it never halts, have `dv_n/dp_n > 0`, so it always exists.
    #[inline]
    pub fn first_normal_velocity(&self, target: f64) -> f64 {
        let s1 = self.first.slope.y;
        if self.halt > 0.0 && s1 > 0.0 {
            let p = (target - self.v0.y) / s1;
            if p <= self.halt {
                return p;
            }
        }
        self.halt + (target - self.v_halt.y) / self.second.slope.y
    }

    /// Normal work `∫₀^p v_n dp_n`.
    #[inline]
    pub fn normal_work_to(&self, p: f64) -> f64 {
        if p <= self.halt {
            p * (self.v0.y + 0.5 * self.first.slope.y * p)
        } else {
            let x = p - self.halt;
            self.work_halt + x * (self.v_halt.y + 0.5 * self.second.slope.y * x)
        }
    }

    /// The `p_f ≥ p_c` at which the restitution work `∫_{p_c}^{p_f} v_n dp_n` reaches
    /// `work ≥ 0` (`v_n ≥ 0` after compression, so the work is increasing).
    #[inline]
    pub fn restitution_work_reached(&self, pc: f64, work: f64) -> f64 {
        // v0 x + ½ k x² = w, cancellation-free root.
        let solve = |v: f64, k: f64, w: f64| {
            let denom = v + (v * v + 2.0 * k * w).max(0.0).sqrt();
            if denom > 0.0 {
                2.0 * w / denom
            } else {
                0.0
            }
        };
        let mut from = pc;
        let mut remaining = work;
        if pc < self.halt {
            let v = self.v0.y + self.first.slope.y * pc;
            let len = self.halt - pc;
            let available = len * (v + 0.5 * self.first.slope.y * len);
            if remaining <= available {
                return pc + solve(v, self.first.slope.y, remaining).min(len);
            }
            remaining -= available;
            from = self.halt;
        }
        let v = self.v_halt.y + self.second.slope.y * (from - self.halt);
        from + solve(v, self.second.slope.y, remaining)
    }

    /// Impulse `p(p_f) = (p_t, p_f)`, contact velocity `v(p_f)` and phases of the path ended
    /// at `pf` (on the piece that holds `pf`: `p_t` and `v` are linear in `p_n`).
    #[inline(always)]
    pub fn end_at(&self, pf: f64) -> (Vec2, Vec2, Phases) {
        let mut phases = Phases::new();
        if pf <= self.halt {
            phases.push(self.first.kind, pf);
            (
                Vec2::new(self.first.ratio * pf, pf),
                self.v0 + self.first.slope * pf,
                phases,
            )
        } else {
            if self.halt > 0.0 {
                phases.push(self.first.kind, self.halt);
            }
            phases.push(self.second.kind, pf);
            let x = pf - self.halt;
            (
                Vec2::new(self.pt_halt + self.second.ratio * x, pf),
                self.v_halt + self.second.slope * x,
                phases,
            )
        }
    }

    /// The brief of the outcome of a termination rule that ends this path at `pf`: `ΔT`,
    /// verdict and phases exactly as in the full record ([`ImpactLaw::resolve_brief`]),
    /// without the works and the compression impulse.
    ///
    /// [`ImpactLaw::resolve_brief`]: crate::law::ImpactLaw::resolve_brief
    #[inline(always)]
    pub fn brief(&self, problem: &ContactProblem, pf: f64) -> OutcomeBrief {
        let (impulse, velocity, phases) = self.end_at(pf);
        let (energy_change, verdict) = energy_and_verdict(problem, impulse, velocity, false);
        OutcomeBrief {
            verdict,
            phases,
            energy_change,
        }
    }

    /// Impulse, velocity, compression, works and phases of the path ended at `pf`.
    #[inline]
    pub fn summarize(&self, pf: f64) -> PathSummary {
        let pc = self.first_normal_velocity(0.0);
        let compression_impulse = (pc <= pf).then_some(pc);
        let normal_work = self.normal_work_to(pf);
        let compression_work = if pc <= pf {
            self.normal_work_to(pc)
        } else {
            normal_work
        };
        let (impulse, velocity, phases) = self.end_at(pf);
        let friction_work = if pf <= self.halt {
            self.first.ratio * pf * (self.v0.x + 0.5 * self.first.slope.x * pf)
        } else {
            let x = pf - self.halt;
            self.friction_halt + self.second.ratio * x * (0.5 * self.second.slope.x * x)
        };
        PathSummary {
            impulse,
            velocity,
            compression_impulse,
            compression_work,
            normal_work,
            friction_work,
            phases,
        }
    }
}
