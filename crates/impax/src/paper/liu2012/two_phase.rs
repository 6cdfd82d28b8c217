//! §3 of the paper: the two-phase scheme (eqs. 16–23) — friction reversed once the slip
//! halts.

use super::row::{f6, formula, number, s6, statement};
use super::{Ctx, Row};
use crate::law::LawId;
use crate::math::Vec2;
use crate::planar::{Inconsistency, LawDetail, Verdict};

impl Ctx {
    /// §3: the switch impulse, the velocities after, the energy and the contradiction.
    pub(super) fn two_phase_rows(&self, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let (s, big_f) = (self.s, self.big_f);
        let tp = self.run(LawId::TwoPhase, 0.0);
        let w0 = self.run(LawId::Whittaker, 0.0);

        // Eq. 21: the switch impulse.
        let switch = match tp.outcome.detail {
            LawDetail::TwoPhase {
                switch_impulse: Some(p),
            } => p,
            _ => f64::NAN,
        };
        rows.push(formula(
            "eq. 21",
            "I'_y/(m v0), normal impulse at the slip halt (two-phase, γ = 0)".into(),
            "(2/(7f)) m v0 (γ + sin α)",
            2.0 / (7.0 * seed.friction) * s,
            self.impulse(switch),
        ));
        // Eqs. 19–20: the slip at the switch.
        let impact = seed.impact(0.0).expect("valid seed");
        let (at_switch, _) = impact.apply(Vec2::new(-seed.friction * switch, switch));
        let slip_switch = impact.body.0.contact_velocity(&at_switch).x / seed.speed;
        rows.push(formula(
            "eq. 20",
            "v'_Px/v0 after I'_y with friction −f I'_y (eq. 19 state, two-phase, γ = 0)".into(),
            "v'_x + ω' r = 0",
            0.0,
            slip_switch,
        ));
        // Eq. 23a: v_x⁺.
        let vx = self.vx(&tp);
        let eq23_printed = big_f - 4.0 / 7.0 * s;
        let eq23_corrected = s + big_f - 4.0 / 7.0 * s;
        rows.push(number(
            "eq. 23a",
            "v_x+/v0 (two-phase, γ = 0)".into(),
            "0.30",
            "0.30",
            vx,
            || {
                format!(
                    "eq. 23 as printed, v0[f(1+e)cos α − (4/7)(γ + sin α)], gives {} — the printed \
                     0.30 — but it drops the initial v0 sin α: eqs. 17–22 give \
                     v0[sin α + f(1+e)cos α − (4/7)(γ + sin α)] = {} (engine {})",
                    f6(eq23_printed),
                    f6(eq23_corrected),
                    f6(vx)
                )
            },
        ));
        // Eq. 23b: ω⁺.
        let om = self.omega(&tp);
        rows.push(number(
            "eq. 23b",
            "ω+ r/v0 (two-phase, γ = 0)".into(),
            "0.76",
            "0.76",
            om,
            || format!("eq. 23b gives {}", f6(2.5 * eq23_printed)),
        ));
        // ΔT/T0.
        let r_tp = self.ratio(&tp);
        let r_w = self.ratio(&w0);
        let pt_stick = -impact.contact_velocity().x / impact.inverse_inertia()[(0, 0)];
        let vy = self.vy(&tp);
        let with_printed = self.eq12(0.30, vy, 0.76, 0.0);
        rows.push(number(
            "§3 ΔT/T0",
            "ΔT/T0 (two-phase, γ = 0)".into(),
            "-0.67",
            "-0.67",
            r_tp,
            || {
                format!(
                    "the engine's ΔT/T0 = {} equals Whittaker's {}: with W_tn = 0 the two-phase \
                     tangential impulse ({}) is Whittaker's ({}) mirrored about the sticking \
                     impulse ({}), so ΔT is the same. Even eq. 12 with the printed v_x+ = 0.30, \
                     ω+ = 0.76 gives {}, not -0.67",
                    s6(r_tp),
                    s6(r_w),
                    f6(self.impulse(tp.outcome.impulse.x)),
                    f6(self.impulse(w0.outcome.impulse.x)),
                    f6(self.impulse(pt_stick)),
                    f6(with_printed)
                )
            },
        ));
        rows.push(statement(
            "§3 energy",
            "energy under the two-phase scheme at γ = 0".into(),
            "ΔT/T0 < 0: no energy gained",
            format!("ΔT/T0 = {}; verdict {}", s6(r_tp), tp.outcome.verdict.id()),
            Some(r_tp),
            tp.outcome.verdict != Verdict::EnergyGained && r_tp < 0.0,
            || {
                format!(
                    "the scheme gains as much energy as Whittaker's rule (ΔT/T0 = {}); the \
                     printed loss rests on the slips in eq. 23 and in the printed ΔT",
                    s6(r_tp)
                )
            },
        ));
        // The slip after and the contradiction.
        let slip = self.slip_after(&tp);
        rows.push(number(
            "§3 v_Px+",
            "v_Px+/v0, slip after (two-phase, γ = 0)".into(),
            "1.06",
            "1.06",
            slip,
            || {
                format!(
                    "the printed 1.06 = {} + {} = {} adds the printed (sin α-less) v_x+ to ω+ r; \
                     the engine's {} is v_x+ + ω+ r = {} + {}, minus Whittaker's slip after ({})",
                    f6(eq23_printed),
                    f6(2.5 * eq23_printed),
                    f6(eq23_printed + 2.5 * eq23_printed),
                    f6(slip),
                    f6(vx),
                    f6(om),
                    f6(self.slip_after(&w0))
                )
            },
        ));
        let contradiction = matches!(
            tp.outcome.inconsistency,
            Some(Inconsistency::ReversalDidNotHappen { .. })
        );
        rows.push(statement(
            "§3 verdict",
            "two-phase assumption at γ = 0".into(),
            "v_Px+ > 0 contradicts the assumed reversal",
            match tp.outcome.inconsistency {
                Some(i) => format!("{} (v_t+ = {})", i.id(), f6(slip)),
                None => format!("consistent (v_t+ = {})", f6(slip)),
            },
            Some(slip),
            contradiction && slip > 0.0,
            || format!("the engine finds v_Px+ = {} and no contradiction", f6(slip)),
        ));
    }
}
