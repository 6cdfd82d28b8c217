//! What several test modules share.

use impax::math::{Mat3, SplitMix64, Vec2};
use impax::multi::{MultiOutcome, MultiProblem};
use impax::planar::ContactProblem;
use nalgebra::{DMatrix, DVector};

/// A uniformly random rotation (from a random unit quaternion).
pub fn rotation(rng: &mut SplitMix64) -> Mat3 {
    loop {
        let q = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let n2: f64 = q.iter().map(|x| x * x).sum();
        if !(1e-3..=1.0).contains(&n2) {
            continue;
        }
        let n = n2.sqrt();
        let (w, x, y, z) = (q[0] / n, q[1] / n, q[2] / n, q[3] / n);
        return Mat3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - z * w),
            2.0 * (x * z + y * w),
            2.0 * (x * y + z * w),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - x * w),
            2.0 * (x * z - y * w),
            2.0 * (y * z + x * w),
            1.0 - 2.0 * (x * x + y * y),
        );
    }
}

/// `W = J M⁻¹ Jᵀ` and `v = J u` from a contact Jacobian, a diagonal mass matrix and `u`.
pub fn contact_space(
    j: &DMatrix<f64>,
    masses: &[f64],
    u: &DVector<f64>,
) -> (DMatrix<f64>, Vec<f64>) {
    let minv = DMatrix::from_diagonal(&DVector::from_iterator(
        masses.len(),
        masses.iter().map(|m| 1.0 / m),
    ));
    let w = j * &minv * j.transpose();
    let v = j * u;
    (w, v.iter().copied().collect())
}

/// The body velocities after: `u⁺ = u⁻ + M⁻¹ Jᵀ p`.
pub fn body_after(
    j: &DMatrix<f64>,
    masses: &[f64],
    u: &DVector<f64>,
    o: &MultiOutcome,
) -> DVector<f64> {
    let p = DVector::from_iterator(
        2 * o.contacts.len(),
        o.contacts.iter().flat_map(|c| [c.impulse.x, c.impulse.y]),
    );
    let du = j.transpose() * p;
    DVector::from_iterator(u.len(), (0..u.len()).map(|i| u[i] + du[i] / masses[i]))
}

/// The kinetic energy `½ Σ m_i u_i²` of a diagonal mass matrix.
pub fn kinetic(masses: &[f64], u: &DVector<f64>) -> f64 {
    0.5 * masses
        .iter()
        .zip(u.iter())
        .map(|(m, x)| m * x * x)
        .sum::<f64>()
}

/// Three equal balls (mass m, radius R, moment of inertia I) in a row along x, touching:
/// [`chain_jacobian`] with three balls.
pub fn cradle_jacobian(radius: f64) -> DMatrix<f64> {
    chain_jacobian(3, radius)
}

/// `n` balls (radius R) in a row along x, touching. Coordinates
/// u = (x1, y1, ω1, x2, y2, ω2, …). Contact j is between ball j (body A) and ball j + 1 (body
/// B): the normal points out of B's surface towards A, n = −x, and t = (n rotated by +90°) =
/// −y; the relative velocity of the contact points is (u_A + ω_A × r_A) − (u_B + ω_B × r_B)
/// with r_A = +R x, r_B = −R x (ω × r = ω (−r_y, r_x)).
pub fn chain_jacobian(balls: usize, radius: f64) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(2 * (balls - 1), 3 * balls);
    let n = [-1.0, 0.0];
    let t = [0.0, -1.0];
    for c in 0..balls - 1 {
        let (a, b) = (3 * c, 3 * (c + 1));
        // Velocity of A's contact point: (x_A − ω_A·0, y_A + ω_A R); of B's: (x_B, y_B − ω_B R).
        for (row, dir) in [(2 * c, t), (2 * c + 1, n)] {
            j[(row, a)] += dir[0];
            j[(row, a + 1)] += dir[1];
            j[(row, a + 2)] += dir[1] * radius;
            j[(row, b)] -= dir[0];
            j[(row, b + 1)] -= dir[1];
            j[(row, b + 2)] -= dir[1] * (-radius);
        }
    }
    j
}

/// A uniform rod (mass m, length l, I = m l²/12) lying flat along x, u = (v_x, v_y, ω); its
/// ends r = (∓l/2, 0) touch the floor (t = x, n = y): v_t = v_x − ω r_y = v_x,
/// v_n = v_y + ω r_x. Four rows, three degrees of freedom.
pub fn rod_jacobian(l: f64) -> DMatrix<f64> {
    DMatrix::from_row_slice(
        4,
        3,
        &[
            1.0,
            0.0,
            0.0,
            0.0,
            1.0,
            -0.5 * l,
            1.0,
            0.0,
            0.0,
            0.0,
            1.0,
            0.5 * l,
        ],
    )
}

/// A random one-contact planar problem (W positive definite, some with W_tn = 0, v_t = 0,
/// μ = 0 or 2, e = 0 or 1).
pub fn random_one(rng: &mut SplitMix64) -> ContactProblem {
    random_planar(rng, -2.0)
}

/// [`random_one`] with the regularising `δ` of `W`'s Cholesky factors drawn from
/// `10^least … 1` (a smaller `least`: more nearly singular `W`).
pub fn random_planar(rng: &mut SplitMix64, least: f64) -> ContactProblem {
    loop {
        let l11 = rng.decades(-1.0, 1.0);
        let l22 = rng.decades(-1.0, 1.0);
        let l21 = if rng.unit() < 0.1 {
            0.0
        } else {
            rng.range(-3.0, 3.0)
        };
        let delta = rng.decades(least, 0.0);
        let (a, b, c) = (l11 * l11 + delta, l11 * l21, l21 * l21 + l22 * l22 + delta);
        let vt = if rng.unit() < 0.05 {
            0.0
        } else {
            rng.range(-2.0, 2.0)
        };
        let vn = -rng.decades(-1.0, 1.0);
        let mu = match rng.next_u64() % 20 {
            0 => 0.0,
            1 => 2.0,
            _ => rng.range(0.0, 2.0),
        };
        let e = match rng.next_u64() % 20 {
            0 => 0.0,
            1 => 1.0,
            _ => rng.unit(),
        };
        if let Ok(p) = ContactProblem::from_entries(a, b, c, vt, vn, mu, e) {
            return p;
        }
    }
}

/// A random problem with K contacts and the numbers it was built from.
pub struct Random {
    pub problem: MultiProblem,
    pub w: DMatrix<f64>,
    pub v: DVector<f64>,
    pub mu: Vec<f64>,
    /// Newton's targets max(−e v_n⁻, 0).
    pub b: Vec<f64>,
}

/// A random problem with `k` contacts: `W = J M⁻¹ Jᵀ` of random bodies (singular when the
/// contacts outnumber the degrees of freedom, 30% of them), `v = J u`.
pub fn random_multi(rng: &mut SplitMix64, k: usize) -> Random {
    loop {
        let dof = if rng.unit() < 0.3 {
            // Fewer degrees of freedom than contact rows: W singular.
            (k + 1 + (rng.next_u64() as usize) % (k - 1).max(1))
                .min(2 * k - 1)
                .max(2)
        } else {
            2 * k + (rng.next_u64() as usize) % 4
        };
        let j = DMatrix::from_fn(2 * k, dof, |_, _| rng.range(-1.0, 1.0));
        let masses: Vec<f64> = (0..dof).map(|_| rng.decades(-1.0, 1.0)).collect();
        let u = DVector::from_fn(dof, |_, _| rng.range(-1.0, 1.0));
        let (w, v) = contact_space(&j, &masses, &u);
        if (0..k).all(|c| v[2 * c + 1] >= 0.0) {
            continue;
        }
        let mu: Vec<f64> = (0..k)
            .map(|_| match rng.next_u64() % 6 {
                0 => 0.0,
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
        let Ok(problem) = MultiProblem::new(w.clone(), &v, &mu, &e) else {
            continue;
        };
        let v = problem.velocity().clone();
        let b = (0..k).map(|c| (-e[c] * v[2 * c + 1]).max(0.0)).collect();
        let asym = (&w - w.transpose()).amax();
        assert!(asym <= 1e-12 * w.amax());
        return Random {
            w: problem.w().clone(),
            problem,
            v,
            mu,
            b,
        };
    }
}

/// The problem as Rust literals (for a failure message).
pub fn dump(r: &Random) -> String {
    let k = r.problem.contacts();
    let upper: Vec<String> = (0..2 * k)
        .flat_map(|i| (i..2 * k).map(move |j| (i, j)))
        .map(|(i, j)| format!("{:e}", r.problem.w()[(i, j)]))
        .collect();
    let v: Vec<String> = r.v.iter().map(|x| format!("{x:e}")).collect();
    let mu: Vec<String> = r.mu.iter().map(|x| format!("{x:e}")).collect();
    let e: Vec<String> = (0..k)
        .map(|c| format!("{:e}", r.problem.restitution(c)))
        .collect();
    format!(
        "--contacts {k} --w {} --v {} --friction {} --restitution {}",
        upper.join(","),
        v.join(","),
        mu.join(","),
        e.join(",")
    )
}

/// Per-contact vectors as one contact-major vector.
pub fn flat(x: &[Vec2]) -> DVector<f64> {
    DVector::from_iterator(2 * x.len(), x.iter().flat_map(|y| [y.x, y.y]))
}

/// The problem of independent contacts: `W` block-diagonal with each one-contact problem's
/// `W`, and their velocities and coefficients in order.
pub fn block_diagonal(ones: &[ContactProblem]) -> MultiProblem {
    let k = ones.len();
    let mut w = DMatrix::zeros(2 * k, 2 * k);
    let mut v = Vec::new();
    let (mut mu, mut e) = (Vec::new(), Vec::new());
    for (j, p) in ones.iter().enumerate() {
        let b = p.w();
        for r in 0..2 {
            for c in 0..2 {
                w[(2 * j + r, 2 * j + c)] = b[(r, c)];
            }
        }
        v.extend([p.velocity().x, p.velocity().y]);
        mu.push(p.friction());
        e.push(p.restitution());
    }
    MultiProblem::new(w, &v, &mu, &e).unwrap()
}

/// A random spatial contact space with `k` contacts: `W = J M⁻¹ Jᵀ` of random bodies (`3K − 2`
/// degrees of freedom for 30% of them: `W` singular) and `v = J u`; `None` when no contact
/// approaches.
pub fn random_spatial_space(rng: &mut SplitMix64, k: usize) -> Option<(DMatrix<f64>, Vec<f64>)> {
    let dof = if rng.unit() < 0.3 {
        3 * k - 2
    } else {
        3 * k + 2
    };
    let j = DMatrix::from_fn(3 * k, dof, |_, _| rng.range(-1.0, 1.0));
    let masses: Vec<f64> = (0..dof).map(|_| rng.decades(-1.0, 1.0)).collect();
    let u = DVector::from_fn(dof, |_, _| rng.range(-1.0, 1.0));
    let (w, v) = contact_space(&j, &masses, &u);
    (0..k).any(|c| v[3 * c + 2] < 0.0).then_some((w, v))
}

/// Asserts that an `lcp` solution of the spatial problem `p` meets the conditions to `1e-12`
/// of the velocity scale, with `v⁺ = v⁻ + W p` recomputed here: the reported velocities, `p_n ≥ 0`, the cone, Newton's target with complementarity, a slip's
/// impulse on the cone's edge against the slip, and `ΔT = ½ (v⁻ + v⁺)·p`. The tolerances are
/// relative to the impulses' and friction's scale, so they hold at any `μ`.
pub fn assert_spatial_lcp_solution(
    p: &impax::multi::spatial::MultiProblem,
    s: &impax::multi::spatial::LcpSolution,
    label: &str,
) {
    let k = p.contacts();
    let flat = DVector::from_iterator(3 * k, s.impulses.iter().flat_map(|x| [x.x, x.y, x.z]));
    let v0 = p.velocity();
    let after = v0 + p.w() * &flat;
    let scale = v0.amax() + (p.w().abs() * flat.abs()).amax();
    let tol = 1e-12 * scale;
    for c in 0..k {
        let mu = p.friction(c);
        let pc = s.impulses[c];
        let vc = impax::math::Vec3::new(after[3 * c], after[3 * c + 1], after[3 * c + 2]);
        let target = (-p.restitution(c) * v0[3 * c + 2]).max(0.0);
        assert!(
            (vc - s.velocities_after[c]).amax() <= tol,
            "{label}: reported v⁺"
        );
        assert!(pc.z >= 0.0, "{label}: p_n < 0");
        let pt = pc.x.hypot(pc.y);
        assert!(
            pt <= mu * pc.z * (1.0 + 1e-12) + 1e-300,
            "{label}: outside the cone"
        );
        assert!(vc.z >= target - tol, "{label}: short of Newton's target");
        if pc.z > 0.0 {
            assert!((vc.z - target).abs() <= tol, "{label}: complementarity");
        }
        if vc.x.hypot(vc.y) > tol {
            // Slip: friction opposes the slip and is on the cone's edge.
            assert!(
                (pt - mu * pc.z).abs() <= 1e-12 * mu * pc.z + tol,
                "{label}: a slip inside the cone"
            );
            let cross = pc.x * vc.y - pc.y * vc.x;
            assert!(
                cross.abs() <= 1e-11 * scale * pt.max(1e-300) + 1e-300,
                "{label}: friction not along the slip"
            );
            assert!(
                pc.x * vc.x + pc.y * vc.y <= tol * pt,
                "{label}: friction drives the slip"
            );
        }
    }
    let dt = 0.5 * (v0 + &after).dot(&flat);
    assert!(
        (dt - s.energy_change).abs() <= 1e-12 * scale * flat.amax(),
        "{label}: ΔT"
    );
}

/// `n` cases made by `make` in order (a random generator's sequence is kept), solved by
/// `solve` in parallel (rayon) a chunk at a time, and handed back in order with their
/// answers: a long randomized test then uses both cores whatever else runs.
pub fn solved_in_parallel<T: Send + Sync, R: Send>(
    n: usize,
    mut make: impl FnMut(usize) -> T,
    solve: impl Fn(&T) -> R + Sync,
) -> impl Iterator<Item = (T, R)> {
    use rayon::prelude::*;
    const CHUNK: usize = 1000;
    (0..n).step_by(CHUNK).flat_map(move |first| {
        let batch: Vec<T> = (first..n.min(first + CHUNK)).map(&mut make).collect();
        let answers: Vec<R> = batch.par_iter().map(&solve).collect();
        batch.into_iter().zip(answers)
    })
}
