//! `impax audit ROBOT.urdf --contact LINK` (or a `space = "3d"` mechanism file): the engine
//! rules (`lcp`, `whittaker`) judged against the rigid-body answer on one contact of a spatial
//! mechanism, at the level of its generalized velocities.

use super::{
    Audit, AuditArgs, Row, RowData, ENGINE_RULES, LAWS, LEGEND, REFERENCE, RIGID_BODY_ANSWER,
};
use crate::input::CliResult;
use crate::output::json;
use crate::sources::{robot, File};

/// The audit of a robot's impact.
pub(super) fn audit(file: &File, args: &AuditArgs) -> CliResult<Audit> {
    let case = robot::load(file, &args.mechanism, args.friction, args.restitution, &[])?;
    let built = case.spec.build()?;
    let impact = built.impact()?;
    let problem = impact.problem(case.friction, case.restitution)?;
    let mut rows = Vec::new();
    for law in LAWS {
        let r = impact.resolve(law, case.friction, case.restitution)?;
        rows.push(Row {
            law,
            result: r.resolution.map(|o| RowData {
                verdict: o.verdict,
                energy_change: o.energy_change,
                phases: o.phases.summary(),
                velocities: r.velocities_after.unwrap_or_default(),
                entry: json::spatial_outcome_fields(&o),
            }),
        });
    }
    let t0 = impact.energy_before();
    let (w, v) = (problem.w(), problem.velocity());
    Ok(Audit {
        description: format!(
            "{}; μ = {}, e = {}",
            built.description(),
            case.friction,
            case.restitution
        ),
        reference: REFERENCE,
        reference_label: RIGID_BODY_ANSWER,
        engine_rules: &ENGINE_RULES,
        legend: LEGEND,
        names: built.model.speeds().iter().map(|c| format!("{c}'")).collect(),
        before: built.u.clone(),
        energy_before: t0,
        problem: json::spatial_problem(&problem),
        problem_line: format!(
            "contact space (3D): W = [[{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}], [{:.6}, {:.6}, {:.6}]], v⁻ = ({:.6}, {:.6}, {:.6}); T⁻ = {:.6}",
            w[(0, 0)], w[(0, 1)], w[(0, 2)], w[(1, 0)], w[(1, 1)], w[(1, 2)], w[(2, 0)], w[(2, 1)], w[(2, 2)], v.x, v.y, v.z, t0
        ),
        rows,
    })
}
