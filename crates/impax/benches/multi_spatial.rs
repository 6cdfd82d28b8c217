//! Spatial impacts at several contacts: the built-in `box-flat` (a box landing flat on four
//! corners, spinning: `K = 4`, `W` 12 × 12 of rank 6) under `lzb`, `lcp` and `sequential`.
//!
//! Run: `cargo bench -p impax --bench multi_spatial`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use impax::multi::scenarios::BoxFlat;
use impax::multi::spatial;
use impax::LawId;

fn bench_box_flat(c: &mut Criterion) {
    // The built-in's defaults: m = 1, half-extents (0.5, 0.3, 0.2), v = (0, 0, −1), ω_z = 2,
    // μ = 0.3, e = 0.5 (the corners slip round the vertical, halt together and stick).
    let sc = BoxFlat::default().build().unwrap();
    let p = sc.impact.spatial_problem(&[0.3], &[0.5]).unwrap();
    let mut g = c.benchmark_group("box-flat");
    for law in [LawId::Lzb, LawId::Lcp, LawId::Sequential] {
        g.bench_with_input(BenchmarkId::from_parameter(law), &p, |b, p| {
            b.iter(|| black_box(spatial::resolve(law, black_box(p))))
        });
    }
    g.finish();
}

criterion_group!(benches, bench_box_flat);
criterion_main!(benches);
