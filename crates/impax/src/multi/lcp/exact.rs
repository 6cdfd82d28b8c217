//! The exact solve of one combination of modes (least-squares, least-norm for a singular
//! `W`) and the solution as reported.

use super::*;

/// Solve the equations of one combination of modes; the candidate if it satisfies every
/// condition to round-off.
#[allow(clippy::needless_range_loop)] // j and i index the contacts and the rows of W alike
pub(super) fn solve_mode<const N: usize>(
    s: &Setup<N>,
    modes: &[Mode; MAX_CONTACTS],
) -> Option<Candidate<N>> {
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
    // The impulse conditions first (cheap), each as a distance from the contact's cone to
    // round-off of the impulses' scale: a slip impulse `y (ratio, 1)/|(ratio, 1)|` is in its
    // cone when `y ≥ 0` — its normal part alone, `y/|(ratio, 1)|`, would let a reversed
    // impulse through when `μ` is large (a spurious slip with friction driving the slip).
    let tol = VELOCITY_ROUND_OFF * pscale;
    for c in 0..n {
        let j = contact[c];
        let bad = match modes[j] {
            Mode::Stick if cn[c] == 0.0 => false,
            Mode::Stick => {
                let (pt, pn) = (p[2 * j], p[2 * j + 1]);
                -pn > tol || (pt.abs() - s.mu[j] * pn) / 1f64.hypot(s.mu[j]) > tol
            }
            _ => -y[c] > tol,
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
pub(super) fn tidy<const N: usize>(s: &Setup<N>, c: &Candidate<N>) -> LcpSolution {
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
