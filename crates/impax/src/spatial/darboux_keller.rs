//! The spatial Darboux–Keller integration in normal impulse (theory §2, "Spatial").
//!
//! Three stages, each exact or integrated to near machine precision:
//!
//! 1. **Initial slip** (when `v_t⁻ ≠ 0`): with `ŝ = v_t/|v_t|` and `g = w_tn − μ W_tt ŝ`,
//!    ```text
//!    dv_t/dp_n = g,  dv_n/dp_n = w_nn − μ w_tn·ŝ,  dp_t/dp_n = −μ ŝ,
//!    dW_n/dp_n = v_n,  dW_t/dp_n = −μ |v_t|,
//!    ```
//!    integrated by an adaptive explicit Runge–Kutta pair of order 8 with error estimators
//!    of orders 5 and 3 (DOP853, Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.5) in
//!    `p_n`. The direction field is singular at `σ = |v_t| → 0`, and steps in `p_n` must
//!    shrink with `σ`, so the independent variable changes:
//!    * first choice wherever the slip turns or shrinks appreciably before the next normal
//!      event: the angle variable `x = ln(sin(δ_b/2)/sin(δ_a/2))` between the invariant
//!      rays behind and ahead of the direction (module `angle`), in which the direction
//!      equation is solved by the map and every other quantity is a quadrature on
//!      Chebyshev panels — smooth through near-zero passes, halts, nearly frozen slips; it
//!      hands back to the variables below only where it cannot apply (the slip on a ray to
//!      round-off, or the direction barely turning before the next event);
//!    * as soon as the slip shrinks steadily (`ŝ·g < −0.9 |g|`: near a centripetal
//!      invariant ray, or on an inward spiral), whatever its size, it becomes `u = ln σ`
//!      (decreasing), in which the system is smooth all the way (the direction is carried
//!      as a vector and `σ` as a state, `dσ/du = σ`, so no trigonometric function is
//!      evaluated):
//!      ```text
//!      dφ/du = (ŝ × g)/(ŝ·g),  dp_n/du = σ/(ŝ·g),  d(·)/du = d(·)/dp_n · dp_n/du,
//!      ```
//!      integrated until the series about the centripetal ray ahead
//!      (module `ray_series`: the normal form of the direction flow, every quadrature in
//!      closed form term by term) gives the whole rest of the slip, the halt at the ray's
//!      angle and any event before it to the tolerance; where that series does not converge
//!      (a weakly attracting ray), until `σ` has shrunk by `e⁻⁴⁰`, the remaining impulse
//!      `σ/|ŝ·g|` then added in closed form;
//!    * once the slip is small (below `σ⁻/20`) and not shrinking steadily, or on leaving
//!      `u` (`ŝ·g ≥ −0.7 |g|`: the direction swings while the slip passes near zero), it
//!      becomes the pseudo-time `τ` with `dp_n = σ dτ`, in which the
//!      system has no division and is smooth away from `v_t = 0` itself:
//!      ```text
//!      dv_t/dτ = σ w_tn − μ W_tt v_t,  dv_n/dτ = σ w_nn − μ w_tn·v_t,  dp_n/dτ = σ,
//!      dp_t/dτ = −μ v_t,  dW_n/dτ = σ v_n,  dW_t/dτ = −μ σ²,
//!      ```
//!      with the step bounded by the stability limit `3/(|w_tn| + μ|W_tt|)`; back to `u`
//!      when the slip shrinks steadily again, to `p_n` once it has grown past `σ⁻/10`.
//!
//!    No small epsilon decides the halt.
//! 2. **Stick** if `|W_tt⁻¹ w_tn| ≤ μ`: `dv_n/dp_n = w_nn − w_tnᵀ W_tt⁻¹ w_tn`, linear;
//! 3. otherwise **resumed slip** at once along the unique centrifugal invariant ray
//!    `(λ' I + μ W_tt) ŝ = w_tn`, `λ' > 0` ([`resumption_direction`]): straight, linear.
//!
//! Events: the end of compression (`v_n = 0`), the termination of the law (`newton`
//! `v_n = −e v_n⁻`; `poisson` `p_n = (1+e) p_c`, or after a jamb the point where the
//! restitution impulse reaches `e` times the compression impulse of every phase — see
//! [`Termination::Poisson`]; `energetic` `W_n = (1 − e²) W_c`), and a second compression
//! (jamb: `v_n` falls back to zero after compression ended; reported; for `poisson` every
//! return to compression and its end). Each is located on the discrete solution by re-stepping from the step's start
//! (Illinois iteration, seeded by the seventh-order dense output of the step and started
//! on a bracket of ±1e-9 of the step around the seed), to near machine precision; in the
//! linear stages they are exact.

mod angle;

use super::invariant::{polish_ray, resumption_direction};
use super::outcome::{Phase3Kind, Phases3};
use super::ray_series::{Field, RaySeries};
use super::ContactProblem3;
use crate::law::BreakdownReason;
use crate::math::{norm_of, Mat2, Vec2, Vec3};
use crate::numerics::dop853::{dop853_step, error_measure, Dense, Step};
use crate::numerics::roots::{illinois, newton_from_seed};

/// The termination rule of a Darboux–Keller law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Termination {
    /// `v_n(p_f) = −e v_n⁻`.
    Newton,
    /// Poisson's kinetic restitution: the impulse of restitution is `e` times that of
    /// compression, `P_r(p_f) = e P_c(p_f)`, with `P_c` the normal impulse over which
    /// `v_n < 0` and `P_r` that over which `v_n ≥ 0` — `p_f = (1 + e) p_c` unless `v_n`
    /// falls back below zero after the end of compression (a jamb, Batlle 1996), whose
    /// phases then add to the compression (Stronge, *Impact Mechanics*, 2000, treats the
    /// kinetic coefficient through such a second compression). The end is always reached
    /// with `v_n ≥ 0` (`P_r` grows only there): an impact does not end approaching.
    Poisson,
    /// `W_n(p_f) = (1 − e²) W_c`.
    Energetic,
}

/// Default relative tolerance of the adaptive integration (per step, on the velocity,
/// impulse and work scales of the problem). With it the integration agrees with an
/// independent reference to better than 1e-10 relative (`tests/spatial_reference.rs`).
pub const RTOL: f64 = 1e-12;

/// Options of the spatial Darboux–Keller integration.
///
/// ```
/// use impax::{LawId, spatial::{ContactProblem3, SpatialOptions}};
/// let p = ContactProblem3::from_upper([2.0, 0.6, 0.3, 1.0, -0.2, 1.5], [0.3, 0.8, -1.0], 0.8, 0.7)
///     .unwrap();
/// let fine = LawId::Energetic.resolve3_with(&p, &SpatialOptions { rtol: 1e-13 }).unwrap();
/// let default = LawId::Energetic.resolve3(&p).unwrap();
/// assert!((fine.impulse - default.impulse).norm() < 1e-10 * default.impulse.norm());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialOptions {
    /// Relative tolerance per step (clamped to `[1e-14, 1e-4]`; NaN gives the default
    /// [`RTOL`]).
    pub rtol: f64,
}

impl Default for SpatialOptions {
    fn default() -> Self {
        SpatialOptions { rtol: RTOL }
    }
}

impl SpatialOptions {
    /// The tolerance actually used.
    #[inline]
    pub fn effective_rtol(&self) -> f64 {
        if self.rtol.is_nan() {
            RTOL
        } else {
            self.rtol.clamp(1e-14, 1e-4)
        }
    }
}

/// How far below the switch the logarithmic stage integrates (`σ` shrinks by `e^-40`).
const LOG_SPAN: f64 = 40.0;

/// The result of the integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathEnd {
    /// Impulse at the end.
    pub impulse: Vec3,
    /// Contact velocity at the end.
    pub velocity: Vec3,
    /// End of (the first) compression, if reached.
    pub compression_impulse: Option<f64>,
    /// Normal work in compression.
    pub compression_work: f64,
    /// Normal work to the end.
    pub normal_work: f64,
    /// Friction work to the end.
    pub friction_work: f64,
    /// Phases.
    pub phases: Phases3,
    /// Where the initial slip halted.
    pub slip_halt: Option<f64>,
    /// Where a second compression began.
    pub second_compression: Option<f64>,
    /// Accepted integration steps.
    pub steps: u32,
}

/// The moving point of the integration, whatever the independent variable.
#[derive(Debug, Clone, Copy)]
struct Point {
    p: f64,
    vt: Vec2,
    vn: f64,
    pt: Vec2,
    wn: f64,
    wt: f64,
}

/// Event bookkeeping shared by the stages.
#[derive(Clone, Copy)]
struct Events {
    term: Termination,
    e: f64,
    target: f64,
    pc: Option<f64>,
    wc: f64,
    second: Option<f64>,
    /// Poisson: the normal impulse of the compression phases after the first (`v_n < 0`
    /// again after a jamb) that have ended.
    recompressed: f64,
    /// Poisson: where the current compression phase after the first began, while in one.
    again: Option<f64>,
}

impl Events {
    /// The termination function, increasing through zero at the end (only after `p_c`).
    ///
    /// Poisson's: the restitution impulse (where `v_n ≥ 0`) reaches `e` times the
    /// compression impulse (where `v_n < 0`), `p − C ≥ e C`, i.e. `p − (1+e) C` with
    /// `C = p_c + recompressed` the compression impulse so far; constant (and negative)
    /// during a later compression phase, which adds to `C` when it ends.
    #[inline]
    fn terminal(&self, pt: &Point) -> f64 {
        match self.term {
            Termination::Newton => pt.vn - self.target,
            Termination::Poisson => {
                let c = self.pc.unwrap_or(f64::INFINITY) + self.recompressed;
                self.again.unwrap_or(pt.p) - (1.0 + self.e) * c
            }
            Termination::Energetic => pt.wn - (1.0 - self.e * self.e) * self.wc,
        }
    }

    /// Whether every compression phase is tracked (Poisson: its termination counts them).
    #[inline]
    fn counts_compression(&self) -> bool {
        self.term == Termination::Poisson
    }
}

/// Scales for the error control, each of its own quantity (the slip and the normal velocity
/// can differ by hundreds of orders of magnitude: a grazing impact, a slip far below the
/// normal velocity), and the relative tolerance.
#[derive(Clone, Copy)]
struct Scales {
    /// Tangential velocity: `σ⁻` plus the most the impact can change it, `|g|_max p`.
    vt: f64,
    /// Normal velocity `|v_n⁻|`.
    vn: f64,
    /// Normal impulse `(1+e) |v_n⁻| / w_nn` (beyond it the relative part takes over).
    p: f64,
    /// Normal work `vn p`.
    wn: f64,
    /// Friction work `vt p`.
    wt: f64,
    rtol: f64,
}

/// Integrate the Darboux–Keller equations of `problem` to the termination `term` with the
/// options `opts`, calling `observe(p_n, v)` at every accepted point (for hodographs).
///
/// The equations are homogeneous: with `v' = a v` and `W' = b W` the path is the same with
/// `p' = (a/b) p` and works `W' = (a²/b) W`. The path is integrated in units where `|v_n⁻|`
/// and `w_nn` are in `[1, 2)` (powers of two from their binary exponents — exact, and the
/// same units for any power-of-two multiple of the problem) and scaled back; a slip above
/// `2⁴⁵⁰` there that the impact turns (its square would overflow) in units where it is
/// below. Each quantity's error is controlled on its own scale (tangential and normal
/// velocity, impulse, normal and friction work), so a slip hundreds of orders of magnitude
/// above or below the normal velocity neither swamps nor is swamped by it; a slip too fast
/// for the impact to turn is the straight path in closed form.
pub fn integrate(
    problem: &ContactProblem3,
    term: Termination,
    opts: &SpatialOptions,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<PathEnd, BreakdownReason> {
    integrate_with(problem, term, opts, true, observe)
}

/// [`integrate`], told whether `observe` does anything: when it does not (`observing`
/// false), the points inside a panel of the angle variable carry `p_n` only where an event
/// reads it, and the cumulative integral for it is formed only there.
pub(crate) fn integrate_with(
    problem: &ContactProblem3,
    term: Termination,
    opts: &SpatialOptions,
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
    problem: &ContactProblem3,
    a: f64,
    b: f64,
    term: Termination,
    opts: &SpatialOptions,
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

fn integrate_scaled(
    problem: &ContactProblem3,
    term: Termination,
    opts: &SpatialOptions,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<Integrated, BreakdownReason> {
    let wtt: Mat2 = problem.wtt();
    let wtn = problem.wtn();
    let wnn = problem.wnn();
    let mu = problem.friction();
    let e = problem.restitution();
    let v0 = problem.velocity();
    let mut ev = Events {
        term,
        e,
        target: -e * v0.z,
        pc: None,
        wc: 0.0,
        second: None,
        recompressed: 0.0,
        again: None,
    };
    let scales = {
        let vn = -v0.z;
        let p = (1.0 + e) * vn / wnn;
        let vt = norm_of(v0.xy()) + (norm_of(wtn) + mu * wtt.norm()) * p;
        Scales {
            vt,
            vn,
            p,
            wn: vn * p,
            wt: vt * p,
            rtol: opts.effective_rtol(),
        }
    };
    let mut pt = Point {
        p: 0.0,
        vt: v0.xy(),
        vn: v0.z,
        pt: Vec2::zeros(),
        wn: 0.0,
        wt: 0.0,
    };
    observe(0.0, v0);
    let mut phases = Phases3::new();
    if mu == 0.0 {
        // Frictionless: a straight path p = p_n (0, 0, 1); v_n is linear and the three
        // terminations coincide at p_f = (1+e) p_c.
        let pc = -v0.z / wnn;
        let pf = (1.0 + e) * pc;
        let vt = v0.xy() + wtn * pf;
        let vt0 = v0.xy();
        let through_zero = vt0.x * wtn.y - vt0.y * wtn.x == 0.0 && vt0.dot(&wtn) < 0.0;
        let halt = norm_of(vt0) / norm_of(wtn);
        if through_zero && halt < pf {
            // The slip runs straight through zero and continues along w_tn.
            let a = vt0.y.atan2(vt0.x);
            phases.push(Phase3Kind::Slip { from: a, to: a }, halt);
        }
        let kind = if through_zero && halt < pf {
            Phase3Kind::Resumed {
                angle: wtn.y.atan2(wtn.x),
            }
        } else if v0.x != 0.0 || v0.y != 0.0 {
            Phase3Kind::Slip {
                from: v0.y.atan2(v0.x),
                to: vt.y.atan2(vt.x),
            }
        } else if wtn.norm() > 0.0 {
            Phase3Kind::Resumed {
                angle: wtn.y.atan2(wtn.x),
            }
        } else {
            Phase3Kind::Stick
        };
        phases.push(kind, pf);
        ev.pc = Some(pc);
        ev.wc = pc * (v0.z + 0.5 * wnn * pc);
        let end = Point {
            p: pf,
            vt,
            vn: v0.z + wnn * pf,
            pt: Vec2::zeros(),
            wn: pf * (v0.z + 0.5 * wnn * pf),
            wt: 0.0,
        };
        observe(pf, Vec3::new(vt.x, vt.y, end.vn));
        let slip_halt = (through_zero && halt < pf).then_some(halt);
        return Ok(Integrated::End(finish(&end, &ev, phases, slip_halt, 0)));
    }
    let mut steps = 0u32;
    let mut slip_halt = None;
    let phi0 = v0.y.atan2(v0.x);

    // ---- Stage 1: initial slip ----
    if pt.vt.x != 0.0 || pt.vt.y != 0.0 {
        if let Some(end) = rigid_slip(&wtt, wtn, wnn, mu, scales, &mut pt, &mut ev)? {
            phases.push(
                Phase3Kind::Slip {
                    from: phi0,
                    to: phi0,
                },
                pt.p,
            );
            observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
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
        // The centrifugal invariant ray, if any: the direction of resumption (theory §2).
        let centrifugal = resumption_direction(problem).map(|(dir, rate)| Centrifugal {
            dir,
            rate,
            slope: problem.resumed_slope(rate),
        });
        let stage = slip_stage(
            &wtt,
            wtn,
            wnn,
            mu,
            centrifugal,
            scales,
            &mut pt,
            &mut ev,
            &mut steps,
            observing,
            observe,
        )?;
        match stage {
            SlipEnd::Terminated { phi } => {
                phases.push(
                    Phase3Kind::Slip {
                        from: phi0,
                        to: phi,
                    },
                    pt.p,
                );
                return Ok(Integrated::End(finish(&pt, &ev, phases, None, steps)));
            }
            SlipEnd::Halted { phi } => {
                phases.push(
                    Phase3Kind::Slip {
                        from: phi0,
                        to: phi,
                    },
                    pt.p,
                );
                slip_halt = Some(pt.p);
            }
        }
    }

    // ---- Stage 2: stick or resumed slip, linear in p_n ----
    // The ratio and the slope of stick from W = L D Lᵀ: the slope is the last pivot, accurate
    // where w_nn + w_tn·λ would cancel (an ill-conditioned W).
    let (lambda, stick_slope) = problem.stick();
    let piece = if lambda.norm() <= mu {
        Linear {
            kind: Phase3Kind::Stick,
            ratio: lambda,
            slope: stick_slope,
            dir: Vec2::zeros(),
            sigma: 0.0,
            dsigma: 0.0,
            length: f64::INFINITY,
        }
    } else {
        let (s, rate) = resumption_direction(problem).ok_or(BreakdownReason::NoSeparation)?;
        Linear {
            kind: Phase3Kind::Resumed {
                angle: s.y.atan2(s.x),
            },
            ratio: -mu * s,
            slope: problem.resumed_slope(rate),
            dir: s,
            sigma: 0.0,
            dsigma: rate,
            length: f64::INFINITY,
        }
    };
    let kind = piece.kind;
    match linear_piece(&piece, &mut pt, &mut ev, mu)? {
        true => {
            observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
            phases.push(kind, pt.p);
            Ok(Integrated::End(finish(&pt, &ev, phases, slip_halt, steps)))
        }
        false => Err(BreakdownReason::NoSeparation),
    }
}

/// The centrifugal invariant ray: there is at most one, the solution `ŝ` of
/// `(λ' I + μ W_tt) ŝ = w_tn` with `λ' > 0` ([`resumption_direction`]), along which the
/// slip grows at the rate `λ'` and `v_n` changes at `slope` ([`ContactProblem3`]'s
/// `resumed_slope`).
#[derive(Clone, Copy)]
struct Centrifugal {
    dir: Vec2,
    rate: f64,
    slope: f64,
}

/// A slip settled on an invariant ray (see `slip_stage`).
#[derive(Clone, Copy)]
enum Settled {
    /// Shrinking along `dir` at the rate `rate < 0`, to a halt.
    Centripetal { dir: Vec2, rate: f64 },
    /// Growing along the centrifugal ray.
    Centrifugal(Centrifugal),
}

/// A slip so fast beside the normal velocity that the impact cannot turn it: `|dv_t/dp_n| =
/// |g| ≤ G = |w_tn| + μ ‖W_tt‖`, so over the normal impulse `L = ε σ⁻/(4G)` the direction
/// turns by less than `ε/4` and the speed changes at the constant rate `ŝ·g` — the path is
/// straight to round-off. If the law ends within `L` on it (every event in closed form),
/// that is the end: the integration is not needed (and its squares of `σ` could overflow).
/// Tried only where `4 G` times the normal impulse scale is below `ε σ⁻`; `None` if the law
/// does not end within `L` (then the integration takes over).
fn rigid_slip(
    wtt: &Mat2,
    wtn: Vec2,
    wnn: f64,
    mu: f64,
    sc: Scales,
    pt: &mut Point,
    ev: &mut Events,
) -> Result<Option<Point>, BreakdownReason> {
    let sigma = norm_of(pt.vt);
    let g_max = norm_of(wtn) + mu * wtt.norm();
    let rigid = 4.0 * g_max * sc.p <= f64::EPSILON * sigma;
    if !rigid {
        return Ok(None);
    }
    let dir = pt.vt / sigma;
    let piece = Linear {
        kind: Phase3Kind::Slip { from: 0.0, to: 0.0 },
        ratio: -mu * dir,
        slope: wnn - mu * wtn.dot(&dir),
        dir,
        sigma,
        dsigma: dir.dot(&(wtn - mu * (wtt * dir))),
        length: f64::EPSILON * sigma / (4.0 * g_max),
    };
    let (mut end, mut events) = (*pt, *ev);
    if linear_piece(&piece, &mut end, &mut events, mu)? {
        (*pt, *ev) = (end, events);
        Ok(Some(end))
    } else {
        Ok(None)
    }
}

/// A straight piece of the path: friction ratio `ratio`, slip `σ dir` with `σ` changing at
/// rate `dsigma` from `sigma`, of normal-impulse length `length`.
struct Linear {
    kind: Phase3Kind,
    ratio: Vec2,
    /// `dv_n/dp_n` on the piece, `w_nn + w_tn·ratio`.
    slope: f64,
    dir: Vec2,
    sigma: f64,
    dsigma: f64,
    length: f64,
}

/// Advance along a straight piece in closed form, locating the end of compression, a second
/// compression and the termination exactly. Returns `true` if the law terminated in the
/// piece (`pt` is then the end point), `false` if the piece was run to its end.
fn linear_piece(
    piece: &Linear,
    pt: &mut Point,
    ev: &mut Events,
    mu: f64,
) -> Result<bool, BreakdownReason> {
    let kn = piece.slope;
    let start = *pt;
    let at = |x: f64| -> Point {
        Point {
            p: start.p + x,
            vt: piece.dir * (piece.sigma + piece.dsigma * x),
            vn: start.vn + kn * x,
            pt: start.pt + piece.ratio * x,
            wn: start.wn + x * (start.vn + 0.5 * kn * x),
            wt: start.wt - mu * x * (piece.sigma + 0.5 * piece.dsigma * x),
        }
    };
    // Smallest x ≥ 0 past the minimum of the work with v x + ½ kn x² = w.
    let work_root = |v: f64, w: f64| -> Option<f64> {
        let disc = v * v + 2.0 * kn * w;
        if disc < 0.0 || kn <= 0.0 && v <= 0.0 {
            return None;
        }
        let sq = disc.max(0.0).sqrt();
        let x = if v >= 0.0 {
            if v + sq > 0.0 {
                2.0 * w / (v + sq)
            } else {
                0.0
            }
        } else {
            (-v + sq) / kn
        };
        (x >= 0.0).then_some(x)
    };
    if ev.pc.is_none() {
        if kn > 0.0 {
            let x = -start.vn / kn;
            if x <= piece.length {
                let c = at(x);
                ev.pc = Some(c.p);
                ev.wc = c.wn;
            }
        }
        if ev.pc.is_none() {
            if !piece.length.is_finite() {
                return Err(BreakdownReason::NoSeparation);
            }
            *pt = at(piece.length);
            return Ok(false);
        }
    } else if ev.second.is_none() && start.vn > 0.0 && kn < 0.0 {
        let x = -start.vn / kn;
        if x <= piece.length {
            ev.second = Some(start.p + x);
        }
    }
    let pc = ev.pc.expect("set above");
    let x_end = match ev.term {
        Termination::Newton => {
            if kn > 0.0 {
                Some(((ev.target - start.vn) / kn).max(0.0))
            } else if start.vn >= ev.target {
                Some(0.0)
            } else {
                None
            }
        }
        Termination::Poisson => poisson_end(ev, &start, kn, piece.length),
        Termination::Energetic => {
            if pc >= start.p && kn > 0.0 {
                // Compression ends inside this piece: from p_c (v_n = 0) the restitution
                // work −e² W_c is reached at x = e √2 √(−W_c) / √k_n — no cancellation, and
                // no overflow of the quotient −W_c / k_n where x itself is representable.
                let root = (-ev.wc).max(0.0).sqrt() / kn.sqrt();
                Some(pc - start.p + ev.e * std::f64::consts::SQRT_2 * root)
            } else {
                let need = (1.0 - ev.e * ev.e) * ev.wc - start.wn;
                if need <= 0.0 && start.p >= pc && start.vn >= 0.0 {
                    Some(0.0)
                } else {
                    work_root(start.vn, need)
                }
            }
        }
    };
    match x_end {
        Some(x) if x <= piece.length => {
            *pt = at(x);
            if ev.term == Termination::Newton && kn > 0.0 && start.vn <= ev.target {
                // Newton's rule holds exactly at its end (not only to the round-off of the
                // path's normal velocity, which after a long compression can exceed it).
                pt.vn = ev.target;
            }
            Ok(true)
        }
        _ if piece.length.is_finite() => {
            *pt = at(piece.length);
            Ok(false)
        }
        _ => Err(BreakdownReason::NoSeparation),
    }
}

/// Where Poisson's law ends on a straight piece from `start` (`v_n` of slope `kn`, of
/// normal-impulse length `length`), after the end of the first compression: `None` if not
/// in the piece. The restitution impulse (where `v_n ≥ 0`) must reach `e` times the
/// compression impulse `C` (where `v_n < 0`, every phase); so a later compression inside the
/// piece is followed to its end, which adds to `C`, and the law never ends while `v_n < 0`.
fn poisson_end(ev: &mut Events, start: &Point, kn: f64, length: f64) -> Option<f64> {
    let pc = ev.pc.expect("after the first compression");
    let mut from = 0.0;
    if ev.again.is_none() && start.vn < 0.0 && start.p > pc {
        // (Already in a later compression phase: its start was not seen.)
        ev.again = Some(start.p);
    }
    if let Some(began) = ev.again {
        // In a later compression phase (v_n ≤ 0): it ends where v_n is back to zero.
        if kn <= 0.0 {
            return None;
        }
        from = (-start.vn / kn).max(0.0);
        if from > length {
            return None;
        }
        ev.recompressed += start.p + from - began;
        ev.again = None;
    }
    let c = pc + ev.recompressed;
    let x = ((1.0 + ev.e) * c - start.p).max(from);
    if kn < 0.0 && start.vn >= 0.0 {
        // v_n falls back to zero inside the piece before the end: a later compression,
        // v_n < 0 for the rest of the piece.
        let back = -start.vn / kn;
        if back < x && back <= length {
            ev.again = Some(start.p + back);
            return None;
        }
    }
    Some(x)
}

fn finish(pt: &Point, ev: &Events, phases: Phases3, slip_halt: Option<f64>, steps: u32) -> PathEnd {
    let pc = ev.pc.filter(|&pc| pc <= pt.p);
    PathEnd {
        impulse: Vec3::new(pt.pt.x, pt.pt.y, pt.p),
        velocity: Vec3::new(pt.vt.x, pt.vt.y, pt.vn),
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

/// The integration variable of the slip stage.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    /// The normal impulse `p_n`.
    P,
    /// `u = ln σ`, decreasing (a steady approach to a halt).
    U,
    /// The pseudo-time `τ`, `dp_n = σ dτ` (small slip that need not shrink steadily).
    T,
}

/// Step-size factor after a rejected step (`en > 1` or NaN): `0.9 en^(-1/8)`, at least 0.2.
#[inline]
fn shrink(en: f64) -> f64 {
    if en.is_finite() {
        (0.9 / en.sqrt().sqrt().sqrt()).max(0.2)
    } else {
        0.2
    }
}

/// Step-size factor after an accepted step: `0.9 en^(-1/8)`, at most 6.
#[inline]
fn grow(en: f64) -> f64 {
    (0.9 / en.max(1e-10).sqrt().sqrt().sqrt()).min(6.0)
}

/// The value of event `kind` (0 = compression end, 1 = termination, 2 = second
/// compression, 3 = end of a later compression) at `c`, increasing through zero at the
/// event.
#[inline]
fn event_value(ev: &Events, kind: u8, c: &Point) -> f64 {
    match kind {
        0 | 3 => c.vn,
        1 => ev.terminal(c),
        _ => -c.vn,
    }
}

/// Locate event `kind` inside the accepted step `st` of size `h` from `(x0, y0)`: seeded by
/// the dense output, then found on the discrete solution by re-stepping from `x0`.
/// Returns the independent variable and the state there.
#[allow(clippy::too_many_arguments)]
fn locate_in_step<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    point: &impl Fn(f64, &[f64; N]) -> Point,
    ev: &Events,
    kind: u8,
    x0: f64,
    y0: &[f64; N],
    k0: &[f64; N],
    h: f64,
    st: &Step<N>,
    k1: &[f64; N],
    ga: f64,
    gb: f64,
) -> (f64, [f64; N]) {
    if ga >= 0.0 {
        // (The end of a later compression that began at v_n = 0 exactly: at the start.)
        return (x0, *y0);
    }
    let dense = Dense::new(f, x0, y0, st, k1, h);
    let dense_g = |th: f64| event_value(ev, kind, &point(x0 + th * h, &dense.at(th)));
    let seed = illinois(dense_g, 0.0, ga, 1.0, gb);
    let (a, b) = ((seed - 1e-6).max(0.0), (seed + 1e-6).min(1.0));
    let slope = (dense_g(b) - dense_g(a)) / (b - a);
    let mut last = (f64::NAN, *y0);
    let theta = newton_from_seed(
        |th| {
            let yt = dop853_step(f, x0, y0, k0, th * h).y;
            last = (th, yt);
            event_value(ev, kind, &point(x0 + th * h, &yt))
        },
        ga,
        gb,
        seed,
        slope,
    );
    let yt = if last.0 == theta {
        last.1
    } else {
        dop853_step(f, x0, y0, k0, theta * h).y
    };
    (x0 + theta * h, yt)
}

/// Record event `kind` at `pt` (the slip direction there is `phi`); returns the end of the
/// slip stage if the law terminated.
fn after_event(kind: u8, pt: &mut Point, ev: &mut Events, phi: f64) -> Option<SlipEnd> {
    match kind {
        0 => {
            pt.vn = 0.0;
            ev.pc = Some(pt.p);
            ev.wc = pt.wn;
            (ev.terminal(pt) >= 0.0).then_some(SlipEnd::Terminated { phi })
        }
        1 => Some(SlipEnd::Terminated { phi }),
        2 => {
            ev.second.get_or_insert(pt.p);
            if ev.counts_compression() {
                ev.again = Some(pt.p);
            }
            None
        }
        _ => {
            // A later compression phase ended: its impulse adds to the compression.
            if let Some(start) = ev.again.take() {
                ev.recompressed += pt.p - start;
            }
            (ev.terminal(pt) >= 0.0).then_some(SlipEnd::Terminated { phi })
        }
    }
}

enum SlipEnd {
    Terminated { phi: f64 },
    Halted { phi: f64 },
}

/// Check the events between two points (`a` before, `b` after a step); returns the first
/// event's kind and a closure-free description: 0 = compression end, 1 = termination,
/// 2 = second compression (`v_n` back to zero after `p_c`; for Poisson every such return),
/// 3 = the end of a later compression phase (Poisson).
///
/// Where a later compression begins inside the step, Poisson's termination function is
/// evaluated at `b` as if it had not (it stops growing there): the second compression is
/// returned, and the caller relocates the termination if it lies before
/// ([`poisson_ends_first`]).
#[inline]
fn first_event(ev: &Events, a: &Point, b: &Point) -> Option<(u8, f64, f64)> {
    if ev.pc.is_none() {
        if b.vn >= 0.0 && a.vn < 0.0 {
            return Some((0, a.vn, b.vn));
        }
        return None;
    }
    if ev.again.is_some() {
        // In a later compression phase: its end (from a located start at v_n = 0 exactly,
        // an end inside the step is at its start).
        let ends = (a.vn < 0.0 && b.vn >= 0.0) || (a.vn == 0.0 && b.vn > 0.0);
        return ends.then_some((3, a.vn, b.vn));
    }
    let (ga, gb) = (ev.terminal(a), ev.terminal(b));
    let term = ga < 0.0 && gb >= 0.0;
    let second = (ev.second.is_none() || ev.counts_compression()) && a.vn > 0.0 && b.vn <= 0.0;
    match (term, second) {
        (true, true) if ev.counts_compression() => Some((2, -a.vn, -b.vn)),
        (true, _) => Some((1, ga, gb)),
        (false, true) => Some((2, -a.vn, -b.vn)),
        _ => None,
    }
}

/// Whether Poisson's termination lies before a later compression located at `c` (kind 2)
/// in the same step: its function, still growing with `p_n`, is already `≥ 0` there.
#[inline]
fn poisson_ends_first(ev: &Events, kind: u8, c: &Point) -> bool {
    kind == 2 && ev.counts_compression() && ev.terminal(c) >= 0.0
}

/// The angle `φ` wrapped to `(−π, π]`.
#[inline]
fn wrap_angle(phi: f64) -> f64 {
    phi.sin().atan2(phi.cos())
}

/// The series about the centripetal invariant ray that a shrinking slip turns toward: the
/// ray is located once the direction turns slowly (`|ŝ × g| ≤ 0.15 |ŝ·g|`), the series
/// built once the direction is within 0.3 rad of it (where it can converge).
struct TailSeries {
    ray: Option<Option<(f64, Vec2)>>,
    series: Option<RaySeries>,
    built: bool,
}

impl TailSeries {
    fn new() -> TailSeries {
        TailSeries {
            ray: None,
            series: None,
            built: false,
        }
    }

    /// With the ray ahead already located.
    fn with_ray(phi: f64, dir: Vec2) -> TailSeries {
        TailSeries {
            ray: Some(Some((phi, dir))),
            series: None,
            built: false,
        }
    }

    fn get(&mut self, field: &Field, wnn: f64, g: Vec2, vt: Vec2) -> Option<&RaySeries> {
        if !self.built {
            let sigma = norm_of(vt);
            let (f, q) = (vt.x * g.y - vt.y * g.x, vt.dot(&g));
            if f.abs() > 0.15 * q.abs() {
                return None;
            }
            let (phi, dir) = (*self.ray.get_or_insert_with(|| {
                field
                    .ray_ahead(vt.y.atan2(vt.x))
                    .map(|phi| (phi, Vec2::new(phi.cos(), phi.sin())))
            }))?;
            if dir.dot(&vt) < 0.955 * sigma {
                return None;
            }
            self.built = true;
            self.series = RaySeries::new(field, wnn, phi).filter(RaySeries::attracts_to_halt);
        }
        self.series.as_ref()
    }
}

/// The rest of a slip running into the centripetal ray of `ser`, in closed form
/// ([`RaySeries`]), with the events in it located on the series: the end of the slip stage,
/// or `None` (nothing changed) while the series does not yet give the rest to the
/// tolerance (its truncation, relative to the rest's impulse, below `rtol` times the impulse
/// scale over that impulse), or an event could hide inside it (`v_n` not monotone on the
/// rest).
#[allow(clippy::too_many_arguments)]
fn series_tail(
    ser: &RaySeries,
    wtn: Vec2,
    wnn: f64,
    mu: f64,
    sc: Scales,
    pt: &mut Point,
    ev: &mut Events,
    observe: &mut impl FnMut(f64, Vec3),
) -> Option<SlipEnd> {
    let sigma0 = norm_of(pt.vt);
    if !(sigma0 > 0.0 && sigma0.is_finite()) {
        return None;
    }
    let dir0 = pt.vt / sigma0;
    let eta0 = ser.offset(dir0);
    if eta0.is_nan() || eta0.abs() > 0.6 {
        return None;
    }
    let xi0 = ser.normal_coordinate(eta0)?;
    let tol = (sc.rtol * sc.p / (sigma0 * ser.impulse_per_slip())).min(1e-6);
    let trunc = ser.truncation(xi0);
    if trunc.is_nan() || trunc > tol {
        return None;
    }
    // v_n must be monotone on the rest, so that each event function is: dv_n/dp_n =
    // w_nn − μ w_tn·ŝ keeps its sign at both ends and has no extremum (ŝ ∥ ±w_tn) between.
    let rate = |s: Vec2| wnn - mu * wtn.dot(&s);
    let (d0, d1) = (rate(dir0), rate(ser.dir));
    if d0 * d1 < 0.0 || (d0 == 0.0) != (d1 == 0.0) {
        return None;
    }
    // ±w_tn strictly inside the arc from the ray to the direction (|η₀| ≤ 0.6 < π, so the
    // short arc): on the side of η₀ seen from the ray, the other side seen from `dir0`.
    if wtn.x != 0.0 || wtn.y != 0.0 {
        let cross = |a: Vec2, b: Vec2| a.x * b.y - a.y * b.x;
        for cand in [wtn, -wtn] {
            let inside = cross(ser.dir, cand) * eta0 > 0.0
                && cross(cand, dir0) * eta0 > 0.0
                && ser.dir.dot(&cand) > 0.0;
            if inside {
                return None;
            }
        }
    }
    let base = *pt;
    // The state at `s` without the slip velocity (what the event functions read), and
    // with it.
    let light = |s: f64| -> Point {
        let inc = ser.increment(sigma0, xi0, base.vn, s);
        Point {
            p: base.p + inc.dp,
            vt: Vec2::new(f64::NAN, f64::NAN),
            vn: base.vn + inc.dvn,
            pt: base.pt + inc.dpt,
            wn: base.wn + inc.dwn,
            wt: base.wt + inc.dwt,
        }
    };
    let at = |s: f64| -> Point {
        let mut pt = light(s);
        pt.vt = if s == f64::NEG_INFINITY {
            Vec2::zeros()
        } else {
            let phi = ser.phi + ser.angle_offset(xi0 * (ser.lambda * s).exp());
            sigma0 * s.exp() * Vec2::new(phi.cos(), phi.sin())
        };
        pt
    };
    let end = at(f64::NEG_INFINITY);
    if !(end.p.is_finite() && end.vn.is_finite() && end.wn.is_finite() && end.wt.is_finite()) {
        return None;
    }
    let halt_phi = ser.dir.y.atan2(ser.dir.x);
    // A few events lie ahead (v_n is monotone on the rest: the compression end or a
    // return to compression, the end of a later compression, then the termination, which
    // ends the loop).
    loop {
        let Some((mut kind, ga, gb)) = first_event(ev, pt, &end) else {
            *pt = end;
            observe(pt.p, Vec3::new(0.0, 0.0, pt.vn));
            return Some(SlipEnd::Halted { phi: halt_phi });
        };
        // θ ∈ [0, 1] from the current point to the halt: s = ln(1 − θ).
        let from = *pt;
        let s_from = if from.vt == base.vt {
            0.0
        } else {
            (norm_of(from.vt) / sigma0).ln()
        };
        let s_of = |th: f64| {
            if th >= 1.0 {
                f64::NEG_INFINITY
            } else {
                s_from + (-th).ln_1p()
            }
        };
        let find = |kind: u8, ga: f64, gb: f64| {
            if ga >= 0.0 {
                // (A later compression that began at v_n = 0 exactly ends at once.)
                return 0.0;
            }
            illinois(
                |th| event_value(ev, kind, &light(s_of(th))),
                0.0,
                ga,
                1.0,
                gb,
            )
        };
        let mut th = find(kind, ga, gb);
        if poisson_ends_first(ev, kind, &light(s_of(th))) {
            kind = 1;
            th = find(kind, ev.terminal(pt), ev.terminal(&end));
        }
        *pt = if th >= 1.0 { end } else { at(s_of(th)) };
        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
        let phi = if th >= 1.0 {
            halt_phi
        } else {
            pt.vt.y.atan2(pt.vt.x)
        };
        if let Some(done) = after_event(kind, pt, ev, phi) {
            return Some(done);
        }
        if th >= 1.0 {
            return Some(SlipEnd::Halted { phi: halt_phi });
        }
    }
}

/// Whether the slip turns or shrinks appreciably before the next normal event (the angle
/// variable pays off), judged from the rates at `pt`: `(|ŝ × g| + max(0, −ŝ·g))/σ` times the
/// normal impulse to the event, `|v_n|` (or `e |v_n⁻|` after compression) over
/// `k_n = w_nn − μ w_tn·ŝ`, at least a quarter (always when `k_n ≤ 0`).
fn turns_before_event(
    pt: &Point,
    ev: &Events,
    vn_start: f64,
    field: &Field,
    wnn: f64,
    wtn: Vec2,
    mu: f64,
) -> bool {
    let sigma = norm_of(pt.vt);
    let s = pt.vt / sigma;
    let kn = wnn - mu * wtn.dot(&s);
    if kn.is_nan() || kn <= 0.0 {
        return true;
    }
    let to_event = if ev.pc.is_none() {
        -pt.vn
    } else {
        ev.e * vn_start.abs()
    }
    .abs()
        / kn;
    let rate = field.f_at(s.x, s.y).abs() + (-field.q_at(s.x, s.y)).max(0.0);
    // (A NaN says nothing: try the angle variable.)
    (rate * to_event).partial_cmp(&(0.25 * sigma)) != Some(std::cmp::Ordering::Less)
}

/// What one attempted step of the slip stage did.
enum Advance {
    /// Rejected, with this error measure: the caller shrinks the step.
    Rejected(f64),
    /// Accepted, with this error measure: the caller may grow the step.
    Accepted(f64),
    /// Stopped at an event inside the step: `Some` if the law terminated there.
    Event(Option<SlipEnd>),
}

/// One DOP853 step of size `h` from `(x, y)` (derivative `k`) in any of the integration
/// variables: the error test against `atol + rtol |y|`, then the first event inside the step
/// located on the discrete solution ([`locate_in_step`]) or else the whole step. On success
/// `x`, `y`, `k`, `pt` and `steps` advance and `observe` sees the new point; after an event
/// the state's `v_n` (entry `vn_at`) takes the point's exact value.
#[allow(clippy::too_many_arguments)]
fn advance<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    point: &impl Fn(f64, &[f64; N]) -> Point,
    atol: &[f64; N],
    rtol: f64,
    vn_at: usize,
    x: &mut f64,
    y: &mut [f64; N],
    k: &mut [f64; N],
    h: f64,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    observe: &mut impl FnMut(f64, Vec3),
) -> Advance {
    let st = dop853_step(f, *x, y, k, h);
    let y1 = st.y;
    let en = error_measure(&st, |i| atol[i] + rtol * y[i].abs().max(y1[i].abs()));
    if en.is_nan() || en > 1.0 {
        return Advance::Rejected(en);
    }
    let b = point(*x + h, &y1);
    let k1 = f(*x + h, &y1);
    if let Some((mut kind, ga, gb)) = first_event(ev, pt, &b) {
        let (mut xe, mut ye) = locate_in_step(f, point, ev, kind, *x, y, k, h, &st, &k1, ga, gb);
        if poisson_ends_first(ev, kind, &point(xe, &ye)) {
            kind = 1;
            let (ga, gb) = (ev.terminal(pt), ev.terminal(&b));
            (xe, ye) = locate_in_step(f, point, ev, kind, *x, y, k, h, &st, &k1, ga, gb);
        }
        *x = xe;
        *y = ye;
        *pt = point(xe, &ye);
        *steps += 1;
        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
        if let Some(end) = after_event(kind, pt, ev, pt.vt.y.atan2(pt.vt.x)) {
            return Advance::Event(Some(end));
        }
        y[vn_at] = pt.vn;
        *k = f(*x, y);
        return Advance::Event(None);
    }
    *x += h;
    *y = y1;
    *k = k1;
    *pt = b;
    *steps += 1;
    observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
    Advance::Accepted(en)
}

#[allow(clippy::too_many_arguments)]
fn slip_stage(
    wtt: &Mat2,
    wtn: Vec2,
    wnn: f64,
    mu: f64,
    centrifugal: Option<Centrifugal>,
    sc: Scales,
    pt: &mut Point,
    ev: &mut Events,
    steps: &mut u32,
    observing: bool,
    observe: &mut impl FnMut(f64, Vec3),
) -> Result<SlipEnd, BreakdownReason> {
    // State in p-mode: [vt1, vt2, vn, pt1, pt2, wn, wt].
    let fp = |_p: f64, y: &[f64; 7]| -> [f64; 7] {
        let vt = Vec2::new(y[0], y[1]);
        let sigma = norm_of(vt);
        let s = vt / sigma;
        let g = wtn - mu * (wtt * s);
        [
            g.x,
            g.y,
            wnn - mu * wtn.dot(&s),
            -mu * s.x,
            -mu * s.y,
            y[2],
            -mu * sigma,
        ]
    };
    // State in τ-mode (dp_n = σ dτ): [vt1, vt2, vn, pt1, pt2, wn, wt, p]; no division, and
    // smooth everywhere but at v_t = 0 itself (σ = |v_t|), which is reached only as τ → ∞.
    let ft = |_t: f64, z: &[f64; 8]| -> [f64; 8] {
        let (v1, v2) = (z[0], z[1]);
        let sigma = norm_of(Vec2::new(v1, v2));
        let wv1 = wtt[(0, 0)] * v1 + wtt[(0, 1)] * v2;
        let wv2 = wtt[(1, 0)] * v1 + wtt[(1, 1)] * v2;
        [
            sigma * wtn.x - mu * wv1,
            sigma * wtn.y - mu * wv2,
            sigma * wnn - mu * (wtn.x * v1 + wtn.y * v2),
            -mu * v1,
            -mu * v2,
            sigma * z[2],
            -mu * sigma * sigma,
            sigma,
        ]
    };
    // State in u-mode (u = ln σ): [ŝ1, ŝ2, σ, p, vn, pt1, pt2, wn, wt] — the direction as a
    // vector (normalised on use) and σ carried along (dσ/du = σ), so no transcendental
    // function is evaluated.
    let fu = |_u: f64, z: &[f64; 9]| -> [f64; 9] {
        let s = Vec2::new(z[0], z[1]);
        let s = s / s.norm();
        let g = wtn - mu * (wtt * s);
        let q = s.dot(&g);
        let f = s.x * g.y - s.y * g.x;
        let sigma = z[2];
        let dp = sigma / q;
        let dphi = f / q;
        [
            -s.y * dphi,
            s.x * dphi,
            sigma,
            dp,
            (wnn - mu * wtn.dot(&s)) * dp,
            -mu * s.x * dp,
            -mu * s.y * dp,
            z[4] * dp,
            -mu * sigma * dp,
        ]
    };
    let to_y = |p: &Point| [p.vt.x, p.vt.y, p.vn, p.pt.x, p.pt.y, p.wn, p.wt];
    let from_y = |p: f64, y: &[f64; 7]| Point {
        p,
        vt: Vec2::new(y[0], y[1]),
        vn: y[2],
        pt: Vec2::new(y[3], y[4]),
        wn: y[5],
        wt: y[6],
    };
    let from_t = |_t: f64, z: &[f64; 8]| Point {
        p: z[7],
        vt: Vec2::new(z[0], z[1]),
        vn: z[2],
        pt: Vec2::new(z[3], z[4]),
        wn: z[5],
        wt: z[6],
    };
    let dir_z = |z: &[f64; 9]| {
        let s = Vec2::new(z[0], z[1]);
        s / s.norm()
    };
    let from_z = |_u: f64, z: &[f64; 9]| Point {
        p: z[3],
        vt: z[2] * dir_z(z),
        vn: z[4],
        pt: Vec2::new(z[5], z[6]),
        wn: z[7],
        wt: z[8],
    };
    let atol_u = [
        sc.rtol,
        sc.rtol,
        sc.rtol * sc.vt,
        sc.rtol * sc.p,
        sc.rtol * sc.vn,
        sc.rtol * sc.p,
        sc.rtol * sc.p,
        sc.rtol * sc.wn,
        sc.rtol * sc.wt,
    ];
    let atol_t = [
        sc.rtol * sc.vt,
        sc.rtol * sc.vt,
        sc.rtol * sc.vn,
        sc.rtol * sc.p,
        sc.rtol * sc.p,
        sc.rtol * sc.wn,
        sc.rtol * sc.wt,
        sc.rtol * sc.p,
    ];
    let atol_p = [
        sc.rtol * sc.vt,
        sc.rtol * sc.vt,
        sc.rtol * sc.vn,
        sc.rtol * sc.p,
        sc.rtol * sc.p,
        sc.rtol * sc.wn,
        sc.rtol * sc.wt,
    ];
    let sigma0 = norm_of(pt.vt);
    let vn_start = pt.vn;
    let field = Field::new(wtt, wtn, mu);
    // The rest of the slip is a straight run into the origin when the direction is (to the
    // last bit of the result) on an invariant ray: the remaining impulse σ/|ŝ·g| times the
    // angular offset from the ray is below 1e-16 of the impulse scale. Returns (ŝ, ŝ·g).
    let straight_tail = |vt: Vec2| -> Option<(Vec2, f64)> {
        let sigma = norm_of(vt);
        let s = vt / sigma;
        let g = wtn - mu * (wtt * s);
        let q = s.dot(&g);
        if q >= 0.0 {
            return None;
        }
        // ŝ × g = ŝ × w_tn − μ [W12 (c² − s²) + (W22 − W11) c s]: exactly zero on the
        // invariant rays of an isotropic, uncoupled W_tt (no swirl, no round-off swirl).
        let f = (s.x * wtn.y - s.y * wtn.x)
            - mu * (wtt[(0, 1)] * (s.x * s.x - s.y * s.y)
                + (wtt[(1, 1)] - wtt[(0, 0)]) * s.x * s.y);
        let gn = norm_of(g);
        let est = (f.abs() / gn) * (1.0 + gn / -q) * (1.0 + mu) * sigma / -q;
        (est <= 1e-16 * sc.p).then_some((s, q))
    };
    // Run the straight tail in closed form to the halt (or to an event inside it).
    let run_tail =
        |pt: &mut Point, ev: &mut Events, s: Vec2, q: f64| -> Result<SlipEnd, BreakdownReason> {
            let sigma = norm_of(pt.vt);
            // From the unnormalised slip: bit-identical to φ0 when the tail starts at v⁻.
            let phi = pt.vt.y.atan2(pt.vt.x);
            let piece = Linear {
                kind: Phase3Kind::Stick,
                ratio: -mu * s,
                slope: wnn - mu * wtn.dot(&s),
                dir: s,
                sigma,
                dsigma: q,
                length: sigma / -q,
            };
            if linear_piece(&piece, pt, ev, mu)? {
                Ok(SlipEnd::Terminated { phi })
            } else {
                pt.vt = Vec2::zeros();
                // The slip halts along the centripetal ray that the direction tends to; where
                // the ray attracts weakly the direction is still measurably off it here.
                let g = wtn - mu * (wtt * s);
                let on_ray = (s.x * g.y - s.y * g.x).abs() <= 1e-9 * norm_of(g);
                let ray = if on_ray {
                    phi
                } else {
                    field.ray_ahead(phi).map_or(phi, wrap_angle)
                };
                Ok(SlipEnd::Halted { phi: ray })
            }
        };
    // A slip that has settled on an invariant ray that attracts the direction (`f' < 0`
    // there: an offset δ obeys `dδ/dp_n = f' δ/σ`) runs straight along it, its speed
    // changing at the ray's rate `q = ŝ·g`. Where `|q|` is small beside `|f'|` (a nearly
    // neutral ray, near the stick limit of an ill-conditioned W) the steps in p_n, τ or the
    // angle variable are held to the decay length `σ/|f'|` of the offset while the impulse
    // to the next event or the halt is of order `σ/|q|`: millions of steps. There, once the
    // offset is at the integration's own noise (`σ δ` within 4 rtol of the velocity scale,
    // what the error control leaves in v_t), the rest is the straight run along the ray in
    // closed form: the offset changes the result as little as one more step would. The ray
    // is the root of `f` next to the direction (Newton's method); a centrifugal one is the
    // direction of resumption, with its rate and slope from `centrifugal`.
    let settled_on_ray = |vt: Vec2| -> Option<Settled> {
        let sigma = norm_of(vt);
        let s = vt / sigma;
        // f' at the direction: df/dφ = s' × g − μ s × W_tt s', s' = (−s_y, s_x).
        let g = wtn - mu * (wtt * s);
        let sp = Vec2::new(-s.y, s.x);
        let h = wtt * sp;
        let df = sp.x * g.y - sp.y * g.x - mu * (s.x * h.y - s.y * h.x);
        // (Each test fails on a NaN.)
        let q = s.dot(&g);
        (df < 0.0 && q.abs() <= 1e-3 * -df).then_some(())?;
        let dir = polish_ray(wtt, wtn, mu, s)?;
        let offset = (s.x * dir.y - s.y * dir.x).abs();
        (offset * sigma <= 4.0 * sc.rtol * sc.vt).then_some(())?;
        let q = dir.dot(&(wtn - mu * (wtt * dir)));
        if q < 0.0 {
            return Some(Settled::Centripetal { dir, rate: q });
        }
        let c = centrifugal?;
        (c.dir.dot(&dir) > 1.0 - 1e-9).then_some(Settled::Centrifugal(c))
    };
    // Run the slip along the centrifugal ray in closed form to the termination.
    let run_centrifugal =
        |pt: &mut Point, ev: &mut Events, c: Centrifugal| -> Result<SlipEnd, BreakdownReason> {
            let piece = Linear {
                kind: Phase3Kind::Stick,
                ratio: -mu * c.dir,
                slope: c.slope,
                dir: c.dir,
                sigma: norm_of(pt.vt),
                dsigma: c.rate,
                length: f64::INFINITY,
            };
            if linear_piece(&piece, pt, ev, mu)? {
                Ok(SlipEnd::Terminated {
                    phi: c.dir.y.atan2(c.dir.x),
                })
            } else {
                Err(BreakdownReason::NoSeparation)
            }
        };
    let run_settled =
        |pt: &mut Point, ev: &mut Events, s: Settled| -> Result<SlipEnd, BreakdownReason> {
            match s {
                Settled::Centripetal { dir, rate } => run_tail(pt, ev, dir, rate),
                Settled::Centrifugal(c) => run_centrifugal(pt, ev, c),
            }
        };
    let max_steps = 200_000u32;
    // The angle variable is tried first, and again a few steps after a start on a ray.
    let mut angle_retry = Some(0u32);
    let mut mode = Mode::P;
    let mut h = 0.05 * sc.p;
    let mut hu = -0.25f64;
    let mut ht = 0.0f64;
    // The rate of change of the slip, `ŝ·g` and `|g|`, for the switches between modes.
    let rates = |vt: Vec2| -> (f64, f64) {
        let s = vt / norm_of(vt);
        let g = wtn - mu * (wtt * s);
        (s.dot(&g), norm_of(g))
    };
    while *steps < max_steps {
        match mode {
            // ---------------- p-mode ----------------
            Mode::P => {
                let mut y = to_y(pt);
                let mut k = fp(pt.p, &y);
                while *steps < max_steps {
                    if let Some((s, q)) = straight_tail(pt.vt) {
                        let end = run_tail(pt, ev, s, q)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    if let Some(c) = settled_on_ray(pt.vt) {
                        let end = run_settled(pt, ev, c)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    let try_angle = angle_retry.is_some_and(|at| {
                        *steps >= at && turns_before_event(pt, ev, vn_start, &field, wnn, wtn, mu)
                    });
                    if try_angle {
                        let cx = angle::Context {
                            wtt,
                            wtn,
                            wnn,
                            mu,
                            field: &field,
                            sc,
                            max_steps,
                            e: ev.e,
                            vn0: vn_start,
                            observing,
                        };
                        let before = *steps;
                        let mut straight = |pt: &mut Point, ev: &mut Events| {
                            straight_tail(pt.vt).map(|(s, q)| run_tail(pt, ev, s, q))
                        };
                        match angle::run(&cx, pt, ev, steps, observe, &mut straight)? {
                            angle::Exit::End(end) => return Ok(end),
                            angle::Exit::Unavailable => angle_retry = None,
                            angle::Exit::Handoff => {
                                angle_retry = (*steps == before).then_some(*steps + 3);
                                y = to_y(pt);
                                k = fp(pt.p, &y);
                                continue;
                            }
                        }
                    }
                    let sigma = norm_of(pt.vt);
                    let (q, gn) = rates(pt.vt);
                    // Go logarithmic as soon as the slip shrinks steadily (hysteresis: enter
                    // only where the shrink rate is nearly |g|): steps in p_n would have to
                    // shrink with σ. Once the slip is small otherwise, go to the
                    // pseudo-time τ, in which a swing of the direction near the origin
                    // takes steps independent of σ. (Only where the slip shrinks
                    // appreciably before the next event: a slip far above the normal
                    // velocity changes ln σ by less than its round-off over the impact.)
                    if q < -0.9 * gn && turns_before_event(pt, ev, vn_start, &field, wnn, wtn, mu) {
                        mode = Mode::U;
                        hu = -(h * -q / sigma).min(0.25);
                        break;
                    }
                    if sigma < 0.05 * sigma0 {
                        mode = Mode::T;
                        ht = (h / sigma).min(0.5 / gn.max(f64::MIN_POSITIVE));
                        break;
                    }
                    // Never step past the predicted halt.
                    if q < 0.0 {
                        h = h.min(0.5 * sigma / -q);
                    }
                    let mut x = pt.p;
                    let adv = advance(
                        &fp, &from_y, &atol_p, sc.rtol, 2, &mut x, &mut y, &mut k, h, pt, ev,
                        steps, observe,
                    );
                    let en = match adv {
                        Advance::Rejected(en) => {
                            h *= shrink(en);
                            if h <= 1e-300 {
                                return Err(BreakdownReason::NoSeparation);
                            }
                            continue;
                        }
                        Advance::Event(Some(end)) => return Ok(end),
                        Advance::Event(None) => continue,
                        Advance::Accepted(en) => en,
                    };
                    h *= grow(en);
                }
            }
            // ---------------- u-mode (u = ln σ, decreasing) ----------------
            Mode::U => {
                let u_start = norm_of(pt.vt).ln();
                let u_end = u_start - LOG_SPAN;
                let mut u = u_start;
                let sigma = norm_of(pt.vt);
                let mut z = [
                    pt.vt.x / sigma,
                    pt.vt.y / sigma,
                    sigma,
                    pt.p,
                    pt.vn,
                    pt.pt.x,
                    pt.pt.y,
                    pt.wn,
                    pt.wt,
                ];
                let mut kz = fu(u, &z);
                let mut leave = false;
                let mut series = TailSeries::new();
                let g0 = wtn - mu * (wtt * (pt.vt / sigma));
                if let Some(ser) = series.get(&field, wnn, g0, pt.vt) {
                    if let Some(end) = series_tail(ser, wtn, wnn, mu, sc, pt, ev, observe) {
                        return Ok(end);
                    }
                }
                while u > u_end && *steps < max_steps {
                    let hstep = hu.max(u_end - u);
                    let adv = advance(
                        &fu, &from_z, &atol_u, sc.rtol, 4, &mut u, &mut z, &mut kz, hstep, pt, ev,
                        steps, observe,
                    );
                    let en = match adv {
                        Advance::Rejected(en) => {
                            hu *= shrink(en);
                            continue;
                        }
                        Advance::Event(Some(end)) => return Ok(end),
                        Advance::Event(None) => continue,
                        Advance::Accepted(en) => en,
                    };
                    let s = dir_z(&z);
                    let g = wtn - mu * (wtt * s);
                    if let Some(ser) = series.get(&field, wnn, g, pt.vt) {
                        if let Some(end) = series_tail(ser, wtn, wnn, mu, sc, pt, ev, observe) {
                            return Ok(end);
                        }
                    }
                    if let Some((s, q)) = straight_tail(pt.vt) {
                        let end = run_tail(pt, ev, s, q)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    // The slip must keep shrinking; otherwise go on in τ.
                    let q = s.dot(&g);
                    if q >= -0.7 * norm_of(g) {
                        mode = Mode::T;
                        let gn = norm_of(g).max(f64::MIN_POSITIVE);
                        ht = (hu.abs() / q.abs().max(f64::MIN_POSITIVE)).min(0.5 / gn);
                        leave = true;
                        break;
                    }
                    hu *= grow(en);
                }
                if leave {
                    continue;
                }
                if *steps >= max_steps {
                    break;
                }
                // σ has shrunk by e^-40: the rest is a straight run at the last bit of the
                // result.
                let s = dir_z(&z);
                let q = s.dot(&(wtn - mu * (wtt * s)));
                if q.is_nan() || q >= 0.0 {
                    return Err(BreakdownReason::NoSeparation);
                }
                let end = run_tail(pt, ev, s, q)?;
                observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                return Ok(end);
            }
            // ---------------- τ-mode (dp_n = σ dτ) ----------------
            Mode::T => {
                let mut t = 0.0f64;
                let mut z = [
                    pt.vt.x, pt.vt.y, pt.vn, pt.pt.x, pt.pt.y, pt.wn, pt.wt, pt.p,
                ];
                let mut kz = ft(t, &z);
                // Stability: the Lipschitz constant of the τ system in v_t is at most
                // |w_tn| + μ |W_tt|, and DOP853 is stable on the real axis to about −6.
                let h_stable = 3.0 / (wtn.norm() + mu * wtt.norm()).max(f64::MIN_POSITIVE);
                let sigma_end = norm_of(pt.vt) * (-LOG_SPAN).exp();
                while *steps < max_steps {
                    ht = ht.min(h_stable);
                    let adv = advance(
                        &ft, &from_t, &atol_t, sc.rtol, 2, &mut t, &mut z, &mut kz, ht, pt, ev,
                        steps, observe,
                    );
                    let en = match adv {
                        Advance::Rejected(en) => {
                            ht *= shrink(en);
                            if ht <= 1e-300 {
                                return Err(BreakdownReason::NoSeparation);
                            }
                            continue;
                        }
                        Advance::Event(Some(end)) => return Ok(end),
                        Advance::Event(None) => continue,
                        Advance::Accepted(en) => en,
                    };
                    if let Some((s, q)) = straight_tail(pt.vt) {
                        let end = run_tail(pt, ev, s, q)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    if let Some(c) = settled_on_ray(pt.vt) {
                        let end = run_settled(pt, ev, c)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    ht *= grow(en);
                    let sigma = norm_of(pt.vt);
                    let (q, gn) = rates(pt.vt);
                    if sigma <= sigma_end && q < 0.0 {
                        // σ has shrunk by e^-40: the rest is a straight run at the last bit
                        // of the result.
                        let end = run_tail(pt, ev, pt.vt / sigma, q)?;
                        observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
                        return Ok(end);
                    }
                    if q < -0.9 * gn && turns_before_event(pt, ev, vn_start, &field, wnn, wtn, mu) {
                        mode = Mode::U;
                        hu = -(q.abs() * ht).min(0.25);
                        break;
                    }
                    if sigma > 0.1 * sigma0 {
                        mode = Mode::P;
                        h = sigma * ht;
                        break;
                    }
                }
            }
        }
    }
    Err(BreakdownReason::NoSeparation)
}
