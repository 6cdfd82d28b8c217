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
