//! The vocabulary every law shares, planar and spatial alike: the stable ids ([`LawId`]),
//! the capability trait ([`ImpactLaw`]), the energy audit ([`WorkSplit`]), the judgement of a
//! result ([`Verdict`], [`Inconsistency`], the energy-gain test of [`energy`]) and the
//! breakdowns ([`Breakdown`], [`BreakdownReason`]); the kinds of contact-space problem
//! ([`Problem`]: one contact in the plane or in space, several contacts in the plane or in
//! space), which [`LawId::resolve`] takes alike, and the [`Options`] of a resolution.

mod breakdown;
pub mod energy;
mod options;
mod verdict;
mod work;

pub use breakdown::{Breakdown, BreakdownReason};
pub use options::Options;
pub use verdict::{Inconsistency, Verdict};
pub(crate) use work::record_is_finite;
pub use work::WorkSplit;

use crate::error::{Error, Result};
use std::fmt;
use std::str::FromStr;

/// Stable ids of the impact laws. These strings are a public contract (CLI, JSON, TOML).
///
/// With the feature `serde`, a law is written as its id (`"two-phase"`) and read back from it
/// ([`LawId::as_str`] and [`FromStr`]: an unknown id is an error listing the known ones).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(into = "&'static str", try_from = "String")
)]
pub enum LawId {
    /// `whittaker`: Newton restitution with Coulomb friction on the total impulses against the
    /// initial slip (paper A eqs. 7–9; Kane & Levinson 1985).
    Whittaker,
    /// `two-phase`: friction reversed after the slip halts (paper A §3, eqs. 16–23; Keller 1986).
    TwoPhase,
    /// `smith`: Smith's 1991 correction factor η on the sliding velocity (paper A §4).
    Smith,
    /// `smith-centre`: Smith's η from the centre-of-mass velocity, the literal reading of
    /// paper A eq. 24 (needs a body, not only contact space).
    SmithCentre,
    /// `brach`: Brach 1989, the sticking ratio capped to the friction cone.
    Brach,
    /// `newton`: Darboux–Keller integration ended by kinematic restitution `v_n⁺ = −e v_n⁻`.
    Newton,
    /// `poisson`: Darboux–Keller integration ended by kinetic restitution `p_f = (1+e) p_c`
    /// (in 3D after a jamb: restitution impulse `e` times the impulse of every compression
    /// phase).
    Poisson,
    /// `energetic`: Darboux–Keller integration ended by Stronge's energetic restitution
    /// `W_r = −e² W_c`.
    Energetic,
    /// `lcp`: the velocity-level complementarity impact that physics engines converge to
    /// (Anitescu & Potra 1997; the fixed point of sequential impulses): Newton's target
    /// `v_n⁺ = −e v_n⁻` and Coulomb friction with maximal dissipation on the final velocity.
    /// With several contacts ([`crate::multi::lcp`]): the same conditions at every contact at
    /// once (Stewart & Trinkle 1996), every solution listed.
    Lcp,
    /// `sequential`: binary impacts for several contacts ([`crate::multi::sequential`]): the
    /// most approaching contact alone with `energetic`, every contact's velocity updated, until
    /// none approaches. With one contact it is `energetic` (the outcome labelled `sequential`).
    Sequential,
    /// `lzb`: the multiple-impact law of Liu, Zhao & Brogliato (2008, 2009) for several
    /// contacts ([`crate::multi::lzb`]): every contact a compliant element storing energy,
    /// the impulses distributed by the contacts' force law, energetic restitution at each
    /// contact, Coulomb friction. With one contact it is `energetic` (the outcome labelled
    /// `lzb`).
    Lzb,
}

impl LawId {
    /// The eight laws defined in contact space, in presentation order.
    pub const CONTACT_SPACE: [LawId; 8] = [
        LawId::Whittaker,
        LawId::TwoPhase,
        LawId::Smith,
        LawId::Brach,
        LawId::Newton,
        LawId::Poisson,
        LawId::Energetic,
        LawId::Lcp,
    ];

    /// Every law, including the body-only `smith-centre`, in presentation order.
    pub const ALL: [LawId; 9] = [
        LawId::Whittaker,
        LawId::TwoPhase,
        LawId::Smith,
        LawId::SmithCentre,
        LawId::Brach,
        LawId::Newton,
        LawId::Poisson,
        LawId::Energetic,
        LawId::Lcp,
    ];

    /// The laws defined for spatial (3D) problems, in presentation order.
    pub const SPATIAL: [LawId; 6] = [
        LawId::Whittaker,
        LawId::Brach,
        LawId::Newton,
        LawId::Poisson,
        LawId::Energetic,
        LawId::Lcp,
    ];

    /// The laws defined for any number of contacts ([`LawId::resolve`]), in
    /// presentation order. (The one-contact tables [`LawId::ALL`], [`LawId::CONTACT_SPACE`]
    /// and [`LawId::SPATIAL`] leave `sequential` and `lzb` out: with one contact both are
    /// `energetic`.)
    pub const MULTI_CONTACT: [LawId; 3] = [LawId::Lcp, LawId::Sequential, LawId::Lzb];

    /// The stable id string.
    pub fn as_str(self) -> &'static str {
        match self {
            LawId::Whittaker => "whittaker",
            LawId::TwoPhase => "two-phase",
            LawId::Smith => "smith",
            LawId::SmithCentre => "smith-centre",
            LawId::Brach => "brach",
            LawId::Newton => "newton",
            LawId::Poisson => "poisson",
            LawId::Energetic => "energetic",
            LawId::Lcp => "lcp",
            LawId::Sequential => "sequential",
            LawId::Lzb => "lzb",
        }
    }

    /// Whether the law needs a body (not only `W` and `v⁻`).
    pub fn needs_body(self) -> bool {
        matches!(self, LawId::SmithCentre)
    }

    /// Whether the law resolves spatial (3D) problems: those of [`LawId::SPATIAL`], and
    /// `sequential` and `lzb` (with one contact, `energetic`).
    pub fn is_spatial(self) -> bool {
        LawId::SPATIAL.contains(&self) || matches!(self, LawId::Sequential | LawId::Lzb)
    }

    /// Whether the law is defined for several contacts at once (`lcp`, `sequential`, `lzb`);
    /// the others are one-contact laws.
    pub fn is_multi_contact(self) -> bool {
        LawId::MULTI_CONTACT.contains(&self)
    }

    /// Whether the law is the exact Darboux–Keller integration (newton, poisson, energetic).
    pub fn is_darboux_keller(self) -> bool {
        matches!(self, LawId::Newton | LawId::Poisson | LawId::Energetic)
    }
}

impl fmt::Display for LawId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for LawId {
    type Err = Error;
    /// Parse a stable id: every id of [`LawId::ALL`], `sequential` and `lzb`.
    fn from_str(s: &str) -> Result<Self> {
        let every = || {
            LawId::ALL
                .iter()
                .copied()
                .chain([LawId::Sequential, LawId::Lzb])
        };
        every()
            .find(|l| l.as_str() == s)
            .ok_or_else(|| Error::UnknownLaw {
                id: s.to_string(),
                known: every().map(|l| l.as_str()).collect::<Vec<_>>().join(", "),
            })
    }
}

impl From<LawId> for &'static str {
    /// The stable id ([`LawId::as_str`]).
    fn from(law: LawId) -> Self {
        law.as_str()
    }
}

impl TryFrom<String> for LawId {
    type Error = Error;
    /// Parse a stable id, as [`FromStr`].
    fn try_from(id: String) -> Result<Self> {
        id.parse()
    }
}

/// A contact-space problem that the laws resolve by id: [`crate::planar::ContactProblem`],
/// [`crate::spatial::ContactProblem`], and several contacts in the plane or in space
/// ([`crate::multi::MultiProblem`], [`crate::multi::spatial::MultiProblem`]).
///
/// ```
/// use impax::{law::Options, planar, spatial, LawId};
/// // The seed's sphere (paper A: α = 30°, e = 0.7, f = 0.4), in the plane and in space.
/// let a = 30f64.to_radians();
/// let p2 = planar::ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7)?;
/// let p3 = spatial::ContactProblem::from_upper(
///     [3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [a.sin(), 0.0, -a.cos()], 0.4, 0.7)?;
/// let planar = LawId::Energetic.resolve(&p2).unwrap();
/// let spatial = LawId::Energetic.resolve_with(&p3, &Options::default()).unwrap();
/// assert!((planar.energy_change - spatial.energy_change).abs() < 1e-12);
/// # Ok::<(), impax::Error>(())
/// ```
pub trait Problem {
    /// What a law gives for it: an outcome or a [`Breakdown`] (for several contacts, first an
    /// [`crate::Error`] naming the field `law` when the law does not take them).
    type Resolution;

    /// Resolve it with the law `law` and the options `options`.
    fn resolve_by(&self, law: LawId, options: &Options) -> Self::Resolution;
}

impl LawId {
    /// Resolve a contact-space problem of any kind ([`Problem`]) with this law and the default
    /// [`Options`].
    ///
    /// For one planar contact, `smith-centre` needs a body's centre velocity, which contact
    /// space does not have: it returns [`BreakdownReason::NeedsBody`] (use
    /// [`crate::planar::bodies::BodyImpact::resolve`] or
    /// [`crate::planar::laws::Smith::centre`]); `two-phase`, `smith` and `smith-centre` are
    /// planar only ([`BreakdownReason::PlanarOnly`] in space). `sequential` and `lzb` with one
    /// contact are `energetic`, its outcome (or breakdown) labelled `sequential` or `lzb`. With
    /// several contacts only the multi-contact laws apply ([`crate::multi::resolve`]).
    #[inline]
    pub fn resolve<P: Problem + ?Sized>(self, problem: &P) -> P::Resolution {
        problem.resolve_by(self, &Options::default())
    }

    /// [`LawId::resolve`] with the options `options` (the tolerance of the integrating laws).
    #[inline]
    pub fn resolve_with<P: Problem + ?Sized>(
        self,
        problem: &P,
        options: &Options,
    ) -> P::Resolution {
        problem.resolve_by(self, options)
    }
}

/// An impact law: maps a contact-space problem to an outcome or a breakdown — the one trait
/// of the planar laws ([`crate::planar::laws`]: `Problem = ContactProblem`,
/// `Outcome = Outcome`, `Brief = OutcomeBrief`), of the spatial ones ([`crate::spatial::laws`],
/// whose brief is the outcome itself) and of any law on another kind of problem.
///
/// Laws are pure functions of the problem: no I/O, no allocation.
pub trait ImpactLaw {
    /// What the law resolves (a contact-space problem).
    type Problem;
    /// What it returns for one impact.
    type Outcome;
    /// What a tally reads of an outcome (verdict, phases and `ΔT`): always the brief of the
    /// outcome of [`resolve`](ImpactLaw::resolve).
    type Brief: for<'a> From<&'a Self::Outcome>;
    /// The law's stable id.
    fn id(&self) -> LawId;
    /// Resolve one impact.
    fn resolve(&self, problem: &Self::Problem) -> std::result::Result<Self::Outcome, Breakdown>;
    /// Resolve one impact to its brief only. Always the brief of the outcome of
    /// [`resolve`](ImpactLaw::resolve) (or the same breakdown); a law may override it to skip
    /// the rest of the record (the planar Darboux–Keller laws do).
    #[inline]
    fn resolve_brief(
        &self,
        problem: &Self::Problem,
    ) -> std::result::Result<Self::Brief, Breakdown> {
        self.resolve(problem).map(|o| Self::Brief::from(&o))
    }
}
