//! What every stage of the integration reads and writes: the moving point of the path, the
//! scales of the error control, the centrifugal invariant ray, and how the slip ended.

use super::super::ContactProblem;
use crate::math::{norm_of, Vec2, Vec3};

/// The moving point of the integration, whatever the independent variable: the normal
/// impulse `p_n`, the contact velocity `(v_t, v_n)`, the tangential impulse `p_t`, the
/// normal work `W_n = ∫ v_n dp_n` and the friction work `W_t = ∫ v_t·dp_t`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Point {
    /// The normal impulse `p_n`.
    pub p: f64,
    /// The tangential (slip) velocity `v_t`.
    pub vt: Vec2,
    /// The normal velocity `v_n`.
    pub vn: f64,
    /// The tangential impulse `p_t`.
    pub pt: Vec2,
    /// The normal work `W_n`.
    pub wn: f64,
    /// The friction work `W_t`.
    pub wt: f64,
}

impl Point {
    /// The start of the path: no impulse yet, the velocity before the impact.
    pub(super) fn start(v0: Vec3) -> Point {
        Point {
            p: 0.0,
            vt: v0.xy(),
            vn: v0.z,
            pt: Vec2::zeros(),
            wn: 0.0,
            wt: 0.0,
        }
    }

    /// The contact velocity `(v_t, v_n)`, what an observer of the path sees.
    #[inline]
    pub(super) fn velocity(&self) -> Vec3 {
        Vec3::new(self.vt.x, self.vt.y, self.vn)
    }
}

/// Scales for the error control, each of its own quantity (the slip and the normal velocity
/// can differ by hundreds of orders of magnitude: a grazing impact, a slip far below the
/// normal velocity), and the relative tolerance.
#[derive(Clone, Copy)]
pub(super) struct Scales {
    /// Tangential velocity: `σ⁻` plus the most the impact can change it, `|g|_max p`.
    pub vt: f64,
    /// Normal velocity `|v_n⁻|`.
    pub vn: f64,
    /// Normal impulse `(1+e) |v_n⁻| / w_nn` (beyond it the relative part takes over).
    pub p: f64,
    /// Normal work `vn p`.
    pub wn: f64,
    /// Friction work `vt p`.
    pub wt: f64,
    /// The relative tolerance per step.
    pub rtol: f64,
}

impl Scales {
    /// The scales of `problem`, with the relative tolerance `rtol`.
    pub(super) fn of(problem: &ContactProblem, rtol: f64) -> Scales {
        let (wtt, wtn, wnn) = (problem.wtt(), problem.wtn(), problem.wnn());
        let (mu, e, v0) = (
            problem.friction(),
            problem.restitution(),
            problem.velocity(),
        );
        let vn = -v0.z;
        let p = (1.0 + e) * vn / wnn;
        let vt = norm_of(v0.xy()) + (norm_of(wtn) + mu * wtt.norm()) * p;
        Scales {
            vt,
            vn,
            p,
            wn: vn * p,
            wt: vt * p,
            rtol,
        }
    }
}

/// The centrifugal invariant ray: there is at most one, the solution `ŝ` of
/// `(λ' I + μ W_tt) ŝ = w_tn` with `λ' > 0` ([`crate::spatial::resumption_direction`]), along
/// which the slip grows at the rate `λ'` and `v_n` changes at `slope` ([`ContactProblem`]'s
/// `resumed_slope`).
#[derive(Clone, Copy)]
pub(super) struct Centrifugal {
    /// The ray's direction `ŝ`.
    pub dir: Vec2,
    /// `dσ/dp_n = λ'` along it.
    pub rate: f64,
    /// `dv_n/dp_n` along it.
    pub slope: f64,
}

/// How the slip stage ended; `phi` is the direction of the slip at its end.
pub(super) enum SlipEnd {
    /// The law terminated while the contact slipped: the impact is over.
    Terminated { phi: f64 },
    /// The slip halted (`v_t = 0`): stick or the resumed slip follows.
    Halted { phi: f64 },
}
