//! The spatial contact-space impact problem `(W, v⁻, μ, e)`.

use crate::error::{finite, Error, Num, Result};
use crate::math::{Mat2, Mat3, Vec2, Vec3};

/// Relative tolerance on the asymmetry of `W` accepted as round-off.
const SYMMETRY_TOL: f64 = 1e-12;

/// A validated spatial impact problem in contact space (theory §1):
///
/// ```text
/// v(p) = v⁻ + W p,   W = J M⁻¹ Jᵀ = [[W_tt, w_tn], [w_tnᵀ, w_nn]],
/// ```
///
/// with the two tangents first and the normal last; `W_tt` is the 2×2 tangential block,
/// `w_tn` the tangential–normal coupling and `w_nn` the normal entry. Approach means
/// `v_n⁻ < 0`; the impulse is the one on body A and `p_n ≥ 0`.
///
/// ```
/// use impax::spatial::ContactProblem3;
/// use impax::math::{Mat3, Vec3};
/// // A sphere (m = 1) on a plane: W = diag(7/2, 7/2, 1).
/// let p = ContactProblem3::new(Mat3::from_diagonal(&Vec3::new(3.5, 3.5, 1.0)),
///                              Vec3::new(0.5, 0.0, -0.866), 0.4, 0.7).unwrap();
/// assert_eq!(p.wnn(), 1.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactProblem3 {
    w: Mat3,
    v: Vec3,
    mu: f64,
    e: f64,
}

impl ContactProblem3 {
    /// Validate and build a problem.
    ///
    /// Errors (each names its field): a non-finite entry; `W` not symmetric (beyond
    /// round-off) or not positive definite (its Cholesky factorisation fails or is
    /// numerically singular); `v_n ≥ 0`; `μ < 0`; `e ∉ [0, 1]`; a velocity whose approach
    /// energy `½ v⁻ᵀ W⁻¹ v⁻` overflows.
    pub fn new(w: Mat3, v: Vec3, friction: f64, restitution: f64) -> Result<Self> {
        const NAMES: [&str; 3] = ["t1", "t2", "n"];
        // (The field's name is formatted only for the error.)
        for i in 0..3 {
            for j in 0..3 {
                if !w[(i, j)].is_finite() {
                    finite(&format!("w[{},{}]", NAMES[i], NAMES[j]), w[(i, j)])?;
                }
            }
            if !v[i].is_finite() {
                finite(&format!("v[{}]", NAMES[i]), v[i])?;
            }
        }
        finite("friction", friction)?;
        finite("restitution", restitution)?;
        let scale = w.abs().max().max(f64::MIN_POSITIVE);
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            if (w[(i, j)] - w[(j, i)]).abs() > SYMMETRY_TOL * scale {
                return Err(Error::NotSymmetric {
                    field: "w".into(),
                    upper: w[(i, j)],
                    lower: w[(j, i)],
                });
            }
        }
        let w = 0.5 * (w + w.transpose());
        for i in 0..3 {
            if w[(i, i)] <= 0.0 {
                return Err(Error::NotPositiveDefinite {
                    field: "w".into(),
                    reason: format!(
                        "diagonal entry {} = {} is not positive",
                        i + 1,
                        Num(w[(i, i)])
                    ),
                });
            }
        }
        // Leading principal minors (Sylvester), relative to the diagonal product.
        let m2 = w[(0, 0)] * w[(1, 1)] - w[(0, 1)] * w[(0, 1)];
        let m3 = w.determinant();
        let diag = w[(0, 0)] * w[(1, 1)] * w[(2, 2)];
        if m2 <= 1e-14 * w[(0, 0)] * w[(1, 1)] || m3 <= 1e-14 * diag {
            return Err(Error::NotPositiveDefinite {
                field: "w".into(),
                reason: format!(
                    "its leading minors are {:e} and {m3:e} (both must be positive, beyond round-off)",
                    m2
                ),
            });
        }
        if v.z >= 0.0 {
            return Err(Error::NotApproaching {
                field: "v".into(),
                value: v.z,
            });
        }
        crate::error::coefficients(friction, restitution)?;
        let problem = Self {
            w,
            v,
            mu: friction,
            e: restitution,
        };
        let energy = problem.approach_energy();
        crate::error::representable_energy(energy, v.norm())?;
        Ok(problem)
    }

    /// Build from the upper triangle of `W`, row by row (`W11, W12, W13, W22, W23, W33`),
    /// and `(v_t1, v_t2, v_n)`.
    pub fn from_upper(w: [f64; 6], v: [f64; 3], friction: f64, restitution: f64) -> Result<Self> {
        let m = Mat3::new(w[0], w[1], w[2], w[1], w[3], w[4], w[2], w[4], w[5]);
        Self::new(m, Vec3::new(v[0], v[1], v[2]), friction, restitution)
    }

    /// Embed a planar problem: the second tangent decoupled (`W_22 = w22`, no coupling).
    pub fn from_planar(p: &crate::planar::ContactProblem, w22: f64) -> Result<Self> {
        let m = Mat3::new(p.wtt(), 0.0, p.wtn(), 0.0, w22, 0.0, p.wtn(), 0.0, p.wnn());
        let v = p.velocity();
        Self::new(m, Vec3::new(v.x, 0.0, v.y), p.friction(), p.restitution())
    }

    /// The same problem with velocities times `a` and `W` times `b` (powers of two: exact),
    /// without the validation of [`ContactProblem3::new`] (the approach energy may not be
    /// representable in these units).
    pub(crate) fn in_units(&self, a: f64, b: f64) -> Self {
        Self {
            w: self.w * b,
            v: self.v * a,
            ..*self
        }
    }

    /// The matrix `W`.
    #[inline]
    pub fn w(&self) -> &Mat3 {
        &self.w
    }
    /// The tangential block `W_tt` (2×2).
    #[inline]
    pub fn wtt(&self) -> Mat2 {
        Mat2::new(
            self.w[(0, 0)],
            self.w[(0, 1)],
            self.w[(1, 0)],
            self.w[(1, 1)],
        )
    }
    /// The coupling `w_tn` (2-vector).
    #[inline]
    pub fn wtn(&self) -> Vec2 {
        Vec2::new(self.w[(0, 2)], self.w[(1, 2)])
    }
    /// The normal entry `w_nn`.
    #[inline]
    pub fn wnn(&self) -> f64 {
        self.w[(2, 2)]
    }
    /// Pre-impact contact velocity `(v_t1⁻, v_t2⁻, v_n⁻)`.
    #[inline]
    pub fn velocity(&self) -> Vec3 {
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
    pub fn velocity_after(&self, p: Vec3) -> Vec3 {
        self.v + self.w * p
    }

    /// Exact kinetic-energy change of any impulse: `ΔT = v⁻·p + ½ pᵀ W p`.
    #[inline]
    pub fn energy_change(&self, p: Vec3) -> f64 {
        self.v.dot(&p) + 0.5 * p.dot(&(self.w * p))
    }

    /// `½ v⁻ᵀ W⁻¹ v⁻`, the most energy any impulse can remove (the scale of energy checks).
    pub fn approach_energy(&self) -> f64 {
        match self.w.cholesky() {
            Some(ch) => 0.5 * self.v.dot(&ch.solve(&self.v)),
            None => f64::INFINITY,
        }
    }

    /// The same problem with the tangent plane rotated by `angle` (radians) about the
    /// normal: `W → R W Rᵀ`, `v → R v`. Impulse magnitudes and normal parts are invariant.
    pub fn rotated(&self, angle: f64) -> Result<Self> {
        let (s, c) = angle.sin_cos();
        let r = Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0);
        Self::new(r * self.w * r.transpose(), r * self.v, self.mu, self.e)
    }
}
