//! Piecewise-linear impulse paths in contact space.
//!
//! Every planar law, algebraic or incremental, moves the impulse along a polyline in the
//! `(p_t, p_n)` plane parameterised by the normal impulse `p_n`: on each segment the friction
//! ratio `k = dp_t/dp_n` is constant, so the contact velocity
//! `v(p_n) = v_start + (W_tt k + W_tn, W_tn k + W_nn) (p_n − p_start)` is linear, the normal
//! work `∫ v_n dp_n` quadratic, and every event (halt of slip, end of compression, each
//! termination rule) is the root of a linear or quadratic equation: exact, with no tolerance.

use super::outcome::{PhaseKind, Phases};
use super::ContactProblem;
use crate::math::Vec2;

/// One straight piece of an impulse path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Regime on this piece.
    pub kind: PhaseKind,
    /// Friction ratio `k = dp_t/dp_n`.
    pub ratio: f64,
    /// Normal impulse at the start.
    pub start: f64,
    /// Normal impulse at the end (`f64::INFINITY` for the last, open piece).
    pub end: f64,
    /// Contact velocity at the start.
    pub v_start: Vec2,
    /// Tangential impulse at the start.
    pub pt_start: f64,
    /// `dv/dp_n` on this piece.
    pub slope: Vec2,
}

impl Segment {
    #[inline]
    fn velocity_at(&self, pn: f64) -> Vec2 {
        self.v_start + self.slope * (pn - self.start)
    }
    /// `∫ v_n dp_n` from the segment start to `pn`.
    #[inline]
    fn normal_work_to(&self, pn: f64) -> f64 {
        let x = pn - self.start;
        x * (self.v_start.y + 0.5 * self.slope.y * x)
    }
    /// `∫ v_t dp_t = k ∫ v_t dp_n` from the segment start to `pn`.
    #[inline]
    fn friction_work_to(&self, pn: f64) -> f64 {
        let x = pn - self.start;
        self.ratio * x * (self.v_start.x + 0.5 * self.slope.x * x)
    }
}

/// Everything the outcome record needs from a path ended at `p_f`, gathered in one pass.
#[derive(Debug, Clone, Copy)]
pub struct PathSummary {
    /// Impulse at `p_f`.
    pub impulse: Vec2,
    /// Contact velocity at `p_f`.
    pub velocity: Vec2,
    /// First `p_n ≤ p_f` with `v_n = 0`, if any.
    pub compression_impulse: Option<f64>,
    /// Normal work up to the end of compression (or to `p_f` if compression does not end).
    pub compression_work: f64,
    /// Normal work up to `p_f`.
    pub normal_work: f64,
    /// Friction work up to `p_f`.
    pub friction_work: f64,
    /// Phases up to `p_f`.
    pub phases: Phases,
}

/// The summary of a straight path `p = p_n (k, 1)`, `0 ≤ p_n ≤ p_f`, in closed form: the
/// algebraic laws' single segment, without building an [`ImpulsePath`].
#[inline]
pub fn line_summary(problem: &ContactProblem, kind: PhaseKind, ratio: f64, pf: f64) -> PathSummary {
    let (a, b, c) = (problem.wtt(), problem.wtn(), problem.wnn());
    let v = problem.velocity();
    let slope = Vec2::new(a * ratio + b, b * ratio + c);
    let normal_work = pf * (v.y + 0.5 * slope.y * pf);
    let (compression_impulse, compression_work) = if v.y >= 0.0 {
        (Some(0.0), 0.0)
    } else if slope.y > 0.0 {
        // Every straight law ends by Newton's rule, v_n(p_f) = −e v_n⁻ ≥ 0: compression has
        // ended by p_f (at p_f when e = 0, whatever the round-off of p_f).
        let pc = (-v.y / slope.y).min(pf);
        (Some(pc), pc * (v.y + 0.5 * slope.y * pc))
    } else {
        (None, normal_work)
    };
    let mut phases = Phases::new();
    phases.push(kind, pf);
    PathSummary {
        impulse: Vec2::new(ratio * pf, pf),
        velocity: v + slope * pf,
        compression_impulse,
        compression_work,
        normal_work,
        friction_work: ratio * pf * (v.x + 0.5 * slope.x * pf),
        phases,
    }
}

/// A polyline impulse path of at most [`ImpulsePath::CAPACITY`] segments, built in order.
#[derive(Debug, Clone, Copy)]
pub struct ImpulsePath {
    a: f64,
    b: f64,
    c: f64,
    segs: [Segment; ImpulsePath::CAPACITY],
    len: usize,
}

impl ImpulsePath {
    /// Most segments a planar law needs.
    pub const CAPACITY: usize = 2;

    /// An empty path starting at `p = 0`, `v = v⁻`.
    #[inline(always)]
    pub fn new(problem: &ContactProblem) -> Self {
        let v = problem.velocity();
        let blank = Segment {
            kind: PhaseKind::Stick,
            ratio: 0.0,
            start: 0.0,
            end: 0.0,
            v_start: v,
            pt_start: 0.0,
            slope: Vec2::zeros(),
        };
        Self {
            a: problem.wtt(),
            b: problem.wtn(),
            c: problem.wnn(),
            segs: [blank; Self::CAPACITY],
            len: 0,
        }
    }

    /// `dv/dp_n` for friction ratio `k`: `W (k, 1)`.
    #[inline]
    pub fn slope_for(&self, ratio: f64) -> Vec2 {
        Vec2::new(self.a * ratio + self.b, self.b * ratio + self.c)
    }

    /// Append a segment with ratio `k` ending at normal impulse `end` (≥ the current end).
    #[inline(always)]
    pub fn push(&mut self, kind: PhaseKind, ratio: f64, end: f64) {
        let (start, v_start, pt_start) = if self.len == 0 {
            (0.0, self.segs[0].v_start, 0.0)
        } else {
            let last = &self.segs[self.len - 1];
            (
                last.end,
                last.velocity_at(last.end),
                last.pt_start + last.ratio * (last.end - last.start),
            )
        };
        assert!(self.len < Self::CAPACITY, "impulse path capacity exceeded");
        self.segs[self.len] = Segment {
            kind,
            ratio,
            start,
            end,
            v_start,
            pt_start,
            slope: self.slope_for(ratio),
        };
        self.len += 1;
    }

    /// Append a segment that starts where the previous one brought the slip to rest: its
    /// starting tangential velocity is exactly zero (the halt is defined by `v_t = 0`; the
    /// recomputed `v_t` would carry round-off).
    #[inline(always)]
    pub fn push_from_rest(&mut self, kind: PhaseKind, ratio: f64, end: f64) {
        self.push(kind, ratio, end);
        self.segs[self.len - 1].v_start.x = 0.0;
    }

    /// Segments so far.
    pub fn segments(&self) -> &[Segment] {
        &self.segs[..self.len]
    }

    /// Index of the segment containing `pn` (the last one if beyond).
    #[inline]
    fn index_of(&self, pn: f64) -> usize {
        let mut i = 0;
        while i + 1 < self.len && pn > self.segs[i].end {
            i += 1;
        }
        i
    }

    /// Contact velocity at normal impulse `pn`.
    pub fn velocity_at(&self, pn: f64) -> Vec2 {
        self.segs[self.index_of(pn)].velocity_at(pn)
    }

    /// Impulse, velocity, compression, works and phases of the path ended at `pf`, in one
    /// pass over the segments.
    #[inline(always)]
    pub fn summarize(&self, pf: f64) -> PathSummary {
        let mut out = PathSummary {
            impulse: Vec2::new(0.0, pf),
            velocity: self.segs[0].v_start,
            compression_impulse: None,
            compression_work: 0.0,
            normal_work: 0.0,
            friction_work: 0.0,
            phases: Phases::new(),
        };
        for (i, s) in self.segments().iter().enumerate() {
            let last = i + 1 == self.len || pf <= s.end;
            let end = if last { pf } else { s.end };
            let len = end - s.start;
            if out.compression_impulse.is_none() {
                if s.v_start.y >= 0.0 {
                    out.compression_impulse = Some(s.start);
                    out.compression_work = out.normal_work;
                } else if s.slope.y > 0.0 {
                    // Compare absolute impulses, computed as in `first_normal_velocity`, so
                    // that a termination at the end of compression (e = 0) finds it exactly.
                    let pc = s.start + -s.v_start.y / s.slope.y;
                    if pc <= end {
                        out.compression_impulse = Some(pc);
                        out.compression_work = out.normal_work + s.normal_work_to(pc);
                    }
                }
            }
            out.normal_work += s.normal_work_to(end);
            out.friction_work += s.friction_work_to(end);
            out.phases.push(s.kind, end);
            if last {
                out.impulse.x = s.pt_start + s.ratio * len;
                out.velocity = s.v_start + s.slope * len;
                break;
            }
        }
        if out.compression_impulse.is_none() {
            out.compression_work = out.normal_work;
        }
        out
    }
}
