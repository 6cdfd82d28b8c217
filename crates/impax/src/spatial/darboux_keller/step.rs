//! One adaptive step of the slip in any of its integration variables (`p_n`, `ln σ`, `τ`):
//! the DOP853 step ([`crate::numerics::dop853`]) with its error test against
//! `atol + rtol |y|`, the first event inside an accepted step located on the discrete
//! solution, and the step-size factors.
//!
//! An event is located by re-stepping from the step's start with a shorter step, so that it
//! lies on the discrete solution itself: the root of the event function in the step's
//! fraction `θ` is seeded by the seventh-order dense output (Illinois iteration on it), then
//! found by Newton's iteration with the dense output's slope, or by the Illinois iteration
//! on a bracket of `±1e-9` about the seed ([`newton_from_seed`]), to near machine precision.

use super::events::{Event, Events};
use super::state::{Point, SlipEnd};
use crate::law::BreakdownReason;
use crate::math::Vec3;
use crate::numerics::dop853::{dop853_step, error_measure, Dense, Step};
use crate::numerics::roots::{illinois, newton_from_seed};

/// A variable of integration of the slip: the state vector in it (`N` components), its
/// right-hand side and the tolerances of its components.
pub(super) trait Variable<const N: usize> {
    /// The component of the state that holds `v_n` (set to its exact value after an event).
    const VN: usize;
    /// The right-hand side `dy/dx` at `(x, y)`.
    fn rhs(&self, x: f64, y: &[f64; N]) -> [f64; N];
    /// The point of the path at `(x, y)`.
    fn point(&self, x: f64, y: &[f64; N]) -> Point;
    /// The absolute tolerance of each component.
    fn atol(&self) -> &[f64; N];
    /// The relative tolerance.
    fn rtol(&self) -> f64;
}

/// The integration in one variable: the independent variable `x`, the state `y` and its
/// derivative `k` there (the first stage of the next step).
pub(super) struct Stepper<const N: usize> {
    /// The independent variable.
    pub x: f64,
    /// The state.
    pub y: [f64; N],
    /// `dy/dx` at `(x, y)`.
    pub k: [f64; N],
}

/// What one attempted step did.
pub(super) enum Advance {
    /// Rejected, with this error measure: the caller shrinks the step.
    Rejected(f64),
    /// Rejected, and the step is already negligible (below `1e-300` in the variable's
    /// canonical units, or lost in the round-off of `x`): shrinking it further cannot help.
    /// The caller reports this breakdown: [`BreakdownReason::Overflow`] if the step's result
    /// was not finite (the right-hand side overflows there), else
    /// [`BreakdownReason::NoSeparation`].
    Stalled(BreakdownReason),
    /// Accepted, with this error measure: the caller may grow the step.
    Accepted(f64),
    /// Stopped at an event inside the step: `Some` if the law terminated there.
    Event(Option<SlipEnd>),
}

/// An accepted step from `(x, y)` (derivative `k`) of size `h`, with its result `st` and the
/// derivative `k1` at its end.
struct Accepted<'a, const N: usize> {
    x: f64,
    y: &'a [f64; N],
    k: &'a [f64; N],
    h: f64,
    st: &'a Step<N>,
    k1: &'a [f64; N],
}

impl<const N: usize> Stepper<N> {
    /// Start at `(x, y)`.
    pub(super) fn new(var: &impl Variable<N>, x: f64, y: [f64; N]) -> Stepper<N> {
        let k = var.rhs(x, &y);
        Stepper { x, y, k }
    }

    /// One DOP853 step of size `h`: the error test against `atol + rtol |y|`, then the first
    /// event inside the step located on the discrete solution ([`locate_in_step`]) or else
    /// the whole step. On success the stepper, `pt` and `steps` advance and `observe` sees
    /// the new point; after an event the state's `v_n` takes the point's exact value.
    pub(super) fn advance<V: Variable<N>>(
        &mut self,
        var: &V,
        h: f64,
        pt: &mut Point,
        ev: &mut Events,
        steps: &mut u32,
        observe: &mut impl FnMut(f64, Vec3),
    ) -> Advance {
        let f = |x: f64, y: &[f64; N]| var.rhs(x, y);
        let (atol, rtol) = (var.atol(), var.rtol());
        let (x, y) = (self.x, &self.y);
        let st = dop853_step(&f, x, y, &self.k, h);
        let y1 = st.y;
        let en = error_measure(&st, |i| atol[i] + rtol * y[i].abs().max(y1[i].abs()));
        if en.is_nan() || en > 1.0 {
            if negligible(x, h) {
                return Advance::Stalled(if en.is_nan() {
                    BreakdownReason::Overflow
                } else {
                    BreakdownReason::NoSeparation
                });
            }
            return Advance::Rejected(en);
        }
        let b = var.point(x + h, &y1);
        let k1 = f(x + h, &y1);
        if let Some((mut event, ga, gb)) = ev.first(pt, &b) {
            let step = Accepted {
                x,
                y,
                k: &self.k,
                h,
                st: &st,
                k1: &k1,
            };
            let (mut xe, mut ye) = locate_in_step(var, ev, event, &step, ga, gb);
            if ev.poisson_ends_first(event, &var.point(xe, &ye)) {
                event = Event::LawEnd;
                let (ga, gb) = (ev.terminal(pt), ev.terminal(&b));
                (xe, ye) = locate_in_step(var, ev, event, &step, ga, gb);
            }
            self.x = xe;
            self.y = ye;
            *pt = var.point(xe, &ye);
            *steps += 1;
            observe(pt.p, pt.velocity());
            if let Some(end) = ev.record(event, pt, pt.vt.y.atan2(pt.vt.x)) {
                return Advance::Event(Some(end));
            }
            self.y[V::VN] = pt.vn;
            self.k = f(self.x, &self.y);
            return Advance::Event(None);
        }
        self.x += h;
        self.y = y1;
        self.k = k1;
        *pt = b;
        *steps += 1;
        observe(pt.p, pt.velocity());
        Advance::Accepted(en)
    }
}

/// Locate `event` inside the accepted `step`, its function `ga < 0` at the start and
/// `gb ≥ 0` at the end: seeded by the dense output, then found on the discrete solution by
/// re-stepping from the step's start. Returns the independent variable and the state there.
fn locate_in_step<const N: usize>(
    var: &impl Variable<N>,
    ev: &Events,
    event: Event,
    step: &Accepted<N>,
    ga: f64,
    gb: f64,
) -> (f64, [f64; N]) {
    let f = |x: f64, y: &[f64; N]| var.rhs(x, y);
    let Accepted {
        x: x0,
        y: y0,
        k: k0,
        h,
        st,
        k1,
    } = *step;
    if ga >= 0.0 {
        // (The end of a later compression that began at v_n = 0 exactly: at the start.)
        return (x0, *y0);
    }
    let dense = Dense::new(&f, x0, y0, st, k1, h);
    let dense_g = |th: f64| ev.value(event, &var.point(x0 + th * h, &dense.at(th)));
    let seed = illinois(dense_g, 0.0, ga, 1.0, gb);
    let (a, b) = ((seed - 1e-6).max(0.0), (seed + 1e-6).min(1.0));
    let slope = (dense_g(b) - dense_g(a)) / (b - a);
    let mut last = (f64::NAN, *y0);
    let theta = newton_from_seed(
        |th| {
            let yt = dop853_step(&f, x0, y0, k0, th * h).y;
            last = (th, yt);
            ev.value(event, &var.point(x0 + th * h, &yt))
        },
        ga,
        gb,
        seed,
        slope,
    );
    let yt = if last.0 == theta {
        last.1
    } else {
        dop853_step(&f, x0, y0, k0, theta * h).y
    };
    (x0 + theta * h, yt)
}

/// Whether the step `h` from `x` is too small to be worth another attempt: not above
/// `1e-300` in size (the variables are in canonical units), or lost in `x`'s round-off.
#[inline]
fn negligible(x: f64, h: f64) -> bool {
    h.abs().is_nan() || h.abs() <= 1e-300 || x + h == x
}

/// Step-size factor after a rejected step (`en > 1` or NaN): `0.9 en^(-1/8)`, at least 0.2.
#[inline]
pub(super) fn shrink(en: f64) -> f64 {
    if en.is_finite() {
        (0.9 / en.sqrt().sqrt().sqrt()).max(0.2)
    } else {
        0.2
    }
}

/// Step-size factor after an accepted step: `0.9 en^(-1/8)`, at most 6.
#[inline]
pub(super) fn grow(en: f64) -> f64 {
    (0.9 / en.max(1e-10).sqrt().sqrt().sqrt()).min(6.0)
}
