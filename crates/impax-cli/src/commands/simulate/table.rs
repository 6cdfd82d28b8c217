//! The table of `impax simulate`: a line per impact (the first 40), the events, the energy and
//! the stop in words.

use super::Case;
use crate::output::fmt::{magnitude, signed, Table};
use impax::mechanism::Mechanism;
use impax::simulation::{EventKind, ImpactRecord, Run, StopReason};

/// The stop reason in words.
fn stop_text(stop: &StopReason, case: &Case) -> String {
    let m = &case.initial.mechanism;
    match stop {
        StopReason::UnsupportedContact { contact, touching } => format!(
            "the {} met its surface while the {} touched: more contacts at once than the simulator resolves",
            m.contacts()[*contact].name,
            touching
                .iter()
                .map(|&j| m.contacts()[j].name)
                .collect::<Vec<_>>()
                .join(" and the ")
        ),
        StopReason::TimeLimit => "the end time was reached".into(),
        StopReason::Rest => "at rest".into(),
        StopReason::ImpactLimit => format!("{} impacts (the limit)", case.options.max_impacts),
        StopReason::Breakdown { reason } => format!("the law does not apply: {reason}"),
        StopReason::Painleve { contact, solutions } => format!(
            "Painlevé's paradox at the {}: the contact forces have {} — a tangential impact would be needed, which is not modelled",
            m.contacts()[*contact].name,
            if *solutions == 0 {
                "no solution".to_string()
            } else {
                format!("{solutions} solutions")
            }
        ),
    }
}

/// The phases column of an impact: the struck contact's phases; at several contacts each
/// contact's, named, and the law.
fn phases_cell(m: &impax::mechanism::builtin::BuiltIn, i: &ImpactRecord) -> String {
    if i.contacts.len() == 1 {
        return i.struck().phase_summary();
    }
    let each: Vec<String> = i
        .contacts
        .iter()
        .zip(&i.outcome.contacts)
        .map(|(&k, c)| format!("{}: {}", m.contacts()[k].name, c.phase_summary()))
        .collect();
    format!("{} ({})", each.join("; "), i.law)
}

/// The table, the events and the summary.
pub(super) fn table(case: &Case, run: &Run) -> String {
    let m = &case.initial.mechanism;
    let mut t = Table::new(&[
        ("#", true),
        ("time", true),
        ("x contact", true),
        ("vt-", true),
        ("vn-", true),
        ("vt+", true),
        ("vn+", true),
        ("ΔT", true),
        ("T+V after", true),
        ("phases", false),
    ]);
    const SHOWN: usize = 40;
    for (k, i) in run.impacts.iter().enumerate().take(SHOWN) {
        let o = i.struck();
        let vb = i.contact_velocity_before();
        let c = m.contact_point(i.contact, &i.q);
        let mut delta = signed(i.energy_change, 6);
        if i.energy_change > 0.0 {
            delta.push_str(" GAIN");
        }
        t.row(vec![
            (k + 1).to_string(),
            format!("{:.6}", i.time),
            signed(c[0], 5),
            signed(vb.x, 5),
            signed(vb.y, 5),
            signed(o.velocity_after.x, 5),
            signed(o.velocity_after.y, 5),
            delta,
            signed(i.total_energy_before + i.energy_change, 6),
            phases_cell(m, i),
        ]);
    }
    let mut text = format!(
        "impax simulate — {}\nlaw {}, μ = {}, e = {}, until {} s; {} impacts, {} samples, {} integrator steps\n\n",
        case.description,
        case.options.law,
        case.options.friction,
        case.options.restitution,
        case.options.until,
        run.impacts.len(),
        run.samples.len(),
        run.steps.0
    );
    if run.impacts.is_empty() {
        text.push_str("no impact\n");
    } else {
        text.push_str(&t.render());
        if run.impacts.len() > SHOWN {
            text.push_str(&format!(
                "… {} more impacts (all in --json)\n",
                run.impacts.len() - SHOWN
            ));
        }
    }
    let name = |k: &usize| m.contacts()[*k].name;
    let lines: Vec<String> = run
        .events
        .iter()
        .filter_map(|(time, e)| match e {
            EventKind::Zeno { limit_time, ratio, .. } => Some(format!(
                "t = {time:.6}: impacts accumulate (interval ratio {ratio:.6}); their limit time t∞ = {limit_time:.12}"
            )),
            EventKind::Sliding => Some(format!("t = {time:.6}: sliding contact begins")),
            EventKind::Rolling => Some(format!("t = {time:.6}: rolling begins")),
            EventKind::Rest => Some(format!("t = {time:.6}: at rest")),
            EventKind::Closes { contact, regime } => Some(format!(
                "t = {time:.6}: the {} stays in contact ({})",
                name(contact),
                regime.label()
            )),
            EventKind::Opens { contact } => Some(format!(
                "t = {time:.6}: the {} leaves its surface (its normal force vanished)",
                name(contact)
            )),
            EventKind::Regime { contact, regime } => Some(format!(
                "t = {time:.6}: the {} changes to {}",
                name(contact),
                regime.label()
            )),
            EventKind::Impact { .. } => None,
        })
        .collect();
    for line in lines.iter().take(SHOWN) {
        text.push_str(line);
        text.push('\n');
    }
    if lines.len() > SHOWN {
        text.push_str(&format!(
            "… {} more events (all in --json)\n",
            lines.len() - SHOWN
        ));
    }
    let gains = run.impacts.iter().filter(|i| i.energy_change > 0.0).count();
    if gains > 0 {
        text.push_str(&format!(
            "energy rises at {gains} impact(s) under {} (marked GAIN)\n",
            case.options.law
        ));
    }
    let e0 = run.samples.first().map_or(0.0, |s| s.kinetic + s.potential);
    let e1 = run.samples.last().map_or(0.0, |s| s.kinetic + s.potential);
    text.push_str(&format!(
        "energy T + V: {} at the start, {} at the end\nstop at t = {:.6}: {} ({})\n",
        magnitude(e0, e0.abs().max(e1.abs()), 6),
        magnitude(e1, e0.abs().max(e1.abs()), 6),
        run.end_time,
        run.stop.id(),
        stop_text(&run.stop, case)
    ));
    text
}
