//! `lcp` with `K` contacts: the velocity-level complementarity impact at every contact at
//! once — what projected Gauss–Seidel and sequential-impulse engines converge to.
//!
//! Anitescu & Potra 1997 (*Formulating dynamic multi-rigid-body contact problems with friction
//! as solvable linear complementarity problems*, Nonlinear Dynamics 14), Stewart & Trinkle 1996
//! (*An implicit time-stepping scheme for rigid body dynamics with inelastic collisions and
//! Coulomb friction*, Int. J. Numer. Methods Eng. 39); the one-contact rule is
//! [`crate::planar::laws::lcp`]. One impulse per contact `p_j = (p_tj, p_nj)`, the velocities
//! after `v⁺ = v⁻ + W p`, Newton's target `b_j = max(−e_j v_nj⁻, 0)`, and at every contact
//!
//! ```text
//! normal:   0 ≤ p_nj  ⊥  v_nj⁺ − b_j ≥ 0
//! friction: |p_tj| ≤ μ_j p_nj;  v_tj⁺ = 0, or p_tj = −μ_j p_nj sign(v_tj⁺)
//! ```
//!
//! (Coulomb's law with maximal dissipation on the final velocity, as for one contact; a
//! contact that is not approaching, `v_nj⁻ ≥ 0`, has `b_j = 0`: it may be pushed apart, never
//! pulled).
//!
//! **Exact enumeration.** In the plane each contact is in one of four modes, and each mode
//! turns the conditions into linear equations:
//!
//! ```text
//! off:     p_tj = p_nj = 0                       needs  v_nj⁺ ≥ b_j
//! stick:   v_tj⁺ = 0,  v_nj⁺ = b_j               needs  p_nj ≥ 0, |p_tj| ≤ μ_j p_nj
//! slip+:   p_tj = −μ_j p_nj,  v_nj⁺ = b_j         needs  p_nj ≥ 0, v_tj⁺ ≥ 0
//! slip−:   p_tj = +μ_j p_nj,  v_nj⁺ = b_j         needs  p_nj ≥ 0, v_tj⁺ ≤ 0
//! ```
//!
//! (a frictionless contact has two: off, or `p_tj = 0` with `v_nj⁺ = b_j`). The law solves
//! every combination of modes (`4^K`; [`MAX_CONTACTS`] `= 6`, 4,096 systems, is the limit),
//! keeps those whose solution satisfies every inequality, and every equation, to round-off
//! ([`VELOCITY_ROUND_OFF`] of the velocity scale `max_i (|v⁻_i| + (|W| |p|)_i)` for
//! velocities, of `max |p|` for impulses), merges those whose velocities after agree to `1e-8`
//! of that scale (the same solution on the boundary of two modes), and returns **every
//! distinct solution**, least kinetic energy after first ([`solutions`]). The result
//! ([`resolve`]) is the first; with several it carries [`Inconsistency::MultipleSolutions`]
//! (verdict `inconsistent-assumption` unless energy is gained), as the spatial one-contact
//! `lcp` does: the conditions alone do not say which solution an engine's iteration reaches.
//! A frictionless problem has one solution in velocities (the conditions are then those of a
//! convex quadratic programme); with friction there can be several.
//!
//! **How the enumeration is made fast** (the solutions are those of the enumeration above,
//! to the last bit, in the same order, merged the same way). Almost every combination fails
//! a condition by far, and the exact solve is only needed for the few that do not. The
//! combinations are visited as the leaves of an *elimination tree*: contact `K − 1` in each
//! of its modes, then contact `K − 2` in each of its modes, …, contact 0 last. Eliminating a
//! contact's equations (its `2 × 2` block in stick, its normal row with `p_t = ∓μ p_n` in
//! slip, nothing when off) leaves the Schur complement `S` as the matrix of the contacts not
//! yet eliminated *whatever their modes*, so each node's `S` serves every combination below
//! it. At a leaf the impulses come by back-substitution, contact 0 first, and each contact's
//! conditions are checked as soon as its impulse is known (its velocity after is its row of
//! the `S` it was eliminated from): most leaves stop at the first or second contact. A
//! combination is **ruled out** only when one of its conditions fails by more than
//! `1e-6` of an upper bound of the scale that condition is measured against — a thousand
//! times the tolerance ([`VELOCITY_ROUND_OFF`]) of the exact check itself. Every other
//! combination goes to the exact solve above, which alone decides, so whatever the tree
//! keeps, the result is the enumeration's.
//!
//! What makes this safe, and where it is a numerical argument rather than a proof:
//!
//! * the scales are bounded from above exactly: the back-substitution gives
//!   `|p_c| ≤ a_c + b_c |p_{0…c−1}|` at every contact (the triangle inequality through the
//!   pivot block's inverse), so the largest impulse of the whole combination, and with it the
//!   velocity scale `max_i |v⁻_i| + (max_i Σ_j |W_ij|) max |p|`, is bounded while only the
//!   first contacts' impulses are known; the filter's tolerance is therefore never below the
//!   exact check's;
//! * the tree's impulses and the exact solve's are two eliminations of the same system.
//!   Where the tree's pivots are small (below `1e-6` of `W`'s largest diagonal entry, or a
//!   stick block's determinant below `1e-6` of its largest entry squared) or its multipliers
//!   large (above `1e4`), or any number is NaN, nothing below that node is ruled out: every
//!   combination there goes to the exact solve (the singular systems of redundant contacts
//!   always do). Elsewhere the two solutions differ by round-off amplified by a bounded
//!   growth, far below the factor 1000 between the two tolerances. This part is not proved
//!   bound by bound: it is checked, the tree against the enumeration of every combination
//!   on 40,000 random problems (`K = 1 … 6`, a third with singular `W`, some frictionless,
//!   plastic, elastic, `μ` up to 4), identical to the last bit, and the check still passes
//!   with a margin ten million times narrower than the one used.
//!
//! **Singular `W`** (redundant contacts: a rod lying flat, a box on four corners). The
//! velocities after are what the conditions determine; the impulses that produce them form
//! a family `p + z`, `W z = 0` (a rod lying flat: how a tangential impulse is shared between
//! its ends). Each mode's equations are solved in the least-squares, least-norm sense
//! (Gaussian elimination with complete pivoting, pivots below `1e-11` of the largest entry
//! taken as zero, the free unknowns chosen to minimise `|p|`), so the impulse reported is the
//! least-norm solution of its mode's equations (a boundary mode's when that one violates an
//! inequality that another member of the family meets), and among modes giving the same
//! velocities the smallest. `ΔT` does not depend on the choice (`v⁻` and `v⁺` are in the
//! range of `W`, orthogonal to `z`).
//!
//! The velocities are reported as the conditions give them: `v_nj⁺ = b_j` at a contact with
//! an impulse, `v_tj⁺ = 0` at a sticking one (`v⁻ + W p` to round-off). The work of each
//! contact is reported along the straight path `s p`, `0 ≤ s ≤ 1` (an engine has no path in
//! impulse space), its normal work split where `v_nj` crosses zero on it.
//!
//! With one contact this is [`crate::planar::laws::Lcp`] (tested to 1e-13).
//!
//! ```
//! use impax::multi::{lcp, MultiProblem};
//! // Newton's cradle, three equal balls (m = 1) touching, e = 1, frictionless: the normals
//! // W = [[2, −1], [−1, 2]], the first contact closing at 1. The LCP sends the first ball back.
//! let p = MultiProblem::from_upper(
//!     2,
//!     &[2.0, 0.0, 0.0, 0.0, /**/ 2.0, 0.0, -1.0, /**/ 2.0, 0.0, /**/ 2.0],
//!     &[0.0, -1.0, 0.0, 0.0],
//!     &[0.0],
//!     &[1.0],
//! )
//! .unwrap();
//! let out = lcp::resolve(&p).unwrap();
//! assert!((out.contacts[0].impulse.y - 4.0 / 3.0).abs() < 1e-12);
//! assert!((out.contacts[1].impulse.y - 2.0 / 3.0).abs() < 1e-12);
//! assert!(out.energy_change.abs() < 1e-12);
//! ```

use super::outcome::{
    assemble, ContactPhaseKind, ContactResult, LcpSolution, MultiDetail, MultiResolution,
    PerContact, Phases, VELOCITY_ROUND_OFF,
};
use super::MultiProblem;
use crate::law::{Breakdown, BreakdownReason, Inconsistency, LawId, WorkSplit};
use crate::math::Vec2;
use crate::planar::SlipDirection;

/// The most contacts `lcp` enumerates (`4^6 = 4096` combinations of modes).
pub const MAX_CONTACTS: usize = 6;

/// The largest system: two unknowns per contact.
pub(crate) const DIM: usize = 2 * MAX_CONTACTS;

/// Pivots below this fraction of the largest entry end the elimination (rank deficiency).
const PIVOT_TOL: f64 = 1e-11;

/// Two solutions whose velocities after differ by less than this fraction of the velocity
/// scale are the same solution.
const SAME: f64 = 1e-8;

/// A contact's mode in the enumeration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Off,
    Stick,
    /// Friction `p_t = −μ p_n`, needs `v_t⁺ ≥ 0`.
    SlipPos,
    /// Friction `p_t = +μ p_n`, needs `v_t⁺ ≤ 0`.
    SlipNeg,
    /// Frictionless contact with an impulse: `p_t = 0`.
    Free,
}

const WITH_FRICTION: [Mode; 4] = [Mode::Off, Mode::Stick, Mode::SlipPos, Mode::SlipNeg];
const FRICTIONLESS: [Mode; 2] = [Mode::Off, Mode::Free];

/// An accepted solution of one combination of modes, in the canonical units.
#[derive(Debug, Clone, Copy)]
struct Candidate<const N: usize> {
    modes: [Mode; MAX_CONTACTS],
    p: [f64; N],
    v: [f64; N],
    vscale: f64,
    norm: f64,
}

/// The distinct solutions found so far, in order: the first [`INLINE`] on the stack.
struct Found<const N: usize> {
    n: usize,
    first: [Candidate<N>; INLINE],
    more: Vec<Candidate<N>>,
}

/// How many solutions [`Found`] keeps on the stack.
const INLINE: usize = 2;

impl<const N: usize> Found<N> {
    fn new() -> Self {
        let empty = Candidate {
            modes: [Mode::Off; MAX_CONTACTS],
            p: [0.0; N],
            v: [0.0; N],
            vscale: 0.0,
            norm: 0.0,
        };
        Found {
            n: 0,
            first: [empty; INLINE],
            more: Vec::new(),
        }
    }

    fn len(&self) -> usize {
        self.n
    }

    fn is_empty(&self) -> bool {
        self.n == 0
    }

    fn iter(&self) -> impl Iterator<Item = &Candidate<N>> {
        self.first[..self.n.min(INLINE)].iter().chain(&self.more)
    }

    fn iter_mut(&mut self) -> impl Iterator<Item = &mut Candidate<N>> {
        self.first[..self.n.min(INLINE)]
            .iter_mut()
            .chain(&mut self.more)
    }

    fn push(&mut self, c: Candidate<N>) {
        if self.n < INLINE {
            self.first[self.n] = c;
        } else {
            self.more.push(c);
        }
        self.n += 1;
    }
}

/// The problem in the canonical units, on the stack (`N = 2K`).
struct Setup<const N: usize> {
    k: usize,
    w: [[f64; N]; N],
    v: [f64; N],
    b: [f64; MAX_CONTACTS],
    mu: [f64; MAX_CONTACTS],
}

/// Every solution of the conditions, least kinetic energy after first (module docs), in the
/// problem's own units. Empty when none is found (not observed) or `K >`
/// [`MAX_CONTACTS`].
///
/// ```
/// use impax::multi::{lcp, MultiProblem};
/// let p = MultiProblem::from_upper(1, &[3.5, 0.0, 1.0], &[0.5, -0.866], &[0.4], &[0.7]).unwrap();
/// assert_eq!(lcp::solutions(&p).len(), 1); // one contact: always exactly one
/// ```
pub fn solutions(problem: &MultiProblem) -> Vec<LcpSolution> {
    match resolve(problem) {
        Ok(o) => match o.detail {
            MultiDetail::Lcp { solutions } => solutions,
            _ => Vec::new(),
        },
        Err(_) => Vec::new(),
    }
}

/// `lcp` on `K` contacts: the solution of least kinetic energy after, every solution in the
/// detail ([`MultiDetail::Lcp`]). Breakdowns: [`BreakdownReason::TooManyContacts`] for
/// `K >` [`MAX_CONTACTS`], [`BreakdownReason::NoSolution`] if no combination of modes
/// satisfies the conditions to round-off, [`BreakdownReason::Overflow`] if a number is not
/// representable.
pub fn resolve(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lcp;
    let k = problem.contacts();
    if k > MAX_CONTACTS {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::TooManyContacts {
                contacts: k,
                limit: MAX_CONTACTS,
            },
        });
    }
    match k {
        1 => solve::<2, 2>(problem),
        2 => solve::<4, 6>(problem),
        3 => solve::<6, 12>(problem),
        4 => solve::<8, 20>(problem),
        5 => solve::<10, 30>(problem),
        _ => solve::<12, 42>(problem),
    }
}

/// [`resolve`] with `N = 2K` and `R = K (K + 1)` ([`Tree`]).
fn solve<const N: usize, const R: usize>(problem: &MultiProblem) -> MultiResolution {
    let law = LawId::Lcp;
    let k = problem.contacts();
    let setup = setup::<N>(problem);
    let mut found = Found::new();
    Tree::<N, R>::run(&setup, &mut found);
    if found.is_empty() {
        return Err(Breakdown {
            law,
            reason: BreakdownReason::NoSolution,
        });
    }
    let mut all: Vec<LcpSolution> = Vec::with_capacity(found.len());
    all.extend(found.iter().map(|c| tidy(&setup, c)));
    // Least kinetic energy after first (stable: ties keep the enumeration's order).
    all.sort_by(|a, b| a.energy_change.total_cmp(&b.energy_change));
    let best = &all[0];
    let contacts: Vec<ContactResult> = (0..k)
        .map(|j| {
            let (p, va) = (best.impulses[j], best.velocities_after[j]);
            let vb = Vec2::new(setup.v[2 * j], setup.v[2 * j + 1]);
            ContactResult {
                impulse: p,
                velocity_after: va,
                phases: Phases::one(super::ContactPhase {
                    kind: best.regimes[j],
                    ends_at: p.y,
                }),
                work: straight_work(vb, va, p),
            }
        })
        .collect();
    let inconsistency =
        (all.len() > 1).then_some(Inconsistency::MultipleSolutions { count: all.len() });
    let out = assemble(
        problem,
        law,
        contacts,
        MultiDetail::Lcp { solutions: all },
        inconsistency,
    );
    if out.is_finite() {
        Ok(out)
    } else {
        Err(Breakdown {
            law,
            reason: BreakdownReason::Overflow,
        })
    }
}

/// The work of one contact along the straight path `s p`: `∫ v_n dp_n = ½ p_n (v_n⁻ + v_n⁺)`
/// split where `v_n(s)` crosses zero, and `∫ v_t dp_t = ½ p_t (v_t⁻ + v_t⁺)`.
fn straight_work(before: Vec2, after: Vec2, p: Vec2) -> WorkSplit {
    let normal = 0.5 * p.y * (before.y + after.y);
    let compression = if before.y >= 0.0 || p.y == 0.0 {
        0.0
    } else if after.y >= 0.0 {
        // v_n(s) = v⁻ + s (v⁺ − v⁻) = 0 at s_c; ∫₀^{s_c} v_n p_n ds = ½ p_n s_c v_n⁻.
        let sc = -before.y / (after.y - before.y);
        0.5 * p.y * sc * before.y
    } else {
        normal
    };
    WorkSplit {
        compression,
        restitution: normal - compression,
        friction: 0.5 * p.x * (before.x + after.x),
    }
}

/// The problem's canonical numbers on the stack, with Newton's targets.
fn setup<const N: usize>(problem: &MultiProblem) -> Setup<N> {
    let (_, w, v, _) = problem.canonical();
    let k = problem.contacts();
    let mut s = Setup {
        k,
        w: [[0.0; N]; N],
        v: [0.0; N],
        b: [0.0; MAX_CONTACTS],
        mu: [0.0; MAX_CONTACTS],
    };
    for i in 0..2 * k {
        s.v[i] = v[i];
        for j in 0..2 * k {
            s.w[i][j] = w[(i, j)];
        }
    }
    for j in 0..k {
        s.b[j] = (-problem.restitutions()[j] * v[2 * j + 1]).max(0.0);
        s.mu[j] = problem.frictions()[j];
    }
    s
}

/// The modes contact `j` can be in.
fn choices<const N: usize>(s: &Setup<N>, j: usize) -> &'static [Mode] {
    if s.mu[j] > 0.0 {
        &WITH_FRICTION
    } else {
        &FRICTIONLESS
    }
}

/// Solve every combination of modes (contact 0 fastest); keep the distinct solutions, in
/// enumeration order: the definition that [`Tree`] reproduces.
#[cfg(test)]
fn enumerate_all<const N: usize>(s: &Setup<N>) -> Found<N> {
    let k = s.k;
    let mut digits = [0usize; MAX_CONTACTS];
    let mut modes = [Mode::Off; MAX_CONTACTS];
    let mut found = Found::new();
    loop {
        for j in 0..k {
            modes[j] = choices(s, j)[digits[j]];
        }
        // Every contact off leaves an approaching contact approaching: never a solution.
        if modes[..k].iter().any(|m| *m != Mode::Off) {
            if let Some(c) = solve_mode(s, &modes) {
                merge(&mut found, c);
            }
        }
        // Next combination (contact 0 fastest).
        let mut j = 0;
        loop {
            if j == k {
                return found;
            }
            digits[j] += 1;
            if digits[j] < choices(s, j).len() {
                break;
            }
            digits[j] = 0;
            j += 1;
        }
    }
}

/// Add `c` to the distinct solutions: if one has the same velocities, keep the one of smaller
/// impulse norm (the earlier on a tie).
fn merge<const N: usize>(found: &mut Found<N>, c: Candidate<N>) {
    for e in found.iter_mut() {
        let tol = SAME * e.vscale.max(c.vscale);
        if e.v.iter().zip(&c.v).all(|(a, b)| (a - b).abs() <= tol) {
            if c.norm < e.norm * (1.0 - SAME) {
                *e = c;
            }
            return;
        }
    }
    found.push(c);
}

mod exact;
mod tree;

pub(crate) use exact::least_norm;
use exact::{solve_mode, tidy};
use tree::Tree;

#[cfg(test)]
mod tests;
