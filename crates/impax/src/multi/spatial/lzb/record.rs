//! What each event changes — the normal and tangential regimes — and the record of each
//! contact (works, phases) and of the primary contact.
//!
//! The phases use the one-contact vocabulary ([`PhaseKind`]): a slip that was sliding when
//! the contact engaged is `slip(from → to)`, its direction at the start and at the end
//! (the fixed direction it halted along); a slip that left rest (after a halt, a stick, at
//! the start or joining at rest) is `resumed-slip(angle)`, the ray it left along (its
//! direction may turn afterwards); `stick`; a frictionless contact's phase is
//! `slip(from → to)` of its slip (`resumed-slip` if it was at rest at the start, `stick` if
//! at rest throughout); `off` between two engagements, one `off` if it never engaged.

use super::events::Event;
use super::field::{eval, slip, slip_rate, Eval};
use super::friction::{choose, halting_ray, rebuild, Allowed};
use super::state::{Modes, Normal, Setup, StickSet, Tangent, MAXK, PER, PN, PT1, PT2, ROWS, S, WT};
use super::variable::HALT_AHEAD;
use crate::law::WorkSplit;
use crate::math::{Vec2, Vec3};
use crate::multi::lzb::common::{NormalWork, Primary};
use crate::multi::spatial::{ContactPhaseKind, ContactResult};
use crate::multi::LzbPrimary;
use crate::numerics::dop853::Dense;
use crate::spatial::PhaseKind;

/// What the path ends with (canonical units).
pub(super) struct End {
    /// One result per contact.
    pub contacts: Vec<ContactResult>,
    /// The primary contacts in turn.
    pub primaries: Vec<LzbPrimary>,
    /// The accepted steps.
    pub steps: usize,
}

/// The current tangential phase of a contact (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Label {
    /// A slip sliding since the angle `from`; `to` the angle of the ray it halts on, once
    /// known.
    Slip { from: f64, to: Option<f64> },
    /// A slip that left rest along `angle`.
    Resumed { angle: f64 },
    /// Stick.
    Stick,
    /// A frictionless contact, its slip's angle when the phase began if it was slipping.
    Free { from: Option<f64> },
}

/// One contact's record.
#[derive(Debug, Clone)]
struct Track {
    /// The normal work so far.
    work: NormalWork,
    /// The current tangential phase, while the contact carries a force.
    label: Option<Label>,
    /// The result being built (phases).
    result: ContactResult,
    /// Whether it has carried a force.
    engaged: bool,
}

/// The regimes, the records and the primary.
pub(super) struct Path<'a> {
    pub setup: &'a Setup,
    pub modes: Modes,
    tracks: Vec<Track>,
    primary: Primary,
    /// Each halting slip's last comparison with its ray: the ray's angle, the slip then and
    /// the angle between its direction and the ray.
    rays: [Option<(f64, f64, f64)>; MAXK],
}

/// The angle of `d` in the tangent plane.
#[inline]
fn angle(d: Vec2) -> f64 {
    d.y.atan2(d.x)
}

/// The angle between the unit vectors `a` and `b`.
#[inline]
fn between(a: Vec2, b: Vec2) -> f64 {
    (a.x * b.y - a.y * b.x).atan2(a.dot(&b)).abs()
}

impl<'a> Path<'a> {
    /// The regimes at the start: the approaching contacts (`v_nj⁻ < −approach`) in
    /// compression, the tangential regimes chosen with the forces' limiting ratios
    /// `F_j ∝ κ_j |v_nj⁻|^η` (at `τ → 0`, `s_j ≈ −v_nj⁻ τ`).
    pub(super) fn start(setup: &'a Setup, y: &[f64]) -> Path<'a> {
        let k = setup.k;
        let mut modes = Modes {
            normal: [Normal::Off; MAXK],
            tangent: [Tangent::Slip; MAXK],
            stick: StickSet::EMPTY,
            limit: [0.0; MAXK],
        };
        let mut f = [0.0; MAXK];
        let mut best = (f64::NEG_INFINITY, 0);
        for (j, fj) in f.iter_mut().enumerate().take(k) {
            let vn = setup.v0[3 * j + 2];
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
                result: ContactResult::empty(),
                engaged: modes.active(j),
            })
            .collect();
        let mut path = Path {
            setup,
            modes,
            tracks,
            primary: Primary::start(best.1),
            rays: [None; MAXK],
        };
        let before = path.modes.tangent;
        let mut rest = Vec::new();
        for j in 0..k {
            if path.modes.active(j) {
                path.set_slip_or_rest(j, slip(&setup.v0, j), &mut rest);
            }
        }
        let allowed = vec![Allowed::ANY; rest.len()];
        path.decide(&f, &setup.v0, y, rest, allowed, &before);
        path
    }

    /// An active contact with friction at rest (`|v_t| ≤` the round-off) goes to `rest`
    /// (its regime to be chosen); one slipping below `2 σ_f` ([`Setup::freeze`]) goes on
    /// along its direction to its halt; otherwise it slips along its own direction.
    fn set_slip_or_rest(&mut self, j: usize, vt: Vec2, rest: &mut Vec<usize>) {
        let setup = self.setup;
        let sigma = vt.norm();
        self.modes.limit[j] = 2.0 * setup.freeze;
        self.rays[j] = None;
        self.modes.tangent[j] = if setup.mu[j] == 0.0 || sigma > 2.0 * setup.freeze {
            Tangent::Slip
        } else if sigma > setup.approach {
            self.modes.limit[j] = 2.0 * sigma;
            Tangent::Fixed {
                dir: vt / sigma,
                leaving: false,
            }
        } else {
            rest.push(j);
            Tangent::Slip
        };
    }

    /// Contact `j`'s slip along its own direction has fallen to `2 σ_f`: it goes on along
    /// the ray it halts on if its direction is within `σ_f / σ` of that ray, else along its
    /// own direction (the halt reported on the ray).
    fn near_halt(&mut self, j: usize, ev: &Eval) {
        let setup = self.setup;
        let vt = slip(&ev.v, j);
        let sigma = vt.norm();
        let s0 = vt / sigma;
        let hint = self.rays[j].map(|(phi, ..)| phi);
        let ray = halting_ray(setup, &self.modes, &ev.f, &ev.v, j, s0, hint);
        let close = ray.is_some_and(|d| sigma * between(s0, d) <= setup.freeze);
        let dir = if close { ray.unwrap_or(s0) } else { s0 };
        self.fix(j, dir, ray, sigma);
    }

    /// A slip going on along the ray it halts on ([`Path::check_halts`]) short of its halt
    /// (`σ > 2 σ_f`) slips freely again at any event but its own slip's (`own` the contacts
    /// whose slips have their own events here — a halt, a stick breaking —, `rest` those
    /// whose regimes are to be chosen): the ray was its slip field's, extrapolated to the
    /// halt, and the event changes how that field evolves (a contact joining before the halt
    /// adds its force). It is compared with its ray again from the next steps.
    fn release_fixed(&mut self, own: &[bool; MAXK], ev: &Eval, rest: &[usize]) {
        let setup = self.setup;
        for (c, &own) in own.iter().enumerate().take(setup.k) {
            if own || rest.contains(&c) || !self.modes.active(c) {
                continue;
            }
            let Tangent::Fixed { leaving: false, .. } = self.modes.tangent[c] else {
                continue;
            };
            if slip(&ev.v, c).norm() > 2.0 * setup.freeze {
                self.modes.tangent[c] = Tangent::Slip;
                self.modes.limit[c] = 2.0 * setup.freeze;
                self.rays[c] = None;
                if let Some(Label::Slip { to, .. }) = &mut self.tracks[c].label {
                    *to = None;
                }
            }
        }
    }

    /// Contact `j`'s slip along its own direction `dir`, on a straight line, halts here
    /// (a phase in closed form, `closed.rs`): it halts along `dir`, as from the last bit.
    pub(super) fn halt_along(&mut self, j: usize, dir: Vec2) {
        self.fix(j, dir, Some(dir), 0.0);
    }

    /// Contact `j`'s slip (now `sigma`) goes on along `dir` to its halt, reported on `ray`.
    fn fix(&mut self, j: usize, dir: Vec2, ray: Option<Vec2>, sigma: f64) {
        self.modes.tangent[j] = Tangent::Fixed {
            dir,
            leaving: false,
        };
        self.modes.limit[j] = 2.0 * sigma;
        self.rays[j] = None;
        if let (Some(Label::Slip { to, .. }), Some(ray)) = (&mut self.tracks[j].label, ray) {
            *to = Some(angle(ray));
        }
    }

    /// At the end of an accepted step (quantities `ev`; the next step `h` of `τ`): each slip
    /// shrinking towards a halt within the next [`HALT_AHEAD`] steps, or below
    /// [`Setup::near`], is compared with the ray it halts on (module docs: the halt); it goes
    /// on along the ray once the slip `σ` times the angle `δ` between its direction and the
    /// ray, with the ray's drift over the rest of the slip (extrapolated from the last
    /// comparison), is below [`Setup::freeze`]: `σ (δ + |Δφ*| σ/(σ' − σ)) ≤ σ_f`, and the
    /// direction has closed on the ray since that comparison (`δ ≤ δ'`; or is on it to
    /// round-off): a direction swinging past the ray, or leaving one that repels it, is
    /// not on its way to the ray, though `δ` be small where it passes. Returns whether any
    /// did.
    pub(super) fn check_halts(&mut self, ev: &Eval, h: f64) -> bool {
        let setup = self.setup;
        let mut fixed = false;
        for j in 0..setup.k {
            if !self.modes.active(j) || setup.mu[j] == 0.0 || self.modes.tangent[j] != Tangent::Slip
            {
                continue;
            }
            let vt = slip(&ev.v, j);
            let sigma = vt.norm();
            let s0 = vt / sigma;
            let q = s0.dot(&slip_rate(setup, j, &ev.f, &ev.pt));
            // (Not shrinking, NaN included, or not near a halt.)
            let shrinks = q < 0.0;
            if !shrinks || (sigma > -q * HALT_AHEAD * h && sigma > setup.near) {
                self.rays[j] = None;
                continue;
            }
            let hint = self.rays[j].map(|(phi, ..)| phi);
            let Some(ray) = halting_ray(setup, &self.modes, &ev.f, &ev.v, j, s0, hint) else {
                self.rays[j] = None;
                continue;
            };
            let phi = angle(ray);
            let delta = between(s0, ray);
            // The ray's drift over the rest of the slip, extrapolated from the last
            // comparison; and whether the direction closes on the ray (a direction that
            // swings past it, or leaves a ray that repels, is not on its way to it), or is
            // on it to round-off (its deviation `σ δ` a thousandth of `σ_f`).
            let (drift, closing) = match self.rays[j] {
                Some((before, at, delta_then)) if at > sigma => {
                    let turned = (phi - before).sin().atan2((phi - before).cos()).abs();
                    (
                        turned * sigma / (at - sigma),
                        delta <= delta_then || sigma * delta <= 1e-3 * setup.freeze,
                    )
                }
                _ => (f64::INFINITY, false),
            };
            self.rays[j] = Some((phi, sigma, delta));
            if closing && sigma * (delta + drift) <= setup.freeze {
                self.fix(j, ray, Some(ray), sigma);
                fixed = true;
            }
        }
        fixed
    }

    /// What `event` changes at the point `y` (located there), then the other contacts'
    /// changes due at the same point and the tangential regimes.
    pub(super) fn apply(&mut self, events: &[Event], y: &mut [f64]) {
        let setup = self.setup;
        let before = self.modes.tangent;
        let mut rest = Vec::new();
        let mut allowed = Vec::new();
        let ev = eval(setup, &self.modes, y);
        let mut done = [false; MAXK];
        let mut own = [false; MAXK];
        for &event in events {
            done[event.contact()] = true;
            own[event.contact()] |= matches!(
                event,
                Event::NearHalt(_) | Event::Halt(_) | Event::Live(_) | Event::StickBreak(_)
            );
            self.change(event, &ev, y, &mut rest, &mut allowed);
        }
        self.release_fixed(&own, &ev, &rest);
        self.settle(&done, y, &mut rest, &mut allowed);
        let ev = eval(setup, &self.modes, y);
        self.decide(&ev.f, &ev.v, y, rest, allowed, &before);
    }

    /// What `event` changes at the point `y` (quantities `ev`): the normal regime, or the
    /// contacts whose tangential regime is to be chosen (`rest`, restricted by `allowed`).
    fn change(
        &mut self,
        event: Event,
        ev: &Eval,
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
                let before = rest.len();
                self.set_slip_or_rest(j, slip(&ev.v, j), rest);
                allowed.resize(allowed.len() + rest.len() - before, Allowed::ANY);
            }
            Event::NearHalt(_) => self.near_halt(j, ev),
            Event::Halt(_) => {
                // It sticks or leaves rest along the dynamics' ray; so do the other slips
                // halting along fixed directions within σ_f of their own halts (a symmetric
                // body's corners halt together).
                for c in (0..setup.k).filter(|&c| self.modes.active(c) && setup.mu[c] > 0.0) {
                    let together = match self.modes.tangent[c] {
                        Tangent::Fixed {
                            dir,
                            leaving: false,
                        } => dir.dot(&slip(&ev.v, c)) <= setup.freeze,
                        _ => false,
                    };
                    if c == j || together {
                        rest.push(c);
                        allowed.push(Allowed::ANY);
                    }
                }
            }
            Event::Live(_) => {
                self.modes.tangent[j] = Tangent::Slip;
                self.modes.limit[j] = 2.0 * setup.freeze;
                self.rays[j] = None;
            }
            Event::StickBreak(_) => {
                rest.push(j);
                allowed.push(Allowed::SLIP);
            }
        }
    }

    /// The normal changes of the contacts not `done` already due at `y` (events of
    /// several contacts at one point: a symmetric body). A compression ends here if it is
    /// within the approach round-off of its end (`v_n > −a`): a symmetric body's contacts
    /// end their compressions together, and with `e = 0` one going off first would leave
    /// the others pressing unequally for a moment; an expansion if what it has left to give
    /// is below the integration's tolerance.
    fn settle(
        &mut self,
        done: &[bool; MAXK],
        y: &mut [f64],
        rest: &mut Vec<usize>,
        allowed: &mut Vec<Allowed>,
    ) {
        let setup = self.setup;
        for _ in 0..3 * setup.k {
            let v = eval(setup, &self.modes, y).v;
            let mut changed = false;
            for j in (0..setup.k).filter(|&j| !done[j]) {
                let (vn, s) = (v[3 * j + 2], y[PER * j + S]);
                match self.modes.normal[j] {
                    Normal::Compression if vn > -setup.approach => self.end_compression(j, y),
                    Normal::Expansion if s <= 0.0 || self.spent(j, s, vn) => self.separate(j, y),
                    Normal::Expansion if vn < -setup.approach => self.recompress(j, y),
                    Normal::Off if vn < -setup.approach => {
                        self.join(j, y);
                        let before = rest.len();
                        self.set_slip_or_rest(j, slip(&v, j), rest);
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

    /// Whether contact `j`, expanding at `vn` with deflection `s`, has less left to give
    /// than the integration's absolute tolerance on its impulse: the rest of its expansion,
    /// `∫ F dτ = e² Ê / v_n`, below it (a symmetric body's contacts separating a hair apart
    /// then separate together).
    fn spent(&self, j: usize, s: f64, vn: f64) -> bool {
        let setup = self.setup;
        vn > 0.0 && setup.energy(j, s) * setup.e[j] * setup.e[j] <= setup.atol[PER * j + PN] * vn
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
        self.tracks[j]
            .work
            .end_expansion(energy, setup.e[j] * setup.e[j]);
        y[PER * j + S] = 0.0;
        self.go_off(j, y);
    }

    /// `j` approaches again while loaded: the expansion so far is restitution work, a new
    /// compression begins.
    fn recompress(&mut self, j: usize, y: &[f64]) {
        let setup = self.setup;
        let energy = setup.energy(j, y[PER * j + S]);
        let work = &mut self.tracks[j].work;
        work.end_expansion(energy, setup.e[j] * setup.e[j]);
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
        tr.label = None;
        self.modes.normal[j] = Normal::Compression;
        self.modes.tangent[j] = Tangent::Slip;
    }

    /// `j` carries no force any more: its phase ends; if it was the primary, the contact with
    /// the most stored energy takes over.
    fn go_off(&mut self, j: usize, y: &[f64]) {
        let vt = self.setup.slip_at(j, y);
        let regime = self.modes.tangent[j];
        self.close(j, regime, vt, y);
        self.modes.normal[j] = Normal::Off;
        self.modes.tangent[j] = Tangent::Slip;
        let (setup, modes) = (self.setup, &self.modes);
        self.primary.hand_over(
            j,
            setup.k,
            |c| setup.energy_order(c, y[PER * c + S]),
            |c| modes.active(c),
            |c| y[PER * c + PN],
        );
    }

    /// End contact `j`'s current phase at `y` (its slip `vt`, its regime up to here
    /// `regime`).
    fn close(&mut self, j: usize, regime: Tangent, vt: Vec2, y: &[f64]) {
        let approach = self.setup.approach;
        let tr = &mut self.tracks[j];
        let Some(label) = tr.label.take() else {
            return;
        };
        let now = (vt.norm() > approach).then(|| angle(vt));
        let kind = match label {
            Label::Slip { from, to } => PhaseKind::Slip {
                from,
                to: match (to, regime) {
                    (Some(to), _) => to,
                    (None, Tangent::Fixed { dir, .. }) => angle(dir),
                    _ => now.unwrap_or(from),
                },
            },
            Label::Resumed { angle } => PhaseKind::Resumed { angle },
            Label::Stick => PhaseKind::Stick,
            Label::Free { from } => match (from, now) {
                (Some(from), Some(to)) => PhaseKind::Slip { from, to },
                (Some(from), None) => PhaseKind::Slip { from, to: from },
                (None, Some(angle)) => PhaseKind::Resumed { angle },
                (None, None) => PhaseKind::Stick,
            },
        };
        tr.result
            .push_phase(ContactPhaseKind::Impact(kind), y[PER * j + PN]);
    }

    /// Choose the tangential regimes: the contacts `rest` (restricted by `allowed`) and
    /// every contact in stick, given the normal forces `f` and the velocities `v`; then
    /// record the phases that changed (`before`: the regimes before the event).
    fn decide(
        &mut self,
        f: &[f64; MAXK],
        v: &[f64; ROWS],
        y: &[f64],
        mut rest: Vec<usize>,
        mut allowed: Vec<Allowed>,
        before: &[Tangent; MAXK],
    ) {
        let setup = self.setup;
        // Keep only active contacts with friction; add those in stick.
        let mut c = 0;
        while c < rest.len() {
            let j = rest[c];
            if !self.modes.active(j) || setup.mu[j] == 0.0 || rest[..c].contains(&j) {
                rest.remove(c);
                allowed.remove(c);
            } else {
                c += 1;
            }
        }
        for j in 0..setup.k {
            if self.modes.active(j) && self.modes.tangent[j] == Tangent::Stick && !rest.contains(&j)
            {
                rest.push(j);
                allowed.push(Allowed::ANY);
            }
        }
        if rest.is_empty() {
            rebuild(setup, &mut self.modes);
        } else {
            choose(setup, &mut self.modes, f, v, &rest, &allowed);
        }
        self.after_change(v, y, before);
    }

    /// Record the tangential phases that changed (a phase ends at the contact's own normal
    /// impulse), `before` the regimes before the change.
    fn after_change(&mut self, v: &[f64; ROWS], y: &[f64], before: &[Tangent; MAXK]) {
        let setup = self.setup;
        for (j, &was) in before.iter().enumerate().take(setup.k) {
            if !self.modes.active(j) {
                continue;
            }
            let vt = slip(v, j);
            let sliding = (vt.norm() > setup.approach).then(|| angle(vt));
            let old = self.tracks[j].label;
            let label = match self.modes.tangent[j] {
                _ if setup.mu[j] == 0.0 => match old {
                    Some(l @ Label::Free { .. }) => l,
                    _ => Label::Free { from: sliding },
                },
                Tangent::Stick => Label::Stick,
                Tangent::Fixed { dir, leaving: true } => match (was, old) {
                    (Tangent::Fixed { leaving: true, .. }, Some(l @ Label::Resumed { .. })) => l,
                    _ => Label::Resumed { angle: angle(dir) },
                },
                Tangent::Slip | Tangent::Fixed { .. } => match old {
                    Some(l @ (Label::Slip { .. } | Label::Resumed { .. })) => l,
                    _ => Label::Slip {
                        from: match self.modes.tangent[j] {
                            Tangent::Fixed { dir, .. } => angle(dir),
                            _ => sliding.unwrap_or(0.0),
                        },
                        to: None,
                    },
                },
            };
            if old != Some(label) {
                self.close(j, was, vt, y);
                self.tracks[j].label = Some(label);
            }
        }
    }

    /// The primary contact along a step from `y0` to the fraction `theta` of it, where the
    /// state is `y1` (the dense output built only if it changes).
    pub(super) fn follow_primary<const N: usize>(
        &mut self,
        theta: f64,
        y0: &[f64; N],
        y1: &[f64; N],
        dense: &dyn Fn() -> Dense<N>,
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

    /// The impact has settled: the contacts still carrying a force are off, their stored
    /// energy (below round-off) lost.
    pub(super) fn end_settled(&mut self, y: &[f64]) {
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
    pub(super) fn finish(self, y: &[f64], steps: usize) -> End {
        let setup = self.setup;
        let ev: Eval = eval(setup, &self.modes, y);
        let contacts = self
            .tracks
            .into_iter()
            .enumerate()
            .map(|(j, mut tr)| {
                let o = PER * j;
                tr.result.impulse = Vec3::new(y[o + PT1], y[o + PT2], y[o + PN]);
                tr.result.velocity_after = Vec3::new(ev.v[3 * j], ev.v[3 * j + 1], ev.v[3 * j + 2]);
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
