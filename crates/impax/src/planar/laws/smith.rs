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

use super::{checked, finish_line, ImpactLaw};
use crate::law::LawId;
use crate::math::{quadratic_roots, sign, Vec2};
use crate::numerics::roots::newton_wide_bracket;
use crate::planar::{
    Breakdown, BreakdownReason, ContactProblem, LawDetail, PhaseKind, Resolution, SlipDirection,
    SmithReading,
};

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

/// Evaluate `p[0] + p[1] x + p[2] x² + p[3] x³`.
#[cfg(test)]
fn horner(p: &[f64; 4], x: f64) -> f64 {
    ((p[3] * x + p[2]) * x + p[1]) * x + p[0]
}

/// The factor `1/max(1, x²)` by which the cubic is evaluated (its sign is the cubic's, and
/// its size stays representable for `|x|` up to the largest friction coefficients).
#[cfg(test)]
fn damping(x: f64) -> f64 {
    let r = 1.0 / x.abs().max(1.0);
    r * r
}

/// Real roots of the cubic with monomial coefficients `p` in `[lo, hi]`, each to the last
/// bit (ascending, deduplicated). `f` evaluates the same cubic times `1/max(1, x²)`,
/// possibly in a better conditioned (factored) form: the monomials only place the critical
/// points that split `[lo, hi]` into monotone pieces and guide Newton; every sign test uses
/// `f`.
fn cubic_roots_in(
    p: &[f64; 4],
    f: impl Fn(f64) -> f64,
    lo: f64,
    hi: f64,
    floor: f64,
) -> ([f64; 3], usize) {
    let mut out = [0.0; 3];
    let mut n = 0;
    if p.iter().all(|&c| c == 0.0) {
        return (out, 0);
    }
    let mut cuts = [lo, hi, hi, hi];
    let mut ncuts = 1;
    let [r1, r2] = quadratic_roots(3.0 * p[3], 2.0 * p[2], p[1]);
    for r in [r1, r2] {
        if r > lo && r < hi {
            cuts[ncuts] = r;
            ncuts += 1;
        }
    }
    cuts[ncuts] = hi;
    ncuts += 1;
    cuts[..ncuts].sort_by(|x, y| x.total_cmp(y));
    let push = |x: f64, out: &mut [f64; 3], n: &mut usize| {
        if *n < 3 && (*n == 0 || out[*n - 1] != x) {
            out[*n] = x;
            *n += 1;
        }
    };
    for w in cuts[..ncuts].windows(2) {
        let (x0, x1) = (w[0], w[1]);
        let (f0, f1) = (f(x0), f(x1));
        if f0 == 0.0 {
            push(x0, &mut out, &mut n);
            continue;
        }
        if f1 == 0.0 || f0.signum() == f1.signum() {
            continue;
        }
        // The derivative damped like `f` (the damping's own derivative multiplies `f` ≈ 0
        // near the root): x r and r are at most 1, so nothing overflows.
        let df = |x: f64| {
            let r = 1.0 / x.abs().max(1.0);
            let xr = x * r;
            (3.0 * p[3] * xr + 2.0 * p[2] * r) * xr + p[1] * r * r
        };
        let root = newton_wide_bracket(&f, df, x0, x1, f0, floor);
        push(root, &mut out, &mut n);
    }
    if f(hi) == 0.0 {
        push(hi, &mut out, &mut n);
    }
    (out, n)
}

/// Product of two polynomials of degree ≤ 1 → degree ≤ 2 (coefficients ascending).
#[inline]
fn mul1(a: [f64; 2], b: [f64; 2]) -> [f64; 3] {
    [a[0] * b[0], a[0] * b[1] + a[1] * b[0], a[1] * b[1]]
}

impl ImpactLaw for Smith {
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
            // Solved in the friction ratio ζ = μ η (p_t = −ζ p_n), in which `D` and `Q` do not
            // contain μ: μ only bounds |ζ| ≤ μ and multiplies the right-hand side,
            // ζ (U D² + Q²) = μ σ (U D² − Q²). (In η the coefficients grow as μ² and the roots
            // shrink as 1/μ: from μ ≈ 1e20 the root finder's resolution, and at μ ≈ 1e154 the
            // monomials, failed.) D(ζ) = d[0] + d[1] ζ ;  Q(ζ) = u⁺ D = q[0] + q[1] ζ.
            let d = [c, -b];
            let q = [u0 * c + big_n * g.y, -(b * u0 + big_n * g.x)];
            let dval = |zeta: f64| d[0] + d[1] * zeta;
            let qval = |zeta: f64| q[0] + q[1] * zeta;
            let sigma = sign(u0);
            if mu == 0.0 {
                // No friction: p_t = 0 whatever η; η from its definition with u⁺ = Q(0)/D(0).
                let up = q[0] / d[0];
                let den = up * up + u0 * u0;
                let eta = if den > 0.0 {
                    (up * up.abs() + u0 * u0.abs()) / den
                } else {
                    0.0
                };
                return checked(finish_line(
                    problem,
                    law,
                    PhaseKind::Slip(SlipDirection::of(v.x)),
                    0.0,
                    big_n / c,
                    LawDetail::Smith {
                        eta,
                        roots: 1,
                        reading: self.reading,
                    },
                    None,
                ));
            }
            // Roots closer to ζ = 0 than 1e-9 of the natural scale of a friction ratio (1, or μ
            // when smaller) are not chased below round-off.
            let floor = 1e-9 * mu.min(1.0);
            let mut cands = [0.0f64; 6];
            let mut nc = 0;
            let mut stick_root = None;
            if sigma != 0.0 {
                let full = mu * sigma;
                if dval(full) > 0.0 && sigma * qval(full) >= 0.0 {
                    cands[nc] = full;
                    nc += 1;
                }
                let uu = u0 * u0;
                let dd = mul1(d, d);
                let qq = mul1(q, q);
                // P(ζ) = ζ (U D² + Q²) − μσ (U D² − Q²)
                let aa = [uu * dd[0] + qq[0], uu * dd[1] + qq[1], uu * dd[2] + qq[2]];
                let bb = [uu * dd[0] - qq[0], uu * dd[1] - qq[1], uu * dd[2] - qq[2]];
                let poly = [
                    -full * bb[0],
                    aa[0] - full * bb[1],
                    aa[1] - full * bb[2],
                    aa[2],
                ];
                // The same cubic in factored form, far better conditioned near a pole of p_n
                // (small D) than its monomials.
                let factored = |zeta: f64| {
                    // Damped by 1/max(1, ζ²) (see `damping`): D and Q divided by max(1, |ζ|).
                    let r = 1.0 / zeta.abs().max(1.0);
                    let (dv, qv) = (dval(zeta) * r, qval(zeta) * r);
                    let (ud, qq) = (uu * dv * dv, qv * qv);
                    zeta * (ud + qq) - full * (ud - qq)
                };
                // Only the reversal region σ Q(ζ) < 0 (Q linear) can hold admissible roots:
                // search there, skipping the inadmissible ones (ζ = 0 is one whenever u⁺ = u⁻).
                let (mut lo, mut hi) = (-mu, mu);
                let slope = sigma * q[1];
                let zero = -q[0] / q[1];
                if slope > 0.0 {
                    hi = hi.min(zero);
                } else if slope < 0.0 {
                    lo = lo.max(zero);
                } else if sigma * q[0] >= 0.0 {
                    hi = lo - 1.0; // no reversal anywhere
                }
                let (roots, nr) = if lo < hi {
                    cubic_roots_in(&poly, factored, lo, hi, floor)
                } else {
                    ([0.0; 3], 0)
                };
                for &zeta in &roots[..nr] {
                    if dval(zeta) > 0.0 && sigma * qval(zeta) < 0.0 {
                        cands[nc] = zeta;
                        nc += 1;
                    }
                }
            } else {
                for zeta in [mu, -mu] {
                    if dval(zeta) > 0.0 && zeta * qval(zeta) > 0.0 {
                        cands[nc] = zeta;
                        nc += 1;
                    }
                }
                let zeta = if q[1] != 0.0 {
                    -q[0] / q[1]
                } else if q[0] == 0.0 {
                    0.0
                } else {
                    f64::NAN
                };
                if (-mu..=mu).contains(&zeta) && dval(zeta) > 0.0 {
                    cands[nc] = zeta;
                    nc += 1;
                    stick_root = Some(zeta);
                }
            }
            if nc == 0 {
                // Distinguish a negative normal impulse from a missing root.
                let reason = if dval(mu) <= 0.0 || dval(-mu) <= 0.0 {
                    BreakdownReason::NegativeNormalImpulse {
                        denominator: dval(mu).min(dval(-mu)),
                    }
                } else {
                    BreakdownReason::NoEtaRoot
                };
                return Err(Breakdown { law, reason });
            }
            let zeta = match stick_root {
                Some(zeta) => zeta,
                None => cands[..nc]
                    .iter()
                    .copied()
                    .fold(f64::NEG_INFINITY, |best, x| {
                        if sigma * x > sigma * best || best == f64::NEG_INFINITY {
                            x
                        } else {
                            best
                        }
                    }),
            };
            let pf = big_n / dval(zeta);
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
                    roots: nc,
                    reading: self.reading,
                },
                None,
            ))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_roots_found_to_the_last_bit() {
        // (x − 0.5)(x + 0.25)(x − 0.9) = x³ − 1.15x² + 0.1x + 0.1125
        let p = [0.1125, 0.1, -1.15, 1.0];
        let (r, n) = cubic_roots_in(&p, |x| horner(&p, x) * damping(x), -1.0, 1.0, 1e-9);
        assert_eq!(n, 3);
        for (x, y) in r.iter().zip([-0.25, 0.5, 0.9]) {
            assert!((x - y).abs() < 1e-15, "{x} vs {y}");
        }
    }
}
