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
//! [`crate::bodies`] and resolved by each law), and where the print differs, from the paper's
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

use crate::bodies::{sphere, spin_state, BodyOutcome, PlanarImpact, Side};
use crate::law::LawId;
use crate::math::{quadratic_roots, Vec2};
use crate::numerics::roots::bisection;
use crate::planar::{ContactProblem, Inconsistency, LawDetail, Verdict};
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
    pub fn impact(&self, gamma: f64) -> crate::Result<PlanarImpact> {
        let body = sphere(self.mass, self.radius, Side::Below)?;
        let state = spin_state(self.speed, self.alpha, gamma, self.radius)?;
        Ok(PlanarImpact::on_fixed_surface(body, state))
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

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

/// Relative tolerance for "the printed formula equals the engine".
const FORMULA_TOL: f64 = 1e-9;

/// `(value, decimals)` of a printed decimal number.
fn parse_printed(printed: &str) -> Option<(f64, usize)> {
    let s = printed.trim().replace('−', "-");
    let value: f64 = s.parse().ok()?;
    let decimals = s.split_once('.').map_or(0, |(_, frac)| frac.len());
    Some((value, decimals))
}

/// `x` with `d` decimals, without a sign on zero.
fn fmt(x: f64, d: usize) -> String {
    let s = format!("{x:.d$}");
    if s.chars().all(|c| matches!(c, '-' | '0' | '.')) {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// Six decimals (formula rows and notes).
fn f6(x: f64) -> String {
    fmt(x, 6)
}

/// Signed, six decimals (`+0.177779`).
fn s6(x: f64) -> String {
    if x > 0.0 {
        format!("+{}", f6(x))
    } else {
        f6(x)
    }
}

/// A row comparing a number with a printed number. `printed_number` is the number as
/// printed; `printed` the fuller text shown (often the same).
fn number(
    id: &'static str,
    quantity: String,
    printed: &str,
    printed_number: &str,
    value: f64,
    why: impl FnOnce() -> String,
) -> Row {
    let decimals = parse_printed(printed_number).map_or(3, |(_, d)| d);
    let agreement = Agreement::of(printed_number, value);
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed: fmt(value, (decimals + 3).min(6)),
        computed_value: Some(value),
        agreement,
        note: if agreement == Agreement::Agrees {
            String::new()
        } else {
            why()
        },
    }
}

/// A row comparing a printed formula, evaluated at the seed, with the engine.
fn formula(
    id: &'static str,
    quantity: String,
    printed: &str,
    from_formula: f64,
    engine: f64,
) -> Row {
    let agrees = (from_formula - engine).abs() <= FORMULA_TOL * engine.abs().max(1.0);
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed: f6(engine),
        computed_value: Some(engine),
        agreement: if agrees {
            Agreement::Agrees
        } else {
            Agreement::Differs
        },
        note: if agrees {
            String::new()
        } else {
            format!(
                "the printed formula gives {}, the engine {}",
                f6(from_formula),
                f6(engine)
            )
        },
    }
}

/// A row checking a printed statement (inequality, condition, conclusion).
fn statement(
    id: &'static str,
    quantity: String,
    printed: &str,
    computed: String,
    value: Option<f64>,
    holds: bool,
    why: impl FnOnce() -> String,
) -> Row {
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed,
        computed_value: value,
        agreement: if holds {
            Agreement::Agrees
        } else {
            Agreement::Differs
        },
        note: if holds { String::new() } else { why() },
    }
}

/// A row with impax's own result, not printed in the paper.
fn reference(quantity: String, computed: String, value: Option<f64>, note: String) -> Row {
    Row {
        id: "exact",
        quantity,
        printed: "—".to_string(),
        computed,
        computed_value: value,
        agreement: Agreement::NotPrinted,
        note,
    }
}

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

// ---------------------------------------------------------------------------------------
// The report
// ---------------------------------------------------------------------------------------

/// The seed with the paper's derived constants and formulas.
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

    fn whittaker_rows(&self, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let (s, big_f) = (self.s, self.big_f);
        let w0 = self.run(LawId::Whittaker, 0.0);

        // Eq. 4: the normal impulse.
        rows.push(formula(
            "eq. 4",
            "I_y/(m v0), normal impulse (Whittaker, γ = 0)".into(),
            "(1 + e) m v0 cos α",
            (1.0 + seed.restitution) * self.c,
            self.impulse(w0.outcome.impulse.y),
        ));
        // Eq. 2.
        let vy = self.vy(&w0);
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
        let vx = self.vx(&w0);
        rows.push(number(
            "eq. 9a",
            "v_x+/v0 (Whittaker, γ = 0)".into(),
            "-0.089",
            "-0.089",
            vx,
            || format!("eq. 9a gives sin α − f(1+e)cos α = {}", f6(s - big_f)),
        ));
        let om = self.omega(&w0);
        rows.push(number(
            "eq. 9b",
            "ω+ r/v0 (Whittaker, γ = 0)".into(),
            "-1.47",
            "-1.47",
            om,
            || format!("eq. 9b gives γ − (5/2) f(1+e)cos α = {}", f6(-2.5 * big_f)),
        ));
        // Eq. 10: the slip after.
        let slip0 = self.slip_after(&w0);
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

        // Eq. 13 at γ = 0.
        let r0 = self.ratio(&w0);
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

    fn two_phase_rows(&self, rows: &mut Vec<Row>) {
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

    fn smith_rows(&self, rows: &mut Vec<Row>) {
        let seed = &self.seed;
        let (s, big_f) = (self.s, self.big_f);
        let g_half = seed.zero_slip_spin();
        let eta_of = |o: &BodyOutcome| match o.outcome.detail {
            LawDetail::Smith { eta, .. } => eta,
            _ => f64::NAN,
        };
        let roots_of = |o: &BodyOutcome| match o.outcome.detail {
            LawDetail::Smith { roots, .. } => roots,
            _ => 0,
        };
        let c0 = self.run(LawId::SmithCentre, 0.0);
        let s0 = self.run(LawId::Smith, 0.0);
        let c5 = self.run(LawId::SmithCentre, g_half);
        let s5 = self.run(LawId::Smith, g_half);

        // Eq. 27 solved directly (the literal reading reduced by the paper).
        let [q_lo, q_hi] = quadratic_roots(1.0, big_f, (s - big_f) * s);
        let residual = |xi: f64| xi * xi + big_f * xi + (s - big_f) * s;
        // The same reduction for the sliding velocity: (7/2) f(1+e)cos α in place of f(1+e)cos α.
        let g7 = 3.5 * big_f;
        let [_, zeta] = quadratic_roots(1.0, g7, (s - g7) * s);

        // ξ.
        let (vx_c, vx_s) = (self.vx(&c0), self.vx(&s0));
        let (slip_c, slip_s) = (self.slip_after(&c0), self.slip_after(&s0));
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
                    roots_of(&c0),
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
        // η.
        let (eta_c, eta_s) = (eta_of(&c0), eta_of(&s0));
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
        // ω⁺ = (γ − const) v0/r.
        let (om_c, om_s) = (self.omega(&c0), self.omega(&s0));
        let om_c5 = self.omega(&c5) - g_half;
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
        // ΔT/T0 at γ = 0.
        let (r_c0, r_s0) = (self.ratio(&c0), self.ratio(&s0));
        let frictionless = s * s + seed.restitution * seed.restitution * self.c * self.c - 1.0;
        let printed_eq12 = self.eq12(-0.0726, self.vy(&c0), -1.41, 0.0);
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
        let (r_c5, r_s5) = (self.ratio(&c5), self.ratio(&s5));
        let printed_eq12_half = self.eq12(-0.0726, self.vy(&c5), g_half - 1.41, g_half);
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
                    f6(eta_of(&c5)),
                    f6(self.omega(&c5)),
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
                    f6(eta_of(&s5)),
                    s6(r_s5),
                    s6(r_c5)
                )
            },
        ));
        // The conclusion of §4, in each reading.
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

    /// §5: the split of ΔT into translational and rotational parts (Whittaker, γ = 0).
    fn split_rows(&self, rows: &mut Vec<Row>) {
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

    /// The exact answer (Darboux–Keller with energetic restitution), not in the paper.
    fn exact_rows(&self, rows: &mut Vec<Row>) {
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

/// Slip before the impact, `v_Px⁻ / v0`, from the engine's contact velocity.
fn problem_slip(impact: &PlanarImpact, seed: &Seed) -> f64 {
    impact.contact_velocity().x / seed.speed
}
