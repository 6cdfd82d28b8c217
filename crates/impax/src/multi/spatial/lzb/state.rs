//! The problem in the law's working form (canonical units, fixed-size arrays), the regimes
//! of the contacts and the layout of the integrated state.
//!
//! The state `y` holds five numbers per contact `j`, at `5j … 5j + 4`:
//!
//! ```text
//! p_t1j, p_t2j, p_nj   the impulse so far,
//! s_j                  the deflection variable, F_j = κ_j s_j^η, Ê_j = κ_j s_j^(η+1)/(η+1),
//! w_tj                 the friction work so far, ∫ v_tj·dp_tj.
//! ```
//!
//! The velocities are not integrated: `v = v⁻ + W p` at every point.

use super::{FREEZE, MAX_CONTACTS, NEAR, RTOL};
use crate::math::{Units, Vec2};
use crate::multi::lzb::common::{stiffness_ratios, ForceLaw};
use crate::multi::spatial::MultiProblem;

pub(super) use crate::multi::lzb::common::Normal;

/// The largest number of contacts (the arrays' size).
pub(super) const MAXK: usize = MAX_CONTACTS;

/// The contact rows of `W` (three per contact).
pub(super) const ROWS: usize = 3 * MAXK;

/// The numbers per contact in the state.
pub(super) const PER: usize = 5;

/// Offsets in a contact's five numbers.
pub(super) const PT1: usize = 0;
pub(super) const PT2: usize = 1;
pub(super) const PN: usize = 2;
pub(super) const S: usize = 3;
pub(super) const WT: usize = 4;

/// The problem in the canonical units of [`MultiProblem`] on the stack, with the law's
/// parameters and tolerances.
#[derive(Debug, Clone)]
pub(super) struct Setup {
    /// The number of contacts.
    pub k: usize,
    /// `W`, contact-major (`t1, t2, n` of each contact).
    pub w: [[f64; ROWS]; ROWS],
    /// `v⁻`.
    pub v0: [f64; ROWS],
    /// Friction coefficients.
    pub mu: [f64; MAXK],
    /// Restitutions.
    pub e: [f64; MAXK],
    /// Stiffness ratios, the largest scaled to 1.
    pub kappa: [f64; MAXK],
    /// `κ_j^(1/(η+1))`, the factor of the primary's ordering quantity.
    pub order: [f64; MAXK],
    /// The force law `F = κ s^η` and the power `m` of the regularising variables.
    pub law: ForceLaw,
    /// A contact approaches while `v_n < −approach`: [`crate::multi::lzb::APPROACH_ROUND_OFF`]
    /// times `max_i |v⁻_i|`. Also the slip below which a contact is at rest.
    pub approach: f64,
    /// The impact has settled when no velocity exceeds this
    /// ([`crate::multi::lzb::SETTLED`] times `max_i |v⁻_i|`).
    pub settled: f64,
    /// `σ_f`: the bound on a slip times its direction's angle from the ray it halts on,
    /// below which it goes on along the ray ([`FREEZE`] times `max_i |v⁻_i|`).
    pub freeze: f64,
    /// The slip below which a slip is near rest ([`NEAR`] times `max_i |v⁻_i|`).
    pub near: f64,
    /// The impact's force scale: the largest force of a contact alone deflected to store the
    /// energy that would stop `max_i |v⁻_i|` there.
    pub fscale: f64,
    /// The problem's canonical units (for the numbers of a breakdown).
    pub units: Units,
    /// The absolute tolerance of each component of the state (the relative one is
    /// [`RTOL`]).
    pub atol: [f64; PER * MAXK],
}

impl Setup {
    /// The working form of `problem` (`K ≤ MAXK`, checked by the caller).
    pub(super) fn new(problem: &MultiProblem) -> Setup {
        let (units, w, v) = problem.canonical();
        let k = problem.contacts();
        debug_assert!(k <= MAXK);
        let mut s = Setup {
            k,
            w: [[0.0; ROWS]; ROWS],
            v0: [0.0; ROWS],
            mu: [0.0; MAXK],
            e: [0.0; MAXK],
            kappa: [0.0; MAXK],
            order: [0.0; MAXK],
            law: ForceLaw::new(problem.exponent()),
            approach: 0.0,
            settled: 0.0,
            freeze: 0.0,
            near: 0.0,
            fscale: 0.0,
            units,
            atol: [0.0; PER * MAXK],
        };
        for i in 0..3 * k {
            s.v0[i] = v[i];
            for j in 0..3 * k {
                s.w[i][j] = w[(i, j)];
            }
        }
        let stiffness: Vec<f64> = (0..k).map(|j| problem.stiffness(j)).collect();
        stiffness_ratios(&stiffness, &mut s.kappa[..k]);
        for j in 0..k {
            s.order[j] = s.law.order(s.kappa[j]);
        }
        for j in 0..k {
            s.mu[j] = problem.friction(j);
            s.e[j] = problem.restitution(j);
        }
        let vmax = s.v0[..3 * k].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        s.approach = crate::multi::lzb::APPROACH_ROUND_OFF * vmax;
        s.settled = crate::multi::lzb::SETTLED * vmax;
        s.freeze = FREEZE * vmax;
        s.near = NEAR * vmax;
        for j in 0..k {
            let (p, energy, defl) = s.law.scales(s.kappa[j], s.w[3 * j + 2][3 * j + 2], vmax);
            s.atol[PER * j + PT1] = 0.1 * RTOL * p;
            s.atol[PER * j + PT2] = 0.1 * RTOL * p;
            s.atol[PER * j + PN] = 0.1 * RTOL * p;
            s.atol[PER * j + S] = 0.1 * RTOL * defl;
            s.atol[PER * j + WT] = 0.1 * RTOL * energy;
            s.fscale = s.fscale.max(s.force(j, defl));
        }
        s
    }

    /// The normal force `F_j = κ_j s^η` (zero for `s ≤ 0`).
    #[inline(always)]
    pub(super) fn force(&self, j: usize, s: f64) -> f64 {
        self.law.force(self.kappa[j], s)
    }

    /// The stored energy `Ê_j` (zero for `s ≤ 0`).
    #[inline]
    pub(super) fn energy(&self, j: usize, s: f64) -> f64 {
        self.law.energy(self.kappa[j], s)
    }

    /// The primary's ordering quantity, increasing with `Ê_j`.
    #[inline]
    pub(super) fn energy_order(&self, j: usize, s: f64) -> f64 {
        self.law.energy_order(self.order[j], s)
    }

    /// Contact `j`'s tangential velocity at the state `y`, `(v⁻ + W p)_tj`.
    pub(super) fn slip_at(&self, j: usize, y: &[f64]) -> Vec2 {
        let mut vt = [self.v0[3 * j], self.v0[3 * j + 1]];
        for (a, out) in vt.iter_mut().enumerate() {
            let row = &self.w[3 * j + a];
            for c in 0..self.k {
                let o = PER * c;
                *out += row[3 * c] * y[o + PT1]
                    + row[3 * c + 1] * y[o + PT2]
                    + row[3 * c + 2] * y[o + PN];
            }
        }
        Vec2::new(vt[0], vt[1])
    }
}

/// The tangential regime of a contact that carries a force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Tangent {
    /// Slip along its own direction `ŝ = v_t/|v_t|`, friction `dp_t = −μ ŝ dp_n` (a
    /// frictionless contact: no friction, whatever its slip).
    Slip,
    /// Slip along the fixed unit direction `dir`, friction `dp_t = −μ dir dp_n`: the last bit
    /// of a slip that halts (`leaving` false, on the ray it halts on) or the first of a slip
    /// that leaves rest (`leaving` true, until [`Setup::near`]).
    Fixed { dir: Vec2, leaving: bool },
    /// Stick: `v_t` held by the friction the stick set's solve gives.
    Stick,
}

/// The sticking contacts and the pseudo-inverse of their tangential block of `W`.
#[derive(Debug, Clone, Copy)]
pub(super) struct StickSet {
    /// How many.
    pub n: usize,
    /// Which (in increasing order).
    pub idx: [usize; MAXK],
    /// `(W_SS^tt)⁺`, `2n × 2n` (the two tangents of each sticking contact in turn).
    pub pinv: [[f64; 2 * MAXK]; 2 * MAXK],
}

impl StickSet {
    pub(super) const EMPTY: StickSet = StickSet {
        n: 0,
        idx: [0; MAXK],
        pinv: [[0.0; 2 * MAXK]; 2 * MAXK],
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
    /// The slip at which each slip's regime changes: a slip along its own direction goes
    /// on along a fixed one below it (`2 σ_f`), a slip along a fixed direction follows its
    /// own above it ([`Setup::near`] leaving rest, twice its slip where it was fixed
    /// halting).
    pub limit: [f64; MAXK],
}

impl Modes {
    /// Whether contact `j` carries a force.
    #[inline(always)]
    pub(super) fn active(&self, j: usize) -> bool {
        self.normal[j] != Normal::Off
    }
}
