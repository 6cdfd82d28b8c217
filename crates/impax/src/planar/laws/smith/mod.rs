//! `smith`: Smith's 1991 correction factor η (paper A §4, eqs. 24–27).
//!
//! Whittaker's impulse is scaled by
//!
//! ```text
//! η = (u⁺|u⁺| + u⁻|u⁻|) / ((u⁺)² + (u⁻)²) ∈ [−1, 1],     p_t = −μ η p_n,
//! ```
//!
//! where `u` is the sliding (contact-point tangential) velocity before and after, and the
//! normal impulse follows Newton's restitution, `p_n = −(1+e) v_n⁻ / (W_nn − μ η W_tn)`.
//! η is signed, so it carries the friction direction (`η = sign(u⁻)` when the slip keeps
//! its direction, Whittaker's rule). Paper A eq. 24 writes the centre velocity `v_x` while
//! its text says sliding velocity; [`Smith::centre`] is that literal reading.
//!
//! The equation is implicit in η because `u⁺` depends on η. With `u⁺ = u⁻ + g·p` linear in
//! the impulse (`g = (W_tt, W_tn)` for the slip; `(1/m, 0)` for a body's centre) and
//! `D(η) = W_nn − μ η W_tn`, `Q(η) = u⁺ D` is linear in η, and each sign case is exact:
//!
//! * no reversal, `sign(u⁺) = sign(u⁻) = σ`: `η = σ`;
//! * reversal: `η ((u⁻)² D² + Q²) = σ ((u⁻)² D² − Q²)`, a cubic in η (eq. 27 for the sphere),
//!   whose roots in `[−1, 1]` are isolated between the critical points and bisected to the
//!   last bit;
//! * `u⁻ = 0`: `η = ±1` with `sign(u⁺) = η`, or the η that leaves `u⁺ = 0`.
//!
//! A root always exists when `D > 0` on `[−1, 1]`. When several do, the one with the
//! largest `σ η` — the least correction of Whittaker's rule — is taken, and the count is
//! reported in [`LawDetail::Smith`].
//!
//! The resolution goes by stages: the lines `D(ζ)` and `Q(ζ)` of the problem, the admissible
//! friction ratios of the slip's sign case (`ratio`, with the cubic's roots from `cubic`),
//! the one taken, and the impulse on the line `p_t = −ζ p_n`.

mod cubic;
mod ratio;

use super::{checked, finish_line, ImpactLaw};
use crate::law::LawId;
use crate::math::{sign, Vec2};
use crate::planar::{
    Breakdown, BreakdownReason, ContactProblem, LawDetail, PhaseKind, Resolution, SlipDirection,
    SmithReading,
};
use ratio::{Candidates, Lines};

/// Smith's law with a chosen reference velocity `u(p) = u⁻ + g·p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Smith {
    reading: SmithReading,
    /// `(u⁻, g)` for the centre reading; `None` for the sliding velocity of the problem.
    reference: Option<(f64, Vec2)>,
}

impl Smith {
    /// The sliding-velocity reading (Smith 1991; the `smith` law id).
    pub const SLIP: Smith = Smith {
        reading: SmithReading::SlipVelocity,
        reference: None,
    };

    /// The literal reading of paper A eq. 24 (`smith-centre`): η from the tangential
    /// centre-of-mass velocity `u⁻` whose change per unit impulse is `gradient`
    /// (`(1/m, 0)` for one body on a fixed plane; `(1/m_A + 1/m_B, 0)` for the relative
    /// centre velocity of two bodies).
    pub fn centre(u_minus: f64, gradient: Vec2) -> Smith {
        Smith {
            reading: SmithReading::CentreVelocity,
            reference: Some((u_minus, gradient)),
        }
    }
}

impl Default for Smith {
    fn default() -> Self {
        Self::SLIP
    }
}

impl ImpactLaw for Smith {
    type Problem = crate::planar::ContactProblem;
    type Outcome = crate::planar::Outcome;
    type Brief = crate::planar::OutcomeBrief;

    fn id(&self) -> LawId {
        match self.reading {
            SmithReading::SlipVelocity => LawId::Smith,
            SmithReading::CentreVelocity => LawId::SmithCentre,
        }
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::in_units(problem, |problem, a_v, b_w| {
            let law = self.id();
            let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
            let v = problem.velocity();
            let mu = problem.friction();
            let big_n = -(1.0 + problem.restitution()) * v.y;
            // A reference velocity of its own (the centre's) in the units of `problem`.
            let (u0, g) = self
                .reference
                .map_or((v.x, Vec2::new(a, b)), |(u, g)| (u * a_v, g * b_w));
            // Solved in the friction ratio ζ = μ η (p_t = −ζ p_n; see `ratio`).
            let lines = Lines {
                d: [c, -b],
                q: [u0 * c + big_n * g.y, -(b * u0 + big_n * g.x)],
            };
            let sigma = sign(u0);
            if mu == 0.0 {
                return self.frictionless(problem, &lines, u0, big_n);
            }
            let candidates = if sigma != 0.0 {
                Candidates::sliding(&lines, u0, mu, sigma)
            } else {
                Candidates::zero_slip(&lines, mu)
            };
            if candidates.count == 0 {
                // Distinguish a negative normal impulse from a missing root.
                let reason = if lines.d(mu) <= 0.0 || lines.d(-mu) <= 0.0 {
                    BreakdownReason::NegativeNormalImpulse {
                        denominator: lines.d(mu).min(lines.d(-mu)),
                    }
                } else {
                    BreakdownReason::NoEtaRoot
                };
                return Err(Breakdown { law, reason });
            }
            let zeta = candidates.chosen(sigma);
            let pf = big_n / lines.d(zeta);
            // |ζ| = μ exactly when the slip keeps its direction: η = ±1 exactly.
            let eta = if zeta.abs() == mu {
                zeta.signum()
            } else {
                zeta / mu
            };
            let dir = if zeta != 0.0 {
                SlipDirection::of(zeta)
            } else {
                SlipDirection::of(v.x)
            };
            checked(finish_line(
                problem,
                law,
                PhaseKind::Slip(dir),
                -zeta,
                pf,
                LawDetail::Smith {
                    eta,
                    roots: candidates.count,
                    reading: self.reading,
                },
                None,
            ))
        })
    }
}

impl Smith {
    /// No friction: `p_t = 0` whatever η; η from its definition with `u⁺ = Q(0)/D(0)`.
    fn frictionless(
        &self,
        problem: &ContactProblem,
        lines: &Lines,
        u0: f64,
        big_n: f64,
    ) -> Resolution {
        let (d, q) = (lines.d, lines.q);
        let up = q[0] / d[0];
        let den = up * up + u0 * u0;
        let eta = if den > 0.0 {
            (up * up.abs() + u0 * u0.abs()) / den
        } else {
            0.0
        };
        checked(finish_line(
            problem,
            self.id(),
            PhaseKind::Slip(SlipDirection::of(problem.velocity().x)),
            0.0,
            big_n / d[0],
            LawDetail::Smith {
                eta,
                roots: 1,
                reading: self.reading,
            },
            None,
        ))
    }
}
