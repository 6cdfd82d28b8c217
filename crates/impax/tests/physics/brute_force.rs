//! Brute-force check of the planar Darboux–Keller laws (`newton`, `poisson`, `energetic`).
//!
//! The Darboux–Keller equations (theory §2) are integrated here in the normal impulse `p_n`
//! from scratch, sharing no code with the library's closed form (no `ImpulsePath`, no
//! `darboux_keller_path`): the state `(p_n, p_t, v_t, v_n, W_n, W_r, W_t)` is stepped by
//! classical RK4 with a regime-dependent right-hand side
//!
//! * slip, `ŝ = sign(v_t)`: `dp_t/dp_n = −μ ŝ`, `dv/dp_n = W (−μ ŝ, 1)`;
//! * `v_t = 0` and `|W_tn| ≤ μ W_tt`: stick, ratio `λ = −W_tn/W_tt`, `dv_t/dp_n = 0`;
//! * `v_t = 0` otherwise: slip resumes along `sign(W_tn)`;
//!
//! with `dW_n/dp_n = v_n`, `dW_t/dp_n = v_t dp_t/dp_n`. Every event — `v_t` reaching zero,
//! `v_n` reaching zero (end of compression), and the termination of each law (newton
//! `v_n = −e v_n⁻`, poisson `p_n = (1+e) p_c`, energetic `W_n = (1−e²) W_c`, tracked as the
//! restitution work `W_r = −e² W_c`) — is located by bisecting the step length down to the
//! last bit, and the integration restarts at the event.
//!
//! The results are compared with the library on 10,000 random problems (random SPD `W` with
//! entries over a few decades, `W_tn` of both signs and sometimes zero, `v_t` sometimes
//! exactly zero, `μ ∈ [0, 2]` including 0 and 2, `e ∈ [0, 1]` including 0 and 1): impulse,
//! velocity after, compression impulse, the three works, the energy change and the halt of
//! the initial slip must agree to 1e-9 relative to `max(1, |value|)` — for velocities and
//! energies, relative to the size of the terms they are sums of (`|v⁻| + |W||p|`,
//! `|v⁻||p| + ½|p|ᵀ|W||p|`, at least 1), which exceed the value by up to `cond W` and set
//! the round-off of any evaluation. The largest deviation is printed
//! (`cargo test -p impax --test physics brute_force -- --nocapture`).

use impax::math::SplitMix64;
use impax::planar::{ContactProblem, LawDetail, Outcome};
use impax::LawId;

/// Agreement required between the brute-force integration and the library.
const TOL: f64 = 1e-9;
/// Number of random problems.
const PROBLEMS: usize = 10_000;

/// A random valid problem. `W = L Lᵀ + δ I` with `L` lower triangular, its entries spread
/// over two decades and the off-diagonal of both signs (zero 15 % of the time).
fn random_problem(rng: &mut SplitMix64) -> ContactProblem {
    let l11 = rng.decades(-1.0, 1.0);
    let l22 = rng.decades(-1.0, 1.0);
    let l21 = if rng.unit() < 0.15 {
        0.0
    } else {
        let m = rng.decades(-1.0, 1.0);
        if rng.unit() < 0.5 {
            -m
        } else {
            m
        }
    };
    let delta = 1e-3 * rng.decades(-1.0, 1.0);
    let (a, b, c) = (l11 * l11 + delta, l11 * l21, l21 * l21 + l22 * l22 + delta);
    let vt = if rng.unit() < 0.1 {
        0.0
    } else {
        rng.range(-2.0, 2.0)
    };
    let vn = rng.range(-2.0, -0.01);
    let u = rng.unit();
    let mu = if u < 0.1 {
        0.0
    } else if u < 0.15 {
        2.0
    } else {
        rng.range(0.0, 2.0)
    };
    let u = rng.unit();
    let e = if u < 0.1 {
        0.0
    } else if u < 0.2 {
        1.0
    } else {
        rng.range(0.0, 1.0)
    };
    ContactProblem::from_entries(a, b, c, vt, vn, mu, e).expect("generated problems are valid")
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Termination {
    Newton,
    Poisson,
    Energetic,
}

impl Termination {
    fn law(self) -> LawId {
        match self {
            Termination::Newton => LawId::Newton,
            Termination::Poisson => LawId::Poisson,
            Termination::Energetic => LawId::Energetic,
        }
    }
}

/// The integrated state.
#[derive(Debug, Clone, Copy)]
struct State {
    pn: f64,
    pt: f64,
    vt: f64,
    vn: f64,
    /// Normal work since the start `∫ v_n dp_n`.
    wn: f64,
    /// Normal work since the end of compression (restitution work).
    wr: f64,
    /// Friction work `∫ v_t dp_t`.
    wt: f64,
}

impl State {
    fn axpy(&self, h: f64, d: &State) -> State {
        State {
            pn: self.pn + h * d.pn,
            pt: self.pt + h * d.pt,
            vt: self.vt + h * d.vt,
            vn: self.vn + h * d.vn,
            wn: self.wn + h * d.wn,
            wr: self.wr + h * d.wr,
            wt: self.wt + h * d.wt,
        }
    }
}

/// The contact regime on a step: friction ratio and velocity slopes.
#[derive(Debug, Clone, Copy)]
struct Regime {
    ratio: f64,
    dvt: f64,
    dvn: f64,
    /// Slip direction `±1`, or 0 for stick.
    slip: f64,
}

/// The problem data the integrator needs (read through the public accessors only).
struct Dk {
    a: f64,
    b: f64,
    c: f64,
    mu: f64,
    e: f64,
    vt0: f64,
    vn0: f64,
}

/// What the brute-force integration reports.
#[derive(Debug, Clone, Copy)]
struct Trace {
    end: State,
    pc: f64,
    wc: f64,
    /// `p_n` at which the initial slip halted, if it did.
    slip_halt: Option<f64>,
    steps: usize,
}

impl Dk {
    fn new(p: &ContactProblem) -> Self {
        Self {
            a: p.wtt(),
            b: p.wtn(),
            c: p.wnn(),
            mu: p.friction(),
            e: p.restitution(),
            vt0: p.velocity().x,
            vn0: p.velocity().y,
        }
    }

    fn regime(&self, s: &State) -> Regime {
        let slip = |dir: f64| {
            let k = -self.mu * dir;
            Regime {
                ratio: k,
                dvt: self.a * k + self.b,
                dvn: self.b * k + self.c,
                slip: dir,
            }
        };
        if s.vt > 0.0 {
            slip(1.0)
        } else if s.vt < 0.0 {
            slip(-1.0)
        } else if self.b.abs() <= self.mu * self.a {
            let k = -self.b / self.a;
            Regime {
                ratio: k,
                dvt: 0.0, // the stick ratio keeps v_t = 0 by construction
                dvn: self.b * k + self.c,
                slip: 0.0,
            }
        } else if self.b > 0.0 {
            slip(1.0)
        } else {
            slip(-1.0)
        }
    }

    /// Right-hand side `d state / d p_n` in a fixed regime.
    fn rhs(&self, s: &State, r: &Regime) -> State {
        State {
            pn: 1.0,
            pt: r.ratio,
            vt: r.dvt,
            vn: r.dvn,
            wn: s.vn,
            wr: s.vn,
            wt: r.ratio * s.vt,
        }
    }

    /// One classical RK4 step of length `h` in regime `r`.
    fn rk4(&self, s: &State, r: &Regime, h: f64) -> State {
        let k1 = self.rhs(s, r);
        let k2 = self.rhs(&s.axpy(0.5 * h, &k1), r);
        let k3 = self.rhs(&s.axpy(0.5 * h, &k2), r);
        let k4 = self.rhs(&s.axpy(h, &k3), r);
        let mut out = *s;
        for (w, k) in [(1.0, k1), (2.0, k2), (2.0, k3), (1.0, k4)] {
            out = out.axpy(w * h / 6.0, &k);
        }
        // p_n is the independent variable: keep it exact.
        out.pn = s.pn + h;
        out
    }

    fn terminated(&self, s: &State, term: Termination, pc: f64, wc: f64) -> bool {
        match term {
            Termination::Newton => s.vn >= -self.e * self.vn0,
            Termination::Poisson => s.pn >= (1.0 + self.e) * pc,
            Termination::Energetic => s.wr >= -self.e * self.e * wc,
        }
    }

    fn integrate(&self, term: Termination) -> Trace {
        let mut s = State {
            pn: 0.0,
            pt: 0.0,
            vt: self.vt0,
            vn: self.vn0,
            wn: 0.0,
            wr: 0.0,
            wt: 0.0,
        };
        // Step: an eighth of the frictionless compression impulse, doubled after every step
        // without an event (so that long slips stay cheap), reset after each event.
        let h0 = 0.125 * -self.vn0 / self.c;
        let mut h = h0;
        let mut compression: Option<(f64, f64)> = None;
        let mut slip_halt = None;
        let mut initial_slip = self.vt0 != 0.0;
        for steps in 0..1_000_000 {
            if let Some((pc, wc)) = compression {
                if self.terminated(&s, term, pc, wc) {
                    return Trace {
                        end: s,
                        pc,
                        wc,
                        slip_halt,
                        steps,
                    };
                }
            }
            let r = self.regime(&s);
            let start = s;
            let slip_stops = |x: &State| r.slip * start.vt > 0.0 && r.slip * x.vt <= 0.0;
            let compression_ends = |x: &State| compression.is_none() && x.vn >= 0.0;
            let ends = |x: &State| match compression {
                Some((pc, wc)) => self.terminated(x, term, pc, wc),
                None => false,
            };
            let any = |x: &State| slip_stops(x) || compression_ends(x) || ends(x);
            let trial = self.rk4(&start, &r, h);
            if !any(&trial) {
                s = trial;
                h *= 2.0;
                continue;
            }
            // Bisect the step length down to the last bit of p_n.
            let (mut lo, mut hi) = (0.0f64, h);
            h = h0;
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi || start.pn + mid == start.pn + hi {
                    break;
                }
                if any(&self.rk4(&start, &r, mid)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            s = self.rk4(&start, &r, hi);
            if slip_stops(&s) {
                s.vt = 0.0;
                if initial_slip {
                    slip_halt = Some(s.pn);
                }
                initial_slip = false;
            }
            if compression_ends(&s) {
                compression = Some((s.pn, s.wn));
                s.wr = 0.0;
            }
        }
        panic!("no termination after 10⁶ steps: {:?}", self.vn0);
    }
}

fn rel(x: f64, y: f64) -> f64 {
    (x - y).abs() / 1f64.max(x.abs()).max(y.abs())
}

/// Largest relative deviation per compared quantity.
#[derive(Debug, Default)]
struct Deviations {
    impulse: f64,
    velocity: f64,
    compression_impulse: f64,
    work_compression: f64,
    work_restitution: f64,
    work_friction: f64,
    energy: f64,
    slip_halt: f64,
}

impl Deviations {
    fn max(&self) -> f64 {
        [
            self.impulse,
            self.velocity,
            self.compression_impulse,
            self.work_compression,
            self.work_restitution,
            self.work_friction,
            self.energy,
            self.slip_halt,
        ]
        .into_iter()
        .fold(0.0, f64::max)
    }
}

/// Compare one law's outcome with the integration; update `dev`; return the worst deviation.
fn compare(p: &ContactProblem, out: &Outcome, t: &Trace, dev: &mut Deviations) -> f64 {
    let s = &t.end;
    let impulse = rel(out.impulse.x, s.pt).max(rel(out.impulse.y, s.pn));
    // Velocities and energies are sums of terms much larger than themselves when W is
    // ill-conditioned: measure them on the size of those terms, `|v⁻| + |W||p|` and
    // `|v⁻||p| + ½ |p|ᵀ|W||p|` (at least 1), the scale of their round-off.
    let v0 = p.velocity();
    let (a, b, c) = (p.wtt(), p.wtn().abs(), p.wnn());
    let (pt, pn) = (s.pt.abs(), s.pn.abs());
    let vscale = (v0.x.abs() + a * pt + b * pn)
        .max(v0.y.abs() + b * pt + c * pn)
        .max(1.0);
    let escale =
        (v0.x.abs() * pt + v0.y.abs() * pn + 0.5 * (a * pt * pt + 2.0 * b * pt * pn + c * pn * pn))
            .max(1.0);
    let on = |x: f64, y: f64, scale: f64| (x - y).abs() / scale;
    let velocity =
        on(out.velocity_after.x, s.vt, vscale).max(on(out.velocity_after.y, s.vn, vscale));
    let pc = out
        .compression_impulse
        .unwrap_or_else(|| panic!("{:?}: no compression impulse for {p:?}", out.law));
    let compression_impulse = rel(pc, t.pc);
    let work_compression = on(out.work.compression, t.wc, escale);
    let work_restitution = on(out.work.restitution, s.wr, escale);
    let work_friction = on(out.work.friction, s.wt, escale);
    // ΔT two ways from the integration: the work integrals, and ½ (v⁻ + v⁺)·p.
    let half_sum = 0.5 * ((v0.x + s.vt) * s.pt + (v0.y + s.vn) * s.pn);
    let energy =
        on(out.energy_change, s.wn + s.wt, escale).max(on(out.energy_change, half_sum, escale));
    let halt = match out.detail {
        LawDetail::DarbouxKeller { slip_halt } => slip_halt,
        other => panic!("{:?}: unexpected detail {other:?}", out.law),
    };
    // The library reports the halt only if it happens before the end of the impact.
    let brute_halt = t.slip_halt.filter(|&ps| ps < s.pn);
    let slip_halt = match (halt, brute_halt) {
        (Some(x), Some(y)) => rel(x, y),
        (None, None) => 0.0,
        // A halt exactly at the end may be counted on either side.
        (Some(x), None) | (None, Some(x)) => rel(x, s.pn),
    };
    dev.impulse = dev.impulse.max(impulse);
    dev.velocity = dev.velocity.max(velocity);
    dev.compression_impulse = dev.compression_impulse.max(compression_impulse);
    dev.work_compression = dev.work_compression.max(work_compression);
    dev.work_restitution = dev.work_restitution.max(work_restitution);
    dev.work_friction = dev.work_friction.max(work_friction);
    dev.energy = dev.energy.max(energy);
    dev.slip_halt = dev.slip_halt.max(slip_halt);
    [
        impulse,
        velocity,
        compression_impulse,
        work_compression,
        work_restitution,
        work_friction,
        energy,
        slip_halt,
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

#[test]
fn darboux_keller_laws_match_brute_force_integration() {
    let mut rng = SplitMix64(0x1A2B_3C4D_5E6F_7081);
    let mut dev = [
        Deviations::default(),
        Deviations::default(),
        Deviations::default(),
    ];
    let mut worst: (f64, Option<(LawId, ContactProblem)>) = (0.0, None);
    let mut failures = Vec::new();
    let mut max_steps = 0;
    let mut halted = 0;
    let mut reversed_or_stuck = 0;
    for _ in 0..PROBLEMS {
        let p = random_problem(&mut rng);
        let dk = Dk::new(&p);
        for (i, term) in [
            Termination::Newton,
            Termination::Poisson,
            Termination::Energetic,
        ]
        .into_iter()
        .enumerate()
        {
            let trace = dk.integrate(term);
            max_steps = max_steps.max(trace.steps);
            if trace.slip_halt.is_some() {
                halted += 1;
            }
            if p.velocity().x == 0.0 || trace.slip_halt.is_some() {
                reversed_or_stuck += 1;
            }
            let out = term
                .law()
                .resolve(&p)
                .unwrap_or_else(|b| panic!("{term:?} broke down on {p:?}: {b}"));
            assert_eq!(out.law, term.law());
            let d = compare(&p, &out, &trace, &mut dev[i]);
            if d > worst.0 {
                worst = (d, Some((term.law(), p)));
            }
            if d > TOL && failures.len() < 10 {
                failures.push(format!(
                    "{term:?} deviates by {d:.3e} on {p:?}\n  library {out:?}\n  brute {trace:?}"
                ));
            }
        }
    }
    for (term, d) in ["newton", "poisson", "energetic"].iter().zip(&dev) {
        println!("{term:9} largest relative deviation {:.3e}: {d:?}", d.max());
    }
    println!(
        "worst {:.3e} ({:?}); max steps {max_steps}; {halted} runs with a slip halt, \
         {reversed_or_stuck} with stick or reversal",
        worst.0, worst.1
    );
    assert!(
        failures.is_empty(),
        "{} disagreements, e.g.:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(worst.0 <= TOL);
    // The sample must exercise the interesting regimes, not only straight slip.
    assert!(halted > PROBLEMS / 4, "only {halted} runs with a slip halt");
}

/// Hand-picked problems on the regime boundaries, where a sloppy event search would fail.
#[test]
fn boundary_cases_match_brute_force_integration() {
    let cases = [
        // Stick exactly on the cone |W_tn| = μ W_tt.
        (2.0, 1.0, 1.5, 0.3, -1.0, 0.5, 0.5),
        (2.0, -1.0, 1.5, 0.3, -1.0, 0.5, 0.5),
        // v_t⁻ = 0: immediate stick, immediate reversal either way.
        (2.0, 0.5, 1.5, 0.0, -1.0, 0.3, 0.5),
        (2.0, 0.5, 1.5, 0.0, -1.0, 0.1, 0.5),
        (2.0, -0.5, 1.5, 0.0, -1.0, 0.1, 0.5),
        // v_n decreases while slipping (μ s0 W_tn > W_nn), then the slip halts.
        (1.0, 0.9, 1.0, 1.0, -1.0, 2.0, 0.8),
        (1.0, -0.9, 1.0, -1.0, -1.0, 2.0, 1.0),
        // Frictionless with W_tn ≠ 0 (v_t crosses zero without changing the path).
        (1.0, 0.7, 1.0, -0.5, -1.0, 0.0, 0.6),
        // The seed's sphere.
        (
            3.5,
            0.0,
            1.0,
            30f64.to_radians().sin(),
            -30f64.to_radians().cos(),
            0.4,
            0.7,
        ),
        // e = 0 and e = 1.
        (1.0, 0.4, 2.0, 0.8, -0.7, 0.2, 0.0),
        (1.0, 0.4, 2.0, 0.8, -0.7, 0.2, 1.0),
    ];
    for (a, b, c, vt, vn, mu, e) in cases {
        let p = ContactProblem::from_entries(a, b, c, vt, vn, mu, e).unwrap();
        let dk = Dk::new(&p);
        for term in [
            Termination::Newton,
            Termination::Poisson,
            Termination::Energetic,
        ] {
            let trace = dk.integrate(term);
            let out = term.law().resolve(&p).unwrap();
            let d = compare(&p, &out, &trace, &mut Deviations::default());
            assert!(
                d <= TOL,
                "{term:?} deviates by {d:.3e} on {p:?}\n  library {out:?}\n  brute {trace:?}"
            );
        }
    }
}

/// The integrator itself, against a case solvable by hand: frictionless, `W_tn = 0`,
/// so `v_n = v_n⁻ + W_nn p_n` and every law ends at `p_f = (1+e) |v_n⁻| / W_nn`.
#[test]
fn integrator_reproduces_the_frictionless_solution() {
    let p = ContactProblem::from_entries(2.0, 0.0, 4.0, 1.0, -2.0, 0.0, 0.5).unwrap();
    let dk = Dk::new(&p);
    for term in [
        Termination::Newton,
        Termination::Poisson,
        Termination::Energetic,
    ] {
        let t = dk.integrate(term);
        assert!(rel(t.pc, 0.5) < 1e-15, "{term:?} {t:?}");
        assert!(rel(t.end.pn, 0.75) < 1e-15, "{term:?} {t:?}");
        assert!(rel(t.end.vn, 1.0) < 1e-15, "{term:?} {t:?}");
        // W_c = −v_n⁻²/(2 W_nn) = −0.5, W_r = e² · 0.5.
        assert!(rel(t.wc, -0.5) < 1e-15, "{term:?} {t:?}");
        assert!(rel(t.end.wr, 0.125) < 1e-15, "{term:?} {t:?}");
        assert_eq!(t.end.pt, 0.0);
        assert_eq!(t.end.vt, 1.0);
    }
}
