//! Every contact-space law on the seed's sphere (paper A: α = 30°, e = 0.7, f = 0.4, γ = 0).
use impax::{planar::ContactProblem, LawId};

fn main() {
    let alpha = 30f64.to_radians();
    let p = ContactProblem::from_entries(3.5, 0.0, 1.0, alpha.sin(), -alpha.cos(), 0.4, 0.7)
        .expect("the seed's problem is valid");
    for law in LawId::CONTACT_SPACE {
        match law.resolve(&p) {
            Ok(o) => println!(
                "{law:10} p = ({:+.6}, {:.6})  v+ = ({:+.6}, {:+.6})  dT/T0 = {:+.6}  {}  {:?} {:?}",
                o.impulse.x,
                o.impulse.y,
                o.velocity_after.x,
                o.velocity_after.y,
                2.0 * o.energy_change,
                o.phases.summary(),
                o.verdict,
                o.detail
            ),
            Err(b) => println!("{law:10} {b}"),
        }
    }
}
