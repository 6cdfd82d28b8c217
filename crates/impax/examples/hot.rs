//! Tight loop over one law for profiling: `cargo run --release --example hot -- energetic 10000000`.
use impax::{planar::ContactProblem, LawId};
use std::hint::black_box;

fn main() {
    let mut args = std::env::args().skip(1);
    let law: LawId = args
        .next()
        .unwrap_or_else(|| "energetic".into())
        .parse()
        .expect("a law id");
    let n: usize = args
        .next()
        .map_or(10_000_000, |s| s.parse().expect("a count"));
    let a = 30f64.to_radians();
    let p =
        ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).expect("valid");
    let t = std::time::Instant::now();
    let mut acc = 0.0;
    for _ in 0..n {
        if let Ok(o) = law.resolve(black_box(&p)) {
            acc += o.energy_change;
        }
    }
    let dt = t.elapsed().as_secs_f64();
    println!("{law}: {:.1} ns per impact ({acc:.3})", dt / n as f64 * 1e9);
}
