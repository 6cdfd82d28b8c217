//! The spatial contact-space impact problem `(W, v⁻, μ, e)`.

use crate::error::{finite, Error, Num, Result};
use crate::math::{Mat2, Mat3, Vec2, Vec3};

/// Relative tolerance on the asymmetry of `W` accepted as round-off.
const SYMMETRY_TOL: f64 = 1e-12;

/// The smallest pivot of `W = L D Lᵀ` (order `t1, t2, n`) accepted, relative to the largest
/// eigenvalue `λ_max` of `W`: `W` is refused as numerically singular when a pivot is at most
/// `PIVOT_TOL λ_max`.
pub const PIVOT_TOL: f64 = 1e-11;

/// A tangential component of `v⁻` or of `w_tn` below this, in the units where `|v_n⁻|` and
/// `w_nn` are in `[1, 2)` (powers of two), is taken as zero by the Darboux–Keller laws
/// (`newton`, `poisson`, `energetic`): its effect on their result is below this fraction of
/// the result's scale, and with it the integration of the slip would work with numbers a few
/// dozen orders of magnitude from the subnormal range.
pub const NEGLIGIBLE_SLIP: f64 = 1e-250;

/// Check that the symmetric `w` is positive definite beyond round-off (see
/// [`ContactProblem::new`]); the reason names the failing quantity with its value.
pub(crate) fn positive_definite(w: &Mat3) -> Result<()> {
    const NAMES: [&str; 3] = ["t1", "t2", "n"];
    let refuse = |reason: String| {
        Err(Error::NotPositiveDefinite {
            field: "w".into(),
            reason,
        })
    };
    for i in 0..3 {
        if w[(i, i)] <= 0.0 {
            let n = NAMES[i];
            return refuse(format!(
                "its diagonal entry w[{n},{n}] = {} is not positive",
                w[(i, i)]
            ));
        }
    }
    // Each 2×2 principal minor: W_ij² ≤ W_ii W_jj (a larger entry, beyond the round-off of
    // the bound, makes W indefinite, and would make the pivots below overflow).
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let bound = w[(i, i)].sqrt() * w[(j, j)].sqrt();
        if w[(i, j)].abs() > bound * (1.0 + 4.0 * f64::EPSILON) {
            let (a, b) = (NAMES[i], NAMES[j]);
            return refuse(format!(
                "W is indefinite: |w[{a},{b}]| = {} exceeds √(w[{a},{a}] w[{b},{b}]) = {}",
                Num(w[(i, j)].abs()),
                Num(bound)
            ));
        }
    }
    // In units of the largest entry (a power of two: exact), where nothing over- or
    // underflows; the diagonal is then at most 1 and the off-diagonal entries are bounded by it.
    let s = crate::math::unit_factor(w.amax(), w.as_slice());
    let a = w * s;
    let lambda_max = a.symmetric_eigenvalues().max();
    // L D Lᵀ in the order t1, t2, n (see `ldl`).
    let (d, _) = ldl(&a, 0.0);
    // (Six significant digits in the message.)
    let short = |x: f64| format!("{x:.5e}").parse::<f64>().unwrap_or(x);
    let pivot = |k: usize, d: f64| -> Result<()> {
        if d > PIVOT_TOL * lambda_max {
            return Ok(());
        }
        let (d, l) = (short(d / s), short(lambda_max / s));
        if d < -PIVOT_TOL * l {
            refuse(format!(
                "W is indefinite: its L D Lᵀ pivot {k} (order t1, t2, n) is {}",
                Num(d)
            ))
        } else {
            refuse(format!(
                "W is numerically singular: its L D Lᵀ pivot {k} (order t1, t2, n) is {}, not above {} of its largest eigenvalue {}",
                Num(d),
                Num(PIVOT_TOL),
                Num(l)
            ))
        }
    };
    pivot(1, d.x)?;
    pivot(2, d.y)?;
    pivot(3, d.z)
}

/// `W = L D Lᵀ` in the order `t1, t2, n`, without pivoting, for `W + c diag(1, 1, 0)`: the
/// pivots `(d1, d2, d3)`, and `λ = −(W_tt + c I)⁻¹ w_tn = −(l31 − l21 l32, l32)` from the
/// multipliers of the unit lower triangular `L` (back substitution `L_ttᵀ λ = −(l31, l32)`):
///
/// ```text
/// d1 = W11,  l21 = W21/d1,  l31 = W31/d1,  d2 = W22 − l21 W21 (= det W_tt / W11),
/// l32 = (W32 − l31 W21)/d2,  d3 = W33 − l31 W31 − l32 (W32 − l31 W21)
///                               (= w_nn − w_tnᵀ W_tt⁻¹ w_tn).
/// ```
///
/// In double-double arithmetic ([`crate::math::Dd`]), the shift `c` added exactly: `d2` and
/// `d3` are differences of nearly equal terms when `W` is ill-conditioned (a factorisation
/// in double is backward stable, but `d3` can then lose `κ(W)` of its digits, and
/// `w_nn − w_tnᵀ W_tt⁻¹ w_tn` through the explicit inverse of `W_tt` can even change sign);
/// here every pivot keeps about `10⁻³² κ` relative accuracy, full double precision for any
/// `W` the problem accepts.
pub(crate) fn ldl(w: &Mat3, c: f64) -> (Vec3, Vec2) {
    use crate::math::Dd;
    let a = |i: usize, j: usize| Dd::from(w[(i, j)]);
    let shift = Dd::from(c);
    let d1 = a(0, 0).add(shift);
    let l21 = a(1, 0).div(d1);
    let l31 = a(2, 0).div(d1);
    let d2 = a(1, 1).add(shift).sub(l21.mul(a(1, 0)));
    let m = a(2, 1).sub(l31.mul(a(1, 0)));
    let l32 = m.div(d2);
    let d3 = a(2, 2).sub(l31.mul(a(2, 0))).sub(l32.mul(m));
    (
        Vec3::new(d1.to_f64(), d2.to_f64(), d3.to_f64()),
        -Vec2::new(l31.sub(l21.mul(l32)).to_f64(), l32.to_f64()),
    )
}

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
/// use impax::spatial::ContactProblem;
/// use impax::math::{Mat3, Vec3};
/// // A sphere (m = 1) on a plane: W = diag(7/2, 7/2, 1).
/// let p = ContactProblem::new(Mat3::from_diagonal(&Vec3::new(3.5, 3.5, 1.0)),
///                              Vec3::new(0.5, 0.0, -0.866), 0.4, 0.7).unwrap();
/// assert_eq!(p.wnn(), 1.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactProblem {
    w: Mat3,
    v: Vec3,
    mu: f64,
    e: f64,
}

impl ContactProblem {
    /// Validate and build a problem.
    ///
    /// Errors (each names its field): a non-finite entry; `W` not symmetric (beyond
    /// round-off); `W` not positive definite: a diagonal entry `≤ 0`, an off-diagonal entry
    /// with `W_ij² > W_ii W_jj`, or a pivot `d_k` of `W = L D Lᵀ` (order `t1, t2, n`:
    /// `d1 = W11`, `d2 = det W_tt / W11`, `d3 = w_nn − w_tnᵀ W_tt⁻¹ w_tn`) at most
    /// [`PIVOT_TOL`] `λ_max(W)` (negative: indefinite; else numerically singular); `v_n ≥ 0`;
    /// `μ < 0` or `μ > 1e300`; `e ∉ [0, 1]`; a velocity whose approach energy `½ v⁻ᵀ W⁻¹ v⁻` overflows.
    ///
    /// The pivots are what the laws divide by (`d1 d2 = det W_tt` in the sticking ratio,
    /// `d3` the slope of `v_n` in stick), and every pivot is at least the smallest eigenvalue
    /// of `W`: any `W` of condition number below `1/PIVOT_TOL` is accepted, whatever its
    /// orientation.
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
        let w = w * 0.5 + w.transpose() * 0.5; // (no overflow at 1e308)
        positive_definite(&w)?;
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

    /// The units in which the spatial laws resolve the problem: `v → a v`, `W → b W` with `a`,
    /// `b` the powers of two that bring `|v_n⁻|` and `w_nn` into `[1, 2)` (limited so that no
    /// nonzero entry leaves `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰]`). Exact, and the same problem in these units for
    /// any power-of-two multiple of `v` and `W`: every law is invariant under such a change of
    /// units, bit for bit, wherever its numbers are representable. `None` when `a = b = 1`.
    pub(crate) fn canonical_units(&self) -> Option<(Self, crate::math::Units)> {
        let a = crate::math::exact_unit_factor(self.v.z.abs(), self.v.as_slice());
        let b = crate::math::exact_unit_factor(self.w[(2, 2)], self.w.as_slice());
        (a != 1.0 || b != 1.0).then(|| (self.in_units(a, b), crate::math::Units { a, b }))
    }

    /// The same problem with velocities times `a` and `W` times `b` (powers of two: exact),
    /// without the validation of [`ContactProblem::new`] (the approach energy may not be
    /// representable in these units).
    pub(crate) fn in_units(&self, a: f64, b: f64) -> Self {
        Self {
            w: self.w * b,
            v: self.v * a,
            ..*self
        }
    }

    /// The problem with its negligible slip and coupling set to zero: each component of
    /// `v_t⁻` and of `w_tn` below [`NEGLIGIBLE_SLIP`] in the units where `v` is times `a` and
    /// `W` times `b` (`|v_n⁻|` and `w_nn` in `[1, 2)`, powers of two: the same test for any
    /// power-of-two multiple of the problem). Their effect on every number of the result
    /// is below `NEGLIGIBLE_SLIP` of its scale; with them, the integration of the slip would
    /// work with numbers a few dozen orders of magnitude from the subnormal range, where the
    /// direction of a slip converging on an invariant ray is lost. `None` when nothing is
    /// negligible.
    pub(crate) fn without_negligible_slip(&self, a: f64, b: f64) -> Option<Self> {
        let mut out = *self;
        let mut changed = false;
        for i in 0..2 {
            let (v, w) = (self.v[i], self.w[(i, 2)]);
            if v != 0.0 && (v * a).abs() < NEGLIGIBLE_SLIP {
                out.v[i] = 0.0;
                changed = true;
            }
            if w != 0.0 && (w * b).abs() < NEGLIGIBLE_SLIP {
                out.w[(i, 2)] = 0.0;
                out.w[(2, i)] = 0.0;
                changed = true;
            }
        }
        changed.then_some(out)
    }

    /// Stick (theory §2): the friction ratio `λ = −W_tt⁻¹ w_tn` that keeps `v_t = 0` and the
    /// slope `dv_n/dp_n = w_nn − w_tnᵀ W_tt⁻¹ w_tn > 0` there, from `W = L D Lᵀ` ([`ldl`]):
    /// `λ = −(l31 − l21 l32, l32)`, the slope `d3`, both to full double precision.
    pub(crate) fn stick(&self) -> (Vec2, f64) {
        let (d, ratio) = ldl(&self.w, 0.0);
        (ratio, d.z)
    }

    /// The slope `dv_n/dp_n = w_nn − μ w_tn·ŝ` of slip resumed along `ŝ` at the rate `λ'`
    /// (`(λ' I + μ W_tt) ŝ = w_tn`, [`super::resumption_direction`]): with `c = λ'/μ`,
    /// `μ ŝ = (W_tt + c I)⁻¹ w_tn`, so the slope is `w_nn − w_tnᵀ (W_tt + c I)⁻¹ w_tn`, the
    /// last pivot of `W + c diag(1, 1, 0) = L D Lᵀ` ([`ldl`]) — accurate where the slope is
    /// small beside `w_nn` (near the stick limit, where `c → 0` and it tends to the slope
    /// of stick), unlike `w_nn − μ w_tn·ŝ` (whose `ŝ` carries the round-off of a nearly
    /// singular solve).
    pub(crate) fn resumed_slope(&self, rate: f64) -> f64 {
        ldl(&self.w, rate / self.mu).0.z
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
