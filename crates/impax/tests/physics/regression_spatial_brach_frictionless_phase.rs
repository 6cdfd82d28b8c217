//! fixed (minor, labelling): frictionless spatial `brach` labels a
//! slipping contact `no-slip`.
//!
//! `PhaseKind::NoSlip` is documented as "no slip at the start and no friction (algebraic
//! laws with `v_t⁻ = 0`)". With `μ = 0` and `v_t⁻ ≠ 0` the 3D `brach` reports `NoSlip`
//! (`kind` is `Slip` only `if mu > 0.0 && pt.norm() > 0.0`), while the planar `brach`
//! reports `slip+`/`slip-` and the 3D `whittaker` reports `slip(0°→0°)` for the same
//! problem.
//!
//! `W = I`, `v⁻ = (1, 0, −1)`, `μ = 0`, `e = 0.5`: expected a `Slip { from: 0, to: 0 }`
//! phase (as `whittaker`); got `NoSlip`. Found by `spatial_planar_embedding` (373 of the
//! 10,000 planar problems, all with `μ = 0`).

use impax::spatial::{ContactProblem, PhaseKind};
use impax::LawId;

#[test]
fn frictionless_brach_labels_the_slip() {
    let p = ContactProblem::from_upper([1.0, 0.0, 0.0, 1.0, 0.0, 1.0], [1.0, 0.0, -1.0], 0.0, 0.5)
        .unwrap();
    let o = LawId::Brach.resolve(&p).unwrap();
    let kind = o.phases.as_slice()[0].kind;
    assert!(
        matches!(kind, PhaseKind::Slip { from, to } if from == 0.0 && to == 0.0),
        "phase {kind:?} for a contact slipping along t1"
    );
}
