//! The batch API (`impax::analysis`): one law over 4096 random problems, as validated
//! problems (`resolve_problems`) and as structure-of-arrays columns validated on the fly
//! (`resolve_columns`); and the parallel sweep driver over 2²⁰ seed-sphere points.
//!
//! Run: `cargo bench -p impax --bench batch`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use impax::analysis::{
    resolve_columns, resolve_problems, run_ordered, ImpactSummary, ProblemColumns, Tally,
};
use impax::math::SplitMix64;
use impax::planar::ContactProblem;
use impax::LawId;

/// Deterministic random problems (splitmix64), as in `planar_laws`.
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

fn bench_batch(c: &mut Criterion) {
    let problems = random_problems(4096);
    let col = |f: fn(&ContactProblem) -> f64| problems.iter().map(f).collect::<Vec<f64>>();
    let (wtt, wtn, wnn) = (col(|p| p.wtt()), col(|p| p.wtn()), col(|p| p.wnn()));
    let (vt, vn) = (col(|p| p.velocity().x), col(|p| p.velocity().y));
    let (mu, e) = (col(|p| p.friction()), col(|p| p.restitution()));
    let cols = ProblemColumns::new(&wtt, &wtn, &wnn, &vt, &vn, &mu, &e).unwrap();
    let mut out = vec![ImpactSummary::INVALID; problems.len()];

    let mut g = c.benchmark_group("batch_problems4096");
    g.throughput(Throughput::Elements(problems.len() as u64));
    for law in LawId::CONTACT_SPACE {
        g.bench_function(BenchmarkId::from_parameter(law), |b| {
            b.iter(|| {
                resolve_problems(law, black_box(&problems), &mut out).unwrap();
                black_box(out[0].energy_change)
            })
        });
    }
    g.finish();

    let mut g = c.benchmark_group("batch_columns4096");
    g.throughput(Throughput::Elements(problems.len() as u64));
    for law in [LawId::Whittaker, LawId::Energetic] {
        g.bench_function(BenchmarkId::from_parameter(law), |b| {
            b.iter(|| {
                resolve_columns(law, black_box(&cols), &mut out).unwrap();
                black_box(out[0].energy_change)
            })
        });
    }
    g.finish();

    // The driver: 2²⁰ seed-sphere points (α, γ grid), energetic, tallied, all threads.
    let n: u64 = 1 << 20;
    let mut g = c.benchmark_group("sweep_driver");
    g.throughput(Throughput::Elements(n));
    g.sample_size(10);
    g.bench_function("energetic_sphere_tally", |b| {
        b.iter(|| {
            let mut total = Tally::new();
            run_ordered(
                n,
                8192,
                |r| {
                    let mut ps = Vec::with_capacity((r.end - r.start) as usize);
                    for i in r {
                        let alpha = (i >> 10) as f64 * (1.5 / 1024.0);
                        let gamma = (i & 1023) as f64 * (6.0 / 1024.0) - 3.0;
                        let (s, co) = alpha.sin_cos();
                        if let Ok(p) =
                            ContactProblem::from_entries(3.5, 0.0, 1.0, s + gamma, -co, 0.4, 0.7)
                        {
                            ps.push(p);
                        }
                    }
                    let mut out = vec![ImpactSummary::INVALID; ps.len()];
                    resolve_problems(LawId::Energetic, &ps, &mut out).unwrap();
                    let mut t = Tally::new();
                    for s in &out {
                        t.add(s, 0.5);
                    }
                    t
                },
                |t| {
                    total.merge(&t);
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
            black_box(total.total)
        })
    });
    g.finish();
}

criterion_group!(benches, bench_batch);
criterion_main!(benches);
