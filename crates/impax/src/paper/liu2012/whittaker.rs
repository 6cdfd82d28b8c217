//! §1–2 and §5 of the paper: Whittaker's rule (eqs. 2–15), Kane's paradox at `γ = 0`, and
//! the split of its energy change into translational and rotational parts.

use super::row::{f6, fmt, formula, number, s6, statement, FORMULA_TOL};
use super::{Agreement, Ctx, Row};
use crate::law::LawId;
use crate::numerics::roots::bisection;
use crate::planar::bodies::BodyOutcome;
use crate::planar::{Inconsistency, Verdict};

/// The root of `f` on the branch that starts at `edge` and extends in direction `dir`
/// (`±1`): bracketed by doubling steps from just inside the edge, then bisected.
fn branch_root(f: impl Fn(f64) -> f64, edge: f64, dir: f64) -> f64 {
    let inner = edge + dir * 1e-9;
    let f_inner = f(inner);
    let mut step = 1.0;
    for _ in 0..60 {
        let outer = edge + dir * step;
        let f_outer = f(outer);
        if f_outer.is_finite() && f_inner.is_finite() && f_outer.signum() != f_inner.signum() {
            return bisection(&f, inner, outer);
        }
        step *= 2.0;
    }
    f64::NAN
}

impl Ctx {
    /// §1–2: Whittaker's rule at the seed, its thresholds in `γ`, and the paradox.
    pub(super) fn whittaker_rows(&self, rows: &mut Vec<Row>) {
        let w0 = self.run(LawId::Whittaker, 0.0);
        self.whittaker_velocities(&w0, rows);
        self.whittaker_reversal(&w0, rows);
        self.whittaker_energy(&w0, rows);
        self.whittaker_thresholds(rows);
        self.whittaker_paradox(&w0, rows);
    }

    /// Eqs. 2–9: the impulse and the velocities after at `γ = 0`.
    fn whittaker_velocities(&self, w0: &BodyOutcome, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let (s, big_f) = (self.s, self.big_f);
        // Eq. 4: the normal impulse.
        rows.push(formula(
            "eq. 4",
            "I_y/(m v0), normal impulse (Whittaker, γ = 0)".into(),
            "(1 + e) m v0 cos α",
            (1.0 + seed.restitution) * self.c,
            self.impulse(w0.outcome.impulse.y),
        ));
        // Eq. 2.
        let vy = self.vy(w0);
        rows.push(number(
            "eq. 2",
            "v_y+/v0 (Whittaker, γ = 0)".into(),
            "0.606",
            "0.606",
            vy,
            || format!("e cos α = {}", f6(seed.restitution * self.c)),
        ));
        // Eq. 6: the slip before.
        let problem0 = seed.problem(0.0).expect("valid seed");
        rows.push(formula(
            "eq. 6",
            "v_Px-/v0, slip before (γ = 0)".into(),
            "v0 (sin α + γ)",
            s,
            problem0.velocity().x / seed.speed,
        ));
        // Eqs. 9a, 9b.
        let vx = self.vx(w0);
        rows.push(number(
            "eq. 9a",
            "v_x+/v0 (Whittaker, γ = 0)".into(),
            "-0.089",
            "-0.089",
            vx,
            || format!("eq. 9a gives sin α − f(1+e)cos α = {}", f6(s - big_f)),
        ));
        let om = self.omega(w0);
        rows.push(number(
            "eq. 9b",
            "ω+ r/v0 (Whittaker, γ = 0)".into(),
            "-1.47",
            "-1.47",
            om,
            || format!("eq. 9b gives γ − (5/2) f(1+e)cos α = {}", f6(-2.5 * big_f)),
        ));
    }

    /// Eqs. 10–11: the slip after, and when it reverses.
    fn whittaker_reversal(&self, w0: &BodyOutcome, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let (s, big_f) = (self.s, self.big_f);
        // Eq. 10: the slip after.
        let slip0 = self.slip_after(w0);
        rows.push(formula(
            "eq. 10",
            "v_Px+/v0, slip after (Whittaker, γ = 0)".into(),
            "v0 [sin α + γ − (7f/2)(1+e) cos α]",
            s - 3.5 * big_f,
            slip0,
        ));
        // Eq. 11 at γ = 0: the condition and the engine's verdict.
        let lhs = big_f;
        let rhs = 2.0 / 7.0 * s;
        let condition = lhs > rhs;
        let reversed = matches!(
            w0.outcome.inconsistency,
            Some(Inconsistency::SlipReversed { .. })
        );
        rows.push(statement(
            "eq. 11",
            "slip reverses under Whittaker at γ = 0".into(),
            "f(1+e) cos α > (2/7)(sin α + γ)",
            format!(
                "condition {condition}: {} > {}; engine: {} (v_t+ = {})",
                f6(lhs),
                f6(rhs),
                if reversed {
                    "slip-reversed"
                } else {
                    "no reversal"
                },
                f6(slip0)
            ),
            Some(lhs - rhs),
            condition == reversed,
            || {
                format!(
                    "eq. 11 says {condition} but the engine's slip after is {}",
                    f6(slip0)
                )
            },
        ));
        // Eq. 11 as a threshold in γ, against the engine's sign change of v_t+.
        let edge = seed.zero_slip_spin();
        let slip_root = branch_root(
            |g| {
                seed.outcome(LawId::Whittaker, g)
                    .map_or(f64::NAN, |o| o.outcome.velocity_after.x)
            },
            edge,
            1.0,
        );
        rows.push(formula(
            "eq. 11 γ",
            "largest γ with reversal (v_Px- > 0): root of the engine's Whittaker v_t+(γ)".into(),
            "γ < (7/2) f(1+e) cos α − sin α",
            3.5 * big_f - s,
            slip_root,
        ));
    }

    /// Eq. 13: the energy change at `γ = 0`, and as a formula over both branches.
    fn whittaker_energy(&self, w0: &BodyOutcome, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let s = self.s;
        // Eq. 13 at γ = 0.
        let r0 = self.ratio(w0);
        let eq13_0 = self.eq13(0.0, 1.0);
        rows.push(number(
            "eq. 13",
            "ΔT/T0 (Whittaker, γ = 0)".into(),
            "0.23",
            "0.23",
            r0,
            || {
                format!(
                    "eq. 13 at the seed gives {} and the engine {} (difference {:.1e}): \
                     the printed 0.23 is an arithmetic slip, {} too low; the sign (a gain) is right",
                    f6(eq13_0),
                    f6(r0),
                    (eq13_0 - r0).abs(),
                    fmt(r0 - 0.23, 4)
                )
            },
        ));
        // Eq. 13 as a formula, over both branches.
        let max_gap = (0..60)
            .map(|k| (k as f64 - 30.0) / 10.0 + 0.05)
            .map(|g| {
                let branch = if s + g > 0.0 { 1.0 } else { -1.0 };
                let engine = seed
                    .energy_ratio(LawId::Whittaker, g)
                    .unwrap_or(f64::INFINITY);
                (self.eq13(g, branch) - engine).abs()
            })
            .fold(0.0, f64::max);
        rows.push(Row {
            id: "eq. 13 formula",
            quantity:
                "max |eq. 13 − engine ΔT/T0| (Whittaker) over 60 γ in [−2.95, 2.95], both branches"
                    .into(),
            printed: "formula".into(),
            computed: format!("{max_gap:.1e}"),
            computed_value: Some(max_gap),
            agreement: if max_gap <= FORMULA_TOL {
                Agreement::Agrees
            } else {
                Agreement::Differs
            },
            note: if max_gap <= FORMULA_TOL {
                String::new()
            } else {
                format!("eq. 13 departs from the engine by up to {max_gap:.3e}")
            },
        });
    }

    /// Eqs. 14–15: the spin ratios at which the energy change vanishes, on each branch.
    fn whittaker_thresholds(&self, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let big_f = self.big_f;
        let edge = seed.zero_slip_spin();
        // Eq. 14: the threshold on the branch v_Px⁻ > 0.
        let energy = |g: f64| {
            seed.outcome(LawId::Whittaker, g)
                .map_or(f64::NAN, |o| o.outcome.energy_change)
        };
        let ratio_at = |g: f64| seed.energy_ratio(LawId::Whittaker, g).unwrap_or(f64::NAN);
        let g14 = branch_root(energy, edge, 1.0);
        let (below14, above14) = (ratio_at(g14 - 0.1), ratio_at(g14 + 0.1));
        let g14_formula = self.eq13(0.0, 1.0) / (2.0 * big_f);
        rows.push(number(
            "eq. 14",
            "γ at which ΔT = 0 (Whittaker, branch v_Px- > 0, γ > −sin α)".into(),
            "γ > 0.20 ⇒ ΔT/T0 < 0; γ < 0.20 ⇒ ΔT/T0 > 0",
            "0.20",
            g14,
            || {
                format!(
                    "engine root γ* = {} (eq. 13: {}), which rounds to {}: the print truncates. \
                     Sides as printed: ΔT/T0 = {} at γ* − 0.1, {} at γ* + 0.1",
                    f6(g14),
                    f6(g14_formula),
                    fmt(g14, 2),
                    s6(below14),
                    s6(above14)
                )
            },
        ));
        // Eq. 15: the threshold on the branch v_Px⁻ < 0.
        let g15 = branch_root(energy, edge, -1.0);
        let (below15, above15) = (ratio_at(g15 - 0.1), ratio_at(g15 + 0.1));
        let g15_formula = -self.eq13(0.0, -1.0) / (2.0 * big_f);
        rows.push(number(
            "eq. 15",
            "γ at which ΔT = 0 (Whittaker, branch v_Px- < 0, γ < −sin α)".into(),
            "γ < -0.20 ⇒ ΔT/T0 < 0; γ > -0.20 ⇒ ΔT/T0 > 0",
            "-0.20",
            g15,
            || {
                format!(
                    "on this branch (γ < −sin α = {}; −0.20 is not even on it) the engine's ΔT \
                     vanishes at γ* = {} (eq. 13, lower signs: {}). The print mirrors eq. 14 about \
                     γ = 0, but the two roots mirror each other about γ = −sin α \
                     (γ₁₄ + γ₁₅ = {} = −2 sin α). The sides are as printed: gain for \
                     {} < γ < {} (ΔT/T0 = {} at γ* + 0.1), loss below (ΔT/T0 = {} at γ* − 0.1)",
                    f6(edge),
                    f6(g15),
                    f6(g15_formula),
                    f6(g14 + g15),
                    fmt(g15, 4),
                    fmt(edge, 1),
                    s6(above15),
                    s6(below15)
                )
            },
        ));
    }

    /// §2: the paradox itself, energy gained at `γ = 0`.
    fn whittaker_paradox(&self, w0: &BodyOutcome, rows: &mut Vec<Row>) {
        let r0 = self.ratio(w0);
        // §2: the paradox itself.
        let gained = w0.outcome.verdict == Verdict::EnergyGained;
        rows.push(statement(
            "§2",
            "energy under Whittaker at γ = 0".into(),
            "ΔT/T0 > 0: energy gained (Kane's paradox)",
            format!("ΔT/T0 = {}; verdict {}", s6(r0), w0.outcome.verdict.id()),
            Some(r0),
            gained,
            || format!("the engine finds ΔT/T0 = {}", s6(r0)),
        ));
    }

    /// §5: the split of ΔT into translational and rotational parts (Whittaker, γ = 0).
    pub(super) fn split_rows(&self, rows: &mut Vec<Row>) {
        let w0 = self.run(LawId::Whittaker, 0.0);
        let t1 = w0.energy_change.translational / self.seed.t0();
        let t2 = w0.energy_change.rotational / self.seed.t0();
        rows.push(statement(
            "§5 ΔT₁",
            "ΔT₁/T0, translational part (Whittaker, γ = 0)".into(),
            "ΔT₁ < 0",
            f6(t1),
            Some(t1),
            t1 < 0.0,
            || format!("the engine's translational change is {}", s6(t1)),
        ));
        rows.push(statement(
            "§5 ΔT₂",
            "ΔT₂/T0, rotational part (Whittaker, γ = 0)".into(),
            "ΔT₂ > 0 (rotation from nothing), ΔT₁ + ΔT₂ > 0",
            format!("{} (sum {})", f6(t2), s6(t1 + t2)),
            Some(t2),
            t2 > 0.0 && t1 + t2 > 0.0,
            || format!("the engine's rotational change is {}", s6(t2)),
        ));
    }
}
