//! One planar impact per law: the seed's sphere, and the mean over a fixed set of 1024
//! random problems (varied regimes: slip throughout, slip–stick, slip reversal).
//!
//! Run: `cargo bench -p impax --bench planar_laws`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use impax::math::SplitMix64;
use impax::planar::ContactProblem;
use impax::LawId;

fn seed() -> ContactProblem {
    let a = 30f64.to_radians();
    ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap()
}

/// Deterministic random problems (splitmix64).
fn random_problems(n: usize) -> Vec<ContactProblem> {
    let mut rng = SplitMix64(0x1234_5678_9abc_def0u64);
    let mut next = move || rng.unit();
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (l11, l21, l22) = (0.2 + 2.0 * next(), 2.0 * next() - 1.0, 0.2 + 2.0 * next());
        let (a, b, c) = (l11 * l11, l11 * l21, l21 * l21 + l22 * l22);
        let vt = 4.0 * next() - 2.0;
        let vn = -0.05 - 2.0 * next();
        if let Ok(p) = ContactProblem::from_entries(a, b, c, vt, vn, 2.0 * next(), next()) {
            out.push(p);
        }
    }
    out
}

fn bench_laws(c: &mut Criterion) {
    let s = seed();
    let mut g = c.benchmark_group("seed");
    for law in LawId::CONTACT_SPACE {
        g.bench_with_input(BenchmarkId::from_parameter(law), &s, |b, p| {
            b.iter(|| black_box(law.resolve(black_box(p))))
        });
    }
    g.finish();

    let problems = random_problems(1024);
    let mut g = c.benchmark_group("random1024");
    g.throughput(Throughput::Elements(problems.len() as u64));
    for law in LawId::CONTACT_SPACE {
        g.bench_with_input(BenchmarkId::from_parameter(law), &problems, |b, ps| {
            b.iter(|| {
                let mut acc = 0.0;
                for p in ps {
                    if let Ok(o) = law.resolve(black_box(p)) {
                        acc += o.energy_change;
                    }
                }
                black_box(acc)
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench_laws);
criterion_main!(benches);
