//! Tight loop over one spatial benchmark case for profiling (instruction counts under
//! `valgrind --tool=callgrind`): `cargo run --release --example spatial_hot -- swirl-stick 1000 [rtol]`.
use impax::law::Options;
use impax::spatial::{ContactProblem, LawDetail};
use impax::LawId;
use std::hint::black_box;

fn case(name: &str) -> ContactProblem {
    let w = [2.0, 0.6, 0.3, 1.0, -0.2, 1.5];
    let (w, v, mu, e) = match name {
        "swirl-stick" => (w, [0.3, 0.8, -1.0], 0.8, 0.7),
        "halt-resume" => (
            [1.64, -0.82, -0.35, 1.62, -0.41, 0.87],
            [0.38, 0.96, -1.0],
            0.53,
            0.7,
        ),
        "near-zero-swirl" => ([1.0, 0.3, 0.8, 2.0, -0.5, 1.5], [-0.4, 0.3, -1.0], 0.3, 0.7),
        "strong-swirl" => (
            [1.16, 0.18, -0.23, 0.75, 0.47, 0.91],
            [0.6, -0.25, -1.0],
            0.17,
            0.7,
        ),
        "swirl-slip" => (w, [2.0, -1.5, -1.0], 0.3, 0.7),
        "sphere" => ([3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [0.5, 0.2, -0.866], 0.4, 0.7),
        _ => panic!(
            "cases: swirl-stick, halt-resume, near-zero-swirl, strong-swirl, swirl-slip, sphere"
        ),
    };
    ContactProblem::from_upper(w, v, mu, e).expect("valid")
}

fn main() {
    let mut args = std::env::args().skip(1);
    let name = args.next().unwrap_or_else(|| "swirl-stick".into());
    let n: usize = args.next().map_or(1000, |s| s.parse().expect("a count"));
    let opts = Options::default().rtol(
        args.next()
            .map_or(Options::DEFAULT_RTOL, |s| s.parse().expect("a tolerance")),
    );
    let p = case(&name);
    let o = LawId::Energetic.resolve_with(&p, &opts).expect("resolves");
    let steps = match o.detail {
        LawDetail::DarbouxKeller { steps, .. } => steps,
        _ => 0,
    };
    let t = std::time::Instant::now();
    let mut acc = 0.0;
    for _ in 0..n {
        if let Ok(o) = LawId::Energetic.resolve_with(black_box(&p), &opts) {
            acc += o.energy_change;
        }
    }
    let dt = t.elapsed().as_secs_f64();
    println!(
        "{name}: {} ({steps} steps), {:.2} µs per impact, p = {:.15e} {:.15e} {:.15e} ({acc:.3})",
        o.phases.summary(),
        dt / n as f64 * 1e6,
        o.impulse.x,
        o.impulse.y,
        o.impulse.z
    );
}
