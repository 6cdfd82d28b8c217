//! The multi-contact laws (`lcp`, `sequential`, `lzb`), planar and spatial, are invariant
//! under a change of the units of velocity and of mass, as the one-contact laws are
//! (`regression_scale_invariance.rs`): `v → s_v v`, `W → s_w W` scales every impulse by
//! `s_v/s_w`, every velocity by `s_v`, `ΔT` and the works by `s_v²/s_w`, and leaves the
//! verdict and each contact's regimes unchanged — for factors from 1e-300 to 1e300.
//!
//! The laws work in canonical units (powers of two that bring `v⁻` and `W` near one), so a
//! power-of-two change is exact to the last bit; any other factor changes the canonical numbers
//! by round-off only, and the results agree to round-off (`lcp`, `sequential`) or to the
//! integration's tolerance (`lzb`, `1e-9` of each quantity's scale).

use super::support::{contact_space, random_multi};
use impax::math::SplitMix64;
use impax::multi::spatial::MultiProblem as Spatial;
use impax::multi::MultiProblem as Planar;
use impax::LawId;
use nalgebra::{DMatrix, DVector};

const LAWS: [LawId; 3] = [LawId::Lcp, LawId::Sequential, LawId::Lzb];

/// The numbers of one outcome: impulses, velocities after, works and `ΔT` (flattened), the
/// verdict and each contact's regimes (as text), or the breakdown's id.
#[derive(Debug)]
struct Numbers {
    impulse: Vec<f64>,
    velocity: Vec<f64>,
    work: Vec<f64>,
    labels: String,
    /// The regimes without those that carry a negligible impulse (`1e-9` of the largest
    /// normal impulse), neighbours of one kind merged.
    regimes: String,
}

/// The [`Numbers`] of a multi-contact resolution, planar or spatial (the two outcomes have the
/// same fields, with 2- or 3-vectors).
macro_rules! numbers {
    ($resolution:expr) => {
        match $resolution.expect("a multi-contact law") {
            Ok(o) => {
                Ok(Numbers {
                    impulse: o
                        .contacts
                        .iter()
                        .flat_map(|c| c.impulse.iter().copied())
                        .collect(),
                    velocity: o
                        .contacts
                        .iter()
                        .flat_map(|c| c.velocity_after.iter().copied())
                        .collect(),
                    work: std::iter::once(o.energy_change)
                        .chain(o.contacts.iter().flat_map(|c| {
                            [c.work.compression, c.work.restitution, c.work.friction]
                        }))
                        .collect(),
                    labels: shape(format!(
                        "{:?} {:?}",
                        o.verdict,
                        o.contacts
                            .iter()
                            .map(|c| c.phases.iter().map(|f| f.kind).collect::<Vec<_>>())
                            .collect::<Vec<_>>()
                    )),
                    regimes: {
                        let pmax = o
                            .contacts
                            .iter()
                            .map(|c| c.impulse.iter().last().copied().unwrap_or(0.0).abs())
                            .fold(0.0, f64::max);
                        let lists: Vec<Vec<String>> = o
                            .contacts
                            .iter()
                            .map(|c| {
                                let mut out: Vec<String> = Vec::new();
                                let mut from = 0.0;
                                for f in &c.phases {
                                    let carried = (f.ends_at - from).abs();
                                    from = f.ends_at;
                                    let kind = format!("{:?}", f.kind);
                                    if carried > 1e-9 * pmax && out.last() != Some(&kind) {
                                        out.push(kind);
                                    }
                                }
                                out
                            })
                            .collect();
                        shape(format!("{:?} {:?}", o.verdict, lists))
                    },
                })
            }
            Err(b) => Err(b.reason.id().to_string()),
        }
    };
}

fn planar_numbers(law: LawId, p: &Planar) -> Result<Numbers, String> {
    numbers!(law.resolve(p))
}

fn spatial_numbers(law: LawId, p: &Spatial) -> Result<Numbers, String> {
    numbers!(law.resolve(p))
}

/// The regimes' text without its numbers (a slip's angles, which scale to round-off).
fn shape(text: String) -> String {
    let mut out = String::new();
    let mut digit = false;
    for c in text.chars() {
        let number = c.is_ascii_digit() || ".-+".contains(c) || (digit && "eE".contains(c));
        digit = c.is_ascii_digit() || (digit && number);
        if !number {
            out.push(c);
        }
    }
    out
}

/// The regimes' text with every repeated cycle of two regimes at a contact written once
/// (`A, B, A, B, A` → `A, B, A`): the micro-impacts of a chattering tail, as many as it takes
/// for the exchanges to fall below the settled threshold (`lzb`), a number that round-off of
/// the canonical units can move by a few in a tail of a hundred.
fn cycles_once(text: &str) -> String {
    let Some(open) = text.find('[') else {
        return text.to_string();
    };
    let (verdict, lists) = text.split_at(open);
    let inner = lists.trim_start_matches("[[").trim_end_matches("]]");
    let contacts: Vec<String> = inner
        .split("], [")
        .map(|c| {
            let mut kinds: Vec<&str> = c.split(", ").collect();
            let mut i = 0;
            while i + 4 <= kinds.len() {
                if kinds[i..i + 2] == kinds[i + 2..i + 4] {
                    kinds.drain(i + 2..i + 4);
                } else {
                    i += 1;
                }
            }
            kinds.join(", ")
        })
        .collect();
    format!("{verdict}[[{}]]", contacts.join("], ["))
}

/// Whether `x · k` stays a normal number (or zero) with room to spare.
fn representable(x: f64, k: f64) -> bool {
    x == 0.0 || (1e-290..1e290).contains(&(x.abs() * k))
}

/// Whether every number of `a` survives the change of units (impulses `kp`, velocities `kv`).
fn fits(a: &Numbers, kp: f64, kv: f64) -> bool {
    a.impulse.iter().all(|&x| representable(x, kp))
        && a.velocity.iter().all(|&x| representable(x, kv))
        && a.work.iter().all(|&x| representable(x, kp * kv))
}

/// `b` is `a` in the scaled units: exactly (`tol = 0`) or to `tol` of each list's largest
/// entry (velocities: of the largest velocity before or after, the scale of their round-off).
fn agree(
    what: &str,
    a: &Result<Numbers, String>,
    b: &Result<Numbers, String>,
    kp: f64,
    kv: f64,
    vmax: f64,
    tol: f64,
) {
    let (x, y) = match (a, b) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(x), Err(y)) => return assert_eq!(x, y, "{what}"),
        _ => panic!("{what}: {a:?} vs {b:?}"),
    };
    // (Exact units: the same regimes to the last one; others: the same regimes among those
    // that carry an impulse above the tolerance, up to the number of micro-impacts of a
    // chattering tail, `cycles_once`.)
    if tol == 0.0 {
        assert_eq!(x.labels, y.labels, "{what}");
    } else {
        assert_eq!(cycles_once(&x.regimes), cycles_once(&y.regimes), "{what}");
    }
    let lists = [
        (&x.impulse, &y.impulse, kp, 0.0),
        (&x.velocity, &y.velocity, kv, vmax),
        (&x.work, &y.work, kp * kv, 0.0),
    ];
    for (u, w, k, floor) in lists {
        let scale = u.iter().fold(floor, |m, z: &f64| m.max(z.abs())) * k;
        for (p, q) in u.iter().zip(w) {
            let ok = if tol == 0.0 {
                p * k == *q
            } else {
                (p * k - q).abs() <= tol * scale
            };
            assert!(ok, "{what}: {u:?} · {k:e} vs {w:?}");
        }
    }
}

/// A change of units: a power of two (exact) or any factor.
fn factors(rng: &mut SplitMix64, exact: bool) -> (f64, f64) {
    if exact {
        let e = |rng: &mut SplitMix64| 2f64.powi((rng.next_u64() % 1801) as i32 - 900);
        (e(rng), e(rng))
    } else {
        (rng.decades(-300.0, 300.0), rng.decades(-300.0, 300.0))
    }
}

fn tolerance(law: LawId, exact: bool) -> f64 {
    match (exact, law) {
        (true, _) => 0.0,
        (false, LawId::Lzb) => 1e-9,
        (false, _) => 1e-11,
    }
}

#[test]
fn planar_laws_scale_with_the_units() {
    let mut rng = SplitMix64(0x5ca1_e0f2);
    let mut compared = 0;
    for case in 0..600 {
        let k = 2 + case % 2;
        let r = random_multi(&mut rng, k);
        let p = r.problem;
        let exact = case % 2 == 0;
        let (sv, sw) = factors(&mut rng, exact);
        let v: Vec<f64> = p.velocity().iter().map(|x| x * sv).collect();
        let mu: Vec<f64> = (0..k).map(|j| p.friction(j)).collect();
        let e: Vec<f64> = (0..k).map(|j| p.restitution(j)).collect();
        let Ok(q) = Planar::new(p.w() * sw, &v, &mu, &e) else {
            continue;
        };
        let vmax = p.velocity().amax() + (p.w().abs() * DVector::repeat(2 * k, 1.0)).amax();
        for law in LAWS {
            let a = planar_numbers(law, &p);
            if a.as_ref().is_ok_and(|x| !fits(x, sv / sw, sv)) {
                continue;
            }
            let b = planar_numbers(law, &q);
            let what = format!("{law} sv {sv:e} sw {sw:e} W {} v {}", p.w(), p.velocity());
            // (The velocity scale: |v⁻| + |W| |p| bounds the round-off of v⁺ = v⁻ + W p.)
            let pmax = a.as_ref().map_or(0.0, |x| {
                x.impulse.iter().fold(0.0f64, |m, z| m.max(z.abs()))
            });
            agree(
                &what,
                &a,
                &b,
                sv / sw,
                sv,
                vmax * pmax.max(1.0),
                tolerance(law, exact),
            );
            compared += 1;
        }
    }
    assert!(compared > 800, "{compared}");
}

#[test]
fn spatial_laws_scale_with_the_units() {
    let mut rng = SplitMix64(0x5ca1_e0f3);
    let mut compared = 0;
    for case in 0..500 {
        let k = 2 + case % 2;
        let dof = 3 * k + 1 + (rng.next_u64() % 3) as usize;
        let j = DMatrix::from_fn(3 * k, dof, |_, _| rng.range(-1.0, 1.0));
        let masses: Vec<f64> = (0..dof).map(|_| rng.decades(-1.0, 1.0)).collect();
        let u = DVector::from_fn(dof, |_, _| rng.range(-1.0, 1.0));
        let (w, v) = contact_space(&j, &masses, &u);
        if (0..k).all(|c| v[3 * c + 2] >= 0.0) {
            continue;
        }
        let mu: Vec<f64> = (0..k).map(|_| rng.range(0.0, 1.2)).collect();
        let e: Vec<f64> = (0..k).map(|_| rng.unit()).collect();
        let Ok(p) = Spatial::new(w.clone(), &v, &mu, &e) else {
            continue;
        };
        let exact = case % 2 == 0;
        let (sv, sw) = factors(&mut rng, exact);
        let vs: Vec<f64> = v.iter().map(|x| x * sv).collect();
        let Ok(q) = Spatial::new(&w * sw, &vs, &mu, &e) else {
            continue;
        };
        let vmax = p.velocity().amax() + (p.w().abs() * DVector::repeat(3 * k, 1.0)).amax();
        for law in LAWS {
            let a = spatial_numbers(law, &p);
            if a.as_ref().is_ok_and(|x| !fits(x, sv / sw, sv)) {
                continue;
            }
            let b = spatial_numbers(law, &q);
            let what = format!("{law} sv {sv:e} sw {sw:e} W {w} v {v:?}");
            let pmax = a.as_ref().map_or(0.0, |x| {
                x.impulse.iter().fold(0.0f64, |m, z| m.max(z.abs()))
            });
            agree(
                &what,
                &a,
                &b,
                sv / sw,
                sv,
                vmax * pmax.max(1.0),
                tolerance(law, exact),
            );
            compared += 1;
        }
    }
    assert!(compared > 550, "{compared}");
}
