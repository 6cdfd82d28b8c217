//! Reproduction report of paper A: Liu Yanzhu, *On Kane's paradox of frictional impact*
//! (关于摩擦碰撞的 Kane 难题), Mechanics in Engineering 2012(1): 91–94.
//!
//! The paper's case: a solid sphere (mass `m`, radius `r`, `J = 2/5 m r²`) strikes a fixed
//! plane with speed `v0` at `α = 30°` from the normal, spin ratio `γ = ω0 r / v0`,
//! restitution `e = 0.7`, friction `f = 0.4`. Every numbered result the paper prints is set
//! beside the value impax computes ([`report`]):
//!
//! * §1–2, Whittaker's rule (eqs. 2–15): the printed velocities agree; the printed
//!   `ΔT/T0 = 0.23` is an arithmetic slip for `0.2424`, and the printed threshold of eq. 15
//!   mirrors eq. 14 about `γ = 0` where the true one mirrors it about `γ = −sin α`;
//! * §3, the two-phase scheme (eqs. 16–23): the printed eq. 23 drops the initial `v0 sin α`
//!   from `v_x⁺`, which explains the printed `0.30` and `v_Px⁺ = 1.06`; the scheme in fact
//!   gains exactly Whittaker's energy for the sphere;
//! * §4, Smith's correction (eqs. 24–27), in both readings of eq. 24: the literal one
//!   (`smith-centre`, `η` from the centre velocity `v_x`) and the one the text and Smith 1991
//!   mean (`smith`, `η` from the sliding velocity);
//! * the exact Darboux–Keller answer, which the paper does not give: the slip halts at
//!   `p_n = 2/7 · m v0 (γ + sin α)/f` and the sphere leaves rolling, losing energy.
//!
//! Every computed value comes from the engine (the seed's sphere built with
//! [`crate::planar::bodies`] and resolved by each law), and where the print differs, from the paper's
//! own formulas evaluated at the seed's numbers, to tell an arithmetic slip from a wrong
//! formula. Printed values are transcribed data; nothing computed is hard-coded.
//!
//! Normalisation as in the paper: velocities by `v0`, `ω` by `v0/r`, impulses by `m v0`,
//! energies by `T0 = ½ m v0²`.
//!
//! ```
//! use impax::paper::liu2012::{report, Agreement};
//! let rows = report();
//! let eq9a = rows.iter().find(|r| r.id == "eq. 9a").unwrap();
//! assert_eq!(eq9a.agreement, Agreement::Agrees); // v_x⁺ = −0.089 v0
//! let eq13 = rows.iter().find(|r| r.id == "eq. 13").unwrap();
//! assert_eq!(eq13.agreement, Agreement::Differs); // printed 0.23, computed 0.2424
//! ```

// One file per section of the paper, in the report's order; `row` sets a printed value
// beside the engine's.
mod exact;
mod row;
mod smith;
mod two_phase;
mod whittaker;

use crate::law::LawId;
use crate::planar::bodies::{sphere, spin_state, BodyImpact, BodyOutcome, Side};
use crate::planar::ContactProblem;
use row::parse_printed;
use serde::Serialize;

/// How a computed value compares with the printed one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Agreement {
    /// Within half a unit of the printed last digit (the print is the computed value
    /// rounded); for a statement or a formula: it holds.
    Agrees,
    /// Off by more than half a unit but at most one unit of the printed last digit
    /// (truncated, or rounded from a slightly different intermediate value).
    Rounding,
    /// Anything else: a slip in the arithmetic, in a formula, or a false statement.
    Differs,
    /// The paper prints no value: the row is impax's own result.
    NotPrinted,
}

impl Agreement {
    /// Stable id: `agrees`, `rounding`, `differs`, `not-printed`.
    pub fn id(self) -> &'static str {
        match self {
            Agreement::Agrees => "agrees",
            Agreement::Rounding => "rounding",
            Agreement::Differs => "differs",
            Agreement::NotPrinted => "not-printed",
        }
    }

    /// Compare `computed` with a printed decimal number such as `"-0.089"` (a Unicode minus
    /// is accepted): [`Agrees`](Self::Agrees) within half a unit of the last printed digit,
    /// [`Rounding`](Self::Rounding) within one unit, else [`Differs`](Self::Differs) (also
    /// when `printed` is not a number or `computed` is not finite).
    ///
    /// ```
    /// use impax::paper::liu2012::Agreement;
    /// assert_eq!(Agreement::of("0.96", 0.964), Agreement::Agrees);
    /// assert_eq!(Agreement::of("0.20", 0.2058), Agreement::Rounding);
    /// assert_eq!(Agreement::of("0.23", 0.2424), Agreement::Differs);
    /// ```
    pub fn of(printed: &str, computed: f64) -> Agreement {
        let Some((value, decimals)) = parse_printed(printed) else {
            return Agreement::Differs;
        };
        if !computed.is_finite() {
            return Agreement::Differs;
        }
        let unit = 10f64.powi(-(decimals as i32));
        let slack = 1e-9 * unit;
        let gap = (computed - value).abs();
        if gap <= 0.5 * unit + slack {
            Agreement::Agrees
        } else if gap <= unit + slack {
            Agreement::Rounding
        } else {
            Agreement::Differs
        }
    }
}

/// One line of the reproduction report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// Where the paper states it, e.g. `eq. 9a`, `§3 v_Px+`, or `exact` for impax's own
    /// Darboux–Keller result.
    pub id: &'static str,
    /// What is compared, with the law and the spin ratio, e.g. `v_x+/v0 (Whittaker, γ = 0)`.
    pub quantity: String,
    /// As printed in the paper (a number, a formula or a statement); `—` when not printed.
    pub printed: String,
    /// The computed value (or outcome), formatted with a few more decimals than the print.
    pub computed: String,
    /// The computed number, when the row has one.
    pub computed_value: Option<f64>,
    /// The verdict.
    pub agreement: Agreement,
    /// Why the print and the computation differ, with numbers; empty when they agree.
    pub note: String,
}

/// The paper's case: a solid sphere striking a fixed plane (paper A, Fig. 2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Seed {
    /// Mass `m`.
    pub mass: f64,
    /// Radius `r`.
    pub radius: f64,
    /// Approach speed `v0`.
    pub speed: f64,
    /// Angle of approach from the normal, `α` (radians).
    pub alpha: f64,
    /// Coefficient of restitution `e`.
    pub restitution: f64,
    /// Coulomb friction coefficient `f`.
    pub friction: f64,
}

impl Seed {
    /// The paper's numbers: `m = r = v0 = 1`, `α = 30°`, `e = 0.7`, `f = 0.4`.
    pub const PAPER: Seed = Seed {
        mass: 1.0,
        radius: 1.0,
        speed: 1.0,
        // Bit for bit `30f64.to_radians()`, as the CLI converts degrees.
        alpha: 30.0 * (std::f64::consts::PI / 180.0),
        restitution: 0.7,
        friction: 0.4,
    };

    /// The sphere with spin ratio `γ` (eq. 1) against the fixed plane.
    pub fn impact(&self, gamma: f64) -> crate::Result<BodyImpact> {
        let body = sphere(self.mass, self.radius, Side::Below)?;
        let state = spin_state(self.speed, self.alpha, gamma, self.radius)?;
        Ok(BodyImpact::on_fixed_surface(body, state))
    }

    /// The contact-space problem at spin ratio `γ`.
    pub fn problem(&self, gamma: f64) -> crate::Result<ContactProblem> {
        self.impact(gamma)?.problem(self.friction, self.restitution)
    }

    /// A law's result at spin ratio `γ`; `None` if the parameters are invalid or the law
    /// breaks down (neither happens for [`Seed::PAPER`]: `W_tn = 0` for a sphere).
    pub fn outcome(&self, law: LawId, gamma: f64) -> Option<BodyOutcome> {
        let impact = self.impact(gamma).ok()?;
        let problem = impact.problem(self.friction, self.restitution).ok()?;
        impact.resolve(law, &problem).ok()
    }

    /// The translational energy of the approach, `T0 = ½ m v0²` (the paper's scale).
    pub fn t0(&self) -> f64 {
        0.5 * self.mass * self.speed * self.speed
    }

    /// `ΔT/T0` of a law at spin ratio `γ` (`None` as for [`Seed::outcome`]).
    pub fn energy_ratio(&self, law: LawId, gamma: f64) -> Option<f64> {
        self.outcome(law, gamma)
            .map(|o| o.outcome.energy_change / self.t0())
    }

    /// The spin ratio at which the slip before the impact vanishes, `γ = −sin α` (eq. 6).
    pub fn zero_slip_spin(&self) -> f64 {
        -self.alpha.sin()
    }
}

/// The reproduction report of paper A at [`Seed::PAPER`], in the paper's order, ending with
/// the exact Darboux–Keller answer.
///
/// # Panics
/// Never: the seed's parameters are valid and no law breaks down for a sphere (`W_tn = 0`).
pub fn report() -> Vec<Row> {
    let ctx = Ctx::new(Seed::PAPER);
    let mut rows = Vec::new();
    ctx.whittaker_rows(&mut rows);
    ctx.two_phase_rows(&mut rows);
    ctx.smith_rows(&mut rows);
    ctx.split_rows(&mut rows);
    ctx.exact_rows(&mut rows);
    rows
}

/// The report as a Markdown table (`id | quantity | printed | computed | agreement | note`).
pub fn markdown(rows: &[Row]) -> String {
    let cell = |s: &str| s.replace('|', "\\|");
    let mut out = String::from(
        "| id | quantity | printed | computed | agreement | note |\n|---|---|---|---|---|---|\n",
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            cell(r.id),
            cell(&r.quantity),
            cell(&r.printed),
            cell(&r.computed),
            r.agreement.id(),
            cell(&r.note)
        ));
    }
    out
}

/// The seed with the paper's derived constants and formulas; each section of the report is a
/// method on it, in its own file.
struct Ctx {
    seed: Seed,
    /// `sin α`.
    s: f64,
    /// `cos α`.
    c: f64,
    /// `f (1+e) cos α`: Whittaker's tangential impulse over `m v0`.
    big_f: f64,
}

impl Ctx {
    fn new(seed: Seed) -> Self {
        let (s, c) = seed.alpha.sin_cos();
        Self {
            seed,
            s,
            c,
            big_f: seed.friction * (1.0 + seed.restitution) * c,
        }
    }

    fn run(&self, law: LawId, gamma: f64) -> BodyOutcome {
        self.seed
            .outcome(law, gamma)
            .expect("the seed's sphere is valid and no law breaks down for it (W_tn = 0)")
    }

    // Normalisations.
    fn vx(&self, o: &BodyOutcome) -> f64 {
        o.body_after.velocity.x / self.seed.speed
    }
    fn vy(&self, o: &BodyOutcome) -> f64 {
        o.body_after.velocity.y / self.seed.speed
    }
    fn omega(&self, o: &BodyOutcome) -> f64 {
        o.body_after.omega * self.seed.radius / self.seed.speed
    }
    fn slip_after(&self, o: &BodyOutcome) -> f64 {
        o.outcome.velocity_after.x / self.seed.speed
    }
    fn ratio(&self, o: &BodyOutcome) -> f64 {
        o.outcome.energy_change / self.seed.t0()
    }
    fn impulse(&self, p: f64) -> f64 {
        p / (self.seed.mass * self.seed.speed)
    }

    /// Eq. 12 in the paper's normalisation: `ΔT/T0` of the sphere going from
    /// `(v0 sin α, −v0 cos α, γ v0/r)` to `(v_x, v_y, ω)` (all normalised).
    fn eq12(&self, vx: f64, vy: f64, omega: f64, gamma: f64) -> f64 {
        vx * vx + vy * vy + 0.4 * (omega * omega - gamma * gamma) - 1.0
    }

    /// Eq. 13, the upper signs for `v_Px⁻ > 0` (`branch = +1`), the lower for `v_Px⁻ < 0`.
    fn eq13(&self, gamma: f64, branch: f64) -> f64 {
        let (f, e, c) = (self.seed.friction, self.seed.restitution, self.c);
        let x = self.s - branch * self.big_f;
        x * x + (e * e + 2.5 * f * f * (1.0 + e) * (1.0 + e)) * c * c
            - 1.0
            - branch * 2.0 * f * gamma * (1.0 + e) * c
    }
}
