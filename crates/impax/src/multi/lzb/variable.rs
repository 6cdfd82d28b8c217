//! The independent variables of the integration. The right-hand side is autonomous in the
//! contact-force time `τ`, and smooth except where a contact's force law is: at `s_j = 0`,
//! where `F_j = κ_j s_j^η` is not analytic. Two such points are met on every path, and a
//! Runge–Kutta step across either has a low order (its error estimate then fails too):
//!
//! * **the start**, `τ = 0`, where every approaching contact has `s_j ≈ −v_nj⁻ τ`, so
//!   `F_j ∝ τ^η`: the path starts in `z = τ^(η+1)` (`dτ/dz = τ^(−η)/(η+1)`), in which it is
//!   analytic for every `η` until the first event (`s_j = τ q_j(z)`, the rest analytic in
//!   `z`: `series/onset.rs`), and goes on in `τ` after it. In `u = √τ` (for `η = 3/2`) the
//!   path is analytic too (`s_j = u² G(u⁵)`), but its series has one nonzero term in five;
//!   `u = τ^(1/m)` is kept for DOP853 steps where the series in `z` overflows, until `τ`
//!   reaches a quarter of the shortest compression time of a contact alone;
//! * **a separation**, where an expanding contact's `s_j` falls linearly to zero, so
//!   `F_j ∝ (τ_e − τ)^η`: once the separation is predicted within the next two steps, the
//!   path goes on in `σ = s_j^(1/m)` (`dτ/dσ = −m σ^(m−1) e_j²/v_nj`, regular while
//!   `v_nj > 0`), in which the separating contact's force `κ_j σ^(mη)` is analytic for
//!   `η = 3/2`, `m = 2`, and the separation is the end of the range, `σ = 0`, reached exactly
//!   (back to `τ` if `v_nj` falls below a quarter of its value on entry: the contact may be
//!   about to recompress; over to another contact's `σ` if that one's separation comes in
//!   less than half the time, on the present rates: its separation would be a singular point
//!   ahead, the steps shrinking toward it — a rod's two ends leaving nearly together).
//!
//! The power `m` is 2 when `2η` is an integer, else the least with `m η ≥ 9` (the force then
//! smooth to beyond the integrator's order); an integer `η` (a linear spring, `η = 1`) has no
//! singular point and is integrated in `τ` throughout. A contact joining mid-impact starts at
//! `v_nj = 0` with `s_j ∝ (τ − τ_j)²`, so its force `∝ (τ − τ_j)^(2η)` is analytic for
//! `η = 3/2`: the series (`series/`) starts there, as at `u = 0`. Any event returns the
//! path to `τ`.

use super::field::{Eval, Field};
use super::state::{Modes, Normal, Setup, MAXK, PER, S};

/// The variable the path is integrated in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Var {
    /// The contact-force time `τ` (`dp_nj = F_j dτ`).
    Time,
    /// `z = τ^(η+1)`, from the impact's start to its first event, in which the whole path
    /// is analytic (`s_j = τ q_j(z)`, module docs); its series is `series/onset.rs`'s.
    Onset,
    /// `u = τ^(1/m)`, at the start where the series in `z` does not apply (DOP853 steps).
    Root,
    /// `σ = √s_j` while contact `contact`'s expansion ends (`σ` decreasing to 0); `entry` its
    /// normal velocity when the variable was taken.
    Separation { contact: usize, entry: f64 },
}

impl Var {
    /// `dτ/dx` at `x`, given the velocities `v`.
    #[inline(always)]
    fn dtau(self, setup: &Setup, x: f64, v: &[f64; 2 * MAXK]) -> f64 {
        let m = setup.law.m;
        match self {
            Var::Time => 1.0,
            Var::Onset => setup.law.onset_rate(x),
            Var::Root => f64::from(m) * setup.law.power_m1(x),
            Var::Separation { contact: j, .. } => {
                -f64::from(m) * setup.law.power_m1(x) * setup.e[j] * setup.e[j] / v[2 * j + 1]
            }
        }
    }

    /// `dy/dx` at `(x, y)`.
    #[inline(always)]
    pub(super) fn rhs<const N: usize>(
        self,
        setup: &Setup,
        field: &Field,
        x: f64,
        y: &[f64; N],
    ) -> [f64; N] {
        let mut dy = field.dy::<N>(setup, y);
        let m = f64::from(setup.law.m);
        let c = match self {
            Var::Time => return dy,
            Var::Onset => setup.law.onset_rate(x),
            Var::Root => m * setup.law.power_m1(x),
            Var::Separation { contact: j, .. } => {
                let vn = field.normal_velocity::<N>(setup, y, j);
                -m * setup.law.power_m1(x) * setup.e[j] * setup.e[j] / vn
            }
        };
        for d in dy.iter_mut() {
            *d *= c;
        }
        if let Var::Separation { contact: j, .. } = self {
            // s_j = σ^m exactly.
            dy[PER * j + S] = m * setup.law.power_m1(x);
        }
        dy
    }

    /// `dy/dx` at `(x, y)` and the point's quantities.
    #[inline(always)]
    pub(super) fn rhs_eval<const N: usize>(
        self,
        setup: &Setup,
        field: &Field,
        x: f64,
        y: &[f64; N],
    ) -> ([f64; N], Eval) {
        let (mut dy, ev) = field.rates::<N>(setup, y);
        if self != Var::Time {
            let c = self.dtau(setup, x, &ev.v);
            for d in dy.iter_mut() {
                *d *= c;
            }
            if let Var::Separation { contact: j, .. } = self {
                // s_j = σ^m exactly.
                dy[PER * j + S] = f64::from(setup.law.m) * setup.law.power_m1(x);
            }
        }
        (dy, ev)
    }

    /// The separating contact, in the separation variable.
    #[inline]
    pub(super) fn separating(self) -> Option<usize> {
        match self {
            Var::Separation { contact, .. } => Some(contact),
            _ => None,
        }
    }

    /// A step `h` of this variable at `x` as a step of `τ` (positive; in `z`, exactly
    /// `τ(x + h) − τ(x)`, `dτ/dz` being infinite at the start).
    #[inline]
    pub(super) fn to_time(self, setup: &Setup, x: f64, h: f64, v: &[f64; 2 * MAXK]) -> f64 {
        if self == Var::Onset {
            let tau = |z: f64| setup.law.onset_time(z);
            return tau(x + h) - tau(x);
        }
        (h * self.dtau(setup, x, v)).abs()
    }

    /// The variable to go on in after an accepted step that ended at `x` (state `y`,
    /// velocities `v`), the next step being `h` in this variable; `root_end` the `τ` where
    /// the start ends.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn next(
        self,
        setup: &Setup,
        modes: &Modes,
        x: f64,
        h: f64,
        y: &[f64],
        v: &[f64; 2 * MAXK],
        root_end: f64,
    ) -> Var {
        match self {
            Var::Onset => Var::Onset,
            Var::Root if x.powi(setup.law.m) >= root_end => Var::Time,
            Var::Root => Var::Root,
            Var::Time if setup.law.m == 1 => Var::Time,
            Var::Time => match soonest(setup, modes, y, v) {
                // The expanding contact whose separation is soonest, within two steps.
                Some((ahead, j)) if ahead <= 2.0 * h => Var::Separation {
                    contact: j,
                    entry: v[2 * j + 1],
                },
                _ => Var::Time,
            },
            Var::Separation { contact: j, entry } => {
                if modes.normal[j] != Normal::Expansion || v[2 * j + 1] < 0.25 * entry {
                    return Var::Time;
                }
                // Another contact separating first (a rod's two ends leaving nearly together)
                // would be a singular point ahead in this variable: its own is taken instead.
                match soonest(setup, modes, y, v) {
                    Some((ahead, i)) if i != j && ahead < 0.5 * ahead_of(setup, y, v, j) => {
                        Var::Separation {
                            contact: i,
                            entry: v[2 * i + 1],
                        }
                    }
                    _ => self,
                }
            }
        }
    }

    /// Where this variable starts at the state `y` and its first step, from a step `h` of `τ`.
    pub(super) fn start_from_time(
        self,
        setup: &Setup,
        y: &[f64],
        h: f64,
        v: &[f64; 2 * MAXK],
    ) -> (f64, f64) {
        match self {
            Var::Time | Var::Root | Var::Onset => (0.0, h),
            Var::Separation { contact: j, .. } => {
                let sigma = y[PER * j + S].max(0.0).powf(1.0 / f64::from(setup.law.m));
                // The step of τ as a step of σ (dτ/dσ = −m σ^(m−1) e²/v_n), at most the whole
                // way to the separation.
                let dtau = self.dtau(setup, sigma, v).abs();
                let step = if dtau > 0.0 && (h / dtau).is_finite() {
                    (h / dtau).min(sigma)
                } else {
                    sigma
                };
                (sigma, -step)
            }
        }
    }
}

/// The `τ` to contact `j`'s separation on its present rates, `s_j e_j² / v_nj`.
fn ahead_of(setup: &Setup, y: &[f64], v: &[f64; 2 * MAXK], j: usize) -> f64 {
    y[PER * j + S] * setup.e[j] * setup.e[j] / v[2 * j + 1]
}

/// The expanding contact whose separation is soonest on the present rates
/// ([`ahead_of`]), and its `τ` to it; contacts moving apart by no more than the settled
/// round-off are passed over.
fn soonest(setup: &Setup, modes: &Modes, y: &[f64], v: &[f64; 2 * MAXK]) -> Option<(f64, usize)> {
    let mut best: Option<(f64, usize)> = None;
    for j in 0..setup.k {
        let vn = v[2 * j + 1];
        if modes.normal[j] != Normal::Expansion || vn.is_nan() || vn <= setup.settled {
            continue;
        }
        let ahead = ahead_of(setup, y, v, j);
        if best.is_none_or(|(b, _)| ahead < b) {
            best = Some((ahead, j));
        }
    }
    best
}
