//! The problem in the law's working form (canonical units, fixed-size arrays), the modes of
//! the contacts and the layout of the integrated state.
//!
//! The state `y` holds four numbers per contact `j`, at `4j … 4j + 3`:
//!
//! ```text
//! p_tj, p_nj   the impulse so far,
//! s_j          the contact's deflection variable, F_j = κ_j s_j^η, Ê_j = κ_j s_j^(η+1)/(η+1),
//! w_tj         the friction work so far, ∫ v_tj dp_tj.
//! ```
//!
//! The velocities are not integrated: `v = v⁻ + W p` at every point.

use super::common::{stiffness_ratios, ForceLaw};
use super::{MAX_CONTACTS, RTOL};
use crate::math::Units;
use crate::multi::MultiProblem;

pub(super) use super::common::Normal;

/// The largest number of contacts (the arrays' size).
pub(super) const MAXK: usize = MAX_CONTACTS;

/// The numbers per contact in the state.
pub(super) const PER: usize = 4;

/// Offsets in a contact's four numbers.
pub(super) const PT: usize = 0;
pub(super) const PN: usize = 1;
pub(super) const S: usize = 2;
pub(super) const WT: usize = 3;

/// The problem in the canonical units of [`MultiProblem`] on the stack, with the law's
/// parameters and tolerances.
#[derive(Debug, Clone)]
pub(super) struct Setup {
    /// The number of contacts.
    pub k: usize,
    /// `W`, contact-major.
    pub w: [[f64; 2 * MAXK]; 2 * MAXK],
    /// `v⁻`.
    pub v0: [f64; 2 * MAXK],
    /// Friction coefficients.
    pub mu: [f64; MAXK],
    /// Restitutions.
    pub e: [f64; MAXK],
    /// Stiffness ratios, the largest scaled to 1.
    pub kappa: [f64; MAXK],
    /// The force law `F = κ s^η` and the power `m` of the regularising variables
    /// (`variable.rs`).
    pub law: ForceLaw,
    /// `κ_j^(1/(η+1))`, the factor of the primary's ordering quantity
    /// ([`Setup::energy_order`]).
    pub order: [f64; MAXK],
    /// A contact approaches while `v_n < −approach`: [`super::APPROACH_ROUND_OFF`] times
    /// `max_i |v⁻_i|`. Also the tangential speed below which a contact joining or starting
    /// is taken at rest.
    pub approach: f64,
    /// The impact has settled when no velocity exceeds this ([`super::SETTLED`] times
    /// `max_i |v⁻_i|`; `path.rs`).
    pub settled: f64,
    /// The problem's canonical units (for the numbers of a breakdown).
    pub units: Units,
    /// The absolute tolerance of each component of the state (the relative one is
    /// [`RTOL`]).
    pub atol: [f64; PER * MAXK],
}

impl Setup {
    /// The working form of `problem` (`K ≤ MAXK`, checked by the caller).
    pub(super) fn new(problem: &MultiProblem) -> Setup {
        let (units, w, v, _) = problem.canonical();
        let k = problem.contacts();
        debug_assert!(k <= MAXK);
        let mut s = Setup {
            k,
            w: [[0.0; 2 * MAXK]; 2 * MAXK],
            v0: [0.0; 2 * MAXK],
            mu: [0.0; MAXK],
            e: [0.0; MAXK],
            kappa: [0.0; MAXK],
            law: ForceLaw::new(problem.exponent()),
            order: [0.0; MAXK],
            approach: 0.0,
            settled: 0.0,
            units,
            atol: [0.0; PER * MAXK],
        };
        for i in 0..2 * k {
            s.v0[i] = v[i];
            for j in 0..2 * k {
                s.w[i][j] = w[(i, j)];
            }
        }
        for j in 0..k {
            s.mu[j] = problem.frictions()[j];
            s.e[j] = problem.restitutions()[j];
        }
        stiffness_ratios(problem.stiffnesses(), &mut s.kappa[..k]);
        for j in 0..k {
            s.order[j] = s.law.order(s.kappa[j]);
        }
        let vmax = s.v0[..2 * k].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        s.approach = super::APPROACH_ROUND_OFF * vmax;
        s.settled = super::SETTLED * vmax;
        // Scales of each component: the normal impulse that would stop `vmax` at the contact
        // alone, the deflection that would store the energy of that impulse, that energy; the
        // absolute tolerance a tenth of the relative one of these scales.
        for j in 0..k {
            let (p, energy, defl) = s.law.scales(s.kappa[j], s.w[2 * j + 1][2 * j + 1], vmax);
            s.atol[PER * j + PT] = 0.1 * RTOL * p;
            s.atol[PER * j + PN] = 0.1 * RTOL * p;
            s.atol[PER * j + S] = 0.1 * RTOL * defl;
            s.atol[PER * j + WT] = 0.1 * RTOL * energy;
        }
        s
    }

    /// The normal force `F_j = κ_j s^η` (zero for `s ≤ 0`).
    #[inline(always)]
    pub(super) fn force(&self, j: usize, s: f64) -> f64 {
        self.law.force(self.kappa[j], s)
    }

    /// The stored energy `Ê_j = κ_j s^(η+1)/(η+1) = s F_j/(η+1)` (zero for `s ≤ 0`).
    #[inline]
    pub(super) fn energy(&self, j: usize, s: f64) -> f64 {
        self.law.energy(self.kappa[j], s)
    }

    /// The primary's ordering quantity `κ_j^(1/(η+1)) s_j`, increasing with `Ê_j`.
    #[inline]
    pub(super) fn energy_order(&self, j: usize, s: f64) -> f64 {
        self.law.energy_order(self.order[j], s)
    }
}

/// The tangential regime of a contact that carries a force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Tangent {
    /// Slip in the direction `σ = ±1` of `v_t`, friction `dp_t = −μ σ dp_n`; a frictionless
    /// contact has `dp_t = 0` and `σ` the direction of its slip (`0` when it does not slip).
    Slip(f64),
    /// Stick: `v_t` held at zero by the friction the stick set's solve gives.
    Stick,
}

/// The sticking contacts and the pseudo-inverse of their tangential block of `W`.
#[derive(Debug, Clone, Copy)]
pub(super) struct StickSet {
    /// How many.
    pub n: usize,
    /// Which (in increasing order).
    pub idx: [usize; MAXK],
    /// `(W_SS^tt)⁺`, `n × n`.
    pub pinv: [[f64; MAXK]; MAXK],
}

impl StickSet {
    pub(super) const EMPTY: StickSet = StickSet {
        n: 0,
        idx: [0; MAXK],
        pinv: [[0.0; MAXK]; MAXK],
    };
}

/// Every contact's regimes: what the right-hand side and the events read.
#[derive(Debug, Clone, Copy)]
pub(super) struct Modes {
    /// The normal regimes.
    pub normal: [Normal; MAXK],
    /// The tangential regimes (meaningful while the contact is not `Off`).
    pub tangent: [Tangent; MAXK],
    /// The sticking contacts.
    pub stick: StickSet,
}

impl Modes {
    /// Whether contact `j` carries a force.
    #[inline(always)]
    pub(super) fn active(&self, j: usize) -> bool {
        self.normal[j] != Normal::Off
    }
}
