//! What the planar `lzb` and the spatial one ([`crate::multi::spatial::lzb`]) share, whatever
//! the number of tangents: the contacts' force law and the scales it sets, the normal regimes
//! and their works, the primary contact, the step-size control and the pseudo-inverse of a
//! stick set's tangential block.

use crate::multi::{LzbPrimary, RANK_TOL};
use crate::numerics::dop853::Interpolant;
use crate::numerics::roots::illinois;

use super::PRIMARY_MARGIN;

/// How `s^η` is evaluated: exactly for the common exponents, by `powf` otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::multi) enum Power {
    /// `η = 1`: a linear spring.
    One,
    /// `η = 3/2`: Hertz, `s √s`.
    ThreeHalves,
    /// Any other `η > 0`.
    General(f64),
}

impl Power {
    #[inline(always)]
    pub(in crate::multi) fn of(self, s: f64) -> f64 {
        match self {
            Power::One => s,
            Power::ThreeHalves => s * s.sqrt(),
            Power::General(eta) => s.powf(eta),
        }
    }
}

/// The contacts' force law `F = κ s^η` and the power `m` of the regularising variables.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::multi) struct ForceLaw {
    /// The exponent `η`.
    pub eta: f64,
    /// `s^η`.
    pub power: Power,
    /// The power `m` of the regularising variables at the start (`τ = u^m`) and at a
    /// separation (`s_j = σ^m`): 1 when `s^η` is analytic (an integer `η`: no
    /// regularisation), 2 when `2η` is an integer (`η = 3/2`: `F ∝ u³`), else the least with
    /// `m η ≥ 9` (the force then smooth to the integrator's order).
    pub m: i32,
    /// `ζ = 2η` where it is an integer from 2 to 6: a force from a double zero of `s`,
    /// `κ (t² q)^η = κ t^ζ q^η`, is then analytic in `t` (a contact joining, the impact's
    /// start in `u = √τ`), and the series of order 17 keeps at least 11 of its terms.
    /// `None` otherwise (the Runge–Kutta step is taken there).
    pub double_zero: Option<usize>,
}

impl ForceLaw {
    /// The law of exponent `eta > 0`.
    pub(in crate::multi) fn new(eta: f64) -> ForceLaw {
        let power = if eta == 1.0 {
            Power::One
        } else if eta == 1.5 {
            Power::ThreeHalves
        } else {
            Power::General(eta)
        };
        let m = if eta.fract() == 0.0 {
            1
        } else if (2.0 * eta).fract() == 0.0 {
            2
        } else {
            ((9.0 / eta).ceil() as i32).clamp(2, 24)
        };
        let zeta = 2.0 * eta;
        let double_zero =
            (zeta.fract() == 0.0 && (2.0..=6.0).contains(&zeta)).then_some(zeta as usize);
        ForceLaw {
            eta,
            power,
            m,
            double_zero,
        }
    }

    /// `x^(m−1)` by repeated squaring, as `f64::powi` computes it (`x` itself for the
    /// common `m = 2`), without the call `powi` makes (which the compiler would also make
    /// where the result is not needed).
    #[inline(always)]
    pub(in crate::multi) fn power_m1(&self, x: f64) -> f64 {
        let (mut base, mut n, mut out) = (x, self.m - 1, 1.0);
        debug_assert!(n >= 0);
        loop {
            if n & 1 != 0 {
                out *= base;
            }
            n >>= 1;
            if n == 0 {
                return out;
            }
            base *= base;
        }
    }

    /// The normal force `κ s^η` (zero for `s ≤ 0`).
    #[inline(always)]
    pub(in crate::multi) fn force(&self, kappa: f64, s: f64) -> f64 {
        if s > 0.0 {
            kappa * self.power.of(s)
        } else {
            0.0
        }
    }

    /// The stored energy `κ s^(η+1)/(η+1) = s F/(η+1)` (zero for `s ≤ 0`).
    #[inline]
    pub(in crate::multi) fn energy(&self, kappa: f64, s: f64) -> f64 {
        s.max(0.0) * self.force(kappa, s) / (self.eta + 1.0)
    }

    /// The factor `κ^(1/(η+1))` of the primary's ordering quantity, once per contact.
    #[inline]
    pub(in crate::multi) fn order(&self, kappa: f64) -> f64 {
        kappa.powf(1.0 / (self.eta + 1.0))
    }

    /// The primary's ordering quantity `κ^(1/(η+1)) s` from the contact's factor `order`
    /// ([`ForceLaw::order`]), increasing with the stored energy.
    #[inline]
    pub(in crate::multi) fn energy_order(&self, order: f64, s: f64) -> f64 {
        order * s.max(0.0)
    }

    /// The deflection that stores `energy`.
    #[inline]
    pub(in crate::multi) fn deflection(&self, kappa: f64, energy: f64) -> f64 {
        ((self.eta + 1.0) * energy / kappa).powf(1.0 / (self.eta + 1.0))
    }

    /// The scales of a contact of own normal entry `wnn` and stiffness ratio `kappa` when
    /// the velocities are of size `vmax`: the normal impulse that would stop `vmax` at the
    /// contact alone, the energy of that impulse, the deflection that stores it.
    #[inline]
    pub(in crate::multi) fn scales(&self, kappa: f64, wnn: f64, vmax: f64) -> (f64, f64, f64) {
        let p = vmax / wnn;
        let energy = 0.5 * vmax * vmax / wnn;
        (p, energy, self.deflection(kappa, energy))
    }

    /// The time `τ = z^(1/(η+1))` at `z` of the start's variable (`variable.rs`).
    #[inline]
    pub(in crate::multi) fn onset_time(&self, z: f64) -> f64 {
        z.max(0.0).powf(1.0 / (self.eta + 1.0))
    }

    /// `dτ/dz = τ^(−η)/(η+1)` at `z = τ^(η+1)` (infinite at `z = 0`).
    #[inline]
    pub(in crate::multi) fn onset_rate(&self, z: f64) -> f64 {
        z.powf(-self.eta / (self.eta + 1.0)) / (self.eta + 1.0)
    }

    /// The time `τ` a contact alone approaching at `vn < 0` would compress in (straight:
    /// the deflection of its energy over its speed).
    #[inline]
    pub(in crate::multi) fn compression_time(&self, kappa: f64, wnn: f64, vn: f64) -> f64 {
        let energy = 0.5 * vn * vn / wnn;
        self.deflection(kappa, energy) / -vn
    }
}

/// The stiffness ratios: each stiffness over the largest, kept representable (a ratio below
/// the smallest normal number would make the forces vanish; the contact is then as soft as
/// arithmetic allows).
pub(in crate::multi) fn stiffness_ratios(stiffness: &[f64], out: &mut [f64]) {
    let kmax = stiffness.iter().fold(0.0f64, |m, &x| m.max(x));
    for (o, &x) in out.iter_mut().zip(stiffness) {
        *o = (x / kmax).max(f64::MIN_POSITIVE);
    }
}

/// The normal regime of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(in crate::multi) enum Normal {
    /// No force: not in contact, or separated (`s = 0`, `v_n ≥ −approach`).
    Off,
    /// Compression: `v_n < 0`, `ds/dτ = −v_n` (the energy stored is the normal work done).
    Compression,
    /// Expansion: `v_n ≥ 0`, `ds/dτ = −v_n / e²` (the normal work done is `e²` times the
    /// energy released).
    Expansion,
}

/// A contact's normal work, split by the sign of `v_n`, from its stored energy at the ends
/// of its normal phases.
#[derive(Debug, Clone, Copy, Default)]
pub(in crate::multi) struct NormalWork {
    /// The stored energy at the start of the current normal phase.
    pub mark: f64,
    /// Normal work in compression so far.
    pub compression: f64,
    /// Normal work in expansion so far.
    pub restitution: f64,
}

impl NormalWork {
    /// A compression ends with `energy` stored: its work is the energy it stored.
    #[inline]
    pub(in crate::multi) fn end_compression(&mut self, energy: f64) {
        self.compression -= energy - self.mark;
    }

    /// An expansion ends (or pauses) with `energy` stored: its work is `e²` times the energy
    /// it released.
    #[inline]
    pub(in crate::multi) fn end_expansion(&mut self, energy: f64, e2: f64) {
        self.restitution += e2 * (self.mark - energy);
    }
}

/// The primary contact (the most stored energy) and the primaries in turn.
#[derive(Debug, Clone)]
pub(in crate::multi) struct Primary {
    /// The current primary.
    pub contact: usize,
    /// Every primary in turn.
    pub list: Vec<LzbPrimary>,
}

impl Primary {
    /// The first primary, at the start.
    pub(in crate::multi) fn start(contact: usize) -> Primary {
        Primary {
            contact,
            list: vec![LzbPrimary {
                contact,
                impulse: 0.0,
            }],
        }
    }

    /// The primary along a step from `y0` to the fraction `theta` of the step, where the
    /// state is `y1`: among the contacts `active` of `0..k`, one whose ordering quantity
    /// (`order`) exceeds the primary's by more than [`PRIMARY_MARGIN`] takes over, where it
    /// overtook the primary's (located on the dense output, which is built only then);
    /// `pn(c, y)` is contact `c`'s normal impulse.
    #[allow(clippy::too_many_arguments)]
    pub(in crate::multi) fn follow<const N: usize, D: Interpolant<N>>(
        &mut self,
        k: usize,
        theta: f64,
        y0: &[f64; N],
        y1: &[f64; N],
        dense: &dyn Fn() -> D,
        order: impl Fn(usize, &[f64]) -> f64,
        active: impl Fn(usize) -> bool,
        pn: impl Fn(usize, &[f64]) -> f64,
    ) {
        let m = self.contact;
        let qm = order(m, y1);
        let mut best = (qm * (1.0 + PRIMARY_MARGIN), m);
        for j in (0..k).filter(|&j| active(j)) {
            let q = order(j, y1);
            if q > best.0 {
                best = (q, j);
            }
        }
        let c = best.1;
        if c == m {
            return;
        }
        let g = |y: &[f64]| order(c, y) - (1.0 + PRIMARY_MARGIN) * order(m, y);
        let g0 = g(y0);
        let at = if g0 > 0.0 {
            pn(c, y0)
        } else {
            let d = dense();
            let th = illinois(|th| g(&d.at(th)), 0.0, g0, theta, g(y1).max(0.0));
            pn(c, &d.at(th))
        };
        self.contact = c;
        self.list.push(LzbPrimary {
            contact: c,
            impulse: at,
        });
    }

    /// Contact `j` carries no force any more: if it was the primary, the contact among
    /// `active` with the most stored energy (`order`) takes over at its normal impulse `pn`.
    pub(in crate::multi) fn hand_over(
        &mut self,
        j: usize,
        k: usize,
        order: impl Fn(usize) -> f64,
        active: impl Fn(usize) -> bool,
        pn: impl Fn(usize) -> f64,
    ) {
        if j != self.contact {
            return;
        }
        let mut best = (0.0, j);
        for c in (0..k).filter(|&c| active(c)) {
            let q = order(c);
            if q > best.0 {
                best = (q, c);
            }
        }
        if best.1 != j {
            self.contact = best.1;
            self.list.push(LzbPrimary {
                contact: best.1,
                impulse: pn(best.1),
            });
        }
    }
}

/// A step of `τ` for going on: `h`, or a hundredth of the shortest compression time if `h`
/// is not a positive number (a change of variable where `dτ/dx` vanishes).
#[inline]
pub(in crate::multi) fn guard(h: f64, shortest: f64) -> f64 {
    if h > 0.0 && h.is_finite() {
        h
    } else {
        0.01 * shortest
    }
}

/// Step-size factor after a rejected step (`en > 1` or NaN): `0.9 en^(-1/8)`, at least 0.2.
#[inline]
pub(in crate::multi) fn shrink(en: f64) -> f64 {
    if en.is_finite() {
        (0.9 / en.sqrt().sqrt().sqrt()).max(0.2)
    } else {
        0.2
    }
}

/// Step-size factor after an accepted step: `0.9 en^(-1/8)`, at most 6.
#[inline]
pub(in crate::multi) fn grow(en: f64) -> f64 {
    (0.9 / en.max(1e-10).sqrt().sqrt().sqrt()).min(6.0)
}

/// The pseudo-inverse of the symmetric positive semidefinite `n × n` matrix `a` (cyclic
/// Jacobi; eigenvalues within [`RANK_TOL`] of the largest are zero).
#[allow(clippy::needless_range_loop)] // the rotations index rows and columns alike
pub(in crate::multi) fn pseudo_inverse<const M: usize>(
    mut a: [[f64; M]; M],
    n: usize,
) -> [[f64; M]; M] {
    let mut out = [[0.0; M]; M];
    if n == 1 {
        if a[0][0] > 0.0 {
            out[0][0] = 1.0 / a[0][0];
        }
        return out;
    }
    let mut v = [[0.0; M]; M];
    for (i, row) in v.iter_mut().enumerate().take(n) {
        row[i] = 1.0;
    }
    for _ in 0..64 {
        let mut off = 0.0;
        let mut diag = 0.0;
        for p in 0..n {
            diag += a[p][p] * a[p][p];
            for q in p + 1..n {
                off += a[p][q] * a[p][q];
            }
        }
        if off <= 1e-34 * diag {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                let apq = a[p][q];
                if apq == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * apq);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for k in 0..n {
                    let (vkp, vkq) = (v[k][p], v[k][q]);
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
    }
    let dmax = (0..n).fold(0.0f64, |m, i| m.max(a[i][i].abs()));
    for e in 0..n {
        let d = a[e][e];
        if d > RANK_TOL * dmax {
            for p in 0..n {
                for q in 0..n {
                    out[p][q] += v[p][e] * v[q][e] / d;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::needless_range_loop)] // matrices indexed as written
    fn pseudo_inverse_of_a_singular_and_a_regular_matrix() {
        // [[1, 1], [1, 1]]⁺ = [[1, 1], [1, 1]] / 4.
        let mut a = [[0.0; 8]; 8];
        a[0][0] = 1.0;
        a[0][1] = 1.0;
        a[1][0] = 1.0;
        a[1][1] = 1.0;
        let p = pseudo_inverse(a, 2);
        for r in 0..2 {
            for c in 0..2 {
                assert!((p[r][c] - 0.25).abs() < 1e-15, "{p:?}");
            }
        }
        // A regular 3 × 3: the inverse.
        let m = [[4.0, -2.0, 1.0], [-2.0, 4.0, -2.0], [1.0, -2.0, 4.0]];
        let mut a = [[0.0; 16]; 16];
        for r in 0..3 {
            for c in 0..3 {
                a[r][c] = m[r][c];
            }
        }
        let p = pseudo_inverse(a, 3);
        for r in 0..3 {
            for c in 0..3 {
                let x: f64 = (0..3).map(|i| m[r][i] * p[i][c]).sum();
                let id = if r == c { 1.0 } else { 0.0 };
                assert!((x - id).abs() < 1e-14, "{r} {c}: {x}");
            }
        }
    }
}
