//! Print the hodograph points of one spatial problem (debugging aid).
use impax::{
    spatial::{laws, ContactProblem},
    LawId,
};
fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().expect("number"))
        .collect();
    let p = ContactProblem::from_upper(
        [args[0], args[1], args[2], args[3], args[4], args[5]],
        [args[6], args[7], args[8]],
        args[9],
        args[10],
    )
    .expect("valid");
    let h = laws::hodograph(&p, LawId::Energetic, &impax::law::Options::default()).expect("ok");
    for x in &h {
        println!("{:.17e} {:+.6e} {:+.6e} {:+.6e}", x[0], x[1], x[2], x[3]);
    }
    println!("{:?}", LawId::Energetic.resolve(&p));
}
