//! The independent variables of the integration. The right-hand side is autonomous in the
//! contact-force time `τ` and smooth except where a contact's force law is (`s_j = 0`: the
//! start and each separation, as in the planar law) and where a contact's slip direction is
//! (`v_tj = 0`: a halt). The first two are the planar law's variables, with the same reasons
//! (`crate::multi::lzb`'s `variable.rs`):
//!
//! * **the start** in `u = τ^(1/m)` (`dτ = m u^(m−1) du`), until `τ` reaches a quarter of
//!   the shortest compression time of a contact alone;
//! * **a separation** in `σ = s_j^(1/m)` (`dτ/dσ = −m σ^(m−1) e_j²/v_nj`), once it is
//!   predicted within the next two steps, to `σ = 0` exactly;
//! * **a halt** in `x = ln σ_j`, `σ_j = |v_tj|`, decreasing, once contact `j`'s slip shrinks
//!   steadily (`ŝ_j·a_j < −½ |a_j|`, `a_j = dv_tj/dτ`) while its direction turns
//!   (`|ŝ_j × a_j| > 10⁻⁶ |a_j|`; on a ray it halts along a straight line, smooth in `τ`) and
//!   its halt is predicted within the next four steps (`σ_j/|ŝ_j·a_j|` ahead), with
//!   ```text
//!   dτ/dx = σ_j / (ŝ_j·a_j),
//!   ```
//!   regular while the slip shrinks (back to `τ` if `ŝ_j·a_j > −¼ |a_j|`: the direction
//!   swings while the slip passes near zero). Near the halt the direction converges to an
//!   invariant ray of the contact's slip field as a power of `σ_j`
//!   (`φ − φ* ∝ σ^λ`, the spatial Darboux–Keller law's `log_sigma.rs`), so in `τ` the path
//!   has a branch point at the halt, while in `x` it is smooth: the steps in `x` are
//!   e-folds of the slip (back to `τ` also when they fall below a sixteenth of one: the
//!   others set the steps, the halt recedes). The slip is compared with the ray it halts
//!   on at the end of each step (`record.rs`) and goes on along it when close and closing
//!   (a direction swinging past the ray is close where it passes), until it halts or
//!   an event changes the field the ray was the slip's in (it then slips freely again);
//!   the variable ends at the latest at the contact's limit `2 σ_f` exactly
//!   ([`Modes::limit`]).
//!
//! The power `m` is the force law's ([`crate::multi::lzb::common::ForceLaw`]). Any event
//! returns the path to `τ`.

use super::events::Event;
use super::field::{rates, slip, slip_rate, Eval};
use super::state::{Modes, Normal, Setup, Tangent, PER, ROWS, S};

/// A slip enters the halt variable while `ŝ·a < −HALT_IN |a|` (it shrinks steadily)...
const HALT_IN: f64 = 0.5;
/// ... and leaves it once `ŝ·a > −HALT_OUT |a|`.
const HALT_OUT: f64 = 0.25;
/// ... with the halt predicted within this many steps.
pub(super) const HALT_AHEAD: f64 = 4.0;

/// The variable the path is integrated in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Var {
    /// The contact-force time `τ` (`dp_nj = F_j dτ`).
    Time,
    /// `u = τ^(1/m)`, at the start.
    Root,
    /// `σ = s_j^(1/m)` while contact `contact`'s expansion ends (`σ` decreasing to 0);
    /// `entry` its normal velocity when the variable was taken.
    Separation { contact: usize, entry: f64 },
    /// `x = ln |v_tj|` while contact `contact`'s slip halts (`x` decreasing to the log of
    /// its limit, [`Modes::limit`]).
    Halt { contact: usize },
}

/// ... and only while its direction turns: `|ŝ × a| > TURNING |a|` (on a ray to within
/// this, the slip halts along a straight line, smooth in `τ`).
const TURNING: f64 = 1e-6;

/// `|v_tj|`, `ŝ_j·a_j`, `ŝ_j × a_j` and `|a_j|` of a slipping contact `j` at a point.
#[inline]
fn shrinking(setup: &Setup, j: usize, ev: &Eval) -> (f64, f64, f64, f64) {
    let vt = slip(&ev.v, j);
    let sigma = vt.norm();
    let a = slip_rate(setup, j, &ev.f, &ev.pt);
    (
        sigma,
        vt.dot(&a) / sigma,
        (vt.x * a.y - vt.y * a.x) / sigma,
        a.norm(),
    )
}

impl Var {
    /// `dτ/dx` at `x`, given the point's quantities `ev`.
    #[inline(always)]
    fn dtau(self, setup: &Setup, x: f64, ev: &Eval) -> f64 {
        let m = setup.law.m;
        match self {
            Var::Time => 1.0,
            Var::Root => f64::from(m) * setup.law.power_m1(x),
            Var::Separation { contact: j, .. } => {
                -f64::from(m) * setup.law.power_m1(x) * setup.e[j] * setup.e[j] / ev.v[3 * j + 2]
            }
            Var::Halt { contact: j } => {
                let (sigma, q, _, _) = shrinking(setup, j, ev);
                sigma / q
            }
        }
    }

    /// `dy/dx` at `(x, y)`.
    #[inline(always)]
    pub(super) fn rhs<const N: usize>(
        self,
        setup: &Setup,
        modes: &Modes,
        x: f64,
        y: &[f64; N],
    ) -> [f64; N] {
        self.rhs_eval(setup, modes, x, y).0
    }

    /// `dy/dx` at `(x, y)` and the point's quantities.
    #[inline(always)]
    pub(super) fn rhs_eval<const N: usize>(
        self,
        setup: &Setup,
        modes: &Modes,
        x: f64,
        y: &[f64; N],
    ) -> ([f64; N], Eval) {
        let (mut dy, ev) = rates::<N>(setup, modes, y);
        if self != Var::Time {
            let c = self.dtau(setup, x, &ev);
            for d in dy.iter_mut() {
                *d *= c;
            }
            if let Var::Separation { contact: j, .. } = self {
                // s_j = σ^m exactly.
                let m = setup.law.m;
                dy[PER * j + S] = f64::from(m) * setup.law.power_m1(x);
            }
        }
        (dy, ev)
    }

    /// The event that is this variable's end of range (not an event inside it), if any.
    #[inline]
    pub(super) fn own_event(self) -> Option<Event> {
        match self {
            Var::Separation { contact, .. } => Some(Event::Separation(contact)),
            Var::Halt { contact } => Some(Event::NearHalt(contact)),
            _ => None,
        }
    }

    /// Where this variable's range ends (both end ranges are approached decreasingly).
    #[inline]
    pub(super) fn end(self, modes: &Modes) -> Option<f64> {
        match self {
            Var::Separation { .. } => Some(0.0),
            Var::Halt { contact } => Some(modes.limit[contact].ln()),
            _ => None,
        }
    }

    /// A step `h` of this variable at `x` as a step of `τ` (positive).
    #[inline]
    pub(super) fn to_time(self, setup: &Setup, x: f64, h: f64, ev: &Eval) -> f64 {
        (h * self.dtau(setup, x, ev)).abs()
    }

    /// The variable to go on in after an accepted step that ended at `x` (quantities `ev`),
    /// the next step being `h` in this variable; `root_end` the `τ` where the start ends.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn next(
        self,
        setup: &Setup,
        modes: &Modes,
        x: f64,
        h: f64,
        y: &[f64],
        ev: &Eval,
        root_end: f64,
    ) -> Var {
        match self {
            Var::Root if x.powi(setup.law.m) >= root_end => Var::Time,
            Var::Root => Var::Root,
            Var::Time => Self::soonest(setup, modes, h, y, ev),
            Var::Separation { contact: j, entry } => {
                if modes.normal[j] != Normal::Expansion || ev.v[3 * j + 2] < 0.25 * entry {
                    Var::Time
                } else {
                    self
                }
            }
            Var::Halt { contact: j } => {
                // (Back to τ also where the halt recedes: the steps in x fall below a fraction
                // of an e-fold, the others' path sets the steps, the contact's own slip
                // barely changes over them — its force vanishing as it separates.)
                let (_, q, _, a) = shrinking(setup, j, ev);
                if !modes.active(j)
                    || modes.tangent[j] != Tangent::Slip
                    || q.is_nan()
                    || q >= -HALT_OUT * a
                    || h.abs() < 1.0 / (4.0 * HALT_AHEAD)
                {
                    Var::Time
                } else {
                    self
                }
            }
        }
    }

    /// From `τ` (next step `h`): the separation or halt soonest ahead, if within its steps.
    fn soonest(setup: &Setup, modes: &Modes, h: f64, y: &[f64], ev: &Eval) -> Var {
        let mut best: Option<(f64, Var)> = None;
        for j in (0..setup.k).filter(|&j| modes.active(j)) {
            let vn = ev.v[3 * j + 2];
            if setup.law.m > 1
                && modes.normal[j] == Normal::Expansion
                && !vn.is_nan()
                && vn > setup.settled
            {
                let e2 = setup.e[j] * setup.e[j];
                let ahead = y[PER * j + S] * e2 / vn;
                if ahead <= 2.0 * h && best.is_none_or(|(b, _)| ahead < b) {
                    best = Some((
                        ahead,
                        Var::Separation {
                            contact: j,
                            entry: vn,
                        },
                    ));
                }
            }
            if setup.mu[j] > 0.0 && modes.tangent[j] == Tangent::Slip {
                let (sigma, q, turn, a) = shrinking(setup, j, ev);
                if sigma > modes.limit[j] && q < -HALT_IN * a && turn.abs() > TURNING * a {
                    let ahead = sigma / -q;
                    if ahead <= HALT_AHEAD * h && best.is_none_or(|(b, _)| ahead < b) {
                        best = Some((ahead, Var::Halt { contact: j }));
                    }
                }
            }
        }
        best.map_or(Var::Time, |(_, v)| v)
    }

    /// Where this variable starts at the state `y` (velocities `v`) and its first step, from
    /// a step `h` of `τ`.
    pub(super) fn start_from_time(
        self,
        setup: &Setup,
        modes: &Modes,
        v: &[f64; ROWS],
        y: &[f64],
        h: f64,
    ) -> (f64, f64) {
        match self {
            Var::Time | Var::Root => (0.0, h),
            Var::Separation { contact: j, .. } => {
                // The whole way to the separation at once (the error test shortens it).
                let sigma = y[PER * j + S].max(0.0).powf(1.0 / f64::from(setup.law.m));
                (sigma, -sigma)
            }
            Var::Halt { contact: j } => {
                // An e-fold of the slip first (towards its limit).
                let x = slip(v, j).norm().ln();
                (x, (modes.limit[j].ln() - x).max(-1.0))
            }
        }
    }
}
