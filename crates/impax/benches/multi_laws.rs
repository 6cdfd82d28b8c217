//! Planar impacts at several contacts: `lcp` (K = 2 and K = 4), `sequential` and `lzb`
//! (K = 2) on a rod landing flat, `lzb` on the same rod landing turning, and all on fixed sets
//! of random problems (`W = J M⁻¹ Jᵀ` of random bodies, `v = J u`, random friction and
//! restitution).
//!
//! Run: `cargo bench -p impax --bench multi_laws`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use impax::math::SplitMix64;
use impax::multi::MultiProblem;
use impax::LawId;
use nalgebra::{DMatrix, DVector};

/// A uniform rod (m = 1, l = 1) lying flat, landing on both ends at v_y = −1 (rank-3 `W`).
fn rod(mu: f64, e: f64) -> MultiProblem {
    MultiProblem::from_upper(
        2,
        &[1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0],
        &[0.0, -1.0, 0.0, -1.0],
        &[mu],
        &[e],
    )
    .unwrap()
}

/// The same rod landing turning, its ends approaching at 1 and 1.5: the contacts do not
/// load in fixed proportions, and `lzb` integrates the whole path (the level landing is taken
/// in closed form).
fn rod_turning(mu: f64, e: f64) -> MultiProblem {
    MultiProblem::from_upper(
        2,
        &[1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0],
        &[0.0, -1.0, 0.0, -1.5],
        &[mu],
        &[e],
    )
    .unwrap()
}

/// Deterministic random problems with `k` contacts: `W = J M⁻¹ Jᵀ` of random bodies with
/// `2k + 1` degrees of freedom (positive definite), `v = J u`, at least one contact
/// approaching.
fn random_problems(k: usize, n: usize) -> Vec<MultiProblem> {
    let mut rng = SplitMix64(0x6d75_6c74_6962_656e);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let dof = 2 * k + 1;
        let j = DMatrix::from_fn(2 * k, dof, |_, _| rng.range(-1.0, 1.0));
        let minv =
            DMatrix::from_diagonal(&DVector::from_fn(dof, |_, _| 1.0 / rng.decades(-0.5, 0.5)));
        let u = DVector::from_fn(dof, |_, _| rng.range(-1.0, 1.0));
        let w = &j * minv * j.transpose();
        let v: Vec<f64> = (&j * u).iter().copied().collect();
        let mu: Vec<f64> = (0..k).map(|_| rng.range(0.0, 1.0)).collect();
        let e: Vec<f64> = (0..k).map(|_| rng.range(0.2, 1.0)).collect();
        if let Ok(p) = MultiProblem::new(w, &v, &mu, &e) {
            out.push(p);
        }
    }
    out
}

fn bench_multi(c: &mut Criterion) {
    let r = rod(0.3, 0.5);
    let mut g = c.benchmark_group("rod-flat");
    for law in LawId::MULTI_CONTACT {
        g.bench_with_input(BenchmarkId::from_parameter(law), &r, |b, p| {
            b.iter(|| black_box(law.resolve(black_box(p))))
        });
    }
    g.finish();

    let r = rod_turning(0.3, 0.5);
    let mut g = c.benchmark_group("rod-turning");
    g.bench_with_input(BenchmarkId::from_parameter(LawId::Lzb), &r, |b, p| {
        b.iter(|| black_box(LawId::Lzb.resolve(black_box(p))))
    });
    g.finish();

    for (k, laws) in [
        (2, &LawId::MULTI_CONTACT[..]),
        (4, &[LawId::Lcp, LawId::Sequential][..]),
    ] {
        let problems = random_problems(k, 256);
        let mut g = c.benchmark_group(format!("random256-k{k}"));
        g.throughput(Throughput::Elements(problems.len() as u64));
        for &law in laws {
            g.bench_with_input(BenchmarkId::from_parameter(law), &problems, |b, ps| {
                b.iter(|| {
                    let mut acc = 0.0;
                    for p in ps {
                        if let Ok(Ok(o)) = law.resolve(black_box(p)) {
                            acc += o.energy_change;
                        }
                    }
                    black_box(acc)
                })
            });
        }
        g.finish();
    }
}

criterion_group!(benches, bench_multi);
criterion_main!(benches);
