//! §4 of the paper: Smith's correction (eqs. 24–27), in both readings of eq. 24 — the
//! literal one (`smith-centre`, η from the centre velocity) and the one the text and Smith
//! 1991 mean (`smith`, η from the sliding velocity).

use super::row::{f6, number, s6, statement};
use super::{Ctx, Row, Seed};
use crate::law::LawId;
use crate::math::quadratic_roots;
use crate::planar::bodies::{BodyImpact, BodyOutcome};
use crate::planar::LawDetail;

/// Both readings at `γ = 0` and at `γ = −sin α` (no slip before the impact).
struct Readings {
    /// `γ = −sin α`.
    g_half: f64,
    /// `smith-centre` at `γ = 0`.
    c0: BodyOutcome,
    /// `smith` at `γ = 0`.
    s0: BodyOutcome,
    /// `smith-centre` at `γ = −sin α`.
    c5: BodyOutcome,
    /// `smith` at `γ = −sin α`.
    s5: BodyOutcome,
}

/// Smith's `η` of an outcome (NaN for another law).
fn eta_of(o: &BodyOutcome) -> f64 {
    match o.outcome.detail {
        LawDetail::Smith { eta, .. } => eta,
        _ => f64::NAN,
    }
}

/// The number of admissible `η` roots of an outcome (0 for another law).
fn roots_of(o: &BodyOutcome) -> usize {
    match o.outcome.detail {
        LawDetail::Smith { roots, .. } => roots,
        _ => 0,
    }
}

/// Slip before the impact, `v_Px⁻ / v0`, from the engine's contact velocity.
fn problem_slip(impact: &BodyImpact, seed: &Seed) -> f64 {
    impact.contact_velocity().x / seed.speed
}

impl Ctx {
    /// §4: eqs. 24–27 and the energy, each beside both readings.
    pub(super) fn smith_rows(&self, rows: &mut Vec<Row>) {
        let g_half = self.seed.zero_slip_spin();
        let r = Readings {
            g_half,
            c0: self.run(LawId::SmithCentre, 0.0),
            s0: self.run(LawId::Smith, 0.0),
            c5: self.run(LawId::SmithCentre, g_half),
            s5: self.run(LawId::Smith, g_half),
        };
        self.smith_xi_rows(&r, rows);
        self.smith_eta_rows(&r, rows);
        self.smith_spin_rows(&r, rows);
        self.smith_energy_rows(&r, rows);
        self.smith_verdict_rows(&r, rows);
    }

    /// Eq. 27: the centre's speed after (`ξ`), against each reading.
    fn smith_xi_rows(&self, r: &Readings, rows: &mut Vec<Row>) {
        let (s, big_f) = (self.s, self.big_f);
        let Readings { c0, s0, .. } = r;
        // Eq. 27 solved directly (the literal reading reduced by the paper).
        let [q_lo, q_hi] = quadratic_roots(1.0, big_f, (s - big_f) * s);
        let residual = |xi: f64| xi * xi + big_f * xi + (s - big_f) * s;
        // The same reduction for the sliding velocity: (7/2) f(1+e)cos α in place of f(1+e)cos α.
        let g7 = 3.5 * big_f;
        let [_, zeta] = quadratic_roots(1.0, g7, (s - g7) * s);

        // ξ.
        let (vx_c, vx_s) = (self.vx(c0), self.vx(s0));
        let (slip_c, slip_s) = (self.slip_after(c0), self.slip_after(s0));
        rows.push(number(
            "eq. 27 centre",
            "ξ = |v_x+|/v0 (smith-centre: η from v_x as eq. 24 writes, γ = 0)".into(),
            "0.0726",
            "0.0726",
            vx_c.abs(),
            || {
                format!(
                    "the literal reading gives v_x+ = {} v0 ({} admissible η root; the slip after is \
                     v_Px+ = {} v0); eq. 27 solved directly: ξ = {} (other root {}), exact for this reading (its cubic factors \
                     as (ξ + sin α)·eq. 27). The residual of eq. 27 at the printed 0.0726 is {}: \
                     not a root, an arithmetic slip",
                    f6(vx_c),
                    roots_of(c0),
                    f6(slip_c),
                    f6(q_hi),
                    f6(q_lo),
                    f6(residual(0.0726))
                )
            },
        ));
        rows.push(number(
            "eq. 27 slip",
            "|v_Px+|/v0, reversed slip speed (smith: η from the sliding velocity, γ = 0)".into(),
            "0.0726",
            "0.0726",
            slip_s.abs(),
            || {
                format!(
                    "with η from the sliding velocity (as the text and Smith 1991 mean) the slip \
                     reverses to v_Px+ = {} v0 while the centre keeps v_x+ = {} v0 (no ξ of \
                     eq. 27); eq. 27 with (7/2) f(1+e)cos α in place of f(1+e)cos α gives this \
                     |v_Px+|/v0 directly: {}",
                    f6(slip_s),
                    s6(vx_s),
                    f6(zeta)
                )
            },
        ));
    }

    /// Eq. 24: the factor `η` in each reading.
    fn smith_eta_rows(&self, r: &Readings, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let Readings { c0, s0, .. } = r;
        let slip_s = self.slip_after(s0);
        // η.
        let (eta_c, eta_s) = (eta_of(c0), eta_of(s0));
        rows.push(number(
            "eq. 24 centre",
            "η (smith-centre, γ = 0)".into(),
            "0.96",
            "0.96",
            eta_c,
            || format!("the literal reading gives η = {}", f6(eta_c)),
        ));
        rows.push(number(
            "eq. 24 slip",
            "η (smith, γ = 0)".into(),
            "0.96",
            "0.96",
            eta_s,
            || {
                format!(
                    "η from the slip, u- = {}, u+ = {}: {}; only the literal reading gives 0.96 ({})",
                    f6(problem_slip(&seed.impact(0.0).expect("valid seed"), seed)),
                    f6(slip_s),
                    f6(eta_s),
                    f6(eta_c)
                )
            },
        ));
    }

    /// Eq. 26b: the spin after, `ω⁺ = (γ − const) v0/r`, in each reading.
    fn smith_spin_rows(&self, r: &Readings, rows: &mut Vec<Row>) {
        let (s, big_f) = (self.s, self.big_f);
        let Readings {
            g_half, c0, s0, c5, ..
        } = r;
        let g_half = *g_half;
        let eta_s = eta_of(s0);
        let (om_c, om_s) = (self.omega(c0), self.omega(s0));
        let om_c5 = self.omega(c5) - g_half;
        let eta_printed = (s * s - 0.0726 * 0.0726) / (s * s + 0.0726 * 0.0726);
        rows.push(number(
            "eq. 26b centre",
            "ω+ r/v0 − γ (smith-centre, γ = 0)".into(),
            "(γ − 1.41) v0/r",
            "-1.41",
            om_c,
            || {
                format!(
                    "the literal reading gives ω+ = (γ − {}) v0/r (the same at γ = −0.5: {}), which \
                     rounds to 1.42; the printed 1.41 follows from the printed ξ = 0.0726 \
                     (η = {} → {})",
                    f6(-om_c),
                    f6(om_c5),
                    f6(eta_printed),
                    f6(2.5 * eta_printed * big_f)
                )
            },
        ));
        rows.push(number(
            "eq. 26b slip",
            "ω+ r/v0 − γ (smith, γ = 0)".into(),
            "(γ − 1.41) v0/r",
            "-1.41",
            om_s,
            || {
                format!(
                    "the slip reading gives ω+ = {} v0/r at γ = 0 (η = {}; η depends on γ in this \
                     reading, so ω+ is not γ − const); the literal reading gives {}",
                    f6(om_s),
                    f6(eta_s),
                    f6(om_c)
                )
            },
        ));
    }

    /// §4's energy changes at `γ = 0` and at `γ = −0.5`, in each reading.
    fn smith_energy_rows(&self, r: &Readings, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let s = self.s;
        let Readings {
            g_half,
            c0,
            s0,
            c5,
            s5,
        } = r;
        let g_half = *g_half;
        let eta_s = eta_of(s0);
        // ΔT/T0 at γ = 0.
        let (r_c0, r_s0) = (self.ratio(c0), self.ratio(s0));
        let frictionless = s * s + seed.restitution * seed.restitution * self.c * self.c - 1.0;
        let printed_eq12 = self.eq12(-0.0726, self.vy(c0), -1.41, 0.0);
        rows.push(number(
            "§4 ΔT/T0 γ=0 centre",
            "ΔT/T0 (smith-centre, γ = 0)".into(),
            "-0.38",
            "-0.38",
            r_c0,
            || {
                format!(
                    "the literal reading gains energy at γ = 0, ΔT/T0 = {} (Kane's paradox \
                     persists); even eq. 12 with the printed v_x+ = -0.0726, ω+ = -1.41 gives {}. \
                     The slip reading gives {}. Neither gives -0.38, which is the frictionless \
                     value sin²α + e²cos²α − 1 = {}",
                    s6(r_c0),
                    s6(printed_eq12),
                    s6(r_s0),
                    f6(frictionless)
                )
            },
        ));
        rows.push(number(
            "§4 ΔT/T0 γ=0 slip",
            "ΔT/T0 (smith, γ = 0)".into(),
            "-0.38",
            "-0.38",
            r_s0,
            || {
                format!(
                    "the slip reading loses ΔT/T0 = {} (η = {}); the literal reading gives {}; \
                     neither is -0.38",
                    s6(r_s0),
                    f6(eta_s),
                    s6(r_c0)
                )
            },
        ));
        // ΔT/T0 at γ = −0.5 (= −sin α: the slip before is exactly zero).
        let slip_before_half = problem_slip(&seed.impact(g_half).expect("valid seed"), seed);
        let (r_c5, r_s5) = (self.ratio(c5), self.ratio(s5));
        let printed_eq12_half = self.eq12(-0.0726, self.vy(c5), g_half - 1.41, g_half);
        rows.push(number(
            "§4 ΔT/T0 γ=-0.5 centre",
            "ΔT/T0 (smith-centre, γ = −0.5)".into(),
            "0.31",
            "0.31",
            r_c5,
            || {
                format!(
                    "in the literal reading η and v_x+ do not depend on γ (v_x- = v0 sin α \
                     whatever the spin): η = {}, ω+ = {} v0/r, ΔT/T0 = {} — a gain as printed, \
                     but not 0.31; eq. 12 with the printed ω+ = (γ − 1.41) gives {}. The slip \
                     reading gives {}",
                    f6(eta_of(c5)),
                    f6(self.omega(c5)),
                    s6(r_c5),
                    s6(printed_eq12_half),
                    s6(r_s5)
                )
            },
        ));
        rows.push(number(
            "§4 ΔT/T0 γ=-0.5 slip",
            "ΔT/T0 (smith, γ = −0.5)".into(),
            "0.31",
            "0.31",
            r_s5,
            || {
                format!(
                    "at γ = −sin α = −0.5 the slip before is exactly zero (v_Px- = v0(sin α + γ) \
                     = {}); η = ±1 would need sign(v_Px+) = η while the impulse drives v_Px+ \
                     against η, so η = {}: no friction impulse, ΔT/T0 = sin²α + e²cos²α − 1 = {} \
                     (a loss). The literal reading gives {}",
                    f6(slip_before_half),
                    f6(eta_of(s5)),
                    s6(r_s5),
                    s6(r_c5)
                )
            },
        ));
    }

    /// The conclusion of §4, in each reading.
    fn smith_verdict_rows(&self, r: &Readings, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let Readings { c0, s0, c5, s5, .. } = r;
        let (r_c0, r_s0) = (self.ratio(c0), self.ratio(s0));
        let (r_c5, r_s5) = (self.ratio(c5), self.ratio(s5));
        let sweep_max = (0..=600)
            .map(|k| -3.0 + 0.01 * k as f64)
            .filter_map(|g| seed.energy_ratio(LawId::Smith, g))
            .fold(f64::NEG_INFINITY, f64::max);
        let printed = "ΔT/T0 < 0 at γ = 0, but ΔT/T0 > 0 at γ = −0.5";
        rows.push(statement(
            "§4 verdict centre",
            "Smith's correction, literal reading (smith-centre)".into(),
            printed,
            format!("ΔT/T0 = {} at γ = 0, {} at γ = −0.5", s6(r_c0), s6(r_c5)),
            None,
            r_c0 < 0.0 && r_c5 > 0.0,
            || {
                format!(
                    "the literal reading gains energy at both (ΔT/T0 = {} and {}): the paper's \
                     wider conclusion, that Smith's fix does not prevent gains, holds for it, \
                     already at γ = 0",
                    s6(r_c0),
                    s6(r_c5)
                )
            },
        ));
        rows.push(statement(
            "§4 verdict slip",
            "Smith's correction, sliding-velocity reading (smith)".into(),
            printed,
            format!(
                "ΔT/T0 = {} at γ = 0, {} at γ = −0.5; max {} over γ in [−3, 3]",
                s6(r_s0),
                s6(r_s5),
                s6(sweep_max)
            ),
            Some(sweep_max),
            r_s0 < 0.0 && r_s5 > 0.0,
            || {
                format!(
                    "the slip reading never gains energy for the sphere: with W_tn = 0, \
                     ΔT = ½(v_n- + v_n+) p_n + ½(u- + u+) p_t and η has the sign of u- + u+, so \
                     friction work ≤ 0; the engine's max ΔT/T0 over 601 γ in [−3, 3] is {}",
                    s6(sweep_max)
                )
            },
        ));
    }
}
