//! The integration's state between two accepted points ([`Stepper`]): where it starts
//! (in `z = τ^(η+1)` from the impact's start, or in `τ` after a phase in closed form), how it
//! restarts after an event, and the first event inside a step, located on the step's series
//! or dense output.

use super::events;
use super::field::{Eval, Field};
use super::series::Series;
use super::state::{Modes, Setup, MAXK};
use super::variable::Var;
use crate::numerics::dop853::Interpolant;
use crate::numerics::roots::illinois;

use super::common::guard;

/// The first step of `τ` after a phase in closed form, as a fraction of the shortest time a
/// contact alone would compress in.
pub(super) const FIRST_STEP: f64 = 0.01;

/// The least ratio of the slowest approach at the start to the fastest for which the start is
/// taken in `z`. A contact that barely approaches (`q_j(0) = −v_nj⁻` small) has `q_j` pushed
/// up by the others' forces from almost zero, where `q_j^η` is singular: the series' radius
/// shrinks with `q_j(0)`, and the start in `z` takes more steps than in `u` (on a two-contact
/// problem, 21 against 19 at `10⁻⁴` of the fastest, 16 against 18 at `10⁻³`). Below it the
/// start is [`fallback`]'s.
const ONSET_SPREAD: f64 = 1e-3;

/// The start: the variable, its first step, and the shortest time a contact alone would
/// compress in. In `z = τ^(η+1)`, whose series takes the path to the first event
/// (`series/onset.rs`), where the approaches are within [`ONSET_SPREAD`] of each other, else
/// in `u` ([`fallback`]); the first step, for DOP853 only, a tenth of the way to a quarter of
/// that time.
fn start(setup: &Setup) -> (Var, f64, f64) {
    let mut shortest = f64::INFINITY;
    let (mut qmin, mut qmax) = (f64::INFINITY, 0.0f64);
    for j in 0..setup.k {
        let vn = setup.v0[2 * j + 1];
        if vn < -setup.approach {
            let wnn = setup.w[2 * j + 1][2 * j + 1];
            shortest = shortest.min(setup.law.compression_time(setup.kappa[j], wnn, vn));
            qmin = qmin.min(-vn);
            qmax = qmax.max(-vn);
        }
    }
    if qmin < ONSET_SPREAD * qmax {
        let (var, _, h) = fallback(setup, 0.0, shortest);
        return (var, h, shortest);
    }
    let h = (0.025 * shortest).powf(setup.law.eta + 1.0);
    (Var::Onset, h, shortest)
}

/// Where the start's series does not apply (approaches further apart than [`ONSET_SPREAD`], a
/// force below the normal numbers, coefficients that overflow): the same point in
/// `u = τ^(1/m)` (DOP853 steps, until a quarter of the shortest compression time), or in `τ`
/// for an integer exponent; the first step a tenth of the way (from the start).
fn fallback(setup: &Setup, z: f64, shortest: f64) -> (Var, f64, f64) {
    let tau = setup.law.onset_time(z);
    let m = f64::from(setup.law.m);
    if setup.law.m == 1 {
        (Var::Time, tau, 0.01 * shortest)
    } else {
        let u = tau.powf(1.0 / m);
        let h = 0.1 * (0.25 * shortest).powf(1.0 / m);
        (Var::Root, u, if u > 0.0 { h.min(0.1 * u) } else { h })
    }
}

/// The integration's state between two accepted points: the variable and where it is, the
/// step to try, the regimes and their field, the derivative at the point, the events
/// watched and their functions there.
pub(super) struct Stepper<'a, const N: usize> {
    pub(super) setup: &'a Setup,
    pub(super) var: Var,
    pub(super) x: f64,
    pub(super) h: f64,
    pub(super) modes: Modes,
    pub(super) field: Field,
    pub(super) k1: [f64; N],
    pub(super) watch: events::Watch,
    pub(super) g_a: [f64; 3 * MAXK],
    /// The shortest time a contact alone would compress in, and where the start in `u`
    /// ends (a quarter of it).
    pub(super) shortest: f64,
    pub(super) root_end: f64,
}

impl<'a, const N: usize> Stepper<'a, N> {
    /// The start ([`start`]) from the point `y` in the regimes `modes`.
    pub(super) fn start(setup: &'a Setup, modes: Modes, y: &[f64; N]) -> Self {
        let (var, h, shortest) = start(setup);
        let field = Field::new(setup, &modes);
        let k1 = var.rhs::<N>(setup, &field, 0.0, y);
        let ev = field.eval::<N>(setup, y);
        let watch = events::watch(setup, &modes, y, &ev);
        let g_a = events::values(setup, &modes, &watch, y, &ev);
        Stepper {
            setup,
            var,
            x: 0.0,
            h,
            modes,
            field,
            k1,
            watch,
            g_a,
            shortest,
            root_end: 0.25 * shortest,
        }
    }

    /// The integration from the point `y` in the regimes `modes` reached in closed form
    /// (`closed.rs`): in time, with a first step of [`FIRST_STEP`] of the shortest time a
    /// contact alone would compress in.
    pub(super) fn resume(setup: &'a Setup, modes: Modes, y: &[f64; N]) -> Self {
        let mut it = Self::start(setup, modes, y);
        let field = Field::new(setup, &modes);
        let ev = field.eval::<N>(setup, y);
        let h = FIRST_STEP * it.shortest;
        it.restart(modes, field, &ev, y, h);
        it
    }

    /// On from the point `y` in the regimes `modes` (changed by an event; `field` theirs,
    /// `ev` the point's quantities in it) with the step `h` of `τ`: in time, or in a
    /// separation's variable if one is near.
    pub(super) fn restart(&mut self, modes: Modes, field: Field, ev: &Eval, y: &[f64; N], h: f64) {
        let setup = self.setup;
        self.modes = modes;
        self.field = field;
        self.var = Var::Time.next(setup, &modes, 0.0, h, y, &ev.v, self.root_end);
        (self.x, self.h) = self.var.start_from_time(setup, y, h, &ev.v);
        self.k1 = self.var.rhs::<N>(setup, &self.field, self.x, y);
        self.watch = events::watch(setup, &modes, y, ev);
        self.g_a = events::values(setup, &modes, &self.watch, y, ev);
    }

    /// Leave the start's variable for [`fallback`]'s, at the point `y`.
    pub(super) fn leave_onset(&mut self, y: &[f64; N]) {
        let (var, x, h) = fallback(self.setup, self.x, self.shortest);
        (self.var, self.x, self.h) = (var, x, h);
        self.k1 = var.rhs::<N>(self.setup, &self.field, x, y);
    }

    /// The step `h` of the current variable at `x` (velocities `v`) as a step of `τ`.
    pub(super) fn time_step(&self, h: f64, v: &[f64; 2 * MAXK]) -> f64 {
        guard(self.var.to_time(self.setup, self.x, h, v), self.shortest)
    }

    /// The first of the events whose functions go from `g_a` to `g_b` across the step (the
    /// watched ones that `crosses`), located on the step's series — each function a
    /// polynomial of it ([`Series::locate`]) — or on the Runge–Kutta step's dense output
    /// (`series` `None`): its fraction of the step and its index in the watch.
    pub(super) fn first_event(
        &self,
        dense: &impl Interpolant<N>,
        series: Option<&Series<N>>,
        g_b: &[f64; 3 * MAXK],
        crosses: impl Fn(usize) -> bool,
    ) -> (f64, usize) {
        let (setup, watch) = (self.setup, &self.watch);
        let mut first: Option<(f64, usize)> = None;
        for i in (0..watch.n).filter(|&i| crosses(i)) {
            let seed = if self.g_a[i] == 0.0 {
                0.0
            } else if let Some(ser) = series {
                ser.locate(
                    setup,
                    &self.modes,
                    &self.field,
                    watch,
                    i,
                    (self.g_a[i], g_b[i]),
                )
            } else {
                let g = |th: f64| {
                    let z = dense.at(th);
                    let ev = self.field.eval::<N>(setup, &z);
                    events::value(setup, &self.modes, watch, i, &z, &ev)
                };
                illinois(g, 0.0, self.g_a[i], 1.0, g_b[i])
            };
            if first.is_none_or(|(th, _)| seed < th) {
                first = Some((seed, i));
            }
        }
        first.expect("a crossing")
    }
}
