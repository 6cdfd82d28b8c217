//! fixed (minor): a slip that cannot swirl reports a turned angle.
//!
//! With isotropic `W_tt` and `w_tn = 0` (a sphere) the slip field is radial and the slip
//! direction never changes; `PhaseKind::Slip` documents "equal angles when it does not
//! swirl". The Darboux–Keller integration takes `from = atan2(v_t2⁻, v_t1⁻)` but `to` from
//! the normalised direction `atan2(ŝ_2, ŝ_1)`, `ŝ = v_t/|v_t|` (in `run_tail`), which can
//! differ in the last bit.
//!
//! `W = I`, `v⁻ = (−0.9344443181862998, −0.3561092756575448, −0.01)`,
//! `μ = 0.8061660820139892`, `e = 0.3947376586024572`, `newton`: expected `from == to`; got
//! `from = −2.777491757852636`, `to = −2.7774917578526357`. (`whittaker` and `brach` report
//! equal angles.) Found by `spatial_properties::isotropic_uncoupled_problems_do_not_swirl`.

use impax::spatial::{ContactProblem, PhaseKind};
use impax::LawId;

#[test]
fn radial_slip_keeps_its_angle() {
    let p = ContactProblem::from_upper(
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [-0.9344443181862998, -0.3561092756575448, -0.01],
        0.8061660820139892,
        0.3947376586024572,
    )
    .unwrap();
    for law in [LawId::Newton, LawId::Poisson, LawId::Energetic] {
        let o = law.resolve(&p).unwrap();
        for ph in o.phases.as_slice() {
            if let PhaseKind::Slip { from, to } = ph.kind {
                assert_eq!(from, to, "{law}: {}", o.phases.summary());
            }
        }
    }
}
