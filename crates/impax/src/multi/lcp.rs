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

/// A mode is ruled out by the elimination tree only when one of its conditions fails by more
/// than this fraction of an upper bound of the scale its check is relative to (a thousand
/// times [`VELOCITY_ROUND_OFF`], the tolerance of the check itself).
const RULED_OUT: f64 = 1e-6;

/// Pivots of the elimination tree below this fraction of the largest diagonal entry of `W`
/// (for a `2 × 2` block: its determinant below this fraction of its largest entry squared)
/// hand the combinations below them to the exact solve unfiltered.
const TREE_PIVOT: f64 = 1e-6;

/// Multipliers of the elimination tree above this hand the combinations below them to the
/// exact solve unfiltered.
const TREE_GROWTH: f64 = 1e4;

/// The elimination tree: the contacts are eliminated in the order `K − 1, …, 0`, each in
/// each of its modes, by block Gaussian elimination of the equations of that mode (the Schur
/// complement `S` of what is eliminated stays the matrix of the contacts left, whatever
/// their modes), so that each combination of modes is a leaf, reached in enumeration order
/// (contact 0 fastest). At a leaf the impulses come out by back-substitution, contact 0
/// first, each contact's conditions checked as soon as its impulse is known; a combination
/// is ruled out only when a condition fails by [`RULED_OUT`] of an upper bound of its scale.
/// The combinations not ruled out are solved exactly ([`solve_mode`]), so the solutions are
/// those of the enumeration of every combination, to the last bit.
///
/// `N = 2K`; the Schur complements are kept in `R = K (K + 1)` rows: the one contact `c` is
/// eliminated from (`2c + 2` rows and columns) in the slot at row `c (c + 1)`.
struct Tree<'a, const N: usize, const R: usize> {
    s: &'a Setup<N>,
    /// The largest diagonal entry of `W`.
    wscale: f64,
    /// `max_i |v⁻_i|` and `max_i Σ_j |W_ij|`: the velocity scale is at most
    /// `vmax + wrow max |p|`.
    vmax: f64,
    wrow: f64,
    /// Per contact: its mode, the slot of the Schur complement it is eliminated from, its
    /// pivot's inverse (stick: the `2 × 2` block's; slip or frictionless: `1/pivot` in
    /// `[0][0]`), `p_t = ratio p_n` in slip, and [`RULED_OUT`] times the bound
    /// `a + b |p_{0…c}|` of the combination's largest impulse (as the pair `(a, b)`).
    mode: [Mode; MAX_CONTACTS],
    slot: [usize; MAX_CONTACTS],
    inv: [[[f64; 2]; 2]; MAX_CONTACTS],
    ratio: [f64; MAX_CONTACTS],
    bound: [(f64, f64); MAX_CONTACTS],
    /// `RULED_OUT vmax`.
    tv: f64,
    /// The Schur complements and their right-hand sides (slot `K − 1`: `W`).
    mats: [[f64; N]; R],
    rhs: [[f64; N]; MAX_CONTACTS],
    found: &'a mut Found<N>,
}

/// `|x|` of a `2 × 2` matrix's rows, the larger (the ∞-norm).
#[inline(always)]
fn norm2(m: &[[f64; 2]; 2]) -> f64 {
    larger(m[0][0].abs() + m[0][1].abs(), m[1][0].abs() + m[1][1].abs())
}

/// Whether `x > bound` (not when either is NaN: a NaN pivot or condition keeps the
/// combination, whose exact solve then decides).
#[inline(always)]
fn exceeds(x: f64, bound: f64) -> bool {
    x > bound
}

/// The larger of two numbers, without `f64::max`'s handling of NaN (which costs more): the
/// tree's numbers are finite (the inputs scaled, the pivots bounded away from zero), and
/// where a NaN did reach a tolerance, the tolerance would be NaN and rule nothing out.
#[inline(always)]
fn larger(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

impl<'a, const N: usize, const R: usize> Tree<'a, N, R> {
    /// The distinct solutions of the problem `s` (`2K = N`), in enumeration order.
    fn run(s: &'a Setup<N>, found: &'a mut Found<N>) {
        let k = s.k;
        debug_assert!(2 * k == N && k * (k + 1) == R);
        let mut tree = Tree {
            s,
            wscale: 0.0,
            vmax: 0.0,
            wrow: 0.0,
            mode: [Mode::Off; MAX_CONTACTS],
            slot: [0; MAX_CONTACTS],
            inv: [[[0.0; 2]; 2]; MAX_CONTACTS],
            ratio: [0.0; MAX_CONTACTS],
            bound: [(0.0, 1.0); MAX_CONTACTS],
            tv: 0.0,
            mats: [[0.0; N]; R],
            rhs: [[0.0; N]; MAX_CONTACTS],
            found,
        };
        let top = (k - 1) * k;
        for i in 0..N {
            tree.mats[top + i].copy_from_slice(&s.w[i][..N]);
            let target = if i % 2 == 0 { 0.0 } else { s.b[i / 2] };
            tree.rhs[k - 1][i] = target - s.v[i];
            tree.wscale = larger(tree.wscale, s.w[i][i].abs());
            tree.vmax = larger(tree.vmax, s.v[i].abs());
            tree.wrow = larger(tree.wrow, s.w[i][..N].iter().map(|x| x.abs()).sum());
        }
        tree.tv = RULED_OUT * tree.vmax;
        tree.branch(k - 1, k - 1, 0.0, 1.0, 0);
    }

    /// Whether a `2 × 2` pivot block is usable: its largest entry above [`TREE_PIVOT`] of
    /// `W`'s, its determinant above [`TREE_PIVOT`] of that entry squared.
    #[inline(always)]
    fn usable(&self, b: [f64; 4], det: f64) -> bool {
        let m = larger(
            larger(b[0].abs(), b[1].abs()),
            larger(b[2].abs(), b[3].abs()),
        );
        m > TREE_PIVOT * self.wscale && det.abs() > TREE_PIVOT * m * m
    }

    /// Eliminate contact `c ≥ 1` in each of its modes from the Schur complement in `slot`
    /// (the contacts `0 … c` left), the largest impulse bounded by `a + b |p_{0…c}|`,
    /// `active` the contacts above `c` with an impulse.
    fn branch(&mut self, c: usize, slot: usize, a: f64, b: f64, active: usize) {
        if c == 0 {
            return self.last(slot, a, b, active);
        }
        self.slot[c] = slot;
        self.bound[c] = (RULED_OUT * a, RULED_OUT * b);
        self.mode[c] = Mode::Off;
        self.branch(c - 1, slot, a, b, active);
        let mu = self.s.mu[c];
        let modes: &[(Mode, f64)] = if mu > 0.0 {
            &[
                (Mode::Stick, 0.0),
                (Mode::SlipPos, -1.0),
                (Mode::SlipNeg, 1.0),
            ]
        } else {
            &[(Mode::Free, 0.0)]
        };
        for &(mode, sign) in modes {
            self.mode[c] = mode;
            let bounds = if mode == Mode::Stick {
                // (The last but one contact, most often eliminated, with its size known: the
                // loops unrolled.)
                if c == 1 {
                    self.eliminate_stick(1, slot, 2)
                } else {
                    self.eliminate_stick(c, slot, 2 * c)
                }
            } else if c == 1 {
                self.eliminate_slip(1, slot, sign * mu, 2)
            } else {
                self.eliminate_slip(c, slot, sign * mu, 2 * c)
            };
            match bounds {
                Some((ac, bc)) => {
                    self.branch(c - 1, c - 1, a + b * ac, b * larger(bc, 1.0), active + 1)
                }
                None => self.unfiltered(c, active + 1),
            }
        }
    }

    /// Contact `c ≥ 1` sticking (`t = 2c`): the Schur complement of its two equations from
    /// the one in `slot` into slot `c − 1`, and `(ac, bc)` with `|p_c| ≤ ac + bc |p_{0…c−1}|`;
    /// `None` if the pivot block or the multipliers are out of bounds.
    #[allow(clippy::needless_range_loop)] // rows and columns of S indexed alike
    #[inline(always)]
    fn eliminate_stick(&mut self, c: usize, slot: usize, t: usize) -> Option<(f64, f64)> {
        debug_assert_eq!(t, 2 * c);
        let n = t + 1;
        let (top, below) = (slot * (slot + 1), (c - 1) * c);
        let (lo, hi) = self.mats.split_at_mut(top);
        let (sm, child) = (&hi[..n + 1], &mut lo[below..below + t]);
        let (rlo, rhi) = self.rhs.split_at_mut(c);
        let (rhs, r2) = (&rhi[slot - c], &mut rlo[c - 1]);
        let (b00, b01, b10, b11) = (sm[t][t], sm[t][n], sm[n][t], sm[n][n]);
        let det = b00 * b11 - b01 * b10;
        let m = larger(larger(b00.abs(), b01.abs()), larger(b10.abs(), b11.abs()));
        if !(m > TREE_PIVOT * self.wscale && det.abs() > TREE_PIVOT * m * m) {
            return None;
        }
        let inv = [[b11 / det, -b01 / det], [-b10 / det, b00 / det]];
        self.inv[c] = inv;
        let (mut rt, mut rn) = (0.0, 0.0);
        let mut fine = true;
        for i in 0..t {
            let l0 = sm[i][t] * inv[0][0] + sm[i][n] * inv[1][0];
            let l1 = sm[i][t] * inv[0][1] + sm[i][n] * inv[1][1];
            fine &= l0.abs() <= TREE_GROWTH && l1.abs() <= TREE_GROWTH;
            for j in 0..t {
                child[i][j] = sm[i][j] - l0 * sm[t][j] - l1 * sm[n][j];
            }
            r2[i] = rhs[i] - l0 * rhs[t] - l1 * rhs[n];
            rt += sm[t][i].abs();
            rn += sm[n][i].abs();
        }
        let ninv = norm2(&inv);
        fine.then(|| {
            (
                ninv * larger(rhs[t].abs(), rhs[n].abs()),
                ninv * larger(rt, rn),
            )
        })
    }

    /// Contact `c ≥ 1` slipping with `p_t = ratio p_n` (frictionless: `ratio = 0`): as
    /// [`Tree::eliminate_stick`] for its normal equation.
    #[allow(clippy::needless_range_loop)] // rows and columns of S indexed alike
    #[inline(always)]
    fn eliminate_slip(
        &mut self,
        c: usize,
        slot: usize,
        ratio: f64,
        t: usize,
    ) -> Option<(f64, f64)> {
        debug_assert_eq!(t, 2 * c);
        let n = t + 1;
        let (top, below) = (slot * (slot + 1), (c - 1) * c);
        let (lo, hi) = self.mats.split_at_mut(top);
        let (sm, child) = (&hi[..n + 1], &mut lo[below..below + t]);
        let (rlo, rhi) = self.rhs.split_at_mut(c);
        let (rhs, r2) = (&rhi[slot - c], &mut rlo[c - 1]);
        let pivot = sm[n][t] * ratio + sm[n][n];
        if !exceeds(pivot.abs(), TREE_PIVOT * self.wscale) {
            return None;
        }
        let ip = 1.0 / pivot;
        self.ratio[c] = ratio;
        self.inv[c][0][0] = ip;
        let mut rn = 0.0;
        let mut fine = true;
        for i in 0..t {
            let l = (sm[i][t] * ratio + sm[i][n]) * ip;
            fine &= l.abs() <= TREE_GROWTH;
            for j in 0..t {
                child[i][j] = sm[i][j] - l * sm[n][j];
            }
            r2[i] = rhs[i] - l * rhs[n];
            rn += sm[n][i].abs();
        }
        let f = larger(ratio.abs(), 1.0) * ip.abs();
        fine.then(|| (f * rhs[n].abs(), f * rn))
    }

    /// Contact 0 in each of its modes, from the `2 × 2` Schur complement in `slot`: its
    /// impulse, its conditions, then the back-substitution of the others ([`Tree::rest`]).
    fn last(&mut self, slot: usize, a: f64, b: f64, active: usize) {
        let top = slot * (slot + 1);
        let (b00, b01) = (self.mats[top][0], self.mats[top][1]);
        let (b10, b11) = (self.mats[top + 1][0], self.mats[top + 1][1]);
        let (rt, rn) = (self.rhs[slot][0], self.rhs[slot][1]);
        let mu = self.s.mu[0];
        // Off: no impulse, v_n⁺ ≥ b needed (every contact off is no solution).
        if active > 0 && !exceeds(rn, RULED_OUT * (self.vmax + self.wrow * a)) {
            self.leaf(Mode::Off, 0.0, 0.0);
        }
        let wscale = self.wscale;
        if mu > 0.0 {
            // Stick.
            let det = b00 * b11 - b01 * b10;
            if !self.usable([b00, b01, b10, b11], det) {
                self.mode[0] = Mode::Stick;
                self.unfiltered(0, active + 1);
            } else {
                let idet = 1.0 / det;
                let (pt, pn) = ((b11 * rt - b01 * rn) * idet, (b00 * rn - b10 * rt) * idet);
                let tolp = RULED_OUT * (a + b * larger(pt.abs(), pn.abs()));
                if !(-pn > tolp || pt.abs() - mu * pn > tolp) {
                    self.leaf(Mode::Stick, pt, pn);
                }
            }
        }
        // Slip (frictionless: no friction).
        let slips: &[(Mode, f64)] = if mu > 0.0 {
            &[(Mode::SlipPos, -1.0), (Mode::SlipNeg, 1.0)]
        } else {
            &[(Mode::Free, 0.0)]
        };
        for &(mode, sign) in slips {
            let ratio = sign * mu;
            let pivot = b10 * ratio + b11;
            if !exceeds(pivot.abs(), TREE_PIVOT * wscale) {
                self.mode[0] = mode;
                self.unfiltered(0, active + 1);
                continue;
            }
            let pn = rn / pivot;
            let pt = ratio * pn;
            let pbound = a + b * larger(pt.abs(), pn.abs());
            if -pn > RULED_OUT * pbound {
                continue;
            }
            if mode != Mode::Free {
                let vt = b00 * pt + b01 * pn - rt;
                let tolv = RULED_OUT * (self.vmax + self.wrow * pbound);
                if sign * vt > tolv {
                    continue;
                }
            }
            self.leaf(mode, pt, pn);
        }
    }

    /// Contact 0 in `mode` with the impulse `(pt, pn)`, its own conditions met: the exact
    /// solve if the back-substitution rules nothing out.
    fn leaf(&mut self, mode: Mode, pt: f64, pn: f64) {
        self.mode[0] = mode;
        if self.rest(pt, pn) {
            let modes = self.mode;
            self.exact(&modes);
        }
    }

    /// The back-substitution of the contacts `1 … K − 1` after contact 0's impulse, each
    /// contact's conditions checked with the tolerance [`RULED_OUT`] of the bound of its
    /// scale: whether none fails.
    fn rest(&self, pt0: f64, pn0: f64) -> bool {
        let s = self.s;
        let mut p = [0.0; N];
        p[0] = pt0;
        p[1] = pn0;
        let mut known = larger(pt0.abs(), pn0.abs());
        for c in 1..N / 2 {
            let (t, n) = (2 * c, 2 * c + 1);
            let slot = self.slot[c];
            let top = slot * (slot + 1);
            let (row_t, row_n) = (&self.mats[top + t], &self.mats[top + n]);
            let rhs = &self.rhs[slot];
            let (mut xt, mut xn) = (0.0, 0.0);
            for i in 0..t {
                xt += row_t[i] * p[i];
                xn += row_n[i] * p[i];
            }
            // The tolerances: RULED_OUT of the bounds a + b |p| (impulses) and
            // vmax + wrow (a + b |p|) (velocities).
            let (ta, tb) = self.bound[c];
            let mode = self.mode[c];
            let (pt, pn) = match mode {
                Mode::Off => {
                    if xn - rhs[n] < -(self.tv + self.wrow * (ta + tb * known)) {
                        return false;
                    }
                    continue;
                }
                Mode::Stick => {
                    let inv = &self.inv[c];
                    let (ut, un) = (rhs[t] - xt, rhs[n] - xn);
                    (
                        inv[0][0] * ut + inv[0][1] * un,
                        inv[1][0] * ut + inv[1][1] * un,
                    )
                }
                _ => {
                    let y = (rhs[n] - xn) * self.inv[c][0][0];
                    (self.ratio[c] * y, y)
                }
            };
            p[t] = pt;
            p[n] = pn;
            known = larger(known, larger(pt.abs(), pn.abs()));
            let tolp = ta + tb * known;
            if -pn > tolp {
                return false;
            }
            let out = match mode {
                Mode::Stick => pt.abs() - s.mu[c] * pn > tolp,
                Mode::SlipPos | Mode::SlipNeg => {
                    let vt = xt + row_t[t] * pt + row_t[n] * pn - rhs[t];
                    let tolv = self.tv + self.wrow * tolp;
                    if mode == Mode::SlipPos {
                        vt < -tolv
                    } else {
                        vt > tolv
                    }
                }
                _ => false,
            };
            if out {
                return false;
            }
        }
        true
    }

    /// Every combination below the current one at contact `c` (the contacts `0 … c − 1` in
    /// each of their modes) to the exact solve, unfiltered; `active` the contacts `c …` with
    /// an impulse.
    fn unfiltered(&mut self, c: usize, active: usize) {
        let s = self.s;
        let mut modes = self.mode;
        let mut digits = [0usize; MAX_CONTACTS];
        loop {
            for j in 0..c {
                modes[j] = choices(s, j)[digits[j]];
            }
            if active > 0 || modes[..c].iter().any(|m| *m != Mode::Off) {
                self.exact(&modes);
            }
            let mut j = 0;
            loop {
                if j == c {
                    return;
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

    /// The exact solve of one combination, merged into the solutions if it is one.
    fn exact(&mut self, modes: &[Mode; MAX_CONTACTS]) {
        if let Some(cand) = solve_mode(self.s, modes) {
            merge(self.found, cand);
        }
    }
}

/// Solve the equations of one combination of modes; the candidate if it satisfies every
/// condition to round-off.
#[allow(clippy::needless_range_loop)] // j and i index the contacts and the rows of W alike
fn solve_mode<const N: usize>(s: &Setup<N>, modes: &[Mode; MAX_CONTACTS]) -> Option<Candidate<N>> {
    // (N = 2K: the loops over the contacts of known length.)
    let k = N / 2;
    debug_assert_eq!(k, s.k);
    // Unknowns: a stick contact has (p_t, p_n), a slip (or frictionless) contact p_n with
    // p_t = ratio p_n, written as y (ratio, 1)/|(ratio, 1)| so that |y| is |p_j|.
    let mut contact = [0usize; N];
    let mut ct = [0.0; N];
    let mut cn = [0.0; N];
    let mut rows = [0usize; N];
    let mut n = 0;
    let mut m = 0;
    for j in 0..k {
        let ratio = match modes[j] {
            Mode::Off => continue,
            Mode::Stick => {
                contact[n] = j;
                ct[n] = 1.0;
                cn[n] = 0.0;
                contact[n + 1] = j;
                ct[n + 1] = 0.0;
                cn[n + 1] = 1.0;
                n += 2;
                rows[m] = 2 * j;
                rows[m + 1] = 2 * j + 1;
                m += 2;
                continue;
            }
            Mode::SlipPos => -s.mu[j],
            Mode::SlipNeg => s.mu[j],
            Mode::Free => 0.0,
        };
        let h = 1f64.hypot(ratio);
        contact[n] = j;
        ct[n] = ratio / h;
        cn[n] = 1.0 / h;
        n += 1;
        rows[m] = 2 * j + 1;
        m += 1;
    }
    debug_assert_eq!(n, m);
    let mut a = [[0.0; N]; N];
    let mut r = [0.0; N];
    for row in 0..n {
        let i = rows[row];
        for c in 0..n {
            let j = contact[c];
            a[row][c] = ct[c] * s.w[i][2 * j] + cn[c] * s.w[i][2 * j + 1];
        }
        let target = if i.is_multiple_of(2) { 0.0 } else { s.b[i / 2] };
        r[row] = target - s.v[i];
    }
    let mut y = [0.0; N];
    // (The small systems with their size known: the loops unrolled, the same operations.)
    match n {
        1 => least_norm_sized::<N, 1>(&mut a, &mut r, &mut y),
        2 => least_norm_sized::<N, 2>(&mut a, &mut r, &mut y),
        3 => least_norm_sized::<N, 3>(&mut a, &mut r, &mut y),
        4 => least_norm_sized::<N, 4>(&mut a, &mut r, &mut y),
        _ => least_norm_n(&mut a, &mut r, n, &mut y),
    }
    let mut p = [0.0; N];
    for c in 0..n {
        let j = contact[c];
        p[2 * j] += ct[c] * y[c];
        p[2 * j + 1] += cn[c] * y[c];
    }
    let pscale = p[..2 * k]
        .iter()
        .fold(0.0f64, |x, y| x.max(y.abs()))
        .max(f64::MIN_POSITIVE);
    // The impulse conditions first (cheap).
    for j in 0..k {
        let (pt, pn) = (p[2 * j], p[2 * j + 1]);
        let bad = match modes[j] {
            Mode::Off => false,
            Mode::Stick => {
                -pn > VELOCITY_ROUND_OFF * pscale
                    || pt.abs() - s.mu[j] * pn > VELOCITY_ROUND_OFF * pscale
            }
            _ => -pn > VELOCITY_ROUND_OFF * pscale,
        };
        if bad {
            return None;
        }
    }
    // Velocities after and their scale.
    let mut v = [0.0; N];
    let mut vscale = 0.0f64;
    for i in 0..2 * k {
        let (mut x, mut size) = (s.v[i], s.v[i].abs());
        for j in 0..k {
            if modes[j] != Mode::Off {
                let (wt, wn) = (s.w[i][2 * j], s.w[i][2 * j + 1]);
                x += wt * p[2 * j] + wn * p[2 * j + 1];
                size += wt.abs() * p[2 * j].abs() + wn.abs() * p[2 * j + 1].abs();
            }
        }
        v[i] = x;
        vscale = vscale.max(size);
    }
    let tol = VELOCITY_ROUND_OFF * vscale;
    for j in 0..k {
        let (vt, vn, b) = (v[2 * j], v[2 * j + 1], s.b[j]);
        let bad = match modes[j] {
            Mode::Off => vn < b - tol,
            Mode::Stick => vt.abs() > tol || (vn - b).abs() > tol,
            Mode::SlipPos => vt < -tol || (vn - b).abs() > tol,
            Mode::SlipNeg => vt > tol || (vn - b).abs() > tol,
            Mode::Free => (vn - b).abs() > tol,
        };
        if bad {
            return None;
        }
    }
    Some(Candidate {
        modes: *modes,
        p,
        v,
        vscale,
        norm: p[..2 * k].iter().map(|x| x * x).sum::<f64>().sqrt(),
    })
}

/// The solution as reported: impulses inside their cones (`p_n ≥ 0`, `|p_t| ≤ μ p_n`,
/// `p_t = ∓μ p_n` in slip: removing round-off), velocities as the conditions give them
/// (`v_n⁺ = b` with an impulse, `v_t⁺ = 0` in stick), and `ΔT`.
fn tidy<const N: usize>(s: &Setup<N>, c: &Candidate<N>) -> LcpSolution {
    let k = s.k;
    let mut regimes = PerContact::filled(k, ContactPhaseKind::Off);
    let mut impulses = PerContact::filled(k, Vec2::zeros());
    let mut velocities = PerContact::filled(k, Vec2::zeros());
    let mut energy = 0.0;
    for j in 0..k {
        let mu = s.mu[j];
        let (mut vt, mut vn) = (c.v[2 * j], c.v[2 * j + 1]);
        let pn = c.p[2 * j + 1].max(0.0);
        let (regime, pt, pn) = match c.modes[j] {
            Mode::Off => (ContactPhaseKind::Off, 0.0, 0.0),
            Mode::Stick => {
                vt = 0.0;
                vn = s.b[j];
                let pt = c.p[2 * j].clamp(-mu * pn, mu * pn);
                (ContactPhaseKind::Stick, pt, pn)
            }
            Mode::SlipPos => {
                vn = s.b[j];
                (
                    ContactPhaseKind::Slip(SlipDirection::Positive),
                    -mu * pn,
                    pn,
                )
            }
            Mode::SlipNeg => {
                vn = s.b[j];
                (ContactPhaseKind::Slip(SlipDirection::Negative), mu * pn, pn)
            }
            Mode::Free => {
                vn = s.b[j];
                (ContactPhaseKind::Slip(SlipDirection::of(vt)), 0.0, pn)
            }
        };
        energy += 0.5 * ((s.v[2 * j] + vt) * pt + (s.v[2 * j + 1] + vn) * pn);
        regimes[j] = regime;
        impulses[j] = Vec2::new(pt, pn);
        velocities[j] = Vec2::new(vt, vn);
    }
    LcpSolution {
        regimes,
        impulses,
        velocities_after: velocities,
        energy_change: energy,
    }
}

/// Solve `a y = r` (`n × n`) in the least-squares, least-norm sense: Gaussian elimination
/// with complete pivoting; a pivot below [`PIVOT_TOL`] of the largest entry ends it (rank
/// `ρ < n`), and the `n − ρ` free unknowns are chosen to minimise `|y|` (with
/// `y₁ = U₁₁⁻¹ (c₁ − U₁₂ y₂)`: `(GᵀG + I) y₂ = Gᵀ a₀`, `G = U₁₁⁻¹ U₁₂`, `a₀ = U₁₁⁻¹ c₁`). The
/// equations left out are checked by the caller (through the velocities after).
pub(crate) fn least_norm(
    a: &mut [[f64; DIM]; DIM],
    r: &mut [f64; DIM],
    n: usize,
    y: &mut [f64; DIM],
) {
    least_norm_n(a, r, n, y);
}

/// [`least_norm_n`] with `n = M` known.
#[inline(always)]
fn least_norm_sized<const D: usize, const M: usize>(
    a: &mut [[f64; D]; D],
    r: &mut [f64; D],
    y: &mut [f64; D],
) {
    least_norm_n(a, r, M, y);
}

/// [`least_norm`] on arrays of any size `D ≥ n` (the same operations in the same order:
/// the same numbers).
#[allow(clippy::needless_range_loop)] // the indices of the triangular factors, as written
#[inline(always)]
fn least_norm_n<const D: usize>(
    a: &mut [[f64; D]; D],
    r: &mut [f64; D],
    n: usize,
    y: &mut [f64; D],
) {
    let mut col = [0usize; D];
    for (i, c) in col.iter_mut().enumerate() {
        *c = i;
    }
    let mut amax = 0.0f64;
    for i in 0..n {
        for j in 0..n {
            amax = amax.max(a[i][j].abs());
        }
    }
    let tol = PIVOT_TOL * amax;
    let mut rank = 0;
    for k in 0..n {
        let (mut pi, mut pj, mut best) = (k, k, 0.0f64);
        for i in k..n {
            for j in k..n {
                let x = a[i][j].abs();
                if x > best {
                    best = x;
                    pi = i;
                    pj = j;
                }
            }
        }
        if best <= tol || best == 0.0 {
            break;
        }
        a.swap(k, pi);
        r.swap(k, pi);
        if pj != k {
            for row in a.iter_mut().take(n) {
                row.swap(k, pj);
            }
            col.swap(k, pj);
        }
        let pivot = a[k][k];
        for i in k + 1..n {
            let f = a[i][k] / pivot;
            if f != 0.0 {
                for j in k + 1..n {
                    a[i][j] -= f * a[k][j];
                }
                r[i] -= f * r[k];
            }
            a[i][k] = 0.0;
        }
        rank += 1;
    }
    // Back substitution with U₁₁ (rank × rank) for a right-hand side.
    let back = |rhs: &mut [f64; D], a: &[[f64; D]; D]| {
        for i in (0..rank).rev() {
            let mut x = rhs[i];
            for j in i + 1..rank {
                x -= a[i][j] * rhs[j];
            }
            rhs[i] = x / a[i][i];
        }
    };
    let mut yp = [0.0; D];
    let mut a0 = *r;
    back(&mut a0, a);
    if rank == n {
        yp[..n].copy_from_slice(&a0[..n]);
    } else {
        let d = n - rank;
        // G = U₁₁⁻¹ U₁₂, one column per free unknown.
        let mut g = [[0.0; D]; D];
        for c in 0..d {
            let mut col_c = [0.0; D];
            for i in 0..rank {
                col_c[i] = a[i][rank + c];
            }
            back(&mut col_c, a);
            for i in 0..rank {
                g[i][c] = col_c[i];
            }
        }
        // (GᵀG + I) z = Gᵀ a₀ by Cholesky (the matrix is ≥ I).
        let mut m = [[0.0; D]; D];
        let mut h = [0.0; D];
        for p in 0..d {
            for q in 0..=p {
                let mut x: f64 = (0..rank).map(|i| g[i][p] * g[i][q]).sum();
                if p == q {
                    x += 1.0;
                }
                m[p][q] = x;
                m[q][p] = x;
            }
            h[p] = (0..rank).map(|i| g[i][p] * a0[i]).sum();
        }
        for p in 0..d {
            for q in 0..p {
                let x = m[p][q] / m[q][q];
                for t in q + 1..=p {
                    m[p][t] -= x * m[q][t];
                }
                h[p] -= x * h[q];
            }
        }
        let mut z = [0.0; D];
        for p in (0..d).rev() {
            let mut x = h[p];
            for q in p + 1..d {
                x -= m[p][q] * z[q];
            }
            z[p] = x / m[p][p];
        }
        for i in 0..rank {
            yp[i] = a0[i] - (0..d).map(|c| g[i][c] * z[c]).sum::<f64>();
        }
        yp[rank..n].copy_from_slice(&z[..d]);
    }
    for kk in 0..n {
        y[col[kk]] = yp[kk];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The least-norm solution of a consistent rank-deficient system: `y₁ + y₂ = 2` twice
    /// (rank 1) has the least-norm solution `(1, 1)`.
    #[test]
    fn least_norm_of_a_rank_deficient_system() {
        let mut a = [[0.0; DIM]; DIM];
        a[0][0] = 1.0;
        a[0][1] = 1.0;
        a[1][0] = 1.0;
        a[1][1] = 1.0;
        let mut r = [0.0; DIM];
        r[0] = 2.0;
        r[1] = 2.0;
        let mut y = [0.0; DIM];
        least_norm(&mut a, &mut r, 2, &mut y);
        assert!(
            (y[0] - 1.0).abs() < 1e-15 && (y[1] - 1.0).abs() < 1e-15,
            "{y:?}"
        );
    }

    /// Random problems as the physics tests draw them: `W = J M⁻¹ Jᵀ` of random bodies
    /// (singular when the contacts outnumber the degrees of freedom), `v = J u`, some
    /// contacts frictionless, some plastic or elastic.
    fn random_problem(rng: &mut crate::math::SplitMix64, k: usize) -> MultiProblem {
        use nalgebra::{DMatrix, DVector};
        loop {
            let dof = match rng.next_u64() % 10 {
                0..=2 => (k + 1 + (rng.next_u64() as usize) % (k - 1).max(1))
                    .min(2 * k - 1)
                    .max(2),
                3 => 2 * k,
                _ => 2 * k + (rng.next_u64() as usize) % 4,
            };
            let j = DMatrix::from_fn(2 * k, dof, |_, _| rng.range(-1.0, 1.0));
            let minv =
                DMatrix::from_diagonal(&DVector::from_fn(dof, |_, _| 1.0 / rng.decades(-1.5, 1.5)));
            let u = DVector::from_fn(dof, |_, _| rng.range(-1.0, 1.0));
            let w = &j * minv * j.transpose();
            let v: Vec<f64> = (&j * u).iter().copied().collect();
            let mu: Vec<f64> = (0..k)
                .map(|_| match rng.next_u64() % 6 {
                    0 => 0.0,
                    1 => rng.range(1.0, 4.0),
                    _ => rng.range(0.0, 1.5),
                })
                .collect();
            let e: Vec<f64> = (0..k)
                .map(|_| match rng.next_u64() % 10 {
                    0 => 0.0,
                    1 => 1.0,
                    _ => rng.unit(),
                })
                .collect();
            if let Ok(p) = MultiProblem::new(w, &v, &mu, &e) {
                return p;
            }
        }
    }

    /// A solution's modes and the bits of its impulses and velocities.
    type Bits = ([Mode; MAX_CONTACTS], Vec<u64>, Vec<u64>);

    /// The solutions of the elimination tree and of the enumeration of every combination
    /// (`N = 2K`).
    fn compare<const N: usize, const R: usize>(p: &MultiProblem) -> (Vec<Bits>, Vec<Bits>) {
        let n = 2 * p.contacts();
        let bits = |x: &[f64]| x[..n].iter().map(|y| y.to_bits()).collect::<Vec<u64>>();
        let s = setup::<N>(p);
        let mut fast = Found::new();
        Tree::<N, R>::run(&s, &mut fast);
        let all = enumerate_all(&s);
        (
            fast.iter()
                .map(|c| (c.modes, bits(&c.p), bits(&c.v)))
                .collect(),
            all.iter()
                .map(|c| (c.modes, bits(&c.p), bits(&c.v)))
                .collect(),
        )
    }

    /// The elimination tree finds, to the last bit and in the same order, the solutions of
    /// the enumeration of every combination of modes.
    #[test]
    fn tree_finds_what_the_full_enumeration_finds() {
        let mut rng = crate::math::SplitMix64(0x7e11);
        let mut several = 0;
        for trial in 0..40_000 {
            let k = match trial % 20 {
                0 => 1,
                1..=7 => 2,
                8..=13 => 3,
                14..=17 => 4,
                18 => 5,
                _ if trial % 100 == 19 => 6,
                _ => 3,
            };
            let p = random_problem(&mut rng, k);
            let (fast, all) = match k {
                1 => compare::<2, 2>(&p),
                2 => compare::<4, 6>(&p),
                3 => compare::<6, 12>(&p),
                4 => compare::<8, 20>(&p),
                5 => compare::<10, 30>(&p),
                _ => compare::<12, 42>(&p),
            };
            several += usize::from(all.len() > 1);
            assert!(fast == all, "trial {trial}: {fast:?}\nvs {all:?}\non {p:?}");
        }
        assert!(several > 100, "{several}");
    }

    /// A full-rank system is solved exactly (a 3 × 3 with a known solution).
    #[test]
    fn full_rank_system() {
        let m = [[4.0, -2.0, 1.0], [-2.0, 4.0, -2.0], [1.0, -2.0, 4.0]];
        let x = [1.0, -2.0, 0.5];
        let mut a = [[0.0; DIM]; DIM];
        let mut r = [0.0; DIM];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] = m[i][j];
                r[i] += m[i][j] * x[j];
            }
        }
        let mut y = [0.0; DIM];
        least_norm(&mut a, &mut r, 3, &mut y);
        for i in 0..3 {
            assert!((y[i] - x[i]).abs() < 1e-14, "{y:?}");
        }
    }
}
