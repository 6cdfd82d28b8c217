//! The path of the impact in `τ`: each step a Taylor series (`series/`) where every loaded
//! contact's force is analytic, else an adaptive DOP853 step with its error test; the first
//! event inside an accepted step located on its dense output, what each event changes, and
//! the record of each contact (works, phases) and of the primary contact.
//!
//! An event is located on the step's dense output — the series itself, or DOP853's
//! seventh-order extension: the root of the event function in the step's fraction `θ` by the
//! Illinois iteration to `4ε` in `θ` (of the events inside one step, the first). The path
//! goes on from the solution there: the series at `θ`, or the discrete solution by
//! re-stepping from the step's start to that `θ` (the dense output and the discrete solution
//! differ by less than the step's error; where the event's function is there a hair below
//! zero, the regime it starts is offset so that it starts below zero all the same:
//! `events.rs`). A series step is long (a fifth of its radius of convergence): where an
//! event's function is below zero at both ends but rises above zero inside, the step is
//! shortened to there ([`Series::first_rise`]).
//!
//! After an event the path goes on with the step that crossed it, shortened by `e_j` where
//! contact `j`'s compression ended (it then expands `1/e_j²` times faster); a separation's
//! variable starts with the current step of `τ` as a step of `σ`, at most the whole way to
//! the separation. Between two events the right-hand side is that of one set of regimes, built
//! once ([`Field`]). At the start and after every event, the phases where the loaded contacts
//! keep fixed proportions are taken in closed form first (`closed.rs`); the integration resumes
//! after them with the step it had, or with `FIRST_STEP` of the shortest compression time (`stepper.rs`).

use super::closed;
use super::common::{grow, shrink, NormalWork, Primary};
use super::events::{self, Event};
use super::field::{eval, tangential_acceleration, tangential_rates, Eval, Field};
use super::friction::{choose, rebuild, Allowed};
use super::series::Series;
use super::state::{Modes, Normal, Setup, StickSet, Tangent, MAXK, PER, PN, PT, S, WT};
use super::stepper::Stepper;
use super::variable::Var;
use super::{MAX_STEPS, RTOL};
use crate::law::{BreakdownReason, WorkSplit};
use crate::math::Vec2;
use crate::multi::{ContactPhaseKind, ContactResult, LzbPrimary};
use crate::numerics::dop853::{dop853_step, error_measure, Dense, Interpolant, Step};
use crate::planar::SlipDirection;

/// What the path ends with (canonical units).
pub(super) struct End {
    /// One result per contact.
    pub contacts: Vec<ContactResult>,
    /// The primary contacts in turn.
    pub primaries: Vec<LzbPrimary>,
    /// The accepted steps.
    pub steps: usize,
}

/// An accepted step: a DOP853 step (and its error measure) or a Taylor series.
enum Taken<const N: usize> {
    Rk(Step<N>, f64),
    /// (The series is the run's workspace.)
    Series,
}

/// A step's continuous extension: DOP853's, or the series itself.
enum Interp<'a, const N: usize> {
    Rk(Dense<N>),
    Series(&'a Series<N>),
}

impl<const N: usize> Interpolant<N> for Interp<'_, N> {
    #[inline]
    fn at(&self, theta: f64) -> [f64; N] {
        match self {
            Interp::Rk(d) => d.at(theta),
            Interp::Series(s) => s.at(theta),
        }
    }
}

impl<const N: usize> Taken<N> {
    /// The step's continuous extension (`f` the right-hand side, the step from `(x, y0)` of
    /// size `h`, `k_end` the derivative at its end).
    fn dense<'a>(
        &self,
        ser: &'a Series<N>,
        f: &impl Fn(f64, &[f64; N]) -> [f64; N],
        x: f64,
        y0: &[f64; N],
        k_end: &[f64; N],
        h: f64,
    ) -> Interp<'a, N> {
        match self {
            Taken::Rk(st, _) => Interp::Rk(Dense::new(f, x, y0, st, k_end, h)),
            Taken::Series => Interp::Series(ser),
        }
    }
}

/// One contact's record.
#[derive(Debug, Clone)]
struct Track {
    /// The normal work so far.
    work: NormalWork,
    /// The current tangential regime, while the contact carries a force.
    label: Option<ContactPhaseKind>,
    /// The result being built (phases).
    result: ContactResult,
    /// Whether it has carried a force.
    engaged: bool,
}

/// The regimes, the records and the primary.
struct Path<'a> {
    setup: &'a Setup,
    modes: Modes,
    tracks: Vec<Track>,
    primary: Primary,
}

/// What the phases in closed form at a point did ([`Path::closed`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Closed {
    /// None was taken.
    Unchanged,
    /// The path moved on; contacts still carry a force.
    Advanced,
    /// The impact ended.
    Ended,
}

/// Integrate the impact to its end (module docs of [`super`]); `N = 4K`.
pub(super) fn run<const N: usize>(setup: &Setup) -> Result<End, BreakdownReason> {
    debug_assert_eq!(N, PER * setup.k);
    let mut y = [0.0; N];
    let mut path = Path::start(setup, &y);
    let (mut attempts, mut steps) = (0usize, 0usize);
    let mut it = match path.closed(&mut y, &mut attempts, None)? {
        Closed::Ended => return Ok(path.finish(&y, steps)),
        Closed::Unchanged => Stepper::<N>::start(setup, path.modes, &y),
        Closed::Advanced => Stepper::<N>::resume(setup, path.modes, &y),
    };
    // (Formed only for a path that is integrated.)
    let mut ser = Series::<N>::new();
    while (0..setup.k).any(|j| it.modes.active(j)) {
        attempts += 1;
        if attempts > MAX_STEPS {
            return Err(BreakdownReason::TooManySteps { limit: MAX_STEPS });
        }
        let Some(taken) = take_step(&mut it, &mut ser, &y) else {
            continue;
        };
        // (The step may have left the start's variable.)
        let (var, x) = (it.var, it.x);
        let field = &it.field;
        let f = |xx: f64, yy: &[f64; N]| var.rhs::<N>(setup, field, xx, yy);
        let mut h = match &taken {
            Taken::Series => ser.h,
            Taken::Rk(..) => it.h,
        };
        let mut y1 = match &taken {
            Taken::Series => ser.end(),
            Taken::Rk(st, _) => st.y,
        };
        let (mut k_end, mut ev_b) = var.rhs_eval::<N>(setup, field, x + h, &y1);
        let mut g_b = events::values(setup, &it.modes, &it.watch, &y1, &ev_b);
        // (In the separation variable its own separation is the end of the range.)
        let own = var.separating();
        if let Taken::Series = taken {
            // A function that rises above zero and falls back inside the long step: the step
            // ends where it is above zero.
            let (modes, watch, skip) = (&it.modes, &it.watch, own.map(Event::Separation));
            if let Some(th) = ser.first_rise(setup, modes, field, watch, &it.g_a, &g_b, skip) {
                ser.h *= th;
                h = ser.h;
                y1 = ser.end();
                (k_end, ev_b) = var.rhs_eval::<N>(setup, field, x + h, &y1);
                g_b = events::values(setup, &it.modes, &it.watch, &y1, &ev_b);
            }
        }
        let lands = matches!(var, Var::Separation { .. }) && x + h <= 0.0;
        let (g_a, list) = (&it.g_a, &it.watch.list);
        let crosses =
            |i: usize| g_a[i] <= 0.0 && g_b[i] > 0.0 && Some(list[i]) != own.map(Event::Separation);
        let crossing = (0..it.watch.n).any(crosses);
        if !crossing {
            if settled(setup, &it.modes, &y1, &ev_b.v) {
                y = y1;
                steps += 1;
                path.end_settled(&y);
                break;
            }
            if let Some(stored) = jammed(setup, &it.modes, &y1, &ev_b) {
                return Err(BreakdownReason::Jammed { stored });
            }
            path.follow_primary(1.0, &y, &y1, &|| taken.dense(&ser, &f, x, &y, &k_end, h));
            y = y1;
            steps += 1;
            if let (true, Some(j)) = (lands, own) {
                // The contact separates: on in time.
                path.apply(&[Event::Separation(j)], &mut y);
                let Some((field, ev)) = path.on_from(&mut y, &mut attempts)? else {
                    break;
                };
                let ht = it.time_step(h, &ev_b.v);
                it.restart(path.modes, field, &ev, &y, ht);
                continue;
            }
            it.x += h;
            it.k1 = k_end;
            it.g_a = g_b;
            it.h = match &taken {
                Taken::Rk(_, en) => h * grow(*en),
                Taken::Series => h,
            };
            // The next variable: the start ends in u; a separation nears or stops nearing.
            let next = var.next(setup, &it.modes, it.x, it.h, &y1, &ev_b.v, it.root_end);
            if next != var {
                let ht = it.time_step(it.h, &ev_b.v);
                (it.x, it.h) = next.start_from_time(setup, &y, ht, &ev_b.v);
                it.var = next;
                it.k1 = next.rhs::<N>(setup, field, it.x, &y);
            }
            continue;
        }
        // The first event inside the step, located on the series' polynomials or on the
        // Runge–Kutta step's dense output.
        let dense = taken.dense(&ser, &f, x, &y, &k_end, h);
        let series = matches!(taken, Taken::Series).then_some(&ser);
        let (seed, i) = it.first_event(&dense, series, &g_b, crosses);
        let event = it.watch.list[i];
        // On the discrete solution: re-step from the step's start to the seed (the series
        // is its own).
        let (theta, ye) = match &taken {
            _ if seed == 0.0 => (0.0, y),
            Taken::Series => (seed, ser.at(seed)),
            Taken::Rk(..) => (seed, dop853_step(&f, x, &y, &it.k1, seed * h).y),
        };
        path.follow_primary(theta, &y, &ye, &|| taken.dense(&ser, &f, x, &y, &k_end, h));
        y = ye;
        steps += 1;
        path.apply(&[event], &mut y);
        // On from the event (its regimes may have changed).
        let Some((field, ev)) = path.on_from(&mut y, &mut attempts)? else {
            break;
        };
        let mut ht = it.time_step(h, &ev.v);
        if let Event::CompressionEnd(j) = event {
            // The contact now expands 1/e² times faster (ds/dτ = −v_n/e²): a shorter step.
            if setup.e[j] > 0.0 {
                ht *= setup.e[j];
            }
        }
        it.restart(path.modes, field, &ev, &y, ht);
    }
    Ok(path.finish(&y, steps))
}

/// One step from the stepper's point `y`: the Taylor series where it applies (every loaded
/// contact has `s > 0`), else a DOP853 step with its error test — `None` if that is rejected
/// (the step shrunk for the next attempt).
fn take_step<const N: usize>(
    it: &mut Stepper<'_, N>,
    ser: &mut Series<N>,
    y: &[f64; N],
) -> Option<Taken<N>> {
    if ser.build(it.setup, &it.field, it.var, it.x, y) {
        return Some(Taken::Series);
    }
    if it.var == Var::Onset {
        // (Its series overflows: DOP853 in `u`.)
        it.leave_onset(y);
        if ser.build(it.setup, &it.field, it.var, it.x, y) {
            return Some(Taken::Series);
        }
    }
    let (setup, var, x) = (it.setup, it.var, it.x);
    // A separation ends exactly at σ = 0.
    if matches!(var, Var::Separation { .. }) && x + it.h <= 0.0 {
        it.h = -x;
    }
    let field = &it.field;
    let f = |xx: f64, yy: &[f64; N]| var.rhs::<N>(setup, field, xx, yy);
    let st = dop853_step(&f, x, y, &it.k1, it.h);
    let en = error_measure(&st, |i| {
        setup.atol[i] + RTOL * y[i].abs().max(st.y[i].abs())
    });
    // (NaN: rejected.)
    if en.is_nan() || en > 1.0 {
        it.h *= shrink(en);
        return None;
    }
    Some(Taken::Rk(st, en))
}

/// Whether the impact has settled at `y` (velocities `v`): every contact that carries a
/// force moves by at most the settled round-off (`|v_nj| ≤ d`, [`super::SETTLED`] of the
/// largest `|v⁻_i|`) and stores at most the energy that could move it by that much alone
/// (`Ê_j ≤ ½ d² / W_njnj`), and no other contact approaches by more than `d`. (A geometric
/// tail of ever smaller exchanges, an inelastic collapse, would otherwise never end.)
fn settled(setup: &Setup, modes: &Modes, y: &[f64], v: &[f64; 2 * MAXK]) -> bool {
    let d = setup.settled;
    (0..setup.k).all(|j| {
        let vn = v[2 * j + 1];
        if modes.active(j) {
            vn.abs() <= d
                && setup.energy(j, y[PER * j + S]) <= 0.5 * d * d / setup.w[2 * j + 1][2 * j + 1]
        } else {
            vn >= -d
        }
    })
}

/// The energy stored in the contacts if they are jammed at `y` (quantities `ev`): every
/// contact that carries a force at rest (its velocity within the settled round-off) and no
/// velocity changing (`|dv_i/dτ|` at those contacts below `1e-9` of `Σ_c |W_ic| |dp_c/dτ|`):
/// the path is at an equilibrium holding energy, which a positive definite `W` cannot have
/// (`W dp/dτ = 0` needs zero forces).
fn jammed(setup: &Setup, modes: &Modes, y: &[f64], ev: &Eval) -> Option<f64> {
    let d = setup.settled;
    let k = setup.k;
    let mut stored = 0.0;
    for j in (0..k).filter(|&j| modes.active(j)) {
        if ev.v[2 * j].abs() > d || ev.v[2 * j + 1].abs() > d {
            return None;
        }
        stored += setup.energy(j, y[PER * j + S]);
    }
    if stored.is_nan() || stored <= 0.0 {
        return None;
    }
    for j in (0..k).filter(|&j| modes.active(j)) {
        for i in [2 * j, 2 * j + 1] {
            let row = &setup.w[i];
            let (mut acc, mut scale) = (0.0, 0.0);
            for c in 0..k {
                acc += row[2 * c] * ev.pt[c] + row[2 * c + 1] * ev.f[c];
                scale += (row[2 * c] * ev.pt[c]).abs() + (row[2 * c + 1] * ev.f[c]).abs();
            }
            if acc.abs() > 1e-9 * scale {
                return None;
            }
        }
    }
    Some(setup.units.work(stored))
}

impl<'a> Path<'a> {
    /// The regimes at the start: the approaching contacts (`v_nj⁻ < −`[`Setup::approach`]) in
    /// compression, the tangential regimes chosen with the forces' limiting ratios
    /// `F_j ∝ κ_j |v_nj⁻|^η` (at `τ → 0`, `s_j ≈ −v_nj⁻ τ`).
    fn start(setup: &'a Setup, y: &[f64]) -> Path<'a> {
        let k = setup.k;
        let mut modes = Modes {
            normal: [Normal::Off; MAXK],
            tangent: [Tangent::Slip(0.0); MAXK],
            stick: StickSet::EMPTY,
        };
        let mut f = [0.0; MAXK];
        let mut best = (f64::NEG_INFINITY, 0);
        for (j, fj) in f.iter_mut().enumerate().take(k) {
            let vn = setup.v0[2 * j + 1];
            // (A contact approaching by less than the round-off is at rest: it joins if it
            // is pushed into approach, as one at rest does.)
            if vn < -setup.approach {
                modes.normal[j] = Normal::Compression;
                *fj = setup.kappa[j] * setup.law.power.of(-vn);
                // The energy grows as κ_j |v_nj|^(η+1) τ^(η+1)/(η+1).
                let growth = *fj * -vn;
                if growth > best.0 {
                    best = (growth, j);
                }
            }
        }
        let tracks = (0..k)
            .map(|j| Track {
                work: NormalWork::default(),
                label: None,
                result: ContactResult {
                    impulse: Vec2::zeros(),
                    velocity_after: Vec2::zeros(),
                    phases: crate::multi::Phases::new(),
                    work: WorkSplit::default(),
                },
                engaged: modes.active(j),
            })
            .collect();
        let mut path = Path {
            setup,
            modes,
            tracks,
            primary: Primary::start(best.1),
        };
        let mut rest = Vec::new();
        for j in 0..k {
            if path.modes.active(j) {
                path.set_slip_or_rest(j, setup.v0[2 * j], &mut rest);
            }
        }
        let allowed = vec![Allowed::ANY; rest.len()];
        let v = eval(setup, &path.modes, y).v;
        path.decide(&f, &v, y, rest, allowed);
        path
    }

    /// On from the point `y` where events were applied: `None` if the impact ends there
    /// (settled, or by its phases in closed form), else the field of the regimes the path
    /// goes on in and the point's quantities in it, after the phases in closed form.
    fn on_from<const N: usize>(
        &mut self,
        y: &mut [f64; N],
        attempts: &mut usize,
    ) -> Result<Option<(Field, Eval)>, BreakdownReason> {
        let setup = self.setup;
        let field = Field::new(setup, &self.modes);
        let ev = field.eval::<N>(setup, y);
        if settled(setup, &self.modes, y, &ev.v) {
            self.end_settled(y);
            return Ok(None);
        }
        Ok(match self.closed(y, attempts, Some((&field, &ev)))? {
            Closed::Ended => None,
            Closed::Unchanged => Some((field, ev)),
            Closed::Advanced => {
                let field = Field::new(setup, &self.modes);
                let ev = field.eval::<N>(setup, y);
                Some((field, ev))
            }
        })
    }

    /// The phases in closed form from the point `y` (`closed.rs`), one after the other, each
    /// with the events at its end; `attempts` counts them with the integration's steps. `at`:
    /// the field and the point's quantities in it, if the caller has them.
    fn closed<const N: usize>(
        &mut self,
        y: &mut [f64; N],
        attempts: &mut usize,
        mut at: Option<(&Field, &Eval)>,
    ) -> Result<Closed, BreakdownReason> {
        let setup = self.setup;
        let mut out = Closed::Unchanged;
        while let Some(end) = closed::phase::<N>(setup, &self.modes, y, at.take()) {
            *attempts += 1;
            if *attempts > MAX_STEPS {
                return Err(BreakdownReason::TooManySteps { limit: MAX_STEPS });
            }
            out = Closed::Advanced;
            self.apply(&end.events[..end.n], y);
            if settled(setup, &self.modes, y, &eval(setup, &self.modes, y).v) {
                self.end_settled(y);
                return Ok(Closed::Ended);
            }
            if !(0..setup.k).any(|j| self.modes.active(j)) {
                return Ok(Closed::Ended);
            }
        }
        Ok(out)
    }

    /// An active contact with friction at rest (`|v_t| ≤` the round-off) goes to `rest` (its
    /// regime to be chosen); otherwise it slips in the direction of `v_t` (a frictionless
    /// contact at rest: its direction chosen with the others).
    fn set_slip_or_rest(&mut self, j: usize, vt: f64, rest: &mut Vec<usize>) {
        if vt.abs() > self.setup.approach {
            self.modes.tangent[j] = Tangent::Slip(vt.signum());
        } else if self.setup.mu[j] > 0.0 {
            rest.push(j);
        } else {
            self.modes.tangent[j] = Tangent::Slip(0.0);
        }
    }

    /// What `event` changes at the point `y` (located there), then the other contacts'
    /// changes due at the same point and the tangential regimes.
    fn apply(&mut self, events: &[Event], y: &mut [f64]) {
        let setup = self.setup;
        let mut rest = Vec::new();
        let mut allowed = Vec::new();
        let v = eval(setup, &self.modes, y).v;
        let mut done = [false; MAXK];
        for &event in events {
            let j = event.contact();
            done[j] = true;
            self.change(event, &v, y, &mut rest, &mut allowed);
        }
        self.settle(&done, y, &mut rest, &mut allowed);
        let ev = eval(setup, &self.modes, y);
        self.decide(&ev.f, &ev.v, y, rest, allowed);
        self.after_change(y);
    }

    /// What `event` changes at the point `y` (velocities `v`): the normal regime, or the
    /// contacts whose tangential regime is to be chosen (`rest`, restricted by `allowed`).
    fn change(
        &mut self,
        event: Event,
        v: &[f64; 2 * MAXK],
        y: &mut [f64],
        rest: &mut Vec<usize>,
        allowed: &mut Vec<Allowed>,
    ) {
        let setup = self.setup;
        let j = event.contact();
        match event {
            Event::CompressionEnd(_) => self.end_compression(j, y),
            Event::Separation(_) => self.separate(j, y),
            Event::Recompression(_) => self.recompress(j, y),
            Event::Join(_) => {
                self.join(j, y);
                self.set_slip_or_rest(j, v[2 * j], rest);
                allowed.resize(rest.len(), Allowed::ANY);
            }
            Event::Halt(_) => {
                let Tangent::Slip(sigma) = self.modes.tangent[j] else {
                    unreachable!("a halt ends a slip")
                };
                if setup.mu[j] > 0.0 {
                    // It sticks or reverses (as with one contact).
                    rest.push(j);
                    allowed.push(Allowed {
                        stick: true,
                        positive: sigma < 0.0,
                        negative: sigma > 0.0,
                    });
                } else {
                    self.modes.tangent[j] = Tangent::Slip(0.0);
                }
            }
            Event::StickBreak(_) => {
                rest.push(j);
                allowed.push(Allowed {
                    stick: false,
                    positive: true,
                    negative: true,
                });
            }
        }
    }

    /// The normal changes of the contacts other than those of `except` already due at `y`
    /// (events of several contacts at one point: a symmetric body).
    fn settle(
        &mut self,
        except: &[bool; MAXK],
        y: &mut [f64],
        rest: &mut Vec<usize>,
        allowed: &mut Vec<Allowed>,
    ) {
        let setup = self.setup;
        for _ in 0..3 * setup.k {
            let v = eval(setup, &self.modes, y).v;
            let mut changed = false;
            for j in (0..setup.k).filter(|&j| !except[j]) {
                let (vn, s) = (v[2 * j + 1], y[PER * j + S]);
                match self.modes.normal[j] {
                    Normal::Compression if vn > 0.0 => self.end_compression(j, y),
                    Normal::Expansion if s <= 0.0 => self.separate(j, y),
                    Normal::Expansion if vn < -setup.approach => self.recompress(j, y),
                    Normal::Off if vn < -setup.approach => {
                        self.join(j, y);
                        let before = rest.len();
                        self.set_slip_or_rest(j, v[2 * j], rest);
                        allowed.resize(allowed.len() + rest.len() - before, Allowed::ANY);
                    }
                    _ => continue,
                }
                changed = true;
            }
            if !changed {
                return;
            }
        }
    }

    /// Compression of `j` ends (`v_nj = 0`): its compression work is the energy stored in
    /// this compression; it expands, or with `e_j = 0` its energy is lost and it is off.
    fn end_compression(&mut self, j: usize, y: &mut [f64]) {
        let setup = self.setup;
        let energy = setup.energy(j, y[PER * j + S]);
        self.tracks[j].work.end_compression(energy);
        if setup.e[j] == 0.0 {
            y[PER * j + S] = 0.0;
            self.go_off(j, y);
        } else {
            self.modes.normal[j] = Normal::Expansion;
            self.tracks[j].work.mark = energy;
        }
    }

    /// `j` separates (its stored energy is back to zero): the restitution work of this
    /// expansion is `e_j²` times the energy released.
    fn separate(&mut self, j: usize, y: &mut [f64]) {
        let setup = self.setup;
        let energy = setup.energy(j, y[PER * j + S]);
        let e2 = setup.e[j] * setup.e[j];
        self.tracks[j].work.end_expansion(energy, e2);
        y[PER * j + S] = 0.0;
        self.go_off(j, y);
    }

    /// `j` approaches again while loaded: the expansion so far is restitution work, a new
    /// compression begins.
    fn recompress(&mut self, j: usize, y: &[f64]) {
        let setup = self.setup;
        let energy = setup.energy(j, y[PER * j + S]);
        let e2 = setup.e[j] * setup.e[j];
        let work = &mut self.tracks[j].work;
        work.end_expansion(energy, e2);
        work.mark = energy;
        self.modes.normal[j] = Normal::Compression;
    }

    /// An off contact starts approaching: a new compression from zero energy.
    fn join(&mut self, j: usize, y: &[f64]) {
        let tr = &mut self.tracks[j];
        if tr.engaged {
            tr.result.push_phase(ContactPhaseKind::Off, y[PER * j + PN]);
        }
        tr.engaged = true;
        tr.work.mark = 0.0;
        self.modes.normal[j] = Normal::Compression;
        self.modes.tangent[j] = Tangent::Slip(0.0);
    }

    /// `j` carries no force any more: its phase ends; if it was the primary, the contact with
    /// the most stored energy takes over.
    fn go_off(&mut self, j: usize, y: &[f64]) {
        self.modes.normal[j] = Normal::Off;
        self.modes.tangent[j] = Tangent::Slip(0.0);
        let tr = &mut self.tracks[j];
        if let Some(label) = tr.label.take() {
            tr.result.push_phase(label, y[PER * j + PN]);
        }
        let (setup, modes) = (self.setup, &self.modes);
        self.primary.hand_over(
            j,
            setup.k,
            |c| setup.energy_order(c, y[PER * c + S]),
            |c| modes.active(c),
            |c| y[PER * c + PN],
        );
    }

    /// Choose the tangential regimes: the contacts `rest` (restricted by `allowed`) and
    /// every contact in stick, given the normal forces `f`; then the direction of the
    /// frictionless contacts at rest (that of their tangential acceleration).
    fn decide(
        &mut self,
        f: &[f64; MAXK],
        v: &[f64; 2 * MAXK],
        y: &[f64],
        mut rest: Vec<usize>,
        mut allowed: Vec<Allowed>,
    ) {
        let setup = self.setup;
        let k = setup.k;
        // Keep only active contacts with friction; add those in stick.
        let mut c = 0;
        while c < rest.len() {
            let j = rest[c];
            if !self.modes.active(j) || setup.mu[j] == 0.0 {
                rest.remove(c);
                allowed.remove(c);
            } else {
                c += 1;
            }
        }
        for j in 0..k {
            if self.modes.active(j) && self.modes.tangent[j] == Tangent::Stick && !rest.contains(&j)
            {
                rest.push(j);
                allowed.push(Allowed::ANY);
            }
        }
        if rest.is_empty() {
            rebuild(setup, &mut self.modes);
        } else {
            choose(setup, &mut self.modes, f, &rest, &allowed);
        }
        // Frictionless contacts at rest: the direction their slip takes.
        let pt = tangential_rates(setup, &self.modes, f);
        let acc = tangential_acceleration(setup, f, &pt);
        let ascale = acc[..k].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for j in 0..k {
            if self.modes.active(j) && setup.mu[j] == 0.0 {
                if let Tangent::Slip(0.0) = self.modes.tangent[j] {
                    let vt = v[2 * j];
                    let sigma = if vt.abs() > setup.approach {
                        vt.signum()
                    } else if acc[j].abs() > 1e-10 * ascale {
                        acc[j].signum()
                    } else {
                        0.0
                    };
                    self.modes.tangent[j] = Tangent::Slip(sigma);
                }
            }
        }
        self.after_change(y);
    }

    /// Record the tangential regimes that changed (a phase ends at the contact's own normal
    /// impulse).
    fn after_change(&mut self, y: &[f64]) {
        for j in 0..self.setup.k {
            if !self.modes.active(j) {
                continue;
            }
            let label = match self.modes.tangent[j] {
                Tangent::Stick => ContactPhaseKind::Stick,
                Tangent::Slip(s) if s > 0.0 => ContactPhaseKind::Slip(SlipDirection::Positive),
                Tangent::Slip(s) if s < 0.0 => ContactPhaseKind::Slip(SlipDirection::Negative),
                // Frictionless and not slipping: held at rest, as the one-contact path labels it.
                Tangent::Slip(_) => ContactPhaseKind::Stick,
            };
            let tr = &mut self.tracks[j];
            match tr.label {
                Some(old) if old != label => {
                    tr.result.push_phase(old, y[PER * j + PN]);
                    tr.label = Some(label);
                }
                Some(_) => {}
                None => tr.label = Some(label),
            }
        }
    }

    /// The primary contact along a step from `(t, y0)` to the fraction `theta` of `h`, where
    /// the state is `y1`: a contact whose stored energy exceeds the primary's by more than
    /// [`super::PRIMARY_MARGIN`] takes over, where its energy overtook the primary's (located
    /// on the dense output, which is built only then).
    fn follow_primary<const N: usize, D: Interpolant<N>>(
        &mut self,
        theta: f64,
        y0: &[f64; N],
        y1: &[f64; N],
        dense: &dyn Fn() -> D,
    ) {
        let (setup, modes) = (self.setup, &self.modes);
        self.primary.follow(
            setup.k,
            theta,
            y0,
            y1,
            dense,
            |j, y| setup.energy_order(j, y[PER * j + S]),
            |j| modes.active(j),
            |j, y| y[PER * j + PN],
        );
    }

    /// The impact has settled ([`settled`]): the contacts still carrying a force are off,
    /// their stored energy (below round-off) lost.
    fn end_settled(&mut self, y: &[f64]) {
        for j in 0..self.setup.k {
            if self.modes.active(j) {
                let energy = self.setup.energy(j, y[PER * j + S]);
                let tr = &mut self.tracks[j];
                if self.modes.normal[j] == Normal::Compression {
                    tr.work.end_compression(energy);
                } else {
                    let e2 = self.setup.e[j] * self.setup.e[j];
                    tr.work.end_expansion(energy, e2);
                }
                self.go_off(j, y);
            }
        }
    }

    /// The results at the end `y`.
    fn finish(self, y: &[f64], steps: usize) -> End {
        let setup = self.setup;
        let ev: Eval = eval(setup, &self.modes, y);
        let contacts = self
            .tracks
            .into_iter()
            .enumerate()
            .map(|(j, mut tr)| {
                let o = PER * j;
                tr.result.impulse = Vec2::new(y[o + PT], y[o + PN]);
                tr.result.velocity_after = Vec2::new(ev.v[2 * j], ev.v[2 * j + 1]);
                tr.result.work = WorkSplit {
                    compression: tr.work.compression,
                    restitution: tr.work.restitution,
                    friction: y[o + WT],
                };
                if !tr.engaged {
                    tr.result.push_phase(ContactPhaseKind::Off, 0.0);
                }
                tr.result
            })
            .collect();
        End {
            contacts,
            primaries: self.primary.list,
            steps,
        }
    }
}
