//! The friction ratio `ζ = μ η` (`p_t = −ζ p_n`) of Smith's law: the admissible roots in each
//! sign case of the slip before, and the one taken.
//!
//! In ζ, `D` and `Q` do not contain μ: μ only bounds `|ζ| ≤ μ` and multiplies the right-hand
//! side, `ζ (U D² + Q²) = μ σ (U D² − Q²)` with `U = (u⁻)²`. (In η the coefficients grow as μ²
//! and the roots shrink as 1/μ: from μ ≈ 1e20 the root finder's resolution, and at μ ≈ 1e154
//! the monomials, failed.)

use super::cubic::{cubic_roots_in, mul1};

/// `D(ζ) = d[0] + d[1] ζ`, the normal impulse's denominator (`p_n = N / D`), and
/// `Q(ζ) = u⁺ D = q[0] + q[1] ζ`, the reference velocity after times `D`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Lines {
    /// Coefficients of `D`.
    pub(super) d: [f64; 2],
    /// Coefficients of `Q`.
    pub(super) q: [f64; 2],
}

impl Lines {
    /// `D(ζ)`.
    pub(super) fn d(&self, zeta: f64) -> f64 {
        self.d[0] + self.d[1] * zeta
    }

    /// `Q(ζ)`.
    pub(super) fn q(&self, zeta: f64) -> f64 {
        self.q[0] + self.q[1] * zeta
    }
}

/// The admissible friction ratios (`D > 0` and the sign condition of their case).
#[derive(Debug, Clone, Copy)]
pub(super) struct Candidates {
    values: [f64; 6],
    /// How many there are.
    pub(super) count: usize,
    /// With no slip before: the ratio that leaves no slip after (`u⁺ = 0`), when admissible.
    stick: Option<f64>,
}

impl Candidates {
    fn push(&mut self, zeta: f64) {
        self.values[self.count] = zeta;
        self.count += 1;
    }

    /// The slip before has the sign `σ ≠ 0` (`u0` the reference velocity before): the full
    /// ratio `μ σ` if the slip keeps its direction, and the reversal roots of the cubic.
    pub(super) fn sliding(lines: &Lines, u0: f64, mu: f64, sigma: f64) -> Self {
        let mut c = Candidates {
            values: [0.0; 6],
            count: 0,
            stick: None,
        };
        // Roots closer to ζ = 0 than 1e-9 of the natural scale of a friction ratio (1, or μ
        // when smaller) are not chased below round-off.
        let floor = 1e-9 * mu.min(1.0);
        let (d, q) = (lines.d, lines.q);
        let full = mu * sigma;
        if lines.d(full) > 0.0 && sigma * lines.q(full) >= 0.0 {
            c.push(full);
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
            // Damped by 1/max(1, ζ²) (see `cubic::damping`): D and Q divided by max(1, |ζ|).
            let r = 1.0 / zeta.abs().max(1.0);
            let (dv, qv) = (lines.d(zeta) * r, lines.q(zeta) * r);
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
            if lines.d(zeta) > 0.0 && sigma * lines.q(zeta) < 0.0 {
                c.push(zeta);
            }
        }
        c
    }

    /// No slip before (`u⁻ = 0`): `η = ±1` with `sign(u⁺) = η`, or the ratio that leaves
    /// `u⁺ = 0`.
    pub(super) fn zero_slip(lines: &Lines, mu: f64) -> Self {
        let mut c = Candidates {
            values: [0.0; 6],
            count: 0,
            stick: None,
        };
        let q = lines.q;
        for zeta in [mu, -mu] {
            if lines.d(zeta) > 0.0 && zeta * lines.q(zeta) > 0.0 {
                c.push(zeta);
            }
        }
        let zeta = if q[1] != 0.0 {
            -q[0] / q[1]
        } else if q[0] == 0.0 {
            0.0
        } else {
            f64::NAN
        };
        if (-mu..=mu).contains(&zeta) && lines.d(zeta) > 0.0 {
            c.push(zeta);
            c.stick = Some(zeta);
        }
        c
    }

    /// The ratio taken: with no slip before, the one that leaves no slip after; else the
    /// largest `σ ζ`, the least correction of Whittaker's rule. Needs a candidate.
    pub(super) fn chosen(&self, sigma: f64) -> f64 {
        match self.stick {
            Some(zeta) => zeta,
            None => self.values[..self.count]
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, |best, x| {
                    if sigma * x > sigma * best || best == f64::NEG_INFINITY {
                        x
                    } else {
                        best
                    }
                }),
        }
    }
}
