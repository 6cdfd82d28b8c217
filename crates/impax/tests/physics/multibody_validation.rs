//! A spatial multibody model refuses what cannot describe one, naming the field: negative
//! masses, inertias not symmetric or not positive semidefinite, zero axes, loops, joints out
//! of tree order, free joints not on the world, bad contacts, states of the wrong length,
//! non-finite or with a quaternion that is not a unit one.

use impax::math::{Mat3, Vec3};
use impax::multibody::{
    mass_matrix, Body, ContactPoint, Joint, JointKind, Model, Placement, Workspace,
};

fn body(name: &str) -> Body {
    Body::new(name, 1.0, Vec3::new(0.0, 0.0, -0.5), Mat3::identity() * 0.1)
}

fn chain() -> (Vec<Body>, Vec<Joint>) {
    let down = Placement::from_translation(Vec3::new(0.0, 0.0, -1.0));
    (
        vec![body("base"), body("thigh"), body("shin")],
        vec![
            Joint::free("root", 0),
            Joint::revolute("hip", Vec3::y(), Some(0), 1, down),
            Joint::revolute("knee", Vec3::y(), Some(1), 2, down),
        ],
    )
}

fn message(bodies: Vec<Body>, joints: Vec<Joint>, contacts: Vec<ContactPoint>) -> String {
    Model::new(bodies, joints, contacts)
        .unwrap_err()
        .to_string()
}

#[test]
fn multibody_model_refusals_name_their_field() {
    let (mut b, j) = chain();
    b[2].mass = -1.0;
    assert_eq!(message(b, j, vec![]), "body[2].mass: -1 is out of range: must be positive, or zero for a massless link (body \"shin\")");
    let (mut b, j) = chain();
    b[1].inertia[(0, 1)] = 0.01;
    assert!(message(b, j, vec![]).starts_with("body[1].inertia: must be symmetric"));
    let (mut b, j) = chain();
    b[1].inertia[(2, 2)] = -0.1;
    assert!(message(b, j, vec![]).starts_with(
        "body[1].inertia: must be positive semidefinite: its smallest eigenvalue is -0.1"
    ));
    let (mut b, j) = chain();
    b[0].com.x = f64::NAN;
    assert_eq!(
        message(b, j, vec![]),
        "body[0].com[0]: must be a finite number, got NaN"
    );
    let (b, mut j) = chain();
    j[1].kind = JointKind::Revolute {
        axis: Vec3::zeros(),
    };
    assert_eq!(
        message(b, j, vec![]),
        "joint[hip].axis: must be a nonzero direction, got (0, 0, 0)"
    );
    let (b, mut j) = chain();
    j[2].parent = Some(7);
    assert_eq!(
        message(b, j, vec![]),
        "joint[knee].parent: unknown body 7: the model has 3 bodies"
    );
    let (b, mut j) = chain();
    j[1].parent = Some(2); // hip hangs from the shin, whose joint comes later
    assert!(message(b, j, vec![])
        .starts_with("joint[hip].parent: body 2 (\"shin\") is the child of a later joint"));
    let (b, mut j) = chain();
    j[2].child = 0; // the base has two parent joints, the shin none
    assert!(message(b, j, vec![])
        .starts_with("joint[knee].child: body 0 (\"base\") is already the child of joint[root]"));
    let (b, mut j) = chain();
    j[2].parent = Some(2);
    assert_eq!(
        message(b, j, vec![]),
        "joint[knee].parent: body 2 cannot be its own parent (a loop)"
    );
    let (b, mut j) = chain();
    j.pop();
    assert!(message(b, j, vec![]).starts_with("body[2]: \"shin\" is the child of no joint"));
    let (b, mut j) = chain();
    j[0].parent = Some(1);
    assert!(message(b, j, vec![]).starts_with("joint[root].parent: a free joint"));
    let (b, mut j) = chain();
    j[1].placement.rotation[(0, 0)] = 2.0;
    assert!(message(b, j, vec![]).starts_with("joint[hip].placement.rotation: must be a rotation"));
    let (b, mut j) = chain();
    j[2].name = "hip".into();
    assert_eq!(
        message(b, j, vec![]),
        "joint[2].name: \"hip\" is already the name of joint[1]"
    );
    let (b, j) = chain();
    assert_eq!(
        message(b, j, vec![ContactPoint::new("toe", 3, Vec3::zeros(), 0.0)]),
        "contact[toe].body: unknown body 3: the model has 3 bodies"
    );
    let (b, j) = chain();
    assert!(
        message(b, j, vec![ContactPoint::new("toe", 2, Vec3::zeros(), -0.1)])
            .starts_with("contact[toe].radius: -0.1 is out of range")
    );
    assert_eq!(
        message(vec![], vec![], vec![]),
        "bodies: a model needs at least one body"
    );
}

#[test]
fn multibody_model_normalises_axes_and_quaternions() {
    let (b, mut j) = chain();
    j[1].kind = JointKind::Revolute {
        axis: Vec3::new(0.0, 3.0, 0.0),
    };
    let model = Model::new(b, j, vec![]).unwrap();
    assert_eq!(
        model.joints()[1].kind,
        JointKind::Revolute { axis: Vec3::y() }
    );
    let mut q = model.neutral();
    q[7] = 0.4;
    q[8] = -1.1;
    let m0 = mass_matrix(&model, &q).unwrap();
    // A quaternion within 1e-6 of unit norm is normalised; the mass matrix is the same.
    q[3] = 1.0 + 5e-7;
    let m1 = mass_matrix(&model, &q).unwrap();
    assert!((m0 - m1).amax() < 1e-15);
    q[3] = 1.1;
    let e = mass_matrix(&model, &q).unwrap_err().to_string();
    assert_eq!(e, "q[3..7] (qw, qx, qy, qz): 1.1 is out of range: the norm of the quaternion must be 1 (to 1e-6)");
    q[3] = 1.0;
    q[8] = f64::INFINITY;
    assert_eq!(
        mass_matrix(&model, &q).unwrap_err().to_string(),
        "q[8] (knee): must be a finite number, got inf"
    );
    assert!(mass_matrix(&model, &q[..5])
        .unwrap_err()
        .to_string()
        .starts_with("q: needs 9 numbers (x, y, z, qw, qx, qy, qz, hip, knee), got 5"));
    q[8] = 0.0;
    q[0] = 1e9;
    assert!(mass_matrix(&model, &q)
        .unwrap_err()
        .to_string()
        .contains("lost to round-off"));
    let mut ws = Workspace::new(&model);
    assert!(ws.update(&model, &model.neutral()).is_ok());
}

#[test]
fn multibody_model_gravity_and_floor() {
    let (b, j) = chain();
    let model = Model::new(b, j, vec![]).unwrap();
    assert_eq!(model.gravity(), 9.81);
    assert_eq!(
        model.clone().with_gravity(-1.0).unwrap_err().field(),
        "gravity"
    );
    assert_eq!(
        model.clone().with_floor(f64::NAN).unwrap_err().field(),
        "floor"
    );
    assert_eq!(model.with_floor(0.3).unwrap().floor(), 0.3);
}
