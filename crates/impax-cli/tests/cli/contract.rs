//! Property test of the command line's contract (`impax_cli::contract`) over random
//! invocations, in-process: for problems, scenarios and states drawn over many decades
//! (1e-300 … 1e300, zeros, signs, extreme coefficients), every run exits 0 or 2; an error is
//! one line naming its field; a successful JSON document holds no null (no NaN or infinity)
//! where a number is documented.

use impax::math::SplitMix64;
use impax_cli::{contract, invoke};

/// A number of random size and sign: often ordinary, sometimes extreme, sometimes special.
fn number(rng: &mut SplitMix64) -> String {
    let u = rng.unit();
    let x = if u < 0.05 {
        0.0
    } else if u < 0.55 {
        rng.range(-2.0, 2.0)
    } else {
        let sign = if rng.unit() < 0.3 { -1.0 } else { 1.0 };
        sign * rng.decades(-300.0, 300.0)
    };
    format!("{x:e}")
}

fn positive(rng: &mut SplitMix64) -> String {
    if rng.unit() < 0.5 {
        format!("{:e}", rng.range(0.01, 3.0))
    } else {
        format!("{:e}", rng.decades(-300.0, 300.0))
    }
}

fn list(rng: &mut SplitMix64, n: usize) -> String {
    (0..n).map(|_| number(rng)).collect::<Vec<_>>().join(",")
}

fn check(args: &[String]) {
    let mut all = vec!["impax".to_string()];
    all.extend(args.iter().cloned());
    let run = invoke(&all);
    if let Err(why) = contract::check(&run) {
        panic!("impax {}: {why}", args.join(" "));
    }
}

fn s(x: &str) -> String {
    x.to_string()
}

#[test]
fn resolve_keeps_the_contract_over_three_hundred_decades() {
    let mut rng = SplitMix64(41);
    for i in 0..3000 {
        let spatial = i % 3 == 0;
        let (w, v) = if spatial {
            (list(&mut rng, 6), list(&mut rng, 3))
        } else {
            (list(&mut rng, 3), list(&mut rng, 2))
        };
        check(&[
            s("resolve"),
            s("--w"),
            w,
            s("--v"),
            v,
            s("--friction"),
            number(&mut rng),
            s("--restitution"),
            format!("{}", rng.range(-0.1, 1.1)),
            s("--json"),
        ]);
    }
}

#[test]
fn compare_keeps_the_contract_for_bodies_and_mechanisms() {
    let mut rng = SplitMix64(42);
    for i in 0..400 {
        let mut args = vec![s("compare")];
        match i % 3 {
            0 => {
                for flag in ["--speed", "--mass", "--radius"] {
                    if rng.unit() < 0.6 {
                        args.extend([s(flag), positive(&mut rng)]);
                    }
                }
                for flag in ["--alpha-deg", "--spin-ratio"] {
                    if rng.unit() < 0.6 {
                        args.extend([s(flag), number(&mut rng)]);
                    }
                }
            }
            1 => {
                args.push(s("double-pendulum"));
                args.extend([
                    s("--masses"),
                    format!("{},{}", positive(&mut rng), positive(&mut rng)),
                ]);
                args.extend([
                    s("--lengths"),
                    format!("{},{}", positive(&mut rng), positive(&mut rng)),
                ]);
                args.extend([s("--rates"), list(&mut rng, 2)]);
                args.extend([
                    s("--angles-deg"),
                    format!("{},{}", rng.range(-180.0, 180.0), rng.range(-180.0, 180.0)),
                ]);
            }
            _ => {
                args.push(s("rod"));
                args.extend([s("--masses"), positive(&mut rng)]);
                args.extend([s("--lengths"), positive(&mut rng)]);
                args.extend([s("--rates"), list(&mut rng, 3)]);
                args.extend([s("--angles-deg"), format!("{}", rng.range(-90.0, 180.0))]);
            }
        }
        for flag in ["--friction", "--restitution"] {
            if rng.unit() < 0.5 {
                args.extend([s(flag), number(&mut rng)]);
            }
        }
        args.push(s("--json"));
        check(&args);
    }
}

#[test]
fn simulate_keeps_the_contract() {
    let mut rng = SplitMix64(43);
    for i in 0..100 {
        let mut args = vec![s("simulate")];
        match i % 5 {
            3 => {
                args.push(s("rocking-block"));
                args.extend([s("--angle-deg"), format!("{}", rng.range(-30.0, 30.0))]);
                args.extend([s("--omega"), format!("{}", rng.range(-3.0, 3.0))]);
            }
            4 => {
                args.push(s("cradle"));
                args.extend([s("--balls"), format!("{}", 2 + (rng.unit() * 6.0) as usize)]);
                args.extend([s("--gap"), format!("{}", rng.range(0.0, 0.2))]);
            }
            0 => {
                args.push(s("bouncing-ball"));
                for flag in ["--height", "--speed", "--mass", "--radius"] {
                    if rng.unit() < 0.5 {
                        args.extend([s(flag), positive(&mut rng)]);
                    }
                }
            }
            1 => {
                args.push(s("rod-drop"));
                args.extend([s("--angle-deg"), format!("{}", rng.range(-180.0, 180.0))]);
                if rng.unit() < 0.5 {
                    args.extend([s("--height"), positive(&mut rng)]);
                }
            }
            _ => {
                args.push(s("double-pendulum-drop"));
                args.extend([
                    s("--rates"),
                    format!("{},{}", rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)),
                ]);
                args.extend([s("--floor"), format!("{}", rng.range(-3.0, -0.5))]);
            }
        }
        args.extend([
            s("--law"),
            s([
                "energetic",
                "newton",
                "poisson",
                "lcp",
                "whittaker",
                "brach",
            ][i % 6]),
            s("--friction"),
            format!("{}", rng.range(0.0, 1.5)),
            s("--restitution"),
            format!("{}", rng.range(0.0, 1.0)),
            s("--until"),
            s("1"),
            s("--samples"),
            s("50"),
            s("--json"),
        ]);
        check(&args);
    }
}
