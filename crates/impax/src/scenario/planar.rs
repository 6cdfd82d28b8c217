//! The planar body scenario: one body striking a fixed surface, or two free bodies.

use super::body::{BodySpec, BuiltBody, Scale};
use crate::error::{Error, Result};
use crate::law::LawId;
use crate::planar::bodies::{BodyImpact, Side};
use serde::Deserialize;

/// The seed's case (paper A): sphere, m = r = v0 = 1, α = 30°, e = 0.7, μ = 0.4, γ = 0.
pub const SEED_TOML: &str = r#"friction = 0.4
restitution = 0.7

[body]
shape = "sphere"
mass = 1.0
radius = 1.0
speed = 1.0
alpha_deg = 30.0
spin_ratio = 0.0
"#;

/// A planar body scenario as written in a file (see the [module docs](super)).
///
/// ```
/// use impax::scenario::{PlanarScenario, SEED_TOML};
/// let s = PlanarScenario::from_toml(SEED_TOML)?;
/// let built = s.build()?;
/// assert_eq!(built.body.description, "sphere m = 1, r = 1, v0 = 1, α = 30°, γ = 0");
/// let p = built.impact.problem(s.friction, s.restitution)?;
/// assert_eq!(p.wtt(), 3.5);
/// # Ok::<(), impax::Error>(())
/// ```
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[serde(deny_unknown_fields)]
pub struct PlanarScenario {
    /// Coulomb friction `μ`.
    pub friction: f64,
    /// Coefficient of restitution `e`.
    pub restitution: f64,
    /// The laws to show (ids), if the file chooses them.
    pub laws: Option<Vec<String>>,
    /// The striking body A (contact at its lowest point).
    pub body: BodySpec,
    /// An optional second free body B, struck at its highest point.
    pub other: Option<BodySpec>,
}

/// A planar scenario built: its impact, its bodies and their description.
#[derive(Debug, Clone)]
pub struct BuiltPlanar {
    /// The impact of body A on the surface or on body B.
    pub impact: BodyImpact,
    /// Body A as built.
    pub body: BuiltBody,
    /// Body B as built, if any.
    pub other: Option<BuiltBody>,
}

impl BuiltPlanar {
    /// The description of the whole scenario, e.g. `sphere m = 1, … striking disc m = 2, …`.
    pub fn description(&self) -> String {
        match &self.other {
            None => self.body.description.clone(),
            Some(o) => format!("{} striking {}", self.body.description, o.description),
        }
    }

    /// How body A's results are normalised.
    pub fn scale(&self) -> Scale {
        self.body.scale
    }
}

impl PlanarScenario {
    /// The seed's scenario ([`SEED_TOML`]).
    pub fn seed() -> Self {
        Self::from_toml(SEED_TOML).expect("the seed's scenario is valid")
    }

    /// Read a scenario from TOML text.
    ///
    /// # Errors
    /// [`Error::Syntax`] with the line and column of the first problem: malformed TOML, a
    /// missing key, a value of the wrong type, an unknown key.
    pub fn from_toml(text: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| Error::syntax(text, &e))
    }

    /// The laws the file chooses, parsed (`None`: every law).
    ///
    /// # Errors
    /// An unknown law id.
    pub fn law_ids(&self) -> Result<Option<Vec<LawId>>> {
        self.laws
            .as_ref()
            .map(|ids| {
                let mut laws = Vec::new();
                for id in ids {
                    let law: LawId = id.trim().parse()?;
                    if !laws.contains(&law) {
                        laws.push(law);
                    }
                }
                Ok(laws)
            })
            .transpose()
    }

    /// Build the bodies and the impact.
    ///
    /// # Errors
    /// As [`BodySpec::build`], naming `body.…` or `other.…`.
    pub fn build(&self) -> Result<BuiltPlanar> {
        let body = self.body.build("body", Side::Below)?;
        let (impact, other) = match &self.other {
            None => (BodyImpact::on_fixed_surface(body.body, body.state), None),
            Some(o) => {
                let other = o.build("other", Side::Above)?;
                (
                    BodyImpact::between(body.body, body.state, other.body, other.state),
                    Some(other),
                )
            }
        };
        Ok(BuiltPlanar {
            impact,
            body,
            other,
        })
    }
}
