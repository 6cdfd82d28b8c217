//! Mechanisms and simulation: the automatic-differentiation dynamics of the double pendulum
//! (mass matrix, accelerations), one double-pendulum impact reduced to contact space and
//! resolved, a 10 s conserved-quantity run of the ring-pendulum, and a whole bouncing-ball
//! simulation with its accumulation of impacts. Run: `cargo bench -p impax --bench mechanisms`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use impax::mechanism::builtin::{DoublePendulum, RingPendulum};
use impax::mechanism::conserved::{track, TrackOptions};
use impax::mechanism::dynamics;
use impax::mechanism::impact::MechanismImpact;
use impax::simulation::{scenarios, simulate, SimulationOptions};
use impax::LawId;

fn bench(c: &mut Criterion) {
    let q = [30f64.to_radians(), 0.0];
    let u = [-1.0, 2.0];
    let dp = DoublePendulum::unit_at(q);
    c.bench_function("double-pendulum mass matrix", |b| {
        b.iter(|| dynamics::mass_matrix(black_box(&dp), black_box(&q)))
    });
    c.bench_function("double-pendulum accelerations", |b| {
        b.iter(|| dynamics::accelerations(black_box(&dp), black_box(&q), black_box(&u)))
    });
    c.bench_function("double-pendulum impact, energetic", |b| {
        b.iter(|| {
            let imp = MechanismImpact::new(black_box(&dp), &q, &u, 0).unwrap();
            imp.resolve(LawId::Energetic, 0.5, 0.5).unwrap()
        })
    });
    let mut group = c.benchmark_group("runs");
    group.sample_size(10);
    let ring = RingPendulum::new(1.0, 1.0, 1.0, 1.0, 9.81).unwrap();
    let symmetries = ring.symmetries();
    group.bench_function("ring-pendulum conserved, 10 s, 100 samples", |b| {
        let opts = TrackOptions {
            intervals: 100,
            ..TrackOptions::default()
        };
        b.iter(|| track(&ring, &[0.0, 0.5], &[0.5, 0.0], &symmetries, &[], opts).unwrap())
    });
    let ball = scenarios::bouncing_ball(1.0, 0.1, 1.0, 2.0, 0.5, 0.0, 9.81, false).unwrap();
    let opts = SimulationOptions::new(LawId::Energetic, 0.3, 0.8, 5.0);
    group.bench_function("bouncing-ball simulation, 5 s", |b| {
        b.iter(|| simulate(&ball.mechanism, &ball.q, &ball.u, &opts).unwrap())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
