//! What the paper does not give: the exact answer, Darboux–Keller integration with
//! energetic restitution — the slip halts and the sphere leaves rolling, losing energy.

use super::row::{f6, reference, s6};
use super::{Ctx, Row};
use crate::law::LawId;
use crate::planar::LawDetail;

impl Ctx {
    /// The exact answer (Darboux–Keller with energetic restitution), not in the paper.
    pub(super) fn exact_rows(&self, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let dk = self.run(LawId::Energetic, 0.0);
        let newton = self.run(LawId::Newton, 0.0);
        let poisson = self.run(LawId::Poisson, 0.0);
        let halt = match dk.outcome.detail {
            LawDetail::DarbouxKeller { slip_halt } => slip_halt,
            _ => None,
        };
        let eq21 = 2.0 / (7.0 * seed.friction) * self.s;
        rows.push(reference(
            "slip halts at p_n/(m v0) (energetic, γ = 0)".into(),
            halt.map_or("no halt".into(), |p| f6(self.impulse(p))),
            halt.map(|p| self.impulse(p)),
            format!(
                "the impulse of eq. 21, {}; |W_tn| = 0 ≤ μ W_tt, so the contact sticks after",
                f6(eq21)
            ),
        ));
        rows.push(reference(
            "phases (energetic, γ = 0)".into(),
            dk.outcome.phases.summary(),
            None,
            String::new(),
        ));
        rows.push(reference(
            "v_x+/v0 (energetic, γ = 0)".into(),
            f6(self.vx(&dk)),
            Some(self.vx(&dk)),
            String::new(),
        ));
        rows.push(reference(
            "v_y+/v0 (energetic, γ = 0)".into(),
            f6(self.vy(&dk)),
            Some(self.vy(&dk)),
            String::new(),
        ));
        rows.push(reference(
            "ω+ r/v0 (energetic, γ = 0)".into(),
            f6(self.omega(&dk)),
            Some(self.omega(&dk)),
            String::new(),
        ));
        rows.push(reference(
            "v_Px+/v0, slip after (energetic, γ = 0)".into(),
            f6(self.slip_after(&dk)),
            Some(self.slip_after(&dk)),
            "the sphere leaves rolling".into(),
        ));
        let r = self.ratio(&dk);
        let t0 = seed.t0();
        rows.push(reference(
            "ΔT/T0 (energetic, γ = 0)".into(),
            s6(r),
            Some(r),
            format!(
                "normal work {} + friction work {} (÷ T0); verdict {}. newton and poisson give {} \
                 and {}: with W_tn = 0 the three restitution rules coincide. Energy is lost: no \
                 paradox",
                f6(dk.outcome.work.normal() / t0),
                f6(dk.outcome.work.friction / t0),
                dk.outcome.verdict.id(),
                s6(self.ratio(&newton)),
                s6(self.ratio(&poisson))
            ),
        ));
    }
}
