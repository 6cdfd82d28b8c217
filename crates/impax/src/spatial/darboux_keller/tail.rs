//! The closed-form ends of a slip (theory §2, "Spatial"): once the direction is on an
//! invariant ray, the rest of the slip is straight and every event on it exact (`linear`);
//! near a centripetal ray the series about it (`ray_series`) gives the rest, the halt on the
//! ray's angle and every event before it, to the tolerance.
//!
//! * **Straight tail**: the direction on a centripetal ray to the last bit of the result —
//!   the remaining impulse `σ/|ŝ·g|` times the angular offset from the ray below `1e-16` of
//!   the impulse scale ([`Slip::straight_tail`]) — runs straight into the origin.
//! * **Settled on a ray**: a slip on a ray that attracts the direction (`f' < 0`) whose speed
//!   changes slowly beside that attraction (`|q| ≤ 1e-3 |f'|`, a nearly neutral ray) once its
//!   offset is at the integration's own noise ([`Slip::settled_on_ray`]): straight along the
//!   ray, to a halt or, on the centrifugal ray, to the termination.
//! * **Series tail**: toward a centripetal ray, the normal form of the direction flow about
//!   it with every quadrature in closed form ([`RaySeries`], [`Slip::series_tail`]).

use super::events::{Event, Events};
use super::field::Field;
use super::linear::Linear;
use super::ray_series::RaySeries;
use super::slip::Slip;
use super::state::{Centrifugal, Point, SlipEnd};
use crate::law::BreakdownReason;
use crate::math::{norm_of, Vec2, Vec3};
use crate::numerics::roots::illinois;
use crate::spatial::invariant::polish_ray;
use crate::spatial::outcome::PhaseKind;

/// A slip settled on an invariant ray ([`Slip::settled_on_ray`]).
#[derive(Clone, Copy)]
pub(super) enum Settled {
    /// Shrinking along `dir` at the rate `rate < 0`, to a halt.
    Centripetal { dir: Vec2, rate: f64 },
    /// Growing along the centrifugal ray.
    Centrifugal(Centrifugal),
}

impl Slip {
    /// The rest of the slip is a straight run into the origin when the direction is (to the
    /// last bit of the result) on an invariant ray: the remaining impulse `σ/|ŝ·g|` times the
    /// angular offset from the ray is below `1e-16` of the impulse scale. Returns
    /// `(ŝ, ŝ·g)`.
    pub(super) fn straight_tail(&self, vt: Vec2) -> Option<(Vec2, f64)> {
        let (wtt, wtn, mu, sc) = (&self.wtt, self.wtn, self.mu, self.sc);
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
    }

    /// Run the straight tail along `s` (at the rate `q = ŝ·g < 0`) in closed form to the
    /// halt, or to the termination inside it.
    pub(super) fn run_tail(
        &self,
        pt: &mut Point,
        ev: &mut Events,
        s: Vec2,
        q: f64,
    ) -> Result<SlipEnd, BreakdownReason> {
        let (wtt, wtn, wnn, mu) = (&self.wtt, self.wtn, self.wnn, self.mu);
        let sigma = norm_of(pt.vt);
        // From the unnormalised slip: bit-identical to φ0 when the tail starts at v⁻.
        let phi = pt.vt.y.atan2(pt.vt.x);
        let piece = Linear {
            kind: PhaseKind::Stick,
            ratio: -mu * s,
            slope: wnn - mu * wtn.dot(&s),
            dir: s,
            sigma,
            dsigma: q,
            length: sigma / -q,
        };
        if piece.run(pt, ev, mu)? {
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
                self.field.ray_ahead(phi).map_or(phi, wrap_angle)
            };
            Ok(SlipEnd::Halted { phi: ray })
        }
    }

    /// A slip that has settled on an invariant ray that attracts the direction (`f' < 0`
    /// there: an offset δ obeys `dδ/dp_n = f' δ/σ`) runs straight along it, its speed
    /// changing at the ray's rate `q = ŝ·g`. Where `|q|` is small beside `|f'|` (a nearly
    /// neutral ray, near the stick limit of an ill-conditioned W) the steps in p_n, τ or the
    /// angle variable are held to the decay length `σ/|f'|` of the offset while the impulse
    /// to the next event or the halt is of order `σ/|q|`: millions of steps. There, once the
    /// offset is at the integration's own noise (`σ δ` within 4 rtol of the velocity scale,
    /// what the error control leaves in v_t), the rest is the straight run along the ray in
    /// closed form: the offset changes the result as little as one more step would. The ray
    /// is the root of `f` next to the direction (Newton's method); a centrifugal one is the
    /// direction of resumption, with its rate and slope from `centrifugal`.
    pub(super) fn settled_on_ray(&self, vt: Vec2) -> Option<Settled> {
        let (wtt, wtn, mu, sc) = (&self.wtt, self.wtn, self.mu, self.sc);
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
        let c = self.centrifugal?;
        (c.dir.dot(&dir) > 1.0 - 1e-9).then_some(Settled::Centrifugal(c))
    }

    /// Run the slip along the centrifugal ray in closed form to the termination.
    fn run_centrifugal(
        &self,
        pt: &mut Point,
        ev: &mut Events,
        c: Centrifugal,
    ) -> Result<SlipEnd, BreakdownReason> {
        let mu = self.mu;
        let piece = Linear {
            kind: PhaseKind::Stick,
            ratio: -mu * c.dir,
            slope: c.slope,
            dir: c.dir,
            sigma: norm_of(pt.vt),
            dsigma: c.rate,
            length: f64::INFINITY,
        };
        if piece.run(pt, ev, mu)? {
            Ok(SlipEnd::Terminated {
                phi: c.dir.y.atan2(c.dir.x),
            })
        } else {
            Err(BreakdownReason::NoSeparation)
        }
    }

    /// The end of a slip settled on a ray, straight along it in closed form.
    fn run_settled(
        &self,
        pt: &mut Point,
        ev: &mut Events,
        s: Settled,
    ) -> Result<SlipEnd, BreakdownReason> {
        match s {
            Settled::Centripetal { dir, rate } => self.run_tail(pt, ev, dir, rate),
            Settled::Centrifugal(c) => self.run_centrifugal(pt, ev, c),
        }
    }

    /// The rest of the slip in closed form if it is on a ray at `pt`: the straight tail
    /// ([`Slip::straight_tail`]) or else the run of a slip settled on a ray
    /// ([`Slip::settled_on_ray`]); `None` (nothing changed) if neither applies.
    pub(super) fn end_on_ray(
        &self,
        pt: &mut Point,
        ev: &mut Events,
    ) -> Result<Option<SlipEnd>, BreakdownReason> {
        if let Some((s, q)) = self.straight_tail(pt.vt) {
            return self.run_tail(pt, ev, s, q).map(Some);
        }
        if let Some(c) = self.settled_on_ray(pt.vt) {
            return self.run_settled(pt, ev, c).map(Some);
        }
        Ok(None)
    }

    /// The rest of a slip running into the centripetal ray of `ser`, in closed form
    /// ([`RaySeries`]), with the events in it located on the series: the end of the slip stage,
    /// or `None` (nothing changed) while the series does not yet give the rest to the
    /// tolerance (its truncation, relative to the rest's impulse, below `rtol` times the impulse
    /// scale over that impulse), or an event could hide inside it (`v_n` not monotone on the
    /// rest).
    pub(super) fn series_tail(
        &self,
        ser: &RaySeries,
        pt: &mut Point,
        ev: &mut Events,
        observe: &mut impl FnMut(f64, Vec3),
    ) -> Option<SlipEnd> {
        let (wtn, wnn, mu, sc) = (self.wtn, self.wnn, self.mu, self.sc);
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
            let Some((mut kind, ga, gb)) = ev.first(pt, &end) else {
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
            let find = |kind: Event, ga: f64, gb: f64| {
                if ga >= 0.0 {
                    // (A later compression that began at v_n = 0 exactly ends at once.)
                    return 0.0;
                }
                illinois(|th| ev.value(kind, &light(s_of(th))), 0.0, ga, 1.0, gb)
            };
            let mut th = find(kind, ga, gb);
            if ev.poisson_ends_first(kind, &light(s_of(th))) {
                kind = Event::LawEnd;
                th = find(kind, ev.terminal(pt), ev.terminal(&end));
            }
            *pt = if th >= 1.0 { end } else { at(s_of(th)) };
            observe(pt.p, Vec3::new(pt.vt.x, pt.vt.y, pt.vn));
            let phi = if th >= 1.0 {
                halt_phi
            } else {
                pt.vt.y.atan2(pt.vt.x)
            };
            if let Some(done) = ev.record(kind, pt, phi) {
                return Some(done);
            }
            if th >= 1.0 {
                return Some(SlipEnd::Halted { phi: halt_phi });
            }
        }
    }
}

/// The angle `φ` wrapped to `(−π, π]`.
#[inline]
fn wrap_angle(phi: f64) -> f64 {
    phi.sin().atan2(phi.cos())
}

/// The series about the centripetal invariant ray that a shrinking slip turns toward: the
/// ray is located once the direction turns slowly (`|ŝ × g| ≤ 0.15 |ŝ·g|`), the series
/// built once the direction is within 0.3 rad of it (where it can converge).
pub(super) struct TailSeries {
    ray: Option<Option<(f64, Vec2)>>,
    series: Option<RaySeries>,
    built: bool,
}

impl TailSeries {
    /// The ray not located yet.
    pub(super) fn new() -> TailSeries {
        TailSeries {
            ray: None,
            series: None,
            built: false,
        }
    }

    /// With the ray ahead already located.
    pub(super) fn with_ray(phi: f64, dir: Vec2) -> TailSeries {
        TailSeries {
            ray: Some(Some((phi, dir))),
            series: None,
            built: false,
        }
    }

    /// The series, once the slip `vt` (with `g = w_tn − μ W_tt ŝ` there) is close enough to
    /// the ray for it; built once (`None` until then, and for good if it does not attract the
    /// direction to a halt).
    pub(super) fn get(&mut self, field: &Field, wnn: f64, g: Vec2, vt: Vec2) -> Option<&RaySeries> {
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
