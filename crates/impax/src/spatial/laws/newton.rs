//! `newton` in 3D by the Darboux–Keller integration ([`crate::spatial::darboux_keller`]).

use crate::law::{ImpactLaw, LawId, Options};
use crate::spatial::{ContactProblem, Outcome, Resolution};

/// `newton` in 3D: the Darboux–Keller integration (Keller 1986; theory §2) ended by Newton's
/// kinematic restitution, the first `p_f` after compression with `v_n(p_f) = −e v_n⁻`. With
/// slip reversal during restitution it can raise the kinetic energy (Stronge 1991).
///
/// The integration's tolerance is [`Options::rtol`](Options); [`ImpactLaw::resolve`] works in
/// the problem's canonical units and scales back ([`super::resolve`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Newton {
    /// The options of the integration.
    pub options: Options,
}

impl ImpactLaw for Newton {
    type Problem = ContactProblem;
    type Outcome = Outcome;
    type Brief = Outcome;

    fn id(&self) -> LawId {
        LawId::Newton
    }

    fn resolve(&self, problem: &ContactProblem) -> Resolution {
        super::resolve(LawId::Newton, problem, &self.options)
    }
}
