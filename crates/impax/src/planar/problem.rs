//! The planar contact-space impact problem `(W, v⁻, μ, e)`.

use crate::error::{finite, Error, Num, Result};
use crate::math::{Mat2, Units, Vec2};

/// A validated planar impact problem in contact space.
///
/// During an impact the configuration is frozen and the contact velocity is affine in the
/// impulse `p` applied to body A (theory §1):
///
/// ```text
/// v(p) = v⁻ + W p,     W = J M⁻¹ Jᵀ = [[a, b], [b, c]],   a = W_tt, b = W_tn, c = W_nn.
/// ```
///
/// Conventions: tangent first, normal last; the normal points out of the struck surface;
/// approach means `v_n⁻ < 0`; the impulse is the one on body A and `p_n ≥ 0`.
///
/// ```
/// use impax::planar::ContactProblem;
/// use impax::math::{Mat2, Vec2};
/// // The seed's sphere (m = 1): W = diag(7/2, 1), α = 30°, v0 = 1, γ = 0.
/// let a = 30f64.to_radians();
/// let p = ContactProblem::new(Mat2::new(3.5, 0.0, 0.0, 1.0), Vec2::new(a.sin(), -a.cos()), 0.4, 0.7)
///     .unwrap();
/// assert_eq!(p.wtt(), 3.5);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactProblem {
    a: f64,
    b: f64,
    c: f64,
    v: Vec2,
    mu: f64,
    e: f64,
}

/// Relative tolerance on the asymmetry of `W` accepted as round-off.
const SYMMETRY_TOL: f64 = 1e-12;

/// A validated contact-space inverse inertia `W = J M⁻¹ Jᵀ` (symmetric positive definite):
/// the part of a [`ContactProblem`] fixed by the bodies and the contact, checked once.
///
/// A sweep that varies only the velocities and coefficients builds this once and then each
/// point with [`ContactProblem::with_inertia`], which checks only what changes.
///
/// ```
/// use impax::planar::{ContactProblem, InverseInertia};
/// use impax::math::{Mat2, Vec2};
/// let w = InverseInertia::new(Mat2::new(3.5, 0.0, 0.0, 1.0)).unwrap();
/// let p = ContactProblem::with_inertia(&w, Vec2::new(0.5, -0.8), 0.4, 0.7).unwrap();
/// assert_eq!(p, ContactProblem::new(w.matrix(), Vec2::new(0.5, -0.8), 0.4, 0.7).unwrap());
/// assert!(InverseInertia::new(Mat2::new(1.0, 2.0, 2.0, 1.0)).is_err()); // det < 0
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InverseInertia {
    a: f64,
    b: f64,
    c: f64,
}

impl InverseInertia {
    /// Validate `W`. Errors (each names the field `w`): a non-finite entry; `W` not symmetric
    /// beyond round-off (relative 1e-12; the mean of the two off-diagonal entries is kept);
    /// `W_tt ≤ 0`, `W_nn ≤ 0` or `det W ≤ 1e-14 W_tt W_nn` (not positive definite).
    pub fn new(w: Mat2) -> Result<Self> {
        for (i, j, name) in [
            (0, 0, "w[t,t]"),
            (0, 1, "w[t,n]"),
            (1, 0, "w[n,t]"),
            (1, 1, "w[n,n]"),
        ] {
            finite(name, w[(i, j)])?;
        }
        let (a, c) = (w[(0, 0)], w[(1, 1)]);
        let (upper, lower) = (w[(0, 1)], w[(1, 0)]);
        let scale = a.abs().max(c.abs()).max(upper.abs()).max(f64::MIN_POSITIVE);
        if (upper - lower).abs() > SYMMETRY_TOL * scale {
            return Err(Error::NotSymmetric {
                field: "w".into(),
                upper,
                lower,
            });
        }
        let b = 0.5 * upper + 0.5 * lower;
        if a <= 0.0 {
            return Err(Error::NotPositiveDefinite {
                field: "w".into(),
                reason: format!("W_tt = {} is not positive", Num(a)),
            });
        }
        if c <= 0.0 {
            return Err(Error::NotPositiveDefinite {
                field: "w".into(),
                reason: format!("W_nn = {} is not positive", Num(c)),
            });
        }
        // det W relative to W_tt W_nn, on entries divided by the largest (no overflow at
        // 1e308, no underflow at 1e-308).
        let s = a.max(c).max(b.abs());
        let (an, bn, cn) = (a / s, b / s, c / s);
        let det = an * cn - bn * bn;
        if det <= 1e-14 * an * cn {
            return Err(Error::NotPositiveDefinite {
                field: "w".into(),
                reason: if det <= 0.0 {
                    format!(
                        "det W = W_tt W_nn − W_tn² is not positive ({} of W_tt W_nn)",
                        Num(det / (an * cn))
                    )
                } else {
                    format!(
                        "det W = W_tt W_nn − W_tn² is {} of W_tt W_nn, below 1e-14 (numerically singular)",
                        Num(det / (an * cn))
                    )
                },
            });
        }
        Ok(Self { a, b, c })
    }

    /// The matrix `[[W_tt, W_tn], [W_tn, W_nn]]`.
    pub fn matrix(&self) -> Mat2 {
        Mat2::new(self.a, self.b, self.b, self.c)
    }
}

impl ContactProblem {
    /// Validate and build a problem.
    ///
    /// Errors (each names its field): a non-finite entry; `W` not symmetric (beyond round-off)
    /// or not positive definite (see [`InverseInertia::new`]); `v_n ≥ 0`; `μ < 0` or
    /// `μ >` [`MAX_FRICTION`](crate::error::MAX_FRICTION);
    /// `e ∉ [0, 1]`; a velocity so large for `W` that the approach energy `½ v⁻ᵀ W⁻¹ v⁻`
    /// overflows.
    pub fn new(w: Mat2, v: Vec2, friction: f64, restitution: f64) -> Result<Self> {
        Self::with_inertia(&InverseInertia::new(w)?, v, friction, restitution)
    }

    /// Build a problem on an already validated `W`: checks only the velocity (finite,
    /// approaching: `v_n < 0`, approach energy representable) and the coefficients
    /// (finite, `0 ≤ μ ≤ 1e300`, `0 ≤ e ≤ 1`). The result equals [`ContactProblem::new`]'s bit for
    /// bit; this is the per-point path of sweeps (no allocation unless the point is invalid).
    #[inline]
    pub fn with_inertia(
        w: &InverseInertia,
        v: Vec2,
        friction: f64,
        restitution: f64,
    ) -> Result<Self> {
        let problem = Self {
            a: w.a,
            b: w.b,
            c: w.c,
            v,
            mu: friction,
            e: restitution,
        };
        // Every impulse and work of an impact is bounded by the approach energy scale; if
        // that overflows the numbers cannot be represented. One branch on the common path:
        // a finite energy with finite inputs, approach, and coefficients in range.
        let energy = problem.approach_energy();
        let ok = energy.is_finite()
            && v.x.is_finite()
            && v.y < 0.0
            && (0.0..=crate::error::MAX_FRICTION).contains(&friction)
            && (0.0..=1.0).contains(&restitution);
        if ok {
            Ok(problem)
        } else {
            Err(Self::velocity_error(v, friction, restitution, energy))
        }
    }

    /// The error of [`ContactProblem::with_inertia`], in the order of the checks of
    /// [`ContactProblem::new`] (kept off the common path).
    #[cold]
    #[inline(never)]
    fn velocity_error(v: Vec2, friction: f64, restitution: f64, energy: f64) -> Error {
        let check = || -> Result<()> {
            finite("v[t]", v.x)?;
            finite("v[n]", v.y)?;
            finite("friction", friction)?;
            finite("restitution", restitution)?;
            if v.y >= 0.0 {
                return Err(Error::NotApproaching {
                    field: "v".into(),
                    value: v.y,
                });
            }
            crate::error::coefficients(friction, restitution)?;
            crate::error::representable_energy(energy, v.norm())
        };
        // Every way `with_inertia`'s test can fail is one of the checks above.
        check().err().unwrap_or(Error::NotFinite {
            field: "v".into(),
            value: energy,
        })
    }

    /// Build from the three independent entries `(W_tt, W_tn, W_nn)` and `(v_t, v_n)`.
    pub fn from_entries(
        wtt: f64,
        wtn: f64,
        wnn: f64,
        vt: f64,
        vn: f64,
        friction: f64,
        restitution: f64,
    ) -> Result<Self> {
        Self::new(
            Mat2::new(wtt, wtn, wtn, wnn),
            Vec2::new(vt, vn),
            friction,
            restitution,
        )
    }

    /// `W_tt` (theory's `a`).
    #[inline]
    pub fn wtt(&self) -> f64 {
        self.a
    }
    /// `W_tn` (theory's `b`).
    #[inline]
    pub fn wtn(&self) -> f64 {
        self.b
    }
    /// `W_nn` (theory's `c`).
    #[inline]
    pub fn wnn(&self) -> f64 {
        self.c
    }
    /// The matrix `W`.
    pub fn w(&self) -> Mat2 {
        Mat2::new(self.a, self.b, self.b, self.c)
    }
    /// Pre-impact contact velocity `(v_t⁻, v_n⁻)`.
    #[inline]
    pub fn velocity(&self) -> Vec2 {
        self.v
    }
    /// Coulomb friction coefficient `μ`.
    #[inline]
    pub fn friction(&self) -> f64 {
        self.mu
    }
    /// Coefficient of restitution `e`.
    #[inline]
    pub fn restitution(&self) -> f64 {
        self.e
    }

    /// Contact velocity after an impulse: `v⁻ + W p`.
    #[inline]
    pub fn velocity_after(&self, p: Vec2) -> Vec2 {
        Vec2::new(
            self.v.x + self.a * p.x + self.b * p.y,
            self.v.y + self.b * p.x + self.c * p.y,
        )
    }

    /// Exact kinetic-energy change of any impulse: `ΔT = v⁻·p + ½ pᵀ W p = ½ (v⁻ + v⁺)·p`.
    #[inline]
    pub fn energy_change(&self, p: Vec2) -> f64 {
        let wp = Vec2::new(self.a * p.x + self.b * p.y, self.b * p.x + self.c * p.y);
        self.v.dot(&p) + 0.5 * p.dot(&wp)
    }

    /// Contact-space kinetic energy of the approach, `½ v⁻ᵀ W⁻¹ v⁻`: the most energy any
    /// impulse can remove (reached by the impulse that stops the contact point). Used as
    /// the scale for "energy gained" decisions.
    #[inline]
    pub fn approach_energy(&self) -> f64 {
        let det = self.a * self.c - self.b * self.b;
        let (vt, vn) = (self.v.x, self.v.y);
        let energy = 0.5 * (self.c * vt * vt - 2.0 * self.b * vt * vn + self.a * vn * vn) / det;
        if energy.is_finite() && det.is_normal() {
            return energy;
        }
        // Extreme entries (det W or the squares under- or overflow): the same with W and v
        // divided by their largest entries (½ vᵀ W⁻¹ v scales as v²/W).
        let s = self.a.max(self.c).max(self.b.abs());
        let r = self.v.x.abs().max(self.v.y.abs());
        if r == 0.0 {
            return 0.0;
        }
        let (a, b, c) = (self.a / s, self.b / s, self.c / s);
        let (vt, vn) = (vt / r, vn / r);
        let unit = 0.5 * (c * vt * vt - 2.0 * b * vt * vn + a * vn * vn) / (a * c - b * b);
        unit * (r / s) * r
    }

    /// The same problem with the tangent reversed (`t → −t`): `W_tn → −W_tn`, `v_t → −v_t`.
    pub fn mirrored(&self) -> Self {
        Self {
            b: -self.b,
            v: Vec2::new(-self.v.x, self.v.y),
            ..*self
        }
    }

    /// The same problem with another friction coefficient and restitution (unchecked
    /// ranges are re-validated).
    pub fn with_coefficients(&self, friction: f64, restitution: f64) -> Result<Self> {
        Self::with_inertia(&self.inverse_inertia(), self.v, friction, restitution)
    }

    /// The problem in units where its normal velocity and `W_nn` are near one, when they are
    /// not (outside `[2⁻⁶⁰, 2⁶⁰]`, where the normal works `∝ v_n²/W_nn` and the squares in
    /// the laws under- or overflow): `v → a v`, `W → b W` with `a`, `b` powers of two —
    /// exact, so a law's result in these units, scaled back by [`Units`], is the result
    /// the law would give with an unbounded exponent. Each factor is limited so that no
    /// nonzero entry leaves `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰]`. `None` when no scaling is needed (the common
    /// case).
    #[inline]
    pub(crate) fn in_units(&self) -> Option<(ContactProblem, Units)> {
        const LO: f64 = 1.0 / (1u64 << 60) as f64;
        const HI: f64 = (1u64 << 60) as f64;
        let vn = self.v.y.abs();
        if (LO..=HI).contains(&vn) && (LO..=HI).contains(&self.c) {
            return None;
        }
        let a = Units::factor(vn, &[self.v.x, self.v.y]);
        let b = Units::factor(self.c, &[self.a, self.b, self.c]);
        let scaled = ContactProblem {
            a: self.a * b,
            b: self.b * b,
            c: self.c * b,
            v: self.v * a,
            mu: self.mu,
            e: self.e,
        };
        Some((scaled, Units { a, b }))
    }

    /// The validated `W` of this problem.
    #[inline]
    pub fn inverse_inertia(&self) -> InverseInertia {
        InverseInertia {
            a: self.a,
            b: self.b,
            c: self.c,
        }
    }
}
