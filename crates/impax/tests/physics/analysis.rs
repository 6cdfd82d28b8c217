//! `impax::analysis`: the batch API equals single calls, the sweep driver is ordered and
//! independent of the thread count, grids are exact, and the eq. 13 threshold of paper A
//! agrees with the engine's own sign change of Whittaker's ΔT.

use impax::analysis::{
    for_each_brief, for_each_resolution, resolve_columns, resolve_problems, run_ordered,
    run_ordered_waves, whittaker_sphere_energy_ratio, whittaker_sphere_thresholds, Axis, Grid,
    ImpactSummary, ProblemColumns, RandomSamples, SampleRange, Sequence, Space, Status, Tally,
};
use impax::math::SplitMix64;
use impax::paper::liu2012::Seed;
use impax::planar::{ContactProblem, OutcomeBrief, Verdict};
use impax::LawId;

fn random_problems(n: usize, seed: u64) -> Vec<ContactProblem> {
    let mut rng = SplitMix64(seed);
    let mut next = move || rng.unit();
    let mut out = Vec::new();
    while out.len() < n {
        let (l11, l21, l22) = (0.2 + 2.0 * next(), 2.0 * next() - 1.0, 0.2 + 2.0 * next());
        let (a, b, c) = (l11 * l11, l11 * l21, l21 * l21 + l22 * l22);
        let vt = if next() < 0.05 {
            0.0
        } else {
            4.0 * next() - 2.0
        };
        if let Ok(p) =
            ContactProblem::from_entries(a, b, c, vt, -0.05 - 2.0 * next(), 2.0 * next(), next())
        {
            out.push(p);
        }
    }
    out
}

#[test]
fn batch_equals_single_calls_for_every_law() {
    let problems = random_problems(3000, 11);
    let mut out = vec![ImpactSummary::INVALID; problems.len()];
    let mut seen = std::collections::HashSet::new();
    for law in LawId::ALL {
        resolve_problems(law, &problems, &mut out).unwrap();
        for (p, s) in problems.iter().zip(&out) {
            let single = ImpactSummary::of_resolution(&law.resolve(p));
            // Bit for bit (NaN fields compare unequal, so compare the debug text).
            assert_eq!(format!("{s:?}"), format!("{single:?}"), "{law}");
            seen.insert((law, s.sequence));
        }
    }
    // The random set exercises every regime of the exact laws.
    for s in [Sequence::Slip, Sequence::SlipStick, Sequence::SlipReverse] {
        assert!(seen.contains(&(LawId::Energetic, s)), "no {s:?}");
    }
    // The fused reduction counts exactly what the records count.
    for law in LawId::ALL {
        resolve_problems(law, &problems, &mut out).unwrap();
        let mut from_records = Tally::new();
        out.iter().for_each(|s| from_records.add(s, 0.5));
        let mut fused = Tally::new();
        for_each_resolution(law, &problems, |_, r| fused.add_resolution(r, 0.5));
        assert_eq!(format!("{fused:?}"), format!("{from_records:?}"), "{law}");
        // The briefs (which the Darboux–Keller laws compute without the full record) too.
        let mut briefed = Tally::new();
        for_each_brief(law, &problems, |_, r| briefed.add_brief(r, 0.5));
        assert_eq!(format!("{briefed:?}"), format!("{from_records:?}"), "{law}");
    }
    // smith-centre needs a body: a breakdown in contact space.
    resolve_problems(LawId::SmithCentre, &problems, &mut out).unwrap();
    assert!(out.iter().all(|s| s.status == Status::Breakdown));
}

#[test]
fn briefs_equal_the_full_outcomes_bit_for_bit() {
    // `resolve_brief` shares the path end and the ΔT/verdict code with `resolve`: the same
    // bits on every problem, for every law (overridden or not).
    let problems = random_problems(3000, 23);
    for law in LawId::ALL {
        let mut briefs = Vec::new();
        for_each_brief(law, &problems, |_, r| briefs.push(*r));
        for (p, brief) in problems.iter().zip(&briefs) {
            let full = law.resolve(p).map(|o| OutcomeBrief::of(&o));
            assert_eq!(format!("{brief:?}"), format!("{full:?}"), "{law}");
            if let (Ok(b), Ok(f)) = (brief, &full) {
                assert_eq!(
                    b.energy_change.to_bits(),
                    f.energy_change.to_bits(),
                    "{law}"
                );
            }
        }
    }
}

#[test]
fn columns_validate_each_problem() {
    let wtt = [3.5, 3.5, -1.0, 3.5];
    let wtn = [0.0; 4];
    let wnn = [1.0; 4];
    let vt = [0.5, 0.5, 0.5, 0.5];
    let vn = [-0.8, 0.3, -0.8, -0.8];
    let mu = [0.4, 0.4, 0.4, f64::NAN];
    let e = [0.7; 4];
    let cols = ProblemColumns::new(&wtt, &wtn, &wnn, &vt, &vn, &mu, &e).unwrap();
    let mut out = [ImpactSummary::BREAKDOWN; 4];
    resolve_columns(LawId::Energetic, &cols, &mut out).unwrap();
    let direct = LawId::Energetic.resolve(&cols.problem(0).unwrap()).unwrap();
    assert_eq!(out[0], ImpactSummary::of(&direct));
    for s in &out[1..] {
        assert_eq!(s.status, Status::Invalid);
        assert!(s.energy_change.is_nan());
    }
    let mut short = [ImpactSummary::INVALID; 3];
    assert!(resolve_columns(LawId::Energetic, &cols, &mut short).is_err());
    assert!(ProblemColumns::new(&wtt, &wtn, &wnn, &vt, &vn, &mu, &e[..3]).is_err());
}

#[test]
fn driver_is_ordered_and_thread_count_independent() {
    let problems = random_problems(20_000, 5);
    let run_waves = |threads: usize, waves: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let mut order = Vec::new();
            let mut tally = Tally::new();
            let mut energies = Vec::new();
            run_ordered_waves(
                problems.len() as u64,
                777,
                waves,
                |r| {
                    let ps = &problems[r.start as usize..r.end as usize];
                    let mut out = vec![ImpactSummary::INVALID; ps.len()];
                    resolve_problems(LawId::Newton, ps, &mut out).unwrap();
                    (r, out)
                },
                |(r, out)| {
                    order.push(r.start);
                    for s in &out {
                        tally.add(s, 1.0);
                        energies.push(s.energy_change.to_bits());
                    }
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
            (order, tally, energies)
        })
    };
    let run = |threads: usize| run_waves(threads, 4);
    let (o1, t1, e1) = run(1);
    let (o3, t3, e3) = run(3);
    // The wave length changes only how many chunks are in flight, never the order.
    for (threads, waves) in [(2, 1), (2, 64), (3, 7)] {
        let (o, t, e) = run_waves(threads, waves);
        assert_eq!(
            (&o, &t, &e),
            (&o1, &t1, &e1),
            "{threads} threads, {waves} per wave"
        );
    }
    assert_eq!(o1, (0..20_000u64).step_by(777).collect::<Vec<_>>());
    assert_eq!(o1, o3);
    assert_eq!(e1, e3);
    assert_eq!(t1, t3);
    assert_eq!(t1.total, 20_000);
    assert_eq!(t1.energy_gained + t1.consistent + t1.inconsistent, 20_000);
    // The sink's error stops the sweep.
    let mut n = 0;
    let r = run_ordered(
        1000,
        10,
        |r| r.start,
        |_| {
            n += 1;
            if n == 3 {
                Err("stop")
            } else {
                Ok(())
            }
        },
    );
    assert_eq!(r, Err("stop"));
    assert_eq!(n, 3);
}

#[test]
fn grids_are_exact_and_random_samples_reproducible() {
    let a = Axis::new("spin-ratio", -3.0, 3.0, 1201).unwrap();
    assert_eq!(a.value(0), -3.0);
    assert_eq!(a.value(600), 0.0);
    assert_eq!(a.value(1200), 3.0);
    assert_eq!(a.value(700), 0.5);
    assert_eq!(a.nearest(0.5012), 700);
    let g = Grid::new(vec![Axis::new("x", 0.0, 1.0, 3).unwrap(), a]).unwrap();
    assert_eq!(g.len(), 3 * 1201);
    let space = Space::Grid(g);
    let mut first = None;
    space.for_each_in(1201..1202, |_, v| first = Some(v.to_vec()));
    assert_eq!(first.unwrap(), vec![0.5, -3.0]);
    let r = RandomSamples::new(
        vec![
            SampleRange::new("friction", 0.0, 2.0).unwrap(),
            SampleRange::new("restitution", 0.5, 1.0).unwrap(),
        ],
        1000,
        9,
    )
    .unwrap();
    let space = Space::Random(r.clone());
    let mut all = Vec::new();
    space.for_each_in(0..1000, |_, v| all.push([v[0], v[1]]));
    let mut tail = Vec::new();
    space.for_each_in(500..1000, |_, v| tail.push([v[0], v[1]]));
    assert_eq!(&all[500..], &tail[..]);
    assert!(all
        .iter()
        .all(|v| (0.0..2.0).contains(&v[0]) && (0.5..1.0).contains(&v[1])));
    let mean = all.iter().map(|v| v[0]).sum::<f64>() / 1000.0;
    assert!((mean - 1.0).abs() < 0.1, "mean {mean}");
    let other_seed = RandomSamples::new(r.ranges().to_vec(), 1000, 10).unwrap();
    let mut p = [0.0; 2];
    other_seed.point(0, &mut p);
    assert_ne!(p, all[0]);
}

/// The engine's root of Whittaker's ΔT(γ) on one branch, by bisection to the last bit.
fn engine_root(seed: &Seed, lo: f64, hi: f64) -> f64 {
    let f = |g: f64| {
        seed.outcome(LawId::Whittaker, g)
            .unwrap()
            .outcome
            .energy_change
    };
    let (mut lo, mut hi) = (lo, hi);
    let flo = f(lo);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f(mid).signum() == flo.signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn eq13_threshold_matches_the_engine() {
    for (e, f) in [(0.7, 0.4), (0.5, 0.2), (1.0, 0.8), (0.0, 0.3)] {
        for k in 1..18 {
            let alpha_deg = 5.0 * k as f64;
            let seed = Seed {
                alpha: alpha_deg * (std::f64::consts::PI / 180.0),
                restitution: e,
                friction: f,
                ..Seed::PAPER
            };
            let t = whittaker_sphere_thresholds(seed.alpha, e, f);
            let edge = -seed.alpha.sin();
            // Eq. 13 itself against the engine's ΔT/T0.
            for g in [-2.5, -1.1, edge - 0.01, edge + 0.01, 0.1, 1.3] {
                let engine = seed.energy_ratio(LawId::Whittaker, g).unwrap();
                let formula = whittaker_sphere_energy_ratio(seed.alpha, e, f, g);
                assert!((engine - formula).abs() < 1e-12, "α={alpha_deg} γ={g}");
            }
            // Each threshold is the engine's sign change, and the sides are right.
            if let Some(up) = t.upper {
                let root = engine_root(&seed, edge + 1e-9, up + 1.0);
                assert!((root - up).abs() < 1e-9, "α={alpha_deg}: {root} vs {up}");
                let o = seed.outcome(LawId::Whittaker, 0.5 * (edge + up)).unwrap();
                assert_eq!(o.outcome.verdict, Verdict::EnergyGained);
            } else {
                let r = seed.energy_ratio(LawId::Whittaker, edge + 1e-6).unwrap();
                assert!(r <= 0.0, "α={alpha_deg}: gain without an upper threshold");
            }
            if let Some(lo) = t.lower {
                let root = engine_root(&seed, lo - 1.0, edge - 1e-9);
                assert!((root - lo).abs() < 1e-9, "α={alpha_deg}: {root} vs {lo}");
                assert!(t.gains(0.5 * (lo + edge), seed.alpha));
                assert!(!t.gains(lo - 0.01, seed.alpha));
            }
        }
    }
    // The seed: γ*₊ ≈ 0.2058 and γ*₋ ≈ −1.2058 (paper A prints ±0.20).
    let t = whittaker_sphere_thresholds(Seed::PAPER.alpha, 0.7, 0.4);
    assert!((t.upper.unwrap() - 0.205811).abs() < 1e-6);
    assert!((t.lower.unwrap() + 1.205811).abs() < 1e-6);
    let none = whittaker_sphere_thresholds(Seed::PAPER.alpha, 0.7, 0.0);
    assert_eq!((none.upper, none.lower), (None, None));
}
