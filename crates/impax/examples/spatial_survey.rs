//! Cost of the spatial `energetic` law beyond the benchmark cases:
//!
//! * the mean over `N` random problems, each resolved once in a loop (`W_tt = R diag(d₁, d₂)
//!   Rᵀ` with `d ∈ [0.3, 2.3]` and any orientation, `w_tn` components in `±0.45`,
//!   `w_nn ∈ [0.5, 2.5]`, `v_t⁻ ∈ [−1, 1]²`, `v_n⁻ = −1`, `μ ∈ [0.05, 0.95]`, `e ∈ [0, 1]`;
//!   draws that are not positive definite are skipped), with how the slip ended;
//! * the cost per impact of the first `K` of them whose slip swirls strongly (slip
//!   throughout, turning 80° or more, `σ` never below `0.3 σ⁻` on the hodograph): median,
//!   90th percentile and largest.
//!
//! `cargo run --release -p impax --example spatial_survey -- [N] [K]` (defaults 4000 and 100;
//! `K = 0` skips the second part). For instruction counts, run it under
//! `valgrind --tool=callgrind` with `K = 0` and two values of `N`, and divide the difference.
use impax::math::SplitMix64;
use impax::spatial::{laws::hodograph, ContactProblem, PhaseKind};
use impax::LawId;
use std::f64::consts::{PI, TAU};
use std::hint::black_box;
use std::time::Instant;

/// A random problem from the generator described above, or `None` if the draw is not
/// positive definite.
fn draw(next: &mut impl FnMut() -> f64) -> Option<ContactProblem> {
    let (d1, d2) = (0.3 + 2.0 * next(), 0.3 + 2.0 * next());
    let (s, c) = (PI * next()).sin_cos();
    let w11 = d1 * c * c + d2 * s * s;
    let w22 = d1 * s * s + d2 * c * c;
    let w12 = (d1 - d2) * c * s;
    let (w13, w23) = (0.9 * (next() - 0.5), 0.9 * (next() - 0.5));
    let wnn = 0.5 + 2.0 * next();
    let v = [2.0 * next() - 1.0, 2.0 * next() - 1.0, -1.0];
    let (mu, e) = (0.05 + 0.9 * next(), next());
    ContactProblem::from_upper([w11, w12, w13, w22, w23, wnn], v, mu, e).ok()
}

/// Whether the energetic slip turns by 80° or more without a halt and without `σ` falling
/// below `0.3 σ⁻`.
fn swirls_strongly(p: &ContactProblem) -> bool {
    let Ok(o) = LawId::Energetic.resolve(p) else {
        return false;
    };
    let [phase] = o.phases.as_slice() else {
        return false;
    };
    let PhaseKind::Slip { from, to } = phase.kind else {
        return false;
    };
    let turn = (to - from).rem_euclid(TAU);
    if turn.min(TAU - turn) < 80f64.to_radians() {
        return false;
    }
    let Ok(path) = hodograph(p, LawId::Energetic, &impax::law::Options::default()) else {
        return false;
    };
    let sigma = |r: &[f64; 4]| r[1].hypot(r[2]);
    let s0 = path.first().map_or(0.0, sigma);
    path.iter().all(|r| sigma(r) >= 0.3 * s0)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(4000, |s| s.parse().expect("N, a count"));
    let k: usize = args.next().map_or(100, |s| s.parse().expect("K, a count"));
    let mut rng = SplitMix64(987_654_321u64);
    let mut next = move || rng.unit();
    let mut problems = Vec::with_capacity(n);
    while problems.len() < n {
        if let Some(p) = draw(&mut next) {
            problems.push(p);
        }
    }
    let start = Instant::now();
    let (mut failed, mut acc) = (0usize, 0.0);
    for p in &problems {
        match LawId::Energetic.resolve(black_box(p)) {
            Ok(o) => acc += o.energy_change,
            Err(_) => failed += 1,
        }
    }
    let mean = start.elapsed().as_secs_f64() / n.max(1) as f64;
    let (mut slip, mut stick, mut resumed) = (0, 0, 0);
    for p in &problems {
        if let Ok(o) = LawId::Energetic.resolve(p) {
            match o.phases.as_slice().last().map(|ph| ph.kind) {
                Some(PhaseKind::Stick) => stick += 1,
                Some(PhaseKind::Resumed { .. }) => resumed += 1,
                _ => slip += 1,
            }
        }
    }
    println!(
        "{n} random problems: {:.2} µs per impact on average ({slip} slip throughout, \
         {stick} halt → stick, {resumed} halt → resumed slip, {failed} failed; ΣΔT {acc:.6})",
        mean * 1e6
    );
    if k == 0 {
        return;
    }
    let mut times = Vec::with_capacity(k);
    let mut tried = 0usize;
    while times.len() < k && tried < 1_000_000 {
        tried += 1;
        let Some(p) = draw(&mut next) else { continue };
        if !swirls_strongly(&p) {
            continue;
        }
        let reps = 5000;
        let start = Instant::now();
        for _ in 0..reps {
            black_box(LawId::Energetic.resolve(black_box(&p)).ok());
        }
        times.push(start.elapsed().as_secs_f64() / reps as f64 * 1e6);
    }
    times.sort_by(f64::total_cmp);
    let at = |q: f64| times[((times.len() - 1) as f64 * q).round() as usize];
    if times.is_empty() {
        println!("no strongly swirling problem among {tried} draws");
    } else {
        println!(
            "{} strongly swirling problems (of {tried} draws): median {:.2} µs, \
             90th percentile {:.2} µs, largest {:.2} µs",
            times.len(),
            at(0.5),
            at(0.9),
            at(1.0)
        );
    }
}
