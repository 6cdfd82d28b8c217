//! `poisson` in 3D by the Darboux–Keller integration ([`crate::spatial::darboux_keller`]).

use crate::law::{ImpactLaw, LawId, Options};
use crate::spatial::{ContactProblem, Outcome, Resolution};

/// `poisson` in 3D: the Darboux–Keller integration (Keller 1986; theory §2) ended by Poisson's
/// kinetic restitution, `p_f = (1 + e) p_c`, the compression impulse `p_c` accumulating every
/// phase where `v_n < 0` (Stronge 2000).
///
/// The integration's tolerance is [`Options::rtol`](Options); [`ImpactLaw::resolve`] works in
/// the problem's canonical units and scales back ([`super::resolve`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Poisson {
    /// The options of the integration.
    pub options: Options,
}

impl ImpactLaw for Poisson {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Poisson
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Poisson, problem, &self.options)
    }
}
