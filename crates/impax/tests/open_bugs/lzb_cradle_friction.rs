//! Open bug: planar `lzb` does not settle on a long inelastic cradle with friction.
//!
//! `impax compare cradle --balls 8 --restitution 0.5 --friction 0.1 --law lzb` breaks down
//! with `too-many-steps` (20,000 integration steps, ≈ 0.7 s), for any μ > 0 with 8 balls
//! and e ≤ 0.5 (found through the explorer). The same cradle with μ = 0 is resolved at once,
//! and so is every cradle of 3 to 7 balls.
//!
//! Expected: the frictionless result. The balls lie on one line through their centres, so
//! the normal impulses give no tangential velocity at any contact (no `W_tn` coupling), the
//! sticking contacts need no tangential impulse, and friction does no work: the velocities
//! after must equal those with μ = 0 (momentum `Σ x_i⁺ = v0`, `T⁺ ≤ T⁻`). The suspicion is
//! the stick/slip assignment of the seven redundant sticking contacts being re-decided at
//! every one of the many re-engagements of the inelastic chain.

use impax::multi::scenarios::Cradle;
use impax::LawId;

#[test]
fn an_inelastic_cradle_with_friction_settles_as_without() {
    let sc = Cradle {
        balls: 8,
        ..Cradle::default()
    }
    .build()
    .unwrap();
    let with = sc.impact.problem(&[0.1], &[0.5]).unwrap();
    let without = sc.impact.problem(&[0.0], &[0.5]).unwrap();
    let a = sc.impact.resolve(LawId::Lzb, &with).unwrap();
    let b = sc.impact.resolve(LawId::Lzb, &without).unwrap();
    let (ua, ub) = (a.velocities_after.unwrap(), b.velocities_after.unwrap());
    for (x, y) in ua.iter().zip(&ub) {
        assert!((x - y).abs() < 1e-9, "{ua:?} vs {ub:?}");
    }
}
