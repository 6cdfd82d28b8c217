//! The elimination tree over the contacts' modes (the module docs: how the enumeration is
//! made fast).

use super::*;

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
pub(super) struct Tree<'a, const N: usize, const R: usize> {
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
    pub(super) fn run(s: &'a Setup<N>, found: &'a mut Found<N>) {
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
