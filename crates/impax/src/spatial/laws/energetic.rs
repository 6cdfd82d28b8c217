//! `energetic` in 3D by the Darboux–Keller integration ([`crate::spatial::darboux_keller`]).

use crate::law::{ImpactLaw, LawId, Options};
use crate::spatial::{ContactProblem, Outcome, Resolution};

/// `energetic` in 3D: the Darboux–Keller integration (Keller 1986; theory §2) ended by
/// Stronge's energetic restitution, `W_n(p_f) = (1 − e²) W_c` (Stronge 1991): never a gain of
/// energy, since `ΔT = W_n + W_t` and `W_t ≤ 0` under Coulomb's law.
///
/// The integration's tolerance is [`Options::rtol`](Options); [`ImpactLaw::resolve`] works in
/// the problem's canonical units and scales back ([`super::resolve`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Energetic {
    /// The options of the integration.
    pub options: Options,
}

impl ImpactLaw for Energetic {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Energetic
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Energetic, problem, &self.options)
    }
}
