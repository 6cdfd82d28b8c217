//! Robots: solo12 with a floating base (18 dof) — one foot impact from `(q, u)` to `u⁺` under
//! `energetic` (kinematics, CRBA, Cholesky, the contact-space problem, the Darboux–Keller
//! integration and `u⁺ = u⁻ + M⁻¹ Jᵀ p`; target ≤ 20 µs), and its parts: the mass matrix, the
//! bias forces. Run: `cargo bench -p impax --bench robots`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use impax::multibody::{
    bias_forces, crba, read_urdf, ContactSpec, Model, SpatialMechanismImpact, UrdfOptions,
    Workspace,
};
use impax::LawId;

fn solo12() -> Model {
    let text = include_str!("../tests/data/urdf/solo12.urdf");
    let mut options = UrdfOptions::default().floating_base(true);
    for foot in ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"] {
        options = options.contact(ContactSpec::new(foot));
    }
    read_urdf(text, &options).expect("solo12").model
}

/// A trotting solo12: base 0.25 m up, turned and tilted a little, the front-left foot coming
/// down while it slides forward.
fn state(model: &Model) -> (Vec<f64>, Vec<f64>) {
    let mut q = model.neutral();
    q[2] = 0.25;
    let (half, axis) = (0.1f64, [0.3f64, 0.2, 0.93]);
    let n = axis.iter().map(|a| a * a).sum::<f64>().sqrt();
    q[3] = half.cos();
    for k in 0..3 {
        q[4 + k] = half.sin() * axis[k] / n;
    }
    let legs = [
        [0.1, 0.7, -1.5],
        [-0.1, 0.8, -1.6],
        [0.05, -0.7, 1.4],
        [-0.05, -0.8, 1.5],
    ];
    for (l, leg) in legs.iter().enumerate() {
        q[7 + 3 * l..10 + 3 * l].copy_from_slice(leg);
    }
    let mut u = vec![0.0; model.nv()];
    u[..6].copy_from_slice(&[0.5, 0.1, -0.8, 0.2, -0.4, 0.3]);
    u[6..9].copy_from_slice(&[0.5, -2.0, 3.0]);
    (q, u)
}

fn bench(c: &mut Criterion) {
    let model = solo12();
    let (q, u) = state(&model);
    let imp = SpatialMechanismImpact::new(&model, &q, &u, 0).unwrap();
    assert!(imp.contact_velocity().z < 0.0, "the foot approaches");
    let mut ws = Some(Workspace::new(&model));
    let mut after = vec![0.0; model.nv()];
    c.bench_function("solo12 foot impact, energetic, (q, u) → u⁺", |b| {
        b.iter(|| {
            let imp = SpatialMechanismImpact::new_in(
                &model,
                black_box(&q),
                black_box(&u),
                0,
                ws.take().unwrap(),
            )
            .unwrap();
            let problem = imp.problem(0.8, 0.5).unwrap();
            let out = LawId::Energetic.resolve(&problem).unwrap();
            imp.velocities_after_into(out.impulse, &mut after);
            ws = Some(imp.into_workspace());
            black_box(&after);
        })
    });
    c.bench_function(
        "solo12 foot reduced to contact space, (q, u) → (W, v⁻)",
        |b| {
            b.iter(|| {
                let imp = SpatialMechanismImpact::new_in(
                    &model,
                    black_box(&q),
                    black_box(&u),
                    0,
                    ws.take().unwrap(),
                )
                .unwrap();
                black_box(imp.problem(0.8, 0.5).unwrap());
                ws = Some(imp.into_workspace());
            })
        },
    );
    let problem = imp.problem(0.8, 0.5).unwrap();
    c.bench_function("solo12 foot problem, energetic law alone", |b| {
        b.iter(|| LawId::Energetic.resolve(black_box(&problem)).unwrap())
    });
    let mut ws = Workspace::new(&model);
    c.bench_function("solo12 kinematics + CRBA (18 dof)", |b| {
        b.iter(|| {
            ws.update(&model, black_box(&q)).unwrap();
            black_box(crba(&model, &mut ws)[(0, 0)]);
        })
    });
    let mut bias = vec![0.0; model.nv()];
    c.bench_function("solo12 bias forces (RNEA)", |b| {
        b.iter(|| {
            bias_forces(&model, &mut ws, black_box(&u), &mut bias);
            black_box(&bias);
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
