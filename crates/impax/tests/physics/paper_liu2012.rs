//! The reproduction report of paper A (Liu 2012): every required row is there, the verdicts
//! that the paper's arithmetic earns, and the engine-side facts behind them.

use impax::paper::liu2012::{markdown, report, Agreement, Row, Seed};
use impax::planar::bodies::{sphere, spin_state, BodyImpact, Side};
use impax::LawId;

fn row<'a>(rows: &'a [Row], id: &str) -> &'a Row {
    rows.iter()
        .find(|r| r.id == id)
        .unwrap_or_else(|| panic!("no row `{id}` in the report"))
}

/// ΔT of Whittaker's rule for the seed's sphere at spin ratio γ, built from the public API
/// independently of the report's own helpers.
fn whittaker_energy(gamma: f64) -> f64 {
    let alpha = 30f64.to_radians();
    let body = sphere(1.0, 1.0, Side::Below).unwrap();
    let state = spin_state(1.0, alpha, gamma, 1.0).unwrap();
    let impact = BodyImpact::on_fixed_surface(body, state);
    let problem = impact.problem(0.4, 0.7).unwrap();
    impact
        .resolve(LawId::Whittaker, &problem)
        .unwrap()
        .outcome
        .energy_change
}

const REQUIRED: [&str; 31] = [
    "eq. 4",
    "eq. 2",
    "eq. 6",
    "eq. 9a",
    "eq. 9b",
    "eq. 10",
    "eq. 11",
    "eq. 11 γ",
    "eq. 13",
    "eq. 13 formula",
    "eq. 14",
    "eq. 15",
    "§2",
    "eq. 21",
    "eq. 20",
    "eq. 23a",
    "eq. 23b",
    "§3 ΔT/T0",
    "§3 energy",
    "§3 v_Px+",
    "§3 verdict",
    "eq. 27 centre",
    "eq. 27 slip",
    "eq. 24 centre",
    "eq. 24 slip",
    "eq. 26b centre",
    "eq. 26b slip",
    "§4 ΔT/T0 γ=0 centre",
    "§4 ΔT/T0 γ=0 slip",
    "§4 ΔT/T0 γ=-0.5 centre",
    "§4 ΔT/T0 γ=-0.5 slip",
];

#[test]
fn report_has_every_required_row() {
    let rows = report();
    for id in REQUIRED {
        row(&rows, id);
    }
    for id in ["§4 verdict centre", "§4 verdict slip", "§5 ΔT₁", "§5 ΔT₂"] {
        row(&rows, id);
    }
    // The report ends with impax's exact answer, which the paper does not print.
    let exact: Vec<&Row> = rows.iter().filter(|r| r.id == "exact").collect();
    assert!(exact.len() >= 5);
    assert_eq!(rows.last().unwrap().id, "exact");
    assert!(exact
        .iter()
        .all(|r| r.agreement == Agreement::NotPrinted && r.printed == "—"));
}

#[test]
fn whittaker_velocities_agree_with_the_print() {
    let rows = report();
    for id in ["eq. 9a", "eq. 9b", "eq. 2"] {
        assert_eq!(row(&rows, id).agreement, Agreement::Agrees, "{id}");
    }
    // The printed formulas match the engine.
    for id in [
        "eq. 4",
        "eq. 6",
        "eq. 10",
        "eq. 11",
        "eq. 11 γ",
        "eq. 13 formula",
        "eq. 21",
    ] {
        assert_eq!(row(&rows, id).agreement, Agreement::Agrees, "{id}");
    }
}

#[test]
fn the_printed_slips_are_flagged() {
    let rows = report();
    for id in [
        "eq. 13",
        "eq. 15",
        "eq. 23a",
        "eq. 27 centre",
        "eq. 27 slip",
        "§3 ΔT/T0",
        "§3 v_Px+",
    ] {
        let r = row(&rows, id);
        assert_eq!(r.agreement, Agreement::Differs, "{id}");
        assert!(!r.note.is_empty(), "{id} needs a note");
    }
    // Eq. 14 is truncated rather than rounded: 0.2058 printed as 0.20.
    assert_eq!(row(&rows, "eq. 14").agreement, Agreement::Rounding);
    // The two-phase verdict (the assumed reversal does not happen) holds nevertheless.
    assert_eq!(row(&rows, "§3 verdict").agreement, Agreement::Agrees);
    // The literal reading of eq. 24 reproduces the printed η.
    assert_eq!(row(&rows, "eq. 24 centre").agreement, Agreement::Agrees);
    assert_eq!(row(&rows, "eq. 24 slip").agreement, Agreement::Differs);
}

#[test]
fn notes_explain_exactly_the_disagreements() {
    for r in report() {
        match r.agreement {
            Agreement::Agrees => assert!(r.note.is_empty(), "{}: {}", r.id, r.note),
            Agreement::Rounding | Agreement::Differs => {
                assert!(!r.note.is_empty(), "{} has no note", r.id)
            }
            Agreement::NotPrinted => {}
        }
    }
}

#[test]
fn every_computed_value_is_finite() {
    for r in report() {
        if let Some(x) = r.computed_value {
            assert!(x.is_finite(), "{}: {x}", r.id);
        }
        assert!(!r.computed.is_empty(), "{}", r.id);
    }
}

#[test]
fn eq14_threshold_is_a_root_of_the_engine_energy() {
    let rows = report();
    let g = row(&rows, "eq. 14").computed_value.unwrap();
    assert!(g > -0.5 && g < 1.0, "{g}");
    assert!(whittaker_energy(g).abs() < 1e-12, "{}", whittaker_energy(g));
    // Gain below, loss above, as eq. 14 says.
    assert!(whittaker_energy(g - 0.05) > 0.0);
    assert!(whittaker_energy(g + 0.05) < 0.0);

    let g15 = row(&rows, "eq. 15").computed_value.unwrap();
    assert!(g15 < -0.5, "{g15}");
    assert!(whittaker_energy(g15).abs() < 1e-12);
    // The two thresholds mirror each other about γ = −sin α.
    assert!((g + g15 + 1.0).abs() < 1e-9, "{g} + {g15}");
}

#[test]
fn headline_numbers() {
    let rows = report();
    let v = |id: &str| row(&rows, id).computed_value.unwrap();
    assert!((v("eq. 13") - 0.242403).abs() < 1e-6);
    assert!((v("eq. 23a") - 0.803183).abs() < 1e-6);
    assert!((v("eq. 23b") - 0.757957).abs() < 1e-6);
    assert!((v("§3 ΔT/T0") - v("eq. 13")).abs() < 1e-12);
    assert!((v("§3 v_Px+") - 1.561140).abs() < 1e-6);
    assert!((v("eq. 27 centre") - 0.067696).abs() < 1e-6);
    assert!((v("eq. 24 slip") - 0.401171).abs() < 1e-6);
    assert!((v("§4 ΔT/T0 γ=0 centre") - 0.177779).abs() < 1e-6);
    assert!((v("§4 ΔT/T0 γ=0 slip") + 0.423402).abs() < 1e-6);
    assert!(v("§4 ΔT/T0 γ=-0.5 slip") < 0.0);
    // The slip reading never gains energy for the sphere.
    assert!(v("§4 verdict slip") <= 0.0);
    let exact_dt = rows
        .iter()
        .find(|r| r.id == "exact" && r.quantity.starts_with("ΔT/T0"))
        .unwrap();
    assert!((exact_dt.computed_value.unwrap() + 0.453929).abs() < 1e-6);
}

#[test]
fn seed_helpers_match_the_paper_case() {
    let seed = Seed::PAPER;
    assert_eq!(seed.t0(), 0.5);
    assert_eq!(seed.alpha, 30f64.to_radians());
    let r = seed.energy_ratio(LawId::Whittaker, 0.0).unwrap();
    assert!((r - 2.0 * whittaker_energy(0.0)).abs() < 1e-12);
    // At γ = −sin α the slip before is exactly zero.
    let p = seed.problem(seed.zero_slip_spin()).unwrap();
    assert_eq!(p.velocity().x, 0.0);
}

#[test]
fn markdown_has_one_line_per_row() {
    let rows = report();
    let md = markdown(&rows);
    assert_eq!(md.lines().count(), rows.len() + 2);
}
