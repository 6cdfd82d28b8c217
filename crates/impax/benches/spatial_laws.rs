//! Spatial Darboux–Keller impacts (energetic): one with swirl then stick, one whose slip
//! halts and resumes at once along the centrifugal ray, one whose slip swings through a
//! near-zero and leaves along a centrifugal ray, one whose slip turns 120° throughout, one
//! slipping throughout with a mild swirl (4°), and the sphere (no swirl; straight run in
//! closed form); and the engine rule `lcp` on the same problems.
//! Run: `cargo bench -p impax --bench spatial_laws`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use impax::spatial::{ContactProblem, LawDetail};
use impax::LawId;

/// The benchmark cases, also printed with their phases and step counts.
pub fn cases() -> Vec<(&'static str, ContactProblem)> {
    let w = [2.0, 0.6, 0.3, 1.0, -0.2, 1.5];
    vec![
        (
            "swirl-stick",
            ContactProblem::from_upper(w, [0.3, 0.8, -1.0], 0.8, 0.7).unwrap(),
        ),
        (
            "halt-resume",
            ContactProblem::from_upper(
                [1.64, -0.82, -0.35, 1.62, -0.41, 0.87],
                [0.38, 0.96, -1.0],
                0.53,
                0.7,
            )
            .unwrap(),
        ),
        (
            "near-zero-swirl",
            ContactProblem::from_upper(
                [1.0, 0.3, 0.8, 2.0, -0.5, 1.5],
                [-0.4, 0.3, -1.0],
                0.3,
                0.7,
            )
            .unwrap(),
        ),
        (
            "strong-swirl",
            ContactProblem::from_upper(
                [1.16, 0.18, -0.23, 0.75, 0.47, 0.91],
                [0.6, -0.25, -1.0],
                0.17,
                0.7,
            )
            .unwrap(),
        ),
        (
            "swirl-slip",
            ContactProblem::from_upper(w, [2.0, -1.5, -1.0], 0.3, 0.7).unwrap(),
        ),
        (
            "sphere",
            ContactProblem::from_upper(
                [3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
                [0.5, 0.2, -0.866],
                0.4,
                0.7,
            )
            .unwrap(),
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("spatial-energetic");
    for (name, p) in cases() {
        let o = LawId::Energetic.resolve(&p).unwrap();
        let steps = match o.detail {
            LawDetail::DarbouxKeller { steps, .. } => steps,
            _ => 0,
        };
        eprintln!("{name}: {} ({steps} steps)", o.phases.summary());
        g.bench_function(name, |b| {
            b.iter(|| black_box(LawId::Energetic.resolve(black_box(&p))))
        });
    }
    g.finish();
    // The engine rule on the same problems: the slip-angle roots (256 samples, bisection).
    let mut g = c.benchmark_group("spatial-lcp");
    for (name, p) in cases() {
        g.bench_function(name, |b| {
            b.iter(|| black_box(LawId::Lcp.resolve(black_box(&p))))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
