//! The analytic energy-gain threshold of Whittaker's rule for the sphere (paper A eq. 13).
//!
//! A solid sphere strikes a fixed plane at `α` from the normal with spin ratio
//! `γ = ω0 r / v0`, restitution `e` and friction `f`. Under Whittaker's rule (paper A
//! eqs. 7–13), with `k = f (1+e) cos α`,
//!
//! ```text
//! ΔT/T0 = [sin α ∓ k]² + [e² + (5/2) f² (1+e)²] cos² α − 1 ∓ 2 f γ (1+e) cos α,
//! ```
//!
//! upper signs when the slip before the impact is positive (`v_Px⁻ > 0`, i.e.
//! `γ > −sin α`), lower signs when it is negative (`γ < −sin α`). `ΔT/T0` is linear in `γ`
//! on each branch, so `ΔT = 0` has one root per branch, kept only if it lies on its branch:
//! energy is gained for `γ*₋ < γ < γ*₊` (except at `γ = −sin α`, where there is no slip and
//! no friction). At the seed (`α = 30°`, `e = 0.7`, `f = 0.4`): `γ*₊ ≈ 0.2058`,
//! `γ*₋ ≈ −1.2058` (paper A prints `±0.20`, see [`crate::paper::liu2012`]).
//!
//! The result is independent of `m`, `r` and `v0`.
//!
//! ```
//! use impax::analysis::whittaker_sphere_thresholds;
//! let t = whittaker_sphere_thresholds(30f64.to_radians(), 0.7, 0.4);
//! assert!((t.upper.unwrap() - 0.2058).abs() < 1e-4);
//! assert!((t.lower.unwrap() + 1.2058).abs() < 1e-4);
//! assert!(t.gains(0.0, 30f64.to_radians()));
//! ```

/// The two roots of `ΔT = 0` of paper A eq. 13, each `None` when it is not on its branch
/// (no energy gain on that side) or friction vanishes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereThresholds {
    /// `γ*₊` on the branch `γ > −sin α`: energy gained for `−sin α < γ < γ*₊`.
    pub upper: Option<f64>,
    /// `γ*₋` on the branch `γ < −sin α`: energy gained for `γ*₋ < γ < −sin α`.
    pub lower: Option<f64>,
}

impl SphereThresholds {
    /// Whether eq. 13 predicts an energy gain at spin ratio `γ` and angle `α` (radians; the
    /// angle the thresholds were computed for).
    pub fn gains(&self, gamma: f64, alpha: f64) -> bool {
        let edge = -alpha.sin();
        match (gamma > edge, gamma < edge) {
            (true, _) => self.upper.is_some_and(|g| gamma < g),
            (_, true) => self.lower.is_some_and(|g| gamma > g),
            _ => false,
        }
    }
}

/// `ΔT/T0` of Whittaker's rule for the sphere, paper A eq. 13 (`α` in radians).
pub fn whittaker_sphere_energy_ratio(
    alpha: f64,
    restitution: f64,
    friction: f64,
    gamma: f64,
) -> f64 {
    let (s, c) = alpha.sin_cos();
    let (e, f) = (restitution, friction);
    let branch = if s + gamma > 0.0 {
        1.0
    } else if s + gamma < 0.0 {
        -1.0
    } else {
        0.0
    };
    let k = f * (1.0 + e) * c * branch;
    let x = s - k;
    let y = e * e + 2.5 * f * f * (1.0 + e) * (1.0 + e) * branch * branch;
    x * x + y * c * c - 1.0 - branch * 2.0 * f * gamma * (1.0 + e) * c
}

/// The energy-gain thresholds of Whittaker's rule for the sphere (paper A eq. 13); none
/// without friction or at grazing incidence (`cos α < 10⁻⁹`).
pub fn whittaker_sphere_thresholds(
    alpha: f64,
    restitution: f64,
    friction: f64,
) -> SphereThresholds {
    let (s, c) = alpha.sin_cos();
    let (e, f) = (restitution, friction);
    let k = f * (1.0 + e) * c;
    let y = (e * e + 2.5 * f * f * (1.0 + e) * (1.0 + e)) * c * c - 1.0;
    let slope = 2.0 * k;
    // Frictionless, or grazing (cos α → 0, where both roots merge with γ = −sin α and the
    // formula loses every digit): no threshold.
    if slope.is_nan() || slope <= 0.0 || c < 1e-9 {
        return SphereThresholds {
            upper: None,
            lower: None,
        };
    }
    let edge = -s;
    let up = ((s - k) * (s - k) + y) / slope;
    let lo = -((s + k) * (s + k) + y) / slope;
    SphereThresholds {
        upper: (up > edge).then_some(up),
        lower: (lo < edge).then_some(lo),
    }
}
