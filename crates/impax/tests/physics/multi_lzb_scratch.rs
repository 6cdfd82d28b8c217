use impax::multi::{lzb, MultiProblem};
use nalgebra::DMatrix;
fn parse(s: &str) -> Vec<f64> { s.split(',').map(|x| x.parse().unwrap()).collect() }
pub fn run(args: &str) {
    let a: Vec<&str> = args.split_whitespace().collect();
    let k: usize = a[1].parse().unwrap();
    let p = MultiProblem::from_upper(k, &parse(a[3]), &parse(a[5]), &parse(a[7]), &parse(a[9])).unwrap();
    let p = if a.len() > 11 { p.with_stiffness(&parse(a[11])).unwrap().with_exponent(a[13].parse().unwrap()).unwrap() } else { p };
    let o = lzb::resolve(&p);
    println!("{o:?}");
    if let Ok(o) = o { let w: f64 = o.contacts.iter().map(|c| c.work.total()).sum(); println!("dT {:e} works {:e}", o.energy_change, w); }
}
#[test]
fn one() { if let Ok(a) = std::env::var("LZB_CASE") { run(&a); } }
#[test]
fn gain() {
    let w = DMatrix::from_row_slice(6, 6, &[4.241097803894478, 3.9435531562686092, -0.7036150660773278, -0.5173366885238264, 3.6026874107954967, -1.755714393203562, 3.9435531562686092, 6.122871013342895, -1.708568696327848, 0.18776055791285076, 3.250954569737055, -4.2881605861046665, -0.7036150660773278, -1.708568696327848, 4.384568654622802, 1.2415529805715142, -2.282154021503096, 0.9851936363795214, -0.5173366885238264, 0.18776055791285076, 1.2415529805715142, 3.0599555982676967, -3.497701849513655, -0.13861133281260626, 3.6026874107954967, 3.250954569737055, -2.282154021503096, -3.497701849513655, 8.68592122435027, -1.6629121386523458, -1.755714393203562, -4.2881605861046665, 0.9851936363795214, -0.13861133281260626, -1.6629121386523458, 4.276319546201287]);
    let p = MultiProblem::new(w, &[-0.7690492953196286, -0.6184567667538233, 1.7458687270223896, 1.3834256044274564, 0.44781718472296406, -0.5133957517942558], &[0.020258268623959297, 0.0, 0.6071589788889802], &[0.5947762901807098, 0.7983819785713734, 0.7830107192358096]).unwrap().with_stiffness(&[0.020305622453142172, 66.17505838922264, 94.44526532236692]).unwrap().with_exponent(1.0).unwrap();
    let o = lzb::resolve(&p).unwrap();
    for c in &o.contacts { println!("work {:?} p {:?} phases {}", c.work, c.impulse, c.phases.len()); }
    let w: f64 = o.contacts.iter().map(|c| c.work.total()).sum(); println!("dT {:e} works {:e}", o.energy_change, w);
}

#[test]
fn dec() {
    let w = DMatrix::from_row_slice(4, 4, &[1.0053978570025945, 0.0, 0.0, 0.0, 0.0, 0.9629657683145351, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    for kap in [[0.04562987686940167, 2.88], [1.0, 1.0]] {
    for eta in [1.4232844209516227, 1.5] {
    let p = MultiProblem::new(w.clone(), &[0.6138530854852937, -3.1711102865182714, 0.0, -0.1], &[0.8157571648263113], &[0.3685368301100115]).unwrap().with_stiffness(&kap).unwrap().with_exponent(eta).unwrap();
    let o = lzb::resolve(&p).unwrap();
    let one = impax::planar::ContactProblem::from_entries(1.0053978570025945, 0.0, 0.9629657683145351, 0.6138530854852937, -3.1711102865182714, 0.8157571648263113, 0.3685368301100115).unwrap();
    let r = impax::LawId::Energetic.resolve(&one).unwrap();
    println!("kappa {kap:?} eta {eta}: {:?} vs {:?} rel {:e} steps {:?}", o.contacts[0].velocity_after, r.velocity_after, (o.contacts[0].velocity_after - r.velocity_after).norm() / 3.17, o.detail);
    }}
}

#[test]
fn dec2() {
    let (a, b, c, vt, vn, mu, e) = (15.413427544009028, -2.039613724528693, 2.3125300156376354, 0.6807145127738417, -6.21305918289545, 1.341989273927163, 1.0);
    let w = DMatrix::from_row_slice(4, 4, &[a, b, 0.0, 0.0, b, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    for kap in [[0.023, 1.0], [1.0, 1.0]] {
    for eta in [2.220851714267221, 1.5] {
    let p = MultiProblem::new(w.clone(), &[vt, vn, 0.0, -0.1], &[mu], &[e]).unwrap().with_stiffness(&kap).unwrap().with_exponent(eta).unwrap();
    let o = lzb::resolve(&p).unwrap();
    let one = impax::planar::ContactProblem::from_entries(a, b, c, vt, vn, mu, e).unwrap();
    let r = impax::LawId::Energetic.resolve(&one).unwrap();
    println!("kappa {kap:?} eta {eta}: {:?} vs {:?} rel {:e} steps {:?} phases {:?} vs {:?}", o.contacts[0].velocity_after, r.velocity_after, (o.contacts[0].velocity_after - r.velocity_after).norm() / 6.2, o.detail, o.contacts[0].phases, r.phases);
    }}
}
