//! An impact in the simulation: one contact strikes, alone or while others touch their
//! surfaces.
//!
//! * **Alone** (no other contact within [`dynamics::touching_tolerance`]): the run's law on the
//!   one-contact problem `W = J M⁻¹ Jᵀ`, `v⁻ = J u` ([`MechanismImpact`]).
//! * **With others touching** (closed contacts, or contacts that reach their surfaces at the
//!   same instant): the impact at all of them at once, `M (u⁺ − u⁻) = Σ_j J_jᵀ p_j`
//!   ([`MultiImpact::from_mechanism`], theory §6), with the run's law when it is a
//!   multi-contact law ([`LawId::is_multi_contact`]: `lcp`, `sequential`), else with `lcp`
//!   (recorded in [`ImpactRecord::law`]). A touching contact that does not approach may be
//!   pushed apart, never pulled.

use super::record::{ImpactRecord, StopReason};
use super::SimulationOptions;
use crate::error::Result;
use crate::law::LawId;
use crate::math::Vec2;
use crate::mechanism::dynamics::{self, Kinematics};
use crate::mechanism::impact::MechanismImpact;
use crate::mechanism::Mechanism;
use crate::multi::{lcp, MultiImpact, MultiOutcome};

/// What an impact gave.
pub(crate) enum Struck {
    /// The impact, resolved.
    Record(Box<ImpactRecord>),
    /// The run cannot go on (the law breaks down, too many contacts).
    Stop(StopReason),
}

/// Translational and rotational kinetic energy at the velocities `u`.
pub(crate) fn energy_parts<M: Mechanism + ?Sized>(
    m: &M,
    kin: &Kinematics,
    u: &[f64],
) -> (f64, f64) {
    let vel = dynamics::body_velocities(kin, u);
    let (mut tr, mut rot) = (0.0, 0.0);
    for (b, v) in m.bodies().iter().zip(&vel) {
        tr += 0.5 * b.mass * (v[0] * v[0] + v[1] * v[1]);
        rot += 0.5 * b.inertia * v[2] * v[2];
    }
    (tr, rot)
}

/// The impact at `(t, q, u)` of contact `struck`, with `others` touching their surfaces.
///
/// # Errors
/// A singular mass matrix; the law's own input errors that are not breakdowns.
pub(crate) fn strike<M: Mechanism + ?Sized>(
    m: &M,
    t: f64,
    q: &[f64],
    u: &[f64],
    struck: usize,
    others: &[usize],
    options: &SimulationOptions,
) -> Result<Struck> {
    let name = m.contacts()[struck].name;
    let breakdown = |reason: String| Ok(Struck::Stop(StopReason::Breakdown { reason }));
    let contacts: Vec<usize> = std::iter::once(struck)
        .chain(others.iter().copied())
        .collect();
    let (law, outcome, after, velocities, kinetic_before, kin) = if others.is_empty() {
        let imp = MechanismImpact::new(m, q, u, struck)?;
        let v = imp.contact_velocity();
        // A contact that one coordinate alone moves (a double pendulum's elbow) has a
        // singular W: no one-contact law applies there.
        let problem = match imp.problem(options.friction, options.restitution) {
            Ok(p) => p,
            Err(e) => {
                return breakdown(format!(
                    "the {name} strikes, and its contact problem is not one a one-contact law takes: {e}"
                ))
            }
        };
        let outcome = match options.law.resolve(&problem) {
            Ok(o) => o,
            Err(b) => return breakdown(b.reason.to_string()),
        };
        let after = imp.velocities_after(outcome.impulse);
        (
            options.law,
            MultiOutcome::from_outcome(&outcome),
            after,
            vec![v],
            imp.energy_before(),
            imp.kinematics().clone(),
        )
    } else {
        let law = if options.law.is_multi_contact() {
            options.law
        } else {
            LawId::Lcp
        };
        if law == LawId::Lcp && contacts.len() > lcp::MAX_CONTACTS {
            return Ok(Struck::Stop(StopReason::UnsupportedContact {
                contact: struck,
                touching: others.to_vec(),
            }));
        }
        let imp = MultiImpact::from_mechanism(m, q, u, &contacts)?;
        let names = || {
            contacts
                .iter()
                .map(|&k| m.contacts()[k].name)
                .collect::<Vec<_>>()
                .join(", ")
        };
        let problem = match imp.problem(&[options.friction], &[options.restitution]) {
            Ok(p) => p,
            Err(e) => {
                return breakdown(format!(
                    "the {name} strikes while {} touch, and their contact problem is not one the multi-contact laws take: {e}",
                    names()
                ))
            }
        };
        let solved = imp.resolve(law, &problem)?;
        let outcome = match solved.resolution {
            Ok(o) => o,
            Err(b) => return breakdown(b.reason.to_string()),
        };
        let after = solved
            .velocities_after
            .expect("a resolved impact has velocities after");
        let v = imp.contact_velocities();
        let velocities = (0..contacts.len())
            .map(|j| Vec2::new(v[2 * j], v[2 * j + 1]))
            .collect();
        (
            law,
            outcome,
            after,
            velocities,
            imp.energy_before(),
            dynamics::kinematics(m, q),
        )
    };
    let (tr0, rot0) = energy_parts(m, &kin, u);
    let (tr1, rot1) = energy_parts(m, &kin, &after);
    let kinetic_after = dynamics::kinetic_energy(m, q, &after);
    Ok(Struck::Record(Box::new(ImpactRecord {
        time: t,
        contact: struck,
        contacts,
        law,
        q: q.to_vec(),
        u_before: u.to_vec(),
        u_after: after,
        contact_velocities_before: velocities,
        outcome,
        kinetic_before,
        energy_change: kinetic_after - kinetic_before,
        translational_change: tr1 - tr0,
        rotational_change: rot1 - rot0,
        total_energy_before: kinetic_before + dynamics::potential_energy(m, q),
    })))
}
