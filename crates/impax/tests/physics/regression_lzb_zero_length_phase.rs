//! Regression: planar `lzb` recorded a phase that carried no impulse.
//!
//! Reproducer: `impax resolve --contacts 2 --w 1,0.2,0,0.1,1,0.1,0,1,0.3,1 --v 0.1,-1,0,-0.5
//! --friction 0.3 --restitution 0.7 --law lzb --stiffness 1,1e-12` (found by sweeping the
//! stiffness ratio): contact 1 read `slip+ → stick → slip+`, the last slip ending at the
//! impulse where the stick ended (`p_n = 1.7993552973072922` both), while the ratio 1e-100
//! gave `slip+ → stick` with the same impulses to nine digits.
//!
//! Cause: when one contact's regimes were chosen again at the point where another's impulse
//! stopped growing, the new regime was recorded as a phase even though the impulse never grew
//! in it. A loaded phase (stick or slip) of zero length is no longer recorded (an `off` phase
//! is: the impulse never grows while off).
//!
//! Expected physics: as the second contact's stiffness falls to 1e-100 of the first's, the
//! impact tends to its limit linearly in the ratio (the impulses move by ≈ 0.2 times it; the
//! first contact's last slip, real up to a ratio of 1e-9, shrinks with it): from 1e-10 on, the
//! impulses agree with the limit's to 1e-10 and every contact reads its phases; on random
//! problems (K = 2, 3; random stiffness ratios), each contact's phases end in order and none
//! but `off` has zero length.

use super::support::random_multi;
use impax::math::SplitMix64;
use impax::multi::{lzb, ContactPhaseKind, MultiProblem};

fn problem(soft: f64) -> MultiProblem {
    MultiProblem::from_upper(
        2,
        &[1.0, 0.2, 0.0, 0.1, 1.0, 0.1, 0.0, 1.0, 0.3, 1.0],
        &[0.1, -1.0, 0.0, -0.5],
        &[0.3],
        &[0.7],
    )
    .unwrap()
    .with_stiffness(&[1.0, soft])
    .unwrap()
}

#[test]
fn a_soft_contact_tends_to_its_limit_with_the_same_phases() {
    let limit = lzb::resolve(&problem(1e-100)).unwrap();
    let summaries: Vec<String> = limit.contacts.iter().map(|c| c.phase_summary()).collect();
    assert_eq!(summaries, ["slip+ → stick", "slip+"]);
    for decades in [10, 11, 12, 13, 14, 16, 20, 40, 70] {
        let o = lzb::resolve(&problem(10f64.powi(-decades))).unwrap();
        for (j, (c, l)) in o.contacts.iter().zip(&limit.contacts).enumerate() {
            assert!(
                (c.impulse - l.impulse).amax() < 1e-10,
                "1e-{decades}, contact {j}: {} against {}",
                c.impulse,
                l.impulse
            );
            assert_eq!(c.phase_summary(), summaries[j], "1e-{decades}, contact {j}");
        }
    }
}

#[test]
fn phases_end_in_order_and_none_loaded_is_empty() {
    let mut rng = SplitMix64(0x2e50);
    for trial in 0..3000 {
        let k = 2 + trial % 2;
        let r = random_multi(&mut rng, k);
        let kappa: Vec<f64> = (0..k).map(|_| rng.decades(-12.0, 0.0)).collect();
        let p = r.problem.clone().with_stiffness(&kappa).unwrap();
        let Ok(o) = lzb::resolve(&p) else { continue };
        for (j, c) in o.contacts.iter().enumerate() {
            let mut before = 0.0;
            for (i, ph) in c.phases.iter().enumerate() {
                assert!(
                    ph.ends_at >= before,
                    "contact {j}: phases out of order on {p:?}"
                );
                if i > 0 && ph.kind != ContactPhaseKind::Off {
                    assert!(
                        ph.ends_at > before,
                        "contact {j}: {} has a loaded phase of zero length on {p:?}",
                        c.phase_summary()
                    );
                }
                before = ph.ends_at;
            }
        }
    }
}
