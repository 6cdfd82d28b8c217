//! Quick check: planar problems embedded in 3D against the planar closed form.
use impax::math::SplitMix64;
use impax::{planar::ContactProblem, spatial, LawId};

fn main() {
    let mut rng = SplitMix64(12345u64);
    let mut next = move || rng.unit();
    let mut worst = 0.0f64;
    let mut steps = 0u64;
    let n = 2000;
    for _ in 0..n {
        let (l11, l21, l22) = (0.2 + 2.0 * next(), 2.0 * next() - 1.0, 0.2 + 2.0 * next());
        let (a, b, c) = (l11 * l11, l11 * l21, l21 * l21 + l22 * l22);
        let p = match ContactProblem::from_entries(
            a,
            b,
            c,
            4.0 * next() - 2.0,
            -0.05 - 2.0 * next(),
            2.0 * next(),
            next(),
        ) {
            Ok(p) => p,
            Err(_) => continue,
        };
        let p3 = spatial::ContactProblem::from_planar(&p, 1.0 + next()).unwrap();
        for law in [
            LawId::Newton,
            LawId::Poisson,
            LawId::Energetic,
            LawId::Whittaker,
            LawId::Brach,
        ] {
            let o2 = law.resolve(&p);
            let o3 = law.resolve(&p3);
            match (o2, o3) {
                (Ok(x), Ok(y)) => {
                    let s = x.impulse.norm().max(1e-300);
                    let d = ((x.impulse.x - y.impulse.x)
                        .abs()
                        .max((x.impulse.y - y.impulse.z).abs())
                        + y.impulse.y.abs())
                        / s;
                    if d > worst {
                        worst = d;
                        if d > 1e-9 {
                            println!(
                                "{law} dev {d:e} {p:?}\n  2d {:?} {}\n  3d {:?} {}",
                                x.impulse,
                                x.phases.summary(),
                                y.impulse,
                                y.phases.summary()
                            );
                        }
                    }
                    if let impax::spatial::LawDetail::DarbouxKeller { steps: s, .. } = y.detail {
                        steps += s as u64;
                    }
                }
                (Err(_), Err(_)) => {}
                (a, b) => println!(
                    "{law} mismatch {:?} vs {:?}",
                    a.map(|o| o.impulse),
                    b.map(|o| o.impulse)
                ),
            }
        }
    }
    println!(
        "worst relative deviation {worst:e}; mean steps {}",
        steps as f64 / (3 * n) as f64
    );
}
