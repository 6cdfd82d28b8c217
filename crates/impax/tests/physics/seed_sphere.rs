//! The seed's sphere (paper A, Liu 2012, *On Kane's paradox of frictional impact*): every
//! closed-form result of the paper, derived here independently of the library, against the
//! engine driven through `impax::planar::bodies`.
//!
//! Sphere `m = 1`, `r = 1` (`J = 2/5 m r²`), speed `v0 = 1` at `α = 30°` from the normal,
//! `e = 0.7`, `f = 0.4`, spin ratio `γ = ω0 r / v0` over a range on both sides of
//! `γ = −sin α` (where the initial slip `v_Px⁻ = v0 (sin α + γ)` changes sign). Checked to
//! 1e-12:
//!
//! * `whittaker`: eqs. 2, 9a/9b (`v_x⁺`, `ω⁺`, both sign branches), eq. 10 (slip after) and
//!   eq. 13 (`ΔT/T0`, `T0 = m v0²/2`, both branches); eq. 14's threshold `γ ≈ 0.20`;
//! * `two-phase`: eq. 21 (switch impulse) and eq. 23 — with the `sin α` term that the print
//!   drops from `v_x⁺`, re-derived from eqs. 17–22:
//!   `v_x⁺ = v0 [sin α + f(1+e) cos α − (4/7)(γ + sin α)]`;
//! * `smith-centre` (the literal centre-velocity reading of eq. 24): eq. 26 with `ξ` from
//!   eq. 27, `ξ² + f(1+e) cos α ξ + (sin α − f(1+e) cos α) sin α = 0`;
//! * the Darboux–Keller laws: the slip halts at `p_n = 2/(7f) (sin α + γ) m v0`, then the
//!   sphere rolls (`v_t⁺ = 0`) and `ΔT/T0 < 0`;
//! * verdicts at `γ = 0`: `whittaker` gains energy and its slip reverses; `two-phase`'s
//!   assumed reversal does not happen.
//!
//! Printed numbers of the paper that do not follow from its own formulas (never used as
//! references here): eq. 13 at `γ = 0` gives `ΔT/T0 = 0.2424`, printed 0.23; eq. 15's sign
//! change is at `γ = −1.21`, printed −0.20; eq. 27 gives `ξ = 0.0677`, printed 0.0726, and
//! then eqs. 12/26 give `ΔT/T0 = +0.178` at `γ = 0`, printed −0.38; the printed two-phase
//! `v_x⁺ = 0.30 v0` and `ΔT/T0 = −0.67` come from the misprinted eq. 23 (the corrected
//! formula gives 0.803 and +0.2424, Whittaker's value).

use impax::planar::bodies::{sphere, spin_state, BodyImpact, BodyOutcome, Side};
use impax::planar::{Inconsistency, LawDetail, Verdict};
use impax::LawId;

const ALPHA_DEG: f64 = 30.0;
const E: f64 = 0.7;
const F: f64 = 0.4;
const TOL: f64 = 1e-12;

/// The seed's parameters with `m = r = v0 = 1`.
struct Seed {
    s: f64,
    c: f64,
    gamma: f64,
}

impl Seed {
    fn new(gamma: f64) -> Self {
        let a = ALPHA_DEG.to_radians();
        Self {
            s: a.sin(),
            c: a.cos(),
            gamma,
        }
    }
    /// `f (1 + e) cos α`, the Whittaker tangential impulse per `m v0`.
    fn fc(&self) -> f64 {
        F * (1.0 + E) * self.c
    }
    /// Sign of the initial slip `v_Px⁻ = v0 (sin α + γ)` (eq. 6).
    fn s0(&self) -> f64 {
        (self.s + self.gamma).signum()
    }
    /// `ΔT/T0` from body velocities after (eq. 12 with `T0 = m v0²/2`, `J = 2/5`).
    fn energy_ratio(&self, vx: f64, vy: f64, omega: f64) -> f64 {
        let t_after = 0.5 * (vx * vx + vy * vy) + 0.5 * 0.4 * omega * omega;
        let t_before = 0.5 + 0.5 * 0.4 * self.gamma * self.gamma;
        (t_after - t_before) / 0.5
    }
}

/// The engine on the seed through `impax::planar::bodies`.
fn engine(gamma: f64, law: LawId) -> BodyOutcome {
    let body = sphere(1.0, 1.0, Side::Below).unwrap();
    let state = spin_state(1.0, ALPHA_DEG.to_radians(), gamma, 1.0).unwrap();
    let impact = BodyImpact::on_fixed_surface(body, state);
    let problem = impact.problem(F, E).unwrap();
    impact
        .resolve(law, &problem)
        .unwrap_or_else(|b| panic!("{law} at γ = {gamma}: {b}"))
}

fn close(what: &str, gamma: f64, got: f64, want: f64) {
    assert!(
        (got - want).abs() <= TOL * want.abs().max(1.0),
        "{what} at γ = {gamma}: engine {got}, paper {want} (diff {:.3e})",
        got - want
    );
}

/// `γ` from −1.5 to 1.5 in steps of 0.05, skipping `γ = −sin α` (no initial slip).
fn gammas() -> impl Iterator<Item = f64> {
    (-30..=30)
        .map(|i| i as f64 * 0.05)
        .filter(|g| (g + 0.5).abs() > 1e-9)
}

#[test]
fn whittaker_matches_eqs_9_10_13() {
    for gamma in gammas() {
        let sd = Seed::new(gamma);
        let (s, c, fc) = (sd.s, sd.c, sd.fc());
        // Upper sign of "∓" when v_Px⁻ > 0.
        let pm = sd.s0();
        let vx = s - pm * fc; // eq. 9a
        let vy = E * c; // eq. 2
        let omega = gamma - pm * 2.5 * fc; // eq. 9b
        let slip = s + gamma - pm * 3.5 * fc; // eq. 10 (and its mirror for v_Px⁻ < 0)
        let ratio = (s - pm * fc).powi(2) + (E * E + 2.5 * F * F * (1.0 + E).powi(2)) * c * c
            - 1.0
            - pm * 2.0 * F * gamma * (1.0 + E) * c; // eq. 13
        let out = engine(gamma, LawId::Whittaker);
        close("v_x⁺", gamma, out.body_after.velocity.x, vx);
        close("v_y⁺", gamma, out.body_after.velocity.y, vy);
        close("ω⁺", gamma, out.body_after.omega, omega);
        close("v_Px⁺", gamma, out.outcome.velocity_after.x, slip);
        close("v_Py⁺", gamma, out.outcome.velocity_after.y, vy);
        close("ΔT/T0", gamma, 2.0 * out.outcome.energy_change, ratio);
        close(
            "ΔT/T0 (bodies)",
            gamma,
            2.0 * out.energy_change.total(),
            ratio,
        );
        // eq. 13 is eq. 12 evaluated on eq. 9: the two derivations agree.
        close(
            "eq. 12 vs eq. 13",
            gamma,
            sd.energy_ratio(vx, vy, omega),
            ratio,
        );
        // Impulses of eq. 4 and eq. 7.
        close("I_y", gamma, out.outcome.impulse.y, (1.0 + E) * c);
        close("I_x", gamma, out.outcome.impulse.x, -pm * fc);
    }
}

#[test]
fn whittaker_energy_threshold_of_eq_14() {
    // ΔT/T0 of eq. 13 (upper sign) vanishes at γ* = A / (2 f (1+e) cos α).
    let sd = Seed::new(0.0);
    let (s, c, fc) = (sd.s, sd.c, sd.fc());
    let a = (s - fc).powi(2) + (E * E + 2.5 * F * F * (1.0 + E).powi(2)) * c * c - 1.0;
    let gamma_star = a / (2.0 * fc);
    assert!((gamma_star - 0.20).abs() < 0.01, "γ* = {gamma_star}");
    for (gamma, gains) in [(gamma_star - 1e-6, true), (gamma_star + 1e-6, false)] {
        let out = engine(gamma, LawId::Whittaker);
        assert_eq!(out.outcome.energy_change > 0.0, gains, "γ = {gamma}");
        assert_eq!(
            out.outcome.verdict == Verdict::EnergyGained,
            gains,
            "γ = {gamma}"
        );
    }
    // Lower sign (v_Px⁻ < 0, γ < −sin α): ΔT/T0 = B + 2 f γ (1+e) cos α vanishes at
    // γ** = −B / (2 f (1+e) cos α) ≈ −1.21 (the print's eq. 15 says −0.20, which is not on
    // this branch at all).
    let b = (s + fc).powi(2) + (E * E + 2.5 * F * F * (1.0 + E).powi(2)) * c * c - 1.0;
    let gamma_low = -b / (2.0 * fc);
    assert!(
        gamma_low < -s && (gamma_low + 1.206).abs() < 1e-3,
        "γ** = {gamma_low}"
    );
    for (gamma, gains) in [(gamma_low - 1e-6, false), (gamma_low + 1e-6, true)] {
        let out = engine(gamma, LawId::Whittaker);
        assert_eq!(out.outcome.energy_change > 0.0, gains, "γ = {gamma}");
    }
}

#[test]
fn whittaker_at_gamma_zero_gains_energy_with_reversed_slip() {
    let out = engine(0.0, LawId::Whittaker).outcome;
    assert_eq!(out.verdict, Verdict::EnergyGained);
    let slip = Seed::new(0.0).s - 3.5 * Seed::new(0.0).fc();
    match out.inconsistency {
        Some(Inconsistency::SlipReversed { slip_after }) => {
            close("slip after", 0.0, slip_after, slip);
            assert!(slip_after < 0.0);
        }
        other => panic!("expected SlipReversed, got {other:?}"),
    }
    // The paper's printed values at γ = 0 (rounded, and ΔT/T0 printed as 0.23 for 0.2424).
    let b = engine(0.0, LawId::Whittaker);
    assert!((b.body_after.velocity.x + 0.089).abs() < 5e-4);
    assert!((b.body_after.velocity.y - 0.606).abs() < 5e-4);
    assert!((b.body_after.omega + 1.47).abs() < 5e-3);
    assert!((2.0 * b.outcome.energy_change - 0.2424).abs() < 1e-4);
}

#[test]
fn two_phase_matches_eqs_21_23() {
    for gamma in gammas() {
        let sd = Seed::new(gamma);
        let (s, c, fc, s0) = (sd.s, sd.c, sd.fc(), sd.s0());
        let switch = 2.0 / (7.0 * F) * (gamma + s).abs(); // eq. 21 (|…| for v_Px⁻ < 0)
        let total = (1.0 + E) * c; // eq. 4
        let out = engine(gamma, LawId::TwoPhase);
        if switch >= total {
            // The slip never halts within Whittaker's impulse: the scheme is Whittaker's.
            assert_eq!(
                out.outcome.detail,
                LawDetail::TwoPhase {
                    switch_impulse: None
                }
            );
            continue;
        }
        // Eq. 23, re-derived from eqs. 17–22 with the sin α term the print drops, and
        // written for either sign s0 of the initial slip (the paper takes s0 = +1):
        // I_x = −s0 f I'_y + s0 f (I_y − I'_y) = s0 f(1+e) cos α − (4/7)(γ + sin α).
        let ix = s0 * fc - 4.0 / 7.0 * (gamma + s);
        let vx = s + ix;
        let omega = gamma + 2.5 * ix;
        let vy = E * c;
        if s0 > 0.0 {
            // The printed form, with sin α restored in v_x⁺ and ω⁺ exactly as printed.
            let printed_omega = gamma + 2.5 * (fc - 4.0 / 7.0 * (gamma + s));
            let corrected_vx = s + fc - 4.0 / 7.0 * (gamma + s);
            close("eq. 23 ω⁺ as printed", gamma, omega, printed_omega);
            close("eq. 23 v_x⁺ corrected", gamma, vx, corrected_vx);
        }
        match out.outcome.detail {
            LawDetail::TwoPhase {
                switch_impulse: Some(p),
            } => close("I'_y (eq. 21)", gamma, p, switch),
            other => panic!("γ = {gamma}: expected a switch, got {other:?}"),
        }
        close("I_y", gamma, out.outcome.impulse.y, total);
        close("I_x", gamma, out.outcome.impulse.x, ix);
        close("v_x⁺", gamma, out.body_after.velocity.x, vx);
        close("v_y⁺", gamma, out.body_after.velocity.y, vy);
        close("ω⁺", gamma, out.body_after.omega, omega);
        close("v_Px⁺", gamma, out.outcome.velocity_after.x, vx + omega);
        let ratio = sd.energy_ratio(vx, vy, omega);
        close("ΔT/T0", gamma, 2.0 * out.outcome.energy_change, ratio);
        // For the sphere (W_tn = 0) the slip after phase 2 is 7/2 f I''_y > 0 along the
        // initial slip: the assumed reversal never happens.
        close(
            "v_Px⁺ = s0 (7/2) f I''_y",
            gamma,
            vx + omega,
            s0 * 3.5 * F * (total - switch),
        );
        match out.outcome.inconsistency {
            Some(Inconsistency::ReversalDidNotHappen { slip_after }) => {
                close("slip after", gamma, slip_after, vx + omega)
            }
            other => panic!("γ = {gamma}: expected ReversalDidNotHappen, got {other:?}"),
        }
    }
}

#[test]
fn two_phase_at_gamma_zero() {
    let out = engine(0.0, LawId::TwoPhase);
    assert!(matches!(
        out.outcome.inconsistency,
        Some(Inconsistency::ReversalDidNotHappen { .. })
    ));
    // With the corrected eq. 23, ΔT/T0 = +0.2424, exactly Whittaker's (for W_tn = 0 the
    // reversed impulse is Whittaker's mirrored about the sticking impulse), so the headline
    // verdict is the energy gain (the print's −0.67 comes from the misprinted eq. 23).
    assert_eq!(out.outcome.verdict, Verdict::EnergyGained);
    let wh = engine(0.0, LawId::Whittaker);
    close(
        "ΔT two-phase vs whittaker",
        0.0,
        out.outcome.energy_change,
        wh.outcome.energy_change,
    );
    let sd = Seed::new(0.0);
    // Corrected eq. 23: v_x⁺ = 0.803 v0 (the print's 0.30 drops sin α); ω⁺ = 0.758 v0/r.
    assert!((out.body_after.velocity.x - 0.803).abs() < 5e-4);
    assert!((out.body_after.omega - 0.758).abs() < 5e-4);
    close(
        "v_x⁺",
        0.0,
        out.body_after.velocity.x,
        sd.s + sd.fc() - 4.0 / 7.0 * sd.s,
    );
}

#[test]
fn smith_centre_matches_eqs_26_27() {
    for gamma in gammas() {
        let sd = Seed::new(gamma);
        let (s, c, fc) = (sd.s, sd.c, sd.fc());
        // With these parameters Whittaker's centre velocity reverses (sin α < f(1+e) cos α),
        // so eq. 27 applies for every γ (the centre velocity does not depend on γ).
        assert!(s < fc);
        // ξ² + fc ξ + (s − fc) s = 0, positive root (cancellation-free form).
        let q0 = (s - fc) * s;
        let xi = -2.0 * q0 / (fc + (fc * fc - 4.0 * q0).sqrt());
        assert!(xi > 0.0);
        assert!((xi * xi + fc * xi + q0).abs() < 1e-15);
        let vx = -xi; // v_x⁺ = −|v_x⁺|
        let eta = (vx * vx.abs() + s * s) / (vx * vx + s * s); // eq. 24
        close("eq. 26a", gamma, s - eta * fc, vx);
        let omega = gamma - 2.5 * eta * fc; // eq. 26b
        let vy = E * c;
        let out = engine(gamma, LawId::SmithCentre);
        match out.outcome.detail {
            LawDetail::Smith { eta: got, .. } => close("η", gamma, got, eta),
            other => panic!("expected Smith detail, got {other:?}"),
        }
        close("I_x (eq. 25)", gamma, out.outcome.impulse.x, -eta * fc);
        close("v_x⁺", gamma, out.body_after.velocity.x, vx);
        close("v_y⁺", gamma, out.body_after.velocity.y, vy);
        close("ω⁺", gamma, out.body_after.omega, omega);
        close(
            "ΔT/T0",
            gamma,
            2.0 * out.outcome.energy_change,
            sd.energy_ratio(vx, vy, omega),
        );
    }
    // At γ = 0: ξ = 0.0677 (printed 0.0726), η = 0.964 (printed 0.96), ω⁺ = −1.4195 v0/r
    // (printed γ − 1.41). Eqs. 12 and 26 then give ΔT/T0 = +0.178: on the literal reading
    // the energy rises (the print says −0.38).
    let out = engine(0.0, LawId::SmithCentre);
    assert!((out.body_after.velocity.x + 0.0677).abs() < 1e-4);
    assert!((out.body_after.omega + 1.4195).abs() < 1e-3);
    assert!((2.0 * out.outcome.energy_change - 0.178).abs() < 1e-3);
}

#[test]
fn darboux_keller_halts_the_slip_and_rolls() {
    for gamma in gammas() {
        let sd = Seed::new(gamma);
        let (s, c) = (sd.s, sd.c);
        let halt = 2.0 / (7.0 * F) * (s + gamma).abs();
        let total = (1.0 + E) * c;
        for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
            let out = engine(gamma, law);
            let o = &out.outcome;
            // W_tn = 0: the three laws end at the same p_n = (1+e) m v0 cos α.
            close("p_n", gamma, o.impulse.y, total);
            close("v_n⁺", gamma, o.velocity_after.y, E * c);
            close("p_c", gamma, o.compression_impulse.unwrap(), c);
            if halt < total {
                match o.detail {
                    LawDetail::DarbouxKeller {
                        slip_halt: Some(ps),
                    } => close("slip halt 2/(7f)(sin α + γ)", gamma, ps, halt),
                    other => panic!("{law} γ = {gamma}: expected a halt, got {other:?}"),
                }
                // Rolling after: the sticking impulse p_t = −(2/7)(sin α + γ) m v0.
                close("p_t", gamma, o.impulse.x, -2.0 / 7.0 * (s + gamma));
                assert!(
                    o.velocity_after.x.abs() <= TOL,
                    "v_t⁺ = {}",
                    o.velocity_after.x
                );
                let vx = s - 2.0 / 7.0 * (s + gamma);
                let omega = gamma - 5.0 / 7.0 * (s + gamma);
                close("v_x⁺", gamma, out.body_after.velocity.x, vx);
                close("ω⁺", gamma, out.body_after.omega, omega);
                close("rolling v_x⁺ + ω⁺ r", gamma, vx + omega, 0.0);
                let ratio = sd.energy_ratio(vx, E * c, omega);
                close("ΔT/T0", gamma, 2.0 * o.energy_change, ratio);
                assert!(ratio < 0.0, "γ = {gamma}: ΔT/T0 = {ratio}");
                assert_eq!(o.verdict, Verdict::Consistent);
                assert_eq!(o.phases.len(), 2, "{}", o.phases.summary());
            } else {
                // The slip never halts: Whittaker's impulse.
                close("p_t", gamma, o.impulse.x, -sd.s0() * sd.fc());
                assert_eq!(o.phases.len(), 1, "{}", o.phases.summary());
            }
        }
    }
}

#[test]
fn darboux_keller_at_gamma_zero_loses_energy_while_whittaker_gains() {
    let dk = engine(0.0, LawId::Energetic).outcome;
    let wh = engine(0.0, LawId::Whittaker).outcome;
    assert!(dk.energy_change < 0.0 && wh.energy_change > 0.0);
    assert!(dk.velocity_after.x.abs() <= TOL);
    // ΔT/T0 = (sin α − 2/7 sin α)² + e² cos² α + 2/5 (5/7 sin α)² − 1.
    let s = Seed::new(0.0).s;
    let c = Seed::new(0.0).c;
    let want = (5.0 / 7.0 * s).powi(2) + E * E * c * c + 0.4 * (5.0 / 7.0 * s).powi(2) - 1.0;
    close("ΔT/T0", 0.0, 2.0 * dk.energy_change, want);
}

#[test]
fn no_initial_slip_means_no_whittaker_friction() {
    // γ = −sin α: v_Px⁻ = 0, Whittaker applies no friction (no direction is defined).
    let gamma = -ALPHA_DEG.to_radians().sin();
    let out = engine(gamma, LawId::Whittaker);
    assert_eq!(out.outcome.impulse.x, 0.0);
    // The Darboux–Keller laws stick at once: v_t stays 0 and p_t = 0 (W_tn = 0).
    let dk = engine(gamma, LawId::Energetic);
    assert_eq!(dk.outcome.impulse.x, 0.0);
    assert_eq!(dk.outcome.velocity_after.x, 0.0);
}
