use impax::math::{Mat3, SplitMix64, Vec3};
use impax::planar::{ContactProblem, Verdict};
use impax::spatial;
use impax::LawId;
fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .map_or(1_000_000, |s| s.parse().unwrap());
    let mut rng = SplitMix64(7);
    let mut bad = [0usize; 9];
    let laws = [
        LawId::Energetic,
        LawId::Poisson,
        LawId::Newton,
        LawId::Lcp,
        LawId::Brach,
    ];
    for _ in 0..n {
        let l11 = rng.decades(-3.0, 3.0);
        let l22 = rng.decades(-4.0, 3.0);
        let l21 = rng.range(-1.0, 1.0) * rng.decades(-3.0, 3.0);
        let d = if rng.unit() < 0.5 {
            0.0
        } else {
            rng.decades(-6.0, 0.0)
        };
        let (a, b, c) = (l11 * l11 + d, l11 * l21, l21 * l21 + l22 * l22 + d);
        let vt = if rng.unit() < 0.1 {
            0.0
        } else {
            rng.range(-2.0, 2.0)
        };
        let vn = -rng.decades(-3.0, 0.3);
        let mu = if rng.unit() < 0.1 {
            0.0
        } else {
            rng.range(0.0, 3.0)
        };
        let e = if rng.unit() < 0.1 {
            1.0
        } else if rng.unit() < 0.1 {
            0.0
        } else {
            rng.unit()
        };
        let Ok(p) = ContactProblem::from_entries(a, b, c, vt, vn, mu, e) else {
            continue;
        };
        for (i, law) in laws.iter().enumerate() {
            if let Ok(o) = law.resolve(&p) {
                if o.verdict == Verdict::EnergyGained && i < 2 {
                    bad[i] += 1;
                    if bad[i] < 4 {
                        eprintln!(
                            "{law} {p:?} dT={:e} E={:e}",
                            o.energy_change,
                            p.approach_energy()
                        );
                    }
                }
            }
        }
    }
    // spatial
    let ns = n / 20;
    for _ in 0..ns {
        let mut m = Mat3::zeros();
        for i in 0..3 {
            for j in 0..=i {
                m[(i, j)] = rng.range(-1.0, 1.0) * rng.decades(-2.0, 2.0);
            }
        }
        let w = m * m.transpose() + Mat3::identity() * rng.decades(-6.0, 0.0);
        let v = Vec3::new(
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
            -rng.decades(-2.0, 0.3),
        );
        let mu = rng.range(0.0, 2.0);
        let e = rng.unit();
        let Ok(p) = spatial::ContactProblem::new(w, v, mu, e) else {
            continue;
        };
        for (i, law) in [LawId::Energetic, LawId::Poisson].iter().enumerate() {
            if let Ok(o) = law.resolve(&p) {
                if o.verdict == Verdict::EnergyGained {
                    bad[4 + i] += 1;
                    if bad[4 + i] < 4 {
                        eprintln!("3d {law} {p:?} dT={:e}", o.energy_change);
                    }
                }
            }
        }
    }
    println!("planar energetic gains {}, poisson {}; spatial energetic {}, poisson {} (n = {n}, spatial {ns})", bad[0], bad[1], bad[4], bad[5]);
}
