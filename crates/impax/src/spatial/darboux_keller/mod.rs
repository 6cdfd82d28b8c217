//! The spatial Darboux–Keller integration in normal impulse (theory §2, "Spatial"; Keller,
//! *Impact with friction*, J. Appl. Mech. 53 (1986) 1; Batlle, *Rough balanced collisions*,
//! J. Appl. Mech. 63 (1996) 168, for the jamb).
//!
//! The contact velocity `v = (v_t, v_n)` is linear in the impulse, `dv = W dp`, and Coulomb's
//! law makes the path `p_n ↦ (v, p_t, W_n, W_t)` the solution of an ordinary differential
//! equation in the normal impulse. Three stages, each exact or integrated to near machine
//! precision:
//!
//! 1. **Initial slip** (when `v_t⁻ ≠ 0`): with `ŝ = v_t/|v_t|` and `g = w_tn − μ W_tt ŝ`,
//!    ```text
//!    dv_t/dp_n = g,  dv_n/dp_n = w_nn − μ w_tn·ŝ,  dp_t/dp_n = −μ ŝ,
//!    dW_n/dp_n = v_n,  dW_t/dp_n = −μ |v_t|.
//!    ```
//!    The direction field is singular at `σ = |v_t| → 0`, where steps in `p_n` must shrink
//!    with `σ`, so the independent variable changes with the slip (module `slip`):
//!    * first choice wherever the slip turns or shrinks appreciably before the next normal
//!      event: the angle variable `x = ln(sin(δ_b/2)/sin(δ_a/2))` between the invariant rays
//!      behind and ahead of the direction (module `angle`), in which the direction equation
//!      is solved by the map and every other quantity is a quadrature on Chebyshev panels —
//!      smooth through near-zero passes, halts, nearly frozen slips; it hands back to the
//!      variables below only where it cannot apply (the slip on a ray to round-off, or the
//!      direction barely turning before the next event);
//!    * otherwise the normal impulse itself (module `p_n`), by an adaptive explicit
//!      Runge–Kutta pair of order 8 with error estimators of orders 5 and 3 (DOP853, Hairer,
//!      Nørsett & Wanner, *Solving ODEs I*, §II.5);
//!    * as soon as the slip shrinks steadily (`ŝ·g < −0.9 |g|`: near a centripetal invariant
//!      ray, or on an inward spiral), whatever its size, `u = ln σ` (module `log_sigma`),
//!      decreasing, in which the system is smooth all the way:
//!      ```text
//!      dφ/du = (ŝ × g)/(ŝ·g),  dp_n/du = σ/(ŝ·g),  d(·)/du = d(·)/dp_n · dp_n/du,
//!      ```
//!      until the series about the centripetal ray ahead (module `ray_series`: the normal
//!      form of the direction flow, every quadrature in closed form term by term) gives the
//!      whole rest of the slip, the halt at the ray's angle and any event before it to the
//!      tolerance (module `tail`); where that series does not converge (a weakly attracting
//!      ray), until `σ` has shrunk by `e⁻⁴⁰`, the remaining impulse `σ/|ŝ·g|` then added in
//!      closed form;
//!    * once the slip is small (below `σ⁻/20`) and not shrinking steadily, or on leaving `u`
//!      (`ŝ·g ≥ −0.7 |g|`: the direction swings while the slip passes near zero), the
//!      pseudo-time `τ` with `dp_n = σ dτ` (module `tau`), in which the system has no
//!      division and is smooth away from `v_t = 0` itself:
//!      ```text
//!      dv_t/dτ = σ w_tn − μ W_tt v_t,  dv_n/dτ = σ w_nn − μ w_tn·v_t,  dp_n/dτ = σ,
//!      dp_t/dτ = −μ v_t,  dW_n/dτ = σ v_n,  dW_t/dτ = −μ σ²,
//!      ```
//!      with the step bounded by the stability limit `3/(|w_tn| + μ|W_tt|)`; back to `u`
//!      when the slip shrinks steadily again, to `p_n` once it has grown past `σ⁻/10`.
//!
//!    Once the direction is on an invariant ray to the last bit of the result, the rest of
//!    the slip is straight, in closed form (module `tail`). No small epsilon decides the
//!    halt.
//! 2. **Stick** if `|W_tt⁻¹ w_tn| ≤ μ`: `dv_n/dp_n = w_nn − w_tnᵀ W_tt⁻¹ w_tn`, linear
//!    (module `linear`);
//! 3. otherwise **resumed slip** at once along the unique centrifugal invariant ray
//!    `(λ' I + μ W_tt) ŝ = w_tn`, `λ' > 0` ([`resumption_direction`]): straight, linear.
//!
//! Events (module `events`): the end of compression (`v_n = 0`), the termination of the law
//! (`Termination`), and a second compression (jamb: `v_n` falls back to zero after
//! compression ended; reported; for `poisson` every return to compression and its end).
//! Each is located on the discrete solution by re-stepping from the step's start (module
//! `step`: Illinois iteration, seeded by the seventh-order dense output of the step and
//! started on a bracket of ±1e-9 of the step around the seed), on a panel's interpolants in
//! the angle variable, or on the series, to near machine precision; on the straight pieces
//! they are exact.
//!
//! ## Layout
//!
//! This module runs the stages in order (`integrate_with`); each stage is a file:
//!
//! | file | what it holds |
//! |---|---|
//! | `state.rs` | the moving point of the path, the error scales, how the slip ended |
//! | `events.rs` | the event functions, which comes first, what each records |
//! | `linear.rs` | the straight pieces: stick, resumed slip, frictionless, unturnable slip |
//! | `slip.rs` | the initial slip: its data and the hand-over between its variables |
//! | `step.rs` | one adaptive DOP853 step in a slip variable, with event location |
//! | `p_n.rs`, `log_sigma.rs`, `tau.rs` | a slip variable each: state, right-hand side, run |
//! | `angle/` | the slip in the angle variable: the sweep by panels, the half-angle map |
//! | `field.rs` | the direction field of the slip, the invariant rays around a direction |
//! | `tail.rs` | the closed-form ends of a slip on or near an invariant ray |
//! | `ray_series.rs` | the series about an invariant ray |
//!
//! The integrators, the Chebyshev panels and the root finders are the library's shared
//! numerics (`crate::numerics`).

mod angle;
mod events;
mod field;
mod linear;
mod log_sigma;
mod p_n;
mod ray_series;
mod slip;
mod state;
mod step;
mod tail;
mod tau;

use self::events::Events;
use self::state::{Point, Scales, SlipEnd};
use super::outcome::{PhaseKind, Phases};
use super::ContactProblem;
use crate::law::{BreakdownReason, Options};
use crate::math::{norm_of, Mat2, Vec3};
#[cfg(doc)]
use crate::spatial::resumption_direction;

/// The termination rule of a Darboux–Keller law: where on the path `p_n ↦ v(p_n)` the impact
/// ends, `p_f`, given the coefficient of restitution `e` (`p_c` the end of compression,
/// `v_n(p_c) = 0`; `W_n = ∫ v_n dp_n` the normal work, `W_c = W_n(p_c)`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Termination {
    /// Newton's kinematic restitution (Newton 1686; Keller 1986): `v_n(p_f) = −e v_n⁻`.
    Newton,
    /// Poisson's kinetic restitution: the impulse of restitution is `e` times that of
    /// compression, `P_r(p_f) = e P_c(p_f)`, with `P_c` the normal impulse over which
    /// `v_n < 0` and `P_r` that over which `v_n ≥ 0` — `p_f = (1 + e) p_c` unless `v_n`
    /// falls back below zero after the end of compression (a jamb, Batlle 1996), whose
    /// phases then add to the compression (Stronge, *Impact Mechanics*, 2000, treats the
    /// kinetic coefficient through such a second compression). The end is always reached
    /// with `v_n ≥ 0` (`P_r` grows only there): an impact does not end approaching.
    Poisson,
    /// Stronge's energetic restitution (Stronge 1991; *Impact Mechanics*, 2000): the
    /// restitution work is `e²` times the magnitude of the compression work,
    /// `W_n(p_f) = (1 − e²) W_c`.
    Energetic,
}

/// The result of the integration: the end `p_f` of the path and what happened on the way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PathEnd {
    /// Impulse at the end, `(p_t, p_n)`.
    pub impulse: Vec3,
    /// Contact velocity at the end.
    pub velocity: Vec3,
    /// End of (the first) compression, if reached.
    pub compression_impulse: Option<f64>,
    /// Normal work in compression, `W_c = ∫₀^{p_c} v_n dp_n` (to the end if compression did
    /// not end).
    pub compression_work: f64,
    /// Normal work to the end, `W_n = ∫₀^{p_f} v_n dp_n`.
    pub normal_work: f64,
    /// Friction work to the end, `W_t = ∫₀^{p_f} v_t·dp_t`.
    pub friction_work: f64,
    /// The phases of the path: initial slip, stick or resumed slip, each with the normal
    /// impulse at its end.
    pub phases: Phases,
    /// Where the initial slip halted.
    pub slip_halt: Option<f64>,
    /// Where a second compression began.
    pub second_compression: Option<f64>,
    /// Accepted integration steps (and panels of the angle variable, and located events).
    pub steps: u32,
}

/// Integrate the Darboux–Keller equations of `problem` (`dv = W dp` under Coulomb's law, in
/// the normal impulse; Keller 1986 and the module documentation) to the termination `term`
/// with the options `opts`, calling `observe(p_n, v)` at every accepted point (for
/// hodographs).
///
/// (Checked in the unit test `integrate_frictionless_and_energetic` below.)
///
/// The equations are homogeneous: with `v' = a v` and `W' = b W` the path is the same with
/// `p' = (a/b) p` and works `W' = (a²/b) W`. The path is integrated in units where `|v_n⁻|`
/// and `w_nn` are in `[1, 2)` (powers of two from their binary exponents — exact, and the
/// same units for any power-of-two multiple of the problem) and scaled back; a slip above
/// `2⁴⁵⁰` there that the impact turns (its square would overflow) in units where it is
/// below. Each quantity's error is controlled on its own scale (tangential and normal
/// velocity, impulse, normal and friction work), so a slip hundreds of orders of magnitude
/// above or below the normal velocity neither swamps nor is swamped by it; a slip too fast
/// for the impact to turn is the straight path in closed form. A slip or coupling `w_tn`
/// below [`NEGLIGIBLE_SLIP`](crate::spatial::NEGLIGIBLE_SLIP) in these units is taken as
/// zero ([`ContactProblem::without_negligible_slip`]): its effect on the result is below
/// that fraction of its scale.
///
/// Told whether `observe` does anything: when it does not (`observing`
/// false), the points inside a panel of the angle variable carry `p_n` only where an event
/// reads it, and the cumulative integral for it is formed only there.
pub(crate) fn integrate_with(
    problem: &ContactProblem,
    term: Termination,
    opts: &Options,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<PathEnd, BreakdownReason> {
    let v = problem.velocity();
    let w = problem.w();
    // Units where v_n⁻ and W_nn are in [1, 2) (the normal works ∝ v_n²/W_nn; a grazing
    // impact, v_n⁻ = −1e-300 beside v_t⁻ = 0.5, keeps its restitution): powers of two from
    // their binary exponents, so that a problem and any power-of-two multiple of it are
    // integrated as the same problem, bit for bit.
    let a = crate::math::exact_unit_factor(v.z.abs(), v.as_slice());
    let b = crate::math::exact_unit_factor(w[(2, 2)], w.as_slice());
    let flushed = problem.without_negligible_slip(a, b);
    let problem = flushed.as_ref().unwrap_or(problem);
    let first = if a == 1.0 && b == 1.0 {
        integrate_scaled(problem, term, opts, observing, observe)?
    } else {
        integrate_in_units(problem, a, b, term, opts, observing, observe)?
    };
    match first {
        Integrated::End(end) => Ok(end),
        // (A slip that the impact turns, far above the normal velocity: once more in units
        // where its square is representable.)
        Integrated::HugeSlip(k) => {
            match integrate_in_units(problem, a * k, b, term, opts, observing, observe)? {
                Integrated::End(end) => Ok(end),
                Integrated::HugeSlip(_) => Err(BreakdownReason::Overflow),
            }
        }
    }
}

/// [`integrate_scaled`] on `problem` with velocities times `a` and `W` times `b` (powers of
/// two: exact), the result scaled back.
fn integrate_in_units(
    problem: &ContactProblem,
    a: f64,
    b: f64,
    term: Termination,
    opts: &Options,
    observing: bool,
    observe: &mut dyn FnMut(f64, Vec3),
) -> Result<Integrated, BreakdownReason> {
    // Built without the checks of `new`: in these units the approach energy of a grazing
    // impact need not be representable, and nothing here reads it.
    let scaled = problem.in_units(a, b);
    // (Each factor a power of two: exact, and (b/a)/a without overflow of a².)
    let (kp, kv, kw) = (b / a, 1.0 / a, (b / a) / a);
    let mut end = match integrate_scaled(&scaled, term, opts, observing, &mut |p, v| {
        observe(p * kp, v * kv)
    })? {
        Integrated::End(end) => end,
        huge => return Ok(huge),
    };
    end.impulse *= kp;
    end.velocity *= kv;
    end.compression_impulse = end.compression_impulse.map(|x| x * kp);
    end.compression_work *= kw;
    end.normal_work *= kw;
    end.friction_work *= kw;
    end.phases.scale_impulse(kp);
    end.slip_halt = end.slip_halt.map(|x| x * kp);
    end.second_compression = end.second_compression.map(|x| x * kp);
    Ok(Integrated::End(end))
}

/// What [`integrate_scaled`] did: the end of the path, or nothing — a slip too fast for
/// these units, to be integrated with velocities times the factor given.
enum Integrated {
    End(PathEnd),
    HugeSlip(f64),
}

/// The largest slip speed integrated in units where `v_n⁻` is near one: `2⁴⁵⁰` (its square
/// and products of it stay far from overflow).
const HUGE_SLIP: f64 = 2.907_354_897_182_427_6e135;

/// The path of `problem` in the units given (see [`integrate`]): the frictionless path in
/// closed form, or the initial slip (a slip too fast to turn in closed form; too fast for
/// these units handed back), then stick or the resumed slip.
fn integrate_scaled(
    problem: &ContactProblem,
    term: Termination,
    opts: &Options,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Integrated, BreakdownReason> {
    let wtt: Mat2 = problem.wtt();
    let wtn = problem.wtn();
    let wnn = problem.wnn();
    let mu = problem.friction();
    let v0 = problem.velocity();
    let mut ev = Events::new(term, problem.restitution(), v0.z);
    let scales = Scales::of(problem, opts.effective_rtol());
    let mut pt = Point::start(v0);
    observe(0.0, v0);
    if mu == 0.0 {
        let (end, phases, slip_halt) = linear::frictionless(problem, &mut ev);
        observe(end.p, end.velocity());
        return Ok(Integrated::End(finish(&end, &ev, phases, slip_halt, 0)));
    }
    let mut phases = Phases::new();
    let mut steps = 0u32;
    let mut slip_halt = None;
    let phi0 = v0.y.atan2(v0.x);

    // ---- Stage 1: initial slip ----
    if pt.vt.x != 0.0 || pt.vt.y != 0.0 {
        if let Some(end) = linear::rigid_slip(&wtt, wtn, wnn, mu, scales, &mut pt, &mut ev)? {
            phases.push(
                PhaseKind::Slip {
                    from: phi0,
                    to: phi0,
                },
                pt.p,
            );
            observe(pt.p, pt.velocity());
            return Ok(Integrated::End(finish(&end, &ev, phases, None, 0)));
        }
        let sigma = norm_of(pt.vt);
        if sigma > HUGE_SLIP {
            // A slip that the impact does turn (it compresses the contact further while
            // slipping, `w_nn − μ w_tn·ŝ ≤ 0`, or the law ends only after the slip has
            // changed) and whose square would overflow in these units: to be integrated
            // in units where it is below `2⁴⁵⁰`, the normal velocity smaller (its square
            // still representable, and negligible beside the compression the slip drives).
            let k = crate::math::exact_unit_factor(2.0 * sigma / HUGE_SLIP, &[sigma, v0.z]);
            return Ok(Integrated::HugeSlip(k));
        }
        let stage = slip::run(
            problem, scales, &mut pt, &mut ev, &mut steps, observing, observe,
        )?;
        let (to, halted) = match stage {
            SlipEnd::Terminated { phi } => (phi, false),
            SlipEnd::Halted { phi } => (phi, true),
        };
        phases.push(PhaseKind::Slip { from: phi0, to }, pt.p);
        if !halted {
            return Ok(Integrated::End(finish(&pt, &ev, phases, None, steps)));
        }
        slip_halt = Some(pt.p);
    }

    // ---- Stage 2: stick or resumed slip, linear in p_n ----
    let piece = linear::stick_or_resumed(problem)?;
    let kind = piece.kind;
    if !piece.run(&mut pt, &mut ev, mu)? {
        return Err(BreakdownReason::NoSeparation);
    }
    observe(pt.p, pt.velocity());
    phases.push(kind, pt.p);
    Ok(Integrated::End(finish(&pt, &ev, phases, slip_halt, steps)))
}

/// The result at the end point `pt` of the path.
fn finish(pt: &Point, ev: &Events, phases: Phases, slip_halt: Option<f64>, steps: u32) -> PathEnd {
    let pc = ev.pc.filter(|&pc| pc <= pt.p);
    PathEnd {
        impulse: Vec3::new(pt.pt.x, pt.pt.y, pt.p),
        velocity: pt.velocity(),
        compression_impulse: pc,
        compression_work: if pc.is_some() { ev.wc } else { pt.wn },
        normal_work: pt.wn,
        friction_work: pt.wt,
        phases,
        slip_halt: slip_halt.filter(|&s| s < pt.p),
        second_compression: ev.second.filter(|&s| s < pt.p),
        steps,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Without friction every termination is `p_f = (1 + e) p_c`; with friction Stronge's
    /// `W_n = (1 − e²) W_c` holds at the end and `ΔT = W_n + W_t` is a loss.
    #[test]
    fn integrate_frictionless_and_energetic() {
        let w = [2.0, 0.6, 0.3, 1.0, -0.2, 1.5];
        let opts = Options::default();
        // Without friction every termination is p_f = (1 + e) p_c with p_c = −v_n⁻/w_nn.
        let p = ContactProblem::from_upper(w, [0.3, 0.8, -1.0], 0.0, 0.5).unwrap();
        let end = integrate_with(&p, Termination::Newton, &opts, true, &mut |_, _| {}).unwrap();
        assert!((end.impulse.z - 1.5 / 1.5).abs() < 1e-15);
        // With friction, Stronge's: W_n = (1 − e²) W_c at the end, and the energy change
        // ΔT = W_n + W_t is a loss.
        let p = ContactProblem::from_upper(w, [0.3, 0.8, -1.0], 0.8, 0.7).unwrap();
        let mut points = 0;
        let end = integrate_with(&p, Termination::Energetic, &opts, true, &mut |_, _| {
            points += 1
        })
        .unwrap();
        let (wc, wn) = (end.compression_work, end.normal_work);
        assert!((wn - (1.0 - 0.7 * 0.7) * wc).abs() < 1e-12 * wc.abs());
        assert!(wn + end.friction_work < 0.0 && points > 2);
    }
}
