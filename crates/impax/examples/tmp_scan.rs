use impax::spatial::{ContactProblem3, Phase3Kind};
use impax::LawId;
fn main() {
    let mut st = 0x9e3779b97f4a7c15u64;
    let mut rnd = || {
        st ^= st << 13;
        st ^= st >> 7;
        st ^= st << 17;
        (st >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut found = Vec::new();
    for _ in 0..20000 {
        let a = 0.5 + 2.0 * rnd();
        let c = 0.5 + 2.0 * rnd();
        let b = (2.0 * rnd() - 1.0) * 0.8 * (a * c).sqrt();
        let w1 = 2.0 * rnd() - 1.0;
        let w2 = 2.0 * rnd() - 1.0;
        let wnn = 0.5 + (c * w1 * w1 - 2.0 * b * w1 * w2 + a * w2 * w2) / (a * c - b * b) + rnd();
        let v = [2.0 * rnd() - 1.0, 2.0 * rnd() - 1.0, -1.0];
        let mu = 0.1 + 0.8 * rnd();
        let Ok(p) = ContactProblem3::from_upper([a, b, w1, c, w2, wnn], v, mu, 0.7) else {
            continue;
        };
        let Ok(o) = LawId::Energetic.resolve3(&p) else {
            continue;
        };
        let ph = o.phases.as_slice();
        let resumed = ph
            .iter()
            .any(|x| matches!(x.kind, Phase3Kind::Resumed { .. }));
        if !resumed {
            continue;
        }
        let turn = match ph[0].kind {
            Phase3Kind::Slip { from, to } => {
                let d = (to - from).abs();
                d.min(std::f64::consts::TAU - d)
            }
            _ => 0.0,
        };
        let t = std::time::Instant::now();
        for _ in 0..300 {
            let _ = LawId::Energetic.resolve3(std::hint::black_box(&p));
        }
        let us = t.elapsed().as_secs_f64() / 300.0 * 1e6;
        found.push((
            us,
            turn.to_degrees(),
            [a, b, w1, c, w2, wnn],
            v,
            mu,
            o.phases.summary(),
        ));
    }
    found.sort_by(|x, y| x.0.total_cmp(&y.0));
    println!("{} resumption cases", found.len());
    let n = found.len();
    for i in [0, n / 10, n / 4, n / 2, 3 * n / 4, 9 * n / 10, n - 1] {
        let f = &found[i];
        println!(
            "{:>5.1}% {:.2} µs turn {:.1}° w {:?} v {:?} mu {:.3} {}",
            100.0 * i as f64 / n as f64,
            f.0,
            f.1,
            f.2,
            f.3,
            f.4,
            f.5
        );
    }
    let swirl: Vec<_> = found.iter().filter(|f| f.1 > 20.0).collect();
    println!(
        "{} with turn > 20°; median {:.2} µs",
        swirl.len(),
        swirl[swirl.len() / 2].0
    );
    let f = swirl[swirl.len() / 2];
    println!(
        "median swirl case: {:.2} µs turn {:.1}° w {:?} v {:?} mu {:.3} {}",
        f.0, f.1, f.2, f.3, f.4, f.5
    );
}
