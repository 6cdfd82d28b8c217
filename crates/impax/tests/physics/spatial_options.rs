//! The tolerance option of the spatial Darboux–Keller integration
//! (`LawId::resolve_with(problem, &Options::default().rtol(rtol))`).
//!
//! On 500 random problems (`W = A Aᵀ + 0.05 I` with `A` uniform in `[−1, 1]`, every slip
//! direction, `μ ∈ [0, 1.5]`, `e ∈ [0, 1]`), for `newton`, `poisson` and `energetic`:
//! * the default tolerance agrees with a ten times tighter one to 1e-10 of `|p|`;
//! * a loose tolerance (1e-7) takes no more steps than the default and still agrees to 1e-5;
//! * `rtol = NaN` gives the default result bit for bit.

use impax::law::Options;
use impax::math::SplitMix64;
use impax::spatial::{ContactProblem, LawDetail};
use impax::LawId;

fn problems(n: usize) -> Vec<ContactProblem> {
    let mut rng = SplitMix64(0x5EED_0003);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let a: [f64; 9] = std::array::from_fn(|_| rng.range(-1.0, 1.0));
        let w = |i: usize, j: usize| {
            (0..3).map(|k| a[3 * i + k] * a[3 * j + k]).sum::<f64>()
                + if i == j { 0.05 } else { 0.0 }
        };
        let angle = rng.range(0.0, std::f64::consts::TAU);
        let speed = rng.range(0.0, 2.0);
        let v = [
            speed * angle.cos(),
            speed * angle.sin(),
            rng.range(-2.0, -0.1),
        ];
        let mu = rng.range(0.0, 1.5);
        let e = rng.unit();
        if let Ok(p) = ContactProblem::from_upper(
            [w(0, 0), w(0, 1), w(0, 2), w(1, 1), w(1, 2), w(2, 2)],
            v,
            mu,
            e,
        ) {
            out.push(p);
        }
    }
    out
}

fn steps(d: &LawDetail) -> u32 {
    match d {
        LawDetail::DarbouxKeller { steps, .. } => *steps,
        _ => 0,
    }
}

#[test]
fn the_tolerance_option_converges_and_trades_steps_for_accuracy() {
    let fine = Options::default().rtol(1e-13);
    let loose = Options::default().rtol(1e-7);
    let nan = Options::default().rtol(f64::NAN);
    let (mut worst_default, mut worst_loose) = (0.0f64, 0.0f64);
    let (mut steps_default, mut steps_loose, mut compared) = (0u64, 0u64, 0usize);
    for p in problems(500) {
        for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
            let (Ok(d), Ok(f), Ok(l), Ok(n)) = (
                law.resolve(&p),
                law.resolve_with(&p, &fine),
                law.resolve_with(&p, &loose),
                law.resolve_with(&p, &nan),
            ) else {
                continue;
            };
            assert_eq!(
                d, n,
                "{law}: NaN tolerance differs from the default for {p:?}"
            );
            let scale = f.impulse.norm().max(f64::MIN_POSITIVE);
            worst_default = worst_default.max((d.impulse - f.impulse).norm() / scale);
            worst_loose = worst_loose.max((l.impulse - f.impulse).norm() / scale);
            steps_default += u64::from(steps(&d.detail));
            steps_loose += u64::from(steps(&l.detail));
            compared += 1;
        }
    }
    eprintln!(
        "spatial options: {compared} resolutions; default vs 1e-13 {worst_default:.3e}, \
         1e-7 vs 1e-13 {worst_loose:.3e}; steps default {steps_default}, loose {steps_loose}"
    );
    assert!(compared > 1_000);
    assert!(
        worst_default <= 1e-10,
        "default tolerance off by {worst_default:e}"
    );
    assert!(
        worst_loose <= 1e-5,
        "loose tolerance off by {worst_loose:e}"
    );
    assert!(steps_loose <= steps_default);
}
