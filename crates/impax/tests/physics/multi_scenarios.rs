//! The built-in systems struck at several contacts (`impax::multi::scenarios`) against answers
//! derived independently here:
//!
//! * `rod-flat`'s rows equal the rod mechanism's Jacobians (automatic differentiation of its
//!   end points) lying flat; a symmetric landing leaves level at `e |v_y|` under `lcp`;
//! * `rocking-block`: Housner's `ω⁺/ω⁻ = 1 − (3/2) sin²α` for `e = 0` with enough friction,
//!   under `lcp` and `sequential`, over aspect ratios, to 1e-12;
//! * `cradle`: `lcp` gives `(−1/3, 2/3, 2/3) v0` (three balls), `sequential` `(0, …, 0, v0)`;
//!   momentum is conserved by every law (the contacts are internal);
//! * `ball-ball-wall`: frictionless, `e = 1`: energy and the momentum along the wall conserved;
//! * every law: `½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻` equals the contact-space `ΔT`;
//! * bad parameters name their field.

use impax::mechanism::builtin::Rod;
use impax::multi::scenarios::{BallBallWall, Cradle, RockingBlock, RodFlat};
use impax::multi::{MultiImpact, MultiScenario, SystemOutcome};
use impax::LawId;

fn run(s: &MultiScenario, law: LawId, mu: f64, e: f64) -> (SystemOutcome, Vec<f64>) {
    let problem = s.impact.problem(&[mu], &[e]).expect("problem");
    let out = s.impact.resolve(law, &problem).expect("resolve");
    let after = out.velocities_after.clone().unwrap_or_else(|| {
        panic!(
            "{law} broke down on {}: {:?}",
            s.description, out.resolution
        )
    });
    let o = out.resolution.as_ref().unwrap();
    let t0 = s.impact.energy_before();
    let de = out.energy_change_from_velocities.unwrap();
    assert!(
        (de - o.energy_change).abs() <= 1e-12 * t0,
        "{law}: ΔT {} from velocities vs {} in contact space",
        de,
        o.energy_change
    );
    (out, after)
}

#[test]
fn rod_flat_rows_are_the_rod_mechanisms() {
    let (m, l) = (2.5, 0.8);
    let s = RodFlat {
        mass: m,
        length: l,
        vx: 0.3,
        vy: -1.2,
        omega: 0.7,
    }
    .build()
    .unwrap();
    let rod = Rod::new(m, l, 9.81, 0.0).unwrap();
    let u = [0.3, -1.2, 0.7];
    let from = MultiImpact::from_mechanism(&rod, &[0.0, 0.0, 0.0], &u, &[0, 1]).unwrap();
    let (a, b) = (s.impact.jacobian(), from.jacobian());
    assert!((a - b).amax() < 1e-15, "{a}\n{b}");
    assert!((s.impact.mass_matrix() - from.mass_matrix()).amax() < 1e-15);
    assert_eq!(from.contacts(), ["end A", "end B"]);
}

#[test]
fn rod_landing_flat_leaves_level() {
    for (m, l, vy) in [(1.0, 1.0, -1.0), (2.5, 0.8, -3.7), (1e-3, 40.0, -0.01)] {
        let s = RodFlat {
            mass: m,
            length: l,
            vx: 0.0,
            vy,
            omega: 0.0,
        }
        .build()
        .unwrap();
        for e in [0.0, 0.3, 0.8, 1.0] {
            for mu in [0.0, 0.5] {
                let (_, after) = run(&s, LawId::Lcp, mu, e);
                let expected = [0.0, e * vy.abs(), 0.0];
                for k in 0..3 {
                    let scale = if k == 2 { vy.abs() / l } else { vy.abs() };
                    assert!(
                        (after[k] - expected[k]).abs() < 1e-12 * scale,
                        "m {m} l {l} e {e} μ {mu}: {after:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn rocking_block_is_housners() {
    // Slender blocks (b < √2 h: the ratio is positive and the block rocks on about B).
    for (b, h) in [(0.2, 0.6), (0.1, 1.0), (0.5, 0.5), (1.0, 0.75), (0.05, 2.0)] {
        for w in [-1.0, -0.03, -25.0] {
            let block = RockingBlock {
                mass: 3.0,
                half_width: b,
                half_height: h,
                omega: w,
            };
            let s = block.build().unwrap();
            // A is at rest and B strikes at 2 b |ω|.
            let v = s.impact.contact_velocities();
            assert!(v[0].abs() < 1e-15 && v[1].abs() < 1e-15);
            assert!((v[3] - 2.0 * b * w).abs() < 1e-15 * b * w.abs());
            for law in [LawId::Lcp, LawId::Sequential] {
                let (out, after) = run(&s, law, 10.0, 0.0);
                let ratio = after[2] / w;
                assert!(
                    (ratio - block.housner_ratio()).abs() < 1e-12,
                    "{law} b {b} h {h}: {ratio} vs {}",
                    block.housner_ratio()
                );
                // Rocking on about B: B at rest, A lifting.
                let o = out.resolution.unwrap();
                assert!(o.contacts[1].velocity_after.norm() < 1e-12 * b * w.abs());
                assert!(o.contacts[0].velocity_after.y > 0.0);
                assert_eq!(o.contacts[0].impulse.norm(), 0.0);
            }
        }
    }
}

#[test]
fn a_squat_block_comes_to_rest() {
    // b > √2 h: Housner's ratio would be negative (the block cannot rock on about B); with
    // e = 0 the complementarity impact leaves it at rest on both corners.
    let block = RockingBlock {
        mass: 1.0,
        half_width: 1.0,
        half_height: 0.3,
        omega: -2.0,
    };
    assert!(block.housner_ratio() < 0.0);
    let s = block.build().unwrap();
    let (_, after) = run(&s, LawId::Lcp, 10.0, 0.0);
    assert!(after.iter().all(|x| x.abs() < 1e-12), "{after:?}");
}

#[test]
fn newtons_cradle() {
    let s = Cradle::default().build().unwrap();
    let (_, lcp) = run(&s, LawId::Lcp, 0.0, 1.0);
    let (_, seq) = run(&s, LawId::Sequential, 0.0, 1.0);
    for (i, (a, b)) in [(-1.0 / 3.0, 0.0), (2.0 / 3.0, 0.0), (2.0 / 3.0, 1.0)]
        .into_iter()
        .enumerate()
    {
        assert!((lcp[3 * i] - a).abs() < 1e-12, "lcp {lcp:?}");
        assert!((seq[3 * i] - b).abs() < 1e-12, "sequential {seq:?}");
    }
    for n in [2, 4, 5, 7] {
        let v0 = 2.5;
        let s = Cradle {
            balls: n,
            mass: 0.7,
            radius: 0.1,
            v0,
        }
        .build()
        .unwrap();
        let laws: &[LawId] = if n <= 7 {
            &[LawId::Lcp, LawId::Sequential]
        } else {
            &[LawId::Sequential]
        };
        for &law in laws {
            let (_, after) = run(&s, law, 0.0, 1.0);
            let momentum: f64 = (0..n).map(|i| after[3 * i]).sum();
            assert!((momentum - v0).abs() < 1e-12 * v0, "{law} N {n}");
            let energy: f64 = (0..n).map(|i| after[3 * i].powi(2)).sum();
            assert!((energy - v0 * v0).abs() < 1e-12 * v0 * v0, "{law} N {n}");
            if law == LawId::Sequential {
                for i in 0..n {
                    let want = if i == n - 1 { v0 } else { 0.0 };
                    assert!((after[3 * i] - want).abs() < 1e-12 * v0, "N {n}: {after:?}");
                }
            }
        }
    }
}

#[test]
fn ball_ball_wall_conserves_energy_and_momentum_along_the_wall() {
    for a in [0.0, 30.0, -45.0, 80.0] {
        let s = BallBallWall {
            angle_deg: a,
            ..Default::default()
        }
        .build()
        .unwrap();
        let t0 = s.impact.energy_before();
        for law in [LawId::Lcp, LawId::Sequential] {
            let (out, after) = run(&s, law, 0.0, 1.0);
            let o = out.resolution.unwrap();
            assert!(
                o.energy_change.abs() < 1e-12 * t0,
                "{law} {a}°: {}",
                o.energy_change
            );
            // The frictionless wall pushes along x only: the y momentum stays 0.
            assert!((after[1] + after[4]).abs() < 1e-12, "{law} {a}°: {after:?}");
            // Nothing approaches after.
            for c in &o.contacts {
                assert!(c.velocity_after.y > -1e-12);
            }
        }
    }
}

#[test]
fn bad_parameters_name_their_field() {
    let field = |r: impax::Result<MultiScenario>| match r {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted"),
    };
    assert!(field(
        RodFlat {
            length: -1.0,
            ..Default::default()
        }
        .build()
    )
    .contains("length"));
    assert!(field(
        RodFlat {
            vy: f64::NAN,
            ..Default::default()
        }
        .build()
    )
    .contains("vy"));
    assert!(field(
        RockingBlock {
            omega: 1.0,
            ..Default::default()
        }
        .build()
    )
    .contains("omega"));
    assert!(field(
        RockingBlock {
            half_height: 0.0,
            ..Default::default()
        }
        .build()
    )
    .contains("half-height"));
    assert!(field(
        Cradle {
            balls: 1,
            ..Default::default()
        }
        .build()
    )
    .contains("balls"));
    assert!(field(
        BallBallWall {
            angle_deg: 90.0,
            ..Default::default()
        }
        .build()
    )
    .contains("angle-deg"));
    // A rod rising on both ends does not strike.
    let s = RodFlat {
        vy: 1.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    assert!(s.impact.problem(&[0.5], &[0.5]).is_err());
}
