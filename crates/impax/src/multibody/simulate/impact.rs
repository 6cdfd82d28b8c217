//! An impact in the spatial run: one contact strikes, alone or while others touch the floor.
//!
//! * **Alone** (no other contact within the touching tolerance): the run's law on the
//!   one-contact problem `W = J M⁻¹ Jᵀ`, `v⁻ = J u` ([`SpatialMechanismImpact`]).
//! * **With others touching**: the impact at all of them at once,
//!   `M (u⁺ − u⁻) = Σ_j J_jᵀ p_j` ([`SpatialMechanismMultiImpact`], theory §6), under the run's
//!   law when it is a multi-contact law ([`LawId::is_multi_contact`]: `lcp`, `sequential`,
//!   `lzb`), else under `lcp` (recorded in [`ImpactRecord::law`]). A touching contact that
//!   does not approach may be pushed off the floor, never pulled.

use super::record::{ImpactRecord, StopReason};
use crate::error::Result;
use crate::law::LawId;
use crate::math::Vec3;
use crate::multi::spatial::{lcp, lzb, MultiOutcome};
use crate::multibody::{Model, SpatialMechanismImpact, SpatialMechanismMultiImpact};
use crate::simulation::SimulationOptions;

/// What an impact gave.
pub(super) enum Struck {
    /// The impact, resolved.
    Record(Box<ImpactRecord>),
    /// The run cannot go on (the law breaks down, too many contacts).
    Stop(StopReason),
}

/// The state of an impact: its time, configuration, speeds and potential energy.
pub(super) struct At<'s> {
    pub t: f64,
    pub q: &'s [f64],
    pub u: &'s [f64],
    pub potential: f64,
}

fn breakdown(reason: String) -> Result<Struck> {
    Ok(Struck::Stop(StopReason::Breakdown { reason }))
}

/// The impact at `at` of contact `struck`, with `others` touching the floor.
///
/// # Errors
/// A singular mass matrix; the law's own input errors that are not breakdowns.
pub(super) fn strike(
    model: &Model,
    at: At<'_>,
    struck: usize,
    others: &[usize],
    options: &SimulationOptions,
) -> Result<Struck> {
    if others.is_empty() {
        return strike_alone(model, at, struck, options);
    }
    let name = |k: usize| model.contacts()[k].name.as_str();
    let contacts: Vec<usize> = std::iter::once(struck)
        .chain(others.iter().copied())
        .collect();
    let law = if options.law.is_multi_contact() {
        options.law
    } else {
        LawId::Lcp
    };
    let most = match law {
        LawId::Lcp => lcp::MAX_CONTACTS,
        LawId::Lzb => lzb::MAX_CONTACTS,
        _ => usize::MAX,
    };
    if contacts.len() > most {
        return Ok(Struck::Stop(StopReason::UnsupportedContact {
            contact: struck,
            touching: others.to_vec(),
        }));
    }
    let imp = SpatialMechanismMultiImpact::new(model, at.q, at.u, &contacts)?;
    let (mu, e) = ([options.friction], [options.restitution]);
    if let Err(err) = imp.problem(&mu, &e) {
        let names: Vec<&str> = contacts.iter().map(|&k| name(k)).collect();
        return breakdown(format!(
            "the contact {} strikes while {} touch, and their contact problem is not one the multi-contact laws take: {err}",
            name(struck),
            names[1..].join(", ")
        ));
    }
    let solved = imp.resolve(law, &mu, &e)?;
    let outcome = match solved.resolution {
        Ok(o) => o,
        Err(b) => return breakdown(b.reason.to_string()),
    };
    let after = solved
        .velocities_after
        .expect("a resolved impact has velocities after");
    let v = imp.contact_velocity();
    let kinetic_before = imp.energy_before();
    Ok(Struck::Record(Box::new(ImpactRecord {
        time: at.t,
        contact: struck,
        contacts,
        law,
        q: at.q.to_vec(),
        u_before: at.u.to_vec(),
        u_after: after,
        contact_velocities_before: v.chunks(3).map(Vec3::from_column_slice).collect(),
        kinetic_before,
        energy_change: solved
            .energy_change_from_velocities
            .expect("a resolved impact has its energy change"),
        law_energy_change: outcome.energy_change,
        outcome,
        total_energy_before: kinetic_before + at.potential,
    })))
}

/// The impact of `struck` alone, under the run's law.
fn strike_alone(
    model: &Model,
    at: At<'_>,
    struck: usize,
    options: &SimulationOptions,
) -> Result<Struck> {
    let imp = SpatialMechanismImpact::new(model, at.q, at.u, struck)?;
    let problem = match imp.problem(options.friction, options.restitution) {
        Ok(p) => p,
        Err(e) => {
            return breakdown(format!(
                "the contact {} strikes, and its contact problem is not one a one-contact law takes: {e}",
                model.contacts()[struck].name
            ))
        }
    };
    let outcome = match options.law.resolve(&problem) {
        Ok(o) => o,
        Err(b) => return breakdown(b.reason.to_string()),
    };
    let after = imp.velocities_after(outcome.impulse);
    let energy_change = imp.energy_change_to(&after);
    let mut multi = MultiOutcome::from_outcome(&outcome);
    multi.law = options.law;
    Ok(Struck::Record(Box::new(ImpactRecord {
        time: at.t,
        contact: struck,
        contacts: vec![struck],
        law: options.law,
        q: at.q.to_vec(),
        u_before: at.u.to_vec(),
        u_after: after,
        contact_velocities_before: vec![imp.contact_velocity()],
        outcome: multi,
        kinetic_before: imp.energy_before(),
        energy_change,
        law_energy_change: outcome.energy_change,
        total_energy_before: imp.energy_before() + at.potential,
    })))
}
